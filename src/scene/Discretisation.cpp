#include "anvil/scene/Discretisation.h"

#include <algorithm>

namespace anvil::scene {
namespace {

/// Appends one body's imposed conditions, its nodes numbered from `first_node`.
void append(ImposedConditions& all, const ImposedConditions& body, int first_node) {
  all.prescribed.insert(all.prescribed.end(), body.prescribed.begin(), body.prescribed.end());
  auto join = [](Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    Eigen::VectorXd joined(a.size() + b.size());
    joined << a, b;
    a.swap(joined);
  };
  join(all.values, body.values);
  join(all.nodal_forces, body.nodal_forces);
  for (std::vector<int> nodes : body.nodes_of_condition) {
    for (int& n : nodes)
      n += first_node;
    all.nodes_of_condition.push_back(std::move(nodes));
  }
}

} // namespace

std::vector<solver::NodalTerm*> Discretisation::contact_terms(const Scene& scene) {
  std::vector<solver::NodalTerm*> terms;
  if (!scene.dies.empty()) terms.push_back(&die_contact);
  if (pair_contact) terms.push_back(pair_contact.get());
  return terms;
}

std::vector<int> Discretisation::touching_die(const Eigen::VectorXd& nodal) const {
  std::vector<int> die(nodal.size() / 4, -1);
  const auto& candidates = die_contact.candidates();
  for (std::size_t c = 0; c < candidates.size(); ++c)
    if (die_contact.pressure(int(c), nodal) > 0.0) die[candidates[c].node] = candidates[c].die;
  return die;
}

namespace {

/// Per boundary face of the run's mesh, 1 where a symmetry condition of its body selects it.
std::vector<char> symmetry_faces(const Scene& scene, const RunState& state) {
  std::vector<char> on_plane(state.mesh.boundary_faces.size(), 0);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const mesh::MeshRange& range = state.bodies[b];
    const mesh::TetMesh body = mesh::extract(state.mesh, range);
    for (const BoundaryCondition& bc : scene.bodies[b].conditions)
      if (bc.kind == BoundaryKind::symmetry)
        for (int f : select_faces(body, bc.faces))
          on_plane[range.first_face + f] = 1;
  }
  return on_plane;
}

/// `conditions` as a remeshed body's faces find them at `time`: a plane
/// that chose a moving face (a plate, an imposed velocity) has moved with
/// it; its nodes moved by their prescribed velocity, increment by increment.
std::vector<BoundaryCondition> at_time(std::vector<BoundaryCondition> conditions, double time) {
  for (BoundaryCondition& c : conditions)
    if (c.faces.tag < 0 && c.prescribes_velocity())
      for (int k = 0; k < 3; ++k)
        c.faces.plane_point[k] += time * c.velocity[k].value_or(0.0);
  return conditions;
}

} // namespace

Discretisation discretise(const Scene& scene, RunState& state, Timers& timers) {
  fem::ElementLaws laws;
  ImposedConditions imposed;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const Body& body = scene.bodies[b];
    const mesh::MeshRange& range = state.bodies[b];
    laws.insert(laws.end(), range.tet_count, body.law.get());
    const bool remeshed = std::any_of(state.remeshes.begin(), state.remeshes.end(),
                                      [&](const RemeshRecord& r) { return r.body == static_cast<int>(b); });
    Timers::Scope scope(timers, "effect boundary_conditions");
    append(imposed,
           remeshed ? impose(mesh::extract(state.mesh, range), at_time(body.conditions, state.time))
                    : body.initial_imposed,
           range.first_node);
  }
  std::vector<char> on_symmetry_plane = symmetry_faces(scene, state);
  std::unique_ptr<contact::BodyContact> pairs;
  if (!scene.input.contact_pairs.empty()) {
    std::vector<contact::BodyPair> list;
    for (const ContactPairSpec& p : scene.input.contact_pairs)
      list.push_back({p.master == p.slave ? scene.bodies[p.master].name + " (self-contact)"
                                          : scene.bodies[p.master].name + "/" + scene.bodies[p.slave].name,
                      state.bodies[p.master], state.bodies[p.slave], p.method, p.friction});
    pairs = std::make_unique<contact::BodyContact>(std::move(list), on_symmetry_plane);
  }
  std::vector<material::PointState> states(state.mesh.tets.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    std::fill_n(states.begin() + state.bodies[b].first_tet, state.bodies[b].tet_count, scene.bodies[b].state);
  for (int e = 0; e < state.mesh.tet_count(); ++e)
    states[e].equivalent_strain = state.equivalent_strain[e];
  for (std::size_t e = 0; e < state.elastic_stress.size() / 6; ++e)
    states[e].elastic_stress = Eigen::Map<const material::Vec6>(&state.elastic_stress[6 * e]);
  std::unique_ptr<Heat> heat;
  if (scene.thermal) {
    heat = std::make_unique<Heat>(scene, state);
    element_temperatures(state.mesh, state.temperature, states);
  }
  for (int k = 0; k < imposed.values.size(); ++k)
    if (imposed.prescribed[k]) state.unknowns.nodal[k] = imposed.values[k];
  solver::LinearSolverSettings linear = scene.input.linear_solver;
  linear.velocity_block.free_rotations = scene.free_rotations;
  auto solver = std::make_unique<solver::IncrementSolver>(state.mesh, imposed.prescribed, linear, timers);
  solver->set_quadrature_degree(scene.input.quadrature_degree);
  return Discretisation{std::move(laws),   std::move(imposed),
                        std::move(states), contact::RigidContact{},
                        std::move(pairs),  mesh::QualityGuard(state.mesh),
                        std::move(solver), std::move(on_symmetry_plane),
                        std::move(heat)};
}

} // namespace anvil::scene

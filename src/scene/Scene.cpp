#include "anvil/scene/Scene.h"

#include "anvil/core/error.h"
#include "anvil/die/overlap_volume.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/mesh_io.h"
#include "anvil/scene/effects.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anvil::scene {
namespace {

mesh::TetMesh build_mesh(const MeshSpec& spec) {
  if (!spec.file.empty()) return mesh::read_mesh(spec.file);
  mesh::TetMesh m = spec.generate == "box"        ? mesh::make_box(spec.origin, spec.size, spec.element_size)
                    : spec.generate == "cylinder" ? mesh::make_cylinder(spec.radius, spec.height, spec.element_size)
                    : spec.generate == "quarter_cylinder"
                        ? mesh::make_quarter_cylinder(spec.radius, spec.height, spec.element_size)
                        : mesh::make_quarter_ring(spec.radius, spec.inner_radius, spec.height, spec.element_size);
  mesh::validate(m, spec.source + " (generated " + spec.generate + ")");
  return m;
}

double mean_boundary_edge(const mesh::TetMesh& mesh) {
  double sum = 0.0;
  for (const mesh::Triangle& f : mesh.boundary_faces)
    for (int k = 0; k < 3; ++k)
      sum += (mesh.nodes[f[k]] - mesh.nodes[f[(k + 1) % 3]]).norm();
  return sum / (3.0 * static_cast<double>(mesh.boundary_faces.size()));
}

/// Vertical distance (mm) between the two dies at zero displacement: lowest
/// point of the upper die above the highest point of the lower one.
double initial_die_gap(const std::vector<Die>& dies, int& upper) {
  auto z_range = [](const Die& d) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const mesh::Point& p : d.surface->triangles().vertices)
      low = std::min(low, p.z()), high = std::max(high, p.z());
    return std::pair{low, high};
  };
  const auto a = z_range(dies[0]), b = z_range(dies[1]);
  upper = a.first + a.second > b.first + b.second ? 0 : 1;
  return upper == 0 ? a.first - b.second : b.first - a.second;
}

} // namespace

Scene::Scene(const Case& c, Timers& timers) : input(c) {
  // The bodies are solved as one mesh of disjoint parts, each element with its body's law.
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const BodySpec& spec = c.bodies[b];
    MaterialCard card = read_material(spec.material_file);
    Body body;
    body.name = spec.name;
    body.material_file = spec.material_file;
    body.law = std::move(card.law);
    body.state.temperature = spec.temperature.value_or(card.temperature.value_or(20.0));
    const mesh::TetMesh part = build_mesh(spec.mesh);
    for (std::size_t i = 0; i < c.boundary.size(); ++i)
      if (c.boundary_body[i] == static_cast<int>(b)) body.conditions.push_back(c.boundary[i]);
    conditions.insert(conditions.end(), body.conditions.begin(), body.conditions.end());
    {
      Timers::Scope scope(timers, "effect boundary_conditions");
      body.initial_imposed = impose(part, body.conditions);
    }
    body.initial_volume = mesh::volume(part);
    body.remesh_size = c.remeshing.element_size > 0.0 ? c.remeshing.element_size : mean_boundary_edge(part);
    initial_ranges.push_back(mesh::append(initial_mesh, part));
    bodies.push_back(std::move(body));
  }
  std::vector<const material::Material*> laws;
  for (const Body& body : bodies)
    laws.push_back(body.law.get());
  solve_displacement = !c.time.enabled && std::all_of(laws.begin(), laws.end(),
                                                      [](const material::Material* l) { return l->is_elastic(); });
  for (Body& body : bodies)
    body.velocity_form = body.law->is_elastic() && !solve_displacement;
  carries_stress = std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.velocity_form; });
  effects = resolve_effects(c, laws);
  compensate_volume = std::find(effects.begin(), effects.end(), "volume_compensation") != effects.end();

  // Scales from the initial mesh, so that a resumed run uses the very same numbers.
  mesh::Point low = initial_mesh.nodes.front(), high = low;
  for (const auto& x : initial_mesh.nodes)
    low = low.cwiseMin(x), high = high.cwiseMax(x);
  body_size = (high - low).norm();
  reference_length = mean_boundary_edge(initial_mesh);
  {
    Timers::Scope scope(timers, "effect rigid_dies (setup)");
    for (const DieSpec& spec : c.dies)
      dies.push_back(build_die(spec, body_size));
  }
  for (std::size_t d = 0; d < dies.size(); ++d)
    surfaces.push_back({dies[d].name, int(d), -1});
  for (std::size_t i = 0; i < conditions.size(); ++i)
    if (conditions[i].prescribes_velocity() && conditions[i].kind != BoundaryKind::symmetry)
      surfaces.push_back({conditions[i].name, -1, int(i)});
  if (c.time.final_gap > 0.0) die_gap0 = initial_die_gap(dies, upper_die);

  // Speed at t = 0 over a short probe step (an increment is far longer).
  const double probe = 1e-3 * std::max(c.time.stroke_increment, 1e-6);
  for (const Die& d : dies)
    reference_velocity = std::max(reference_velocity, d.velocity(DieState{}, probe).norm());
  for (const Body& body : bodies) {
    const ImposedConditions& imposed = body.initial_imposed;
    for (int k = 0; k < imposed.values.size(); ++k)
      if (imposed.prescribed[k] && k % 4 != 3)
        reference_velocity = std::max(reference_velocity, std::abs(imposed.values[k]));
  }
  if (c.time.enabled && !(reference_velocity > 0.0))
    throw InputError(c.path + ": nothing moves at t = 0 (no moving die, no prescribed velocity): the time loop "
                              "needs a motion");
}

double Scene::die_gap(std::span<const DieState> dies_now) const {
  return die_gap0 + dies_now[upper_die].displacement.z() - dies_now[1 - upper_die].displacement.z();
}

RunState initial_state(const Scene& scene) {
  RunState state;
  state.mesh = scene.initial_mesh;
  state.bodies = scene.initial_ranges;
  state.unknowns = {Eigen::VectorXd::Zero(4 * state.mesh.node_count()),
                    Eigen::VectorXd::Zero(3 * state.mesh.tet_count())};
  state.equivalent_strain.assign(state.mesh.tets.size(), 0.0);
  if (scene.carries_stress) state.elastic_stress.assign(6 * state.mesh.tets.size(), 0.0);
  state.dies.assign(scene.dies.size(), DieState{});
  state.volume.initial = mesh::volume(state.mesh);
  state.inside_dies = inside_dies(scene, state);
  return state;
}

void check_resumable(const Scene& scene, const RunState& state) {
  if (state.dies.size() != scene.dies.size())
    throw InputError("checkpoint: " + std::to_string(state.dies.size()) + " dies, the case has " +
                     std::to_string(scene.dies.size()));
  // Until a remesh the bodies keep the meshes the case builds.
  bool same_bodies = state.bodies.size() == scene.bodies.size();
  for (std::size_t b = 0; same_bodies && state.remeshes.empty() && b < scene.bodies.size(); ++b)
    same_bodies = state.bodies[b].node_count == scene.initial_ranges[b].node_count &&
                  state.bodies[b].tet_count == scene.initial_ranges[b].tet_count;
  if (!same_bodies) throw InputError("checkpoint: the bodies do not match the case's (was the case changed?)");
  if (scene.carries_stress != !state.elastic_stress.empty())
    throw InputError("checkpoint: elastic stresses do not match the case's bodies (was the case changed?)");
}

double inside_dies(const Scene& scene, const mesh::TetMesh& mesh, const mesh::MeshRange& range, int body,
                   std::span<const DieState> dies_now) {
  double inside = 0.0;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    inside += die::overlap_volume(mesh, range, *scene.dies[d].surface, dies_now[d].displacement,
                                  scene.bodies[body].remesh_size);
  return inside;
}

std::vector<double> inside_dies(const Scene& scene, const RunState& state) {
  std::vector<double> inside(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    inside[b] = inside_dies(scene, state.mesh, state.bodies[b], int(b), state.dies);
  return inside;
}

} // namespace anvil::scene

#include "anvil/run/Increment.h"

#include "anvil/run/blows.h"

#include "anvil/core/log.h"

#include "anvil/contact/contact_scales.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/run/TimeStepControl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <span>

namespace anvil::run {

using namespace scene; // the loop runs on the scene's types throughout
namespace {

/// A closed die's flash stage runs at a fifth to a third of the nominal
/// increment (the displacement limit) while its overlap with the dies grows
/// every increment: a loss restored over the nominal increment leaves the
/// material 0.35-0.38 % behind at closure, over the increment itself (down
/// to this share of the nominal one) 0.04-0.13 % (hub flanges, 1 mm and
/// adaptive).
constexpr double kShortestRestore = 0.25;

/// Share of a body's volume free of the dies (Σ φ_e V_e / V) from which
/// the loss is given back in the free elements alone; below it the pressing
/// elements take a growing share, all of them alike when nothing is free.
constexpr double kFreeEnough = 0.5;

/// Contact pressure, as a share of the nodal flow stress, at which a node
/// presses fully on its die (φ = 0 in its elements): below it φ rises
/// linearly to 1, so that the shares are continuous in the velocities.
constexpr double kPressingPressure = 0.1;

/// Fastest push of a node out of a die it starts inside, as a share of the
/// reference (press) speed: ContactIncrement::recovery_speed. A remesh
/// leaves nodes up to two thirds of an element inside the dies where putting
/// them on would flatten an element; pushed out faster, they drive a flow
/// of their own that lowers the press load (docs/method.md, contact). The
/// projection after the increment takes them out geometrically where it can.
constexpr double kRecoverySpeed = 0.1;

/// The external vector of an increment of `dt`: the boundary tractions, and
/// the volume compensation of the incompressible bodies. The flow of the
/// increment is asked to restore the volume each lost so far (explicit
/// update error, O(Δt) over a run, and contact projection): ∫ q div v = ∫ q g
/// with g_e = w_e (V₀ − V_m)/(Σ w_e V_e Δt'), entered as the pressure rows of
/// the external vector (r_p = −∫N (div v − g)). V_m is the material: the mesh
/// less what overlaps the dies, which is not material and which a remesh's
/// put-back cuts off at once. Δt' = max(Δt, kShortestRestore × nominal):
/// each increment restores the whole loss, and one much shorter than the
/// nominal (a stop criterion, a cut) no more than that share of it, so that
/// it does not get a large dilatation. The loss goes where the material is
/// free to take it: w_e = φ_e + λ (1 − φ_e), with φ_e the element's freedom
/// from the dies (kPressingPressure) and λ = max(0, 1 − Σ φ V / (kFreeEnough
/// V)). Given to the elements against a die alike, much of it went into the
/// die's fillets between their nodes. `asked` is Σ g_e V_e Δt (mm³).
Eigen::VectorXd external_vector(const Scene& scene, const Discretisation& disc, const RunState& state, double dt,
                                double nominal, std::span<const double> flow_stress, double& asked) {
  Eigen::VectorXd external = disc.imposed.nodal_forces;
  asked = 0.0;
  if (!scene.compensate_volume) return external;
  std::vector<double> pressing(state.mesh.node_count(), 0.0); // 0 free, 1 pressing
  if (!scene.dies.empty()) {
    const auto& candidates = disc.die_contact.candidates();
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const int node = candidates[c].node;
      if (const double p = disc.die_contact.pressure(int(c), state.unknowns.nodal); p > 0.0)
        pressing[node] = std::min(p / (kPressingPressure * flow_stress[node]), 1.0);
    }
  }
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (std::isfinite(scene.bodies[b].law->bulk_modulus())) continue;
    const mesh::MeshRange& range = state.bodies[b];
    std::vector<double> free(range.tet_count), volumes(range.tet_count); // φ_e, V_e
    double volume = 0.0, free_volume = 0.0;
    for (int k = 0; k < range.tet_count; ++k) {
      const int e = range.first_tet + k;
      double most = 0.0;
      for (int node : state.mesh.tets[e])
        most = std::max(most, pressing[node]);
      free[k] = 1.0 - most;
      volumes[k] = mesh::signed_volume(state.mesh, e);
      volume += volumes[k];
      free_volume += free[k] * volumes[k];
    }
    const double spread = std::max(0.0, 1.0 - free_volume / (kFreeEnough * volume)); // λ
    const double taken = free_volume + spread * (volume - free_volume);              // Σ w_e V_e
    const double material = volume - state.inside_dies[b];
    const double g = (scene.bodies[b].initial_volume - material) / (taken * std::max(dt, kShortestRestore * nominal));
    asked += g * taken * dt;
    for (int k = 0; k < range.tet_count; ++k) {
      const double quarter = 0.25 * (free[k] + spread * (1.0 - free[k])) * volumes[k]; // ¼ w_e V_e
      for (int node : state.mesh.tets[range.first_tet + k])
        external[4 * node + 3] -= g * quarter;
    }
  }
  return external;
}

/// The law of each element over an increment of `dt`: its body's law, or for
/// an elastic body in velocity form that law over `dt` (σ = σ_n + Δt C:ε̇).
struct IncrementLaws {
  std::vector<std::unique_ptr<material::IncrementalElastic>> velocity_form; ///< the bodies' that need one
  fem::ElementLaws of_element;
};

IncrementLaws increment_laws(const Scene& scene, const Discretisation& disc, const RunState& state, double dt) {
  IncrementLaws laws{{}, disc.element_laws};
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (!scene.bodies[b].velocity_form) continue;
    laws.velocity_form.push_back(std::make_unique<material::IncrementalElastic>(
        dynamic_cast<const material::LinearElastic&>(*scene.bodies[b].law), dt));
    const mesh::MeshRange& range = state.bodies[b];
    std::fill_n(laws.of_element.begin() + range.first_tet, range.tet_count, laws.velocity_form.back().get());
  }
  return laws;
}

/// Newton on (v, p) from `guess` for an increment of `dt` from `state`, with contact scales `scales`.
IncrementOutcome solve_at(const Scene& scene, Discretisation& disc, const RunState& state, double dt, double nominal,
                          const contact::ContactScales& scales, const fem::BodyUnknowns& guess, Timers& timers) {
  // Candidates: boundary nodes that can reach a die or another body within the increment.
  std::vector<contact::DieView> views;
  double die_speed = 0.0, body_speed = 0.0;
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const Die& die = scene.dies[d];
    views.push_back({die.surface.get(), state.dies[d].displacement, die.velocity(state.dies[d], dt), die.friction});
    die_speed = std::max(die_speed, views.back().velocity.norm());
  }
  for (int i = 0; i < state.mesh.node_count(); ++i)
    body_speed = std::max(body_speed, state.unknowns.nodal.segment<3>(4 * i).norm());
  const double reach = 2.0 * (die_speed + std::max(body_speed, die_speed)) * dt + 0.05 * scene.reference_length;
  {
    Timers::Scope scope(timers, "search");
    if (!scene.dies.empty()) disc.die_contact.search(state.mesh, views, reach);
    if (disc.pair_contact) disc.pair_contact->search(state.mesh, reach);
  }
  // Gap tolerance: a penetration velocity of 1e-4 of the reference speed is
  // 1e-4 of the stroke over the run, and projection removes it anyway.
  const contact::ContactIncrement increment{
      .time_step = dt,
      .penalty = scales.penalty,
      .regularisation = scene.input.contact.regularisation * scene.reference_velocity,
      .gap_tolerance = 1e-4 * scene.reference_velocity,
      .recovery_time = nominal,
      .recovery_speed = scene.reference_velocity > 0.0 ? kRecoverySpeed * scene.reference_velocity
                                                       : std::numeric_limits<double>::infinity(),
      .flow_stress = scales.flow_stress,
      .consistency = scales.consistency};
  if (!scene.dies.empty()) disc.die_contact.set_increment(increment);
  if (disc.pair_contact) disc.pair_contact->set_increment(increment);

  IncrementOutcome out;
  out.time_step = dt;
  const Eigen::VectorXd external =
      external_vector(scene, disc, state, dt, nominal, scales.flow_stress, out.compensation);
  const IncrementLaws laws = increment_laws(scene, disc, state, dt);
  const solver::IncrementProblem problem{
      state.mesh, laws.of_element,           disc.point_states,        external,
      {},         disc.contact_terms(scene), scene.reference_velocity, scales.reference_force};
  out.unknowns = guess;
  Timers::Scope scope(timers, "newton");
  out.report = disc.solver->solve(problem, scene.input.newton, out.unknowns);
  out.failure = out.report.failure;
  return out;
}

/// Force (N) on every load surface at `inc`'s solution, in Scene::surfaces order.
std::vector<Eigen::Vector3d> surface_forces(const Scene& scene, const Discretisation& disc,
                                            const IncrementOutcome& inc) {
  const std::vector<Eigen::Vector3d> die_force =
      scene.dies.empty() ? std::vector<Eigen::Vector3d>{} : disc.die_contact.die_forces(inc.unknowns.nodal);
  std::vector<Eigen::Vector3d> forces;
  for (const LoadSurface& surface : scene.surfaces)
    // On a plate: minus the reaction on the body.
    forces.push_back(surface.die >= 0
                         ? die_force[surface.die]
                         : Eigen::Vector3d(-reaction(disc.imposed, surface.condition, disc.solver->residual())));
  return forces;
}

/// The loads.csv records of `forces`, solved on the geometry after
/// `increment` increments (`mesh` at time `time`, the dies at `dies`), with
/// the dies' fill there (die_fill); they replace records of that geometry
/// already there (a resumed run's last ones).
void append_loads(const Scene& scene, const mesh::TetMesh& mesh, std::span<const DieState> dies, int increment,
                  double time, const std::vector<Eigen::Vector3d>& forces, std::vector<LoadRecord>& loads,
                  Timers& timers) {
  std::vector<std::optional<contact::DieFill>> fills(scene.dies.size());
  if (std::find(scene.effects.begin(), scene.effects.end(), "die_fill") != scene.effects.end()) {
    Timers::Scope scope(timers, "effect die_fill");
    fills = die_fills(scene, mesh, dies, false);
  }
  std::erase_if(loads, [&](const LoadRecord& r) { return r.increment == increment; });
  for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
    LoadRecord record{increment, time, int(s), surface_stroke(scene, dies, int(s), time), forces[s]};
    const int die = scene.surfaces[s].die;
    if (die >= 0 && fills[die]) {
      record.contact_area = fills[die]->contact_area;
      record.fill = fills[die]->fraction();
    }
    loads.push_back(record);
  }
}

void count_iterations(const solver::NewtonReport& report, RunState& state) {
  state.newton_iterations += static_cast<int>(report.iterations.size());
  state.iterations.push_back({static_cast<int>(report.iterations.size()), report.linear_iterations});
}

} // namespace

double surface_stroke(const Scene& scene, std::span<const DieState> dies, int surface, double time) {
  const LoadSurface& s = scene.surfaces[surface];
  if (s.die >= 0) return dies[s.die].stroke;
  const auto& v = scene.conditions[s.condition].velocity;
  return time *
         std::sqrt(std::pow(v[0].value_or(0.0), 2) + std::pow(v[1].value_or(0.0), 2) + std::pow(v[2].value_or(0.0), 2));
}

IncrementOutcome solve_increment(const Scene& scene, Discretisation& disc, const RunState& state, const TimeStep& step,
                                 Timers& timers, ContactEvents events, const fem::BodyUnknowns* guess) {
  const contact::ContactScales scales = [&] {
    if (!scene.has_contact()) return contact::ContactScales{};
    std::vector<contact::ScaledBody> bodies;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      bodies.push_back({state.bodies[b], scene.bodies[b].law.get()});
    return contact::contact_scales(state.mesh, bodies, disc.element_laws, disc.point_states, state.unknowns,
                                   scene.reference_rate(), scene.body_size, scene.input.contact.penalty);
  }();
  const fem::BodyUnknowns& start = guess ? *guess : state.unknowns;
  IncrementOutcome out = solve_at(scene, disc, state, step.length, step.nominal, scales, start, timers);
  // A free node reaching a die inside the increment ends it there (contact
  // event): the overshoot left in a longer step is projected by the update.
  if (out.converged() && events == ContactEvents::end_increment && scene.input.time.enabled && !scene.dies.empty()) {
    const double touch = disc.die_contact.first_contact_time(out.unknowns.nodal, 1e-3 * scene.reference_length);
    if (TimeStepControl(scene).ends_at_contact(step, touch))
      out = solve_at(scene, disc, state, touch, step.nominal, scales, start, timers);
  }
  if (out.converged()) {
    out.forces = surface_forces(scene, disc, out);
    out.fields = fem::element_fields(state.mesh, increment_laws(scene, disc, state, out.time_step).of_element,
                                     disc.point_states, out.unknowns);
  }
  return out;
}

IncrementOutcome solve_coupled(const Scene& scene, Discretisation& disc, const RunState& state, const TimeStep& step,
                               Timers& timers, const fem::BodyUnknowns* guess) {
  const double tolerance = scene.input.thermal.coupling_tolerance;
  const bool iterated = disc.heat && tolerance > 0.0;
  // The flow starts from T_n, also when retrying a cut step.
  if (iterated) element_temperatures(state.mesh, state.temperature, disc.point_states);
  IncrementOutcome inc = solve_increment(scene, disc, state, step, timers, ContactEvents::end_increment, guess);
  if (!iterated) return inc;
  constexpr int kMostCouplings = 5;
  for (; inc.converged(); ++inc.couplings) {
    std::vector<double> end;
    {
      Timers::Scope scope(timers, "effect heat");
      end = disc.heat->predict(scene, state, disc.heat_contacts(scene, inc.unknowns.nodal), inc.fields, inc.time_step);
    }
    double change = 0.0;
    for (int e = 0; e < state.mesh.tet_count(); ++e) {
      const double mean = thermal::element_mean(state.mesh.tets[e], end);
      change = std::max(change, std::abs(mean - disc.point_states[e].temperature));
      disc.point_states[e].temperature = mean;
    }
    if (change <= tolerance) return inc;
    if (inc.couplings == kMostCouplings) {
      inc.report.converged = false;
      inc.failure = "heat and flow still differ by " + std::to_string(change) + " C after " +
                    std::to_string(kMostCouplings) + " coupled solves (thermal.coupling_tolerance " +
                    std::to_string(tolerance) + " C)";
      return inc;
    }
    const int couplings = inc.couplings;
    TimeStep again = step;
    again.length = inc.time_step;
    inc = solve_increment(scene, disc, state, again, timers, ContactEvents::ignore);
    inc.couplings = couplings;
  }
  return inc;
}

namespace {

/// Die wear over an increment of `dt` s (effect die_wear): each worn die's
/// vertices under the part's contact nodes at the start of the increment
/// wear at the rate of that node's pressure and sliding speed
/// (contact/die_wear.h). `state` is the increment's start.
void add_die_wear(const Scene& scene, const Discretisation& disc, const Eigen::VectorXd& nodal, double dt,
                  RunState& state) {
  if (std::none_of(scene.dies.begin(), scene.dies.end(), [](const Die& d) { return d.wear.has_value(); })) return;
  const mesh::TetMesh& mesh = state.mesh;
  const std::vector<contact::ContactCandidate>& candidates = disc.die_contact.candidates();
  // A node's contact area is that of the boundary faces at it that face its
  // die: contact spreads a node's force over all its boundary faces, so at
  // an edge or a corner of the contact its pressure would read low.
  std::vector<int> candidate_of(mesh.nodes.size(), -1);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (scene.dies[candidates[i].die].wear) candidate_of[candidates[i].node] = static_cast<int>(i);
  std::vector<double> facing(mesh.nodes.size(), 0.0);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const Eigen::Vector3d a = mesh::area_vector(mesh, mesh.boundary_faces[f]);
    for (int node : mesh.boundary_faces[f])
      if (const int i = candidate_of[node]; i >= 0 && a.dot(candidates[i].normal) < -0.5 * a.norm())
        facing[node] += a.norm() / 3.0;
  }
  std::vector<std::vector<contact::WearPoint>> points(scene.dies.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const contact::ContactCandidate& c = candidates[i];
    const std::optional<contact::WearLaw>& law = scene.dies[c.die].wear;
    if (!law || facing[c.node] <= 0.0) continue;
    const double pressure = disc.die_contact.pressure(static_cast<int>(i), nodal) * c.area / facing[c.node];
    if (pressure <= 0.0) continue;
    // A square patch of the node's area reaches 1/√2 of its side from the node; a little more.
    points[c.die].push_back({mesh.nodes[c.node] - c.gap * c.normal - state.dies[c.die].displacement,
                             law->rate(pressure, disc.die_contact.sliding_speed(static_cast<int>(i), nodal)),
                             0.75 * std::sqrt(facing[c.node])});
  }
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (scene.dies[d].wear) contact::add_wear(scene.dies[d].shown().vertices, points[d], dt, state.wear[d]);
}

/// Wear of the meshed dies over the increment: each worn body's boundary
/// nodes under a touching projected node of a contact pair it is in (the
/// node's pressure, its sliding speed relative to the other body, its area
/// facing it) wear at that node's rate, divided by the die's H^c at the die
/// node (its card's table at the node's temperature, when read there).
void add_body_wear(const Scene& scene, const Discretisation& disc, const Eigen::VectorXd& nodal, double dt,
                   RunState& state) {
  if (!disc.pair_contact ||
      std::none_of(scene.bodies.begin(), scene.bodies.end(), [](const Body& b) { return b.wear.has_value(); }))
    return;
  const mesh::TetMesh& mesh = state.mesh;
  const contact::BodyContact& pairs = *disc.pair_contact;
  const std::vector<char> on_boundary = mesh::boundary_node_flags(mesh);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const std::optional<contact::WearLaw>& law = scene.bodies[b].wear;
    if (!law) continue;
    const mesh::MeshRange& body = state.bodies[b];
    contact::WearLaw unit_hardness = *law; // H^c is the die node's: applied where the wear lands
    unit_hardness.hardness = 1.0;
    std::vector<contact::WearPoint> points;
    for (std::size_t i = 0; i < pairs.projected_nodes().size(); ++i) {
      const contact::ContactPoint& p = pairs.projected_nodes()[i];
      const contact::BodyPair& pair = pairs.pairs()[p.pair];
      if (pair.master.first_node != body.first_node && pair.slave.first_node != body.first_node) continue;
      // The other body's nodes sample the contact, as the part's nodes do on
      // a rigid die (a quasi-symmetric master node's λ̃ swings as the other
      // mesh slides by); the die's own where only they are projected (the
      // die the slave of a master/slave pair).
      const bool own = p.node() >= body.first_node && p.node() < body.first_node + body.node_count;
      const bool only_own =
          pair.method.formulation == contact::PairFormulation::master_slave && pair.slave.first_node == body.first_node;
      if (own != only_own) continue;
      const double pressure = pairs.node_pressure(static_cast<int>(i), nodal);
      if (pressure <= 0.0) continue;
      const Eigen::Vector3d sliding =
          (Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose()) * contact::relative_velocity(p, nodal);
      points.push_back({mesh.nodes[p.node()], unit_hardness.rate(pressure, sliding.norm()), 0.75 * std::sqrt(p.area)});
    }
    std::vector<mesh::Point> nodes(mesh.nodes.begin() + body.first_node,
                                   mesh.nodes.begin() + body.first_node + body.node_count);
    std::vector<double> scale(nodes.size(), 0.0); // 1/H^c, nil off the boundary
    for (int i = 0; i < body.node_count; ++i) {
      if (!on_boundary[body.first_node + i]) continue;
      const Body& die = scene.bodies[b];
      double hardness = law->hardness;
      if (die.hardness) {
        const double t = !std::isnan(die.wear_temperature) ? die.wear_temperature
                         : !state.temperature.empty()      ? state.temperature[body.first_node + i]
                                                           : die.state.temperature;
        hardness = die.hardness->at(t);
      }
      scale[i] = std::pow(hardness, -law->hardness_exponent);
    }
    contact::add_wear(nodes, points, dt, state.body_wear[b], scale);
  }
}

} // namespace

bool accept_increment(const Scene& scene, Discretisation& disc, IncrementOutcome& inc, RunState& state,
                      Timers& timers) {
  Timers::Scope scope(timers, "update");
  const double dt = inc.time_step;
  // The new geometry is built apart and taken only when no element inverts.
  mesh::TetMesh moved = state.mesh;
  std::vector<DieState> dies = state.dies;
  const double volume_before = mesh::volume(state.mesh);
  for (int i = 0; i < moved.node_count(); ++i)
    moved.nodes[i] += dt * inc.unknowns.nodal.segment<3>(4 * i);
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    scene.dies[d].advance(dies[d], dt);
  const double volume_flow = mesh::volume(moved);
  // Contact nodes back onto their die at its new position, along the node's
  // free directions only (a node on a symmetry plane stays on it), and not
  // where the move would take an element below the remesher's own floor (or
  // below what it is, if less): a node left inside by a remesh's put-back,
  // where the die corner needs an element flattened, stays in until the next
  // remesh rather than leave a flat element (quality 1e-15 on hot_conrod),
  // whose conduction the heat step cannot solve, or end the run.
  const auto& candidates = disc.die_contact.candidates();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const contact::ContactCandidate& c = candidates[i];
    const Eigen::Vector3d& shift = dies[c.die].displacement;
    const die::DieSurface& surface = *scene.dies[c.die].surface;
    const die::SurfaceProjection p = surface.project(moved.nodes[c.node] - shift);
    if (disc.die_contact.pressure(int(i), inc.unknowns.nodal) <= 0.0 && p.distance >= 0.0) continue;
    const std::array<bool, 3> free{!disc.imposed.prescribed[4 * c.node], !disc.imposed.prescribed[4 * c.node + 1],
                                   !disc.imposed.prescribed[4 * c.node + 2]};
    const mesh::Point& x = moved.nodes[c.node];
    disc.projection_guard.move(moved, c.node,
                               shift + die::project_keeping(surface, x - shift, free, 1e-9 * scene.reference_length),
                               scene.input.remeshing.worst_allowed_quality());
  }
  for (int e = 0; e < moved.tet_count(); ++e)
    if (mesh::signed_volume(moved, e) <= 0.0) {
      inc.failure = "element " + std::to_string(e + 1) + " would invert";
      return false;
    }

  const double volume_after = mesh::volume(moved);
  // A flow's loads were solved on the geometry where the increment starts
  // (its strain rates there, ε̄ and T at its start): they are recorded at
  // its stroke and time. Elastic bodies' loads hold at its end.
  if (!scene.all_elastic)
    append_loads(scene, state.mesh, state.dies, state.increment, state.time, inc.forces, state.loads, timers);
  add_die_wear(scene, disc, inc.unknowns.nodal, dt, state);
  add_body_wear(scene, disc, inc.unknowns.nodal, dt, state);
  state.mesh.nodes = std::move(moved.nodes); // the elements stay: the discretisation holds on to them
  state.dies = std::move(dies);
  state.unknowns = std::move(inc.unknowns);
  if (scene.all_elastic)
    append_loads(scene, state.mesh, state.dies, state.increment + 1, state.time + dt, inc.forces, state.loads, timers);
  state.volume.solver += volume_flow - volume_before;
  state.volume.compensation += inc.compensation;
  state.volume.projection += volume_after - volume_flow;
  state.volume.largest_increment =
      std::max(state.volume.largest_increment, std::abs(volume_after - volume_before) / volume_before);
  {
    Timers::Scope overlap(timers, "die overlap");
    state.inside_dies = inside_dies(scene, state);
  }
  ++state.increment;
  state.time += dt;
  count_iterations(inc.report, state);
  // ε̄ += Δt ε̄̇ per element, with the rates on the geometry solved on.
  for (int e = 0; e < state.mesh.tet_count(); ++e) {
    state.equivalent_strain[e] += dt * inc.fields.rate[e];
    disc.point_states[e].equivalent_strain = state.equivalent_strain[e];
  }
  // D += f(σ) Δε̄ per element of the flowing bodies, with the stress and rate
  // of the same solve (material/damage.h).
  if (!scene.input.damage.empty())
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      if (scene.bodies[b].law->is_elastic()) continue;
      const mesh::MeshRange& r = state.bodies[b];
      for (int e = r.first_tet; e < r.first_tet + r.tet_count; ++e) {
        const material::DamageStress sigma = material::damage_stress(inc.fields.stress[e]); // once for all criteria
        for (std::size_t k = 0; k < scene.input.damage.size(); ++k)
          state.damage[k][e] += material::damage_weight(scene.input.damage[k], sigma) * dt * inc.fields.rate[e];
      }
    }
  // σ_{n+1} = σ_n + Δt C:ε̇ in elastic bodies (IncrementalElastic): the stress just solved.
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (scene.bodies[b].velocity_form)
      for (int e = state.bodies[b].first_tet; e < state.bodies[b].first_tet + state.bodies[b].tet_count; ++e) {
        disc.point_states[e].elastic_stress = inc.fields.stress[e];
        Eigen::Map<material::Vec6>(&state.elastic_stress[6 * e]) = inc.fields.stress[e];
      }
  // A load-limited press slows down for the next increment; an energy press
  // goes on at the speed its blow's energy left gives (run/blows.h).
  const double rate_sensitivity = scene.bodies.front().law->rate_sensitivity(disc.point_states.front());
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const Eigen::Vector3d v = scene.dies[d].velocity(state.dies[d], dt);
    if (v.norm() == 0.0) continue;
    // The press's limit and energy hold for the whole part, not for a symmetry model of it.
    const double resisting = scene.symmetry_copies * inc.forces[d].dot(-v.normalized());
    scene.dies[d].limit_speed(state.dies[d], resisting, rate_sensitivity);
    if (scene.dies[d].energy) spend_blow_energy(scene, static_cast<int>(d), resisting, v.norm() * dt, state);
  }
  return true;
}

void advance_heat(const Scene& scene, Discretisation& disc, const IncrementOutcome& inc, RunState& state,
                  Timers& timers) {
  Timers::Scope scope(timers, "effect heat");
  disc.heat->advance(scene, state, disc.heat_contacts(scene, state.unknowns.nodal), &inc.fields, inc.time_step);
  element_temperatures(state.mesh, state.temperature, disc.point_states);
}

void heat_alone(const Scene& scene, Discretisation& disc, RunState& state, double dt, int steps, Timers& timers) {
  Timers::Scope scope(timers, "effect heat");
  // Bodies resting on each other exchange where they touch (nothing moves: one search).
  if (disc.pair_contact) disc.pair_contact->search(state.mesh, 0.05 * scene.reference_length);
  for (int k = 0; k < steps; ++k)
    disc.heat->advance(scene, state, {nullptr, disc.pair_contact.get(), disc.symmetry_faces, nullptr}, nullptr, dt);
  element_temperatures(state.mesh, state.temperature, disc.point_states);
}

void transfer(const Scene& scene, Discretisation& disc, RunState& state, Timers& timers) {
  const ThermalSpec& spec = scene.input.thermal;
  heat_alone(scene, disc, state, spec.transfer_time / spec.transfer_steps, spec.transfer_steps, timers);
  state.transfer_time = spec.transfer_time;
}

void record_final_loads(const Scene& scene, Discretisation& disc, RunState& state, double dt, Timers& timers) {
  if (scene.all_elastic) return; // the last increment's loads are those of its end already
  // The dies at their place, at the speed of the last increment (a table or
  // a crank that ends there would otherwise stand still).
  RunState end = state;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    end.dies[d].press_time -= end.dies[d].speed_factor * dt;
  // Much as an increment is solved: Newton that ran out of both its budgets
  // while its residual fell goes on from its last iterate at the same step
  // (a record, not a step of the run), else a shorter step.
  TimeStep step{.nominal = dt, .planned = dt, .length = dt};
  IncrementOutcome inc = solve_increment(scene, disc, end, step, timers, ContactEvents::ignore);
  for (int tries = 0; !inc.converged() && !inc.report.interrupted && tries < scene.input.time.max_cuts; ++tries) {
    const bool on_its_way = inc.report.on_its_way();
    if (!on_its_way) step.length *= 0.5;
    const fem::BodyUnknowns stopped_at = on_its_way ? std::move(inc.unknowns) : fem::BodyUnknowns{};
    inc = solve_increment(scene, disc, end, step, timers, ContactEvents::ignore, on_its_way ? &stopped_at : nullptr);
  }
  if (inc.converged())
    append_loads(scene, state.mesh, state.dies, state.increment, state.time, inc.forces, state.loads, timers);
  else
    log::info("the loads at the final geometry are not recorded: %s", inc.failure.c_str());
}

void accept_without_motion(const Scene& scene, const IncrementOutcome& inc, RunState& state, Timers& timers) {
  state.increment = 1;
  state.unknowns = inc.unknowns;
  count_iterations(inc.report, state);
  append_loads(scene, state.mesh, state.dies, 1, 0.0, inc.forces, state.loads, timers);
}

Advance advance(const Scene& scene, Discretisation& disc, RunState& state, const TimeStepControl& clock, TimeStep step,
                Timers& timers) {
  IncrementOutcome inc = solve_coupled(scene, disc, state, step, timers);
  // An energy press's last increment of a blow is fitted to spend its energy:
  // a few solves, the load hardly depending on Δt.
  constexpr int kMaxBlowFits = 4;
  for (int cuts = 0, fits = 0;;) {
    if (inc.converged()) {
      if (const std::optional<double> spending =
              fits < kMaxBlowFits ? step_spending_blow(scene, state, inc) : std::nullopt) {
        if (fits++ == 0)
          log::info("  increment %d: the blow's energy is spent within it: dt %.4g s -> %.4g s", state.increment + 1,
                    inc.time_step, *spending);
        step.length = *spending;
        inc = solve_coupled(scene, disc, state, step, timers);
        continue;
      }
      if (accept_increment(scene, disc, inc, state, timers)) break;
    }
    if (inc.report.interrupted) return {Advance::End::interrupted, std::move(inc)};
    const std::optional<double> shorter = clock.cut(inc.time_step, cuts++);
    if (!shorter) return {Advance::End::failed, std::move(inc)};
    step.length = *shorter;
    log::info("  increment %d: %s; retrying with dt = %.4g s (cut %d of %d)", state.increment + 1, inc.failure.c_str(),
              step.length, cuts, scene.input.time.max_cuts);
    // From the last iterate when the residual fell: the flow hardly depends on Δt.
    const bool on_its_way = inc.report.on_its_way();
    const fem::BodyUnknowns stopped_at = on_its_way ? std::move(inc.unknowns) : fem::BodyUnknowns{};
    inc = solve_coupled(scene, disc, state, step, timers, on_its_way ? &stopped_at : nullptr);
  }
  return {Advance::End::accepted, std::move(inc)};
}

} // namespace anvil::run

#include "anvil/remesh/Remesher.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/die/overlap_volume.h"
#include "anvil/io/Checkpoint.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/mesh/grid_snap.h"
#include "anvil/mesh/manifold.h"
#include "anvil/mesh/node_budget.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/die_feature_depth.h"
#include "anvil/remesh/expected_nodes.h"
#include "anvil/remesh/field_transfer.h"
#include "anvil/remesh/fit_to_dies.h"
#include "anvil/remesh/free_surface_tags.h"
#include "anvil/remesh/local_remesh.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/remesh_body.h"
#include "anvil/remesh/remesh_progress.h"
#include "anvil/remesh/remesh_tries.h"
#include "anvil/remesh/size_field.h"
#include "anvil/thermal/HeatStep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>
#include <optional>
#include <stop_token>

namespace anvil::remesh {
namespace {

/// One body's new mesh, the best of up to four tries.
struct Remeshed {
  mesh::TetMesh remeshed;   ///< CGAL's mesh of the old body: the fields are transferred onto it
  mesh::TetMesh mesh;       ///< the same, fitted to the dies
  double edge_length = 0.0; ///< mm
  double expected = 0.0;    ///< the nodes estimated before CGAL ran (remesh/expected_nodes.h)
  double worst = 0.0;       ///< worst quality of `mesh`
  PutBack put_back;
  double volume_put_back = 0.0;   ///< mm³, of `mesh` after the put-back, before keep_material
  double given_back = 0.0;        ///< mm, keep_material's move of the free surface
  std::string failed;             ///< why CGAL's mesh could not be made or used; empty when it was
  std::vector<log::HeldLine> log; ///< what making it logged, written when the try is taken up
};

/// A remesh may not change the body's volume by more than this before the
/// put-back onto the dies (CGAL's own loss; the cases lose below 0.01 %).
constexpr double kMostVolumeChange = 0.01;
/// Bisections of the coarsening that meets the node budget (to 1e-9 of it).
constexpr int kCoarsenBisections = 40;
/// Why a try run beside a good enough one was not made to its end (never taken up).
constexpr const char* kNotNeeded = "stopped: another try was good enough";

/// What is wrong with the shape of a remeshed body `after` (to follow "it
/// is"), empty when nothing: it is not a manifold, or it was a ball
/// (`was_ball`, mesh::is_ball) and is no longer, from which CGAL refuses to
/// build a triangulation at every remesh after (the connecting rod near
/// closure).
std::string shape_fault(bool was_ball, const mesh::TetMesh& after) {
  if (const std::string pinch = mesh::manifold_fault(after); !pinch.empty()) return "not a manifold: " + pinch;
  if (was_ball && !mesh::is_ball(after))
    return "no longer bounded by one closed surface (a second part, a cavity or a hole through)";
  return {};
}

/// Remeshes `part`, body `b` of `state` (`in_old` locates points in it;
/// `ball`: whether it is one, mesh::is_ball), fitted to the dies; nothing,
/// with `refused` saying why, when no try keeps the body's volume and an
/// acceptable worst quality.
std::optional<Remeshed> remesh_part(const scene::Scene& scene, const scene::RunState& state, int b,
                                    const mesh::TetMesh& part, bool ball, const PointLocator& in_old,
                                    std::span<const int> touching_die, std::span<const double> rate, double material,
                                    std::string& refused) {
  const scene::RemeshSpec& spec = scene.input.remeshing;
  const scene::Body& body = scene.bodies[b];
  // By default half the element size, or a smaller size box's size (a
  // given smallest_size is at most the boxes' sizes: read_case checks it).
  double smallest = spec.smallest_size > 0.0 ? spec.smallest_size : 0.5 * body.remesh_size;
  for (const scene::SizeBox& box : spec.size_boxes)
    smallest = std::min(smallest, box.size);
  const auto size_field =
      spec.adaptive ? adaptive_size(part, in_old, rate, scene, state.dies, body.remesh_size, smallest) : nullptr;
  // The node budget: sizes that would make more nodes than this machine can
  // solve are coarsened all alike until they fit.
  const double budget =
      spec.max_nodes > 0 ? std::min<double>(spec.max_nodes, mesh::affordable_nodes()) : mesh::affordable_nodes();
  double coarsen = 1.0;
  const ExpectedNodes terms = expected_nodes(
      part, [&](const mesh::Point& x) { return size_field ? size_field(x, 1.0) : body.remesh_size; }, body.remesh_size,
      size_field ? smallest : body.remesh_size);
  double expected = terms.at(1.0);
  if (expected > budget) {
    // terms.at(c) falls with c from above the budget at 1 to below it at
    // √(expected / budget): bisected between.
    double low = 1.0, high = std::sqrt(expected / budget);
    for (int step = 0; step < kCoarsenBisections; ++step)
      (terms.at(0.5 * (low + high)) > budget ? low : high) = 0.5 * (low + high);
    coarsen = high;
    log::info("    remesh of '%s': its sizes would make about %.3g nodes, more than the node budget of %.3g; "
              "every size is made %.3f times larger",
              body.name.c_str(), expected, budget, coarsen);
    expected = terms.at(coarsen);
  }
  const RemeshProgress progress(body.name, expected);
  const auto deadline = deadline_in(spec.time_limit);
  auto make = [&](const RemeshTry& to, std::stop_token stop) {
    const auto [scale, feature_angle, free_surface] = to;
    RemeshSettings settings;
    settings.deadline = deadline;
    settings.stop = stop;
    settings.edge_length = coarsen * scale * body.remesh_size;
    settings.feature_angle = feature_angle;
    settings.iterations = spec.iterations;
    settings.quality_floor = spec.quality;
    settings.grid = mesh::remesh_grid(body.remesh_size, state.remeshes.size());
    if (size_field) {
      settings.smallest_edge_length = coarsen * scale * smallest;
      settings.size = [&size_field, s = coarsen * scale](const mesh::Point& x) { return size_field(x, s); };
    }
    Remeshed t;
    const log::Holding holding(t.log);
    t.edge_length = settings.edge_length;
    t.expected = terms.at(coarsen * scale);
    try {
      if (free_surface) {
        mesh::TetMesh freed = part;
        free_surface_tags(freed, body.conditions);
        t.remeshed = remesh_body(freed, settings);
      } else {
        t.remeshed = remesh_body(part, settings);
      }
    } catch (const RunError& error) {
      t.failed = error.what();
      return t;
    } catch (const RemeshStopped& stopped) {
      char text[120];
      std::snprintf(text, sizeof text, "CGAL was still at work after remeshing.time_limit (%g s)", spec.time_limit);
      t.failed = stopped.out_of_time ? text : kNotNeeded;
      return t;
    }
    if (stop.stop_requested()) {
      t.failed = kNotNeeded;
      return t;
    }
    t.mesh = t.remeshed;
    t.put_back = put_onto_dies(t.mesh, part, touching_die, scene, b, state.dies, settings.edge_length, spec.quality);
    t.volume_put_back = mesh::volume(t.mesh);
    t.given_back = keep_material(t.mesh, scene, b, state.dies, material, settings.edge_length);
    t.worst = worst_quality(t.mesh);
    return t;
  };
  // A mesh already below the floor is replaced by any better one: kept, its
  // worst element is crushed further by the next increments until one
  // inverts (the connecting rod under a die edge: 0.001 kept against 0.04).
  const double volume = mesh::volume(part), floor = std::min(spec.worst_allowed_quality(), worst_quality(part));
  // Why try `t` cannot replace the body's mesh; empty when it can.
  auto fault = [&](const Remeshed& t) {
    if (!t.failed.empty()) return t.failed;
    char text[200] = "";
    const double change = mesh::volume(t.remeshed) / volume - 1.0;
    if (std::abs(change) > kMostVolumeChange)
      std::snprintf(text, sizeof text, "the new mesh changes the volume by %+.2f%% (at most %.0f%%)", 100.0 * change,
                    100.0 * kMostVolumeChange);
    else if (!(t.worst >= floor))
      std::snprintf(text, sizeof text,
                    "its worst element has quality %.3f, below %.3g (a third of remeshing.quality, or the old mesh's "
                    "worst)",
                    t.worst, floor);
    else if (const std::string shape = shape_fault(ball, t.mesh); !shape.empty())
      return "the new mesh is " + shape;
    else if (const std::string lost = scene::condition_losing_faces(body.conditions, part, t.mesh); !lost.empty())
      return "the new mesh has no face for boundary " + lost;
    return std::string(text);
  };
  const auto tries = remesh_tries(spec.feature_angle); // the best acceptable one is kept
  // The tries do not depend on each other: as many run at once as this
  // process has cores, and they are taken up one after the other as if made
  // so, which gives the same mesh on any number of cores. Those beside a try
  // that is good enough are stopped, not waited for.
  const std::size_t at_once = std::max(1, processes::available_cores());
  std::optional<Remeshed> best;
  auto done = [&] { return best && (best->worst >= spec.quality || std::chrono::steady_clock::now() > deadline); };
  for (std::size_t first = 0; first < tries.size() && !done(); first += at_once) {
    const std::size_t end = std::min(tries.size(), first + at_once);
    std::stop_source not_needed;
    std::vector<std::future<Remeshed>> beside;
    for (std::size_t k = first + 1; k < end; ++k)
      beside.push_back(std::async(std::launch::async,
                                  [&make, &tries, k, stop = not_needed.get_token()] { return make(tries[k], stop); }));
    Remeshed own = make(tries[first], {});
    for (std::size_t k = first; k < end && !(k > first && done()); ++k) {
      const auto& [scale, angle, free_surface] = tries[k];
      Remeshed again = k == first ? std::move(own) : beside[k - first - 1].get();
      log::write_held(again.log);
      const std::string why = fault(again);
      const char* surface = free_surface ? ", the billet's faces one free surface" : "";
      if (!again.failed.empty())
        log::info("    remesh of '%s' with h %.3g mm, feature angle %.0f deg%s not made: %s", body.name.c_str(),
                  again.edge_length, angle, surface, why.c_str());
      else if (scale != 1.0 || angle != spec.feature_angle || free_surface || !why.empty())
        log::info("    remesh of '%s' with h %.3g mm, feature angle %.0f deg%s: worst quality %.3f%s%s",
                  body.name.c_str(), again.edge_length, angle, surface, again.worst,
                  why.empty() ? "" : "; not taken: ", why.c_str());
      if (why.empty() && (!best || again.worst > best->worst))
        best = std::move(again);
      else if (!best)
        refused = why;
    }
    not_needed.request_stop(); // before `beside` is destroyed, which waits for its tries
  }
  return best;
}

/// Logs what fitting a new mesh to the dies did: `put_back` took its volume
/// from `remeshed` to `put_back_volume` (mm³), and the material given back
/// (the free surface moved `given_back`, mm) to `after`.
void log_fit(const PutBack& put_back, double remeshed, double put_back_volume, double given_back, double after) {
  if (put_back.nodes + put_back.closed > 0)
    log::info("    put onto the dies: %d new boundary nodes inside them (deepest %.3g mm; %d with the interior under "
              "them), %d off them where the old surface touched (widest gap %.3g mm): volume %+.4f%% (contact "
              "projection)",
              put_back.nodes, put_back.deepest, put_back.carried, put_back.closed, put_back.widest,
              100.0 * relative(put_back_volume, remeshed));
  if (put_back.left > 0)
    log::info("    left inside the dies: %d new boundary nodes (deepest %.3g mm): moving them would spoil an element",
              put_back.left, put_back.deepest_left);
  if (given_back != 0.0)
    log::info("    material given back: the free surface moved %+.3g mm along its outward normal, volume %+.4f%%",
              given_back, 100.0 * relative(after, put_back_volume));
}

/// How much more of body `b` lies inside the dies at `dies_now` as the mesh
/// `after` than as `before` (each the body alone), mm³: the share of the
/// faces of its surface that changed (die::overlap_change), as
/// scene::inside_dies measures it.
double inside_dies_change(const scene::Scene& scene, const mesh::TetMesh& before, const mesh::TetMesh& after, int b,
                          std::span<const scene::DieState> dies_now) {
  double change = 0.0;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    change += die::overlap_change(before, after, *scene.dies[d].surface, dies_now[d].displacement,
                                  scene.bodies[b].remesh_size);
  return change;
}

void remesh_bodies(const scene::Scene& scene, scene::RunState& state, std::span<const RemeshDue> due,
                   std::span<const int> touching_die, std::span<const double> rate, double time_step, Timers& timers) {
  Timers::Scope scope(timers, "remeshing");
  const bool carries_stress = !state.elastic_stress.empty();
  const bool thermal = !state.temperature.empty();
  const bool flow_lines = !state.material_position.empty();
  mesh::TetMesh next;
  std::vector<mesh::MeshRange> ranges;
  std::vector<double> nodal, strain, stress, temperature, material;
  std::vector<std::vector<double>> damage(state.damage.size());
  auto append_values = [](std::vector<double>& to, const double* first, std::size_t count) {
    to.insert(to.end(), first, first + count);
  };
  // mm³ per body before the remesh: inside the dies, and the material (the mesh less that).
  const std::vector<double> inside_before = state.inside_dies;
  std::vector<double> material_before(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    material_before[b] = mesh::volume(state.mesh, state.bodies[b]) - inside_before[b];
  const std::size_t first_record = state.remeshes.size();
  // Per record from first_record: whether the remesh fitted the body's
  // surface to the dies (a whole remesh, a local one around sunk die
  // corners or edges); another leaves the dies' triggers to the last fit
  // (remesh_due).
  std::vector<char> fitted;
  // mm³ per body inside the dies after the remesh, where it follows from
  // before: a kept mesh's is as it was, a local remesh's changes by its
  // changed faces' share (their search is most of a local remesh's cost
  // otherwise); a whole remesh's is measured anew.
  std::vector<std::optional<double>> inside_after(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const auto start = std::chrono::steady_clock::now();
    const mesh::MeshRange& range = state.bodies[b];
    const mesh::TetMesh part = mesh::extract(state.mesh, range);
    const double* part_nodal = state.unknowns.nodal.data() + 4 * range.first_node;
    const std::vector<double> part_strain(state.equivalent_strain.begin() + range.first_tet,
                                          state.equivalent_strain.begin() + range.first_tet + range.tet_count);
    std::vector<std::vector<double>> part_damage;
    for (const std::vector<double>& d : state.damage)
      part_damage.emplace_back(d.begin() + range.first_tet, d.begin() + range.first_tet + range.tet_count);
    const auto why = std::find_if(due.begin(), due.end(), [&](const RemeshDue& d) { return d.body == int(b); });
    const double* part_temperature = thermal ? state.temperature.data() + range.first_node : nullptr;
    const double* part_material = flow_lines ? state.material_position.data() + 3 * range.first_node : nullptr;
    auto keep_mesh = [&] {
      inside_after[b] = inside_before[b];
      ranges.push_back(mesh::append(next, part));
      append_values(nodal, part_nodal, 4 * range.node_count);
      if (thermal) append_values(temperature, part_temperature, range.node_count);
      if (flow_lines) append_values(material, part_material, 3 * range.node_count);
      append_values(strain, part_strain.data(), part_strain.size());
      for (std::size_t k = 0; k < damage.size(); ++k)
        append_values(damage[k], part_damage[k].data(), part_damage[k].size());
      if (carries_stress) append_values(stress, &state.elastic_stress[6 * range.first_tet], 6 * range.tet_count);
    };
    if (why == due.end()) {
      keep_mesh();
      continue;
    }
    auto body_fields = [&] {
      BodyFields fields{
          part,
          Eigen::Map<const Eigen::VectorXd>(part_nodal, 4 * range.node_count),
          part_strain,
          part_damage,
          {},
          {},
          {touching_die.begin() + range.first_node, touching_die.begin() + range.first_node + range.node_count}};
      if (thermal) fields.temperature.assign(part_temperature, part_temperature + range.node_count);
      if (flow_lines) fields.material.assign(part_material, part_material + 3 * range.node_count);
      return fields;
    };
    // Region::due for a local trigger; a periodic remesh rebuilds the whole
    // body with its contact surface kept (at a uniform size: an adaptive
    // field takes CGAL's levels below); short of those, the whole body is
    // remeshed freely. A trigger that fits the dies (a die corner, the
    // overlap, poor elements the region could not mend) goes on remeshing
    // freely: keeping the contact surface did not lower its load jump on
    // the hub flange (docs/remeshing.md).
    const bool ball = mesh::is_ball(part);
    std::optional<LocalRemesh> local;
    std::string whole;
    Region region = Region::due;
    auto try_region = [&](Region choice) {
      region = choice;
      local = remesh_locally(scene, state, int(b), *why, body_fields(), material_before[b], time_step, choice, whole);
      if (local)
        if (const std::string shape = shape_fault(ball, local->mesh); !shape.empty()) {
          whole = "the local remesh left a body that is " + shape;
          local.reset();
        }
    };
    if (why->local) try_region(Region::due);
    if (why->periodic && !scene.input.remeshing.adaptive) try_region(Region::whole_body);
    if (local) {
      inside_after[b] = inside_before[b] + inside_dies_change(scene, part, local->mesh, int(b), state.dies);
      ranges.push_back(mesh::append(next, local->mesh));
      append_values(nodal, local->nodal.data(), local->nodal.size());
      if (thermal) {
        append_values(temperature, local->temperature.data(), local->temperature.size());
        // The heat of the volume the fit to the dies moved (budget apart, as for a whole remesh).
        if (const auto& body_thermal = scene.bodies[b].thermal)
          state.heat.remeshing += stored_heat(local->mesh, local->temperature.data(), *body_thermal) -
                                  stored_heat(part, part_temperature, *body_thermal);
      }
      if (flow_lines) append_values(material, local->material.data(), local->material.size());
      append_values(strain, local->strain.data(), local->strain.size());
      for (std::size_t k = 0; k < damage.size(); ++k)
        append_values(damage[k], local->damage[k].data(), local->damage[k].size());
      if (carries_stress) stress.insert(stress.end(), 6 * local->mesh.tets.size(), 0.0);
      const double volume_before = mesh::volume(part), volume_after = mesh::volume(local->mesh);
      scene::RemeshRecord record{state.increment,
                                 int(b),
                                 part.node_count(),
                                 local->mesh.node_count(),
                                 worst_quality(part),
                                 worst_quality(local->mesh),
                                 relative(volume_after, volume_before),
                                 local->strain_integral_change,
                                 local->strain_max_change,
                                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
      record.rebuilt_share = region == Region::whole_body ? 1.0 : double(local->rebuilt) / part.tet_count();
      const bool kept_surface = local->surface == RegionSurface::kept;
      if (!kept_surface) {
        // As for a whole remesh: CGAL's change and the material given
        // back, and apart the put-back's (a contact projection).
        record.volume_change = relative(local->volume_remeshed, volume_before);
        state.volume.remeshing += local->volume_remeshed - volume_before + volume_after - local->volume_put_back;
        state.volume.projection += local->volume_put_back - local->volume_remeshed;
      } else {
        state.volume.remeshing += volume_after - volume_before; // the surface's mending
      }
      state.remeshes.push_back(record);
      // A region rebuilt for its poor elements fits its own surface, not
      // the overlap elsewhere: counted as a fit, it would put off the
      // whole remesh that puts that overlap back. The whole body rebuilt
      // with its surface fits all of it.
      fitted.push_back(!kept_surface &&
                       (region == Region::whole_body || !why->die_corners.empty() || !why->sunk_edges.empty()));
      if (region == Region::whole_body)
        log::info("  remesh '%s' (%s): the whole body rebuilt, its contact surface kept; %d -> %d nodes, %d -> %d "
                  "elements; worst quality %.3f -> %.3f; transfer: integral of strain %+.3f%%, max strain %+.3f%%; "
                  "%.2f s",
                  scene.bodies[b].name.c_str(), why->why.c_str(), record.nodes_before, record.nodes_after,
                  part.tet_count(), local->mesh.tet_count(), record.worst_quality_before, record.worst_quality_after,
                  100.0 * record.strain_integral_change, 100.0 * record.strain_max_change, record.seconds);
      else if (!why->sunk_edges.empty())
        log::info("  remesh '%s' (%s): %d elements split, their new surface nodes put onto the dies, the rest "
                  "kept; %d -> %d nodes; worst quality %.3f -> %.3f; %.2f s",
                  scene.bodies[b].name.c_str(), why->why.c_str(), local->rebuilt, record.nodes_before,
                  record.nodes_after, record.worst_quality_before, record.worst_quality_after, record.seconds);
      else
        log::info("  remesh '%s' (%s), local: %d of %d elements rebuilt, the rest and %s kept; %d -> %d nodes; "
                  "worst quality %.3f -> %.3f; transfer: integral of strain %+.3f%%, max strain %+.3f%%; %.2f s",
                  scene.bodies[b].name.c_str(), why->why.c_str(), local->rebuilt, part.tet_count(),
                  !kept_surface                          ? "the surface outside the region"
                  : local->flips + local->collapses == 0 ? "the surface"
                                                         : "the surface (mended in places)",
                  record.nodes_before, record.nodes_after, record.worst_quality_before, record.worst_quality_after,
                  100.0 * record.strain_integral_change, 100.0 * record.strain_max_change, record.seconds);
      if (local->short_of_trigger)
        log::info("    taken short of remeshing.quality %g: better than the worst element before, and the next remesh "
                  "waits until the worst is below %g (a whole remesh would move every contact node)",
                  scene.input.remeshing.quality,
                  quality_due_below(record.worst_quality_after, scene.input.remeshing.quality));
      if (local->flips + local->collapses > 0)
        log::info("    surface mended where its elements were poor: %d edges flipped, %d short edges collapsed; "
                  "volume %+.4f%%",
                  local->flips, local->collapses, 100.0 * record.volume_change);
      if (local->peeled > 0)
        log::info("    %d flat elements on sharp edges of the kept surface taken off; volume %+.4f%% by this remesh",
                  local->peeled, 100.0 * record.volume_change);
      if (!kept_surface)
        log_fit(local->put_back, local->volume_remeshed, local->volume_put_back, local->given_back, volume_after);
      continue;
    }
    if (!why->sunk_edges.empty()) {
      // Not worth a whole remesh: the overlap's own trigger takes that.
      log::info("  remesh '%s' (%s) not made: %s; the body keeps its mesh", scene.bodies[b].name.c_str(),
                why->why.c_str(), whole.c_str());
      keep_mesh();
      continue;
    }
    if (region == Region::whole_body)
      log::info("  remesh '%s': the whole body remeshed freely, as its rebuild with the contact surface kept "
                "failed: %s",
                scene.bodies[b].name.c_str(), whole.c_str());
    else if (why->local)
      log::info("  remesh '%s': the whole body, as %s", scene.bodies[b].name.c_str(), whole.c_str());
    const PointLocator in_old(part);
    std::string refused;
    const std::optional<Remeshed> tried =
        remesh_part(scene, state, int(b), part, ball, in_old, touching_die.subspan(range.first_node, range.node_count),
                    rate.subspan(range.first_tet, range.tet_count), material_before[b], refused);
    if (!tried) {
      // No silent loss of material: the body goes on with its mesh, and the
      // run with it for as long as that mesh holds.
      log::info("  remesh '%s' (%s) refused: %s; the body keeps its mesh", scene.bodies[b].name.c_str(),
                why->why.c_str(), refused.c_str());
      keep_mesh();
      continue;
    }
    // A remesh for poor elements that leaves a worse one is no remesh: the
    // body keeps its mesh (and is remeshed again when it is due again).
    if (const double worst_before = worst_quality(part);
        why->local && worst_before < scene.input.remeshing.quality && tried->worst <= worst_before) {
      log::info("  remesh '%s' (%s) not taken: its worst element (quality %.3f) is no better than the mesh's; the "
                "body keeps its mesh",
                scene.bodies[b].name.c_str(), why->why.c_str(), tried->worst);
      keep_mesh();
      continue;
    }
    const Remeshed& best = *tried;
    const mesh::TetMesh& fresh = best.mesh;
    const double volume_before = mesh::volume(part), volume_remeshed = mesh::volume(best.remeshed);
    const double volume_after = mesh::volume(fresh);
    // Nodal v and p interpolated: the next Newton's first guess. ε̄ (and D) by a
    // conservative remap onto the mesh CGAL made of the old body (the same
    // domain), its peaks kept; fitting to the dies then moves the elements
    // with their values, as an increment's update does.
    const std::vector<Location> at = in_old.locate(fresh.nodes);
    const Eigen::VectorXd fresh_nodal =
        interpolate_nodal(part, Eigen::Map<const Eigen::VectorXd>(part_nodal, 4 * range.node_count), 4, at);
    const std::vector<double> fresh_strain = transfer_element(part, part_strain, in_old, best.remeshed);
    ranges.push_back(mesh::append(next, fresh));
    append_values(nodal, fresh_nodal.data(), fresh_nodal.size());
    if (thermal) {
      // T interpolated linearly at the new nodes (P1, as it is solved).
      // Interpolation smooths a steep skin profile and so changes the stored
      // heat; a uniform shift gives it back, so that only the change of the
      // mesh's volume (the put-back onto the dies, the material given back)
      // changes it, at the body's mean heat per mm³. That change is logged
      // and kept apart in the heat budget.
      Eigen::VectorXd fresh_temperature =
          interpolate_nodal(part, Eigen::Map<const Eigen::VectorXd>(part_temperature, range.node_count), 1, at);
      if (const auto& body_thermal = scene.bodies[b].thermal) {
        const double before = stored_heat(part, part_temperature, *body_thermal);
        const double by_volume = before * relative(volume_after, volume_before);
        const thermal::NodalMass m = nodal_mass(fresh, *body_thermal);
        const mesh::MeshRange all = mesh::whole_range(fresh);
        const double interpolated = thermal::enthalpy(m, all, {fresh_temperature.data(), fresh.nodes.size()});
        double capacity = 0.0; // mJ/K of the body at its temperatures
        for (int i = 0; i < fresh.node_count(); ++i)
          capacity += m.mass[i] * body_thermal->specific_heat.at(fresh_temperature[i]);
        const double shift = (before + by_volume - interpolated) / capacity;
        fresh_temperature.array() += shift;
        const double after = thermal::enthalpy(m, all, {fresh_temperature.data(), fresh.nodes.size()});
        state.heat.remeshing += after - before;
        log::info("    temperature interpolated (stored heat %+.4g mJ) and shifted by %+.3g C to keep it; stored heat "
                  "%+.4g mJ (%+.3f%%) with the change of volume",
                  interpolated - before, shift, after - before, 100.0 * relative(after, before));
      }
      append_values(temperature, fresh_temperature.data(), fresh_temperature.size());
    }
    if (flow_lines) {
      // Where the new nodes' material started: interpolated linearly (and
      // extended linearly to a new surface node off the old surface), exact
      // where the flow so far was homogeneous (docs/reading-a-run.md §4).
      const Eigen::VectorXd fresh_material =
          interpolate_nodal(part, Eigen::Map<const Eigen::VectorXd>(part_material, 3 * range.node_count), 3, at, true);
      append_values(material, fresh_material.data(), fresh_material.size());
    }
    append_values(strain, fresh_strain.data(), fresh_strain.size());
    for (std::size_t k = 0; k < damage.size(); ++k) {
      const std::vector<double> fresh_damage = transfer_element(part, part_damage[k], in_old, best.remeshed);
      append_values(damage[k], fresh_damage.data(), fresh_damage.size());
    }
    if (carries_stress) stress.insert(stress.end(), 6 * fresh.tets.size(), 0.0); // a flowing body carries none

    const double strain_remeshed = integral(best.remeshed, fresh_strain); // ∫ε̄ dV before the fit to the dies
    scene::RemeshRecord record{state.increment,
                               int(b),
                               part.node_count(),
                               fresh.node_count(),
                               worst_quality(part),
                               best.worst,
                               relative(volume_remeshed, volume_before),
                               relative(strain_remeshed, integral(part, part_strain)),
                               relative(*std::max_element(fresh_strain.begin(), fresh_strain.end()),
                                        *std::max_element(part_strain.begin(), part_strain.end())),
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    // What the remesh changed (CGAL's mesh, and the material given back),
    // and apart, what the put-back took off: a contact projection, as after
    // an increment.
    state.volume.remeshing += volume_remeshed - volume_before + volume_after - best.volume_put_back;
    state.volume.projection += best.volume_put_back - volume_remeshed;
    record.rebuilt_share = 1.0;
    state.remeshes.push_back(record);
    fitted.push_back(1);
    log::info("  remesh '%s' (%s): %d -> %d nodes, %d -> %d elements, h %.3g mm (about %.0f nodes expected); worst "
              "quality %.3f -> %.3f; volume %+.4f%%; transfer: integral of strain %+.3f%%, max strain %+.3f%%; %.2f s",
              scene.bodies[b].name.c_str(), why->why.c_str(), record.nodes_before, record.nodes_after, part.tet_count(),
              fresh.tet_count(), best.edge_length, best.expected, record.worst_quality_before,
              record.worst_quality_after, 100.0 * record.volume_change, 100.0 * record.strain_integral_change,
              100.0 * record.strain_max_change, record.seconds);
    log_fit(best.put_back, volume_remeshed, best.volume_put_back, best.given_back, volume_after);
    if (volume_after != volume_remeshed)
      log::info("    integral of strain %+.3f%% by these moves (the elements carry their values)",
                100.0 * relative(integral(fresh, fresh_strain), strain_remeshed));
  }
  state.unknowns.nodal = Eigen::Map<const Eigen::VectorXd>(nodal.data(), static_cast<Eigen::Index>(nodal.size()));
  state.unknowns.bubble = Eigen::VectorXd::Zero(3 * next.tet_count()); // condensed per element: a zero guess
  state.mesh = std::move(next);
  state.bodies = std::move(ranges);
  state.equivalent_strain = std::move(strain);
  state.damage = std::move(damage);
  state.elastic_stress = std::move(stress);
  if (thermal) state.temperature = std::move(temperature);
  if (flow_lines) state.material_position = std::move(material);
  {
    Timers::Scope overlap(timers, "die overlap");
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      state.inside_dies[b] = inside_after[b]
                                 ? *inside_after[b]
                                 : scene::inside_dies(scene, state.mesh, state.bodies[b], int(b), state.dies);
  }
  const std::vector<std::vector<mesh::Point>> die_vertices = dies_in_place(scene, state);
  for (std::size_t r = first_record; r < state.remeshes.size(); ++r) {
    scene::RemeshRecord& record = state.remeshes[r];
    const int b = record.body;
    record.material_change =
        (mesh::volume(state.mesh, state.bodies[b]) - state.inside_dies[b]) / material_before[b] - 1.0;
    if (scene.dies.empty() || !fitted[r - first_record]) continue;
    record.die_overlap_after = state.inside_dies[b];
    record.die_depth_after = 0.0;
    for (const DieFeature& f : die_feature_depths(state.mesh, state.bodies[b], die_vertices))
      record.die_depth_after = std::max(record.die_depth_after, f.depth);
    log::info("    '%s' inside the dies: %.3f%% of its initial volume (%.3f%% before the remesh); material %+.4f%%",
              scene.bodies[b].name.c_str(), 100.0 * state.inside_dies[b] / scene.bodies[b].initial_volume,
              100.0 * inside_before[b] / scene.bodies[b].initial_volume, 100.0 * record.material_change);
  }
}

} // namespace

void remesh(const scene::Scene& scene, scene::RunState& state, std::span<const RemeshDue> due,
            std::span<const int> touching_die, std::span<const double> rate, double next_step, Timers& timers) {
  // Several processes: rank 0 remeshes, the others take its new mesh and fields.
  processes::on_root([&] { remesh_bodies(scene, state, due, touching_die, rate, next_step, timers); });
  io::share_state(state);
}

} // namespace anvil::remesh

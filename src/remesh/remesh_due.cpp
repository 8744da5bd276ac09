#include "anvil/remesh/remesh_due.h"

#include "anvil/core/log.h"
#include "anvil/remesh/die_feature_depth.h"
#include "anvil/remesh/fit_to_dies.h"
#include "anvil/remesh/quality.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace anvil::remesh {
namespace {

/// What the last remesh of body `b` left: its worst element (1 before
/// any), and what the last remesh that fitted the surface to the dies left
/// of them inside it (0 before any, or where an older checkpoint did not
/// keep it). A remesh that kept the surface is no new start for the dies:
/// the overlap it leaves is what the flow pressed in since the last fit,
/// and taking it as the new start let the overlap grow to 2.4 % of the
/// body between fits.
struct LeftByRemesh {
  double worst_quality = 1.0; ///< of the last remesh, whatever it was
  double die_depth = 0.0;     ///< mm, the deepest die vertex the last fit left
  double die_overlap = 0.0;   ///< mm³, the overlap with the dies the last fit left
};
LeftByRemesh left_by_last_remesh(const scene::RunState& state, int b) {
  LeftByRemesh left;
  for (const scene::RemeshRecord& r : state.remeshes) {
    if (r.body != b) continue;
    left.worst_quality = r.worst_quality_after;
    if (!std::isnan(r.die_overlap_after)) {
      left.die_depth = r.die_depth_after;
      left.die_overlap = r.die_overlap_after;
    }
  }
  return left;
}

/// A die trigger on `value` (a die vertex's depth, the body's overlap with
/// the dies): above `trigger`, and half a trigger beyond what the last remesh
/// left. A die edge the remesh cannot fit sinks in again at once, and the
/// body would be remeshed every increment for nothing; a whole trigger's
/// wait let elements under a rib's edge of the connecting rod be crushed
/// inside out before the remesh came. Local remeshes keep the surface, so
/// the overlap grows between whole remeshes alike.
bool due_again(double value, double trigger, double left) {
  return value > std::max(trigger, left + 0.5 * trigger);
}

/// A die-corner remesh rebuilds around the die vertices deeper than this
/// share of its trigger.
constexpr double kAlongEdge = 0.5;
/// A boundary edge whose midpoint is this share of the element size inside
/// a die is split (its midpoint put onto the die), if it is longer than
/// kShortestSplit element sizes: an edge is split once or twice, not down
/// to the die's own facets.
constexpr double kSunkEdgeDepth = 0.1;
constexpr double kShortestSplit = 0.6;

} // namespace

double quality_due_below(double left, double floor) {
  return left < floor ? kQualityAgain * floor : floor;
}

std::vector<RemeshDue> remesh_due(const scene::Scene& scene, const scene::RunState& state, double dt) {
  const scene::RemeshSpec& spec = scene.input.remeshing;
  std::vector<RemeshDue> due;
  std::vector<std::vector<mesh::Point>> die_vertices; // in place, gathered once when a body needs them
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const scene::Body& body = scene.bodies[b];
    if (body.law->is_elastic()) continue; // an elastic die keeps its mesh
    const QualityReport q = assess_quality(state.mesh, state.bodies[b], state.unknowns.nodal, dt, spec.quality);
    const mesh::Point& at = q.worst_at;
    log::detail("  quality '%s': worst %.3f (element %d at %.3g, %.3g, %.3g mm), %d below %g; next increment %.3f",
                body.name.c_str(), q.worst, q.worst_tet + 1, at.x(), at.y(), at.z(), q.below, spec.quality,
                q.predicted_worst);
    char why[160] = "";
    const LeftByRemesh left = left_by_last_remesh(state, int(b));
    const double quality_trigger = quality_due_below(left.worst_quality, spec.quality);
    const bool poor = q.worst < quality_trigger;
    // A local remesh may do for poor elements and for a die corner (its
    // region's surface rebuilt); a periodic remesh takes the whole body.
    bool local = spec.local && (poor || q.predicted_worst <= 0.0);
    std::vector<mesh::Point> corners;
    bool periodic = false;
    // The overlap trigger comes first: its whole remesh mends poor elements
    // too, and a local remesh for them, which keeps the surface, would let
    // the overlap grow an increment more (to 1.24 % of closed_die_flash's
    // volume at closure, past its 1 % trigger).
    const double overlap = scene.dies.empty() ? 0.0 : state.inside_dies[b];
    if (due_again(overlap, spec.die_overlap * body.initial_volume, left.die_overlap)) {
      std::snprintf(why, sizeof why, "%.3g%% of its initial volume lies inside the dies",
                    100.0 * overlap / body.initial_volume);
      local = false;
    } else if (poor && quality_trigger < spec.quality)
      std::snprintf(why, sizeof why, "worst quality %.3f below %.3g, %g of %g: the last remesh left %.3f", q.worst,
                    quality_trigger, kQualityAgain, spec.quality, left.worst_quality);
    else if (poor)
      std::snprintf(why, sizeof why, "worst quality %.3f below %g", q.worst, spec.quality);
    else if (q.predicted_worst <= 0.0)
      std::snprintf(why, sizeof why, "element %d would invert in the next increment", q.predicted_tet + 1);
    else if (spec.every > 0 && state.increment % spec.every == 0) {
      std::snprintf(why, sizeof why, "every %d increments", spec.every);
      periodic = true;
    } else if (!scene.dies.empty()) {
      if (die_vertices.empty()) die_vertices = dies_in_place(scene, state); // the scene has dies here
      const std::vector<SunkVertex> sunk = sunk_die_vertices(state.mesh, state.bodies[b], die_vertices);
      const std::vector<DieFeature> inside = deepest_per_die(sunk, scene.dies.size());
      const double depth_trigger = spec.die_penetration * body.remesh_size;
      for (std::size_t d = 0; d < scene.dies.size() && !why[0]; ++d)
        if (due_again(inside[d].depth, depth_trigger, left.die_depth)) {
          const mesh::Point& x = inside[d].vertex;
          std::snprintf(why, sizeof why, "the vertex of die '%s' at %.3g, %.3g, %.3g mm is %.3g mm inside",
                        scene.dies[d].name.c_str(), x.x(), x.y(), x.z(), inside[d].depth);
          // Rebuilt around every die vertex half as deep: a die edge sinks
          // along its length, and a region around its deepest vertex alone
          // leaves the rest of it to crush the elements under it.
          local = spec.local;
          for (const SunkVertex& v : sunk)
            if (v.feature.depth > kAlongEdge * depth_trigger) corners.push_back(v.feature.vertex);
        }
    }
    if (why[0])
      due.push_back({.body = int(b),
                     .why = why,
                     .local = local,
                     .periodic = periodic,
                     .die_corners = std::move(corners),
                     .sunk_edges = {}});
    else if (std::optional<RemeshDue> split = sunk_edges_due(scene, state, int(b)))
      due.push_back(std::move(*split));
  }
  return due;
}

std::optional<RemeshDue> sunk_edges_due(const scene::Scene& scene, const scene::RunState& state, int b) {
  const scene::Body& body = scene.bodies[b];
  if (!scene.input.remeshing.split_sunk_edges || scene.dies.empty() || body.law->is_elastic()) return std::nullopt;
  std::vector<SunkEdge> sunk_edges =
      edges_over_die_features(state.mesh, state.bodies[b], scene, state.dies, kSunkEdgeDepth * body.remesh_size,
                              kShortestSplit * body.remesh_size, body.remesh_size);
  if (sunk_edges.empty()) return std::nullopt;
  char why[160];
  std::snprintf(why, sizeof why, "%zu boundary edges over a die fillet or edge, %.3g%% of its volume inside the dies",
                sunk_edges.size(), 100.0 * state.inside_dies[b] / body.initial_volume);
  return RemeshDue{
      .body = b, .why = why, .local = true, .periodic = false, .die_corners = {}, .sunk_edges = std::move(sunk_edges)};
}

} // namespace anvil::remesh

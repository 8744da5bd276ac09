// When the time loop remeshes a body: the triggers (docs/remeshing.md).
#pragma once
#include "anvil/remesh/fit_to_dies.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace anvil::remesh {

/// A body due for a remesh, and why (for the log).
struct RemeshDue {
  int body;
  std::string why;
  /// remeshing.local and a trigger that a local remesh may meet: poor
  /// elements (now or in the next increment), a die corner sunk into the
  /// body (its region's surface rebuilt). The overlap with the dies and a
  /// periodic remesh are of the whole body.
  bool local = false;
  /// remeshing.every: nothing to mend, the whole body rebuilt with its
  /// contact surface kept (local_remesh.h, Region::whole_body).
  bool periodic = false;
  /// The die vertex sunk into the body that asked for the remesh (mm);
  /// none for the other triggers.
  std::vector<mesh::Point> die_corners;
  /// Boundary edges over a die fillet or edge sunk between contact nodes:
  /// only they are split, their midpoints put onto the die; none for the
  /// other triggers.
  std::vector<SunkEdge> sunk_edges;
};

/// A remesh that could not lift the worst element above remeshing.quality
/// (a flat tet CGAL keeps on a crease of the surface) is not redone until
/// the worst element is below this share of the trigger: the hot
/// connecting rod was remeshed whole at nearly every increment from 8.2 mm
/// on, 4-7 s each, for the same 0.06-0.09.
constexpr double kQualityAgain = 0.8;

/// The worst quality below which a body is due for a remesh for quality:
/// `floor` (remeshing.quality), or kQualityAgain × `floor` when `left`, the
/// worst the body's last remesh left, is below it. The lower trigger does
/// not follow `left` down: taken-short remeshes, each due at a share of
/// what the last one left, let the connecting rod's trigger fall from 0.15
/// to 0.066 at 1.44 mm, and an element was crushed flat between two
/// remeshes.
double quality_due_below(double left, double floor);

/// The bodies of `state` to remesh after an increment of `dt` (s), by the
/// case's triggers: worst quality below remeshing.quality (below
/// kQualityAgain × it, when the last remesh left less), an
/// element that would invert in a next increment alike, every N increments, a die vertex
/// deeper than die_penetration × the element size inside the body, more than
/// die_overlap × its initial volume inside the dies (each of the last two
/// again only once it has grown by half its trigger beyond what the body's
/// last remesh left: a remesh that cannot fit a die does not repeat). Short
/// of those, with remeshing.split_sunk_edges, boundary edges whose midpoint lies deeper
/// than a tenth of the element size inside a die (sunk_edges). Elastic
/// bodies keep their mesh. Logs each body's quality.
std::vector<RemeshDue> remesh_due(const scene::Scene& scene, const scene::RunState& state, double dt);

/// Body `b` due for the split of its boundary edges sunk over a die fillet
/// or edge (remesh_due's last trigger), with remeshing.split_sunk_edges;
/// nothing without it, or when no edge is sunk that deep.
std::optional<RemeshDue> sunk_edges_due(const scene::Scene& scene, const scene::RunState& state, int b);

} // namespace anvil::remesh

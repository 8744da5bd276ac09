// Where a chain puts the part before an operation (scene::Placement):
// flipped, turned about the press axis, moved, rested on the lowest die.
#pragma once
#include "anvil/die/DieSurface.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Chain.h"
#include "anvil/scene/RunState.h"

namespace anvil::run {

/// A symmetry plane of a model: normal to `axis`, at `at` (mm) along it.
struct SymmetryPlane {
  int axis;
  double at;
};

/// The symmetry planes of `c`'s conditions on `mesh`: a plane's normal, or
/// that of the faces a tag selects.
std::vector<SymmetryPlane> symmetry_planes(const scene::Case& c, const mesh::TetMesh& mesh);

/// Moves every body of `part` as `place` says, the dies of `next` (the
/// operation's case) at their start. The fields stay with the material.
/// A flip is half a turn about a horizontal axis through the part's centre;
/// a model cut by symmetry planes is turned about the axis in its planes, or
/// mirrored in z when it has two (the whole part's half turn, by its
/// symmetry). Throws InputError for a placement the model cannot take.
void place_part(const scene::Placement& place, const scene::Case& next, scene::RunState& part,
                const std::string& where);

/// mm the part must move along z to rest on a die's surface `die`: the
/// smallest height of a boundary node above its upward facets below it
/// (negative: the part sinks into the die by that much; infinite: no facet
/// lies under the part).
double height_above_die(const scene::RunState& part, const die::SurfaceTriangles& die);

} // namespace anvil::run

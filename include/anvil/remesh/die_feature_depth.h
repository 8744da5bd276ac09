// Remeshing trigger "a die feature penetrates the body surface" (issue 5
// point 2). Contact is nodal: it keeps body nodes out of the die, not die
// corners out of the body. A die corner that has gone between body nodes is
// seen here, and a remesh puts nodes where the die shapes the body.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::remesh {

/// Deepest penetration (mm, ≥ 0) of the points `die_vertices` into the body
/// `body` (one body's mesh): the distance to its surface of those inside it.
/// 0 when none is inside.
double die_feature_depth(const mesh::TetMesh& body, const std::vector<mesh::Point>& die_vertices);

} // namespace anvil::remesh

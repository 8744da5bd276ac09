// Remeshing trigger "a die feature penetrates the body surface" (issue 5
// point 2). Contact is nodal: it keeps body nodes out of the die, not die
// corners out of the body. A die corner that has gone between body nodes is
// seen here, and a remesh puts nodes where the die shapes the body.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::remesh {

/// For each die (its vertices, in place), the deepest penetration (mm, ≥ 0)
/// of its vertices into the body `body` of `mesh`: the distance to the
/// body's surface of those inside it; 0 when none is inside.
std::vector<double> die_feature_depths(const mesh::TetMesh& mesh, const mesh::MeshRange& body,
                                       const std::vector<std::vector<mesh::Point>>& die_vertices);

} // namespace anvil::remesh

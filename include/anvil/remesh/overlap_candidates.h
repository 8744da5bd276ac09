// Which old elements a new element may overlap: the candidates of the
// conservative remap of element fields (field_transfer.h), found for all
// new elements at once by one sweep over both meshes' bounding boxes.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::remesh {

/// For each tet of a mesh, the tets of another whose bounding boxes meet its
/// own (closed boxes: touching counts).
struct OverlapCandidates {
  std::vector<int> first; ///< tet n's candidates: tets[first[n]], …, tets[first[n + 1] − 1], ascending
  std::vector<int> tets;
};

/// The tets of `from` whose boxes meet each tet of `to`'s box (CGAL's
/// box_intersection_d: a segment tree over both sets, not a query per tet).
OverlapCandidates overlap_candidates(const mesh::TetMesh& to, const mesh::TetMesh& from);

} // namespace anvil::remesh

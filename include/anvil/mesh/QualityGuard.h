// Moving single nodes of a finished mesh (a new boundary node back onto the
// old surface or onto a die after a remesh, a contact node onto its die after
// an increment) without spoiling the elements around them: a move is judged
// by the worst element it leaves behind.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::mesh {

class QualityGuard {
public:
  /// The elements around each node of `mesh`: the guard serves any mesh with
  /// these elements (the same mesh, or a copy whose nodes moved).
  explicit QualityGuard(const TetMesh& mesh);

  /// Smallest quality (mesh::quality) among the elements around `node` of `mesh`.
  double worst_around(const TetMesh& mesh, int node) const;

  /// Moves `node` of `mesh` to `to` unless an element around it would end
  /// worse than `floor` or than it is now, whichever is lower, or flat (a
  /// node put onto a die plane that three nodes of its element lie in:
  /// quality exactly 0). Returns whether it moved.
  bool move(TetMesh& mesh, int node, const Point& to, double floor) const;

private:
  std::vector<std::vector<int>> tets_of_; ///< the elements around each node
};

} // namespace anvil::mesh

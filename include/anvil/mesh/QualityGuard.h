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
  /// Keeps a reference: `mesh` must outlive the guard and keep its elements.
  explicit QualityGuard(TetMesh& mesh);

  /// Smallest quality (mesh::quality) among the elements around `node`.
  double worst_around(int node) const;

  /// Moves `node` to `to` unless an element around it would end worse than
  /// `floor` or than it is now, whichever is lower. Returns whether it moved.
  bool move(int node, const Point& to, double floor);

private:
  TetMesh& mesh_;
  std::vector<std::vector<int>> tets_of_; ///< the elements around each node
};

} // namespace anvil::mesh

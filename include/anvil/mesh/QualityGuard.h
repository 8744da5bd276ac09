// Moving single nodes of a finished mesh (a new boundary node back onto the
// old surface or onto a die after a remesh, a contact node onto its die after
// an increment) without spoiling the elements around them: a move is judged
// by the worst element it leaves behind.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <span>
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

  /// Moves the boundary nodes `nodes` of `mesh` to `to` (one point each)
  /// and carries the free interior around them along, so that the thin
  /// elements between them and the interior are not crushed as `move`
  /// alone would crush them: a node not `fixed` that lies r element rings
  /// from a group (nodes sharing an element move as one) moves by the mean
  /// move of its neighbours a ring nearer times (rings + 1 − r)/(rings + 2 − r),
  /// so the move falls linearly to zero past ring `rings`. Each group takes
  /// the largest of its whole move, a half and a quarter of it that leaves
  /// no element around a moved node worse than `floor` or than the worst of
  /// them was, whichever is lower, nor flat; none if no fraction does.
  /// Returns the fraction each node of `nodes` was moved by (1, ½, ¼ or 0).
  std::vector<double> move_carrying(TetMesh& mesh, std::span<const int> nodes, std::span<const Point> to,
                                    std::span<const char> fixed, int rings, double floor) const;

private:
  std::vector<std::vector<int>> tets_of_; ///< the elements around each node
};

} // namespace anvil::mesh

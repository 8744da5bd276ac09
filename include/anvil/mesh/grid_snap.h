// A body's nodes rounded to a grid before a remesh, and given back after it.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <array>
#include <cstddef>
#include <map>

namespace anvil::mesh {

/// A grid of points (n + offset) × spacing along each axis (mm); spacing 0:
/// no grid.
struct Grid {
  double spacing = 0.0;
  double offset = 0.0; ///< a share of the step
};

/// The step of the grid a body of element size `h` (mm) is rounded to: the
/// largest power of two at most h/64, 16 microns at a millimetre.
double snap_spacing(double h);

/// Where the grid of the `k`-th remesh of a run lies: its points at (n + the
/// share returned) steps. CGAL splits an edge at its midpoint, and the
/// midpoint of two points of a grid lies on a half step of that grid, where
/// rounding parts two runs whose nodes drift apart; each remesh's grid is
/// shifted by frac(k (φ − 1)/2) of a step (φ the golden ratio), so that the
/// last grids' midpoints lie away from this one's half steps.
double grid_offset(std::size_t k);

/// The grid of the `k`-th remesh of a run, for a body of element size `h`.
Grid remesh_grid(double h, std::size_t k);

/// The nodes of a body rounded to a grid of `spacing` for a remesh
/// (docs/remeshing.md, the same mesh on any number of processes). A remesh
/// is not a continuous function of the nodes: CGAL's order of operations
/// follows ties of lengths and angles on flat faces and planes of symmetry,
/// which round-off breaks one way on one process count and another way on
/// the next. On the grid the nodes are the same numbers on any process
/// count, unless two runs' coordinates lie on either side of a half step.
/// A node stays where it is when rounding it would leave a tet of it below
/// half its volume, or two nodes on one grid point.
class GridSnap {
public:
  /// `grid.spacing` 0: the body as it is.
  GridSnap(const TetMesh& body, Grid grid);
  /// The body on the grid: what the remesh is given.
  const TetMesh& snapped() const { return snapped_; }
  /// The nodes of `remeshed` that lie where a node of snapped() lies (a
  /// node the remesh kept where it was) get that node's own coordinates
  /// back, unless that would leave a tet of theirs below half its volume.
  /// Returns how many got them back.
  int restore(TetMesh& remeshed) const;

private:
  TetMesh snapped_;
  std::map<std::array<double, 3>, Point> exact_; ///< per point of the grid a node was rounded to
};

} // namespace anvil::mesh

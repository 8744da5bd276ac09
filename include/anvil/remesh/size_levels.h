// The levels a size field is met in (remesh_body): CGAL 5.5 takes one edge
// length per call, so after the whole body at the element size each finer
// level, ¾ of the one before, rebuilds the cells that want it with their
// border to the coarser cells frozen (docs/remeshing.md).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <functional>
#include <vector>

namespace anvil::remesh {

/// The level after one of `previous` mm: ¾ of it (RemeshSettings::size),
/// at least `smallest` mm.
double finer_level(double previous, double smallest);

/// Flags of the cells of `mesh` that go to the level at `length` after the
/// one at `previous`: those whose centroid wants less than the geometric
/// mean of the two, so that a cell goes to the level nearest its size.
std::vector<char> level_cells(const mesh::TetMesh& mesh, const std::function<double(const mesh::Point&)>& size,
                              double previous, double length);

/// One finer level: its length and the one before (mm), and the area of its
/// border with the coarser cells (mm²) as the cells of a given mesh draw it.
struct LevelBorder {
  double coarser = 0.0, length = 0.0, area = 0.0;
};
/// The finer levels remesh_body makes of `body` under `size` from
/// `edge_length` down to `smallest`, each border drawn by the cells of
/// `body`. A level's border keeps the coarser cells' faces, their long
/// edges bisected: it adds nodes like a surface.
std::vector<LevelBorder> level_borders(const mesh::TetMesh& body, const std::function<double(const mesh::Point&)>& size,
                                       double edge_length, double smallest);

} // namespace anvil::remesh

#include "anvil/remesh/overlap_candidates.h"

#include "anvil/mesh/tet_geometry.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <utility>

namespace anvil::remesh {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

std::vector<Box> tet_boxes(const mesh::TetMesh& m) {
  std::vector<Box> boxes;
  boxes.reserve(m.tets.size());
  for (int e = 0; e < m.tet_count(); ++e) {
    const Eigen::AlignedBox3d b = mesh::bounding_box(m, e);
    boxes.emplace_back(CGAL::Bbox_3(b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z()), e);
  }
  return boxes;
}

} // namespace

OverlapCandidates overlap_candidates(const mesh::TetMesh& to, const mesh::TetMesh& from) {
  std::vector<Box> new_boxes = tet_boxes(to), old_boxes = tet_boxes(from); // the sweep reorders them
  std::vector<std::pair<int, int>> pairs;                                  // (tet of `to`, tet of `from`)
  CGAL::box_intersection_d(new_boxes.begin(), new_boxes.end(), old_boxes.begin(), old_boxes.end(),
                           [&](const Box& a, const Box& b) { pairs.emplace_back(a.info(), b.info()); });
  std::sort(pairs.begin(), pairs.end());
  OverlapCandidates c;
  c.first.assign(to.tets.size() + 1, 0);
  c.tets.reserve(pairs.size());
  for (const auto& [n, e] : pairs) {
    ++c.first[n + 1];
    c.tets.push_back(e);
  }
  for (std::size_t n = 0; n < to.tets.size(); ++n)
    c.first[n + 1] += c.first[n];
  return c;
}

} // namespace anvil::remesh

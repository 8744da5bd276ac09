// The candidates of the conservative remap: for each tet of one mesh, the
// tets of another whose bounding boxes meet its own, against every pair.
#include "test_common.h"

#include "anvil/mesh/generators.h"
#include "anvil/remesh/overlap_candidates.h"

#include <Eigen/Geometry>

using namespace anvil;

namespace {

Eigen::AlignedBox3d tet_box(const mesh::TetMesh& m, int e) {
  Eigen::AlignedBox3d box;
  for (const int v : m.tets[e])
    box.extend(m.nodes[v]);
  return box;
}

} // namespace

TEST_CASE("overlap candidates: each tet's are the other mesh's tets whose boxes meet its box, ascending",
          "[unit][remesh]") {
  // Two meshes of one cylinder at other sizes, one shifted off the other's
  // border: boxes that meet, touch and miss.
  const mesh::TetMesh from = mesh::make_cylinder(5.0, 8.0, 1.3);
  mesh::TetMesh to = mesh::make_cylinder(5.0, 8.0, 1.0);
  for (mesh::Point& x : to.nodes)
    x += mesh::Point(0.7, 0.0, 0.4);
  const remesh::OverlapCandidates c = remesh::overlap_candidates(to, from);
  REQUIRE(c.first.size() == to.tets.size() + 1);
  std::size_t pairs = 0;
  for (int n = 0; n < to.tet_count(); ++n) {
    std::vector<int> expected;
    const Eigen::AlignedBox3d box = tet_box(to, n);
    for (int e = 0; e < from.tet_count(); ++e)
      if (box.intersects(tet_box(from, e))) expected.push_back(e);
    const std::vector<int> found(c.tets.begin() + c.first[n], c.tets.begin() + c.first[n + 1]);
    CHECK(found == expected);
    pairs += expected.size();
  }
  CHECK(pairs > to.tets.size()); // most tets meet several
  CHECK(c.tets.size() == pairs);
}

// Fold detection on meshes whose answer is known (edge 1 mm: reach 0.1 mm,
// depth 0.5 mm): a block alone has none;
// two blocks of one body 0.05 mm apart face to face (a lap about to close)
// fold over the whole 1 mm² of each face, one fold; pushed 0.05 mm into
// each other they still do (a fold gone through itself); the same two
// blocks as two bodies do not (that is contact between bodies); a face on a
// symmetry plane is not looked at.
#include "test_common.h"

#include "anvil/contact/folds.h"
#include "anvil/mesh/generators.h"

using namespace anvil;

namespace {

/// Two unit blocks, the second `gap` mm above the first, as one body or two.
mesh::TetMesh two_blocks(double gap, std::vector<mesh::MeshRange>& bodies, bool one_body) {
  mesh::TetMesh m;
  const mesh::MeshRange a = mesh::append(m, mesh::make_box({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
  const mesh::MeshRange b = mesh::append(m, mesh::make_box({0, 0, 1 + gap}, {1, 1, 1}, {2, 2, 2}));
  bodies = one_body ? std::vector<mesh::MeshRange>{{0, m.node_count(), 0, m.tet_count(), 0,
                                                    static_cast<int>(m.boundary_faces.size())}}
                    : std::vector<mesh::MeshRange>{a, b};
  return m;
}

} // namespace

TEST_CASE("folds: a body's faces meeting face to face, within reach or through each other", "[unit][contact]") {
  std::vector<mesh::MeshRange> bodies;
  const mesh::TetMesh block = mesh::make_box({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  const std::vector<mesh::MeshRange> alone{mesh::whole_range(block)};
  CHECK(contact::find_folds(block, alone, {}, 1.0).folds.empty());

  for (const double gap : {0.05, -0.05}) {
    INFO("gap " << gap << " mm");
    const mesh::TetMesh m = two_blocks(gap, bodies, true);
    const contact::FoldScan scan = contact::find_folds(m, bodies, {}, 1.0);
    REQUIRE(scan.folds.size() == 1);
    CHECK(scan.folds.front().area == Approx(2.0).epsilon(1e-12)); // both 1 mm² faces
    CHECK(scan.folds.front().faces == 16);                        // 8 triangles a side
    CHECK(scan.folds.front().centre.x() == Approx(0.5).epsilon(1e-12));
    CHECK(scan.folds.front().centre.z() == Approx(1.0 + gap / 2).epsilon(1e-12));
  }
  const mesh::TetMesh apart = two_blocks(0.2, bodies, true); // beyond reach
  CHECK(contact::find_folds(apart, bodies, {}, 1.0).folds.empty());
  const mesh::TetMesh pair = two_blocks(0.05, bodies, false); // two bodies
  CHECK(contact::find_folds(pair, bodies, {}, 1.0).folds.empty());
  const mesh::TetMesh one = two_blocks(0.05, bodies, true);
  std::vector<char> skip(one.boundary_faces.size(), 1); // every face on a symmetry plane, say
  CHECK(contact::find_folds(one, bodies, skip, 1.0).folds.empty());
}

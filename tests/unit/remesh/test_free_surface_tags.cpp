// Free surface tags (remesh/free_surface_tags.h): a deformed face of the
// generated billet joins the free surface (tag 0) unless a condition names
// its tag; flat tags stay apart.
#include "test_common.h"

#include "anvil/mesh/generators.h"
#include "anvil/remesh/free_surface_tags.h"

#include <algorithm>

using namespace anvil;

TEST_CASE(
    "A billet face the dies deformed joins the free surface, unless a condition names its tag or it is still flat",
    "[remesh]") {
  // Box tags (generators.h): 1 x-min, 2 x-max, 3 y-min, 4 y-max, 5 z-min, 6 z-max.
  mesh::TetMesh box = mesh::make_box(mesh::Point(0, 0, 0), mesh::Point(4, 3, 2), {4, 3, 2});
  // A node inside the top face pressed down, and one inside the x-min face pushed in.
  auto node_at = [&](const mesh::Point& x) {
    const auto it =
        std::find_if(box.nodes.begin(), box.nodes.end(), [&](const mesh::Point& n) { return (n - x).norm() < 1e-12; });
    REQUIRE(it != box.nodes.end());
    return static_cast<int>(it - box.nodes.begin());
  };
  box.nodes[node_at(mesh::Point(2, 1, 2))].z() -= 0.2;
  box.nodes[node_at(mesh::Point(0, 1, 1))].x() += 0.2;
  const std::vector<int> before = box.boundary_tags;
  scene::BoundaryCondition symmetry_x;
  symmetry_x.kind = scene::BoundaryKind::symmetry;
  symmetry_x.faces.tag = 1;

  const int changed = remesh::free_surface_tags(box, std::vector<scene::BoundaryCondition>{symmetry_x});

  const auto top_faces = std::count(before.begin(), before.end(), 6);
  CHECK(changed == top_faces);
  for (std::size_t f = 0; f < before.size(); ++f)
    CHECK(box.boundary_tags[f] == (before[f] == 6 ? 0 : before[f]));

  SECTION("without the condition the pushed x-min face joins it too") {
    box.boundary_tags = before;
    CHECK(remesh::free_surface_tags(box, {}) == top_faces + std::count(before.begin(), before.end(), 1));
    for (std::size_t f = 0; f < before.size(); ++f)
      CHECK(box.boundary_tags[f] == (before[f] == 6 || before[f] == 1 ? 0 : before[f]));
  }
}

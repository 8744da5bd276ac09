// bisect_edges: the halves fill their parents exactly and conform.
#include "anvil/mesh/edge_bisection.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("Bisected edges: each tet on them is split in two halves of its volume, the boundary with its tags",
          "[unit][mesh]") {
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {3, 2, 2}, 1.0);
  const mesh::TetMesh before = box;
  // Two edges of one boundary face and an interior edge of the first tet.
  const mesh::Triangle& f = box.boundary_faces.front();
  const mesh::Tet& t = box.tets.front();
  const std::vector<std::array<int, 2>> edges{{f[0], f[1]}, {f[1], f[2]}, {t[0], t[3]}, {-1, -2}};
  const mesh::Bisection cut = mesh::bisect_edges(box, edges);

  CHECK(cut.midpoint_of.size() == 3); // the pair that is no edge is skipped
  REQUIRE(box.node_count() == before.node_count() + 3);
  for (std::size_t k = 0; k < cut.midpoint_of.size(); ++k) {
    const auto& [a, b] = cut.midpoint_of[k];
    CHECK((box.nodes[before.node_count() + k] - 0.5 * (box.nodes[a] + box.nodes[b])).norm() < 1e-15);
  }
  // Every half inside its parent: the parents' volumes are the sums of their halves'.
  std::vector<double> by_parent(before.tets.size(), 0.0);
  REQUIRE(cut.parent.size() == box.tets.size());
  for (int e = 0; e < box.tet_count(); ++e) {
    CHECK(mesh::signed_volume(box, e) > 0.0);
    by_parent[cut.parent[e]] += mesh::signed_volume(box, e);
  }
  for (int e = 0; e < before.tet_count(); ++e)
    CHECK(by_parent[e] == Approx(mesh::signed_volume(before, e)).epsilon(1e-12));
  // A conforming mesh: its boundary from the tets is the bisected boundary, tags included.
  mesh::TetMesh rebuilt = box;
  mesh::build_boundary(rebuilt, box.boundary_faces, box.boundary_tags);
  CHECK(rebuilt.boundary_faces.size() == box.boundary_faces.size());
  CHECK(mesh::fault(box).empty());
  double area = 0.0, area_before = 0.0;
  for (const mesh::Triangle& g : box.boundary_faces)
    area += mesh::area_vector(box, g).norm();
  for (const mesh::Triangle& g : before.boundary_faces)
    area_before += mesh::area_vector(before, g).norm();
  CHECK(area == Approx(area_before).epsilon(1e-12));
}

// manifold_fault: the meshes the generators make are manifolds; bodies that
// touch themselves at a node, along an edge or on a face are named.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/manifold.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace anvil;

namespace {

/// The unit tet at the origin (nodes 0-3) and tets made of node 0 or of
/// nodes 0 and 1 with new nodes further out: `extra` lists their other nodes.
mesh::TetMesh unit_tet_and(const std::vector<mesh::Point>& more, const std::vector<mesh::Tet>& extra) {
  mesh::TetMesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.nodes.insert(m.nodes.end(), more.begin(), more.end());
  m.tets = {{0, 1, 2, 3}};
  m.tets.insert(m.tets.end(), extra.begin(), extra.end());
  return m;
}

} // namespace

TEST_CASE("The generators' meshes are manifolds", "[mesh]") {
  CHECK(mesh::manifold_fault(mesh::make_box({0, 0, 0}, {2, 1, 1}, {4, 2, 2})).empty());
  CHECK(mesh::manifold_fault(mesh::make_quarter_cylinder(5, 4, 1)).empty());
  CHECK(mesh::manifold_fault(mesh::make_quarter_ring(5, 2, 3, 1)).empty());
}

TEST_CASE("Two tets that share one node only are a pinch at that node", "[mesh]") {
  const mesh::TetMesh m = unit_tet_and({{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}, {{0, 5, 4, 6}});
  CHECK(mesh::manifold_fault(m) ==
        "the boundary faces around node 1 form more than one fan (two parts of the body touch there)");
}

TEST_CASE("Two tets that share one edge only put four boundary faces on it", "[mesh]") {
  const mesh::TetMesh m = unit_tet_and({{0, -1, 0}, {0, 0, -1}}, {{0, 1, 4, 5}});
  CHECK(mesh::manifold_fault(m) == "the boundary edge of nodes 1, 2 is on 4 boundary faces");
}

TEST_CASE("A face in three tets is named", "[mesh]") {
  const mesh::TetMesh m = unit_tet_and({{0, 0, -1}, {0.2, 0.2, 2}}, {{0, 2, 1, 4}, {0, 1, 2, 5}});
  CHECK(mesh::manifold_fault(m) == "the face of nodes 1, 2, 3 is in 3 tetrahedra");
}

TEST_CASE("A pinch is cut by removing the smaller side at the node or the edge", "[mesh]") {
  // A second tet of edge s against the unit tet, at a node and at an edge:
  // the larger of the two stays.
  for (const double s : {0.5, 2.0}) {
    const mesh::TetMesh at_node = unit_tet_and({{-s, 0, 0}, {0, -s, 0}, {0, 0, -s}}, {{0, 5, 4, 6}});
    const mesh::TetMesh at_edge = unit_tet_and({{0, -s, 0}, {0, 0, -s}}, {{0, 1, 4, 5}});
    // The second tet's volume: s³/6 at the node, s²/6 at the edge (one leg is the unit tet's).
    for (auto [m, second] : {std::pair{at_node, s * s * s / 6.0}, std::pair{at_edge, s * s / 6.0}}) {
      mesh::build_boundary(m);
      CHECK(mesh::cut_pinches(m) == 1);
      CHECK(mesh::manifold_fault(m).empty());
      REQUIRE(m.tet_count() == 1);
      CHECK(m.node_count() == 4);
      CHECK(m.boundary_faces.size() == 4);
      CHECK(mesh::volume(m) == Approx(std::max(1.0 / 6.0, second)));
    }
  }
}

TEST_CASE("Cutting a fin off a box at its corner gives back the box and its tags", "[mesh]") {
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  mesh::TetMesh pinched = box;
  CHECK(mesh::cut_pinches(box) == 0);
  // A small tet outside the box, on its corner node (1, 1, 1) alone.
  const auto corner =
      std::find(pinched.nodes.begin(), pinched.nodes.end(), mesh::Point(1, 1, 1)) - pinched.nodes.begin();
  const int n = pinched.node_count();
  pinched.nodes.insert(pinched.nodes.end(), {{1.2, 1, 1}, {1, 1.2, 1}, {1, 1, 1.2}});
  pinched.tets.push_back({int(corner), n, n + 1, n + 2});
  mesh::build_boundary(pinched, box.boundary_faces, box.boundary_tags);
  REQUIRE(mesh::manifold_fault(pinched) == "the boundary faces around node " + std::to_string(corner + 1) +
                                               " form more than one fan (two parts of the body touch there)");
  CHECK(mesh::cut_pinches(pinched) == 1);
  CHECK(pinched.nodes == box.nodes);
  CHECK(pinched.tets == box.tets);
  CHECK(pinched.boundary_faces == box.boundary_faces);
  CHECK(pinched.boundary_tags == box.boundary_tags);
}

TEST_CASE("A ball is one piece bounded by one sphere: not two pieces, not a ring", "[mesh]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {3, 3, 1}, {3, 3, 1});
  CHECK(mesh::is_ball(box));
  CHECK(mesh::is_ball(mesh::make_quarter_ring(5, 2, 3, 1))); // a quarter of a ring is no ring
  mesh::TetMesh two = box;
  mesh::append(two, mesh::make_box({5, 0, 0}, {1, 1, 1}, {1, 1, 1}));
  CHECK_FALSE(mesh::is_ball(two));
  // The box without its middle cell: a ring (Euler characteristic 0).
  std::vector<char> middle(box.tets.size(), 0);
  for (int e = 0; e < box.tet_count(); ++e) {
    const mesh::Point c = mesh::centroid(box, e);
    middle[e] = c.x() > 1 && c.x() < 2 && c.y() > 1 && c.y() < 2;
  }
  mesh::TetMesh ring = box;
  mesh::remove_tets(ring, middle, {}, {});
  REQUIRE(ring.tet_count() < box.tet_count());
  CHECK(mesh::manifold_fault(ring).empty());
  CHECK_FALSE(mesh::is_ball(ring));
}

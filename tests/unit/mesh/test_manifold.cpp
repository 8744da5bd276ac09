// manifold_fault: the meshes the generators make are manifolds; bodies that
// touch themselves at a node, along an edge or on a face are named.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/manifold.h"

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
  const mesh::TetMesh m = unit_tet_and({{0, -1, 0}, {0, 0, -1}}, {{0, 1, 5, 4}});
  CHECK(mesh::manifold_fault(m) == "the boundary edge of nodes 1, 2 is on 4 boundary faces");
}

TEST_CASE("A face in three tets is named", "[mesh]") {
  const mesh::TetMesh m = unit_tet_and({{0, 0, -1}, {0.2, 0.2, 2}}, {{0, 2, 1, 4}, {0, 1, 2, 5}});
  CHECK(mesh::manifold_fault(m) == "the face of nodes 1, 2, 3 is in 3 tetrahedra");
}

// QualityGuard: a node moves only when no element around it ends worse than
// the floor or than it was.
#include "anvil/mesh/QualityGuard.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("A guarded move keeps the elements around the node", "[unit][mesh]") {
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {2, 2, 2}, {2, 2, 2});
  int centre = -1;
  for (int i = 0; i < box.node_count(); ++i)
    if ((box.nodes[i] - mesh::Point(1, 1, 1)).norm() < 1e-12) centre = i;
  REQUIRE(centre >= 0);
  mesh::QualityGuard guard(box);
  const double before = guard.worst_around(box, centre);
  // Nearly onto a corner of its cells: elements around it go flat.
  CHECK_FALSE(guard.move(box, centre, {0.05, 0.05, 0.05}, 0.1));
  CHECK(box.nodes[centre] == mesh::Point(1, 1, 1));
  CHECK(guard.worst_around(box, centre) == before);
  // A small shift keeps every element above the floor.
  CHECK(guard.move(box, centre, {1.05, 1.0, 1.0}, 0.1));
  CHECK(box.nodes[centre] == mesh::Point(1.05, 1.0, 1.0));
  CHECK(guard.worst_around(box, centre) >= 0.1);
}

TEST_CASE("A guarded move with floor 0 never leaves an element flat", "[unit][mesh]") {
  // A contact node put back onto a die plane that the three other nodes of
  // one of its elements lie in (the hot connecting rod at 9.6 mm): the
  // element's volume would be exactly 0, which the increment refuses as an
  // inversion; the node stays where it is.
  mesh::TetMesh tet;
  tet.nodes = {{0, 0, -0.5}, {1, 0, -0.5}, {0, 1, -0.5}, {0.3, 0.3, -0.8}};
  tet.tets = {{0, 1, 2, 3}};
  if (mesh::signed_volume(tet, 0) < 0.0) std::swap(tet.tets[0][0], tet.tets[0][1]);
  mesh::QualityGuard guard(tet);
  REQUIRE(guard.worst_around(tet, 3) > 0.1);
  CHECK_FALSE(guard.move(tet, 3, {0.3, 0.3, -0.5}, 0.0));
  CHECK(tet.nodes[3] == mesh::Point(0.3, 0.3, -0.8));
  // Part of the way is fine at floor 0.
  CHECK(guard.move(tet, 3, {0.3, 0.3, -0.6}, 0.0));
  CHECK(guard.worst_around(tet, 3) > 0.0);
}

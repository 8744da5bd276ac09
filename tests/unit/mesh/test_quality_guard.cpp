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

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

TEST_CASE("A boundary node pushed deeper than its element carries the interior under it", "[unit][mesh]") {
  // A new surface node sampled on an old chord that a die edge cut deep: put
  // onto the die alone, it would pass the node under it; with the interior
  // carried along, the elements between keep their shape.
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {4, 4, 2}, {8, 8, 8});
  const std::vector<char> boundary = mesh::boundary_node_flags(box);
  auto node_at = [&](const mesh::Point& x) {
    for (int i = 0; i < box.node_count(); ++i)
      if ((box.nodes[i] - x).norm() < 1e-12) return i;
    return -1;
  };
  const int top = node_at({2, 2, 2}), next = node_at({2.5, 2, 2});
  REQUIRE(top >= 0);
  REQUIRE(next >= 0);
  const double floor = 0.1;
  mesh::QualityGuard guard(box);
  const mesh::Point to(2, 2, 1.6); // 0.4 mm down: past the layer 0.25 mm under it
  CHECK_FALSE(guard.move(box, top, to, floor));
  const mesh::TetMesh before = box;
  const std::vector<int> nodes{top, next};
  const std::vector<mesh::Point> targets{to, {2.5, 2, 1.7}};
  const std::vector<double> taken = guard.move_carrying(box, nodes, targets, boundary, 3, floor);
  REQUIRE(taken.size() == 2);
  CHECK(taken[0] == 1.0); // the two share an element: one group, one fraction
  CHECK(taken[1] == 1.0);
  CHECK(box.nodes[top] == to);
  CHECK(box.nodes[next] == targets[1]);
  double worst = 1.0;
  for (int e = 0; e < box.tet_count(); ++e)
    worst = std::min(worst, mesh::quality(box, e));
  CHECK(worst >= floor);
  // Other boundary nodes stay; interior nodes move only within three rings
  // (0.25 mm layers: nothing below z = 1.25, the third layer under the top).
  int carried = 0;
  for (int i = 0; i < box.node_count(); ++i) {
    if (i == top || i == next) continue;
    if (boundary[i] || before.nodes[i].z() < 1.25 - 1e-12)
      CHECK(box.nodes[i] == before.nodes[i]);
    else
      carried += box.nodes[i] != before.nodes[i];
  }
  CHECK(carried > 0);
  // The node right under `top`, one ring in, moved down by 3/4 of the mean
  // move of the pushed nodes it shares elements with (0.4 and 0.3 mm).
  int under = -1;
  for (int i = 0; i < before.node_count(); ++i)
    if ((before.nodes[i] - mesh::Point(2, 2, 1.75)).norm() < 1e-12) under = i;
  REQUIRE(under >= 0);
  const double down = before.nodes[under].z() - box.nodes[under].z();
  CHECK(down >= 0.75 * 0.3 - 1e-12);
  CHECK(down <= 0.75 * 0.4 + 1e-12);
}

TEST_CASE("A carried move that would crush an element is not made", "[unit][mesh]") {
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {2, 2, 0.5}, {4, 4, 1});
  const std::vector<char> boundary = mesh::boundary_node_flags(box);
  int top = -1;
  for (int i = 0; i < box.node_count(); ++i)
    if ((box.nodes[i] - mesh::Point(1, 1, 0.5)).norm() < 1e-12) top = i;
  REQUIRE(top >= 0);
  const mesh::TetMesh before = box;
  mesh::QualityGuard guard(box);
  // Through a plate one element thick, all of its nodes on its surface:
  // even a quarter of the move passes the bottom face, which does not move.
  const std::vector<int> nodes{top};
  const std::vector<mesh::Point> targets{{1, 1, -3.0}};
  const std::vector<double> taken = guard.move_carrying(box, nodes, targets, boundary, 3, 0.1);
  CHECK(taken[0] == 0.0);
  for (int i = 0; i < box.node_count(); ++i)
    CHECK(box.nodes[i] == before.nodes[i]);
}

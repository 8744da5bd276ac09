// Giving a mesh back a volume along the normals of chosen boundary nodes.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/restore_volume.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("Volume is restored by moving the chosen boundary nodes along their normals", "[unit][mesh]") {
  // A 1 mm cube, 3 % short, given back by its top face's inner nodes only:
  // they rise by 0.03 / 0.5625 mm (their share of the top, Σ A/3: 0.5625 mm²).
  mesh::TetMesh cube = mesh::make_box({0, 0, 0}, {1, 1, 1}, 0.25);
  const double target = 1.03;
  std::vector<char> top_inside(cube.nodes.size(), 0);
  int chosen = 0;
  for (std::size_t v = 0; v < cube.nodes.size(); ++v) {
    const mesh::Point& x = cube.nodes[v];
    top_inside[v] = x.z() == 1.0 && x.x() > 0.0 && x.x() < 1.0 && x.y() > 0.0 && x.y() < 1.0;
    chosen += top_inside[v];
  }
  REQUIRE(chosen == 9);
  const std::vector<mesh::Point> before = cube.nodes;
  const double lift = mesh::restore_volume(cube, target, top_inside);
  // On a flat face the volume is linear in the nodes' heights (the integral
  // of a piecewise linear surface): the first pass is exact, to rounding.
  CHECK(mesh::volume(cube) == Approx(target).epsilon(1e-12));
  CHECK(lift == Approx(0.03 / 0.5625).epsilon(1e-12));
  for (std::size_t v = 0; v < cube.nodes.size(); ++v) {
    if (!top_inside[v])
      CHECK(cube.nodes[v] == before[v]);
    else
      CHECK((cube.nodes[v] - before[v] - lift * mesh::Point::UnitZ()).norm() < 1e-12);
  }
}

// Putting a node onto a die while it keeps a coordinate (a symmetry plane).
#include "anvil/die/DieSurface.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace anvil;

TEST_CASE("A node kept on its symmetry plane is put onto an inclined die within the plane", "[unit][die]") {
  // The die x + z = 0 (out of the die: +x+z); the node at z = -1 inside it,
  // kept on the plane x = 0. The closest point moves x; restricted to y and
  // z, each pass halves the depth (cos² 45°), so 20 passes leave 2⁻²⁰.
  const die::PlaneSurface die({0, 0, 0}, {1, 0, 1}, 10.0);
  const mesh::Point onto = die::project_keeping(die, {0.0, 0.3, -1.0}, {false, true, true}, 1e-9);
  CHECK(onto.x() == 0.0);
  CHECK(onto.y() == Approx(0.3).epsilon(1e-15));
  CHECK(std::abs(onto.z()) <= std::ldexp(1.0, -20) * (1.0 + 1e-9));
  // An infinite tolerance makes one pass: half the depth is left.
  const mesh::Point once =
      die::project_keeping(die, {0.0, 0.3, -1.0}, {false, true, true}, std::numeric_limits<double>::infinity());
  CHECK((once - mesh::Point(0.0, 0.3, -0.5)).norm() < 1e-15);
  // Free in every direction: one pass reaches the closest point.
  const mesh::Point closest = die::project_keeping(die, {0.0, 0.3, -1.0}, {true, true, true}, 1e-9);
  CHECK((closest - mesh::Point(0.5, 0.3, -0.5)).norm() < 1e-15);
}

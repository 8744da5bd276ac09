// The part of a body's mesh inside a rigid die (die::overlap_volume).
#include "anvil/die/overlap_volume.h"
#include "anvil/mesh/edge_bisection.h"
#include "anvil/mesh/generators.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace anvil;

namespace {

/// A 90° ridge pointing down along y, its edge at x = 0.5, z = `edge`: the
/// die is z > edge + |x − 0.5|. Exact from inside (the closest point is on
/// the nearer wall of a convex die); from outside the sign is right and the
/// distance to that wall's plane is at most the true one.
class Ridge final : public die::DieSurface {
public:
  explicit Ridge(double edge) : edge_(edge) {}
  die::SurfaceProjection project(const mesh::Point& x) const override {
    const double u = x.x() - 0.5;
    const Eigen::Vector3d normal = Eigen::Vector3d(u < 0.0 ? -1.0 : 1.0, 0.0, -1.0) / std::sqrt(2.0);
    const double distance = normal.dot(x - mesh::Point(0.5, x.y(), edge_)); // < 0 inside, to the nearer wall
    return {x - distance * normal, normal, distance};
  }
  const die::SurfaceTriangles& triangles() const override { return triangles_; }
  std::string describe() const override { return "ridge"; }

private:
  double edge_;
  die::SurfaceTriangles triangles_;
};

} // namespace

TEST_CASE("A flat die's overlap with a body is its depth times the face it covers", "[unit][die]") {
  // A 1 mm cube under the plane z = 0.9 (the die above it, out of the die
  // −z): the top 0.1 mm is inside. The depth is constant on the top face,
  // so the midpoint rule is exact; the side faces cut across the overlap
  // (the die's normal lies in them) and add nothing.
  const mesh::TetMesh cube = mesh::make_box({0, 0, 0}, {1, 1, 1}, 0.25);
  const die::PlaneSurface die({0, 0, 0.9}, {0, 0, -1}, 10.0);
  CHECK(die::overlap_volume(cube, mesh::whole_range(cube), die, Eigen::Vector3d::Zero(), 1.0) ==
        Approx(0.1).epsilon(1e-12));
  // The die's shift moves it: 0.05 mm higher, half the overlap.
  CHECK(die::overlap_volume(cube, mesh::whole_range(cube), die, {0, 0, 0.05}, 1.0) == Approx(0.05).epsilon(1e-12));
  // Deeper than `deepest` is the far side of an open surface: none.
  CHECK(die::overlap_volume(cube, mesh::whole_range(cube), die, Eigen::Vector3d::Zero(), 0.05) == 0.0);
}

TEST_CASE("A die ridge sunk between nodes overlaps the body by its wedge", "[unit][die]") {
  // The ridge's edge 0.2 mm below the top of a 1 mm cube (faces 0.25 mm):
  // the wedge inside is 0.4 mm wide and 0.2 mm deep, 0.04 mm³ over the cube's
  // 1 mm length, between nodes at x = 0.25 and 0.75 that stay outside. The
  // depth below the top face is piecewise linear with kinks at x = 0.3, 0.5
  // and 0.7, which the midpoint rule on sub-triangles of 0.0625 mm integrates
  // to within slope × sub-triangle width² / 8 per unit length at each kink:
  // 3 × 0.0625² / 8 = 1.5e-3 mm³, 3.7 % of the wedge.
  const mesh::TetMesh cube = mesh::make_box({0, 0, 0}, {1, 1, 1}, 0.25);
  const Ridge die(0.8);
  const double overlap = die::overlap_volume(cube, mesh::whole_range(cube), die, Eigen::Vector3d::Zero(), 1.0);
  CHECK(std::abs(overlap - 0.04) <= 1.5e-3);
}

TEST_CASE("The overlap's change from a few changed faces is the whole overlap's change", "[unit][die]") {
  // The ridge sunk 0.2 mm into the cube's top; a top edge over the ridge
  // is bisected and its midpoint pressed down past the die's wall, as a
  // split over a sunk die edge does. overlap_change looks at the faces that changed
  // only; added to the overlap before, it must give the overlap measured
  // anew, to the rounding of two sums of the same face shares (1e-12).
  const mesh::TetMesh before = mesh::make_box({0, 0, 0}, {1, 1, 1}, 0.25);
  const Ridge die(0.8);
  const double overlap_before = die::overlap_volume(before, mesh::whole_range(before), die, {0, 0, 0}, 1.0);
  mesh::TetMesh after = before;
  std::array<int, 2> across{-1, -1};
  for (const mesh::Triangle& f : after.boundary_faces)
    for (int i = 0; i < 3 && across[0] < 0; ++i) {
      const mesh::Point &a = after.nodes[f[i]], &b = after.nodes[f[(i + 1) % 3]];
      if (a.z() == 1.0 && b.z() == 1.0 && a.x() != b.x() && std::abs(a.x() - 0.5) <= 0.25 &&
          std::abs(b.x() - 0.5) <= 0.25)
        across = {f[i], f[(i + 1) % 3]};
    }
  REQUIRE(across[0] >= 0);
  mesh::bisect_edges(after, {across});
  after.nodes.back().z() -= 0.1; // out of the ridge (0.075 mm inside it before): less overlap
  const double overlap_after = die::overlap_volume(after, mesh::whole_range(after), die, {0, 0, 0}, 1.0);
  REQUIRE(overlap_after < overlap_before);
  const double change = die::overlap_change(before, after, die, {0, 0, 0}, 1.0);
  CHECK(std::abs(overlap_before + change - overlap_after) <= 1e-12 * overlap_before);
  // The same surface numbered otherwise changes nothing: no face differs.
  mesh::TetMesh renumbered = before;
  std::reverse(renumbered.boundary_faces.begin(), renumbered.boundary_faces.end());
  CHECK(die::overlap_change(before, renumbered, die, {0, 0, 0}, 1.0) == 0.0);
}

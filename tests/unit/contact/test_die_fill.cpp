// Die fill of a flat square die, 10 × 10 mm in two triangles at z = 0, under
// a block of the part: the area touching, its share of a region, and the
// underfill (distance to the part) at the die's corners, against their
// exact values. The die touches where it is within the tolerance of the
// part: a block h above the die touches over its footprint widened by
// w = √(tolerance² − h²), A + P w + π w² for a footprint of area A and
// perimeter P. The sampled areas are exact where no piece of the die (no
// edge longer than the spacing) straddles the edge of the contact or of the
// region; elsewhere they err by at most the pieces cut by that edge: its
// length times their diameter, the spacing.
#include "test_common.h"

#include "anvil/contact/die_fill.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/mesh/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <random>

using namespace anvil;

namespace {

die::SurfaceTriangles square_die() {
  return {{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, {{0, 1, 2}, {0, 2, 3}}};
}

const contact::FillRegion kWholeDie; // unbounded: the whole die
const Eigen::AlignedBox3d kWholePart(Eigen::Vector3d::Constant(-1e300), Eigen::Vector3d::Constant(1e300));

/// The square die's fill in `region`, sampled at `spacing`, which is also the reach inside the part.
contact::DieFill square_die_fill(const Eigen::Vector3d& displacement, const contact::FillRegion& region,
                                 const Eigen::AlignedBox3d& side, const contact::PartSurface& part, double tolerance,
                                 double spacing, bool with_underfill) {
  return contact::measure_die_fill(contact::fill_samples(square_die(), region, spacing), square_die(), displacement,
                                   side, part, tolerance, spacing, with_underfill);
}

} // namespace

TEST_CASE("die fill: a part covering the whole die fills it", "[unit][contact]") {
  const mesh::TetMesh part = mesh::make_box({-1, -1, 0}, {12, 12, 3}, {4, 4, 1});
  const contact::PartSurface surface(part);
  const contact::DieFill fill =
      square_die_fill(Eigen::Vector3d::Zero(), kWholeDie, kWholePart, surface, 0.1, 0.5, false);
  CHECK(fill.region_area == Approx(100.0).epsilon(1e-12));
  CHECK(fill.contact_area == Approx(100.0).epsilon(1e-12));
  CHECK(fill.fraction() == Approx(1.0).epsilon(1e-12));
  CHECK(fill.underfill.empty());
}

TEST_CASE("die fill: a block on the die, its area, a region and the tolerance", "[unit][contact]") {
  // The block [2, 6]² × [0.05, 3]: 0.05 mm above the die.
  const mesh::TetMesh part = mesh::make_box({2, 2, 0.05}, {4, 4, 2.95}, {4, 4, 3});
  const contact::PartSurface surface(part);
  const double spacing = 0.05;
  const double diameter = spacing; // of a piece
  const contact::DieFill near =
      square_die_fill(Eigen::Vector3d::Zero(), kWholeDie, kWholePart, surface, 0.1, spacing, true);
  const double w = std::sqrt(0.1 * 0.1 - 0.05 * 0.05), pi = std::acos(-1.0);
  CHECK(near.region_area == Approx(100.0).epsilon(1e-10)); // a sum of 2.6e5 pieces: round-off about 1e-11
  CHECK(std::abs(near.contact_area - (16.0 + 16.0 * w + pi * w * w)) <= (16.0 + 2 * pi * w) * diameter);
  // Beyond the tolerance nothing touches.
  const contact::DieFill far =
      square_die_fill(Eigen::Vector3d::Zero(), kWholeDie, kWholePart, surface, 0.01, spacing, false);
  CHECK(far.contact_area == 0.0);
  // The die's corners: distances to the block's nearest edge or corner.
  REQUIRE(near.underfill.size() == 4);
  CHECK(near.underfill[0] == Approx(std::sqrt(2 * 2 + 2 * 2 + 0.05 * 0.05)).epsilon(1e-12));
  CHECK(near.underfill[2] == Approx(std::sqrt(4 * 4 + 4 * 4 + 0.05 * 0.05)).epsilon(1e-12));
  // The region x ≤ 4 (die frame at rest): 40 % of the die, half the block.
  contact::FillRegion half;
  half.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(4, 11, 1));
  const contact::DieFill left =
      square_die_fill(Eigen::Vector3d::Zero(), half, kWholePart, surface, 0.1, spacing, false);
  CHECK(std::abs(left.region_area - 40.0) <= 10.0 * diameter); // the region's edge: 10 mm long
  CHECK(std::abs(left.contact_area - (8.0 + 8.0 * w + pi * w * w / 2)) <= (12.0 + pi * w) * diameter);
  // The die moved 1 mm in x: the region moves with it, to x ≤ 5, and meets
  // the block over [2, 5] × [2, 6].
  const contact::DieFill moved =
      square_die_fill(Eigen::Vector3d(1, 0, 0), half, kWholePart, surface, 0.1, spacing, false);
  CHECK(std::abs(moved.contact_area - (12.0 + 10.0 * w + pi * w * w / 2)) <= (14.0 + pi * w) * diameter);
}

TEST_CASE("die fill: a die point inside the part is at distance zero", "[unit][contact]") {
  const mesh::TetMesh part = mesh::make_box({2, 2, -1}, {4, 4, 4}, {2, 2, 2});
  const contact::PartSurface surface(part);
  CHECK(surface.distance({4.0, 4.3, 0.0}) == 0.0);
  CHECK(surface.distance({4.0, 4.3, 3.5}) == Approx(0.5).epsilon(1e-12));
  CHECK(surface.distance({1.0, 4.0, 0.0}) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("die fill: the distance to a part with a concave side is the nearest face's, zero inside",
          "[unit][contact]") {
  // A quarter ring (its inner wall concave) against every face and every
  // tet: a point is inside when some tet holds it (volumes of the four
  // sub-tets all ≥ 0), else at the smallest distance to a boundary face.
  const mesh::TetMesh part = mesh::make_quarter_ring(10.0, 6.0, 4.0, 1.5);
  const contact::PartSurface surface(part);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(-3.0, 13.0), up(-3.0, 7.0);
  int inside = 0;
  for (int k = 0; k < 400; ++k) {
    const mesh::Point x(across(random), across(random), up(random));
    const bool held = std::any_of(part.tets.begin(), part.tets.end(), [&](const mesh::Tet& t) {
      for (int a = 0; a < 4; ++a) {
        std::array<mesh::Point, 4> corners;
        for (int b = 0; b < 4; ++b)
          corners[b] = b == a ? x : part.nodes[t[b]];
        if (mesh::signed_volume(corners[0], corners[1], corners[2], corners[3]) < 0.0) return false;
      }
      return true;
    });
    double nearest = std::numeric_limits<double>::infinity();
    for (const mesh::Triangle& f : part.boundary_faces)
      nearest = std::min(
          nearest, (x - mesh::nearest_on_triangle(x, part.nodes[f[0]], part.nodes[f[1]], part.nodes[f[2]])).norm());
    inside += held;
    CHECK(surface.distance(x) == Approx(held ? 0.0 : nearest).margin(1e-12));
  }
  CHECK(inside > 20); // the points sample the inside too
}

TEST_CASE("die fill: a half model counts the die on its side, and mirrors the rest", "[unit][contact]") {
  // The block of the test above cut by its symmetry plane x = 4: the model is
  // [4, 6] × [2, 6] × [0.05, 3], the die is drawn whole.
  const mesh::TetMesh part = mesh::make_box({4, 2, 0.05}, {2, 4, 2.95}, {2, 4, 3});
  const contact::PartSurface surface(part);
  Eigen::AlignedBox3d side = kWholePart;
  side.min().x() = 4.0;
  const double spacing = 0.05;
  const double diameter = spacing;
  const double w = std::sqrt(0.1 * 0.1 - 0.05 * 0.05), pi = std::acos(-1.0);
  const contact::DieFill fill = square_die_fill(Eigen::Vector3d::Zero(), kWholeDie, side, surface, 0.1, spacing, true);
  CHECK(std::abs(fill.region_area - 60.0) <= 10.0 * diameter); // the plane's trace: 10 mm
  // Widened on three sides, not across the plane: 2 + 4 + 2 mm of edge.
  CHECK(std::abs(fill.contact_area - (8.0 + 8.0 * w + pi * w * w / 2)) <= (12.0 + pi * w) * diameter);
  // The corner (0, 0) is the mirror image's: measured at (8, 0), as the whole block's.
  CHECK(fill.underfill[0] == Approx(std::sqrt(2 * 2 + 2 * 2 + 0.05 * 0.05)).epsilon(1e-12));
}

TEST_CASE("die fill: a region of revolution about the press axis", "[unit][contact]") {
  // The part covers the die; the region is the disc r ≤ 5 about (0, 0): a
  // quarter of it lies on the die, π 25 / 4 mm², touching all over.
  const mesh::TetMesh part = mesh::make_box({-1, -1, 0}, {12, 12, 3}, {4, 4, 1});
  const contact::PartSurface surface(part);
  contact::FillRegion disc;
  disc.radius = 5.0;
  const double spacing = 0.05, pi = std::acos(-1.0);
  const double diameter = spacing;
  const contact::DieFill fill =
      square_die_fill(Eigen::Vector3d::Zero(), disc, kWholePart, surface, 0.1, spacing, false);
  CHECK(std::abs(fill.region_area - pi * 25.0 / 4.0) <= (pi * 5.0 / 2.0) * diameter); // the arc: 7.9 mm
  CHECK(fill.contact_area == fill.region_area);
}

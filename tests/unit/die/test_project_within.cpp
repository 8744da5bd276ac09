// A die's closest point looked for within a reach (DieSurface::project_within).
#include "anvil/die/StlSurface.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace anvil;

namespace {

/// project_within(x, reach) against project(x) at points of a lattice over
/// `box` (mm): the same closest point and distance when the die comes closer
/// than the reach, nothing when it does not. Returns how many were within.
int check_against_project(const die::DieSurface& die, const Eigen::AlignedBox3d& box, double reach) {
  constexpr int n = 12;
  int within = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const mesh::Point x =
            box.min() + box.sizes().cwiseProduct(Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5) / double(n));
        const die::SurfaceProjection all = die.project(x);
        const std::optional<die::SurfaceProjection> near = die.project_within(x, reach);
        INFO("point " << x.transpose() << ", distance " << all.distance);
        REQUIRE(near.has_value() == (std::abs(all.distance) < reach));
        if (!near) continue;
        ++within;
        // One closest point; where two facets share it (an edge) the search
        // may name either, with the same point to round-off.
        CHECK((near->point - all.point).norm() <= 1e-12 * (1.0 + x.norm()));
        CHECK(near->distance == Approx(all.distance).margin(1e-12));
      }
  return within;
}

} // namespace

TEST_CASE("A die looked for within a reach gives its closest point, or nothing beyond", "[unit][die]") {
  // The hub flange's upper die (16k facets, flats, drafts and fillets),
  // queried around its cavity: points within 1 mm and points farther.
  const auto die = die::read_stl_surface(ANVIL_SOURCE_DIR "/dies/hub_flange_upper.stl", "test");
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-3.0, -3.0, 0.0), Eigen::Vector3d(30.0, 30.0, 25.0));
  const int within = check_against_project(*die, box, 1.0);
  const int wider = check_against_project(*die, box, 5.0);
  // Both answers occur: the lattice is not all near or all far.
  CHECK(within > 0);
  CHECK(wider > within);
  CHECK(wider < 12 * 12 * 12);
  // An analytic die answers the same way (the default: one projection).
  const die::PlaneSurface plane({0, 0, 10.0}, {0, 0, -1}, 50.0);
  CHECK(check_against_project(plane, box, 1.0) > 0);
}

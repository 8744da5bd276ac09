// The intersection quadrature's geometry (contact/facet_quadrature.h): the
// parts of a facet over the facets of another surface cover it once, and the
// 3-point rule on them integrates M_k N_j exactly between flat facets.
#include "anvil/contact/facet_quadrature.h"

#include <catch2/catch.hpp>

using namespace anvil::contact;
using Corners = std::array<Eigen::Vector3d, 3>;

namespace {

double covered(const FacetOverlap& o) {
  double sum = 0.0;
  for (int i = 0; i < o.count; ++i)
    sum += o.area_fraction[i];
  return sum;
}

/// The unit square [0,1]² at height z, as two triangles (normal up unless `down`).
std::array<Corners, 2> square(double z, bool down) {
  const Eigen::Vector3d a(0, 0, z), b(1, 0, z), c(1, 1, z), d(0, 1, z);
  if (down) return {Corners{a, c, b}, Corners{a, d, c}};
  return {Corners{a, b, c}, Corners{a, c, d}};
}

} // namespace

TEST_CASE("a facet over another surface is covered once by its overlaps", "[unit]") {
  // A facet facing down (the upper body's bottom), inside the unit square,
  // over a lower surface facing up made of the square's two triangles.
  const Corners own{Eigen::Vector3d(0.1, 0.2, 1e-3), Eigen::Vector3d(0.7, 0.9, 1e-3), Eigen::Vector3d(0.9, 0.1, 1e-3)};
  double total = 0.0;
  for (const Corners& other : square(0.0, false)) {
    const FacetOverlap o = overlap(own, other);
    total += covered(o);
    for (int i = 0; i < o.count; ++i)
      for (const Eigen::Vector3d& corner : o.parts[i]) {
        CHECK(corner.sum() == Approx(1.0).margin(1e-14));
        CHECK(corner.minCoeff() >= -1e-12); // inside own
      }
  }
  CHECK(total == Approx(1.0).margin(1e-13));
}

TEST_CASE("facets that do not overlap, or stand edge-on, have no overlap", "[unit]") {
  const Corners other = square(0.0, false)[0];
  const Corners apart{Eigen::Vector3d(2, 2, 0), Eigen::Vector3d(3, 2, 0), Eigen::Vector3d(2, 3, 0)};
  CHECK(overlap(apart, other).count == 0);
  const Corners edge_on{Eigen::Vector3d(0.5, 0.2, 0), Eigen::Vector3d(0.5, 0.2, 1), Eigen::Vector3d(0.5, 0.6, 0)};
  CHECK(overlap(edge_on, other).count == 0);
}

TEST_CASE("a tilted facet is projected along the other facet's normal", "[unit]") {
  // Own spans x in [0.5, 1.5] and rises with x; half of its projection lies over other.
  const Corners other{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  const Corners big{Eigen::Vector3d(-1, -1, 0.0), Eigen::Vector3d(3, -1, 0.4), Eigen::Vector3d(-1, 3, 0.0)};
  // Other's projection (area 1/2) lies wholly inside big's (area 8).
  CHECK(covered(overlap(big, other)) == Approx(0.5 / 8.0).epsilon(1e-12));
}

TEST_CASE("the 3-point rule on the overlaps integrates M_k N_j exactly", "[unit]") {
  // ∫_own M_k N_j over own's overlap with one lower triangle, against the
  // same integral by a fine subdivision (an independent, converging rule).
  const Corners own{Eigen::Vector3d(0.1, 0.2, 0), Eigen::Vector3d(0.9, 0.1, 0), Eigen::Vector3d(0.7, 0.9, 0)};
  const Corners other = square(0.0, false)[0]; // (0,0), (1,0), (1,1): N = (1 − x, x − y, y)
  auto lower_shape = [](const Eigen::Vector3d& x) { return Eigen::Vector3d(1 - x.x(), x.x() - x.y(), x.y()); };
  auto at = [&](const Eigen::Vector3d& l) { return l[0] * own[0] + l[1] * own[1] + l[2] * own[2]; };
  Eigen::Matrix3d exact = Eigen::Matrix3d::Zero(), reference = Eigen::Matrix3d::Zero();
  const FacetOverlap o = overlap(own, other);
  REQUIRE(o.count > 0);
  for (int i = 0; i < o.count; ++i)
    for (const FacetQuadraturePoint& g : degree_two_rule(o.parts[i], o.area_fraction[i]))
      exact += g.weight * g.barycentric * lower_shape(at(g.barycentric)).transpose();
  // Reference: 4^7 sub-triangles, midpoint rule, only those whose centroid lies over `other`.
  std::vector<SubTriangle> parts{whole_facet()};
  for (int level = 0; level < 7; ++level) {
    std::vector<SubTriangle> next;
    for (const SubTriangle& t : parts)
      for (const SubTriangle& child : split(t))
        next.push_back(child);
    parts.swap(next);
  }
  for (const SubTriangle& t : parts) {
    const Eigen::Vector3d l = (t[0] + t[1] + t[2]) / 3.0;
    const Eigen::Vector3d n = lower_shape(at(l));
    if (n.minCoeff() >= 0.0) reference += (1.0 / static_cast<double>(parts.size())) * l * n.transpose();
  }
  // The reference errs only in the strips along other's edges (3·2^7 of its
  // 4^7 parts), with errors of both signs: 4e-6 measured. A part of the
  // overlap lost or counted twice (a few % of the area) errs by 1e-3 or more.
  CHECK((exact - reference).cwiseAbs().maxCoeff() < 1e-4);
  CHECK(exact.sum() == Approx(covered(o)).epsilon(1e-13)); // Σ M_k N_j = 1
}

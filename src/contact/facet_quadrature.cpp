#include "anvil/contact/facet_quadrature.h"

#include <Eigen/Geometry>
#include <cmath>

namespace anvil::contact {

SubTriangle whole_facet() {
  return {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
}

std::array<SubTriangle, 4> split(const SubTriangle& t) {
  const Eigen::Vector3d m01 = 0.5 * (t[0] + t[1]), m12 = 0.5 * (t[1] + t[2]), m20 = 0.5 * (t[2] + t[0]);
  return {SubTriangle{t[0], m01, m20}, SubTriangle{m01, t[1], m12}, SubTriangle{m20, m12, t[2]},
          SubTriangle{m12, m20, m01}};
}

std::array<FacetQuadraturePoint, 3> degree_two_rule(const SubTriangle& t, double area_fraction) {
  std::array<FacetQuadraturePoint, 3> rule;
  for (int k = 0; k < 3; ++k)
    rule[k] = {(2.0 / 3.0) * t[k] + (1.0 / 6.0) * (t[(k + 1) % 3] + t[(k + 2) % 3]), area_fraction / 3.0};
  return rule;
}

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// A convex polygon of at most 6 corners in a plane: a triangle clipped by three half-planes.
struct Polygon {
  int count = 0;
  std::array<Eigen::Vector2d, 6> corner;
};

/// The part of `p` on the left of the directed line a→b (Sutherland-Hodgman, one edge).
Polygon clip(const Polygon& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Polygon out;
  const Eigen::Vector2d edge = b - a;
  for (int i = 0; i < p.count; ++i) {
    const Eigen::Vector2d& s = p.corner[i];
    const Eigen::Vector2d& e = p.corner[(i + 1) % p.count];
    const double ds = cross(edge, s - a), de = cross(edge, e - a);
    if (ds >= 0.0 && out.count < 6) out.corner[out.count++] = s;
    if (((ds > 0.0 && de < 0.0) || (ds < 0.0 && de > 0.0)) && out.count < 6)
      out.corner[out.count++] = s + (ds / (ds - de)) * (e - s);
  }
  return out;
}

} // namespace

FacetOverlap overlap(const std::array<Eigen::Vector3d, 3>& own, const std::array<Eigen::Vector3d, 3>& other) {
  FacetOverlap result;
  // In-plane frame of `other`, counter-clockwise about its normal.
  const Eigen::Vector3d normal = (other[1] - other[0]).cross(other[2] - other[0]).normalized();
  const Eigen::Vector3d e1 = (other[1] - other[0]).normalized(), e2 = normal.cross(e1);
  auto in_plane = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector2d((x - other[0]).dot(e1), (x - other[0]).dot(e2));
  };
  Polygon p;
  p.count = 3;
  for (int k = 0; k < 3; ++k)
    p.corner[k] = in_plane(own[k]);
  // Own's projection, oriented so its barycentric map below is signed right.
  const double own_area = 0.5 * cross(p.corner[1] - p.corner[0], p.corner[2] - p.corner[0]);
  const double own_size = (own[1] - own[0]).norm() + (own[2] - own[1]).norm() + (own[0] - own[2]).norm();
  if (std::abs(own_area) <= 1e-12 * own_size * own_size) return result; // edge-on
  const std::array<Eigen::Vector2d, 3> own_2d{p.corner[0], p.corner[1], p.corner[2]};
  for (int k = 0; k < 3 && p.count > 0; ++k)
    p = clip(p, in_plane(other[k]), in_plane(other[(k + 1) % 3]));
  if (p.count < 3) return result;
  auto own_barycentric = [&](const Eigen::Vector2d& x) {
    const double l1 = cross(x - own_2d[0], own_2d[2] - own_2d[0]) / (2.0 * own_area);
    const double l2 = cross(own_2d[1] - own_2d[0], x - own_2d[0]) / (2.0 * own_area);
    return Eigen::Vector3d(1.0 - l1 - l2, l1, l2);
  };
  // The clipped polygon keeps own's orientation, which faces away from
  // other's when the bodies face each other.
  for (int i = 1; i + 1 < p.count; ++i) { // fan from the first corner
    const double part = 0.5 * cross(p.corner[i] - p.corner[0], p.corner[i + 1] - p.corner[0]) / own_area;
    if (part <= 1e-14) continue; // a sliver of round-off
    result.parts[result.count] = {own_barycentric(p.corner[0]), own_barycentric(p.corner[i]),
                                  own_barycentric(p.corner[i + 1])};
    result.area_fraction[result.count++] = part;
  }
  return result;
}

} // namespace anvil::contact

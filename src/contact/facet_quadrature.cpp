#include "anvil/contact/facet_quadrature.h"

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

} // namespace anvil::contact

#include "anvil/mesh/tet_geometry.h"

#include <Eigen/Dense>
#include <cmath>

namespace anvil::mesh {

double signed_volume(const Point& x0, const Point& x1, const Point& x2, const Point& x3) {
  return (x1 - x0).dot((x2 - x0).cross(x3 - x0)) / 6.0;
}

double quality(const Point& x0, const Point& x1, const Point& x2, const Point& x3) {
  const double sum_sq = (x1 - x0).squaredNorm() + (x2 - x0).squaredNorm() + (x3 - x0).squaredNorm() +
                        (x2 - x1).squaredNorm() + (x3 - x1).squaredNorm() + (x3 - x2).squaredNorm();
  const double l_rms = std::sqrt(sum_sq / 6.0);
  if (l_rms == 0.0) return 0.0;
  return 6.0 * std::sqrt(2.0) * signed_volume(x0, x1, x2, x3) / (l_rms * l_rms * l_rms);
}

P1Gradients p1_gradients(const Point& x0, const Point& x1, const Point& x2, const Point& x3) {
  // Rows of J⁻ᵀ ... : with J = [x1-x0, x2-x0, x3-x0], ∇λ_{1..3} are the rows of J⁻¹,
  // and ∇λ_0 = -(∇λ_1 + ∇λ_2 + ∇λ_3).
  Eigen::Matrix3d jacobian;
  jacobian.col(0) = x1 - x0;
  jacobian.col(1) = x2 - x0;
  jacobian.col(2) = x3 - x0;
  const Eigen::Matrix3d inverse = jacobian.inverse();
  P1Gradients g;
  g.grad.row(1) = inverse.row(0);
  g.grad.row(2) = inverse.row(1);
  g.grad.row(3) = inverse.row(2);
  g.grad.row(0) = -(inverse.row(0) + inverse.row(1) + inverse.row(2));
  g.volume = jacobian.determinant() / 6.0;
  return g;
}

} // namespace anvil::mesh

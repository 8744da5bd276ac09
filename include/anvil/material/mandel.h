// Symmetric 3×3 tensors as 6-vectors in Mandel notation:
// [xx, yy, zz, √2 xy, √2 yz, √2 zx]. With it a:b is a plain dot product and
// fourth-order tangents are symmetric 6×6 matrices.
#pragma once
#include <Eigen/Core>
#include <cmath>

namespace anvil::material {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

inline constexpr double kSqrt2 = 1.4142135623730951;

/// Deviatoric projector P (P ε = dev ε).
inline Mat6 deviatoric_projector() {
  Mat6 p = Mat6::Identity();
  p.topLeftCorner<3, 3>().array() -= 1.0 / 3.0;
  return p;
}

inline Vec6 deviator(const Vec6& a) {
  Vec6 d = a;
  const double mean = (a[0] + a[1] + a[2]) / 3.0;
  d[0] -= mean;
  d[1] -= mean;
  d[2] -= mean;
  return d;
}

/// Equivalent strain rate sqrt(2/3 dev ε̇ : dev ε̇) (1/s).
inline double equivalent_strain_rate(const Vec6& strain_rate) {
  return std::sqrt(2.0 / 3.0 * deviator(strain_rate).squaredNorm());
}

/// von Mises stress sqrt(3/2 s:s) (MPa).
inline double von_mises(const Vec6& stress) {
  return std::sqrt(1.5 * deviator(stress).squaredNorm());
}

/// Mandel 6-vector -> tensor components [xx, yy, zz, xy, yz, zx].
inline Vec6 to_components(const Vec6& mandel) {
  Vec6 c = mandel;
  c.tail<3>() /= kSqrt2;
  return c;
}

} // namespace anvil::material

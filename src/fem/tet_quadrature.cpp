#include "anvil/fem/tet_quadrature.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace anvil::fem {

namespace {

/// A symmetric rule, built orbit by orbit (weights as fractions of the volume).
class RuleBuilder {
public:
  /// 4 points: one coordinate 1 − 3a, the others a.
  RuleBuilder& s31(double a, double w) {
    for (int i = 0; i < 4; ++i) {
      TetQuadraturePoint& q = points_.emplace_back(TetQuadraturePoint{{a, a, a, a}, w});
      q.barycentric[i] = 1.0 - 3.0 * a;
    }
    return *this;
  }
  /// 6 points: two coordinates a, the others 1/2 − a.
  RuleBuilder& s22(double a, double w) {
    const double b = 0.5 - a;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        TetQuadraturePoint& q = points_.emplace_back(TetQuadraturePoint{{b, b, b, b}, w});
        q.barycentric[i] = q.barycentric[j] = a;
      }
    return *this;
  }
  /// 12 points: one coordinate b, another 1 − 2a − b, the other two a.
  RuleBuilder& s211(double a, double b, double w) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != j) {
          TetQuadraturePoint& q = points_.emplace_back(TetQuadraturePoint{{a, a, a, a}, w});
          q.barycentric[i] = b;
          q.barycentric[j] = 1.0 - 2.0 * a - b;
        }
    return *this;
  }
  std::vector<TetQuadraturePoint> points() const { return points_; }

private:
  std::vector<TetQuadraturePoint> points_;
};

} // namespace

std::span<const TetQuadraturePoint> tet_quadrature(int degree) {
  static const std::vector<TetQuadraturePoint> degree5 = RuleBuilder()
                                                             .s31(0.3108859192633006, 0.1126879257180159)
                                                             .s31(0.0927352503108912, 0.0734930431163620)
                                                             .s22(0.0455037041256496, 0.0425460207770815)
                                                             .points();
  // Keast's weights are given for the reference tet of volume 1/6.
  static const std::vector<TetQuadraturePoint> degree6 =
      RuleBuilder()
          .s31(0.2146028712591517, 6.0 * 0.006653791709694646)
          .s31(0.04067395853461135, 6.0 * 0.001679535175886783)
          .s31(0.3223378901422757, 6.0 * 0.009226196923942399)
          .s211(0.06366100187501752, 0.2696723314583159, 6.0 * 0.008035714285714286)
          .points();
  if (degree == 5) return degree5;
  if (degree == 6) return degree6;
  throw std::invalid_argument("no tetrahedron quadrature of degree " + std::to_string(degree) + " (5 or 6)");
}

} // namespace anvil::fem

#include "anvil/fem/tet_quadrature.h"

namespace anvil::fem {

const std::array<TetQuadraturePoint, kTetQuadratureSize>& tet_quadrature() {
  static const std::array<TetQuadraturePoint, kTetQuadratureSize> rule = [] {
    std::array<TetQuadraturePoint, kTetQuadratureSize> r{};
    int n = 0;
    auto orbit31 = [&](double a, double w) {
      const double b = 1.0 - 3.0 * a;
      for (int i = 0; i < 4; ++i) {
        r[n].barycentric = {a, a, a, a};
        r[n].barycentric[i] = b;
        r[n++].weight = w;
      }
    };
    auto orbit22 = [&](double a, double w) {
      const double b = 0.5 - a;
      constexpr int pairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
      for (const auto& pr : pairs) {
        r[n].barycentric = {b, b, b, b};
        r[n].barycentric[pr[0]] = a;
        r[n].barycentric[pr[1]] = a;
        r[n++].weight = w;
      }
    };
    orbit31(0.3108859192633006, 0.1126879257180159);
    orbit31(0.0927352503108912, 0.0734930431163620);
    orbit22(0.0455037041256496, 0.0425460207770815);
    return r;
  }();
  return rule;
}

} // namespace anvil::fem

#include "test_common.h"

#include "anvil/fem/tet_quadrature.h"

#include <algorithm>
#include <cmath>

using anvil::fem::tet_quadrature;

namespace {
double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}
} // namespace

TEST_CASE("each tet quadrature integrates barycentric monomials up to its degree exactly, and not beyond", "[unit]") {
  // ∫ λ0^a λ1^b λ2^c λ3^d dV / V = 6 a! b! c! d! / (a+b+c+d+3)!
  for (const int degree : anvil::fem::kTetQuadratureDegrees) {
    double worst_beyond = 0.0; // the largest relative error at degree + 1
    for (int a = 0; a <= degree + 1; ++a)
      for (int b = 0; a + b <= degree + 1; ++b)
        for (int c = 0; a + b + c <= degree + 1; ++c)
          for (int d = 0; a + b + c + d <= degree + 1; ++d) {
            double sum = 0.0;
            for (const auto& q : tet_quadrature(degree)) {
              const auto& l = q.barycentric;
              sum += q.weight * std::pow(l[0], a) * std::pow(l[1], b) * std::pow(l[2], c) * std::pow(l[3], d);
            }
            const double exact =
                6.0 * factorial(a) * factorial(b) * factorial(c) * factorial(d) / factorial(a + b + c + d + 3);
            if (a + b + c + d == degree + 1) {
              worst_beyond = std::max(worst_beyond, std::abs(sum / exact - 1.0));
              continue;
            }
            INFO("degree " << degree << ", exponents " << a << b << c << d);
            CHECK(sum == Approx(exact).epsilon(1e-13));
          }
    INFO("degree " << degree);
    CHECK(worst_beyond > 1e-4);
  }
}

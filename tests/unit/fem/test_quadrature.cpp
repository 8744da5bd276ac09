#include "test_common.h"

#include "anvil/fem/tet_quadrature.h"

#include <cmath>

using anvil::fem::tet_quadrature;

namespace {
double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}
} // namespace

TEST_CASE("tet quadrature integrates barycentric monomials up to degree 5 exactly", "[unit]") {
  // ∫ λ0^a λ1^b λ2^c λ3^d dV / V = 6 a! b! c! d! / (a+b+c+d+3)!
  for (int a = 0; a <= 5; ++a)
    for (int b = 0; a + b <= 5; ++b)
      for (int c = 0; a + b + c <= 5; ++c)
        for (int d = 0; a + b + c + d <= 5; ++d) {
          double sum = 0.0;
          for (const auto& q : tet_quadrature()) {
            const auto& l = q.barycentric;
            sum += q.weight * std::pow(l[0], a) * std::pow(l[1], b) * std::pow(l[2], c) * std::pow(l[3], d);
          }
          const double exact =
              6.0 * factorial(a) * factorial(b) * factorial(c) * factorial(d) / factorial(a + b + c + d + 3);
          INFO("exponents " << a << b << c << d);
          CHECK(sum == Approx(exact).epsilon(1e-13));
        }
}

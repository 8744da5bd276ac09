// 14-point quadrature on the tetrahedron, exact for polynomials of degree 5
// (Walkington 2000, "Quadrature on simplices of arbitrary dimension", rule
// with orbits S31(a1), S31(a2), S22(a3)). Degree 5 integrates the bubble's
// gradient (degree 3) exactly, so ∫ ∇b = 0 holds to round-off, which keeps
// homogeneous solutions exact.
#pragma once
#include <array>

namespace anvil::fem {

struct TetQuadraturePoint {
  std::array<double, 4> barycentric;
  double weight; ///< fraction of the tet volume; weights sum to 1
};

inline constexpr int kTetQuadratureSize = 14;

const std::array<TetQuadraturePoint, kTetQuadratureSize>& tet_quadrature();

} // namespace anvil::fem

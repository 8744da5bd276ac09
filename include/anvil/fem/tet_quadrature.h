// Quadrature on the tetrahedron (docs/method.md, "Element quadrature").
// Degree 5, 14 points (Walkington 2000, "Quadrature on simplices of arbitrary
// dimension", orbits S31(a1), S31(a2), S22(a3)): integrates the bubble's
// gradient (degree 3) and the coupling of the bubble with the linear
// velocity (degree 3 for a linear law) exactly, so ∫ ∇b = 0 holds to
// round-off, which keeps homogeneous solutions exact. The bubble-bubble
// stiffness ∫ ∇b ∇bᵀ of a linear law is of degree 6: under-integrated.
// Degree 6, 24 points (Keast 1986, "Moderate-degree tetrahedral quadrature
// formulas", orbits S31 × 3, S211): exact for it.
#pragma once
#include <array>
#include <span>

namespace anvil::fem {

struct TetQuadraturePoint {
  std::array<double, 4> barycentric;
  double weight; ///< fraction of the tet volume; weights sum to 1
};

/// The rules there are: the degree of polynomial each integrates exactly.
inline constexpr std::array<int, 2> kTetQuadratureDegrees = {5, 6};

/// The rule exact to degree `degree` (5 or 6; throws std::invalid_argument otherwise).
std::span<const TetQuadraturePoint> tet_quadrature(int degree = 5);

} // namespace anvil::fem

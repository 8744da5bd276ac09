// The P1+/P1 (MINI) tetrahedron (docs/design.md §2): linear velocity plus the cubic
// bubble b = 256 λ1λ2λ3λ4, linear continuous pressure. The 19×19 element
// system (12 nodal + 3 bubble velocities, 4 pressures) is condensed onto the
// nodal unknowns: a 16×16 system ordered [vx vy vz p] per vertex, matching
// the global interleaved numbering.
#pragma once
#include "anvil/fem/strain_rate_dual.h"
#include "anvil/material/Material.h"
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <functional>

namespace anvil::fem {

using Vec3 = Eigen::Vector3d;
using Vec16 = Eigen::Matrix<double, 16, 1>;
using Mat16 = Eigen::Matrix<double, 16, 16>;

/// Gradient of the bubble b = 256 λ0λ1λ2λ3 at barycentric point `l`, given
/// the P1 gradients ∇λa as rows: ∇b = 256 Σ_a (Π_{c≠a} λc) ∇λa (1/mm).
inline Vec3 bubble_gradient(const std::array<double, 4>& l, const Eigen::Matrix<double, 4, 3>& grad) {
  return 256.0 * (l[1] * l[2] * l[3] * grad.row(0) + l[0] * l[2] * l[3] * grad.row(1) +
                  l[0] * l[1] * l[3] * grad.row(2) + l[0] * l[1] * l[2] * grad.row(3))
                     .transpose();
}

/// Body force density f(x) in N/mm³ (MPa/mm); empty when the scene has none.
using BodyForce = std::function<Vec3(const mesh::Point&)>;

/// Current values of the element's unknowns.
struct MiniElementInput {
  std::array<mesh::Point, 4> vertices;    ///< positive orientation, mm
  std::array<Vec3, 4> nodal_velocity;     ///< mm/s (mm for elastic laws)
  Vec3 bubble_velocity = Vec3::Zero();    ///< bubble coefficient, same unit
  std::array<double, 4> nodal_pressure{}; ///< MPa
  material::PointState state;             ///< element history
  /// The rank-one term of the nodes' tangent is built with max(m, this) for m
  /// (0: the consistent tangent); Newton's far phase (IncrementSolver).
  double tangent_sensitivity_floor = 0.0;
  int quadrature_degree = 5; ///< of the rule over the element (fem::tet_quadrature)
  /// Newton's own direction of the strain rate (fem/strain_rate_dual.h);
  /// null: the consistent tangent.
  const ElementDual* dual = nullptr;
};

/// Condensed element system. Residual sign: R = internal − external, so
/// Newton solves tangent · Δ = −residual.
struct MiniElementSystem {
  Vec16 residual;
  Mat16 tangent;                            ///< symmetric; filled only when asked for
  Eigen::Matrix<double, 3, 16> bubble_gain; ///< K_bb⁻¹ [K_bl  G_b]
  Vec3 bubble_residual_solved;              ///< K_bb⁻¹ r_b
  double bubble_residual_sq = 0.0;          ///< |r_b|², for the residual norm
  double volume = 0.0;                      ///< mm³; ≤ 0 means the tet is inverted
  /// Mean tangent viscosity tr(∫D)/(10 V) (MPa·s; the shear modulus for
  /// elastic laws): η for a Newtonian law (D = 2η P_dev, tr P_dev = 5), between
  /// mη and η for Norton-Hoff; scales the Schur-complement approximation.
  double viscosity = 0.0;
};

/// Fills `out` for one element. Returns false, leaving `out` unspecified, when
/// the tet is inverted or flat (the caller names element and body).
/// Allocates nothing (unless `body_force` does).
bool mini_element(const MiniElementInput& in, const material::Material& law, bool with_tangent,
                  const BodyForce& body_force, MiniElementSystem& out);

/// Bubble increment that goes with nodal increments `delta` (ordered as the
/// condensed system): Δb = −(K_bb⁻¹ r_b + bubble_gain · delta).
inline Vec3 bubble_increment(const MiniElementSystem& system, const Vec16& delta) {
  return -(system.bubble_residual_solved + system.bubble_gain * delta);
}

/// Element-centre values for output: strain rate of the linear part (the
/// bubble's gradient vanishes at the centroid), deviatoric stress and mean pressure.
struct MiniElementFields {
  material::Vec6 strain_rate; ///< Mandel, 1/s
  material::Vec6 stress;      ///< Cauchy σ = s − p I, Mandel, MPa
  double equivalent_strain_rate;
};
MiniElementFields mini_element_fields(const MiniElementInput& in, const material::Material& law);

} // namespace anvil::fem

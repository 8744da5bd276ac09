#include "anvil/fem/mini_element.h"

#include "anvil/fem/tet_quadrature.h"
#include "anvil/mesh/tet_geometry.h"

#include <Eigen/Dense>

namespace anvil::fem {
namespace {

using material::kSqrt2;
using material::Mat6;
using material::Vec6;

/// Mandel strain of the velocity field v ⊗ g (one shape-function gradient g
/// times a unit vector per column): 6×3 block.
Eigen::Matrix<double, 6, 3> strain_operator(const Vec3& g) {
  Eigen::Matrix<double, 6, 3> b = Eigen::Matrix<double, 6, 3>::Zero();
  const double s = 1.0 / kSqrt2; // Mandel shear: √2 · ½ (∂i vj + ∂j vi)
  b(0, 0) = g.x();
  b(1, 1) = g.y();
  b(2, 2) = g.z();
  b(3, 0) = s * g.y();
  b(3, 1) = s * g.x();
  b(4, 1) = s * g.z();
  b(4, 2) = s * g.y();
  b(5, 0) = s * g.z();
  b(5, 2) = s * g.x();
  return b;
}

// ∫ λ1λ2λ3λ4 dV = V/840 (∫ Πλ^a = 6V Πa!/(Σa+3)!), so ∫ b = 256 V/840.
constexpr double kBubbleIntegral = 256.0 / 840.0;

struct Geometry {
  Eigen::Matrix<double, 6, 12> linear_strain; ///< B_l: constant over the tet
  Eigen::Matrix<double, 4, 3> grad;           ///< ∇λ_a as rows
  double volume;
};

bool geometry(const MiniElementInput& in, Geometry& g) {
  const auto& x = in.vertices;
  const mesh::P1Gradients p1 = mesh::p1_gradients(x[0], x[1], x[2], x[3]);
  if (!(p1.volume > 0.0)) return false; // inverted or flat: the gradients are meaningless
  g.grad = p1.grad;
  g.volume = p1.volume;
  for (int a = 0; a < 4; ++a)
    g.linear_strain.block<6, 3>(0, 3 * a) = strain_operator(g.grad.row(a).transpose());
  return true;
}

Eigen::Matrix<double, 12, 1> stack(const std::array<Vec3, 4>& nodal) {
  Eigen::Matrix<double, 12, 1> v;
  for (int a = 0; a < 4; ++a)
    v.segment<3>(3 * a) = nodal[a];
  return v;
}

} // namespace

bool mini_element(const MiniElementInput& in, const material::Material& law, bool with_tangent,
                  const BodyForce& body_force, MiniElementSystem& out) {
  Geometry g;
  if (!geometry(in, g)) {
    out.volume = 0.0;
    return false;
  }
  const double volume = g.volume;
  out.volume = volume;
  const Eigen::Matrix<double, 12, 1> v_lin = stack(in.nodal_velocity);
  const Vec6 linear_strain = g.linear_strain * v_lin;

  // Quadrature of the viscous (or elastic) term. B_l is constant, so only
  // Σ w s, Σ w D and Σ w D B_b are accumulated per point (the 12×12 products
  // are formed once per element). K_bb and K_lb are always needed: the
  // condensed residual is r_l − K_lb K_bb⁻¹ r_b.
  Vec6 stress_sum = Vec6::Zero();
  Mat6 tangent_sum = Mat6::Zero();
  Eigen::Matrix<double, 6, 3> tangent_bubble_sum = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix3d k_bb = Eigen::Matrix3d::Zero();
  Vec3 r_b = Vec3::Zero();
  Eigen::Matrix<double, 12, 1> r_l_force = Eigen::Matrix<double, 12, 1>::Zero();
  Vec6 stress;
  Mat6 tangent;
  for (const TetQuadraturePoint& q : tet_quadrature()) {
    const auto& l = q.barycentric;
    const Eigen::Matrix<double, 6, 3> b_bubble = strain_operator(bubble_gradient(l, g.grad));
    law.deviatoric_stress(linear_strain + b_bubble * in.bubble_velocity, in.state, stress, tangent);
    const double w = q.weight * volume;
    const Eigen::Matrix<double, 6, 3> d_b = tangent * b_bubble;
    stress_sum += w * stress;
    r_b.noalias() += w * b_bubble.transpose() * stress;
    tangent_sum += w * tangent;
    tangent_bubble_sum += w * d_b;
    k_bb.noalias() += w * b_bubble.transpose() * d_b;
    if (body_force) {
      const mesh::Point x =
          l[0] * in.vertices[0] + l[1] * in.vertices[1] + l[2] * in.vertices[2] + l[3] * in.vertices[3];
      const Vec3 f = body_force(x);
      for (int a = 0; a < 4; ++a)
        r_l_force.segment<3>(3 * a) -= w * l[a] * f;
      r_b -= w * 256.0 * l[0] * l[1] * l[2] * l[3] * f;
    }
  }

  // Pressure coupling, exact: G_l[(a,j),k] = −(V/4) ∂jλa, G_b[j,k] = (∫b) ∂jλk.
  Eigen::Matrix<double, 12, 4> g_l;
  for (int a = 0; a < 4; ++a)
    g_l.block<3, 4>(3 * a, 0).colwise() = -0.25 * volume * g.grad.row(a).transpose();
  const Eigen::Matrix<double, 3, 4> g_b = kBubbleIntegral * volume * g.grad.transpose();
  Eigen::Matrix4d c = Eigen::Matrix4d::Zero(); // ∫ N_k N_l / κ = V (1 + δkl) / (20 κ)
  const double kappa = law.bulk_modulus();
  if (std::isfinite(kappa)) c = (volume / (20.0 * kappa)) * (Eigen::Matrix4d::Ones() + Eigen::Matrix4d::Identity());

  const Eigen::Vector4d p = Eigen::Map<const Eigen::Vector4d>(in.nodal_pressure.data());
  const Eigen::Matrix<double, 12, 1> r_l = g.linear_strain.transpose() * stress_sum + g_l * p + r_l_force;
  r_b.noalias() += g_b * p;
  // An elastic body's pressure equation is div v + (p − p_n)/κ = 0 (κ = bulk
  // modulus × Δt), p_n the pressure it carries in (zero for other laws).
  const double carried_pressure = -in.state.elastic_stress.head<3>().sum() / 3.0;
  const Eigen::Vector4d r_p = g_l.transpose() * v_lin + g_b.transpose() * in.bubble_velocity -
                              c * (p - Eigen::Vector4d::Constant(carried_pressure));

  // Condense the bubble: Δb = −K_bb⁻¹ (r_b + K_bl Δl + G_b Δp).
  const Eigen::Matrix<double, 12, 3> k_lb = g.linear_strain.transpose().lazyProduct(tangent_bubble_sum);
  Eigen::Matrix<double, 3, 16> coupling; // [K_bl  G_b] in condensed ordering
  for (int a = 0; a < 4; ++a) {
    coupling.block<3, 3>(0, 4 * a) = k_lb.block<3, 3>(3 * a, 0).transpose();
    coupling.col(4 * a + 3) = g_b.col(a);
  }
  const Eigen::LLT<Eigen::Matrix3d> k_bb_factor(k_bb);
  out.bubble_residual_solved = k_bb_factor.solve(r_b);
  out.bubble_residual_sq = r_b.squaredNorm();
  out.viscosity = tangent_sum.trace() / (10.0 * volume);
  out.bubble_gain = k_bb_factor.solve(coupling);

  for (int a = 0; a < 4; ++a) {
    out.residual.segment<3>(4 * a) = r_l.segment<3>(3 * a);
    out.residual(4 * a + 3) = r_p(a);
  }
  out.residual.noalias() -= coupling.transpose() * out.bubble_residual_solved;

  if (with_tangent) {
    // Small fixed-size products: coefficient-wise (lazy), not Eigen's blocked GEMM.
    const Eigen::Matrix<double, 6, 12> d_l = tangent_sum.lazyProduct(g.linear_strain);
    const Eigen::Matrix<double, 12, 12> k_ll = g.linear_strain.transpose().lazyProduct(d_l);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        out.tangent.block<3, 3>(4 * a, 4 * b) = k_ll.block<3, 3>(3 * a, 3 * b);
        out.tangent.block<3, 1>(4 * a, 4 * b + 3) = g_l.block<3, 1>(3 * a, b);
        out.tangent.block<1, 3>(4 * a + 3, 4 * b) = g_l.block<3, 1>(3 * b, a).transpose();
        out.tangent(4 * a + 3, 4 * b + 3) = -c(a, b);
      }
    out.tangent.noalias() -= coupling.transpose().lazyProduct(out.bubble_gain);
  }
  return true;
}

MiniElementFields mini_element_fields(const MiniElementInput& in, const material::Material& law) {
  Geometry g;
  MiniElementFields f{};
  if (!geometry(in, g)) return f;
  f.strain_rate = g.linear_strain * stack(in.nodal_velocity);
  Vec6 s;
  Mat6 tangent;
  law.deviatoric_stress(f.strain_rate, in.state, s, tangent);
  const double p = 0.25 * (in.nodal_pressure[0] + in.nodal_pressure[1] + in.nodal_pressure[2] + in.nodal_pressure[3]);
  f.stress = s;
  f.stress.head<3>().array() -= p;
  f.equivalent_strain_rate = material::equivalent_strain_rate(f.strain_rate);
  return f;
}

} // namespace anvil::fem

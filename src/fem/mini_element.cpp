#include "anvil/fem/mini_element.h"

#include "anvil/fem/tet_quadrature.h"
#include "anvil/mesh/tet_geometry.h"

#include <Eigen/Dense>

// Strain operators are not formed as 6×3 matrices: with B(g)u = sym(u ⊗ g)
// (Mandel) and the J2 tangent D = 2η P + β e⊗e (material::J2Tangent), every
// product the element needs has a closed form in the gradients:
//   B(g)ᵀ s          = S g                        (S the tensor of s)
//   B(g)ᵀ P B(h)     = ½(g·h) I + ½ h gᵀ − ⅓ g hᵀ
//   B(g)ᵀ (e⊗e) B(h) = (E g)(E h)ᵀ
// and B is linear in g, so Σ_q w 2η P B(∇b_q) = P B(Σ_q w 2η ∇b_q).

namespace anvil::fem {
namespace {

using material::kSqrt2;
using material::Vec6;
using Mat3 = Eigen::Matrix3d;
using Mat6 = material::Mat6;

constexpr double kInvSqrt2 = 1.0 / kSqrt2;

/// S g for the symmetric tensor S of the Mandel vector `s`: B(g)ᵀ s.
Vec3 tensor_times(const Vec6& s, const Vec3& g) {
  return {s[0] * g[0] + kInvSqrt2 * (s[3] * g[1] + s[5] * g[2]), s[1] * g[1] + kInvSqrt2 * (s[3] * g[0] + s[4] * g[2]),
          s[2] * g[2] + kInvSqrt2 * (s[4] * g[1] + s[5] * g[0])};
}

/// Mandel strain of the velocity u times a field of gradient g: B(g) u.
Vec6 strain_of(const Vec3& g, const Vec3& u) {
  Vec6 e;
  e << u[0] * g[0], u[1] * g[1], u[2] * g[2], kInvSqrt2 * (u[0] * g[1] + u[1] * g[0]),
      kInvSqrt2 * (u[1] * g[2] + u[2] * g[1]), kInvSqrt2 * (u[2] * g[0] + u[0] * g[2]);
  return e;
}

/// B(g)ᵀ P B(h): the deviatoric stiffness per unit 2η between gradients g and h.
Mat3 deviatoric_coupling(const Vec3& g, const Vec3& h) {
  Mat3 k = 0.5 * h * g.transpose() - (1.0 / 3.0) * g * h.transpose();
  k.diagonal().array() += 0.5 * g.dot(h);
  return k;
}

/// B(g)ᵀ M for the columns of M (Mandel vectors): column j is tensor_times(M.col(j), g).
template <int Cols>
Eigen::Matrix<double, 3, Cols> strain_transpose_times(const Vec3& g, const Eigen::Matrix<double, 6, Cols>& m) {
  Eigen::Matrix<double, 3, Cols> out;
  for (int j = 0; j < Cols; ++j)
    out.col(j) = tensor_times(m.col(j), g);
  return out;
}

/// M B(h) for a symmetric 6×6 M: column j is M times the strain of unit vector j and gradient h.
Eigen::Matrix<double, 6, 3> times_strain(const Mat6& m, const Vec3& h) {
  Eigen::Matrix<double, 6, 3> out;
  out.col(0) = h[0] * m.col(0) + kInvSqrt2 * (h[1] * m.col(3) + h[2] * m.col(5));
  out.col(1) = h[1] * m.col(1) + kInvSqrt2 * (h[0] * m.col(3) + h[2] * m.col(4));
  out.col(2) = h[2] * m.col(2) + kInvSqrt2 * (h[1] * m.col(4) + h[0] * m.col(5));
  return out;
}

// ∫ λ1λ2λ3λ4 dV = V/840 (∫ Πλ^a = 6V Πa!/(Σa+3)!), so ∫ b = 256 V/840.
constexpr double kBubbleIntegral = 256.0 / 840.0;

struct Geometry {
  std::array<Vec3, 4> grad; ///< ∇λ_a (1/mm)
  Eigen::Matrix<double, 4, 3> grad_rows;
  double volume;
};

bool geometry(const MiniElementInput& in, Geometry& g) {
  const auto& x = in.vertices;
  const mesh::P1Gradients p1 = mesh::p1_gradients(x[0], x[1], x[2], x[3]);
  if (!(p1.volume > 0.0)) return false; // inverted or flat: the gradients are meaningless
  g.grad_rows = p1.grad;
  for (int a = 0; a < 4; ++a)
    g.grad[a] = p1.grad.row(a).transpose();
  g.volume = p1.volume;
  return true;
}

Vec6 linear_strain(const Geometry& g, const std::array<Vec3, 4>& nodal_velocity) {
  Vec6 e = Vec6::Zero();
  for (int a = 0; a < 4; ++a)
    e += strain_of(g.grad[a], nodal_velocity[a]);
  return e;
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
  const Vec6 strain_l = linear_strain(g, in.nodal_velocity);
  const Vec6 strain_l_last = in.dual ? linear_strain(g, in.dual->nodal_velocity) : Vec6::Zero();

  // Quadrature of the viscous (or elastic) term (docs/design.md §2). Per point only
  // sums of scalars, 3-vectors and the rank-one parts are accumulated; the
  // element matrices are formed once from them.
  Vec6 stress_sum = Vec6::Zero();                                                    // Σ w s
  Vec3 r_b = Vec3::Zero();                                                           // Σ w B_bᵀ s
  double two_eta_sum = 0.0;                                                          // Σ w 2η
  Vec3 two_eta_bubble = Vec3::Zero();                                                // Σ w 2η ∇b
  Mat6 rank_one_sum = Mat6::Zero();                                                  // Σ w β e⊗e (with the tangent)
  Eigen::Matrix<double, 6, 3> rank_one_bubble = Eigen::Matrix<double, 6, 3>::Zero(); // Σ w β e (E∇b)ᵀ
  double rank_one_trace = 0.0;                                                       // Σ w β |e|²
  Mat3 k_bb = Mat3::Zero();
  Eigen::Matrix<double, 12, 1> r_l_force = Eigen::Matrix<double, 12, 1>::Zero();
  Vec6 stress;
  material::J2Tangent tangent;
  const std::span<const TetQuadraturePoint> rule = tet_quadrature(in.quadrature_degree);
  for (std::size_t point = 0; point < rule.size(); ++point) {
    const TetQuadraturePoint& q = rule[point];
    const auto& l = q.barycentric;
    const Vec3 grad_b = bubble_gradient(l, g.grad_rows);
    const Vec6 strain = strain_l + strain_of(grad_b, in.bubble_velocity);
    law.deviatoric_stress(strain, in.state, stress, tangent);
    const double w = q.weight * volume;
    stress_sum += w * stress;
    r_b += w * tensor_times(stress, grad_b);
    const double w_two_eta = w * tangent.two_eta;
    two_eta_sum += w_two_eta;
    two_eta_bubble += w_two_eta * grad_b;
    k_bb.noalias() += (w_two_eta / 6.0) * grad_b * grad_b.transpose();
    k_bb.diagonal().array() += 0.5 * w_two_eta * grad_b.squaredNorm();
    const Vec6 e = material::deviator(strain);
    Vec6 e_dual = e; // n̂ r, in place of one e of the rank-one term
    if (in.dual) {
      const Vec6 e_last = material::deviator(strain_l_last + strain_of(grad_b, in.dual->bubble_velocity));
      const Vec6 n_dual = dual_direction(e, e_last, in.dual->last ? in.dual->last + point : nullptr, in.dual->step);
      in.dual->trial[point] = n_dual.cast<float>();
      e_dual = std::sqrt(2.0 / 3.0 * e.squaredNorm()) * n_dual;
    }
    if (tangent.beta != 0.0) {
      const Vec3 e_grad_b = tensor_times(e, grad_b); // B_bᵀ e
      const Vec3 d_grad_b = tensor_times(e_dual, grad_b);
      // β ∝ (m − 1): a floor m_t > m scales the term by (1 − m_t)/(1 − m). The
      // bubble's part too (without it, closed_die_flash's flash stage took 16
      // Newton iterations per increment instead of 9); its condensation then
      // changes the condensed residual by −K_lb K_bb⁻¹ r_b, nothing once the
      // bubble is in equilibrium.
      const double m = tangent.sensitivity, m_t = in.tangent_sensitivity_floor;
      const double w_beta = w * tangent.beta * (m < m_t ? (1.0 - m_t) / (1.0 - m) : 1.0);
      // The rank-one term β sym(ê ⊗ e), ê = e without the dual.
      const double half = 0.5 * w_beta;
      rank_one_bubble.noalias() += (half * e_dual) * e_grad_b.transpose() + (half * e) * d_grad_b.transpose();
      k_bb.noalias() += (half * d_grad_b) * e_grad_b.transpose() + (half * e_grad_b) * d_grad_b.transpose();
      rank_one_trace += w_beta * e_dual.dot(e);
      if (with_tangent) rank_one_sum.noalias() += (half * e_dual) * e.transpose() + (half * e) * e_dual.transpose();
    }
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
    g_l.block<3, 4>(3 * a, 0).colwise() = -0.25 * volume * g.grad[a];
  const Eigen::Matrix<double, 3, 4> g_b = kBubbleIntegral * volume * g.grad_rows.transpose();
  Eigen::Matrix4d c = Eigen::Matrix4d::Zero(); // ∫ N_k N_l / κ = V (1 + δkl) / (20 κ)
  const double kappa = law.bulk_modulus();
  if (std::isfinite(kappa)) c = (volume / (20.0 * kappa)) * (Eigen::Matrix4d::Ones() + Eigen::Matrix4d::Identity());

  const Eigen::Vector4d p = Eigen::Map<const Eigen::Vector4d>(in.nodal_pressure.data());
  Eigen::Matrix<double, 12, 1> r_l = g_l * p + r_l_force;
  for (int a = 0; a < 4; ++a)
    r_l.segment<3>(3 * a) += tensor_times(stress_sum, g.grad[a]);
  r_b.noalias() += g_b * p;
  // An elastic body's pressure equation is div v + (p − p_n)/κ = 0 (κ = bulk
  // modulus × Δt), p_n the pressure it carries in (zero for other laws).
  const double carried_pressure = -in.state.elastic_stress.head<3>().sum() / 3.0;
  Eigen::Vector4d r_p = g_b.transpose() * in.bubble_velocity - c * (p - Eigen::Vector4d::Constant(carried_pressure));
  for (int a = 0; a < 4; ++a)
    r_p += g_l.block<3, 4>(3 * a, 0).transpose() * in.nodal_velocity[a];

  // Condense the bubble: Δb = −K_bb⁻¹ (r_b + K_bl Δl + G_b Δp), with
  // K_lb (block a) = B_aᵀ Σ w D B_b = B_aᵀ P B(Σ w 2η ∇b) + B_aᵀ Σ w β e (E∇b)ᵀ.
  Eigen::Matrix<double, 3, 16> coupling; // [K_bl  G_b] in condensed ordering
  for (int a = 0; a < 4; ++a) {
    const Mat3 k_la =
        deviatoric_coupling(g.grad[a], two_eta_bubble) + strain_transpose_times<3>(g.grad[a], rank_one_bubble);
    coupling.block<3, 3>(0, 4 * a) = k_la.transpose();
    coupling.col(4 * a + 3) = g_b.col(a);
  }
  const Mat3 k_bb_inverse = k_bb.inverse(); // SPD 3×3: the closed form is exact enough and cheap
  out.bubble_residual_solved = k_bb_inverse * r_b;
  out.bubble_residual_sq = r_b.squaredNorm();
  // Mean tangent viscosity tr(∫D)/(10 V), tr D = 5·2η + β|e|².
  out.viscosity = (5.0 * two_eta_sum + rank_one_trace) / (10.0 * volume);
  out.bubble_gain.noalias() = k_bb_inverse * coupling;

  for (int a = 0; a < 4; ++a) {
    out.residual.segment<3>(4 * a) = r_l.segment<3>(3 * a);
    out.residual(4 * a + 3) = r_p(a);
  }
  out.residual.noalias() -= coupling.transpose() * out.bubble_residual_solved;

  if (with_tangent) {
    // K_ll (a, b) = 2η_sum B_aᵀ P B_b + B_aᵀ (Σ w β e⊗e) B_b, symmetric: upper blocks, mirrored.
    std::array<Eigen::Matrix<double, 6, 3>, 4> rank_one_strain;
    if (rank_one_trace != 0.0)
      for (int b = 0; b < 4; ++b)
        rank_one_strain[b] = times_strain(rank_one_sum, g.grad[b]);
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b) {
        Mat3 k = two_eta_sum * deviatoric_coupling(g.grad[a], g.grad[b]);
        if (rank_one_trace != 0.0) k += strain_transpose_times<3>(g.grad[a], rank_one_strain[b]);
        out.tangent.block<3, 3>(4 * a, 4 * b) = k;
        out.tangent.block<3, 3>(4 * b, 4 * a) = k.transpose();
      }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
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
  f.strain_rate = linear_strain(g, in.nodal_velocity);
  Vec6 s;
  material::J2Tangent tangent;
  law.deviatoric_stress(f.strain_rate, in.state, s, tangent);
  const double p = 0.25 * (in.nodal_pressure[0] + in.nodal_pressure[1] + in.nodal_pressure[2] + in.nodal_pressure[3]);
  f.stress = s;
  f.stress.head<3>().array() -= p;
  f.equivalent_strain_rate = material::equivalent_strain_rate(f.strain_rate);
  return f;
}

} // namespace anvil::fem

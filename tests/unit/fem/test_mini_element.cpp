#include "test_common.h"

#include "anvil/fem/mini_element.h"
#include "anvil/fem/tet_quadrature.h"

#include <Eigen/Dense>

using namespace anvil;

namespace {

fem::MiniElementInput distorted_element() {
  fem::MiniElementInput in;
  in.vertices = {mesh::Point(0.1, -0.05, 0.0), mesh::Point(1.2, 0.1, 0.05), mesh::Point(0.2, 0.9, -0.1),
                 mesh::Point(0.05, 0.15, 1.1)};
  in.nodal_velocity = {fem::Vec3(0.3, -0.2, 0.1), fem::Vec3(-0.1, 0.4, 0.2), fem::Vec3(0.5, 0.1, -0.3),
                       fem::Vec3(-0.2, -0.3, 0.6)};
  in.nodal_pressure = {0.2, -0.1, 0.3, 0.05};
  return in;
}

/// Puts the bubble in equilibrium (r_b = 0) by a local Newton: there the
/// condensed tangent is the exact derivative of the condensed residual.
void balance_bubble(fem::MiniElementInput& in, const material::Material& law) {
  fem::MiniElementSystem s;
  for (int it = 0; it < 50; ++it) {
    REQUIRE(fem::mini_element(in, law, false, {}, s));
    in.bubble_velocity -= s.bubble_residual_solved;
    if (s.bubble_residual_sq < 1e-28) break;
  }
}

/// Condensed residual with the bubble in equilibrium: the function whose
/// exact derivative is the condensed tangent.
fem::Vec16 condensed_residual(fem::MiniElementInput in, const material::Material& law) {
  balance_bubble(in, law);
  fem::MiniElementSystem s;
  REQUIRE(fem::mini_element(in, law, false, {}, s));
  return s.residual;
}

void set_dof(fem::MiniElementInput& in, int i, double value) {
  if (i % 4 == 3)
    in.nodal_pressure[i / 4] = value;
  else
    in.nodal_velocity[i / 4][i % 4] = value;
}
double get_dof(const fem::MiniElementInput& in, int i) {
  return i % 4 == 3 ? in.nodal_pressure[i / 4] : in.nodal_velocity[i / 4][i % 4];
}

} // namespace

TEST_CASE("condensed MINI tangent equals finite differences of the residual", "[unit]") {
  // m = 1, 0.15, 0.02; regularisation small against the element's strain rates (~1/s).
  const double m = GENERATE(1.0, 0.15, 0.02);
  const material::NortonHoff law(10.0, m, 1e-3);
  fem::MiniElementInput in = distorted_element();
  balance_bubble(in, law);
  fem::MiniElementSystem s;
  REQUIRE(fem::mini_element(in, law, true, {}, s));
  const fem::Mat16 tangent = s.tangent;
  CHECK((tangent - tangent.transpose()).norm() <= 1e-12 * tangent.norm());

  fem::Mat16 fd;
  for (int j = 0; j < 16; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(get_dof(in, j)));
    fem::MiniElementInput plus = in, minus = in;
    set_dof(plus, j, get_dof(in, j) + h);
    set_dof(minus, j, get_dof(in, j) - h);
    fd.col(j) = (condensed_residual(plus, law) - condensed_residual(minus, law)) / (2 * h);
  }
  INFO("m = " << m << ", max |tangent - fd| = " << (tangent - fd).cwiseAbs().maxCoeff()
              << ", max |tangent| = " << tangent.cwiseAbs().maxCoeff());
  // Central differences: error O(h²·|R'''|) + round-off ~1e-16·|R|/h: 1e-6 relative is the floor.
  CHECK((tangent - fd).cwiseAbs().maxCoeff() <= 1e-6 * tangent.cwiseAbs().maxCoeff());
}

TEST_CASE("rigid motion gives zero residual and the condensed tangent is symmetric", "[unit]") {
  const material::NortonHoff law(5.0, 1.0, 0.0);
  fem::MiniElementInput in = distorted_element();
  const fem::Vec3 translation(0.3, -0.7, 0.2), rotation(0.1, 0.2, -0.4);
  for (int a = 0; a < 4; ++a)
    in.nodal_velocity[a] = translation + rotation.cross(in.vertices[a]);
  in.nodal_pressure = {0, 0, 0, 0};
  fem::MiniElementSystem s;
  REQUIRE(fem::mini_element(in, law, true, {}, s));
  CHECK(s.residual.norm() <= 1e-12);
  CHECK((s.tangent - s.tangent.transpose()).norm() <= 1e-12 * s.tangent.norm());
}

TEST_CASE("an inverted element is reported, not computed", "[unit]") {
  const material::NortonHoff law(5.0, 1.0, 0.0);
  fem::MiniElementInput in = distorted_element();
  std::swap(in.vertices[0], in.vertices[1]);
  fem::MiniElementSystem s;
  CHECK_FALSE(fem::mini_element(in, law, true, {}, s));
}

TEST_CASE("Newton's far-phase tangent: the residual is unchanged, the tangent stiffer along the rate, and no change "
          "for a law at or above the floor",
          "[unit]") {
  const material::NortonHoff power_law(10.0, 0.15, 1e-3);
  fem::MiniElementInput in = distorted_element();
  // The bubble in equilibrium (r_b = 0): there the condensed residual does
  // not depend on the bubble's tangent, which the floor changes too.
  balance_bubble(in, power_law);
  auto system = [&](const material::Material& law, double floor) {
    in.tangent_sensitivity_floor = floor;
    fem::MiniElementSystem s;
    REQUIRE(fem::mini_element(in, law, true, {}, s));
    return s;
  };
  const fem::MiniElementSystem consistent = system(power_law, 0.0), far = system(power_law, 0.5);
  // The same problem: the floor only shapes the direction.
  CHECK((far.residual - consistent.residual).norm() <= 1e-12 * consistent.residual.norm());
  CHECK((far.tangent - far.tangent.transpose()).norm() <= 1e-12 * far.tangent.norm());
  // The rank-one term 2η(m − 1)… is negative: a smaller |m − 1| can only add
  // stiffness. On the velocity rows (the pressure ones are a saddle point),
  // the difference is positive semi-definite and not zero.
  Eigen::Matrix<double, 12, 12> added;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      added(i, j) = far.tangent(4 * (i / 3) + i % 3, 4 * (j / 3) + j % 3) -
                    consistent.tangent(4 * (i / 3) + i % 3, 4 * (j / 3) + j % 3);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eigen(0.5 * (added + added.transpose()));
  CHECK(eigen.eigenvalues().minCoeff() >= -1e-12 * far.tangent.norm());
  CHECK(eigen.eigenvalues().maxCoeff() > 1e-3 * far.tangent.norm());
  // A law at or above the floor keeps its consistent tangent.
  const material::NortonHoff newtonian(10.0, 1.0, 0.0), mild(10.0, 0.6, 1e-3);
  CHECK(system(newtonian, 0.5).tangent == system(newtonian, 0.0).tangent);
  CHECK(system(mild, 0.5).tangent == system(mild, 0.0).tangent);
}

TEST_CASE("Newton's own strain-rate direction: the residual unchanged, the consistent tangent where it equals the "
          "rate's, a stiffer one where the rate turned round, never an indefinite one",
          "[unit]") {
  const material::NortonHoff law(10.0, 0.15, 1e-3);
  fem::MiniElementInput in = distorted_element();
  balance_bubble(in, law); // the condensed residual then does not depend on the bubble's tangent
  const std::size_t points = fem::tet_quadrature(in.quadrature_degree).size();
  std::vector<fem::DualDirection> trial(points);
  auto system = [&](const fem::ElementDual* dual) {
    in.dual = dual;
    fem::MiniElementSystem s;
    REQUIRE(fem::mini_element(in, law, true, {}, s));
    in.dual = nullptr;
    return s;
  };
  auto velocity_block = [](const fem::Mat16& k) {
    Eigen::Matrix<double, 12, 12> v;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        v(i, j) = k(4 * (i / 3) + i % 3, 4 * (j / 3) + j % 3);
    return v;
  };
  const fem::MiniElementSystem consistent = system(nullptr);
  const double scale = consistent.tangent.norm();

  // Newton's first iterate: n̂ = n, the consistent tangent.
  fem::ElementDual at_iterate{in.nodal_velocity, in.bubble_velocity, 0.0, nullptr, trial.data()};
  const fem::MiniElementSystem same = system(&at_iterate);
  CHECK((same.residual - consistent.residual).norm() <= 1e-12 * consistent.residual.norm());
  CHECK((same.tangent - consistent.tangent).norm() <= 1e-12 * scale);

  // From a last iterate that moved the other way, a full step: n̂ keeps the
  // last iterate's direction, −n, so the rank-one term β e⊗e (β < 0) changes
  // sign: stiffer along the rate, where Newton would overshoot.
  fem::ElementDual reversed{{}, -in.bubble_velocity, 1.0, nullptr, trial.data()};
  for (int a = 0; a < 4; ++a)
    reversed.nodal_velocity[a] = -in.nodal_velocity[a];
  const fem::MiniElementSystem turned = system(&reversed);
  CHECK((turned.residual - consistent.residual).norm() <= 1e-12 * consistent.residual.norm());
  CHECK((turned.tangent - turned.tangent.transpose()).norm() <= 1e-12 * scale);
  const Eigen::Matrix<double, 12, 12> added = velocity_block(turned.tangent) - velocity_block(consistent.tangent);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> stiffer(0.5 * (added + added.transpose()));
  CHECK(stiffer.eigenvalues().minCoeff() >= -1e-12 * scale);
  CHECK(stiffer.eigenvalues().maxCoeff() > 1e-3 * scale);

  // From any last iterate and step, n̂ is scaled back to ⅔ n̂:n̂ ≤ 1 and the
  // velocity block stays positive semi-definite (zero on the six rigid
  // motions and the change of volume, the pressure's part).
  fem::ElementDual elsewhere{
      {fem::Vec3(-0.4, 0.1, 0.3), fem::Vec3(0.2, -0.5, 0.1), fem::Vec3(0.1, 0.3, 0.4), fem::Vec3(0.6, -0.1, -0.2)},
      fem::Vec3(0.05, -0.02, 0.01),
      0.5,
      nullptr,
      trial.data()};
  const Eigen::Matrix<double, 12, 12> k = velocity_block(system(&elsewhere).tangent);
  for (const fem::DualDirection& n : trial)
    CHECK(2.0 / 3.0 * n.cast<double>().squaredNorm() <= 1.0 + 1e-6);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> definite(0.5 * (k + k.transpose()));
  CHECK(definite.eigenvalues().minCoeff() >= -1e-12 * scale);
  CHECK(definite.eigenvalues()[7] > 1e-3 * scale);
}

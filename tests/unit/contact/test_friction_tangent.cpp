#include "test_common.h"

#include "anvil/contact/Friction.h"
#include "anvil/contact/FrictionDual.h"

using namespace anvil;

TEST_CASE("Newton's far-phase friction tangent: the same stress, stiffer along the sliding only", "[unit]") {
  contact::FrictionLaw tresca;
  tresca.kind = contact::FrictionKind::tresca;
  tresca.tresca_factor = 0.3;
  const Eigen::Vector3d w(3.0, -4.0, 0.0), across(4.0, 3.0, 0.0); // |w| = 5 mm/s
  contact::FrictionInput in{w, 50.0, 100.0, 0.0, 0.1, 0.0};
  const contact::FrictionStress consistent = contact::friction_stress(tresca, in);
  in.tangent_sensitivity_floor = 0.5;
  const contact::FrictionStress far = contact::friction_stress(tresca, in);
  CHECK(far.stress == consistent.stress);
  // τ = c w/s, s = sqrt(|w|² + w₀²): along w the consistent tangent is
  // c w₀²/s³ (nearly nothing at |w| = 50 w₀), the far one c/s (1 − 0.5 |w|²/s²);
  // across w both are c/s.
  const double c = 0.3 * 100.0 / std::sqrt(3.0), s = std::sqrt(25.0 + 0.01);
  CHECK((consistent.d_sliding * w - c * 0.01 / (s * s * s) * w).norm() <= 1e-12 * c);
  CHECK((far.d_sliding * w - c / s * (1.0 - 0.5 * 25.0 / (s * s)) * w).norm() <= 1e-12 * c);
  CHECK((far.d_sliding * across - consistent.d_sliding * across).norm() <= 1e-12 * c);
  // A Norton law with q above the floor keeps its tangent.
  contact::FrictionLaw norton;
  norton.kind = contact::FrictionKind::norton;
  norton.coefficient = 0.2;
  norton.exponent = 0.7;
  in.consistency = 80.0;
  in.tangent_sensitivity_floor = 0.0;
  const Eigen::Matrix3d norton_consistent = contact::friction_stress(norton, in).d_sliding;
  in.tangent_sensitivity_floor = 0.5;
  CHECK(contact::friction_stress(norton, in).d_sliding == norton_consistent);
}

TEST_CASE("Newton's own sliding direction: the same stress, the consistent tangent where it equals w/s, a stiffer one "
          "where the sliding turned round",
          "[unit]") {
  contact::FrictionLaw tresca;
  tresca.kind = contact::FrictionKind::tresca;
  tresca.tresca_factor = 0.3;
  const double w0 = 0.1, c = 0.3 * 100.0 / std::sqrt(3.0);
  const Eigen::Vector3d w(3.0, -4.0, 0.0), across(4.0, 3.0, 0.0); // |w| = 5 mm/s
  const double s = std::sqrt(25.0 + w0 * w0);
  contact::FrictionDual dual;
  dual.start(
      1, [&](std::size_t) { return w; }, w0);
  // At Newton's first iterate λ = w/s: the consistent tangent.
  const Eigen::Vector3d at_start = *dual.direction(0, w);
  CHECK((at_start - w / s).norm() <= 1e-15);
  contact::FrictionInput in{w, 50.0, 100.0, 0.0, w0, 0.0};
  const contact::FrictionStress consistent = contact::friction_stress(tresca, in);
  in.direction = at_start;
  CHECK((contact::friction_stress(tresca, in).d_sliding - consistent.d_sliding).norm() <= 1e-12 * c);

  // A full step that turns the sliding round: λ keeps the last direction,
  // λ = a w with a = (1 − 2 w₀²/s²)/s (the update of the header), so along w
  // the tangent is c/s (1 + a |w|²/s), nearly 2c/s, not c w₀²/s³; the stress is τ(−w).
  dual.set_step(1.0);
  const Eigen::Vector3d turned = *dual.direction(0, -w);
  const double a = (1.0 - 2.0 * w0 * w0 / (s * s)) / s;
  CHECK((turned - a * w).norm() <= 1e-15);
  contact::FrictionInput back{-w, 50.0, 100.0, 0.0, w0, 0.0};
  const contact::FrictionStress plain = contact::friction_stress(tresca, back);
  back.direction = turned;
  const contact::FrictionStress kept = contact::friction_stress(tresca, back);
  CHECK(kept.stress == plain.stress);
  CHECK((kept.d_sliding * w - c / s * (1.0 + a * 25.0 / s) * w).norm() <= 1e-12 * c);
  CHECK((kept.d_sliding * across - plain.d_sliding * across).norm() <= 1e-12 * c);

  // Accepted, the trial's λ is the new iterate's; any other trial's λ is
  // scaled back to |λ| ≤ 1.
  dual.accept([&](std::size_t) { return Eigen::Vector3d(-w); });
  dual.set_step(0.0);
  CHECK((*dual.direction(0, -w) - turned).norm() <= 1e-15);
  dual.set_step(0.5);
  CHECK(dual.direction(0, Eigen::Vector3d(-40.0, 7.0, 0.0))->norm() <= 1.0 + 1e-15);
}

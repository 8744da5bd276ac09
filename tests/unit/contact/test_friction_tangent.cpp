#include "test_common.h"

#include "anvil/contact/Friction.h"

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

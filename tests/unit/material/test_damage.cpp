// The damage criteria's weights against their values on stress states where
// they are known in closed form.
#include "test_common.h"

#include "anvil/material/damage.h"

using namespace anvil;
using material::DamageCriterion;

namespace {

double weight(DamageCriterion c, const material::Vec6& stress, double a = 0.5) {
  return material::damage_weight({c, a}, stress);
}

material::Vec6 diagonal(double x, double y, double z) {
  material::Vec6 s = material::Vec6::Zero();
  s << x, y, z, 0, 0, 0;
  return s;
}

} // namespace

TEST_CASE("damage weights in uniaxial tension and compression", "[unit]") {
  // Uniaxial tension σ: σ1 = σ, σm = σ/3, σ̄ = σ.
  const material::Vec6 tension = diagonal(0, 0, 120.0);
  CHECK(weight(DamageCriterion::cockcroft_latham, tension) == Approx(1.0));
  CHECK(weight(DamageCriterion::ayada, tension) == Approx(1.0 / 3.0));
  CHECK(weight(DamageCriterion::oyane, tension, 0.5) == Approx(1.0 + (1.0 / 3.0) / 0.5));
  CHECK(weight(DamageCriterion::brozzo, tension) == Approx(2.0 * 120.0 / (3.0 * (120.0 - 40.0))));
  // Uniaxial compression −σ: σ1 = 0, σm = −σ/3.
  const material::Vec6 compression = diagonal(0, 0, -120.0);
  CHECK(weight(DamageCriterion::cockcroft_latham, compression) == Approx(0.0).margin(1e-12));
  CHECK(weight(DamageCriterion::ayada, compression) == Approx(-1.0 / 3.0));
  CHECK(weight(DamageCriterion::oyane, compression, 0.5) == Approx(1.0 - (1.0 / 3.0) / 0.5));
  CHECK(weight(DamageCriterion::brozzo, compression) == Approx(0.0).margin(1e-12));
}

TEST_CASE("damage weights do not depend on the axes: pure shear turned by 45 degrees", "[unit]") {
  // Pure shear τ on xy is tension τ and compression −τ along the diagonals:
  // σ1 = τ, σm = 0, σ̄ = √3 τ.
  const double tau = 50.0;
  material::Vec6 shear = material::Vec6::Zero();
  shear[3] = material::kSqrt2 * tau;
  const material::Vec6 turned = diagonal(tau, -tau, 0);
  for (const auto& [name, c] : material::damage_criterion_names()) {
    INFO(name);
    CHECK(weight(c, shear) == Approx(weight(c, turned)).margin(1e-12));
  }
  CHECK(weight(DamageCriterion::cockcroft_latham, shear) == Approx(1.0 / std::sqrt(3.0)));
  CHECK(weight(DamageCriterion::brozzo, shear) == Approx(2.0 / 3.0));
  CHECK(weight(DamageCriterion::ayada, shear) == Approx(0.0).margin(1e-12));
}

TEST_CASE("a hydrostatic stress weighs nothing, and names round-trip", "[unit]") {
  for (const auto& [name, c] : material::damage_criterion_names()) {
    CHECK(weight(c, diagonal(-80.0, -80.0, -80.0)) == 0.0);
    CHECK(material::damage_criterion(name) == c);
    CHECK(material::to_string(c) == name);
  }
  CHECK_FALSE(material::damage_criterion("rice_tracey"));
}

// The flow-stress cards against the laws they were fitted to: reads the card
// through the case reader and evaluates σ̄ through the Material interface.
#include "test_common.h"

#include "anvil/scene/Case.h"
#include "anvil/scene/MaterialCard.h"

#include <cmath>

using namespace anvil;

TEST_CASE("the AA6061 Hansel-Spittel card follows Sheppard & Jackson's Sellars-Tegart law", "[unit]") {
  const scene::MaterialCard card = scene::read_material(source_path("materials/aluminium_6061_hansel_spittel.yaml"));
  // Sheppard & Jackson (1997), AA6061: ε̄̇ exp(Q/RT) = A sinh(α σ̄)^n.
  constexpr double alpha = 0.045, n = 3.55, Q = 145e3, ln_A = 19.3, R = 8.314;
  auto sellars_tegart = [&](double temperature, double rate) {
    const double ln_Z = std::log(rate) + Q / (R * (temperature + 273.15));
    return std::asinh(std::exp((ln_Z - ln_A) / n)) / alpha;
  };
  REQUIRE(card.temperature == 450.0);
  double worst = 0.0;
  for (double temperature = 400.0; temperature <= 500.0; temperature += 25.0)
    for (double rate : {1.0, 3.0, 10.0}) {
      const double expected = sellars_tegart(temperature, rate);
      const double stress = card.law->flow_stress(rate, {0.5, temperature});
      worst = std::max(worst, std::abs(stress - expected) / expected);
    }
  INFO("worst deviation " << worst);
  // 1.1 %: the fit's own residual on its grid is 1.0 % (card header); the
  // regularisation rate (1e-4 1/s) changes σ̄ by far less at 1 1/s.
  CHECK(worst < 0.011);
  CHECK_FALSE(card.law->hardens());
}

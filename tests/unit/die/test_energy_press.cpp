// die::EnergyPress: the ram's speed from the energy left.
#include "anvil/die/EnergyPress.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using anvil::die::EnergyPress;

TEST_CASE("a hammer's impact speed is sqrt(2 eta E / M)", "[energy_press]") {
  const EnergyPress h = EnergyPress::hammer(10.0, 0.8, 500.0, 1, 0.0);      // 10 kJ, 500 kg
  CHECK(h.energy() == Approx(8e6));                                         // mJ
  CHECK(h.impact_speed() == Approx(std::sqrt(2.0 * 8000.0 / 500.0) * 1e3)); // mm/s from J and kg
}

TEST_CASE("a screw press's flywheel is a mass I (2 pi / p)^2 on the ram", "[energy_press]") {
  // 200 kg m² at 120 rpm, pitch 250 mm, a 3 t ram: v = ω p / 2π at impact.
  const double omega = 2.0 * std::numbers::pi * 120.0 / 60.0;
  const EnergyPress s = EnergyPress::screw_press(0.0, 120.0, 200.0, 250.0, 1.0, 3000.0, 1, 0.0);
  const double k = 2.0 * std::numbers::pi / 0.25; // rad per m
  CHECK(s.mass() == Approx((200.0 * k * k + 3000.0) * 1e-3));
  CHECK(s.energy() == Approx(0.5 * 200.0 * omega * omega * 1e3)); // J → mJ
  // Without the ram's mass the ram moves at the screw's speed.
  const EnergyPress bare = EnergyPress::screw_press(0.0, 120.0, 200.0, 250.0, 1.0, 0.0, 1, 0.0);
  CHECK(bare.impact_speed() == Approx(omega * 250.0 / (2.0 * std::numbers::pi)));
}

TEST_CASE("the mean speed is exact under a constant load", "[energy_press]") {
  // Constant F: v(s)² = v0² − 2Fs/M, time over Δs = M (v0 − v1)/F.
  const EnergyPress h = EnergyPress::hammer(1.0, 1.0, 100.0, 1, 0.0);
  const double load = 2e5, v0 = h.impact_speed(); // N, mm/s
  const double stroke = 0.5 * h.energy() / load;  // half the stopping distance
  const double v1 = std::sqrt(v0 * v0 - 2.0 * load * stroke / h.mass());
  const double time = h.mass() * (v0 - v1) / load;
  CHECK(stroke / h.mean_speed(h.energy(), load, stroke) == Approx(time).epsilon(1e-12));
  // A stroke beyond the stopping distance: the ram stops, at mean speed v0/2.
  CHECK(h.mean_speed(h.energy(), load, 3.0 * stroke) == Approx(0.5 * v0).epsilon(1e-12));
  // No load: the ram keeps its speed.
  CHECK(h.mean_speed(h.energy(), 0.0, stroke) == Approx(v0).epsilon(1e-12));
}

#include "anvil/die/EnergyPress.h"

#include "anvil/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace anvil::die {

namespace {
constexpr double kMjPerKj = 1e6; // kJ → mJ (N·mm)
constexpr double kTonnesPerKg = 1e-3;
constexpr double kTonneMm2PerKgM2 = 1e3; // kg·m² → t·mm²
} // namespace

EnergyPress::EnergyPress(std::string kind, double energy, double mass, int blows, double pause)
    : kind_(std::move(kind)), energy_(energy), mass_(mass), blows_(blows), pause_(pause) {
  ANVIL_ASSERT(energy > 0.0 && mass > 0.0 && blows >= 1 && pause >= 0.0);
}

EnergyPress EnergyPress::hammer(double blow_energy_kj, double efficiency, double ram_mass_kg, int blows, double pause) {
  return {"hammer", efficiency * blow_energy_kj * kMjPerKj, ram_mass_kg * kTonnesPerKg, blows, pause};
}

EnergyPress EnergyPress::screw_press(double flywheel_energy_kj, double flywheel_rpm, double inertia, double pitch_mm,
                                     double efficiency, double ram_mass_kg, int blows, double pause) {
  const double inertia_t_mm2 = inertia * kTonneMm2PerKgM2;
  const double turns = 2.0 * std::numbers::pi / pitch_mm; // rad per mm of ram travel
  const double mass = inertia_t_mm2 * turns * turns + ram_mass_kg * kTonnesPerKg;
  double energy = flywheel_energy_kj * kMjPerKj;
  if (!(energy > 0.0)) {
    const double omega = 2.0 * std::numbers::pi * flywheel_rpm / 60.0;
    energy = 0.5 * inertia_t_mm2 * omega * omega;
  }
  return {"screw press", efficiency * energy, mass, blows, pause};
}

double EnergyPress::impact_speed() const {
  return std::sqrt(2.0 * energy_ / mass_);
}

double EnergyPress::mean_speed(double energy_left, double load, double stroke) const {
  const double start = std::sqrt(2.0 * std::max(energy_left, 0.0) / mass_);
  const double end = std::sqrt(2.0 * std::max(energy_left - std::max(load, 0.0) * stroke, 0.0) / mass_);
  return 0.5 * (start + end);
}

std::string EnergyPress::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "%s, %.4g kJ per blow on an equivalent mass of %.4g kg: impact at %.4g m/s, %d blow%s", kind_.c_str(),
                energy_ / kMjPerKj, mass_ / kTonnesPerKg, impact_speed() * 1e-3, blows_, blows_ > 1 ? "s" : "");
  std::string out = text;
  if (blows_ > 1) {
    std::snprintf(text, sizeof text, " %g s apart", pause_);
    out += text;
  }
  return out;
}

} // namespace anvil::die

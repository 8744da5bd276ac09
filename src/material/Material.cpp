#include "anvil/material/Material.h"

#include "anvil/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace anvil::material {
namespace {

/// Norton-Hoff stress from the potential φ = K/(m+1) (√3 ε̄̇_r)^(m+1):
/// s = ∂φ/∂ε̇ = 2η e with e = dev ε̇, η = K (√3 ε̄̇_r)^(m−1),
/// ∂s/∂ε̇ = 2η [P + (m−1)(2/3) e⊗e / ε̄̇_r²]. Shared by every viscoplastic law.
void norton_hoff_stress(double consistency, double sensitivity, double regularisation_rate, const Vec6& strain_rate,
                        Vec6& stress, J2Tangent& tangent) {
  const Vec6 e = deviator(strain_rate);
  const double rate_sq = 2.0 / 3.0 * e.squaredNorm() + regularisation_rate * regularisation_rate;
  const bool linear = sensitivity == 1.0;
  const double eta = linear ? consistency : consistency * std::pow(3.0 * rate_sq, 0.5 * (sensitivity - 1.0));
  stress = 2.0 * eta * e;
  tangent.two_eta = 2.0 * eta;
  tangent.beta = !linear && rate_sq > 0.0 ? 2.0 * eta * (sensitivity - 1.0) * 2.0 / 3.0 / rate_sq : 0.0;
  tangent.sensitivity = sensitivity;
}

double norton_hoff_viscosity(double consistency, double sensitivity, double regularisation_rate,
                             double equivalent_rate) {
  const double rate = std::sqrt(equivalent_rate * equivalent_rate + regularisation_rate * regularisation_rate);
  return consistency * std::pow(std::sqrt(3.0) * rate, sensitivity - 1.0);
}

} // namespace

NortonHoff::NortonHoff(double consistency, double sensitivity, double regularisation_rate, Softening softening)
    : consistency_(consistency), sensitivity_(sensitivity), regularisation_rate_(regularisation_rate),
      softening_(softening) {
  if (!(consistency > 0.0)) throw InputError("Norton-Hoff: K must be > 0 MPa.s^m");
  if (!(sensitivity > 0.0 && sensitivity <= 1.0)) throw InputError("Norton-Hoff: m must be in (0, 1]");
  if (!(regularisation_rate >= 0.0)) throw InputError("Norton-Hoff: regularisation rate must be >= 0 1/s");
  if (sensitivity < 1.0 && regularisation_rate == 0.0)
    throw InputError("Norton-Hoff: m < 1 needs a regularisation rate > 0 (rigid zones)");
}

double NortonHoff::viscosity(double equivalent_rate) const {
  return norton_hoff_viscosity(consistency_, sensitivity_, regularisation_rate_, equivalent_rate);
}

double NortonHoff::consistency(const PointState& state) const {
  if (softening_.activation_temperature == 0.0) return consistency_;
  constexpr double kelvin = 273.15;
  return consistency_ *
         std::exp(softening_.activation_temperature *
                  (1.0 / (state.temperature + kelvin) - 1.0 / (softening_.reference_temperature + kelvin)));
}

NortonHoff NortonHoff::at_temperature(double temperature) const {
  PointState state;
  state.temperature = temperature;
  return NortonHoff(consistency(state), sensitivity_, regularisation_rate_);
}

double NortonHoff::secant_viscosity(double equivalent_rate, const PointState& state) const {
  return norton_hoff_viscosity(consistency(state), sensitivity_, regularisation_rate_, equivalent_rate);
}

void NortonHoff::deviatoric_stress(const Vec6& strain_rate, const PointState& state, Vec6& stress,
                                   J2Tangent& tangent) const {
  norton_hoff_stress(consistency(state), sensitivity_, regularisation_rate_, strain_rate, stress, tangent);
}

std::string NortonHoff::describe() const {
  char text[200];
  if (sensitivity_ == 1.0)
    std::snprintf(text, sizeof text, "Newtonian, viscosity %g MPa.s", consistency_);
  else
    std::snprintf(text, sizeof text, "Norton-Hoff, K %g MPa.s^m, m %g, regularisation rate %g 1/s", consistency_,
                  sensitivity_, regularisation_rate_);
  std::string line = text;
  if (softening_.activation_temperature != 0.0) {
    std::snprintf(text, sizeof text, "; K at %g C, times exp(%g K (1/T - 1/T_ref))", softening_.reference_temperature,
                  softening_.activation_temperature);
    line += text;
  }
  return line;
}

LinearElastic::LinearElastic(double young_modulus, double poisson_ratio)
    : young_modulus_(young_modulus), poisson_ratio_(poisson_ratio) {
  if (!(young_modulus > 0.0)) throw InputError("linear elastic: E must be > 0 MPa");
  if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5)) throw InputError("linear elastic: nu must be in (-1, 0.5]");
}

void LinearElastic::deviatoric_stress(const Vec6& strain, const PointState&, Vec6& stress, J2Tangent& tangent) const {
  tangent.two_eta = 2.0 * shear_modulus();
  tangent.beta = 0.0;
  stress = tangent.two_eta * deviator(strain);
}

double LinearElastic::bulk_modulus() const {
  if (poisson_ratio_ == 0.5) return std::numeric_limits<double>::infinity();
  return young_modulus_ / (3.0 * (1.0 - 2.0 * poisson_ratio_));
}

void IncrementalElastic::deviatoric_stress(const Vec6& strain_rate, const PointState& state, Vec6& stress,
                                           J2Tangent& tangent) const {
  elastic_.deviatoric_stress(strain_rate, state, stress, tangent);
  stress = time_step_ * stress + deviator(state.elastic_stress);
  tangent.two_eta *= time_step_;
}

std::string LinearElastic::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "linear elastic, E %g MPa, nu %g", young_modulus_, poisson_ratio_);
  return text;
}

HanselSpittel::HanselSpittel(const Coefficients& c, double minimum_strain, double regularisation_rate)
    : c_(c), minimum_strain_(minimum_strain), regularisation_rate_(regularisation_rate) {
  if (!(c.A > 0.0)) throw InputError("Hansel-Spittel: A must be > 0 MPa");
  if (!(minimum_strain > 0.0)) throw InputError("Hansel-Spittel: the minimum strain must be > 0");
  if (!(regularisation_rate > 0.0)) throw InputError("Hansel-Spittel: the regularisation rate must be > 0 1/s");
}

double HanselSpittel::equivalent_stress(double strain, double rate, double temperature) const {
  const double e = std::max(strain, minimum_strain_), T = temperature;
  return c_.A * std::exp(c_.m1 * T) * (c_.m9 != 0.0 ? std::pow(T, c_.m9) : 1.0) * std::pow(e, c_.m2) *
         std::exp(c_.m4 / e) * std::pow(1.0 + e, c_.m5 * T) * std::exp(c_.m7 * e) * std::pow(rate, c_.m3 + c_.m8 * T);
}

double HanselSpittel::consistency(const PointState& state) const {
  // σ̄ = √3 K (√3 ε̄̇)^m  ⇒  K = σ̄(ε̄̇ = 1/√3) / √3.
  return equivalent_stress(state.equivalent_strain, 1.0 / std::sqrt(3.0), state.temperature) / std::sqrt(3.0);
}

double HanselSpittel::secant_viscosity(double equivalent_rate, const PointState& state) const {
  return norton_hoff_viscosity(consistency(state), rate_sensitivity(state), regularisation_rate_, equivalent_rate);
}

void HanselSpittel::deviatoric_stress(const Vec6& strain_rate, const PointState& state, Vec6& stress,
                                      J2Tangent& tangent) const {
  // K(ε̄, T) is constant within an increment (ε̄ is updated after it), so the
  // potential, its stress and tangent are those of Norton-Hoff.
  norton_hoff_stress(consistency(state), rate_sensitivity(state), regularisation_rate_, strain_rate, stress, tangent);
}

std::string HanselSpittel::describe() const {
  char text[300];
  std::snprintf(text, sizeof text,
                "Hansel-Spittel, A %g MPa, m1 %g 1/C, m2 %g, m3 %g, m4 %g, m5 %g 1/C, m7 %g, m8 %g 1/C, m9 %g; "
                "minimum strain %g, regularisation rate %g 1/s",
                c_.A, c_.m1, c_.m2, c_.m3, c_.m4, c_.m5, c_.m7, c_.m8, c_.m9, minimum_strain_, regularisation_rate_);
  return text;
}

} // namespace anvil::material

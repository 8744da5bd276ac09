#include "anvil/material/Material.h"

#include "anvil/core/error.h"

#include <cmath>
#include <cstdio>

namespace anvil::material {

NortonHoff::NortonHoff(double consistency, double sensitivity, double regularisation_rate)
    : consistency_(consistency), sensitivity_(sensitivity), regularisation_rate_(regularisation_rate) {
  if (!(consistency > 0.0)) throw InputError("Norton-Hoff: K must be > 0 MPa.s^m");
  if (!(sensitivity > 0.0 && sensitivity <= 1.0)) throw InputError("Norton-Hoff: m must be in (0, 1]");
  if (!(regularisation_rate >= 0.0)) throw InputError("Norton-Hoff: regularisation rate must be >= 0 1/s");
  if (sensitivity < 1.0 && regularisation_rate == 0.0)
    throw InputError("Norton-Hoff: m < 1 needs a regularisation rate > 0 (rigid zones)");
}

double NortonHoff::viscosity(double equivalent_rate) const {
  const double rate = std::sqrt(equivalent_rate * equivalent_rate + regularisation_rate_ * regularisation_rate_);
  return consistency_ * std::pow(std::sqrt(3.0) * rate, sensitivity_ - 1.0);
}

void NortonHoff::deviatoric_stress(const Vec6& strain_rate, const PointState&, Vec6& stress,
                                   Mat6& tangent) const {
  // Potential φ = K/(m+1) (√3 ε̄̇_r)^(m+1); s = ∂φ/∂ε̇ = 2η e with e = dev ε̇,
  // ∂s/∂ε̇ = 2η [P + (m-1)(2/3) e⊗e / ε̄̇_r²].
  const Vec6 e = deviator(strain_rate);
  const double rate_sq = 2.0 / 3.0 * e.squaredNorm() + regularisation_rate_ * regularisation_rate_;
  const double eta = consistency_ * std::pow(3.0 * rate_sq, 0.5 * (sensitivity_ - 1.0));
  static const Mat6 projector = deviatoric_projector();
  stress = 2.0 * eta * e;
  tangent = 2.0 * eta * projector;
  if (sensitivity_ != 1.0 && rate_sq > 0.0)
    tangent.noalias() += (2.0 * eta * (sensitivity_ - 1.0) * 2.0 / 3.0 / rate_sq) * (e * e.transpose());
}

std::string NortonHoff::describe() const {
  char text[200];
  if (sensitivity_ == 1.0)
    std::snprintf(text, sizeof text, "Newtonian, viscosity %g MPa.s", consistency_);
  else
    std::snprintf(text, sizeof text, "Norton-Hoff, K %g MPa.s^m, m %g, regularisation rate %g 1/s", consistency_,
                  sensitivity_, regularisation_rate_);
  return text;
}

LinearElastic::LinearElastic(double young_modulus, double poisson_ratio)
    : young_modulus_(young_modulus), poisson_ratio_(poisson_ratio) {
  if (!(young_modulus > 0.0)) throw InputError("linear elastic: E must be > 0 MPa");
  if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5)) throw InputError("linear elastic: nu must be in (-1, 0.5]");
}

void LinearElastic::deviatoric_stress(const Vec6& strain, const PointState&, Vec6& stress, Mat6& tangent) const {
  const double shear = young_modulus_ / (2.0 * (1.0 + poisson_ratio_));
  static const Mat6 projector = deviatoric_projector();
  stress = 2.0 * shear * deviator(strain);
  tangent = 2.0 * shear * projector;
}

double LinearElastic::bulk_modulus() const {
  if (poisson_ratio_ == 0.5) return std::numeric_limits<double>::infinity();
  return young_modulus_ / (3.0 * (1.0 - 2.0 * poisson_ratio_));
}

std::string LinearElastic::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "linear elastic, E %g MPa, nu %g", young_modulus_, poisson_ratio_);
  return text;
}

} // namespace anvil::material

// Constitutive laws (docs/design.md §2). Stateless: the stress follows from the strain
// rate (or small strain, for elastic laws) and the history passed in; the
// history itself (ε̄, T) lives in the body's per-element arrays.
#pragma once
#include "anvil/material/mandel.h"

#include <limits>
#include <memory>
#include <string>

namespace anvil::material {

/// History and temperature at an integration point.
struct PointState {
  double equivalent_strain = 0.0; ///< ε̄ (-)
  double temperature = 20.0;      ///< T (°C)
  /// Cauchy stress σ_n an elastic body carries into the increment (MPa,
  /// Mandel; IncrementalElastic); zero for laws without elastic memory.
  Vec6 elastic_stress = Vec6::Zero();
};

/// The tangent ds/dε of a J2 law: s depends on ε through e = dev ε only and
/// points along e (s = 2η(ε̄̇) e, plus a carried stress for elastic memory),
/// so that
///   ds/dε = 2η P + β e⊗e      (P the deviatoric projector, Mandel).
/// Every law here is of this kind; assembly uses the form, not a 6×6 matrix.
struct J2Tangent {
  double two_eta = 0.0;     ///< 2η: MPa·s (MPa for elastic laws)
  double beta = 0.0;        ///< of the rank-one term, MPa·s³ (0 for linear laws)
  double sensitivity = 1.0; ///< m of a power law: β = 2η (m − 1)(2/3)/ε̄̇_r² (1 for linear laws)
};

/// Deviatoric stress s and its tangent ds/dε for a strain rate ε (Mandel,
/// any trace: the law applies it to dev ε). s derives from a convex potential,
/// so the tangent is symmetric positive semi-definite.
class Material {
public:
  virtual ~Material() = default;

  /// s (MPa) and tangent at strain rate ε (1/s); for elastic laws ε is the
  /// small strain (-) and 2η is twice the shear modulus (MPa).
  virtual void deviatoric_stress(const Vec6& strain, const PointState& state, Vec6& stress,
                                 J2Tangent& tangent) const = 0;

  /// Bulk modulus κ (MPa, or MPa·s): the pressure equation is
  /// div v + p/κ = 0. Infinite for incompressible laws.
  virtual double bulk_modulus() const { return std::numeric_limits<double>::infinity(); }

  /// True when the unknown is a displacement (mm) rather than a velocity (mm/s).
  virtual bool is_elastic() const { return false; }

  /// True when s is linear in ε (Newton then converges in one step).
  virtual bool is_linear() const = 0;

  /// Secant viscosity (or shear modulus) s / (2 dev ε) at equivalent rate
  /// ε̄̇ (1/s): the Newtonian law that best stands in for this one at that rate.
  virtual double secant_viscosity(double equivalent_rate, const PointState& state) const = 0;

  /// Equivalent flow stress σ₀ = √(3/2)|s| (MPa) at equivalent rate ε̄̇ (1/s),
  /// the σ₀ of Tresca friction: 3 η ε̄̇ for any law of secant viscosity η.
  double flow_stress(double equivalent_rate, const PointState& state) const {
    return 3.0 * secant_viscosity(equivalent_rate, state) * equivalent_rate;
  }

  /// Consistency K (MPa·s^m) of the viscoplastic form s = 2K(√3ε̄̇)^(m−1)ε̇,
  /// the K of viscoplastic (Norton) friction; the shear modulus for elastic laws.
  virtual double consistency(const PointState& state) const = 0;

  /// True when the stress depends on ε̄ (the body needs ε̄ accumulated).
  virtual bool hardens() const { return false; }

  /// True when the stress depends on T (thermal softening in a thermal scene).
  virtual bool depends_on_temperature() const { return false; }

  /// Strain-rate sensitivity m (-): load ∝ velocity^m (0 for elastic laws).
  virtual double rate_sensitivity(const PointState& state) const = 0;

  /// One line for the log: law and parameters with units.
  virtual std::string describe() const = 0;
};

/// Norton-Hoff viscoplastic law: s = 2K (√3 ε̄̇_r)^(m-1) dev ε̇ with the
/// regularised rate ε̄̇_r = sqrt(ε̄̇² + ε̄̇₀²) (docs/design.md §2). m = 1 is Newtonian
/// with viscosity η = K. K may soften with temperature by an Arrhenius
/// factor, K(T) = K exp(β (1/T − 1/T_ref)) with T in kelvin (the form of
/// FORGE's Norton-Hoff cards, K₀ exp(β/T)).
class NortonHoff final : public Material {
public:
  /// Temperature dependence of K: none when β = 0.
  struct Softening {
    double activation_temperature = 0.0; ///< β (K)
    double reference_temperature = 20.0; ///< T_ref (°C), where K holds
  };
  /// K in MPa·s^m, 0 < m ≤ 1, ε̄̇₀ ≥ 0 in 1/s (> 0 required when m < 1 so
  /// that rigid zones have a finite viscosity).
  NortonHoff(double consistency, double sensitivity, double regularisation_rate, Softening softening);
  NortonHoff(double consistency, double sensitivity, double regularisation_rate)
      : NortonHoff(consistency, sensitivity, regularisation_rate, Softening{0.0, 20.0}) {}

  void deviatoric_stress(const Vec6& strain_rate, const PointState& state, Vec6& stress,
                         J2Tangent& tangent) const override;
  std::string describe() const override;
  bool is_linear() const override { return sensitivity_ == 1.0; }
  double secant_viscosity(double equivalent_rate, const PointState& state) const override;
  /// K(T) at the point's temperature.
  double consistency(const PointState& state) const override;
  bool depends_on_temperature() const override { return softening_.activation_temperature != 0.0; }
  double rate_sensitivity(const PointState&) const override { return sensitivity_; }
  double consistency() const { return consistency_; }
  double sensitivity() const { return sensitivity_; }
  double regularisation_rate() const { return regularisation_rate_; }
  /// The same law with K fixed at its value at `temperature` (°C): an
  /// isothermal scene pays no exp() per point.
  NortonHoff at_temperature(double temperature) const;
  /// Viscosity η = K (√3 ε̄̇_r)^(m-1) at equivalent strain rate ε̄̇ (MPa·s), at T_ref.
  double viscosity(double equivalent_rate) const;

private:
  double consistency_;
  double sensitivity_;
  double regularisation_rate_;
  Softening softening_;
};

/// Isotropic linear elasticity, small strain, in u-p mixed form: s = 2G dev ε,
/// p = -κ tr ε enforced weakly, so ν → 0.5 (κ → ∞) does not lock.
class LinearElastic final : public Material {
public:
  /// E in MPa, -1 < ν ≤ 0.5.
  LinearElastic(double young_modulus, double poisson_ratio);

  void deviatoric_stress(const Vec6& strain, const PointState& state, Vec6& stress, J2Tangent& tangent) const override;
  double bulk_modulus() const override;
  bool is_elastic() const override { return true; }
  bool is_linear() const override { return true; }
  double secant_viscosity(double, const PointState&) const override {
    return young_modulus_ / (2.0 * (1.0 + poisson_ratio_));
  }
  double consistency(const PointState& state) const override { return secant_viscosity(0.0, state); }
  double rate_sensitivity(const PointState&) const override { return 0.0; }
  std::string describe() const override;
  double shear_modulus() const { return young_modulus_ / (2.0 * (1.0 + poisson_ratio_)); }

private:
  double young_modulus_;
  double poisson_ratio_;
};

/// One increment Δt of a linear elastic law in velocity form, for an elastic
/// body (a die) solved with flowing ones: σ = σ_n + Δt C:ε̇ (small strain,
/// updated Lagrangian, rotations neglected: die strains are ~1e-3). With σ_n
/// from PointState::elastic_stress, s = dev σ_n + 2GΔt dev ε̇, and the
/// pressure equation is div v + (p − p_n)/(κΔt) = 0, p_n = −tr σ_n / 3:
/// a Newtonian law of viscosity GΔt with an initial stress. One object per
/// increment length: the law of an increment is built for its Δt.
class IncrementalElastic final : public Material {
public:
  /// `time_step` Δt > 0 in s; `elastic` must outlive the law.
  IncrementalElastic(const LinearElastic& elastic, double time_step) : elastic_(elastic), time_step_(time_step) {}

  void deviatoric_stress(const Vec6& strain_rate, const PointState& state, Vec6& stress,
                         J2Tangent& tangent) const override;
  double bulk_modulus() const override { return elastic_.bulk_modulus() * time_step_; }
  bool is_linear() const override { return true; }
  double secant_viscosity(double, const PointState&) const override { return elastic_.shear_modulus() * time_step_; }
  double consistency(const PointState& state) const override { return secant_viscosity(0.0, state); }
  double rate_sensitivity(const PointState&) const override { return 0.0; }
  std::string describe() const override { return elastic_.describe() + ", in velocity form"; }

private:
  const LinearElastic& elastic_;
  double time_step_; ///< s
};

/// Hansel-Spittel flow stress, T the point's temperature:
///   σ̄ = A e^(m1 T) T^m9 ε̄^m2 e^(m4/ε̄) (1+ε̄)^(m5 T) e^(m7 ε̄) ε̄̇^(m3 + m8 T),
/// T in °C, written as Norton-Hoff with m = m3 + m8 T and the strain- and
/// temperature-dependent consistency K = σ̄(ε̄̇ = 1/√3) / √3, so that
/// σ̄ = √3 K (√3 ε̄̇)^m. ε̄ is floored at `minimum_strain` (ε̄^m2 and e^(m4/ε̄)
/// are singular at 0).
class HanselSpittel final : public Material {
public:
  struct Coefficients {
    double A = 0.0; ///< MPa
    double m1 = 0, m2 = 0, m3 = 0, m4 = 0, m5 = 0, m7 = 0, m8 = 0, m9 = 0;
  };
  HanselSpittel(const Coefficients& c, double minimum_strain, double regularisation_rate);

  void deviatoric_stress(const Vec6& strain_rate, const PointState& state, Vec6& stress,
                         J2Tangent& tangent) const override;
  std::string describe() const override;
  bool is_linear() const override { return false; }
  /// ε̄ matters only through m2, m4, m5, m7; a steady-state card (all zero)
  /// needs no strain accumulated.
  bool hardens() const override { return c_.m2 != 0.0 || c_.m4 != 0.0 || c_.m5 != 0.0 || c_.m7 != 0.0; }
  bool depends_on_temperature() const override { return c_.m1 != 0.0 || c_.m5 != 0.0 || c_.m8 != 0.0 || c_.m9 != 0.0; }
  double secant_viscosity(double equivalent_rate, const PointState& state) const override;
  double consistency(const PointState& state) const override;
  double rate_sensitivity(const PointState& state) const override { return c_.m3 + c_.m8 * state.temperature; }
  /// σ̄ (MPa) at ε̄, ε̄̇ (1/s, unregularised), T: the formula above.
  double equivalent_stress(double strain, double rate, double temperature) const;

private:
  Coefficients c_;
  double minimum_strain_;
  double regularisation_rate_;
};

} // namespace anvil::material

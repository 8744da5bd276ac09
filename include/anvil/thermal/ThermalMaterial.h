// Thermal properties of a material card (docs/design.md §2, heat): conductivity and
// specific heat as constants or tables in T, density, surface emissivity.
// Units (docs/heat.md, Units): the card gives SI datasheet values, the
// solver works in mm, s, N, °C, so energy is mJ and power mW:
//   k [W/(m·K)] = k [mW/(mm·K)],  ρc [J/(m³·K)] × 1e-6 = ρc [mJ/(mm³·K)].
#pragma once
#include <string>
#include <vector>

namespace anvil::thermal {

/// A property against one variable (temperature, contact pressure): one
/// value, or a table interpolated linearly and held constant beyond its ends.
class PropertyTable {
public:
  PropertyTable() = default;
  explicit PropertyTable(double value) : values_{value} {}
  /// `at` increasing, one value each (sizes checked by the readers).
  PropertyTable(std::vector<double> at, std::vector<double> values);

  double at(double variable) const;
  /// Mean of the property between a and b, ∫ₐᵇ/(b − a) (its value where they
  /// meet): exact for the linear pieces and the constant ends.
  double mean(double a, double b) const;
  /// ∫₀ˣ of the property.
  double integral(double variable) const;
  bool constant() const { return values_.size() == 1; }

private:
  std::vector<double> at_; ///< the variable's values; empty for a constant
  std::vector<double> values_;
};

struct ThermalMaterial {
  PropertyTable conductivity;  ///< k, W/(m·K) = mW/(mm·K)
  PropertyTable specific_heat; ///< c, J/(kg·K)
  double density = 0.0;        ///< ρ, kg/m³
  double emissivity = 0.0;     ///< ε of the surface, -

  /// ρc in mJ/(mm³·K) (= MPa/K) at T (°C).
  double capacity(double temperature) const { return 1e-6 * density * specific_heat.at(temperature); }
  /// Enthalpy per volume ρ ∫₀ᵀ c dT in mJ/mm³ (0 at 0 °C): what a volume at T stores.
  double enthalpy(double temperature) const { return 1e-6 * density * specific_heat.integral(temperature); }
  /// Effusivity √(kρc) in mW·s^½/(mm²·K): splits friction heat between two surfaces.
  double effusivity(double temperature) const;
  /// α = k/(ρc), mm²/s.
  double diffusivity(double temperature) const { return conductivity.at(temperature) / capacity(temperature); }
  std::string describe(double temperature) const;
};

} // namespace anvil::thermal

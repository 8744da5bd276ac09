#include "anvil/thermal/ThermalMaterial.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace anvil::thermal {

PropertyTable::PropertyTable(std::vector<double> at, std::vector<double> values)
    : at_(std::move(at)), values_(std::move(values)) {
  if (values_.size() == 1) at_.clear();
}

double PropertyTable::at(double variable) const {
  if (at_.empty()) return values_.front();
  if (variable <= at_.front()) return values_.front();
  if (variable >= at_.back()) return values_.back();
  const auto upper = std::upper_bound(at_.begin(), at_.end(), variable);
  const std::size_t j = static_cast<std::size_t>(upper - at_.begin());
  const double s = (variable - at_[j - 1]) / (at_[j] - at_[j - 1]);
  return (1.0 - s) * values_[j - 1] + s * values_[j];
}

double PropertyTable::mean(double a, double b) const {
  if (at_.empty()) return values_.front();
  const double low = std::min(a, b), high = std::max(a, b);
  if (high - low <= 1e-12 * (1.0 + std::abs(low))) return at(low);
  // Trapezoids between the breakpoints inside (low, high): exact for linear pieces.
  double sum = 0.0, x = low;
  for (double point : at_)
    if (point > low && point < high) {
      sum += 0.5 * (at(x) + at(point)) * (point - x);
      x = point;
    }
  sum += 0.5 * (at(x) + at(high)) * (high - x);
  return sum / (high - low);
}

double PropertyTable::integral(double variable) const {
  return variable == 0.0 ? 0.0 : mean(0.0, variable) * variable;
}

double ThermalMaterial::effusivity(double temperature) const {
  return std::sqrt(conductivity.at(temperature) * capacity(temperature));
}

std::string ThermalMaterial::describe(double temperature) const {
  char text[200];
  std::snprintf(text, sizeof text, "k %.3g W/(m.K), rho %.4g kg/m3, c %.4g J/(kg.K), emissivity %.2g (at %g C)%s",
                conductivity.at(temperature), density, specific_heat.at(temperature), emissivity, temperature,
                conductivity.constant() && specific_heat.constant() ? "" : ", tables in T");
  return text;
}

} // namespace anvil::thermal

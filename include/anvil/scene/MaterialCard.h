// A material card (materials/*.yaml): the constitutive law, the temperature
// its numbers hold at, thermal properties and a die steel's hardness, each
// number with its source (docs/design.md §5).
#pragma once
#include "anvil/material/Material.h"
#include "anvil/thermal/ThermalMaterial.h"

#include <memory>
#include <optional>
#include <string>

namespace anvil::scene {

/// A material card as read.
struct MaterialCard {
  std::unique_ptr<material::Material> law;
  std::optional<double> temperature;               ///< °C, the temperature the numbers hold at
  std::optional<thermal::ThermalMaterial> thermal; ///< when the card gives thermal properties
  std::optional<thermal::PropertyTable> hardness;  ///< HRC against °C, die steels (die wear)
};

/// Reads a material card, requiring a source for every number.
MaterialCard read_material(const std::string& path);

} // namespace anvil::scene

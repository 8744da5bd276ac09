// The exact solution of frictionless compression between flat dies, against
// which the time loop is verified (tests, tools/study).
#pragma once
#include "anvil/material/Material.h"

#include <cmath>

namespace anvil::material {

/// Press load (N) on an incompressible body of volume V (mm³) at height H
/// (mm), squeezed from H0 between frictionless flat dies closing at speed v
/// (mm/s). The flow is homogeneous: ε̄̇ = v/H and ε̄ = ln(H0/H), so the
/// pressure is the flow stress and F = (V/H) σ₀(ε̄̇, ε̄).
inline double homogeneous_compression_load(const Material& law, double volume, double height, double initial_height,
                                           double speed, double temperature) {
  const PointState state{std::log(initial_height / height), temperature};
  return volume / height * law.flow_stress(speed / height, state);
}

} // namespace anvil::material

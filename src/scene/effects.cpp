#include "anvil/scene/effects.h"

#include <algorithm>
#include <cmath>

namespace anvil::scene {

const std::vector<Effect>& effect_registry() {
  static const std::vector<Effect> registry = {
      {"viscous_flow", "incompressible viscous or viscoplastic flow, P1+/P1 (MINI) element"},
      {"elasticity", "small-strain linear elasticity in u-p mixed form"},
      {"compressibility", "finite bulk modulus: the −C p term of the pressure equation"},
      {"nonlinear_law", "rate-dependent viscosity (m < 1): Newton iterations after a Newtonian predictor"},
      {"velocity_conditions", "prescribed velocity components on selected faces"},
      {"symmetry_planes", "zero normal velocity on axis-aligned planes"},
      {"sticking_plates", "flat plates moving the faces they touch with them"},
      {"frictionless_plates", "flat plates imposing the normal velocity only"},
      {"surface_loads", "tractions and pressures on selected faces (nodal forces)"},
  };
  return registry;
}

std::vector<std::string> resolve_effects(const Case& c, const std::vector<const material::Material*>& laws) {
  std::vector<std::string> active;
  auto add = [&](const std::string& name) {
    if (std::find(active.begin(), active.end(), name) == active.end()) active.push_back(name);
  };
  for (const material::Material* law : laws) {
    add(law->is_elastic() ? "elasticity" : "viscous_flow");
    if (std::isfinite(law->bulk_modulus())) add("compressibility");
    if (!law->is_linear()) add("nonlinear_law");
  }
  for (const BoundaryCondition& bc : c.boundary) switch (bc.kind) {
    case BoundaryKind::velocity: add("velocity_conditions"); break;
    case BoundaryKind::symmetry: add("symmetry_planes"); break;
    case BoundaryKind::sticking_plate: add("sticking_plates"); break;
    case BoundaryKind::frictionless_plate: add("frictionless_plates"); break;
    case BoundaryKind::traction:
    case BoundaryKind::pressure: add("surface_loads"); break;
    }
  // Registry order, so logs of different scenes compare line by line.
  std::vector<std::string> ordered;
  for (const Effect& e : effect_registry())
    if (std::find(active.begin(), active.end(), e.name) != active.end()) ordered.push_back(e.name);
  return ordered;
}

} // namespace anvil::scene

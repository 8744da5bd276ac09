#include "anvil/scene/effects.h"

#include <algorithm>
#include <cmath>
#include <iterator>

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
      {"time_stepping", "updated-Lagrangian time loop: x += Δt v, ε̄ += Δt ε̄̇, Δt control, checkpoints"},
      {"volume_compensation",
       "incompressible bodies in the time loop: each increment's flow restores the volume lost so far"},
      {"rigid_dies", "contact with rigid dies (plane or STL): search, penalty, active set, projection"},
      {"body_contact", "contact between deformable bodies: master/slave, symmetric or quasi-symmetric (Fourment 2008)"},
      {"self_contact", "a body's contact with itself (a contact pair of one body): the sides of a fold or lap kept "
                       "from passing through each other (docs/reading-a-run.md §5)"},
      {"friction", "friction on die or body contact (sticking, Tresca, Coulomb, Norton), regularised near zero slip"},
      {"hardening", "flow stress depending on ε̄ (Hansel-Spittel)"},
      {"remeshing",
       "quality watch every increment; CGAL remeshing of flowing bodies with field transfer when triggered"},
      {"heat", "temperature of the bodies with thermal properties: P1 conduction, lumped capacity, backward Euler "
               "on the enthalpy, staggered with the flow each increment (or iterated: thermal.coupling_tolerance)"},
      {"plastic_heating", "β σ:ε̇ of the flowing bodies into the heat equation (Taylor-Quinney)"},
      {"air_cooling", "convection and radiation of the free surfaces to the environment"},
      {"die_heat_transfer", "heat exchange with rigid dies held at their temperature (h constant or against pressure)"},
      {"contact_heat_transfer", "heat exchange between bodies in contact, through the contact pairs"},
      {"friction_heating", "friction heat on die and pair contact, split between the two surfaces"},
      {"thermal_softening", "flow stress at the local temperature (Hansel-Spittel T terms, Norton-Hoff K(T))"},
      {"flow_lines", "material lines: each node carries where its material started, interpolated through remeshes "
                     "(docs/reading-a-run.md §4)"},
      {"folds", "folds and laps: a body's surface meeting itself, found after each increment "
                "(docs/reading-a-run.md §5)"},
      {"die_fill", "die fill: each asking die's area touching the part, its share of a region, the underfill field "
                   "(docs/reading-a-run.md §3)"},
      {"damage", "ductile damage: D = ∫ f(σ) dε̄ per element of the flowing bodies for each criterion asked, "
                 "carried through remeshes (docs/method.md, \"Ductile damage\")"},
      {"die_wear", "die wear: the generalized Archard law w = ∫ K p^a v^b / H^c dt at each vertex of an asking die "
                   "(docs/method.md, \"Die wear\")"},
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
  for (const BoundaryCondition& bc : c.boundary)
    switch (bc.kind) {
    case BoundaryKind::velocity:
      add("velocity_conditions");
      break;
    case BoundaryKind::symmetry:
      add("symmetry_planes");
      break;
    case BoundaryKind::sticking_plate:
      add("sticking_plates");
      break;
    case BoundaryKind::frictionless_plate:
      add("frictionless_plates");
      break;
    case BoundaryKind::traction:
    case BoundaryKind::pressure:
      add("surface_loads");
      break;
    }
  if (c.time.enabled) {
    add("time_stepping");
    if (c.time.volume_compensation)
      for (const material::Material* law : laws)
        if (!std::isfinite(law->bulk_modulus())) add("volume_compensation");
  }
  if (!c.dies.empty()) add("rigid_dies");
  for (const ContactPairSpec& p : c.contact_pairs)
    add(p.master == p.slave ? "self_contact" : "body_contact");
  for (const DieSpec& d : c.dies)
    if (d.friction.kind != contact::FrictionKind::frictionless) add("friction");
  for (const ContactPairSpec& p : c.contact_pairs)
    if (p.friction.kind != contact::FrictionKind::frictionless) add("friction");
  for (const material::Material* law : laws)
    if (law->hardens()) add("hardening");
  if (c.remeshing.enabled) add("remeshing");
  for (const DieSpec& d : c.dies)
    if (d.fill) add("die_fill");
  for (const DieSpec& d : c.dies)
    if (d.wear.enabled) add("die_wear");
  for (const BodySpec& b : c.bodies)
    if (b.wear.enabled) add("die_wear");
  if (c.flow_line_axis >= 0) add("flow_lines");
  if (c.detect_folds && c.time.enabled) add("folds");
  if (!c.damage.empty()) add("damage");
  if (c.thermal.enabled) {
    add("heat");
    add("air_cooling");
    for (const material::Material* law : laws) {
      if (!law->is_elastic()) add("plastic_heating");
      if (law->depends_on_temperature()) add("thermal_softening");
    }
    if (!c.dies.empty()) add("die_heat_transfer");
    if (!c.contact_pairs.empty()) add("contact_heat_transfer");
    for (const DieSpec& d : c.dies)
      if (d.friction.kind != contact::FrictionKind::frictionless) add("friction_heating");
    for (const ContactPairSpec& p : c.contact_pairs)
      if (p.friction.kind != contact::FrictionKind::frictionless) add("friction_heating");
  }
  // Registry order, so logs of different scenes compare line by line.
  std::vector<std::string> ordered;
  for (const Effect& e : effect_registry())
    if (std::find(active.begin(), active.end(), e.name) != active.end()) ordered.push_back(e.name);
  return ordered;
}

std::vector<std::string> heat_alone_effects(const std::vector<std::string>& effects) {
  static const std::vector<std::string> exercised = {
      "symmetry_planes",   "time_stepping",         "rigid_dies", "heat", "air_cooling",
      "die_heat_transfer", "contact_heat_transfer", "flow_lines"};
  std::vector<std::string> kept;
  std::copy_if(effects.begin(), effects.end(), std::back_inserter(kept), [](const std::string& e) {
    return std::find(exercised.begin(), exercised.end(), e) != exercised.end();
  });
  return kept;
}

} // namespace anvil::scene

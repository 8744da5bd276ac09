#include "anvil/scene/Die.h"

#include "anvil/core/error.h"
#include "anvil/die/StlSurface.h"
#include "anvil/scene/MaterialCard.h"

#include <algorithm>
#include <cmath>

namespace anvil::scene {

Eigen::Vector3d Die::velocity(const DieState& s, double time_step) const {
  if (!kinematics) return Eigen::Vector3d::Zero();
  const double next = s.press_time + s.speed_factor * time_step;
  return (kinematics->displacement(next) - kinematics->displacement(s.press_time)) / time_step;
}

void Die::advance(DieState& s, double time_step) const {
  if (!kinematics) return;
  s.press_time += s.speed_factor * time_step;
  // Relative to the start: a displacement table need not begin at zero.
  const Eigen::Vector3d next = kinematics->displacement(s.press_time) - kinematics->displacement(0.0);
  s.stroke += (next - s.displacement).norm();
  s.displacement = next;
}

void Die::limit_speed(DieState& s, double resisting, double rate_sensitivity) const {
  if (!std::isfinite(load_limit) || resisting <= 0.0) return;
  // Load ∝ v^m, so the speed that gives the limit is v (limit/load)^(1/m);
  // m is floored so that a near-rigid-plastic body does not stop the press dead.
  const double m = std::max(rate_sensitivity, 0.05);
  s.speed_factor = std::min(1.0, s.speed_factor * std::pow(load_limit / resisting, 1.0 / m));
}

Die build_die(const DieSpec& spec, double body_size, double sampling) {
  Die d;
  d.name = spec.name;
  d.friction = spec.friction;
  if (!spec.stl_file.empty())
    d.surface = die::read_stl_surface(spec.stl_file, spec.source, spec.stl_offset);
  else
    d.surface = std::make_unique<die::PlaneSurface>(spec.plane_point, spec.plane_normal,
                                                    spec.plane_half_size > 0.0 ? spec.plane_half_size : body_size);
  if (spec.motion == "constant" || spec.motion == "hydraulic")
    d.kinematics = std::make_unique<die::ConstantVelocity>(spec.velocity);
  else if (spec.motion == "table")
    d.kinematics = std::make_unique<die::TableMotion>(spec.direction, spec.table_time, spec.table_values,
                                                      spec.table_is_speed ? die::TableMotion::Quantity::speed
                                                                          : die::TableMotion::Quantity::displacement);
  else if (spec.motion == "crank")
    d.kinematics = std::make_unique<die::CrankPress>(spec.direction, spec.crank_radius, spec.rod_length, spec.rpm,
                                                     spec.start_angle);
  else if (spec.motion == "hammer" || spec.motion == "screw_press") {
    d.energy =
        spec.motion == "hammer"
            ? die::EnergyPress::hammer(spec.blow_energy, spec.efficiency, spec.ram_mass, spec.blows, spec.pause)
            : die::EnergyPress::screw_press(spec.blow_energy, spec.flywheel_speed, spec.inertia, spec.screw_pitch,
                                            spec.efficiency, spec.ram_mass, spec.blows, spec.pause);
    d.kinematics = std::make_unique<die::ConstantVelocity>(d.energy->impact_speed() * spec.direction.normalized());
  }
  d.load_limit = spec.load_limit;
  if (spec.wear.enabled) {
    d.refined = die::refine(d.surface->triangles(), sampling);
    d.wear = spec.wear.law;
    if (!spec.wear.card.empty()) {
      const MaterialCard card = read_material(spec.wear.card);
      if (!card.hardness)
        throw InputError(spec.source + ": key 'dies[].wear.material': '" + spec.wear.card +
                         "' has no hardness table ('hardness', HRC)");
      d.wear->hardness =
          card.hardness->at(std::isnan(spec.wear.temperature) ? spec.temperature : spec.wear.temperature);
    }
  }
  return d;
}

} // namespace anvil::scene

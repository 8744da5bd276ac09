#include "anvil/scene/Heat.h"

#include "anvil/material/mandel.h"
#include "anvil/mesh/tet_geometry.h"

#include <cmath>

namespace anvil::scene {
namespace {

constexpr double kKelvin = 273.15;
/// Stefan-Boltzmann constant, 5.670374e-8 W/(m²·K⁴) in mW/(mm²·K⁴) (CODATA 2018).
constexpr double kStefanBoltzmann = 5.670374419e-11;

} // namespace

void element_temperatures(const mesh::TetMesh& mesh, std::span<const double> temperature,
                          std::span<material::PointState> states) {
  for (int e = 0; e < mesh.tet_count(); ++e)
    states[e].temperature = thermal::element_mean(mesh.tets[e], temperature);
}

Heat::Heat(const Scene& scene, const RunState& state)
    : materials_(state.mesh.tets.size(), nullptr), body_of_node_(state.mesh.nodes.size(), -1) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const mesh::MeshRange& range = state.bodies[b];
    std::fill_n(body_of_node_.begin() + range.first_node, range.node_count, int(b));
    if (scene.bodies[b].thermal)
      std::fill_n(materials_.begin() + range.first_tet, range.tet_count, &*scene.bodies[b].thermal);
  }
}

void Heat::exchanges(const Scene& scene, const RunState& state, const HeatContacts& contacts) {
  const mesh::TetMesh& mesh = state.mesh;
  const int n = mesh.node_count();
  exchanges_.clear();
  facet_contacts_.clear();
  node_power_.assign(n, 0.0);
  in_contact_.assign(n, 0);
  friction_generated_ = friction_to_dies_ = 0.0;
  // The exchanging area of each node: its boundary faces off the symmetry planes.
  area_ = contact::boundary_node_areas(mesh, contacts.symmetry_faces);
  auto solved = [&](int node) { return scene.bodies[body_of_node_[node]].thermal.has_value(); };
  // Without a solution (transfer), what lies within this distance touches, at zero pressure.
  const double touching = 1e-3 * scene.reference_length;
  auto die_exchange = [&](int node, int die, double pressure) {
    const DieSpec& spec = scene.input.dies[die];
    exchanges_.push_back(
        {node, area_[node], spec.heat.coefficient.at(pressure), spec.temperature, thermal::Sink::dies});
    in_contact_[node] = 1;
  };
  if (contacts.dies) {
    const auto& candidates = contacts.dies->candidates();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const contact::ContactCandidate& c = candidates[i];
      const double p = contacts.dies->pressure(int(i), *contacts.solution);
      if (p <= 0.0 || area_[c.node] == 0.0 || !solved(c.node)) continue;
      die_exchange(c.node, c.die, p);
      const double power = contacts.dies->friction_power(int(i), *contacts.solution);
      const double to_body = scene.input.dies[c.die].friction_heat_to_body;
      node_power_[c.node] += to_body * power;
      friction_generated_ += power;
      friction_to_dies_ += (1.0 - to_body) * power;
    }
  } else {
    // Transfer: a node lying on a die (the billet on the lower die) exchanges with it at h(0).
    for (int node = 0; node < n; ++node) {
      if (area_[node] == 0.0 || !solved(node)) continue;
      for (std::size_t d = 0; d < scene.dies.size(); ++d)
        if (scene.dies[d].surface->project(mesh.nodes[node] - state.dies[d].displacement).distance <= touching) {
          die_exchange(node, int(d), 0.0);
          break;
        }
    }
  }
  if (contacts.pairs) {
    const auto& points = contacts.pairs->projected_nodes();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const contact::ContactPoint& p = points[i];
      if (!p.on_slave || area_[p.node()] == 0.0) continue;
      const double pressure = contacts.solution ? contacts.pairs->node_pressure(int(i), *contacts.solution) : 0.0;
      if (contacts.solution ? pressure <= 0.0 : p.gap > touching) continue;
      const ContactPairSpec& spec = scene.input.contact_pairs[p.pair];
      facet_contacts_.push_back({p.node(), p.facet, p.shape, area_[p.node()], spec.heat.coefficient.at(pressure)});
      in_contact_[p.node()] = 1;
      for (int j : p.facet)
        in_contact_[j] = 1;
    }
  }
  if (contacts.pairs && contacts.solution) friction_between_bodies(scene, state, contacts);
  // The rest of the surface gives the air convection and radiation.
  const ThermalSpec& air = scene.input.thermal;
  const double air_kelvin = air.environment_temperature + kKelvin;
  for (int node = 0; node < n; ++node) {
    if (area_[node] == 0.0 || in_contact_[node] || !solved(node)) continue;
    const double emissivity = scene.bodies[body_of_node_[node]].thermal->emissivity;
    const double t = state.temperature[node] + kKelvin;
    const double radiation = emissivity * kStefanBoltzmann * (t * t + air_kelvin * air_kelvin) * (t + air_kelvin);
    exchanges_.push_back(
        {node, area_[node], air.convection + radiation, air.environment_temperature, thermal::Sink::environment});
  }
}

void Heat::friction_between_bodies(const Scene& scene, const RunState& state, const HeatContacts& contacts) {
  contacts.pairs->friction_power(*contacts.solution, point_power_);
  const auto& points = contacts.pairs->points();
  // Heat into a node of a body not solved for heat leaves the budget, as into a die.
  auto deposit = [&](int node, double power) {
    if (scene.bodies[body_of_node_[node]].thermal)
      node_power_[node] += power;
    else
      friction_to_dies_ += power;
  };
  auto effusivity = [&](int node) {
    const auto& thermal = scene.bodies[body_of_node_[node]].thermal;
    return thermal ? thermal->effusivity(state.temperature[node]) : 0.0;
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double power = point_power_[i];
    if (power == 0.0) continue;
    const contact::ContactPoint& p = points[i];
    // Split by the effusivities √(kρc) of the two surfaces; half each when
    // one body is not solved for heat (its effusivity is not known).
    const double own = effusivity(p.own[0]), other = effusivity(p.facet[0]);
    const double to_own = own > 0.0 && other > 0.0 ? own / (own + other) : 0.5;
    friction_generated_ += power;
    for (int k = 0; k < 3; ++k)
      if (p.own[k] >= 0) deposit(p.own[k], to_own * power * p.own_shape[k]);
    for (int j = 0; j < 3; ++j)
      deposit(p.facet[j], (1.0 - to_own) * power * p.shape[j]);
  }
}

thermal::HeatFlows Heat::step(const Scene& scene, const RunState& state, const HeatContacts& contacts,
                              const fem::ElementFields* fields, double dt, std::vector<double>& temperature) {
  exchanges(scene, state, contacts);
  element_power_.assign(state.mesh.tets.size(), 0.0);
  plastic_ = 0.0;
  if (fields)
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      if (!scene.bodies[b].thermal || scene.bodies[b].law->is_elastic()) continue;
      const mesh::MeshRange& range = state.bodies[b];
      for (int e = range.first_tet; e < range.first_tet + range.tet_count; ++e) {
        // σ:ε̇ = σ̄ ε̄̇ for a J2 flow law; the mesh has moved by Δt v since, at constant volume.
        element_power_[e] = scene.input.thermal.taylor_quinney * material::von_mises(fields->stress[e]) *
                            fields->rate[e] * mesh::signed_volume(state.mesh, e);
        plastic_ += element_power_[e] * dt;
      }
    }
  temperature = state.temperature;
  return step_.advance(state.mesh, materials_, {dt, element_power_, node_power_, exchanges_, facet_contacts_},
                       temperature);
}

thermal::HeatFlows Heat::advance(const Scene& scene, RunState& state, const HeatContacts& contacts,
                                 const fem::ElementFields* fields, double dt) {
  std::vector<double> next;
  const thermal::HeatFlows flows = step(scene, state, contacts, fields, dt, next);
  state.temperature = std::move(next);
  HeatBudget& budget = state.heat;
  budget.plastic += plastic_;
  budget.friction += friction_generated_ * dt;
  budget.to_dies += flows.to_dies + friction_to_dies_ * dt;
  budget.to_environment += flows.to_environment;
  budget.stored += flows.stored;
  return flows;
}

std::vector<double> Heat::predict(const Scene& scene, const RunState& state, const HeatContacts& contacts,
                                  const fem::ElementFields& fields, double dt) {
  std::vector<double> next;
  step(scene, state, contacts, &fields, dt, next);
  return next;
}

} // namespace anvil::scene

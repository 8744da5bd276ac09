// The heat effect of a run (docs/design.md §2, docs/heat.md): after each accepted
// increment, one heat step over its Δt on the moved mesh (staggered
// coupling: the flow of the next increment sees the new temperature). The
// step's sources and exchanges come from the increment:
// - plastic heat β σ̄ ε̄̇ V per element of the flowing bodies;
// - a boundary node pressed on a rigid die exchanges h(σn) (T − T_die) over
//   its tributary area, and takes the share `friction_heat_to_body` of the
//   friction power τ·w A made there; the rest goes to the die;
// - a slave node pressed on the other body of a contact pair exchanges
//   h(σn) (T − T_facet) with the master facet it projects onto (once per
//   node pair: master nodes of symmetric formulations do not exchange again);
//   the pair's friction power τ·w f_p A_p at each of its contact points
//   (nodes or quadrature points) is split between the two surfaces by their
//   effusivities √(kρc), each side's share spread on its nodes by their
//   shape functions there;
// - every other boundary node not on a symmetry plane gives the air
//   h (T − T_air) + εσ_SB (T⁴ − T_air⁴), the radiation as the secant
//   coefficient εσ_SB (T² + T_air²)(T + T_air) at T_n (kelvin).
// Before the press moves (thermal.transfer_time) the same step runs without
// flow; a node then exchanges with a die or the facet of another body it
// lies on (within 1e-3 of the mean boundary edge) at h(0).
#pragma once
#include "anvil/contact/BodyContact.h"
#include "anvil/contact/RigidContact.h"
#include "anvil/fem/element_fields.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/thermal/HeatStep.h"

#include <span>
#include <vector>

namespace anvil::scene {

/// What moves heat in one step besides conduction.
struct HeatContacts {
  const contact::RigidContact* dies = nullptr; ///< die contact of the increment (null: by proximity)
  const contact::BodyContact* pairs = nullptr; ///< pair contact of the increment (null: none)
  std::span<const char> symmetry_faces;        ///< per boundary face: on a symmetry plane
  const Eigen::VectorXd* solution = nullptr;   ///< nodal (v, p) the contacts' pressures are read at (null: transfer)
};

class Heat {
public:
  /// The thermal material of each element of `state`'s mesh.
  Heat(const Scene& scene, const RunState& state);

  /// One step of `dt` on state.mesh: state.temperature and state.heat
  /// advance. `fields`: the increment's (plastic heat), or null (transfer).
  thermal::HeatFlows advance(const Scene& scene, RunState& state, const HeatContacts& contacts,
                             const fem::ElementFields* fields, double dt);
  /// The temperatures the same step would give, `state` unchanged: the
  /// iterated coupling's estimate of the end of an increment being solved.
  std::vector<double> predict(const Scene& scene, const RunState& state, const HeatContacts& contacts,
                              const fem::ElementFields& fields, double dt);

  std::span<const thermal::ThermalMaterial* const> materials() const { return materials_; }

private:
  void exchanges(const Scene& scene, const RunState& state, const HeatContacts& contacts);
  /// The friction heat of the contact pairs into node_power_, split between the two surfaces.
  void friction_between_bodies(const Scene& scene, const RunState& state, const HeatContacts& contacts);
  /// The step from state.temperature into `temperature`.
  thermal::HeatFlows step(const Scene& scene, const RunState& state, const HeatContacts& contacts,
                          const fem::ElementFields* fields, double dt, std::vector<double>& temperature);

  std::vector<const thermal::ThermalMaterial*> materials_; ///< per element; null where not solved
  std::vector<int> body_of_node_;
  thermal::HeatStep step_;
  // Reused from step to step.
  std::vector<thermal::NodeExchange> exchanges_;
  std::vector<thermal::FacetExchange> facet_contacts_;
  std::vector<double> element_power_, node_power_, area_, point_power_;
  std::vector<char> in_contact_;
  double friction_generated_ = 0.0, friction_to_dies_ = 0.0; ///< mW of the step being built
  double plastic_ = 0.0;                                     ///< mJ of plastic heat the step puts in
};

/// Per element, the mean of its nodes' temperatures (the flow law's T).
void element_temperatures(const mesh::TetMesh& mesh, std::span<const double> temperature,
                          std::span<material::PointState> states);

} // namespace anvil::scene

// The material scales contact terms need in an increment: σ₀ and K per
// node for friction, the penalty ρ and the force scale of the Newton test.
#pragma once
#include "anvil/fem/Assembler.h"
#include "anvil/material/Material.h"
#include "anvil/mesh/TetMesh.h"

#include <span>
#include <vector>

namespace anvil::contact {

/// A body of the scene as the scales see it.
struct ScaledBody {
  mesh::MeshRange range;
  const material::Material* law; ///< the body's law as the case gives it
};

struct ContactScales {
  std::vector<double> flow_stress; ///< σ₀ per node (MPa); infinite on elastic bodies
  std::vector<double> consistency; ///< K per node; infinite on elastic bodies
  double penalty = 0.0;            ///< ρ (MPa·s/mm)
  double reference_force = 0.0;    ///< N, 3 η ε̇_ref V^(2/3) of the softest body
};

/// Scales from the solution `u` of the increment before, frozen over the
/// next one so that its tangent stays exact. σ₀ and K are nodal means of the
/// element values at the element's own rate (the process rate
/// `reference_rate` where it is at rest). ρ = `penalty_factor` × 3η/L with η
/// the mean secant viscosity of the softest body at `reference_rate` and L =
/// `body_size`: the penetration velocity σn/ρ is then about 1/factor of the
/// press speed, whatever the flow stress does along the stroke.
ContactScales contact_scales(const mesh::TetMesh& mesh, std::span<const ScaledBody> bodies,
                             const fem::ElementLaws& laws, std::span<const material::PointState> states,
                             const fem::BodyUnknowns& u, double reference_rate, double body_size,
                             double penalty_factor);

} // namespace anvil::contact

// Element-centre fields of a solution: the ε̄̇ that ε̄ integrates and the
// size field reads, the σ elastic bodies carry and the VTK series shows.
#pragma once
#include "anvil/fem/Assembler.h"
#include "anvil/material/Material.h"
#include "anvil/mesh/TetMesh.h"

#include <span>
#include <vector>

namespace anvil::fem {

struct ElementFields {
  std::vector<double> rate;           ///< ε̄̇ per element (1/s; ε̄ for a displacement solve)
  std::vector<material::Vec6> stress; ///< Cauchy σ per element, Mandel (MPa)
};

/// The fields of `u` at the centroid of each element of `mesh` (element e
/// with law laws[e] and history states[e]), where the bubble's gradient
/// vanishes (mini_element_fields).
ElementFields element_fields(const mesh::TetMesh& mesh, const ElementLaws& laws,
                             std::span<const material::PointState> states, const BodyUnknowns& u);

} // namespace anvil::fem

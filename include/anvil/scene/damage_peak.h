// Where a damage criterion is largest: the value a forging engineer compares
// with the material's critical one, and where the crack would start.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/RunState.h"

#include <vector>

namespace anvil::scene {

struct DamagePeak {
  double value = 0.0;
  int body = 0;                               ///< index in the scene's bodies
  mesh::Point position = mesh::Point::Zero(); ///< mm, centroid of the element holding it
};

/// The largest D of criterion `k` over the elements of `state` (the first
/// such element where several hold it).
DamagePeak damage_peak(const RunState& state, std::size_t k);

} // namespace anvil::scene

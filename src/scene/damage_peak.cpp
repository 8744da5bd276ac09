#include "anvil/scene/damage_peak.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>

namespace anvil::scene {

DamagePeak damage_peak(const RunState& state, std::size_t k) {
  const std::vector<double>& d = state.damage.at(k);
  DamagePeak peak;
  if (d.empty()) return peak;
  const int e = static_cast<int>(std::max_element(d.begin(), d.end()) - d.begin());
  peak.value = d[e];
  peak.position = mesh::centroid(state.mesh, e);
  for (std::size_t b = 0; b < state.bodies.size(); ++b)
    if (e >= state.bodies[b].first_tet && e < state.bodies[b].first_tet + state.bodies[b].tet_count)
      peak.body = static_cast<int>(b);
  return peak;
}

} // namespace anvil::scene

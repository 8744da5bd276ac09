#include "anvil/remesh/size_field.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace anvil::remesh {

std::function<double(const mesh::Point&, double scale)>
adaptive_size(const mesh::TetMesh& old, const PointLocator& in_old, std::span<const double> rate,
              const scene::Scene& scene, std::span<const scene::DieState> dies_now, double coarse, double smallest) {
  double mean_rate = 0.0;
  for (int e = 0; e < old.tet_count(); ++e)
    mean_rate += rate[e] * mesh::signed_volume(old, e);
  mean_rate /= mesh::volume(old);
  // The distance to the nearest die at the old nodes, interpolated between
  // them: CGAL asks for the size millions of times, far too often for a die
  // projection each. Farther than `coarse` makes no difference.
  std::vector<double> die_distance(old.nodes.size(), coarse);
  for (std::size_t i = 0; i < old.nodes.size(); ++i)
    for (std::size_t d = 0; d < scene.dies.size(); ++d)
      die_distance[i] =
          std::min(die_distance[i],
                   std::max(0.0, scene.dies[d].surface->project(old.nodes[i] - dies_now[d].displacement).distance));
  return [&old, &in_old, rate, mean_rate, coarse, smallest,
          die_distance = std::move(die_distance)](const mesh::Point& x, double scale) {
    const Location at = in_old.locate(x);
    double to_die = 0.0;
    for (int a = 0; a < 4; ++a)
      to_die += at.weights[a] * die_distance[old.tets[at.tet][a]];
    double wanted = std::min(scale * coarse, to_die);
    const double here = rate[at.tet];
    if (here > 0.0) wanted = std::min(wanted, scale * coarse * std::sqrt(mean_rate / here));
    return std::max(wanted, scale * smallest);
  };
}

} // namespace anvil::remesh

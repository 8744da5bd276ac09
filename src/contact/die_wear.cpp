#include "anvil/contact/die_wear.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace anvil::contact {

double WearLaw::rate(double pressure, double sliding) const {
  if (pressure <= 0.0 || sliding <= 0.0) return 0.0;
  return coefficient * std::pow(pressure, pressure_exponent) * std::pow(sliding, velocity_exponent) /
         std::pow(hardness, hardness_exponent);
}

namespace {

/// A cell of a uniform grid of side `cell`, as one key.
std::int64_t cell_key(const mesh::Point& x, double cell) {
  const auto index = [&](double c) { return static_cast<std::int64_t>(std::floor(c / cell)) & 0x1fffff; };
  return (index(x.x()) << 42) | (index(x.y()) << 21) | index(x.z());
}

} // namespace

void add_wear(std::span<const mesh::Point> vertices, std::span<const WearPoint> points, double dt,
              std::vector<double>& wear, std::span<const double> scale) {
  if (points.empty()) return;
  double cell = 0.0;
  for (const WearPoint& p : points)
    cell = std::max(cell, p.reach);
  if (!(cell > 0.0)) return;
  // The points by grid cell of side the largest reach: a vertex's candidates
  // are in its cell and the 26 around it.
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  for (std::size_t i = 0; i < points.size(); ++i)
    grid[cell_key(points[i].at, cell)].push_back(static_cast<int>(i));
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const mesh::Point& x = vertices[v];
    int nearest = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find(cell_key(x + cell * Eigen::Vector3d(dx, dy, dz), cell));
          if (found == grid.end()) continue;
          for (int i : found->second) {
            const double distance = (points[i].at - x).norm();
            if (distance <= points[i].reach && distance < best) best = distance, nearest = i;
          }
        }
    if (nearest >= 0) wear[v] += dt * points[nearest].rate * (scale.empty() ? 1.0 : scale[v]);
  }
}

} // namespace anvil::contact

#include "anvil/remesh/size_levels.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>

namespace anvil::remesh {

double finer_level(double previous, double smallest) {
  return std::max(0.75 * previous, smallest);
}

std::vector<char> level_cells(const mesh::TetMesh& mesh, const std::function<double(const mesh::Point&)>& size,
                              double previous, double length) {
  const double finer_than = std::sqrt(previous * length);
  std::vector<char> region(mesh.tets.size(), 0);
  for (int e = 0; e < mesh.tet_count(); ++e)
    region[e] = size(mesh::centroid(mesh, e)) < finer_than;
  return region;
}

std::vector<LevelBorder> level_borders(const mesh::TetMesh& body, const std::function<double(const mesh::Point&)>& size,
                                       double edge_length, double smallest) {
  std::vector<LevelBorder> borders;
  std::vector<mesh::InnerFace> inner; // made at the first level: a uniform size has none
  std::vector<double> area_of;
  for (double previous = edge_length; previous > smallest * (1.0 + 1e-9);) {
    const double length = finer_level(previous, smallest);
    const std::vector<char> region = level_cells(body, size, previous, length);
    if (std::find(region.begin(), region.end(), 1) == region.end()) break;
    if (inner.empty()) {
      inner = mesh::inner_faces(body);
      for (const mesh::InnerFace& f : inner)
        area_of.push_back(mesh::area_vector(body, f.face).norm());
    }
    double area = 0.0;
    for (std::size_t k = 0; k < inner.size(); ++k)
      if (region[inner[k].tets[0]] != region[inner[k].tets[1]]) area += area_of[k];
    borders.push_back({previous, length, area});
    previous = length;
  }
  return borders;
}

} // namespace anvil::remesh

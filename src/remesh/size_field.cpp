#include "anvil/remesh/size_field.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace anvil::remesh {
namespace {

constexpr double kInfinite = std::numeric_limits<double>::infinity();

/// `size` lowered so that it grows by at most (kGradation − 1)·L along each
/// edge of length L: shortest paths from the smallest sizes (Dijkstra).
void grade(const mesh::TetMesh& mesh, std::vector<double>& size) {
  const std::vector<std::vector<int>> tets_around = mesh::tets_around_nodes(mesh);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::size_t n = 0; n < size.size(); ++n)
    queue.emplace(size[n], static_cast<int>(n));
  while (!queue.empty()) {
    const auto [h, i] = queue.top();
    queue.pop();
    if (h > size[i]) continue;
    for (int e : tets_around[i])
      for (int j : mesh.tets[e]) {
        const double through = h + (kGradation - 1.0) * (mesh.nodes[i] - mesh.nodes[j]).norm();
        if (through < size[j]) size[j] = through, queue.emplace(through, j);
      }
  }
}

} // namespace

std::vector<double> die_vertex_radii(const std::vector<mesh::Point>& vertices,
                                     const std::vector<std::array<int, 3>>& faces) {
  // Each facet's edges as (smaller vertex, larger vertex, facet): sorted,
  // the two facets of an edge are neighbours.
  std::vector<std::array<int, 3>> sides;
  sides.reserve(3 * faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f)});
    }
  std::sort(sides.begin(), sides.end());
  auto area_vector = [&](int f) {
    const auto& t = faces[f];
    return mesh::Point((vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]));
  };
  std::vector<double> radius(vertices.size(), kInfinite);
  for (std::size_t k = 0; k + 1 < sides.size(); ++k) {
    if (sides[k][0] != sides[k + 1][0] || sides[k][1] != sides[k + 1][1]) continue;
    const mesh::Point n1 = area_vector(sides[k][2]), n2 = area_vector(sides[k + 1][2]);
    const double length = (vertices[sides[k][1]] - vertices[sides[k][0]]).norm();
    if (length == 0.0 || n1.norm() == 0.0 || n2.norm() == 0.0) continue;
    const double angle = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
    // The facets' heights over the edge: twice their areas over its length.
    const double width = 0.5 * (n1.norm() + n2.norm()) / length;
    if (angle <= 0.0) continue;
    const double r = width / angle;
    for (int v : {sides[k][0], sides[k][1]})
      radius[v] = std::min(radius[v], r);
  }
  return radius;
}

std::vector<double> wanted_sizes(const mesh::TetMesh& old, std::span<const double> rate, const scene::Scene& scene,
                                 std::span<const scene::DieState> dies_now,
                                 const std::vector<std::vector<double>>& die_radii, double coarse, double smallest) {
  const std::size_t nodes = old.nodes.size();
  std::vector<double> size(nodes, coarse);
  // The flash: the gap between the two nearest dies, kAcrossGap elements across.
  if (scene.dies.size() >= 2)
    for (std::size_t i = 0; i < nodes; ++i) {
      double nearest = kInfinite, second = kInfinite;
      for (std::size_t d = 0; d < scene.dies.size(); ++d) {
        const double to =
            std::max(0.0, scene.dies[d].surface->project(old.nodes[i] - dies_now[d].displacement).distance);
        if (to < nearest)
          second = nearest, nearest = to;
        else
          second = std::min(second, to);
      }
      size[i] = std::min(size[i], (nearest + second) / kAcrossGap);
    }
  // A die's fillets and edges: each curved die vertex near the body asks for
  // kEdgeOverRadius of its radius there, growing away from it by the gradation.
  const Eigen::AlignedBox3d box = mesh::bounding_box(old);
  const mesh::Point low = box.min(), high = box.max();
  const double reach = coarse / (kGradation - 1.0);
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const auto& vertices = scene.dies[d].surface->triangles().vertices;
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      const double at_vertex = std::max(smallest, kEdgeOverRadius * die_radii[d][v]);
      if (at_vertex >= coarse) continue;
      const mesh::Point x = vertices[v] + dies_now[d].displacement;
      if ((x.array() < low.array() - reach).any() || (x.array() > high.array() + reach).any()) continue;
      for (std::size_t i = 0; i < nodes; ++i)
        size[i] = std::min(size[i], at_vertex + (kGradation - 1.0) * (old.nodes[i] - x).norm());
    }
  }
  // Fast flow: coarse·√(mean ε̄̇ / ε̄̇) of the node's fastest element.
  double mean_rate = 0.0;
  for (int e = 0; e < old.tet_count(); ++e)
    mean_rate += rate[e] * mesh::signed_volume(old, e);
  mean_rate /= mesh::volume(old);
  for (int e = 0; e < old.tet_count(); ++e)
    if (rate[e] > 0.0)
      for (int n : old.tets[e])
        size[n] = std::min(size[n], coarse * std::sqrt(mean_rate / rate[e]));
  for (double& h : size)
    h = std::max(h, smallest);
  grade(old, size);
  return size;
}

std::function<double(const mesh::Point&, double scale)>
adaptive_size(const mesh::TetMesh& old, const PointLocator& in_old, std::span<const double> rate,
              const scene::Scene& scene, std::span<const scene::DieState> dies_now, double coarse, double smallest) {
  std::vector<std::vector<double>> die_radii;
  for (const scene::Die& die : scene.dies)
    die_radii.push_back(die_vertex_radii(die.surface->triangles().vertices, die.surface->triangles().faces));
  const std::vector<double> size = wanted_sizes(old, rate, scene, dies_now, die_radii, coarse, smallest);
  // The user's size boxes, each where its die is now: their size inside,
  // growing by the gradation with the distance outside (at the samples, not
  // the old nodes: a box may be smaller than the old elements).
  std::vector<std::pair<Eigen::AlignedBox3d, double>> boxes;
  for (const scene::SizeBox& b : scene.input.remeshing.size_boxes) {
    const mesh::Point shift = b.die >= 0 ? mesh::Point(dies_now[b.die].displacement) : mesh::Point::Zero();
    boxes.emplace_back(Eigen::AlignedBox3d(b.box.min() + shift, b.box.max() + shift), b.size);
  }
  // CGAL asks for the size at millions of cell centroids while it remeshes:
  // the field is sampled once on a grid of spacing `smallest` over the body
  // (a field that grows by at most half a millimetre per millimetre is
  // linear enough between the samples) and interpolated trilinearly.
  const Eigen::AlignedBox3d extent = mesh::bounding_box(old);
  const mesh::Point low = extent.min(), high = extent.max();
  std::array<int, 3> cells{};
  for (int k = 0; k < 3; ++k)
    cells[k] = std::max(1, static_cast<int>(std::ceil((high[k] - low[k]) / smallest)));
  const mesh::Point spacing = (high - low).cwiseQuotient(mesh::Point(cells[0], cells[1], cells[2]));
  // The grid cell that holds x along axis k (the field's own rule, below).
  auto cell_along = [low, spacing, cells](double x, int k) {
    const double u = std::clamp((x - low[k]) / spacing[k], 0.0, double(cells[k]));
    return std::pair{std::min(static_cast<int>(u), cells[k] - 1), u};
  };
  auto sample_index = [cells](int i, int j, int k) {
    return (std::size_t(k) * (cells[1] + 1) + j) * (cells[0] + 1) + i;
  };
  // The field is asked inside the body only, so only the corners of the grid
  // cells within one cell of an element are ever read. The others lie
  // outside, many far from the body, where locating a sample takes a box
  // query as wide as its distance to the mesh (VTK's is quadratic in the
  // elements the box holds): they keep the coarse size, unread.
  std::vector<char> needed(std::size_t(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1), 0);
  for (int e = 0; e < old.tet_count(); ++e) {
    const Eigen::AlignedBox3d b = mesh::bounding_box(old, e);
    std::array<int, 3> first{}, last{};
    for (int k = 0; k < 3; ++k) {
      first[k] = std::max(cell_along(b.min()[k], k).first - 1, 0);
      last[k] = std::min(cell_along(b.max()[k], k).first + 2, cells[k]); // the far corner of the cell beyond
    }
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i)
          needed[sample_index(i, j, k)] = 1;
  }
  std::vector<double> sample(needed.size(), coarse);
  for (int k = 0; k <= cells[2]; ++k)
    for (int j = 0; j <= cells[1]; ++j)
      for (int i = 0; i <= cells[0]; ++i) {
        if (!needed[sample_index(i, j, k)]) continue;
        const mesh::Point x = low + mesh::Point(i, j, k).cwiseProduct(spacing);
        const Location at = in_old.locate(x);
        double h = 0.0;
        for (int a = 0; a < 4; ++a)
          h += at.weights[a] * size[old.tets[at.tet][a]];
        for (const auto& [user_box, box_size] : boxes)
          h = std::min(h, box_size + (kGradation - 1.0) * user_box.exteriorDistance(x));
        sample[sample_index(i, j, k)] = h;
      }
  return [cell_along, sample_index, sample = std::move(sample)](const mesh::Point& x, double scale) {
    std::array<int, 3> cell{};
    std::array<double, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const auto [c, u] = cell_along(x[k], k);
      cell[k] = c;
      t[k] = u - c;
    }
    double h = 0.0;
    for (int c = 0; c < 8; ++c) {
      const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
      const double w = (di ? t[0] : 1.0 - t[0]) * (dj ? t[1] : 1.0 - t[1]) * (dk ? t[2] : 1.0 - t[2]);
      h += w * sample[sample_index(cell[0] + di, cell[1] + dj, cell[2] + dk)];
    }
    return scale * h;
  };
}

} // namespace anvil::remesh

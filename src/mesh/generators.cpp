#include "anvil/mesh/generators.h"

#include "anvil/core/error.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace anvil::mesh {
namespace {

/// Cells of about `element_size` along `length`, at least one; a double, so
/// that counting the nodes of a mistyped size cannot overflow.
double cell_count(double length, double element_size) {
  return std::max(1.0, std::round(length / element_size));
}

std::array<int, 3> as_ints(const std::array<double, 3>& cells) {
  return {static_cast<int>(cells[0]), static_cast<int>(cells[1]), static_cast<int>(cells[2])};
}

double grid_nodes(const std::array<double, 3>& cells) {
  return (cells[0] + 1.0) * (cells[1] + 1.0) * (cells[2] + 1.0);
}

std::array<double, 3> box_cells(const Point& size, double element_size) {
  return {cell_count(size.x(), element_size), cell_count(size.y(), element_size), cell_count(size.z(), element_size)};
}

/// Rings of the disc, layers along z.
std::array<double, 2> cylinder_cells(double radius, double height, double element_size) {
  return {cell_count(radius, element_size), cell_count(height, element_size)};
}

/// The unit box mapped onto the quarter disc: radial cells twice, layers.
std::array<double, 3> quarter_cylinder_cells(double radius, double height, double element_size) {
  const double n = cell_count(radius, element_size);
  return {n, n, cell_count(height, element_size)};
}

/// Radial cells, cells along the mid arc, layers.
std::array<double, 3> quarter_ring_cells(double outer_radius, double inner_radius, double height, double element_size) {
  const double mid = 0.5 * (outer_radius + inner_radius);
  return {cell_count(outer_radius - inner_radius, element_size), cell_count(0.5 * std::numbers::pi * mid, element_size),
          cell_count(height, element_size)};
}

void orient_positive(TetMesh& mesh) {
  for (int e = 0; e < mesh.tet_count(); ++e)
    if (signed_volume(mesh, e) < 0.0) std::swap(mesh.tets[e][2], mesh.tets[e][3]);
}

/// Tags each boundary face by its outward normal's dominant direction.
template <class TagOfNormal> void tag_by_normal(TetMesh& mesh, TagOfNormal tag_of_normal) {
  build_boundary(mesh);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    mesh.boundary_tags[f] = tag_of_normal(area_vector(mesh, mesh.boundary_faces[f]).normalized());
  }
}

} // namespace

TetMesh make_box(const Point& origin, const Point& size, double element_size) {
  if (!(element_size > 0.0)) throw InputError("box mesh: element_size must be > 0");
  return make_box(origin, size, as_ints(box_cells(size, element_size)));
}

TetMesh make_box(const Point& origin, const Point& size, const std::array<int, 3>& cells) {
  const auto [nx, ny, nz] = cells;
  TetMesh mesh;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  mesh.nodes.reserve(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.push_back(origin + Point(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz));
  // Kuhn split: one tet per path 000 -> 111 along the axes in the order of a permutation.
  constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  mesh.tets.reserve(static_cast<std::size_t>(6 * nx * ny * nz));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& perm : kPermutations) {
          std::array<int, 3> corner{i, j, k};
          Tet t;
          t[0] = id(corner[0], corner[1], corner[2]);
          for (int s = 0; s < 3; ++s) {
            ++corner[perm[s]];
            t[s + 1] = id(corner[0], corner[1], corner[2]);
          }
          mesh.tets.push_back(t);
        }
  orient_positive(mesh);
  tag_by_normal(mesh, [](const Point& n) {
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    return 2 * axis + (n[axis] > 0.0 ? 2 : 1);
  });
  return mesh;
}

TetMesh make_cylinder(double radius, double height, double element_size) {
  if (!(radius > 0.0 && height > 0.0 && element_size > 0.0))
    throw InputError("cylinder mesh: radius, height and element_size must be > 0");
  const std::array<double, 2> cells = cylinder_cells(radius, height, element_size);
  const int rings = static_cast<int>(cells[0]), layers = static_cast<int>(cells[1]);

  // Disc: node 0 at the centre, ring k (1..rings) has 6k nodes at radius R k / rings.
  std::vector<Eigen::Vector2d> disc{Eigen::Vector2d::Zero()};
  std::vector<int> ring_start{0};
  for (int k = 1; k <= rings; ++k) {
    ring_start.push_back(static_cast<int>(disc.size()));
    const double r = radius * k / rings;
    for (int j = 0; j < 6 * k; ++j) {
      const double a = 2.0 * std::numbers::pi * j / (6 * k);
      disc.emplace_back(r * std::cos(a), r * std::sin(a));
    }
  }
  // Triangles between consecutive rings: zip the two rings by angle.
  std::vector<Triangle> triangles;
  for (int k = 1; k <= rings; ++k) {
    const int n_out = 6 * k, out0 = ring_start[k];
    if (k == 1) {
      for (int j = 0; j < n_out; ++j)
        triangles.push_back({0, out0 + j, out0 + (j + 1) % n_out});
      continue;
    }
    const int n_in = 6 * (k - 1), in0 = ring_start[k - 1];
    int i = 0, j = 0;
    while (i < n_in || j < n_out) {
      const double next_in = static_cast<double>(i + 1) / n_in, next_out = static_cast<double>(j + 1) / n_out;
      if (j < n_out && (i == n_in || next_out <= next_in)) {
        triangles.push_back({in0 + i % n_in, out0 + j, out0 + (j + 1) % n_out});
        ++j;
      } else {
        triangles.push_back({in0 + i % n_in, out0 + j % n_out, in0 + (i + 1) % n_in});
        ++i;
      }
    }
  }

  TetMesh mesh;
  const int per_layer = static_cast<int>(disc.size());
  for (int l = 0; l <= layers; ++l)
    for (const auto& p : disc)
      mesh.nodes.emplace_back(p.x(), p.y(), height * l / layers);
  for (int l = 0; l < layers; ++l) {
    for (Triangle tri : triangles) {
      std::sort(tri.begin(), tri.end());
      const int a0 = tri[0] + l * per_layer, b0 = tri[1] + l * per_layer, c0 = tri[2] + l * per_layer;
      const int a1 = a0 + per_layer, b1 = b0 + per_layer, c1 = c0 + per_layer;
      // Each quad side (x<y) is cut by the diagonal y0-x1, so neighbours agree.
      mesh.tets.push_back({a0, b0, c0, a1});
      mesh.tets.push_back({b0, c0, a1, b1});
      mesh.tets.push_back({c0, a1, b1, c1});
    }
  }
  orient_positive(mesh);
  tag_by_normal(mesh, [](const Point& n) { return n.z() < -0.5 ? 1 : (n.z() > 0.5 ? 2 : 3); });
  return mesh;
}

TetMesh make_quarter_cylinder(double radius, double height, double element_size) {
  if (!(radius > 0.0 && height > 0.0 && element_size > 0.0))
    throw InputError("quarter cylinder mesh: radius, height and element_size must be > 0");
  TetMesh mesh =
      make_box(Point::Zero(), Point(1.0, 1.0, height), as_ints(quarter_cylinder_cells(radius, height, element_size)));
  // (u, v) ∈ [0,1]² → (R u sqrt(1 − v²/2), R v sqrt(1 − u²/2)): u = 1 and v = 1
  // land on the arc x² + y² = R², u = 0 on x = 0, v = 0 on y = 0.
  for (Point& p : mesh.nodes) {
    const double u = p.x(), v = p.y();
    p.x() = radius * u * std::sqrt(1.0 - 0.5 * v * v);
    p.y() = radius * v * std::sqrt(1.0 - 0.5 * u * u);
  }
  for (int& tag : mesh.boundary_tags)
    if (tag == 4) tag = 2; // both mapped sides are the lateral surface
  orient_positive(mesh);
  return mesh;
}

TetMesh make_quarter_ring(double outer_radius, double inner_radius, double height, double element_size) {
  if (!(outer_radius > inner_radius && inner_radius > 0.0 && height > 0.0 && element_size > 0.0))
    throw InputError("quarter ring mesh: need outer radius > inner radius > 0, height and element_size > 0");
  TetMesh mesh = make_box(Point::Zero(), Point(1.0, 1.0, height),
                          as_ints(quarter_ring_cells(outer_radius, inner_radius, height, element_size)));
  for (Point& p : mesh.nodes) {
    const double r = inner_radius + (outer_radius - inner_radius) * p.x(), angle = 0.5 * std::numbers::pi * p.y();
    p.x() = r * std::cos(angle);
    p.y() = r * std::sin(angle);
  }
  orient_positive(mesh);
  return mesh;
}

double box_node_count(const Point& size, double element_size) {
  return grid_nodes(box_cells(size, element_size));
}

double cylinder_node_count(double radius, double height, double element_size) {
  const auto [rings, layers] = cylinder_cells(radius, height, element_size);
  return (1.0 + 3.0 * rings * (rings + 1.0)) * (layers + 1.0); // the centre and 6k nodes on ring k, per layer
}

double quarter_cylinder_node_count(double radius, double height, double element_size) {
  return grid_nodes(quarter_cylinder_cells(radius, height, element_size));
}

double quarter_ring_node_count(double outer_radius, double inner_radius, double height, double element_size) {
  return grid_nodes(quarter_ring_cells(outer_radius, inner_radius, height, element_size));
}

} // namespace anvil::mesh

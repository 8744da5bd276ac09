#include "anvil/contact/die_fill.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/mesh/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anvil::contact {

PartSurface::PartSurface(const mesh::TetMesh& mesh)
    : mesh_(&mesh), search_(std::make_unique<SurfaceSearch>(mesh.nodes, mesh.boundary_faces)) {}

PartSurface::~PartSurface() = default;
PartSurface::PartSurface(PartSurface&&) noexcept = default;
PartSurface& PartSurface::operator=(PartSurface&&) noexcept = default;

PartSurface::Nearest PartSurface::nearest(const mesh::Point& x, const std::vector<int>& faces) const {
  // Inside the part when behind every face nearest to x: one face where the
  // nearest point is within it, all the faces sharing it at an edge or a
  // corner (at a convex edge a point outside is in front of one of its two
  // faces at least).
  double nearest = std::numeric_limits<double>::infinity();
  for (const int face : faces) {
    const mesh::Triangle& f = mesh_->boundary_faces[face];
    nearest = std::min(
        nearest,
        (x - mesh::nearest_on_triangle(x, mesh_->nodes[f[0]], mesh_->nodes[f[1]], mesh_->nodes[f[2]])).squaredNorm());
  }
  const double distance = std::sqrt(nearest);
  bool behind = false, in_front = false;
  for (const int face : faces) {
    const mesh::Triangle& f = mesh_->boundary_faces[face];
    const mesh::Point &a = mesh_->nodes[f[0]], &b = mesh_->nodes[f[1]], &c = mesh_->nodes[f[2]];
    const mesh::Point on = mesh::nearest_on_triangle(x, a, b, c);
    if ((x - on).norm() > distance + 1e-9 * (b - a).norm()) continue; // not a nearest face
    ((x - on).dot((b - a).cross(c - a)) >= 0.0 ? in_front : behind) = true;
  }
  return {distance, behind && !in_front};
}

double PartSurface::distance(const mesh::Point& x) const {
  const double reach = (x - search_->closest(x).point).norm();
  const double half = reach * (1.0 + 1e-9) + 1e-12;
  search_->overlapping(Eigen::AlignedBox3d(x.array() - half, x.array() + half), around_);
  const Nearest n = nearest(x, around_);
  return n.inside ? 0.0 : n.distance;
}

bool PartSurface::within(const mesh::Point& x, double tolerance, double reach) const {
  const double half = std::max(tolerance, reach);
  search_->overlapping(Eigen::AlignedBox3d(x.array() - half, x.array() + half), around_);
  if (around_.empty()) return false;
  const Nearest n = nearest(x, around_);
  return n.inside ? n.distance <= half : n.distance <= tolerance;
}

DieFill measure_die_fill(const die::SurfaceTriangles& die, const Eigen::Vector3d& displacement,
                         const FillRegion& region, const Eigen::AlignedBox3d& model_side, const PartSurface& part,
                         double tolerance, double spacing, bool with_underfill) {
  DieFill fill;
  for (const std::array<int, 3>& f : die.faces) {
    const mesh::Point& a = die.vertices[f[0]];
    const Eigen::Vector3d u = die.vertices[f[1]] - a, v = die.vertices[f[2]] - a;
    const double longest = std::max({u.norm(), v.norm(), (v - u).norm()});
    const int n = std::max(1, static_cast<int>(std::ceil(longest / spacing)));
    // n² sub-triangles of area A/n²: (i, j) and, but on the last row, its
    // flipped twin; each measured at its centroid.
    const double piece = 0.5 * u.cross(v).norm() / (n * n);
    auto measure = [&](double s, double t) {
      const mesh::Point x = a + (s / n) * u + (t / n) * v;
      if (!region.contains(x) || !model_side.contains(x + displacement)) return;
      fill.region_area += piece;
      if (part.within(x + displacement, tolerance, spacing)) fill.contact_area += piece;
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        measure(i + 1.0 / 3.0, j + 1.0 / 3.0);
        if (i + j < n - 1) measure(i + 2.0 / 3.0, j + 2.0 / 3.0);
      }
  }
  if (with_underfill)
    for (const mesh::Point& x : die.vertices) {
      mesh::Point mirrored = x + displacement;
      for (int k = 0; k < 3; ++k)
        if (mirrored[k] < model_side.min()[k])
          mirrored[k] = 2.0 * model_side.min()[k] - mirrored[k];
        else if (mirrored[k] > model_side.max()[k])
          mirrored[k] = 2.0 * model_side.max()[k] - mirrored[k];
      fill.underfill.push_back(part.distance(mirrored));
    }
  return fill;
}

} // namespace anvil::contact

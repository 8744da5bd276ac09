#include "anvil/contact/die_fill.h"

#include "anvil/contact/SurfaceSearch.h"
#include "anvil/core/processes.h"
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
  // The faces nearest to x are those that hold its closest point: the faces
  // around that point, not all those within the distance of x (hundreds, for
  // a die vertex far from the part).
  const mesh::Point closest = search_->closest(x).point;
  const double half = 1e-9 * (1.0 + closest.norm());
  search_->overlapping(Eigen::AlignedBox3d(closest.array() - half, closest.array() + half), around_);
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

FillSamples fill_samples(const die::SurfaceTriangles& die, const FillRegion& region, double spacing) {
  const die::SurfaceTriangles pieces = die::refine(die, spacing);
  FillSamples samples;
  for (const std::array<int, 3>& f : pieces.faces) {
    const mesh::Point &a = pieces.vertices[f[0]], &b = pieces.vertices[f[1]], &c = pieces.vertices[f[2]];
    const mesh::Point centroid = (a + b + c) / 3.0;
    if (!region.contains(centroid)) continue;
    samples.points.push_back(centroid);
    samples.areas.push_back(0.5 * (b - a).cross(c - a).norm());
  }
  return samples;
}

DieFill measure_die_fill(const FillSamples& samples, const die::SurfaceTriangles& die,
                         const Eigen::Vector3d& displacement, const Eigen::AlignedBox3d& model_side,
                         const PartSurface& part, double tolerance, double reach, bool with_underfill) {
  DieFill fill;
  // Per sample: its area on the model's side, and of that the area touching the part.
  const int count = static_cast<int>(samples.points.size());
  const std::vector<double> areas = processes::share_out(count, 2, [&](int k, double* area) {
    const mesh::Point x = samples.points[k] + displacement;
    if (!model_side.contains(x)) return;
    area[0] = samples.areas[k];
    if (part.within(x, tolerance, reach)) area[1] = samples.areas[k];
  });
  for (int k = 0; k < count; ++k) {
    fill.region_area += areas[2 * k];
    fill.contact_area += areas[2 * k + 1];
  }
  if (with_underfill)
    fill.underfill = processes::share_out(static_cast<int>(die.vertices.size()), 1, [&](int vertex, double* distance) {
      mesh::Point mirrored = die.vertices[vertex] + displacement;
      for (int k = 0; k < 3; ++k)
        if (mirrored[k] < model_side.min()[k])
          mirrored[k] = 2.0 * model_side.min()[k] - mirrored[k];
        else if (mirrored[k] > model_side.max()[k])
          mirrored[k] = 2.0 * model_side.max()[k] - mirrored[k];
      *distance = part.distance(mirrored);
    });
  return fill;
}

} // namespace anvil::contact

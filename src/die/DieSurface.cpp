#include "anvil/die/DieSurface.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace anvil::die {

mesh::Point project_keeping(const DieSurface& surface, mesh::Point x, const std::array<bool, 3>& free,
                            double tolerance) {
  for (int pass = 0; pass < 20; ++pass) {
    const mesh::Point closest = surface.project(x).point;
    double moved = 0.0;
    for (int k = 0; k < 3; ++k)
      if (free[k]) moved = std::max(moved, std::abs(closest[k] - x[k])), x[k] = closest[k];
    if (moved <= tolerance) break;
  }
  return x;
}

SurfaceTriangles refine(const SurfaceTriangles& surface, double longest_edge) {
  // Longest-edge bisection: a long thin triangle (an STL's fan of a flat
  // annulus) is cut across its long side only.
  SurfaceTriangles out{surface.vertices, {}};
  std::map<std::pair<int, int>, int> midpoints; // by edge, so neighbours cutting an edge share its midpoint
  const auto midpoint = [&](int a, int b) {
    const auto [at, added] = midpoints.try_emplace(std::minmax(a, b), static_cast<int>(out.vertices.size()));
    if (added) out.vertices.push_back(0.5 * (out.vertices[a] + out.vertices[b]));
    return at->second;
  };
  std::vector<std::array<int, 3>> pending(surface.faces.rbegin(), surface.faces.rend());
  while (!pending.empty()) {
    const std::array<int, 3> f = pending.back();
    pending.pop_back();
    int longest = 0;
    double length = 0.0;
    for (int k = 0; k < 3; ++k)
      if (const double l = (out.vertices[f[(k + 1) % 3]] - out.vertices[f[k]]).norm(); l > length)
        length = l, longest = k;
    if (length <= longest_edge) {
      out.faces.push_back(f);
      continue;
    }
    const int a = f[longest], b = f[(longest + 1) % 3], c = f[(longest + 2) % 3], m = midpoint(a, b);
    pending.push_back({m, b, c});
    pending.push_back({a, m, c});
  }
  return out;
}

PlaneSurface::PlaneSurface(const mesh::Point& point, const Eigen::Vector3d& normal, double half_size)
    : point_(point), normal_(normal.normalized()) {
  // Two in-plane unit vectors for the display square.
  const Eigen::Vector3d helper = std::abs(normal_.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = normal_.cross(helper).normalized(), w = normal_.cross(u);
  for (int corner = 0; corner < 4; ++corner) {
    const double a = (corner == 0 || corner == 3) ? -1.0 : 1.0, b = corner < 2 ? -1.0 : 1.0;
    triangles_.vertices.push_back(point_ + half_size * (a * u + b * w));
  }
  triangles_.faces = {{0, 1, 2}, {0, 2, 3}};
}

SurfaceProjection PlaneSurface::project(const mesh::Point& x) const {
  const double distance = (x - point_).dot(normal_);
  return {x - distance * normal_, normal_, distance};
}

std::string PlaneSurface::describe() const {
  char text[200];
  std::snprintf(text, sizeof text, "plane through (%g, %g, %g) mm, normal (%g, %g, %g)", point_.x(), point_.y(),
                point_.z(), normal_.x(), normal_.y(), normal_.z());
  return text;
}

} // namespace anvil::die

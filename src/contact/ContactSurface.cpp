#include "anvil/contact/ContactSurface.h"

#include "anvil/contact/facet_quadrature.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace anvil::contact {
namespace {

/// Barycentric coordinates of the projection of `q` onto the plane of triangle abc.
Eigen::Vector3d plane_barycentric(const mesh::Point& q, const mesh::Point& a, const mesh::Point& b,
                                  const mesh::Point& c) {
  const Eigen::Vector3d e0 = b - a, e1 = c - a, r = q - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = r.dot(e0), d21 = r.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  Eigen::Vector3d l;
  l[1] = (d11 * d20 - d01 * d21) / det;
  l[2] = (d00 * d21 - d01 * d20) / det;
  l[0] = 1.0 - l[1] - l[2];
  return l;
}

/// Barycentric coordinates of `q` (on or near the plane of triangle f), clamped to the triangle.
Eigen::Vector3d barycentric(const mesh::Point& q, const mesh::TetMesh& mesh, const mesh::Triangle& f) {
  const Eigen::Vector3d l = plane_barycentric(q, mesh.nodes[f[0]], mesh.nodes[f[1]], mesh.nodes[f[2]]).cwiseMax(0.0);
  return l / l.sum();
}

/// The point of triangle f with barycentric coordinates `shape`.
mesh::Point point_on(const mesh::TetMesh& mesh, const mesh::Triangle& f, const Eigen::Vector3d& shape) {
  return shape[0] * mesh.nodes[f[0]] + shape[1] * mesh.nodes[f[1]] + shape[2] * mesh.nodes[f[2]];
}

/// A face looks at the other body when its outward normal opposes the
/// other body's normal by more than about 70° (not the sides of a block,
/// whose edge nodes would otherwise weigh double).
bool looks_at(const Eigen::Vector3d& face_area_vector, const Eigen::Vector3d& other_normal) {
  return face_area_vector.dot(other_normal) < -0.3 * face_area_vector.norm();
}

/// `p` for the point x, its gap snapped to zero within round-off; nothing
/// when it lies `search_distance` or more from the surface.
std::optional<SurfaceProjection> within_reach(SurfaceProjection p, const mesh::Point& x, double search_distance) {
  // Touching to round-off is touching: a quadrature point interpolated
  // between nodes on the other body's plane lies off it by 1e-16, and a
  // static case has no speed to set an active-set tolerance from.
  if (std::abs(p.gap) <= 1e-12 * (1.0 + x.norm())) p.gap = 0.0;
  // Deeper than the reach is not a penetration of this increment: the
  // point lies behind the other body's edge (a block's top corner over
  // the side of the block below), where the side test is ambiguous.
  if (std::abs(p.gap) >= search_distance) return std::nullopt;
  return p;
}

std::vector<int> surface_facets(const ContactBoundary& boundary, const mesh::MeshRange& body) {
  std::vector<int> list;
  for (int f = body.first_face; f < body.first_face + body.face_count; ++f)
    if (!boundary.on_symmetry_plane(f)) list.push_back(f);
  return list;
}

std::vector<mesh::Triangle> triangles(const mesh::TetMesh& mesh, const std::vector<int>& faces) {
  std::vector<mesh::Triangle> list;
  for (int f : faces)
    list.push_back(mesh.boundary_faces[f]);
  return list;
}

} // namespace

ContactBoundary::ContactBoundary(const mesh::TetMesh& mesh, const std::vector<char>& symmetry_faces)
    : mesh_(mesh), symmetry_faces_(symmetry_faces), node_faces_(mesh.nodes.size()) {
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    for (int node : mesh.boundary_faces[f])
      node_faces_[node].push_back(static_cast<int>(f));
}

Eigen::Vector3d ContactBoundary::own_normal(int node) const {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int f : node_faces_[node])
    if (!on_symmetry_plane(f)) n += mesh::area_vector(mesh_, mesh_.boundary_faces[f]);
  return n.isZero() ? n : n.normalized();
}

double ContactBoundary::tributary_area(int node, const Eigen::Vector3d& other_normal) const {
  double area = 0.0;
  for (int f : node_faces_[node])
    if (const Eigen::Vector3d n = mesh::area_vector(mesh_, mesh_.boundary_faces[f]);
        !on_symmetry_plane(f) && looks_at(n, other_normal))
      area += n.norm() / 3.0;
  return area;
}

ContactSurface::ContactSurface(const ContactBoundary& boundary, const mesh::MeshRange& body)
    : boundary_(boundary), body_(body), facets_(surface_facets(boundary, body)),
      search_(boundary.mesh().nodes, triangles(boundary.mesh(), facets_)) {}

bool ContactSurface::holds(int face) const {
  return face >= body_.first_face && face < body_.first_face + body_.face_count && !boundary_.on_symmetry_plane(face);
}

std::optional<SurfaceProjection> ContactSurface::project(const mesh::Point& x, const Eigen::Vector3d& own,
                                                         double search_distance) const {
  const mesh::TetMesh& mesh = boundary_.mesh();
  const SurfaceSearch::Closest hit = search_.closest(x);
  // On an edge or a vertex several facets hold the closest point (to a
  // hair: two blocks sharing a symmetry plane meet there to round-off);
  // the one that faces the point's own surface best gives the normal and
  // the side (a point on the rim of a block lying on another must not
  // take the side face of the block below).
  const double hair = std::max(1e-9 * (1.0 + hit.point.norm()), 1e-3 * search_distance);
  int best = facets_[hit.face];
  double best_facing = mesh::area_vector(mesh, mesh.boundary_faces[best]).normalized().dot(own);
  for (int vertex : mesh.boundary_faces[best])
    for (int f : boundary_.faces_of(vertex)) {
      if (!holds(f)) continue;
      const mesh::Triangle& t = mesh.boundary_faces[f];
      const double facing = mesh::area_vector(mesh, t).normalized().dot(own);
      if (facing < best_facing && (point_on(mesh, t, barycentric(hit.point, mesh, t)) - hit.point).norm() <= hair)
        best = f, best_facing = facing;
    }
  const mesh::Triangle& facet = mesh.boundary_faces[best];
  const Eigen::Vector3d facet_normal = mesh::area_vector(mesh, facet).normalized();
  // Inside a facet (or off its edge by a hair: bodies pressed together
  // widen alike, to round-off) the offset is along its normal; off an
  // edge or a vertex the offset direction is the surface normal there.
  // The side comes from the facet.
  const Eigen::Vector3d shape = barycentric(x, mesh, facet);
  const Eigen::Vector3d offset = x - point_on(mesh, facet, shape);
  const double along_normal = offset.dot(facet_normal);
  const double lateral = (offset - along_normal * facet_normal).norm();
  const bool over_facet = lateral <= hair;
  const double side = along_normal >= 0.0 ? 1.0 : -1.0;
  return within_reach({best, shape, over_facet ? facet_normal : Eigen::Vector3d(side * offset / offset.norm()),
                       over_facet ? along_normal : side * offset.norm()},
                      x, search_distance);
}

std::optional<SurfaceProjection> ContactSurface::project_onto(const mesh::Point& x, int facet,
                                                              double search_distance) const {
  const mesh::TetMesh& mesh = boundary_.mesh();
  const mesh::Triangle& t = mesh.boundary_faces[facet];
  const Eigen::Vector3d normal = mesh::area_vector(mesh, t).normalized();
  const Eigen::Vector3d shape = barycentric(x, mesh, t);
  return within_reach({facet, shape, normal, (x - point_on(mesh, t, shape)).dot(normal)}, x, search_distance);
}

std::optional<SurfaceProjection> ContactSurface::project_self(int node, double search_distance) const {
  const mesh::TetMesh& mesh = boundary_.mesh();
  const mesh::Point& x = mesh.nodes[node];
  search_.overlapping({x - Eigen::Vector3d::Constant(search_distance), x + Eigen::Vector3d::Constant(search_distance)},
                      near_);
  std::optional<SurfaceProjection> best;
  double best_distance = search_distance;
  for (int index : near_) {
    const int facet = facets_[index];
    const mesh::Triangle& t = mesh.boundary_faces[facet];
    if (std::find(t.begin(), t.end(), node) != t.end()) continue;
    const Eigen::Vector3d normal = mesh::area_vector(mesh, t).normalized();
    const std::vector<int>& around = boundary_.faces_of(node);
    if (std::none_of(around.begin(), around.end(), [&](int f) {
          return holds(f) && mesh::area_vector(mesh, mesh.boundary_faces[f]).normalized().dot(normal) < -0.5;
        }))
      continue;
    const Eigen::Vector3d shape = barycentric(x, mesh, t);
    const Eigen::Vector3d offset = x - point_on(mesh, t, shape);
    const double gap = offset.dot(normal), distance = offset.norm();
    const double edge = ((mesh.nodes[t[1]] - mesh.nodes[t[0]]).norm() + (mesh.nodes[t[2]] - mesh.nodes[t[1]]).norm() +
                         (mesh.nodes[t[0]] - mesh.nodes[t[2]]).norm()) /
                        3.0;
    // Over the facet, or off its edge by a little where the surface it faces
    // is convex (off the edge of a facet facing the other way is off the surface).
    const bool over = (offset - gap * normal).norm() <= 0.1 * edge;
    if (!over || gap <= -0.1 * edge || distance >= best_distance) continue;
    best = SurfaceProjection{facet, shape, normal, gap};
    best_distance = distance;
  }
  if (best) return within_reach(*best, x, search_distance);
  return best;
}

void ContactSurface::facet_points(int f, const PairMethod& method, double search_distance,
                                  std::vector<FacetPoint>& points) const {
  points.clear();
  if (method.quadrature == FacetQuadrature::intersection)
    overlap_points(f, search_distance, points);
  else
    subdivision_points(f, method.facet_subdivision, search_distance, points);
}

void ContactSurface::overlap_points(int f, double search_distance, std::vector<FacetPoint>& points) const {
  const mesh::TetMesh& mesh = boundary_.mesh();
  const mesh::Triangle& t = mesh.boundary_faces[f];
  const Eigen::Vector3d area_vector = mesh::area_vector(mesh, t);
  const std::array<Eigen::Vector3d, 3> own{mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(search_distance);
  search_.overlapping(
      {own[0].cwiseMin(own[1]).cwiseMin(own[2]) - reach, own[0].cwiseMax(own[1]).cwiseMax(own[2]) + reach}, near_);
  for (int index : near_) {
    const int facet = facets_[index];
    const mesh::Triangle& other = mesh.boundary_faces[facet];
    if (!looks_at(area_vector, mesh::area_vector(mesh, other).normalized())) continue;
    const FacetOverlap o = overlap(own, {mesh.nodes[other[0]], mesh.nodes[other[1]], mesh.nodes[other[2]]});
    for (int i = 0; i < o.count; ++i)
      for (const FacetQuadraturePoint& g : degree_two_rule(o.parts[i], o.area_fraction[i]))
        if (const std::optional<SurfaceProjection> hit =
                project_onto(point_on(mesh, t, g.barycentric), facet, search_distance))
          points.push_back({g.barycentric, g.weight, *hit});
  }
}

void ContactSurface::subdivision_points(int f, int levels, double search_distance,
                                        std::vector<FacetPoint>& points) const {
  const mesh::TetMesh& mesh = boundary_.mesh();
  const mesh::Triangle& t = mesh.boundary_faces[f];
  const Eigen::Vector3d area_vector = mesh::area_vector(mesh, t);
  const Eigen::Vector3d own = area_vector.normalized();
  double longest = 0.0;
  for (int k = 0; k < 3; ++k)
    longest = std::max(longest, (mesh.nodes[t[k]] - mesh.nodes[t[(k + 1) % 3]]).norm());
  // Sub-triangle `c`, a fraction `area_fraction` of the facet with its
  // longest edge `size`, at subdivision `level` (facet_quadrature.h).
  auto integrate = [&](auto& self, const SubTriangle& c, int level, double area_fraction, double size) -> void {
    // A sub-triangle whose centroid is beyond the reach by more than its
    // longest edge has no point within reach.
    const std::optional<SurfaceProjection> centre =
        project(point_on(mesh, t, (c[0] + c[1] + c[2]) / 3.0), own, search_distance + size);
    if (!centre) return;
    const mesh::Triangle& other = mesh.boundary_faces[centre->facet];
    bool one_facet = true; // every corner projects into the centroid's facet
    for (const Eigen::Vector3d& corner : c)
      one_facet = one_facet && plane_barycentric(point_on(mesh, t, corner), mesh.nodes[other[0]], mesh.nodes[other[1]],
                                                 mesh.nodes[other[2]])
                                       .minCoeff() >= -1e-9;
    if (!one_facet && level < levels) {
      for (const SubTriangle& child : split(c))
        self(self, child, level + 1, area_fraction / 4.0, size / 2.0);
      return;
    }
    for (const FacetQuadraturePoint& g : degree_two_rule(c, area_fraction))
      if (const std::optional<SurfaceProjection> hit = project(point_on(mesh, t, g.barycentric), own, search_distance);
          hit && looks_at(area_vector, hit->normal))
        points.push_back({g.barycentric, g.weight, *hit});
  };
  integrate(integrate, whole_facet(), 0, 1.0, longest);
  // Grouped by the facet each point falls on, as the overlaps are.
  std::stable_sort(points.begin(), points.end(),
                   [](const FacetPoint& a, const FacetPoint& b) { return a.hit.facet < b.hit.facet; });
}

} // namespace anvil::contact

// STL die surfaces with CGAL: soup reading, repair, orientation, AABB tree
// closest-point search (docs/libraries.md §2). The only translation unit that sees
// CGAL; built in its own library so that -frounding-math stays here.
#include "anvil/die/StlSurface.h"

#include "anvil/core/error.h"
#include "anvil/core/input_file.h"
#include "anvil/core/log.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace anvil::die {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Vector3 = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

class TriangulatedSurface final : public DieSurface {
public:
  TriangulatedSurface(Mesh mesh, std::string description)
      : mesh_(std::move(mesh)), description_(std::move(description)) {
    for (auto v : mesh_.vertices()) {
      const Point3& p = mesh_.point(v);
      triangles_.vertices.emplace_back(p.x(), p.y(), p.z());
    }
    normals_.resize(mesh_.number_of_faces());
    for (auto f : mesh_.faces()) {
      std::array<int, 3> ids{};
      int k = 0;
      for (auto v : CGAL::vertices_around_face(mesh_.halfedge(f), mesh_))
        ids[k++] = static_cast<int>(v.idx());
      triangles_.faces.push_back(ids);
      const mesh::Point &a = triangles_.vertices[ids[0]], &b = triangles_.vertices[ids[1]],
                        &c = triangles_.vertices[ids[2]];
      normals_[f.idx()] = (b - a).cross(c - a).normalized();
    }
    tree_.insert(faces(mesh_).first, faces(mesh_).second, mesh_);
    tree_.build();
    tree_.accelerate_distance_queries();
  }

  SurfaceProjection project(const mesh::Point& x) const override {
    return projection(x, tree_.closest_point_and_primitive(Point3(x.x(), x.y(), x.z())));
  }

  SurfaceProjection project_near(const mesh::Point& x, const SurfaceProjection& near) const override {
    if (near.facet < 0) return project(x);
    const Tree::Point_and_primitive_id hint(Point3(near.point.x(), near.point.y(), near.point.z()),
                                            Mesh::Face_index(near.facet));
    return projection(x, tree_.closest_point_and_primitive(Point3(x.x(), x.y(), x.z()), hint));
  }

  std::optional<SurfaceProjection> project_within(const mesh::Point& x, double reach) const override {
    // CGAL's search keeps its best point so far and visits only the boxes
    // closer than it: started from a point at distance `reach` that no
    // facet owns, it looks inside that ball alone, and gives the start back
    // when no facet is closer.
    const Point3 query(x.x(), x.y(), x.z()), start(x.x() + reach, x.y(), x.z());
    const Tree::Point_and_primitive_id found = tree_.closest_point_and_primitive(query, {start, *faces(mesh_).first});
    if (found.first == start) return std::nullopt;
    return projection(x, found);
  }

  const SurfaceTriangles& triangles() const override { return triangles_; }
  std::string describe() const override { return description_; }

private:
  /// The projection of x whose closest point and facet the tree found.
  SurfaceProjection projection(const mesh::Point& x, const Tree::Point_and_primitive_id& found) const {
    const auto& [closest, face] = found;
    const mesh::Point point(closest.x(), closest.y(), closest.z());
    const Eigen::Vector3d& facet_normal = normals_[face.idx()];
    const Eigen::Vector3d offset = x - point;
    const double distance = offset.norm();
    // Inside a facet the offset is along its normal; on an edge or a vertex it
    // is not, and the offset direction is the normal of the surface there.
    // The side (sign) comes from the facet the closest point belongs to.
    const double side = offset.dot(facet_normal) >= 0.0 ? 1.0 : -1.0;
    const int facet = static_cast<int>(face.idx());
    if (distance < 1e-12 * (1.0 + x.norm())) return {point, facet_normal, 0.0, true, facet};
    const bool on_facet = std::abs(offset.dot(facet_normal)) >= (1.0 - 1e-9) * distance;
    return {point, side * offset / distance, side * distance, on_facet, facet};
  }

  Mesh mesh_;
  Tree tree_;
  std::vector<Eigen::Vector3d> normals_;
  SurfaceTriangles triangles_;
  std::string description_;
};

/// Refuses a vertex that is not a finite number, read from the file's own
/// numbers: CGAL's reader merges vertices through comparisons that NaN
/// breaks, so after it a NaN vertex may sit anywhere.
void check_finite_vertices(const std::string& path, const std::string& at) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto refuse = [&](const std::string& where, const std::string& value) {
    throw InputError(at + ": " + where + ": vertex coordinate '" + value + "' is not a finite number");
  };
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) { // binary: 50 bytes a facet
      for (std::size_t f = 0; f < count; ++f)
        for (int k = 3; k < 12; ++k) { // the normal (floats 0-2) is not used
          float value = 0.0f;
          std::memcpy(&value, bytes.data() + 84 + 50 * f + 4 * k, 4);
          if (!std::isfinite(value))
            refuse("facet " + std::to_string(f + 1) + ", vertex " + std::to_string(k / 3), std::to_string(value));
        }
      return;
    }
  }
  std::istringstream text(bytes);
  int line_number = 0;
  for (std::string line; std::getline(text, line);) {
    ++line_number;
    std::istringstream words(line);
    std::string word;
    if (!(words >> word) || word != "vertex") continue;
    for (int c = 0; c < 3 && words >> word; ++c) {
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(value))
        refuse("line " + std::to_string(line_number), word);
    }
  }
}

} // namespace

std::unique_ptr<DieSurface> read_stl_surface(const std::string& path, const std::string& source,
                                             const Eigen::Vector3d& offset) {
  const std::string at = source + ": STL die '" + path + "'";
  if (const std::string problem = input_file_problem(path, kMaxStlBytes); !problem.empty())
    throw InputError(at + ": " + problem);
  check_finite_vertices(path, at);
  std::vector<Point3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  if (!CGAL::IO::read_polygon_soup(path, points, triangles) || triangles.empty())
    throw InputError(at + ": not a readable STL surface (ASCII or binary) with at least one facet");
  for (std::size_t v = 0; v < points.size(); ++v)
    if (!std::isfinite(points[v].x()) || !std::isfinite(points[v].y()) || !std::isfinite(points[v].z()))
      throw InputError(at + ": vertex " + std::to_string(v + 1) + " is not a finite number (" +
                       std::to_string(points[v].x()) + ", " + std::to_string(points[v].y()) + ", " +
                       std::to_string(points[v].z()) + ")");
  const Vector3 shift(offset.x(), offset.y(), offset.z());
  for (Point3& p : points)
    p = p + shift;
  const std::size_t read = triangles.size();
  // Degenerate (zero-area, repeated-vertex) and duplicate facets are dropped and reported.
  std::vector<std::array<std::size_t, 3>> kept;
  for (const auto& t : triangles)
    if (!CGAL::collinear(points[t[0]], points[t[1]], points[t[2]])) kept.push_back(t);
  const std::size_t degenerate = read - kept.size();
  triangles.swap(kept);
  PMP::repair_polygon_soup(points, triangles);
  if (triangles.empty()) throw InputError(at + ": every facet is degenerate");
  if (degenerate > 0 || triangles.size() + degenerate != read)
    log::info("  %s: %zu degenerate and %zu duplicate facets dropped", at.c_str(), degenerate,
              read - degenerate - triangles.size());
  // Consistent orientation; remember how many facets it had to flip, to keep
  // the file's sense for open surfaces.
  const auto before = triangles;
  if (!PMP::orient_polygon_soup(points, triangles))
    log::info("  %s: non-manifold vertices were duplicated to orient the surface", at.c_str());
  std::size_t flipped = 0;
  for (std::size_t i = 0; i < std::min(before.size(), triangles.size()); ++i)
    flipped += before[i] != triangles[i];
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  if (!CGAL::is_triangle_mesh(mesh) || mesh.number_of_faces() == 0)
    throw InputError(at + ": the facets do not form a triangle surface");
  const bool closed = CGAL::is_closed(mesh);
  std::string orientation;
  if (closed) {
    if (!PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
    orientation = "closed, oriented outwards";
  } else {
    if (2 * flipped > triangles.size()) PMP::reverse_face_orientations(mesh);
    orientation = "open, normals as in the file (" + std::to_string(std::min(flipped, triangles.size() - flipped)) +
                  " facets re-oriented to agree)";
  }
  char text[400];
  std::snprintf(text, sizeof text, "STL %s: %zu facets, %zu vertices, %s",
                std::filesystem::path(path).filename().c_str(), static_cast<std::size_t>(mesh.number_of_faces()),
                static_cast<std::size_t>(mesh.number_of_vertices()), orientation.c_str());
  return std::make_unique<TriangulatedSurface>(std::move(mesh), text);
}

} // namespace anvil::die

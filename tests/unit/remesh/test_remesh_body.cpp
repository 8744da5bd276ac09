// remesh_body: a new mesh of the same volume, tags kept on flat faces.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/remesh_body.h"

#include <catch2/catch.hpp>

#include <set>

using namespace anvil;

namespace {
/// Tags present on the boundary of `m`.
std::set<int> tags_of(const mesh::TetMesh& m) { return {m.boundary_tags.begin(), m.boundary_tags.end()}; }
} // namespace

TEST_CASE("Remeshing a box keeps its volume, faces and tags", "[unit][remesh]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 2.0);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  const mesh::TetMesh out = remesh::remesh_body(box, settings);
  CHECK(out.tet_count() > 2 * box.tet_count()); // refined: h 2 → 1
  // Flat faces marked as patches: the volume is kept to round-off (TECH-NOTES probe: 1.000).
  CHECK(mesh::volume(out) == Approx(240.0).epsilon(1e-9));
  CHECK(tags_of(out) == std::set<int>{1, 2, 3, 4, 5, 6});
  // Every face keeps its tag: its nodes lie on the plane the tag names.
  for (std::size_t f = 0; f < out.boundary_faces.size(); ++f) {
    const int tag = out.boundary_tags[f];
    const int axis = (tag - 1) / 2;
    const double plane = tag % 2 == 1 ? 0.0 : std::array<double, 3>{10, 6, 4}[axis];
    for (int n : out.boundary_faces[f]) CHECK(out.nodes[n][axis] == Approx(plane).margin(1e-9));
  }
  CHECK(remesh::worst_quality(out) > 0.1);
}

TEST_CASE("Remeshing a quarter cylinder keeps its volume and its lateral surface", "[unit][remesh]") {
  const double radius = 10.0, h_old = 1.5;
  const mesh::TetMesh body = mesh::make_quarter_cylinder(radius, 15.0, h_old);
  remesh::RemeshSettings settings;
  settings.edge_length = 1.0;
  const mesh::TetMesh out = remesh::remesh_body(body, settings);
  // The lateral nodes are shifted along their normal to restore the volume.
  CHECK(mesh::volume(out) == Approx(mesh::volume(body)).epsilon(1e-9));
  CHECK(tags_of(out) == tags_of(body));
  // ... by about the chord error of the facets, so they stay on the cylinder
  // to within the sagitta of the old facets, h²/8R = 0.028 mm.
  const double sagitta = h_old * h_old / (8.0 * radius);
  for (std::size_t f = 0; f < out.boundary_faces.size(); ++f)
    if (out.boundary_tags[f] == 2)
      for (int n : out.boundary_faces[f]) CHECK(out.nodes[n].head<2>().norm() == Approx(radius).margin(sagitta));
}

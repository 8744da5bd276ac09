#include "test_common.h"

#include "anvil/core/error.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/mesh_io.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace anvil;

namespace {

int faces_with_tag(const mesh::TetMesh& m, int tag) {
  return static_cast<int>(std::count(m.boundary_tags.begin(), m.boundary_tags.end(), tag));
}

/// Boundary faces must be oriented outwards: Σ (centroid · area normal)/3 = volume (divergence theorem).
double volume_from_boundary(const mesh::TetMesh& m) {
  double v = 0.0;
  for (const auto& f : m.boundary_faces) {
    const mesh::Point &a = m.nodes[f[0]], &b = m.nodes[f[1]], &c = m.nodes[f[2]];
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

std::string error_of(const std::string& file) {
  try {
    mesh::read_mesh(source_path("tests/data/" + file));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("the three readers give the same two-tet mesh with its tags", "[unit]") {
  for (const char* file : {"two_tets_v22.msh", "two_tets_v41.msh", "two_tets.mesh"}) {
    INFO(file);
    const mesh::TetMesh m = mesh::read_mesh(source_path(std::string("tests/data/") + file));
    CHECK(m.node_count() == 5);
    CHECK(m.tet_count() == 2);
    CHECK(m.boundary_faces.size() == 6);
    CHECK(faces_with_tag(m, 7) == 1);
    CHECK(mesh::volume(m) == Approx(1.0 / 6.0 + 1.0 / 3.0)); // det 1 and det 2
    CHECK(volume_from_boundary(m) == Approx(mesh::volume(m)));
  }
}

TEST_CASE("bad meshes are rejected naming file and element or node", "[unit]") {
  CHECK_THAT(error_of("inverted.mesh"),
             Catch::Contains("inverted.mesh") && Catch::Contains("tetrahedron 2 is inverted"));
  CHECK_THAT(error_of("unreferenced.mesh"), Catch::Contains("node 5 is not used"));
  CHECK_THAT(error_of("bad_index.msh"), Catch::Contains("tetrahedron 1 refers to node 9"));
  CHECK_THAT(error_of("missing.msh"), Catch::Contains("cannot open"));
}

TEST_CASE("box generator: volume, tags, orientation", "[unit]") {
  const mesh::TetMesh m = mesh::make_box(mesh::Point(1, 2, 3), mesh::Point(4, 2, 1), 0.5);
  mesh::validate(m, "box");
  CHECK(mesh::volume(m) == Approx(8.0).epsilon(1e-12));
  CHECK(volume_from_boundary(m) == Approx(8.0).epsilon(1e-12));
  for (int tag = 1; tag <= 6; ++tag)
    CHECK(faces_with_tag(m, tag) > 0);
  CHECK(faces_with_tag(m, 0) == 0);
}

TEST_CASE("cylinder generator: conforming, positive, near the exact volume", "[unit]") {
  const double radius = 10.0, height = 5.0;
  const mesh::TetMesh m = mesh::make_cylinder(radius, height, 1.0);
  mesh::validate(m, "cylinder");
  // Conforming: the boundary has the area of the polygonal cylinder only (no
  // internal faces used once). Volume: inscribed polygons, error O(h²/R²).
  const double exact = std::numbers::pi * radius * radius * height;
  CHECK(std::abs(mesh::volume(m) - exact) / exact < 0.01);
  CHECK(volume_from_boundary(m) == Approx(mesh::volume(m)).epsilon(1e-12));
  double worst = 1.0;
  for (int e = 0; e < m.tet_count(); ++e)
    worst = std::min(worst, mesh::quality(m, e));
  CHECK(worst > 0.2); // ring meshes stay well shaped (observed ~0.5)
  for (int tag = 1; tag <= 3; ++tag)
    CHECK(faces_with_tag(m, tag) > 0);
}

TEST_CASE("inner faces: each face two tets share, once, with both tets", "[unit]") {
  // A box's faces: 4 per tet, each inner one counted by two tets, each
  // boundary one by one.
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {3, 2, 2}, 1.0);
  const std::vector<mesh::InnerFace> inner = mesh::inner_faces(box);
  CHECK(2 * inner.size() + box.boundary_faces.size() == 4 * box.tets.size());
  for (const mesh::InnerFace& f : inner)
    for (int e : f.tets) {
      mesh::Tet t = box.tets[e];
      CHECK(std::all_of(f.face.begin(), f.face.end(),
                        [&](int v) { return std::find(t.begin(), t.end(), v) != t.end(); }));
    }
  CHECK(inner.front().tets[0] != inner.front().tets[1]);
}

TEST_CASE("connected parts: each body of an appended mesh is one part, numbered by its first node", "[unit]") {
  // Three boxes appended, the second touching the first along a face (its
  // nodes coincide with the first's, but no tet joins them): three parts.
  mesh::TetMesh scene = mesh::make_box({0, 0, 0}, {1, 1, 1}, 0.5);
  const mesh::MeshRange second = mesh::append(scene, mesh::make_box({0, 0, 1}, {1, 1, 2}, 0.5));
  const mesh::MeshRange third = mesh::append(scene, mesh::make_box({3, 0, 0}, {4, 1, 1}, 0.5));
  const std::vector<int> parts = mesh::connected_parts(scene);
  REQUIRE(parts.size() == scene.nodes.size());
  for (int v = 0; v < scene.node_count(); ++v)
    CHECK(parts[v] == (third.has_node(v) ? 2 : second.has_node(v) ? 1 : 0));
  // A tet joining the first and third boxes makes them one part, numbered 0;
  // the second box becomes part 1.
  scene.tets.push_back({0, 1, 2, third.first_node});
  const std::vector<int> joined = mesh::connected_parts(scene);
  for (int v = 0; v < scene.node_count(); ++v)
    CHECK(joined[v] == (second.has_node(v) ? 1 : 0));
}

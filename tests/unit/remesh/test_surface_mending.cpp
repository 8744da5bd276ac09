// Surface mending (remesh/surface_mending.h): poor elements held by the
// surface mended by surface edge flips and collapses, the other nodes
// where they were.
#include "test_common.h"

#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/surface_mending.h"

#include <algorithm>
#include <map>

using namespace anvil;

namespace {

/// The boundary of `m` as build_boundary finds it from the tets: sorted
/// vertices -> (outward face, tag).
std::map<std::array<int, 3>, std::pair<mesh::Triangle, int>> boundary_of(const mesh::TetMesh& m) {
  mesh::TetMesh again = m;
  mesh::build_boundary(again, m.boundary_faces, m.boundary_tags);
  std::map<std::array<int, 3>, std::pair<mesh::Triangle, int>> faces;
  for (std::size_t f = 0; f < again.boundary_faces.size(); ++f) {
    std::array<int, 3> key = again.boundary_faces[f];
    std::sort(key.begin(), key.end());
    faces[key] = {again.boundary_faces[f], again.boundary_tags[f]};
  }
  return faces;
}

/// Whether m's own boundary faces are exactly those of its tets, outward,
/// each with its tag.
void check_boundary(const mesh::TetMesh& m) {
  const auto expected = boundary_of(m);
  REQUIRE(m.boundary_faces.size() == expected.size());
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
    std::array<int, 3> key = m.boundary_faces[f];
    std::sort(key.begin(), key.end());
    const auto it = expected.find(key);
    REQUIRE(it != expected.end());
    // The same outward normal: the same cyclic order.
    CHECK(mesh::area_vector(m, m.boundary_faces[f]).dot(mesh::area_vector(m, it->second.first)) > 0.0);
  }
}

} // namespace

TEST_CASE("A skinny surface triangle is mended by flipping its long edge, the nodes unmoved", "[unit][remesh]") {
  // Two tets under the plane z = 0 share edge ab; their top faces abc (c
  // 0.05 mm from ab, a skinny triangle) and abd lie in the plane. Flipping ab
  // to cd keeps the four nodes and the volume (the plane is flat).
  mesh::TetMesh m;
  m.nodes = {{-1, 0, 0}, {1, 0, 0}, {0, 0.05, 0}, {0, -1.5, 0}, {0, -0.5, -1}};
  m.tets = {{0, 1, 2, 4}, {1, 0, 3, 4}};
  for (int e = 0; e < m.tet_count(); ++e)
    if (mesh::signed_volume(m, e) < 0.0) std::swap(m.tets[e][0], m.tets[e][1]);
  mesh::build_boundary(m);
  std::fill(m.boundary_tags.begin(), m.boundary_tags.end(), 5);
  const mesh::TetMesh before = m;
  std::vector<double> strain{1.0, 3.0};
  const double worst = remesh::worst_quality(m);
  REQUIRE(worst < 0.15);

  const remesh::SurfaceMending mended = remesh::mend_surface(m, {&strain}, 0.15, 20.0);
  CHECK(mended.flips == 1);
  CHECK(mended.collapses == 0);
  CHECK(mesh::fault(m).empty());
  CHECK(remesh::worst_quality(m) > worst);
  CHECK(m.nodes == before.nodes);
  CHECK(std::abs(mended.volume_change) < 1e-12);
  check_boundary(m);
  for (int tag : m.boundary_tags)
    CHECK(tag == 5);
  // The new elements take ε̄ by the transfer of every remesh: within the
  // old range, the peak kept.
  REQUIRE(strain.size() == m.tets.size());
  CHECK(*std::max_element(strain.begin(), strain.end()) == 3.0);
  CHECK(*std::min_element(strain.begin(), strain.end()) >= 1.0);
}

TEST_CASE("A short edge on a flat face of a box is mended, every other node where it was", "[unit][remesh]") {
  // A node inside the top face of a box moved along the face to 0.05 mm of
  // a neighbour: the elements on that short edge are poor and held by the
  // surface (their interior nodes cannot mend a needle triangle).
  mesh::TetMesh m = mesh::make_box({0, 0, 0}, {4, 4, 4}, {4, 4, 4});
  const auto on_top = [](const mesh::Point& x) { return x.z() == 4.0; };
  int u = -1, v = -1;
  for (int n = 0; n < m.node_count() && u < 0; ++n)
    if (m.nodes[n] == mesh::Point(2, 2, 4)) u = n;
  REQUIRE(u >= 0);
  for (const mesh::Tet& t : m.tets)
    if (std::count(t.begin(), t.end(), u))
      for (int w : t)
        if (w != u && on_top(m.nodes[w]) &&
            (v < 0 || (m.nodes[w] - m.nodes[u]).norm() < (m.nodes[v] - m.nodes[u]).norm()))
          v = w;
  REQUIRE(v >= 0);
  m.nodes[u] = m.nodes[v] + 0.05 * (m.nodes[u] - m.nodes[v]).normalized();
  const mesh::TetMesh before = m;
  std::vector<double> strain(m.tets.size(), 0.5);
  const double worst = remesh::worst_quality(m);
  REQUIRE(worst < 0.15);

  const remesh::SurfaceMending mended = remesh::mend_surface(m, {&strain}, 0.15, 20.0);
  CHECK(mended.collapses == 1); // a needle: no flip mends it
  CHECK(mesh::fault(m).empty());
  CHECK(remesh::worst_quality(m) > worst);
  CHECK(mended.worst_after > mended.worst_before);
  CHECK(std::abs(mended.volume_change) < 1e-12);
  CHECK(mesh::volume(m) == Approx(64.0).epsilon(1e-12));
  check_boundary(m);
  REQUIRE(strain.size() == m.tets.size());
  REQUIRE(mended.old_node.size() == m.nodes.size());
  REQUIRE(m.node_count() == before.node_count() - mended.collapses);
  for (int n = 0; n < m.node_count(); ++n)
    CHECK(m.nodes[n] == before.nodes[mended.old_node[n]]);
}

TEST_CASE("The surface is not mended across a crease", "[unit][remesh]") {
  // The same two tets with the skinny triangle folded down by 45° along ab:
  // a flip there would cut the crease off.
  mesh::TetMesh m;
  m.nodes = {{-1, 0, 0}, {1, 0, 0}, {0, 0.05, -0.05}, {0, -1.5, 0}, {0, -0.5, -1}};
  m.tets = {{0, 1, 2, 4}, {1, 0, 3, 4}};
  for (int e = 0; e < m.tet_count(); ++e)
    if (mesh::signed_volume(m, e) < 0.0) std::swap(m.tets[e][0], m.tets[e][1]);
  mesh::build_boundary(m);
  const mesh::TetMesh before = m;
  std::vector<double> strain{1.0, 3.0};
  REQUIRE(remesh::worst_quality(m) < 0.15);
  const remesh::SurfaceMending mended = remesh::mend_surface(m, {&strain}, 0.15, 20.0);
  CHECK(mended.flips + mended.collapses == 0);
  CHECK(m.tets == before.tets);
  CHECK(m.nodes == before.nodes);
}

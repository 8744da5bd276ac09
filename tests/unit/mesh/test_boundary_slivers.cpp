// peel_boundary_slivers: flat tets on the surface go where the surface stays
// a manifold, and nothing else changes.
#include "anvil/mesh/boundary_slivers.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace anvil;

namespace {

/// `t` with positive orientation (two vertices swapped when needed).
mesh::Tet oriented(const mesh::TetMesh& m, mesh::Tet t) {
  if (mesh::signed_volume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]) < 0.0) std::swap(t[2], t[3]);
  return t;
}

/// Two tets under a square of diagonal a-b (nodes 0, 1) and a sliver (tet
/// 2) on it whose corners c, d (nodes 2, 3) lie 1e-3 above a and b; every
/// boundary face tagged `tag`.
mesh::TetMesh sliver_on_two_tets(int tag) {
  mesh::TetMesh m;
  const double lift = 1e-3;
  m.nodes = {{0, 0, 0}, {1, 1, 0}, {1, 0, lift}, {0, 1, lift}, {0.5, 0.5, -1}}; // a b c d e
  m.tets = {oriented(m, {0, 2, 1, 4}), oriented(m, {0, 1, 3, 4}), oriented(m, {0, 1, 2, 3})};
  mesh::build_boundary(m);
  m.boundary_tags.assign(m.boundary_faces.size(), tag);
  return m;
}

/// Checks that every upward boundary face of `m` has tag `tag`; returns how many there are.
int top_faces_tagged(const mesh::TetMesh& m, int tag) {
  int top = 0;
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
    if (mesh::area_vector(m, m.boundary_faces[f]).z() <= 0.0) continue;
    CHECK(m.boundary_tags[f] == tag);
    ++top;
  }
  return top;
}

/// Puts on the first boundary face of `box` a cap of height 1e-3 whose apex
/// (the new last node) is in no other tet; returns the face.
mesh::Triangle add_cap(mesh::TetMesh& box) {
  const mesh::Triangle f = box.boundary_faces.front();
  const mesh::Point normal = mesh::area_vector(box, f).normalized();
  box.nodes.push_back((box.nodes[f[0]] + box.nodes[f[1]] + box.nodes[f[2]]) / 3.0 + 1e-3 * normal);
  box.tets.push_back(oriented(box, {f[0], f[1], f[2], box.node_count() - 1}));
  return f;
}

/// `box` with the cap of add_cap on it, its boundary rebuilt with the box's tags.
mesh::TetMesh capped(const mesh::TetMesh& box) {
  mesh::TetMesh out = box;
  add_cap(out);
  mesh::build_boundary(out, box.boundary_faces, box.boundary_tags);
  return out;
}

} // namespace

TEST_CASE("A flat tet with three faces on the surface goes with its apex node, and the box is as before",
          "[unit][mesh]") {
  const mesh::TetMesh before = mesh::make_box({0, 0, 0}, {2, 2, 2}, 1.0);
  mesh::TetMesh box = capped(before);
  const double q = mesh::quality(box, box.tet_count() - 1);
  REQUIRE(q < 0.01);

  CHECK(mesh::peel_boundary_slivers(box, q, 0.0) == 0); // not below the bound: kept
  CHECK(mesh::peel_boundary_slivers(box, 2.0 * q, 0.0) == 1);
  CHECK(box.nodes == before.nodes);
  CHECK(box.tets == before.tets);
  CHECK(box.boundary_faces.size() == before.boundary_faces.size());
  CHECK(mesh::volume(box) == Approx(mesh::volume(before)).epsilon(1e-14));
  CHECK(mesh::fault(box).empty());
}

TEST_CASE("A flat tet with two faces on the surface uncovers its other two, tagged as the faces it lost",
          "[unit][mesh]") {
  mesh::TetMesh m = sliver_on_two_tets(0);
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f)
    if (mesh::area_vector(m, m.boundary_faces[f]).z() > 0.0) m.boundary_tags[f] = 7; // the top
  REQUIRE(mesh::quality(m, 2) < 0.01);
  const double volume = mesh::volume(m), sliver = mesh::signed_volume(m, 2);

  CHECK(mesh::peel_boundary_slivers(m, 0.05, 0.0) == 1);
  REQUIRE(m.tet_count() == 2);
  CHECK(m.node_count() == 5);
  CHECK(mesh::fault(m).empty());
  CHECK(mesh::volume(m) == Approx(volume - sliver).epsilon(1e-14));
  REQUIRE(m.boundary_faces.size() == 6); // the four sides and the two uncovered top faces
  CHECK(top_faces_tagged(m, 7) == 2);
}

TEST_CASE("A flat tet whose removal would pinch the surface stays", "[unit][mesh]") {
  // The cap of the first test with a tall tet on its face f0 f1 p: the cap
  // keeps two faces on the surface, and taking it off would put the edge
  // f0 f1, already on the tall tet's surface, on four boundary faces.
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {2, 2, 2}, 1.0);
  const mesh::TetMesh before = box;
  const mesh::Triangle f = add_cap(box);
  const mesh::Point normal = mesh::area_vector(box, f).normalized();
  const int p = box.node_count() - 1;
  const mesh::Point apex = box.nodes[p];
  // A second tet on the apex: a tall one above the cap (not flat).
  box.nodes.push_back(apex + 0.5 * normal + 0.1 * (box.nodes[f[0]] - apex));
  box.tets.push_back(oriented(box, {f[0], f[1], p, box.node_count() - 1}));
  mesh::build_boundary(box, before.boundary_faces, before.boundary_tags);
  REQUIRE(mesh::fault(box).empty());
  const mesh::TetMesh capped = box;

  CHECK(mesh::peel_boundary_slivers(box, 0.05, 0.0) == 0);
  CHECK(box.tets == capped.tets);
}

TEST_CASE("An uncovered face takes no flat tag whose plane it is off", "[unit][mesh]") {
  // The sliver of the second test with one top face on a tag of its own
  // (one face: flat), the rest on a tag that is not: both uncovered faces,
  // off that plane, take the other tag, so the flat tag stays flat (the
  // remesher keeps a flat tag's nodes on its plane, a symmetry plane's
  // among them). Were both tags flat, the sliver would stay.
  mesh::TetMesh m = sliver_on_two_tets(7); // the sides too: 7 is not flat
  for (std::size_t f = m.boundary_faces.size(); f-- > 0;)
    if (mesh::area_vector(m, m.boundary_faces[f]).z() > 0.0) {
      m.boundary_tags[f] = 9;
      break;
    }

  CHECK(mesh::peel_boundary_slivers(m, 0.05, 0.0) == 1);
  CHECK(top_faces_tagged(m, 7) == 2);
}

TEST_CASE("An ear above the bound goes where it covers a poorer flat tet, which then goes too", "[unit][mesh]") {
  // The cap of the first test (flat, two faces on the surface once covered)
  // under an ear on its face f0 f1 p: the cap's inner faces share the box's
  // edge f0 f1, so it cannot go while the ear holds it, and the ear (three
  // faces on the surface around a node of its own) is above the bound.
  mesh::TetMesh box = mesh::make_box({0, 0, 0}, {2, 2, 2}, 1.0);
  const mesh::TetMesh before = box;
  const mesh::Triangle f = add_cap(box);
  const int p = box.node_count() - 1;
  const mesh::Point normal = mesh::area_vector(box, f).normalized();
  const mesh::Point middle = 0.5 * (box.nodes[f[0]] + box.nodes[f[1]]);
  const mesh::Point away = (middle - box.nodes[f[2]]).normalized();
  // The ear's apex above the edge f0 f1, leaning off the cap: the ear is fair, not flat.
  box.nodes.push_back(middle + 0.2 * away + 0.5 * normal);
  box.tets.push_back(oriented(box, {f[0], f[1], p, box.node_count() - 1}));
  mesh::build_boundary(box, before.boundary_faces, before.boundary_tags);
  REQUIRE(mesh::fault(box).empty());
  const double cap = mesh::quality(box, box.tet_count() - 2), ear = mesh::quality(box, box.tet_count() - 1);
  REQUIRE(cap < 0.05);
  REQUIRE(ear > 0.05);
  REQUIRE(ear < 0.5);
  const mesh::TetMesh capped = box;

  CHECK(mesh::peel_boundary_slivers(box, 0.05, ear) == 0); // the ear not below its bound: both stay
  CHECK(box.tets == capped.tets);
  CHECK(mesh::peel_boundary_slivers(box, 0.05, 0.5) == 2);
  CHECK(box.nodes == before.nodes);
  CHECK(box.tets == before.tets);
  CHECK(mesh::volume(box) == Approx(mesh::volume(before)).epsilon(1e-14));
  CHECK(mesh::fault(box).empty());
}

TEST_CASE("Frozen tets stay, first and in their order, and the nodes left are mapped to their numbers before",
          "[unit][mesh]") {
  // The cap of the first test, put first: frozen, it stays; put last
  // behind the frozen box, it goes with its apex node (the last), and
  // every node left keeps its number.
  const mesh::TetMesh before = mesh::make_box({0, 0, 0}, {2, 2, 2}, 1.0);
  mesh::TetMesh box = capped(before);
  mesh::TetMesh cap_first = box;
  std::rotate(cap_first.tets.begin(), cap_first.tets.end() - 1, cap_first.tets.end());
  const mesh::TetMesh capped = cap_first;
  std::vector<int> old_node;

  CHECK(mesh::peel_boundary_slivers(cap_first, 0.05, 0.0, 1, &old_node) == 0);
  CHECK(cap_first.tets == capped.tets);
  REQUIRE(old_node.size() == capped.nodes.size());
  for (int n = 0; n < capped.node_count(); ++n)
    CHECK(old_node[n] == n);

  CHECK(mesh::peel_boundary_slivers(box, 0.05, 0.0, before.tet_count(), &old_node) == 1);
  CHECK(box.tets == before.tets);
  REQUIRE(old_node.size() == before.nodes.size());
  for (int n = 0; n < before.node_count(); ++n)
    CHECK(old_node[n] == n);
}

// mend_flat_tets: a flat tet of four coplanar nodes goes with one
// of its edges, the tets before `first` and the boundary stay as they are.
#include "anvil/mesh/flat_tet_mending.h"
#include "anvil/mesh/tet_geometry.h"

#include <catch2/catch.hpp>

#include <set>

using namespace anvil;

namespace {

enum Node { a, b, c, d, p, q };

/// The double pyramid over the unit square abcd (apex p above, q below),
/// the top split along ac and the bottom along bd, the flat tet abcd
/// between them; the tets in the order `order` names (0-1 top, 2 the flat
/// tet, 3-4 bottom).
mesh::TetMesh double_pyramid(std::array<int, 5> order) {
  mesh::TetMesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}, {0.5, 0.5, -1}};
  const std::array<mesh::Tet, 5> tets{mesh::Tet{p, a, b, c}, mesh::Tet{p, a, c, d}, mesh::Tet{a, b, c, d},
                                      mesh::Tet{q, a, b, d}, mesh::Tet{q, b, c, d}};
  for (int k : order)
    m.tets.push_back(tets[k]);
  for (mesh::Tet& t : m.tets)
    if (mesh::signed_volume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]) < 0.0) std::swap(t[2], t[3]);
  mesh::build_boundary(m);
  return m;
}

std::set<std::array<int, 4>> as_sets(const std::vector<mesh::Tet>& tets) {
  std::set<std::array<int, 4>> out;
  for (mesh::Tet t : tets) {
    std::sort(t.begin(), t.end());
    out.insert(t);
  }
  return out;
}

std::set<mesh::Triangle> faces(const mesh::TetMesh& m) {
  std::set<mesh::Triangle> out;
  for (const mesh::Triangle& f : m.boundary_faces)
    out.insert(mesh::sorted(f));
  return out;
}

} // namespace

TEST_CASE("A flat tet between a top split along ac and a bottom split along bd goes by edge removal, no node added",
          "[unit][mesh]") {
  mesh::TetMesh m = double_pyramid({0, 1, 2, 3, 4});
  const mesh::TetMesh before = m;
  REQUIRE(mesh::quality(m, 2) == Approx(0.0).margin(1e-15));
  CHECK(mesh::mend_flat_tets(m, 0, 0.1) == 1);
  // Both diagonals remove it equally well; either way the double pyramid
  // is split along one diagonal above and below.
  const auto along_bd = as_sets({{p, a, b, d}, {p, b, c, d}, {q, a, b, d}, {q, b, c, d}});
  const auto along_ac = as_sets({{p, a, b, c}, {p, a, c, d}, {q, a, b, c}, {q, a, c, d}});
  const auto got = as_sets(m.tets);
  CHECK((got == along_bd || got == along_ac));
  for (int e = 0; e < m.tet_count(); ++e)
    CHECK(mesh::signed_volume(m, e) > 0.0);
  CHECK(mesh::volume(m) == Approx(mesh::volume(before)).epsilon(1e-12));
  CHECK(m.nodes == before.nodes);
  mesh::build_boundary(m);
  CHECK(faces(m) == faces(before));
}

TEST_CASE("Mending keeps the tets before `first`: the flat tet goes with the edge whose ring is after it",
          "[unit][mesh]") {
  // Top tets first: edge ac's ring reaches them, edge bd's does not.
  mesh::TetMesh m = double_pyramid({0, 1, 2, 3, 4});
  const mesh::TetMesh before = m;
  CHECK(mesh::mend_flat_tets(m, 2, 0.1) == 1);
  REQUIRE(m.tet_count() == 4);
  CHECK(m.tets[0] == before.tets[0]);
  CHECK(m.tets[1] == before.tets[1]);
  CHECK(as_sets({m.tets[2], m.tets[3]}) == as_sets({{q, a, b, c}, {q, a, c, d}}));
}

TEST_CASE("A flat tet whose inner edges both have a ring reaching before `first` stays", "[unit][mesh]") {
  // Its other four edges are on the surface (open rings).
  mesh::TetMesh m = double_pyramid({0, 3, 2, 1, 4});
  const mesh::TetMesh before = m;
  CHECK(mesh::mend_flat_tets(m, 2, 0.1) == 0);
  CHECK(m.tets == before.tets);
}

TEST_CASE("A flat tet on a frozen plane whose edge's ring no triangulation fills goes by a lifted split",
          "[unit][mesh]") {
  // Kept tets under the square abcd (split along bd, before `first`), the
  // flat tet abcd, and three tets around ac above it whose link polygon
  // b p1 p2 d has no triangulation joined to a and c without a tet of
  // quality below -0.06 (the apexes lean over a).
  mesh::TetMesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.4, 0.1, 1.3}, {0.5, 1.2, 1.3}, {0.5, 0.5, -1}};
  const int p1 = 4, p2 = 5, below = 6;
  m.tets = {{below, a, b, d}, {below, b, c, d}, {a, b, c, d}, {a, c, b, p1}, {a, c, p1, p2}, {a, c, p2, d}};
  for (mesh::Tet& t : m.tets)
    if (mesh::signed_volume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]) < 0.0) std::swap(t[2], t[3]);
  mesh::build_boundary(m);
  const mesh::TetMesh before = m;
  CHECK(mesh::mend_flat_tets(m, 2, 0.1) == 1);
  REQUIRE(m.node_count() == before.node_count() + 1);
  CHECK(m.nodes.back().z() > 0.0); // on the side of the rebuilt tets, off the kept plane
  CHECK(m.tets[0] == before.tets[0]);
  CHECK(m.tets[1] == before.tets[1]);
  REQUIRE(m.tet_count() == 2 + 8); // each of the four tets around ac halved
  double worst = 1.0;
  for (int e = 2; e < m.tet_count(); ++e)
    worst = std::min(worst, mesh::quality(m, e));
  // The best of the lifts gives 0.354 (the ring's other tets: 0.56-0.78).
  CHECK(worst > 0.3);
  CHECK(mesh::volume(m) == Approx(mesh::volume(before)).epsilon(1e-12));
  mesh::build_boundary(m);
  CHECK(faces(m) == faces(before));
}

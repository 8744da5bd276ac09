// GridSnap: a body's nodes on a grid for a remesh, the same numbers from
// meshes that differ by round-off, and the nodes a remesh kept given back.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/grid_snap.h"
#include "anvil/mesh/tet_geometry.h"
#include "shaken_mesh.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace anvil;

namespace {
/// One tet on the plane z = 0 with its apex at `apex`.
mesh::TetMesh one_tet(const mesh::Point& apex) {
  mesh::TetMesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, apex};
  m.tets = {{0, 1, 2, 3}};
  mesh::build_boundary(m);
  return m;
}
} // namespace

TEST_CASE("The grid is a power of two between h/128 and h/64", "[unit][mesh]") {
  for (const double h : {0.1, 0.7, 1.0, 1.2, 3.0}) {
    const double q = mesh::snap_spacing(h);
    int exponent = 0;
    CHECK(std::frexp(q, &exponent) == 0.5); // a power of two
    CHECK(q <= h / 64.0);
    CHECK(q > h / 128.0);
  }
}

TEST_CASE("Each remesh's grid keeps its half steps away from the last three grids' midpoints", "[unit][mesh]") {
  // A midpoint of grid j lies at (m/2 + offset j) steps, a half step of grid
  // k at (n + 1/2 + offset k): their distance is that of offset j − offset k
  // from a multiple of 1/2.
  for (std::size_t k = 1; k < 200; ++k)
    for (std::size_t j = k >= 3 ? k - 3 : 0; j < k; ++j) {
      const double apart = std::fmod(std::abs(mesh::grid_offset(j) - mesh::grid_offset(k)), 0.5);
      INFO("remesh " << k << " against " << j);
      CHECK(std::min(apart, 0.5 - apart) > 0.07);
    }
  const double q = mesh::snap_spacing(1.0), offset = mesh::grid_offset(1);
  const mesh::GridSnap on_grid(mesh::make_box({0, 0, 0}, {2, 2, 2}, 1.0), {q, offset});
  for (const mesh::Point& x : on_grid.snapped().nodes)
    for (int k = 0; k < 3; ++k)
      CHECK(std::abs(x[k] / q - offset - std::round(x[k] / q - offset)) < 1e-9);
}

TEST_CASE("Meshes that differ by round-off are the same on the grid, and get their own nodes back", "[unit][mesh]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {10, 6, 4}, 1.0);
  const mesh::TetMesh one = shaken(box, 1e-9, 1), other = shaken(box, 1e-9, 2);
  const double q = mesh::snap_spacing(1.0);
  const mesh::GridSnap on_grid(one, {q, 0.0}), other_on_grid(other, {q, 0.0});
  CHECK(on_grid.snapped().nodes == other_on_grid.snapped().nodes);
  for (const mesh::Point& x : on_grid.snapped().nodes)
    for (int k = 0; k < 3; ++k)
      CHECK(x[k] == std::round(x[k] / q) * q);
  // A remesh that kept every node where the grid put it but one, which it moved.
  mesh::TetMesh remeshed = on_grid.snapped();
  remeshed.nodes[7].x() += 0.01;
  CHECK(on_grid.restore(remeshed) == one.node_count() - 1);
  for (int i = 0; i < one.node_count(); ++i)
    if (i != 7) CHECK(remeshed.nodes[i] == one.nodes[i]); // bit for bit
  CHECK(remeshed.nodes[7] == on_grid.snapped().nodes[7] + mesh::Point(0.01, 0, 0));
}

TEST_CASE("A node whose rounding would flatten a tet stays where it is", "[unit][mesh]") {
  const double q = mesh::snap_spacing(1.0);
  // The apex 0.3 q above the base rounds onto it: the tet would be flat.
  const mesh::TetMesh low = one_tet({0.3, 0.3, 0.3 * q});
  const mesh::GridSnap low_on_grid(low, {q, 0.0});
  CHECK(low_on_grid.snapped().nodes[3] == low.nodes[3]);
  CHECK(mesh::signed_volume(low_on_grid.snapped(), 0) == mesh::signed_volume(low, 0));
  // Ten steps up, rounding changes the tet's volume by a few per cent: it goes onto the grid.
  const mesh::TetMesh high = one_tet({0.3, 0.3, 10.3 * q});
  const mesh::GridSnap high_on_grid(high, {q, 0.0});
  CHECK(high_on_grid.snapped().nodes[3] == mesh::Point(std::round(0.3 / q) * q, std::round(0.3 / q) * q, 10 * q));
}

TEST_CASE("Two nodes that would round onto one grid point stay where they are", "[unit][mesh]") {
  const double q = mesh::snap_spacing(1.0);
  // Node 4 lies a tenth of a step from node 0 (on a body: the ends of an
  // edge crushed to nothing). Rounded, both would land on one grid point,
  // and restore could not tell which node was which.
  mesh::TetMesh m = one_tet({0.3, 0.3, 0.5});
  m.nodes.push_back({0.1 * q, -0.1 * q, 0.0});
  const mesh::GridSnap on_grid(m, {q, 0.0});
  CHECK(on_grid.snapped().nodes[4] == m.nodes[4]);
  CHECK(on_grid.snapped().nodes[3] != m.nodes[3]); // the apex, alone on its point, is rounded
}

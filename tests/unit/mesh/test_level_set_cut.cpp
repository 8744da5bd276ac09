// A tet mesh cut along a level set: conforming pieces, the exact volume of a
// plane cut, the input's face tags kept on the pieces of its faces.
#include "anvil/mesh/generators.h"
#include "anvil/mesh/level_set_cut.h"
#include "anvil/mesh/tet_geometry.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace anvil;

TEST_CASE("a plane cuts a mesh into conforming pieces of its exact volume", "[unit][mesh]") {
  // The unit cube (tags 1-6 by side) cut by the oblique plane a·x = d: the
  // kept part's volume is (Σ over the cube's corners s of (−1)^|s|
  // max(0, d − a·s)³) / (6 a_x a_y a_z).
  const mesh::TetMesh cube = mesh::make_box({0, 0, 0}, {1, 1, 1}, 0.25);
  const mesh::Point a(1.0, 0.7, 0.3);
  const double d = 0.9;
  const auto level = [&](const mesh::Point& x) { return a.dot(x) - d; };
  // Nodes on the plane (the grid of 0.25 mm has some) have φ = 0 exactly,
  // as the cut asks: rounding would leave them a side and a flat piece.
  std::vector<double> phi;
  for (const mesh::Point& x : cube.nodes)
    phi.push_back(std::abs(level(x)) < 1e-12 ? 0.0 : level(x));
  const mesh::LevelSetCut cut = mesh::cut_by_level_set(cube, phi, level);
  double exact = 0.0;
  for (int s = 0; s < 8; ++s) {
    const mesh::Point corner(s & 1, (s >> 1) & 1, (s >> 2) & 1);
    const int sign = (corner.sum() == 0.0 || corner.sum() == 2.0) ? 1 : -1;
    exact += sign * std::pow(std::max(0.0, d - a.dot(corner)), 3);
  }
  exact /= 6.0 * a.x() * a.y() * a.z();
  CHECK(mesh::fault(cut.mesh).empty());
  CHECK(mesh::volume(cut.mesh) == Approx(exact).epsilon(1e-12));
  // Conforming: the boundary is closed (its area vectors sum to zero) and
  // each face lies on a side of the cube, with that side's tag, or on the
  // plane, untagged; a face two pieces split differently would be neither.
  mesh::Point closed = mesh::Point::Zero();
  for (std::size_t f = 0; f < cut.mesh.boundary_faces.size(); ++f) {
    const mesh::Triangle& face = cut.mesh.boundary_faces[f];
    closed += mesh::area_vector(cut.mesh, face);
    const mesh::Point c = (cut.mesh.nodes[face[0]] + cut.mesh.nodes[face[1]] + cut.mesh.nodes[face[2]]) / 3.0;
    int side = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(c[axis]) < 1e-12) side = 2 * axis + 1;
      if (std::abs(c[axis] - 1.0) < 1e-12) side = 2 * axis + 2;
    }
    INFO("face " << f << " at " << c.transpose());
    if (side != 0)
      CHECK(cut.mesh.boundary_tags[f] == side);
    else {
      CHECK(std::abs(level(c)) < 1e-12);
      CHECK(cut.mesh.boundary_tags[f] == 0);
    }
  }
  CHECK(closed.norm() < 1e-12);
  // Each node is where its origin says: on its edge at t.
  for (int n = 0; n < cut.mesh.node_count(); ++n) {
    const mesh::NodeOrigin& o = cut.origin[n];
    const mesh::Point x = (1.0 - o.t) * cube.nodes[o.a] + o.t * cube.nodes[o.b];
    CHECK((x - cut.mesh.nodes[n]).norm() < 1e-14);
  }
}

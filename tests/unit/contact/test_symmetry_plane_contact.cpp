// Faces on a body's symmetry plane are no contact surface: a node on the
// plane two bodies share, pressed a little into the other body, projects onto
// the face it presses on, not onto the other body's symmetry face beside it.
#include "anvil/contact/BodyContact.h"
#include "anvil/mesh/generators.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("a node on a shared symmetry plane projects onto the face it presses, not the symmetry face",
          "[unit][contact]") {
  // A small block on a larger one, both cut by the symmetry plane y = 0 (and
  // sharing no other plane); the upper one 1e-3 mm into the lower one: more
  // than the projection's hair (1e-3 of the reach), so that the lower
  // block's face y = 0 is closer to a node on the plane than its top.
  const double depth = 1e-3, reach = 0.05;
  mesh::TetMesh mesh;
  const mesh::MeshRange lower = mesh::append(mesh, mesh::make_box({0, 0, 0}, {1, 1, 1}, std::array<int, 3>{2, 2, 2}));
  const mesh::MeshRange upper =
      mesh::append(mesh, mesh::make_box({0.25, 0, 1 - depth}, {0.5, 0.5, 0.5}, std::array<int, 3>{2, 2, 2}));
  std::vector<char> symmetry(mesh.boundary_faces.size(), 0);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    bool on_plane = true;
    for (int node : mesh.boundary_faces[f])
      on_plane = on_plane && mesh.nodes[node].y() == 0.0;
    symmetry[f] = on_plane;
  }
  const contact::PairMethod method{contact::PairFormulation::master_slave, contact::PairIntegration::nodal};
  contact::BodyContact contact({{"lower/upper", lower, upper, method, {}}}, symmetry);
  contact.search(mesh, reach);
  // Every node of the upper block's bottom (3 × 3) presses on the lower top.
  int on_plane = 0;
  for (const contact::ContactPoint& p : contact.projected_nodes()) {
    INFO("node at " << mesh.nodes[p.node()].transpose());
    CHECK(p.normal.z() == Approx(1.0));
    CHECK(p.gap == Approx(-depth));
    on_plane += mesh.nodes[p.node()].y() == 0.0;
  }
  CHECK(contact.projected_nodes().size() == 9);
  CHECK(on_plane == 3);
}

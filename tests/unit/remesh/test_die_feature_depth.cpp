// The remeshing trigger "a die vertex inside the body".
#include "anvil/mesh/generators.h"
#include "anvil/remesh/die_feature_depth.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("A die vertex is inside a body only when it is in one of its tets", "[unit][remesh]") {
  mesh::TetMesh scene;
  mesh::append(scene, mesh::make_box({-5, -5, -5}, {2, 2, 2}, 1.0)); // another body, first in the mesh
  // The billet of cases/closed_die_flash.yaml: R 8, H 15.7, h 1.
  const mesh::MeshRange billet = mesh::append(scene, mesh::make_quarter_cylinder(8.0, 15.7, 1.0));
  const std::vector<std::vector<mesh::Point>> dies = {
      {{2.0, 2.0, 15.2}},   // inside, 0.5 mm under the top face
      {{-4.0, -4.0, -4.0}}, // inside the other body, not the billet
      // A vertex of the lower die's web fillet (r 11.07 mm, 11 µm above the
      // billet's bottom face), inside the billet's bounding box but 3 mm
      // outside the billet. In the flash case, on the billet deformed by 6
      // increments, the side of its closest facet (a bottom facet at the
      // rim) called it inside; this undeformed billet does not reproduce
      // that, it checks the tet-based test on the same geometry.
      {{7.83, 7.83, 0.0113}}};
  const auto found = remesh::die_feature_depths(scene, billet, dies);
  CHECK(found[0].depth == Approx(0.5));
  CHECK(found[0].vertex.isApprox(dies[0][0]));
  CHECK(found[1].depth == 0.0);
  CHECK(found[2].depth == 0.0);
}

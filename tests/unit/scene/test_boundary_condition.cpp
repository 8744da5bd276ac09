// condition_losing_faces: a new mesh of a body must keep every face a
// boundary condition selects (the remesher refuses one that does not).
#include "anvil/mesh/generators.h"
#include "anvil/scene/BoundaryCondition.h"

#include <catch2/catch.hpp>

using namespace anvil;

TEST_CASE("A new mesh whose symmetry plane moved off the plane loses the condition's faces", "[unit][scene]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {4, 2, 2}, 1.0);
  scene::BoundaryCondition symmetry;
  symmetry.name = "symmetry_y";
  symmetry.kind = scene::BoundaryKind::symmetry;
  symmetry.faces.plane_normal = mesh::Point::UnitY();
  scene::BoundaryCondition elsewhere = symmetry; // a plane no face of the box lies on
  elsewhere.name = "elsewhere";
  elsewhere.faces.plane_point = mesh::Point(0, 1, 0);
  const std::vector<scene::BoundaryCondition> conditions{elsewhere, symmetry};

  CHECK(scene::condition_losing_faces(conditions, box, box).empty());
  // Every node of the plane moved out by 10 tolerances, as a volume
  // restoration that takes the plane for free surface would move it.
  mesh::TetMesh moved = box;
  for (mesh::Point& x : moved.nodes)
    if (x.y() == 0.0) x.y() -= 10.0 * symmetry.faces.tolerance;
  CHECK(scene::condition_losing_faces(conditions, box, moved) == "condition 'symmetry_y'");
  // One node off leaves the plane's other faces: the condition still holds.
  mesh::TetMesh one_off = box;
  for (mesh::Point& x : one_off.nodes)
    if (x.y() == 0.0) {
      x.y() -= 10.0 * symmetry.faces.tolerance;
      break;
    }
  CHECK(scene::condition_losing_faces(conditions, box, one_off).empty());
}

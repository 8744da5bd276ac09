// Scene::free_rotations: a body whose conditions leave it a rotation, which
// only its contact holds, has the velocity AMG aggregate with the six
// rigid-body modes (docs/linear-solve.md).
#include "scene_at_start.h"

#include <catch2/catch.hpp>

TEST_CASE("A body with one symmetry plane has a rotation only contact holds, and two planes or a fixed face hold it",
          "[unit][scene]") {
  CHECK(SceneAtStart("cases/lap.yaml", {}).scene.free_rotations);             // symmetry y = 0 alone
  CHECK_FALSE(SceneAtStart("cases/upsetting.yaml", {}).scene.free_rotations); // planes normal to x and y
  CHECK_FALSE(SceneAtStart("cases/compression_cylinder_norton_hoff.yaml", {}).scene.free_rotations); // sticking plates
  // Two planes of one normal are one constraint on rotations: the rotation
  // about that normal stays free.
  CHECK(SceneAtStart("cases/upsetting.yaml", {"boundary[1].tag=1"}).scene.free_rotations); // both on x = 0
}

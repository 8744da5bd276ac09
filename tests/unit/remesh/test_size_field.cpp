// The adaptive size field (remesh/size_field.h): die curvature from a
// triangulated surface, the flash gap between two dies, the gradation.
#include "test_common.h"

#include "anvil/core/Timers.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/size_field.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Scene.h"

#include <cmath>
#include <numbers>

using namespace anvil;

TEST_CASE("A die's radius of curvature is read from its triangles: a cylinder's radius, a plane's infinity",
          "[unit][remesh]") {
  // A cylinder of radius 5 mm, 36 facets round, 4 rings: between two
  // facets the chord 2R sin(θ/2) over the angle θ, R (1 − θ²/24): 0.25 %
  // below R at θ = 10°.
  const double radius = 5.0;
  const int round = 36, rings = 4;
  std::vector<mesh::Point> vertices;
  std::vector<std::array<int, 3>> faces;
  for (int k = 0; k <= rings; ++k)
    for (int j = 0; j < round; ++j) {
      const double angle = 2.0 * std::numbers::pi * j / round;
      vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 2.0 * k);
    }
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < round; ++j) {
      const int a = k * round + j, b = k * round + (j + 1) % round;
      faces.push_back({a, b, b + round});
      faces.push_back({a, b + round, a + round});
    }
  for (double r : remesh::die_vertex_radii(vertices, faces))
    CHECK(r == Approx(radius).epsilon(0.01));
  // A flat square of two facets: no curvature.
  const std::vector<mesh::Point> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (double r : remesh::die_vertex_radii(square, {{0, 1, 2}, {0, 2, 3}}))
    CHECK(std::isinf(r));
}

TEST_CASE("The adaptive size field puts three elements across the gap between two dies and grades by 1.5",
          "[unit][remesh]") {
  // cases/upsetting.yaml's quarter cylinder (h 15 mm) between its flat
  // dies, the top one lowered to z = 3 mm: below it the gap is 3 mm, so
  // 1 mm is wanted there; above, the nodes it holds want z/3, at most 2 mm.
  Timers timers;
  const scene::Case input = scene::read_case(source_path("cases/upsetting.yaml"), {"bodies[].mesh.element_size=1"});
  const scene::Scene scene(input, timers);
  scene::RunState state = scene::initial_state(scene);
  state.dies[0].displacement = Eigen::Vector3d(0, 0, -12);
  const mesh::TetMesh& body = state.mesh;
  const std::vector<double> rate(body.tets.size(), 0.0);
  std::vector<std::vector<double>> radii;
  for (const scene::Die& die : scene.dies)
    radii.push_back(remesh::die_vertex_radii(die.surface->triangles().vertices, die.surface->triangles().faces));
  const std::vector<double> size = remesh::wanted_sizes(body, rate, scene, state.dies, radii, 2.0, 0.25);
  int below = 0;
  for (std::size_t i = 0; i < body.nodes.size(); ++i) {
    if (body.nodes[i].z() <= 3.0) {
      CHECK(size[i] == Approx(1.0).epsilon(1e-12));
      ++below;
    }
    CHECK(size[i] <= 2.0);
    CHECK(size[i] >= 0.25);
  }
  CHECK(below > 0);
  // Graded: along every edge, at most (1.5 − 1) mm more per mm.
  for (const mesh::Tet& t : body.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        CHECK(size[t[b]] <=
              size[t[a]] + (remesh::kGradation - 1.0) * (body.nodes[t[a]] - body.nodes[t[b]]).norm() + 1e-12);
}

TEST_CASE("A size box asks for its size inside and grades by 1.5 around it, and a die's box moves with the die",
          "[unit][remesh]") {
  // cases/upsetting.yaml's quarter cylinder (radius 10, height 15 mm) with
  // the top die lowered by 5 mm: the gap (10 mm) asks for 3.3 mm, above the
  // coarse 2 mm, so the field is 2 mm but for the boxes. A fixed box at the
  // origin asks for 0.5 mm; a box of the top die, given at z 11-13 mm where
  // the die starts, is at z 6-8 mm now and asks for 0.6 mm. The points
  // checked are samples of the field's grid (spacing 0.25 mm) where the
  // distance to a box is linear, so the interpolation is exact.
  Timers timers;
  scene::Case input = scene::read_case(source_path("cases/upsetting.yaml"), {"bodies[].mesh.element_size=2"});
  input.remeshing.size_boxes = {{Eigen::AlignedBox3d(mesh::Point(0, 0, 0), mesh::Point(2, 2, 2)), 0.5, -1},
                                {Eigen::AlignedBox3d(mesh::Point(4, 4, 11), mesh::Point(6, 6, 13)), 0.6, 0}};
  const scene::Scene scene(input, timers);
  scene::RunState state = scene::initial_state(scene);
  state.dies[0].displacement = Eigen::Vector3d(0, 0, -5);
  const mesh::TetMesh& body = state.mesh;
  const remesh::PointLocator in_body(body);
  const auto size =
      remesh::adaptive_size(body, in_body, std::vector<double>(body.tets.size(), 0.0), scene, state.dies, 2.0, 0.25);
  CHECK(size({1, 1, 1}, 1.0) == Approx(0.5).epsilon(1e-9));    // inside the fixed box
  CHECK(size({3, 1, 1}, 1.0) == Approx(1.0).epsilon(1e-9));    // 1 mm beside it: 0.5 + 0.5 × 1
  CHECK(size({5, 5, 7}, 1.0) == Approx(0.6).epsilon(1e-9));    // inside the die's box, where the die is now
  CHECK(size({5, 5, 9.5}, 1.0) == Approx(1.35).epsilon(1e-9)); // 1.5 mm above it: 0.6 + 0.5 × 1.5
  CHECK(size({5, 5, 12}, 1.0) == Approx(2.0).epsilon(1e-9));   // where the box was: the coarse size
  CHECK(size({1, 1, 1}, 0.9) == Approx(0.45).epsilon(1e-9));   // a try's scale
}

TEST_CASE("The size field reads only samples it has located: a box over the whole body gives its size everywhere in it",
          "[unit][remesh]") {
  // The quarter cylinder of cases/upsetting.yaml (radius 10, height 15 mm)
  // under one size box of 0.5 mm a millimetre wider all round. The grid
  // locates only the samples near the body's elements; those it leaves (the
  // corner beyond the radius, up to 4 mm from the surface) keep the coarse
  // 2 mm. Every sample the field reads near the body is the box's 0.5 mm, so
  // a node or centroid that read an unlocated sample would get more.
  Timers timers;
  scene::Case input = scene::read_case(source_path("cases/upsetting.yaml"), {"bodies[].mesh.element_size=2"});
  input.remeshing.size_boxes = {{Eigen::AlignedBox3d(mesh::Point(-1, -1, -1), mesh::Point(11, 11, 16)), 0.5, -1}};
  const scene::Scene scene(input, timers);
  const scene::RunState state = scene::initial_state(scene);
  const mesh::TetMesh& body = state.mesh;
  const remesh::PointLocator in_body(body);
  const auto size =
      remesh::adaptive_size(body, in_body, std::vector<double>(body.tets.size(), 0.0), scene, state.dies, 2.0, 0.25);
  for (const mesh::Point& x : body.nodes)
    CHECK(size(x, 1.0) == Approx(0.5).epsilon(1e-12));
  for (int e = 0; e < body.tet_count(); ++e)
    CHECK(size(mesh::centroid(body, e), 1.0) == Approx(0.5).epsilon(1e-12));
}

// The put-back of a new mesh onto the dies (remesh::put_onto_dies), on
// cases/upsetting.yaml's quarter cylinder (R 10 mm, h 15 mm, symmetry planes
// x = 0 and y = 0) between its flat dies at z = 15 (top, die 0) and z = 0:
// the billet's own mesh with its top face moved stands in for a new mesh.
#include "test_common.h"

#include "anvil/core/Timers.h"
#include "anvil/mesh/QualityGuard.h"
#include "anvil/remesh/fit_to_dies.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Scene.h"

#include <algorithm>
#include <cmath>

using namespace anvil;

namespace {

constexpr double kElement = 2.0; // mm
constexpr double kTop = 15.0;    // mm, the top die's plane

struct Billet {
  Timers timers;
  scene::Case input; // the scene keeps a reference to it
  scene::Scene scene;
  scene::RunState state;
  std::vector<int> top_nodes;
  Billet()
      : input(scene::read_case(source_path("cases/upsetting.yaml"), {"bodies[].mesh.element_size=2"})),
        scene(input, timers), state(scene::initial_state(scene)) {
    for (int i = 0; i < state.mesh.node_count(); ++i)
      if (std::abs(state.mesh.nodes[i].z() - kTop) < 1e-9) top_nodes.push_back(i);
  }
  /// The billet's mesh with its top face moved by `dz` (mm).
  mesh::TetMesh with_top_moved(double dz) const {
    mesh::TetMesh moved = state.mesh;
    for (int i : top_nodes)
      moved.nodes[i].z() += dz;
    return moved;
  }
  /// Per node of the billet: the die its top face touched (0), else −1.
  std::vector<int> touching_top(bool touching) const {
    std::vector<int> die(state.mesh.node_count(), -1);
    if (touching)
      for (int i : top_nodes)
        die[i] = 0;
    return die;
  }
};

} // namespace

TEST_CASE("Boundary nodes inside a die by less than an element are put onto it, on their symmetry planes",
          "[unit][remesh]") {
  Billet b;
  REQUIRE(b.top_nodes.size() > 10);
  mesh::TetMesh fresh = b.with_top_moved(0.3); // 0.3 mm into the top die
  const remesh::PutBack done =
      remesh::put_onto_dies(fresh, b.state.mesh, b.touching_top(false), b.scene, 0, b.state.dies, kElement, 0.0);
  CHECK(done.nodes == int(b.top_nodes.size()));
  CHECK(done.deepest == Approx(0.3));
  CHECK(done.closed == 0);
  for (int i : b.top_nodes) {
    CHECK(fresh.nodes[i].z() == Approx(kTop).epsilon(1e-12));
    CHECK(fresh.nodes[i].head<2>() == b.state.mesh.nodes[i].head<2>()); // along the die's normal: x = 0, y = 0 kept
  }
}

TEST_CASE("A node deeper than an element in a die is not this body's contact and stays", "[unit][remesh]") {
  Billet b;
  mesh::TetMesh fresh = b.with_top_moved(1.2 * kElement);
  const mesh::TetMesh before = fresh;
  const remesh::PutBack done =
      remesh::put_onto_dies(fresh, b.state.mesh, b.touching_top(false), b.scene, 0, b.state.dies, kElement, 0.0);
  CHECK(done.nodes == 0);
  CHECK(fresh.nodes == before.nodes);
}

TEST_CASE("A gap below a quarter element is closed only where the old surface touched the die", "[unit][remesh]") {
  Billet b;
  // The old surface 0.4 mm below the top die and the new mesh on it; the
  // nodes inside the top face (off its rim and the symmetry planes, where
  // the closest old face may be a side face) have only top faces around them.
  const mesh::TetMesh old = b.with_top_moved(-0.2 * kElement);
  std::vector<int> inner;
  for (int i : b.top_nodes) {
    const mesh::Point& x = old.nodes[i];
    if (x.x() > 1e-9 && x.y() > 1e-9 && x.head<2>().norm() < 10.0 - 1e-6) inner.push_back(i);
  }
  REQUIRE(inner.size() > 3);
  for (const bool touching : {false, true}) {
    mesh::TetMesh fresh = old;
    const remesh::PutBack done =
        remesh::put_onto_dies(fresh, old, b.touching_top(touching), b.scene, 0, b.state.dies, kElement, 0.0);
    INFO("old surface touching the die: " << touching);
    CHECK(done.nodes == 0);
    CHECK(done.closed >= (touching ? int(inner.size()) : 0));
    CHECK(done.closed <= (touching ? int(b.top_nodes.size()) : 0));
    for (int i : inner)
      CHECK(fresh.nodes[i].z() == Approx(touching ? kTop : kTop - 0.2 * kElement).epsilon(1e-12));
  }
  // Wider than a quarter element: left to the next increment's contact.
  const mesh::TetMesh wide = b.with_top_moved(-0.3 * kElement);
  mesh::TetMesh fresh = wide;
  CHECK(remesh::put_onto_dies(fresh, wide, b.touching_top(true), b.scene, 0, b.state.dies, kElement, 0.0).closed == 0);
}

TEST_CASE("A put-back that would leave an element worse than the quality floor and than it was is not made",
          "[unit][remesh]") {
  Billet b;
  // A top node whose elements are better with it 0.3 mm higher (flat ones
  // under it), raised into the die: putting it back makes them worse.
  const mesh::QualityGuard guard(b.state.mesh);
  mesh::TetMesh fresh = b.state.mesh;
  int n = -1;
  for (int i : b.top_nodes) {
    fresh.nodes[i].z() = kTop + 0.3;
    if (guard.worst_around(fresh, i) > guard.worst_around(b.state.mesh, i) + 0.01) {
      n = i;
      break;
    }
    fresh.nodes[i].z() = kTop;
  }
  REQUIRE(n >= 0);
  for (const double floor : {0.0, 1.0}) {
    mesh::TetMesh tried = fresh;
    const remesh::PutBack done =
        remesh::put_onto_dies(tried, b.state.mesh, b.touching_top(false), b.scene, 0, b.state.dies, kElement, floor);
    INFO("quality floor " << floor);
    // Floor 0: any element that does not invert will do; floor 1: none may get worse.
    CHECK(done.nodes == (floor == 0.0 ? 1 : 0));
    CHECK(tried.nodes[n].z() == Approx(floor == 0.0 ? kTop : kTop + 0.3).epsilon(1e-12));
  }
}

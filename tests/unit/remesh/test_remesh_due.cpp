// When the time loop remeshes a body (remesh::remesh_due): poor elements
// (once a remesh has left one, only when it gets worse), every N increments, a die vertex sunk into the body, a die
// edge the last remesh could not fit that has not sunk further, and the body's overlap with the dies, alike; surface
// edges over a sunk die feature, and their split.
#include "scene_at_start.h"

#include "anvil/core/Timers.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/Remesher.h"
#include "anvil/remesh/die_feature_depth.h"
#include "anvil/remesh/local_remesh.h"
#include "anvil/remesh/quality.h"
#include "anvil/remesh/remesh_due.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Scene.h"

#include <algorithm>

using namespace anvil;

namespace {

using Run = SceneAtStart;

constexpr double kStep = 1e-3; // s, the Δt over which the next increment is looked ahead (nothing moves)

/// The deepest vertex of the upper die of cases/closed_die_flash.yaml inside the billet.
remesh::DieFeature upper_die_feature(const Run& r) {
  std::vector<mesh::Point> vertices = r.scene.dies[0].surface->triangles().vertices;
  for (mesh::Point& x : vertices)
    x += r.state.dies[0].displacement;
  return remesh::die_feature_depths(r.state.mesh, r.state.bodies[0], {vertices})[0];
}
double upper_die_depth(const Run& r) {
  return upper_die_feature(r).depth;
}

} // namespace

TEST_CASE("A body is remeshed when an element is poor, and every N increments when asked", "[unit][remesh]") {
  Run r("cases/upsetting_75.yaml", {"bodies[].mesh.element_size=2", "remeshing.every=3"});
  r.state.increment = 1;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty()); // a fresh mesh

  r.state.increment = 3;
  auto due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  CHECK(due[0].why == "every 3 increments");
  CHECK(due[0].periodic);
  CHECK_FALSE(due[0].local);

  // Element 1's first vertex moved most of the way to its opposite face: quality far below 0.15.
  r.state.increment = 4;
  const mesh::Tet& t = r.state.mesh.tets[0];
  const mesh::Point opposite = (r.state.mesh.nodes[t[1]] + r.state.mesh.nodes[t[2]] + r.state.mesh.nodes[t[3]]) / 3.0;
  r.state.mesh.nodes[t[0]] = opposite + 0.05 * (r.state.mesh.nodes[t[0]] - opposite);
  due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  CHECK(due[0].body == 0);
  CHECK(due[0].why.find("worst quality") == 0);
  CHECK_FALSE(due[0].periodic);
}

TEST_CASE("A periodic remesh rebuilds the whole body and keeps its contact surface: the nodes pressing on a die and "
          "those about to touch one stay where they were",
          "[unit][remesh]") {
  // closed_die_flash's billet as it starts, its bottom face on the lower
  // die's web floor: those nodes are about to touch a die (within a tenth of
  // an element of one). A node on the billet's side, far from the dies, is
  // then said to press on one.
  Run r("cases/closed_die_flash.yaml", {"remeshing.check_load=false", "remeshing.every=1"});
  const double h = r.scene.bodies[0].remesh_size;
  r.state.increment = 1;
  const mesh::TetMesh before = r.state.mesh;
  std::vector<int> touching(before.nodes.size(), -1);
  const std::vector<char> kept = remesh::contact_surface(before, touching, r.scene, 0, r.state.dies);
  const std::vector<char> on_boundary = mesh::boundary_node_flags(before);
  int about_to_touch = 0;
  for (std::size_t n = 0; n < kept.size(); ++n) {
    INFO("node " << n << " at z " << before.nodes[n].z());
    if (!on_boundary[n]) REQUIRE_FALSE(kept[n]);
    about_to_touch += kept[n];
  }
  REQUIRE(about_to_touch > 0); // the bottom face on the web floor
  // A boundary node far from every die (mid-height on the billet's side) is kept only when it presses on a die.
  int side = -1;
  for (std::size_t n = 0; n < kept.size() && side < 0; ++n)
    if (on_boundary[n] && !kept[n] && std::abs(before.nodes[n].z() - 0.5 * 15.7) < h) side = int(n);
  REQUIRE(side >= 0);
  touching[side] = 1;
  const std::vector<char> with_side = remesh::contact_surface(before, touching, r.scene, 0, r.state.dies);
  CHECK(with_side[side]);

  const std::vector<remesh::RemeshDue> due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  REQUIRE(due[0].periodic);
  const std::vector<double> rate(before.tets.size(), 0.0);
  remesh::remesh(r.scene, r.state, due, touching, rate, kStep, r.timers);
  REQUIRE(r.state.remeshes.size() == 1);
  CHECK(r.state.remeshes[0].rebuilt_share == 1.0);
  // Every kept node is a node of the new mesh, bit for bit (the body starts at node 0).
  std::vector<mesh::Point> after = r.state.mesh.nodes;
  auto less = [](const mesh::Point& a, const mesh::Point& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(after.begin(), after.end(), less);
  for (std::size_t n = 0; n < with_side.size(); ++n)
    if (with_side[n]) {
      INFO("kept node " << n);
      CHECK(std::binary_search(after.begin(), after.end(), before.nodes[n], less));
    }
  for (int e = 0; e < r.state.mesh.tet_count(); ++e)
    REQUIRE(mesh::quality(r.state.mesh, e) >= r.input.remeshing.quality);
}

TEST_CASE("An element a remesh left below the quality floor asks for a remesh again below four fifths of the floor, "
          "however poor the remesh left it",
          "[unit][remesh]") {
  Run r("cases/upsetting_75.yaml", {"bodies[].mesh.element_size=2"});
  r.state.increment = 4;
  const double floor = r.input.remeshing.quality;
  const double again = remesh::kQualityAgain * floor;
  const mesh::Tet& t = r.state.mesh.tets[0];
  const mesh::Point opposite = (r.state.mesh.nodes[t[1]] + r.state.mesh.nodes[t[2]] + r.state.mesh.nodes[t[3]]) / 3.0;
  const mesh::Point apex = r.state.mesh.nodes[t[0]];
  // Element 1 flattened towards its opposite face; returns the body's worst quality.
  auto flatten = [&](double share) {
    r.state.mesh.nodes[t[0]] = opposite + share * (apex - opposite);
    return remesh::worst_quality(r.state.mesh);
  };
  const double left = flatten(0.09); // element 1 or a neighbour
  REQUIRE(left < floor);
  REQUIRE(left > again);
  REQUIRE(remesh::remesh_due(r.scene, r.state, kStep).size() == 1);

  // The last remesh could do no better than this element: not due again for it …
  scene::RemeshRecord record{};
  record.body = 0;
  record.worst_quality_after = left;
  r.state.remeshes.push_back(record);
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  REQUIRE(flatten(0.085) > again);
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  // … until it is below four fifths of the floor.
  REQUIRE(flatten(0.08) < again);
  const auto due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  CHECK(due[0].why.find("worst quality") == 0);
  // A remesh that left a nearly flat element does not lower the trigger:
  // a chain of such remeshes would let an element be crushed between two.
  r.state.remeshes.back().worst_quality_after = 0.3 * floor;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).size() == 1);
  REQUIRE(flatten(0.085) > again);
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  // A remesh that left every element above the floor: the floor decides.
  r.state.remeshes.back().worst_quality_after = 0.3;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).size() == 1);
}

TEST_CASE("A die vertex sunk into the body asks for a remesh, and once a remesh has left it in, only half a trigger "
          "deeper again",
          "[unit][remesh]") {
  // closed_die_flash: billet R 8 mm at 1 mm elements; its upper die's cavity
  // vertices sink into the billet as the die comes down. Trigger: 0.5 mm.
  Run r("cases/closed_die_flash.yaml", {"remeshing.die_penetration=0.5", "remeshing.check_load=false"});
  const double trigger = 0.5 * r.scene.bodies[0].remesh_size;
  r.state.increment = 1;
  REQUIRE(upper_die_depth(r) == 0.0);
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());

  // The die lowered until one of its vertices is deeper than the trigger.
  double lowered = 0.0;
  while (upper_die_depth(r) <= trigger && lowered < 20.0) {
    lowered += 0.05;
    r.state.dies[0].displacement.z() = -lowered;
  }
  const double depth = upper_die_depth(r);
  REQUIRE(depth > trigger);
  auto due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  CHECK(due[0].why.find("the vertex of die 'upper'") == 0);
  CHECK(due[0].local); // a die corner: its region rebuilt, surface included
  // Around every die vertex at least half the trigger deep: the upper die's (z > 0), the deepest among them.
  REQUIRE_FALSE(due[0].die_corners.empty());
  for (const mesh::Point& x : due[0].die_corners)
    CHECK(x.z() > 0.0);
  const mesh::Point deepest = upper_die_feature(r).vertex;
  CHECK(std::count(due[0].die_corners.begin(), due[0].die_corners.end(), deepest) == 1);

  // A remesh that could not fit that vertex left it this deep: not due again at once …
  scene::RemeshRecord record{};
  record.body = 0;
  record.die_depth_after = depth;
  record.die_overlap_after = 0.0; // a remesh that fits the surface to the dies measures both
  r.state.remeshes.push_back(record);
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  // … and due once it is half a trigger deeper than it was left.
  while (upper_die_depth(r) <= depth + 0.5 * trigger && lowered < 20.0) {
    lowered += 0.01;
    r.state.dies[0].displacement.z() = -lowered;
  }
  REQUIRE(upper_die_depth(r) > depth + 0.5 * trigger);
  due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  CHECK(due[0].why.find("the vertex of die 'upper'") == 0);
}

TEST_CASE("A body overlapping the dies by more than remeshing.die_overlap of its volume is remeshed whole, and once "
          "a remesh has left an overlap, only half a trigger more again",
          "[unit][remesh]") {
  Run r("cases/closed_die_flash.yaml", {"remeshing.die_overlap=0.01", "remeshing.check_load=false"});
  r.state.increment = 1;
  const double trigger = 0.01 * r.scene.bodies[0].initial_volume; // mm³
  r.state.inside_dies[0] = 0.9 * trigger;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  r.state.inside_dies[0] = 1.1 * trigger;
  auto due = remesh::remesh_due(r.scene, r.state, kStep);
  REQUIRE(due.size() == 1);
  CHECK(due[0].why == "1.1% of its initial volume lies inside the dies");
  CHECK_FALSE(due[0].local);

  scene::RemeshRecord record{};
  record.body = 0;
  record.die_overlap_after = 1.1 * trigger; // a remesh that could not reduce it
  r.state.remeshes.push_back(record);
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  r.state.inside_dies[0] = 1.55 * trigger;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  r.state.inside_dies[0] = 1.65 * trigger;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).size() == 1);
  // A remesh that kept the surface since (no overlap measured) is no new
  // start: the overlap is still due half a trigger beyond the last fit's.
  scene::RemeshRecord kept{};
  kept.body = 0;
  r.state.remeshes.push_back(kept);
  r.state.inside_dies[0] = 1.55 * trigger;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).empty());
  r.state.inside_dies[0] = 1.65 * trigger;
  CHECK(remesh::remesh_due(r.scene, r.state, kStep).size() == 1);
}

TEST_CASE("Surface edges over a die fillet or edge sunk between the nodes are split, their midpoints put onto the "
          "die, and every other node and element keeps its place and fields",
          "[unit][remesh]") {
  // closed_die_flash's upper die lowered into the (undeformed) billet until
  // the first boundary edges have their midpoint a tenth of an element inside
  // it, the die vertices still short of their own trigger (a quarter element).
  Run r("cases/closed_die_flash.yaml", {"remeshing.check_load=false", "remeshing.split_sunk_edges=true"});
  const double h = r.scene.bodies[0].remesh_size;
  r.state.increment = 1;
  std::vector<remesh::RemeshDue> due;
  double lowered = 0.0;
  while (due.empty() && lowered < 20.0) {
    lowered += 0.01;
    r.state.dies[0].displacement.z() = -lowered;
    r.state.inside_dies = scene::inside_dies(r.scene, r.state);
    due = remesh::remesh_due(r.scene, r.state, kStep);
  }
  REQUIRE(due.size() == 1);
  INFO(due[0].why);
  REQUIRE_FALSE(due[0].sunk_edges.empty());
  CHECK(due[0].local);
  CHECK(due[0].why.find("boundary edges over a die fillet or edge") != std::string::npos);
  CHECK(upper_die_depth(r) <= 0.25 * h);

  // Distinct ε̄ per element, to follow each element's value.
  const mesh::TetMesh before = r.state.mesh;
  for (std::size_t e = 0; e < r.state.equivalent_strain.size(); ++e)
    r.state.equivalent_strain[e] = 1.0 + 1e-3 * double(e);
  const std::vector<double> strain_before = r.state.equivalent_strain;
  const double inside_before = r.state.inside_dies[0];
  double worst_before = 1.0;
  for (int e = 0; e < before.tet_count(); ++e)
    worst_before = std::min(worst_before, mesh::quality(before, e));
  const std::vector<int> touching(before.nodes.size(), -1);
  const std::vector<double> rate(before.tets.size(), 0.0);
  remesh::remesh(r.scene, r.state, due, touching, rate, kStep, r.timers);

  const mesh::TetMesh& after = r.state.mesh;
  const int added = after.node_count() - before.node_count();
  CHECK(added > 0);
  CHECK(added <= int(due[0].sunk_edges.size()));
  // The old nodes stay where they were, bit for bit.
  for (int n = 0; n < before.node_count(); ++n)
    REQUIRE(after.nodes[n] == before.nodes[n]);
  // Every element's ε̄ is one of the old elements' (a half takes its parent's).
  std::vector<double> sorted = strain_before;
  std::sort(sorted.begin(), sorted.end());
  for (double value : r.state.equivalent_strain)
    REQUIRE(std::binary_search(sorted.begin(), sorted.end(), value));
  // Less of the body inside the die; no element made or moved below twice the trigger.
  CHECK(r.state.inside_dies[0] < inside_before);
  double worst_after = 1.0;
  for (int e = 0; e < after.tet_count(); ++e)
    worst_after = std::min(worst_after, mesh::quality(after, e));
  CHECK(worst_after >= std::min(worst_before, 2.0 * r.input.remeshing.quality));
  REQUIRE(r.state.remeshes.size() == 1);
  CHECK(r.state.remeshes[0].nodes_after == after.node_count());
}

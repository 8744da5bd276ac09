// The remesh step of the time loop (run::remesh_checking_load) with
// remeshing.split_sunk_edges: a remesh for another trigger is followed, in
// the same step, by the split of the edges its new mesh leaves sunk over a
// die feature, instead of increments later.
#include "scene_at_start.h"

#include "anvil/core/Timers.h"
#include "anvil/remesh/remesh_due.h"
#include "anvil/run/load_check.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Scene.h"

#include <vector>

using namespace anvil;

namespace {

struct Run : SceneAtStart {
  explicit Run(const std::vector<std::string>& overrides) : SceneAtStart("cases/closed_die_flash.yaml", overrides) {}

  /// The upper die lowered into the (undeformed) billet until boundary
  /// edges are sunk over its fillets, then `further` mm more.
  void sink_upper_die(double further) {
    double lowered = 0.0;
    while (!remesh::sunk_edges_due(scene, state, 0) && lowered < 20.0)
      lower_upper_die(lowered += 0.01);
    lower_upper_die(lowered + further);
  }
  void lower_upper_die(double by) {
    state.dies[0].displacement.z() = -by;
    state.inside_dies = scene::inside_dies(scene, state);
  }
};

constexpr double kFurther = 0.3; // mm: fillets sunk deeper than the fit of a whole remesh takes back
constexpr double kStep = 1e-3;   // s, the Δt of the next increment (nothing moves)

} // namespace

TEST_CASE("With the split of sunk edges on, a whole remesh for the overlap with the dies is followed in the same "
          "step by the split of the edges its new mesh leaves sunk over a die fillet",
          "[unit][remesh]") {
  for (const bool split : {true, false}) {
    // The die sunk past its fillets: the overlap trigger is due, and comes
    // before the split (remesh_due).
    Run r({"remeshing.check_load=false", std::string("remeshing.split_sunk_edges=") + (split ? "true" : "false")});
    r.state.increment = 1;
    r.input.remeshing.split_sunk_edges = true; // sunk_edges_due reads it: sink the die with it on, then as asked
    r.sink_upper_die(kFurther);
    r.input.remeshing.split_sunk_edges = split;
    const std::vector<remesh::RemeshDue> due = remesh::remesh_due(r.scene, r.state, kStep);
    REQUIRE(due.size() == 1);
    INFO(due[0].why);
    REQUIRE(due[0].sunk_edges.empty()); // the overlap's whole remesh comes first
    const std::vector<int> touching(r.state.mesh.nodes.size(), -1);
    const std::vector<double> rate(r.state.mesh.tets.size(), 0.0);
    scene::TimeStep next;
    next.nominal = next.planned = next.length = kStep;
    run::remesh_checking_load(r.scene, r.state, due, touching, rate, next, r.timers);
    REQUIRE_FALSE(r.state.remeshes.empty());
    CHECK(r.state.remeshes.front().rebuilt_share == 1.0); // the overlap's remesh is of the whole body
    if (split) {
      // The whole remesh resampled the surface at the body's size over the
      // sunk die; its edges over the die feature were split at once.
      REQUIRE(r.state.remeshes.size() == 2);
      CHECK(r.state.remeshes.back().rebuilt_share < 1.0);
      CHECK(r.state.remeshes.back().nodes_after > r.state.remeshes.back().nodes_before);
    } else {
      CHECK(r.state.remeshes.size() == 1);
    }
  }
}

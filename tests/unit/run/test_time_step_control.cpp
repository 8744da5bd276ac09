// TimeStepControl on cases/upsetting.yaml's scene (top die at 10 mm/s,
// stroke increment 0.15 mm, stop at a stroke of 7.5 mm): the step it plans
// from a state, its cuts, the sliver rule for contact events, and its stops.
#include "scene_at_start.h"

#include "anvil/run/TimeStepControl.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Scene.h"

#include <cmath>

using namespace anvil;

namespace {

struct Upsetting : SceneAtStart {
  explicit Upsetting(const std::vector<std::string>& overrides = {})
      : SceneAtStart("cases/upsetting.yaml", overrides) {}
};

} // namespace

TEST_CASE("TimeStepControl plans the nominal step, limits it by the fastest node, and meets the stop in equal steps",
          "[unit][scene]") {
  Upsetting u({"time.max_displacement=0.2"});
  const run::TimeStepControl control(u.scene);
  const double nominal = 0.15 / 10.0; // stroke increment / die speed (s)

  scene::TimeStep step = control.next_step(u.state);
  CHECK(step.nominal == Approx(nominal).epsilon(1e-12));
  CHECK(step.planned == Approx(nominal).epsilon(1e-12)); // at rest no node limits it
  CHECK(step.length == step.planned);

  // One node at 1000 mm/s: it may move 0.2 of its local element size.
  const int node = u.state.mesh.node_count() / 2;
  u.state.unknowns.nodal[4 * node] = 1000.0;
  step = control.next_step(u.state);
  CHECK(step.nominal == Approx(nominal).epsilon(1e-12));
  CHECK(step.planned < nominal);
  CHECK(step.planned * 1000.0 < 0.2 * 2.0); // below 0.2 of any edge of the 1 mm mesh (at most 2 mm long)
  u.state.unknowns.nodal[4 * node] = 0.0;

  // 1.1 steps before the stop: two equal steps, not a step and a sliver.
  u.state.dies[0].stroke = 7.5 - 1.1 * 0.15;
  CHECK(control.next_step(u.state).planned == Approx(0.55 * nominal).epsilon(1e-9));
  // 0.4 of a step before it: exactly that.
  u.state.dies[0].stroke = 7.5 - 0.4 * 0.15;
  CHECK(control.next_step(u.state).planned == Approx(0.4 * nominal).epsilon(1e-9));
}

TEST_CASE("TimeStepControl halves a failed step time.max_cuts times, and ends a step at a contact only away from its "
          "ends",
          "[unit][scene]") {
  Upsetting u({"time.max_cuts=3", "time.min_step_fraction=0.1"});
  const run::TimeStepControl control(u.scene);
  double dt = 0.016;
  for (int cuts = 0; cuts < 3; ++cuts) {
    const std::optional<double> shorter = control.cut(dt, cuts);
    REQUIRE(shorter);
    CHECK(*shorter == dt / 2);
    dt = *shorter;
  }
  CHECK_FALSE(control.cut(dt, 3));

  const scene::TimeStep step{.nominal = 0.01, .planned = 0.01, .length = 0.01};
  CHECK(control.ends_at_contact(step, 0.005));
  CHECK_FALSE(control.ends_at_contact(step, 0.0005)); // a sliver after the start
  CHECK_FALSE(control.ends_at_contact(step, 0.0095)); // a sliver before the end
}

TEST_CASE("TimeStepControl stops at the final stroke (complete) and at time.max_increments (not complete)",
          "[unit][scene]") {
  Upsetting u({"time.max_increments=40"});
  const run::TimeStepControl control(u.scene);
  CHECK_FALSE(control.stop(u.state));
  CHECK(control.progress(u.state) == 0.0);

  u.state.dies[0].stroke = 3.75;
  CHECK(control.progress(u.state) == Approx(0.5));
  u.state.increment = 40;
  const run::Stop early = control.stop(u.state);
  REQUIRE(early);
  CHECK_FALSE(early.complete);
  CHECK(early.reason.find("time.max_increments (40)") != std::string::npos);
  CHECK(early.reason.find("final stroke 7.5 mm of die 'top', at 3.75 mm") != std::string::npos);

  u.state.increment = 39;
  u.state.dies[0].stroke = 7.5;
  const run::Stop done = control.stop(u.state);
  REQUIRE(done);
  CHECK(done.complete);
  CHECK(done.reason == "final stroke reached");
}

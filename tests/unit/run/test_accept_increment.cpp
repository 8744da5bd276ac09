// accept_increment on cases/upsetting.yaml's scene (quarter cylinder R 10 mm,
// h 15 mm, top die at 10 mm/s): what an accepted increment puts into the run
// state, and that a refused one changes nothing.
#include "test_common.h"

#include "anvil/core/Timers.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/run/Increment.h"
#include "anvil/run/TimeStepControl.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/Scene.h"

#include <cmath>

using namespace anvil;

namespace {

struct FirstIncrement {
  Timers timers;
  scene::Case input; // the scene keeps a reference to it
  scene::Scene scene;
  scene::RunState state;
  scene::Discretisation disc;
  run::IncrementOutcome inc;
  FirstIncrement()
      : input(scene::read_case(source_path("cases/upsetting.yaml"), {"bodies[].mesh.element_size=2"})),
        scene(input, timers), state(scene::initial_state(scene)), disc(scene::discretise(scene, state, timers)) {
    const scene::TimeStep step = run::TimeStepControl(scene).next_step(state);
    inc = run::solve_increment(scene, disc, state, step, timers);
  }
};

constexpr double kDieSpeed = 10.0; // mm/s, the top die of cases/upsetting.yaml

} // namespace

TEST_CASE("An accepted increment moves the nodes by Δt v, the die by its stroke, puts contact nodes onto the die, "
          "records the loads where they were solved and integrates ε̄",
          "[unit][run]") {
  FirstIncrement f;
  REQUIRE(f.inc.converged());
  const scene::RunState before = f.state;
  const double dt = f.inc.time_step;
  const Eigen::VectorXd v = f.inc.unknowns.nodal;
  const std::vector<double> rate = f.inc.fields.rate;
  REQUIRE(run::accept_increment(f.scene, f.disc, f.inc, f.state, f.timers));

  CHECK(f.state.increment == before.increment + 1);
  CHECK(f.state.time == Approx(before.time + dt).epsilon(1e-14));
  CHECK(f.state.dies[0].stroke == Approx(kDieSpeed * dt).epsilon(1e-12));
  CHECK(f.state.dies[0].displacement.z() == Approx(-kDieSpeed * dt).epsilon(1e-12));
  CHECK(f.state.dies[1].stroke == 0.0);

  // Free nodes: x + Δt v to round-off. Nodes pressing on the top die: on its
  // plane at its new height (15 − stroke), whatever Δt v left them at.
  const double top = 15.0 - kDieSpeed * dt;
  int on_top = 0, free_moved = 0;
  for (int i = 0; i < f.state.mesh.node_count(); ++i) {
    const mesh::Point expected = before.mesh.nodes[i] + dt * v.segment<3>(4 * i);
    const mesh::Point& x = f.state.mesh.nodes[i];
    if (std::abs(before.mesh.nodes[i].z() - 15.0) < 1e-9) {
      ++on_top;
      CHECK(x.z() == Approx(top).epsilon(1e-9));
      CHECK((x - expected).head<2>().norm() < 1e-12); // projected along the die's normal only
    } else if (before.mesh.nodes[i].z() > 1e-9) {
      ++free_moved;
      CHECK((x - expected).norm() < 1e-12);
    }
  }
  CHECK(on_top > 0);
  CHECK(free_moved > 0);

  // One row per load surface, at the geometry, stroke and time the increment
  // was solved on: after 0 increments.
  REQUIRE(f.state.loads.size() == before.loads.size() + f.scene.surfaces.size());
  for (std::size_t s = 0; s < f.scene.surfaces.size(); ++s) {
    const scene::LoadRecord& row = f.state.loads[before.loads.size() + s];
    CHECK(row.increment == before.increment);
    CHECK(row.time == before.time);
    CHECK(row.stroke == 0.0);
  }
  // The top die pushes the billet down: its load on the model is upwards.
  CHECK(f.state.loads[before.loads.size()].force.z() > 0.0);

  for (int e = 0; e < f.state.mesh.tet_count(); ++e) {
    CHECK(f.state.equivalent_strain[e] == Approx(before.equivalent_strain[e] + dt * rate[e]).epsilon(1e-14));
    CHECK(f.disc.point_states[e].equivalent_strain == f.state.equivalent_strain[e]);
  }
}

TEST_CASE("An increment that would invert an element is refused and changes nothing in the run state", "[unit][run]") {
  FirstIncrement f;
  REQUIRE(f.inc.converged());
  // Send the first vertex of element 1 through its opposite face within Δt.
  const mesh::Tet& t = f.state.mesh.tets[0];
  const mesh::Point opposite = (f.state.mesh.nodes[t[1]] + f.state.mesh.nodes[t[2]] + f.state.mesh.nodes[t[3]]) / 3.0;
  const mesh::Point through = opposite + (opposite - f.state.mesh.nodes[t[0]]);
  f.inc.unknowns.nodal.segment<3>(4 * t[0]) = (through - f.state.mesh.nodes[t[0]]) / f.inc.time_step;
  const scene::RunState before = f.state;

  CHECK_FALSE(run::accept_increment(f.scene, f.disc, f.inc, f.state, f.timers));
  CHECK(f.inc.failure.find("would invert") != std::string::npos);
  CHECK(f.state.increment == before.increment);
  CHECK(f.state.time == before.time);
  CHECK(f.state.mesh.nodes == before.mesh.nodes);
  CHECK(f.state.dies[0].stroke == before.dies[0].stroke);
  CHECK(f.state.loads.size() == before.loads.size());
  CHECK(f.state.equivalent_strain == before.equivalent_strain);
  CHECK(f.state.unknowns.nodal == before.unknowns.nodal);
}

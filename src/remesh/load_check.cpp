#include "anvil/remesh/load_check.h"

#include "anvil/scene/Discretisation.h"
#include "anvil/scene/Increment.h"

#include <cmath>
#include <limits>

namespace anvil::remesh {

double next_increment_load(const scene::Scene& scene, const scene::RunState& state, const scene::TimeStep& step,
                           int solves, Timers& timers) {
  Timers::Scope scope(timers, "load check");
  scene::RunState copy = state;
  scene::Discretisation disc = scene::discretise(scene, copy, timers);
  double load = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < solves; ++k) {
    scene::IncrementOutcome inc = scene::solve_increment(scene, disc, copy, step, timers, scene::ContactEvents::ignore);
    if (!inc.converged()) return std::numeric_limits<double>::quiet_NaN();
    load = std::abs(inc.forces.front().z()); // the press load, as LoadRecord::press_load
    copy.unknowns = std::move(inc.unknowns);
  }
  return load;
}

} // namespace anvil::remesh

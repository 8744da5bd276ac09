#include "anvil/run/fold_watch.h"

#include "anvil/core/log.h"

#include <algorithm>

namespace anvil::run {

void watch_folds(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state, Timers& timers) {
  Timers::Scope scope(timers, "effect folds");
  const double near = 2.0 * scene.reference_length;
  const contact::FoldScan scan =
      contact::find_folds(state.mesh, state.bodies, disc.symmetry_faces, scene.reference_length);
  for (const contact::Fold& fold : scan.folds) {
    const auto known = std::find_if(state.folds.begin(), state.folds.end(), [&](const scene::FoldRecord& r) {
      return r.body == fold.body && (r.centre - fold.centre).norm() <= near;
    });
    if (known != state.folds.end()) {
      known->centre = fold.centre;
      known->area = std::max(known->area, fold.area);
      continue;
    }
    state.folds.push_back({state.increment, fold.body, fold.centre, fold.area});
    log::info("  fold: the surface of '%s' meets itself at %.3g, %.3g, %.3g mm over %.3g mm2 (%d faces)",
              scene.bodies[fold.body].name.c_str(), fold.centre.x(), fold.centre.y(), fold.centre.z(), fold.area,
              fold.faces);
  }
}

} // namespace anvil::run

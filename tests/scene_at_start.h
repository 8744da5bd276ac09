// A case read from the source tree and its scene at the start of the run: the
// fixture of the tests that drive one part of the time loop by hand.
#pragma once
#include "test_common.h"

#include "anvil/core/Timers.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Scene.h"

#include <string>
#include <vector>

struct SceneAtStart {
  anvil::Timers timers;
  anvil::scene::Case input; // the scene keeps a reference to it
  anvil::scene::Scene scene;
  anvil::scene::RunState state;
  SceneAtStart(const std::string& file, const std::vector<std::string>& overrides)
      : input(anvil::scene::read_case(source_path(file), overrides)), scene(input, timers),
        state(anvil::scene::initial_state(scene)) {}
};

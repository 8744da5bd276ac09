// Private to src/scene: the `remeshing` section of a case.
#pragma once
#include "anvil/scene/Case.h"

#include "checked_yaml.h"

namespace anvil::scene {

/// c.remeshing from the case's `remeshing` section (absent: remeshing off);
/// its size boxes name dies, so c.dies and c.time are read before.
void read_remeshing(const CheckedYaml& doc, Case& c);

} // namespace anvil::scene

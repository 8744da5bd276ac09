// The effects registry (docs/design.md §5, STYLE "Effects"): every term Anvil can
// add, declared in one function. A scene resolves to the subset it needs and
// only that subset is built; `anvil --list` prints the registry.
#pragma once
#include "anvil/scene/Case.h"

#include <string>
#include <vector>

namespace anvil::scene {

struct Effect {
  std::string name;
  std::string doc;
};

/// All effects, in a fixed order.
const std::vector<Effect>& effect_registry();

/// Names of the effects `c` needs, given its bodies' laws.
std::vector<std::string> resolve_effects(const Case& c, const std::vector<const material::Material*>& laws);

} // namespace anvil::scene

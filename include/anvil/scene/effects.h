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

/// Of `effects`, those a scene in which nothing moves exercises: it solves
/// heat alone (a transfer, dwell or cooling), so no flow, friction,
/// remeshing or what they feed.
std::vector<std::string> heat_alone_effects(const std::vector<std::string>& effects);

} // namespace anvil::scene

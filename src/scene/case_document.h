// Private to src/scene: a case read from a checked document, the whole
// file's or one operation's (Chain.cpp).
#pragma once
#include "anvil/scene/Case.h"

#include "checked_yaml.h"

namespace anvil::scene {

/// The case `doc.root()` describes; `overrides` are recorded as applied.
Case read_case_document(const CheckedYaml& doc, const std::vector<std::string>& overrides);

} // namespace anvil::scene

// Private to src/scene: the pieces the case and material schemas are
// built of (schema.h's KeySpec with its type, range, choices and default),
// and the physical ranges both use.
#pragma once
#include "anvil/scene/schema.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace anvil::scene::schema_keys {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Physical ranges of the thermal keys: wide enough for every metal forged
// and every die, narrow enough that a slip of units or sign is caught here,
// not as a numerical failure later.
inline constexpr double kAbsoluteZero = -273.15; ///< °C, excluded
inline constexpr double kHottest = 3500.0;       ///< °C: above tungsten's melting point, 3422 °C
inline constexpr double kFastest = 1e5;          ///< mm/s, a velocity component: ten times a forging hammer's 10 m/s

inline KeySpec key(std::string path, KeyType type, std::string doc, std::string unit = "") {
  KeySpec k;
  k.path = std::move(path);
  k.type = type;
  k.doc = std::move(doc);
  k.unit = std::move(unit);
  if (type == KeyType::integer) { // what the reader stores them in: int
    k.min = std::numeric_limits<int>::min();
    k.max = std::numeric_limits<int>::max();
  }
  return k;
}
inline KeySpec required(KeySpec k) {
  k.required = true;
  return k;
}
inline KeySpec with_default(KeySpec k, std::string value) {
  k.default_value = std::move(value);
  return k;
}
inline KeySpec range(KeySpec k, double min, double max, bool min_exclusive = false) {
  k.min = std::max(k.min, min);
  k.max = std::min(k.max, max);
  k.min_exclusive = min_exclusive && k.min == min;
  return k;
}
inline KeySpec choices(KeySpec k, std::vector<std::string> values) {
  k.choices = std::move(values);
  return k;
}

inline KeySpec alias(KeySpec k, std::string of) {
  k.alias = std::move(of);
  return k;
}

/// The top-level sections an operation of a chain may give its own (a list
/// replaces the top level's, a map stands over it key by key).
struct OperationSection {
  const char* name;
  KeyType type;
};
inline constexpr OperationSection kOperationSections[] = {
    {"dies", KeyType::list},          {"boundary", KeyType::list}, {"contact", KeyType::map},
    {"contact_pairs", KeyType::list}, {"time", KeyType::map},      {"remeshing", KeyType::map},
    {"output", KeyType::map},         {"thermal", KeyType::map},   {"solver", KeyType::map}};

/// The keys of a chain of operations (`operations`, operation_schema.cpp).
std::vector<KeySpec> operation_keys();

} // namespace anvil::scene::schema_keys

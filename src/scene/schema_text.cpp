// Looking keys up in a schema (aliases resolved) and saying what a key
// takes: the error messages' "expected ..." and `anvil --schema`.
#include "anvil/scene/schema.h"

#include <cmath>
#include <sstream>

namespace anvil::scene {
namespace {

const char* type_name(KeyType t) {
  switch (t) {
  case KeyType::integer:
    return "integer";
  case KeyType::number:
    return "number";
  case KeyType::string:
    return "string";
  case KeyType::name:
    return "a name of letters, digits, '_', '-' and '.' (part of file names and CSV fields), at most 64 characters";
  case KeyType::boolean:
    return "boolean";
  case KeyType::vector3:
    return "[x, y, z]";
  case KeyType::numbers:
    return "list of numbers";
  case KeyType::list:
    return "list";
  case KeyType::map:
    return "map";
  }
  return "?";
}

} // namespace

const KeySpec* find_key(const std::vector<KeySpec>& schema, const std::string& path) {
  for (const KeySpec& k : schema)
    if (k.path == path) return &k;
  for (const KeySpec& k : schema)
    if (!k.alias.empty() && path.size() > k.path.size() && path.compare(0, k.path.size(), k.path) == 0 &&
        (path[k.path.size()] == '.' || path[k.path.size()] == '['))
      return find_key(schema, k.alias + path.substr(k.path.size()));
  return nullptr;
}

std::string expectation(const KeySpec& k) {
  std::ostringstream s;
  s << (k.type == KeyType::integer ? "an integer" : k.type == KeyType::number ? "a number" : type_name(k.type));
  if (k.type == KeyType::integer || k.type == KeyType::number || k.type == KeyType::numbers ||
      k.type == KeyType::vector3) {
    const bool low = std::isfinite(k.min), high = std::isfinite(k.max);
    if ((low || high) && (k.type == KeyType::numbers || k.type == KeyType::vector3)) s << ", each";
    if (low && high && k.min == k.max)
      s << " equal to " << k.min;
    else {
      if (low) s << (k.min_exclusive ? " > " : " >= ") << k.min;
      if (low && high) s << " and";
      if (high) s << " <= " << k.max;
    }
  }
  if (!k.choices.empty()) {
    s << ", one of";
    for (std::size_t i = 0; i < k.choices.size(); ++i)
      s << (i ? ", " : " ") << k.choices[i];
  }
  if (!k.unit.empty()) s << " (" << k.unit << ")";
  return s.str();
}

std::string schema_text() {
  std::ostringstream s;
  auto print = [&](const char* title, const std::vector<KeySpec>& schema) {
    s << title << "\n";
    for (const KeySpec& k : schema) {
      s << "  " << k.path << "\n      " << expectation(k);
      if (k.required)
        s << "; required";
      else if (!k.default_value.empty())
        s << "; default " << k.default_value;
      s << "\n      " << k.doc << "\n";
    }
  };
  print("Case file (YAML, format 1):", case_schema());
  print("\nMaterial card (YAML, format 1):", material_schema());
  return s.str();
}

} // namespace anvil::scene

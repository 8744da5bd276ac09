// A required number of a tool's YAML parameter file.
#pragma once
#include "anvil/core/error.h"

#include <yaml-cpp/yaml.h>

#include <string>

/// `node[key]` as a number; InputError naming `file` and the key when it is missing.
inline double yaml_number(const YAML::Node& node, const std::string& file, const char* key) {
  if (!node[key]) throw anvil::InputError(file + ": missing key '" + key + "'");
  return node[key].as<double>();
}

// Private to src/scene: a YAML file checked against a schema before use.
// Every error names file, line, key, value and what was expected.
#pragma once
#include "anvil/core/error.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/schema.h"
#include "anvil/thermal/ThermalMaterial.h"

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace anvil::scene {

/// `node` as "key = value" lines in document order: maps as dotted keys, lists
/// as key[i], an empty value as "~".
std::vector<std::string> flatten(const YAML::Node& node);

class CheckedYaml {
public:
  /// Parses `path`, applies the command-line `overrides` ("key.path=value",
  /// see apply_override) and checks every key against `schema` (unknown keys,
  /// types, ranges, choices, required keys). Throws InputError.
  CheckedYaml(const std::string& path, const std::vector<KeySpec>& schema,
              const std::vector<std::string>& overrides = {});

  const YAML::Node& root() const { return root_; }
  /// The same file read through another root: an operation's document,
  /// built of this file's nodes (checked already).
  CheckedYaml with_root(const YAML::Node& root) const {
    CheckedYaml copy = *this;
    // reset, not assignment: a YAML::Node copy shares this root's node, and
    // assigning to it would make this file's root the operation's document.
    copy.root_.reset(root);
    return copy;
  }
  const std::string& path() const { return path_; }

  /// "file:line" of a node.
  std::string at(const YAML::Node& node) const;

  // Typed access to child `key` of `map` whose schema path is `spec_path`;
  // the schema default applies when the key is absent. Values were checked at load.
  double number(const YAML::Node& map, const std::string& key, const std::string& spec_path) const;
  int integer(const YAML::Node& map, const std::string& key, const std::string& spec_path) const;
  std::string text(const YAML::Node& map, const std::string& key, const std::string& spec_path) const;
  bool boolean(const YAML::Node& map, const std::string& key, const std::string& spec_path) const;
  /// A vector whose components may be null (~).
  std::array<std::optional<double>, 3> partial_vector(const YAML::Node& map, const std::string& key) const;
  mesh::Point vector(const YAML::Node& map, const std::string& key, const std::string& spec_path) const;
  /// A list of numbers (checked at load); empty when absent.
  std::vector<double> numbers(const YAML::Node& map, const std::string& key) const;

  /// The input file named by `key` of `map` (a path relative to this file):
  /// fails naming the key unless it is a regular file of at most `max_bytes`.
  std::string input_file(const YAML::Node& map, const std::string& key, const std::string& shown,
                         std::uintmax_t max_bytes) const;

  /// Fails unless `map` has `key`: "key 'shown.key': missing: <why>".
  void require(const YAML::Node& map, const std::string& key, const std::string& shown, const std::string& why) const;
  /// Fails when `map` has `key`: "key 'shown.key': does not apply to <context>".
  void forbid(const YAML::Node& map, const std::string& key, const std::string& shown,
              const std::string& context) const;

  /// Throws InputError "file:line: key 'shown': message".
  [[noreturn]] void fail(const YAML::Node& node, const std::string& shown_key, const std::string& message) const;

private:
  /// One "key.path=value" override: "[]" after a list key means every element,
  /// "[N]" element N; maps on the way are created; the value is parsed as YAML.
  void apply_override(const std::string& override_text);
  void check(const YAML::Node& node, const std::string& spec_prefix, const std::string& shown_prefix) const;
  void check_value(const YAML::Node& value, const KeySpec& spec, const std::string& shown) const;
  const KeySpec& spec(const std::string& spec_path) const;

  std::string path_;
  const std::vector<KeySpec>& schema_;
  YAML::Node root_;
  /// Nodes set from the command line, and the text that set them (for at()).
  std::vector<std::pair<YAML::Node, std::string>> overridden_;
};

/// Calls `read(entry, shown)` for each entry of the list `list` (absent: none),
/// `shown` being "key[i]", the entry as error messages name it.
template <class Read> void for_each_entry(const YAML::Node& list, const std::string& key, Read read) {
  for (std::size_t i = 0; list && i < list.size(); ++i)
    read(list[i], key + "[" + std::to_string(i) + "]");
}

/// A table `values_key` against `at_key` of `item` (both lists of numbers,
/// `at_key` increasing, one value for each), or one value (a constant).
thermal::PropertyTable read_table(const CheckedYaml& doc, const YAML::Node& item, const std::string& values_key,
                                  const std::string& at_key, const std::string& shown);

} // namespace anvil::scene

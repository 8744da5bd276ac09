// Every key of the case file and of the material cards, declared once with
// type, default, range, unit and a one-line doc (STYLE "Input and errors").
// The readers accept nothing that is not declared here; `anvil --schema`
// prints it.
#pragma once
#include <limits>
#include <string>
#include <vector>

namespace anvil::scene {

/// `name`: a string that becomes part of file names and CSV fields (letters,
/// digits, '_', '-', '.'; not '.' or '..'; at most 64 characters).
enum class KeyType { integer, number, string, name, boolean, vector3, numbers, list, map };

struct KeySpec {
  std::string path; ///< dotted; list items as "[]", e.g. "bodies[].mesh.file"
  KeyType type;
  std::string default_value; ///< as text; empty when required or optional without default
  bool required = false;
  /// numbers: allowed range; integers are at most that of a 32-bit int
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::vector<std::string> choices; ///< strings: allowed values (empty = any)
  std::string unit;
  std::string doc;
  /// Checked as this key: an operation's section ("operations[].dies" as "dies").
  std::string alias;
};

/// Keys of a case file (format version 1).
const std::vector<KeySpec>& case_schema();
/// Keys of a material card (format version 1).
const std::vector<KeySpec>& material_schema();

/// Looks `path` up in `schema`; nullptr if undeclared. A path under an
/// aliased key is looked up under its alias ("operations[].time.stop" as
/// "time.stop").
const KeySpec* find_key(const std::vector<KeySpec>& schema, const std::string& path);

/// "number > 0 (mm)", "one of box, cylinder" ...: what a value must be.
std::string expectation(const KeySpec& key);

/// The schema as text, one key per line, for `anvil --schema`.
std::string schema_text();

} // namespace anvil::scene

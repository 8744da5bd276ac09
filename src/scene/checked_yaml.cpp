#include "checked_yaml.h"

#include "anvil/core/input_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace anvil::scene {
namespace {

std::string parent_of(const std::string& spec_path) {
  const auto dot = spec_path.rfind('.');
  return dot == std::string::npos ? "" : spec_path.substr(0, dot);
}
std::string leaf_of(const std::string& spec_path) {
  const auto dot = spec_path.rfind('.');
  return dot == std::string::npos ? spec_path : spec_path.substr(dot + 1);
}
std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

std::optional<double> parse_number(const YAML::Node& node) {
  if (!node.IsScalar()) return std::nullopt;
  std::istringstream s(node.Scalar());
  double value = 0.0;
  if (!(s >> value) || !(s >> std::ws).eof() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string shown_value(const YAML::Node& node) {
  if (node.IsScalar()) {
    // One line, whatever the value holds: control characters as \n, \t, \xNN.
    std::string shown;
    for (const char c : node.Scalar()) {
      if (c == '\n')
        shown += "\\n";
      else if (c == '\t')
        shown += "\\t";
      else if (static_cast<unsigned char>(c) < 0x20) {
        char code[8];
        std::snprintf(code, sizeof code, "\\x%02x", static_cast<unsigned char>(c));
        shown += code;
      } else
        shown += c;
    }
    return "'" + shown + "'";
  }
  if (node.IsNull()) return "(empty)";
  if (node.IsSequence()) return "a list";
  return "a map";
}

void flatten_into(const YAML::Node& node, const std::string& prefix, std::vector<std::string>& lines) {
  if (node.IsMap()) {
    for (const auto& entry : node)
      flatten_into(entry.second, join(prefix, entry.first.Scalar()), lines);
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      flatten_into(node[i], prefix + "[" + std::to_string(i) + "]", lines);
  } else {
    lines.push_back(prefix + " = " + (node.IsNull() ? std::string("~") : node.Scalar()));
  }
}

} // namespace

std::vector<std::string> flatten(const YAML::Node& node) {
  std::vector<std::string> lines;
  flatten_into(node, "", lines);
  return lines;
}

CheckedYaml::CheckedYaml(const std::string& path, const std::vector<KeySpec>& schema,
                         const std::vector<std::string>& overrides)
    : path_(path), schema_(schema) {
  if (const std::string problem = input_file_problem(path, kMaxYamlBytes); !problem.empty())
    throw InputError(path + ": " + (problem == "file not found" ? "cannot open the file: not found" : problem));
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  try {
    root_ = YAML::Load(in);
  } catch (const YAML::Exception& e) {
    throw InputError(where(path, e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root_.IsMap()) throw InputError(path + ": expected a YAML map of keys at the top level");
  for (const std::string& text : overrides)
    apply_override(text);
  check(root_, "", "");
}

namespace {

/// One step of an override path: a key, optionally indexing a list.
struct PathStep {
  std::string key;
  enum class Index { none, every, one } index = Index::none;
  std::size_t element = 0;
};

/// "key", "key[]" or "key[N]"; throws std::invalid_argument saying what is wrong.
PathStep parse_step(const std::string& part) {
  PathStep step;
  const auto open = part.find('[');
  step.key = part.substr(0, open);
  if (open == std::string::npos) return step;
  if (part.back() != ']' || step.key.empty()) throw std::invalid_argument("'" + part + "' is not key, key[] or key[N]");
  const std::string inside = part.substr(open + 1, part.size() - open - 2);
  if (inside.empty()) {
    step.index = PathStep::Index::every;
    return step;
  }
  const auto [end, error] = std::from_chars(inside.data(), inside.data() + inside.size(), step.element);
  if (error != std::errc() || end != inside.data() + inside.size())
    throw std::invalid_argument("'" + inside + "' is not a list index");
  step.index = PathStep::Index::one;
  return step;
}

} // namespace

void CheckedYaml::apply_override(const std::string& text) {
  const auto bad = [&](const std::string& why) -> InputError { return InputError("--set '" + text + "': " + why); };
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw bad("expected key.path=value, e.g. time.stroke_increment=0.1");
  const std::string key_path = text.substr(0, equals);
  YAML::Node value;
  try {
    value = YAML::Load(text.substr(equals + 1));
  } catch (const YAML::Exception& e) {
    throw bad("the value is not valid YAML: " + e.msg);
  }
  std::vector<PathStep> steps;
  std::string spec_path; // the schema's name of the key: every index written []
  std::istringstream split(key_path);
  for (std::string part; std::getline(split, part, '.');) {
    if (part.empty()) throw bad("empty key in '" + key_path + "'");
    try {
      steps.push_back(parse_step(part));
    } catch (const std::invalid_argument& e) {
      throw bad(e.what());
    }
    spec_path = join(spec_path, steps.back().key + (steps.back().index == PathStep::Index::none ? "" : "[]"));
  }
  if (find_key(schema_, spec_path) == nullptr)
    throw bad("no key '" + spec_path + "' in the schema (run 'anvil --schema' for the list)");

  // Walks the document; `node` is a handle, so assignments change root_.
  const auto walk = [&](auto&& self, YAML::Node node, std::size_t i) -> void {
    const PathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    const auto assign_or_descend = [&](YAML::Node parent, const auto& index) {
      if (last) {
        parent[index] = YAML::Clone(value);
        overridden_.emplace_back(parent[index], text);
        return;
      }
      if (!parent[index]) parent[index] = YAML::Node(YAML::NodeType::Map);
      if (!parent[index].IsMap())
        throw bad("'" + steps[i + 1].key + "' sits under something that is not a map in " + path_);
      self(self, parent[index], i + 1);
    };
    if (step.index == PathStep::Index::none) return assign_or_descend(node, step.key);
    YAML::Node list = node[step.key];
    if (!list || !list.IsSequence()) throw bad("'" + step.key + "' is not a list in " + path_);
    if (step.index == PathStep::Index::one && step.element >= list.size())
      throw bad("'" + step.key + "' has " + std::to_string(list.size()) + " elements (indices from 0)");
    for (std::size_t e = 0; e < list.size(); ++e)
      if (step.index == PathStep::Index::every || e == step.element) assign_or_descend(list, e);
  };
  walk(walk, root_, 0);
}

std::string CheckedYaml::input_file(const YAML::Node& map, const std::string& key, const std::string& shown,
                                    std::uintmax_t max_bytes) const {
  const std::filesystem::path given(map[key].Scalar());
  const std::string file = given.is_absolute()
                               ? given.string()
                               : (std::filesystem::path(path_).parent_path() / given).lexically_normal().string();
  if (const std::string problem = input_file_problem(file, max_bytes); !problem.empty())
    fail(map[key], shown + "." + key, "'" + file + "' " + problem);
  return file;
}

std::string CheckedYaml::at(const YAML::Node& node) const {
  for (const auto& [overridden, text] : overridden_)
    if (node.is(overridden)) return "--set '" + text + "'";
  const int line = node.Mark().line;
  return where(path_, line >= 0 ? line + 1 : 0);
}

void CheckedYaml::require(const YAML::Node& map, const std::string& key, const std::string& shown,
                          const std::string& why) const {
  if (!map[key]) fail(map, join(shown, key), "missing: " + why);
}

void CheckedYaml::forbid(const YAML::Node& map, const std::string& key, const std::string& shown,
                         const std::string& context) const {
  if (map[key]) fail(map[key], join(shown, key), "does not apply to " + context);
}

void CheckedYaml::fail(const YAML::Node& node, const std::string& shown_key, const std::string& message) const {
  throw InputError(at(node) + ": key '" + shown_key + "': " + message);
}

const KeySpec& CheckedYaml::spec(const std::string& spec_path) const {
  const KeySpec* k = find_key(schema_, spec_path);
  ANVIL_ASSERT(k != nullptr);
  return *k;
}

void CheckedYaml::check(const YAML::Node& node, const std::string& spec_prefix, const std::string& shown_prefix) const {
  if (!node.IsMap()) {
    throw InputError(at(node) + ": " + (shown_prefix.empty() ? std::string("the file") : "key '" + shown_prefix + "'") +
                     ": expected a map of keys, found " + shown_value(node));
  }
  std::vector<std::pair<std::string, YAML::Node>> seen;
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    const std::string spec_path = join(spec_prefix, key), shown = join(shown_prefix, key);
    // YAML maps have unique keys; a reader would silently keep one of two.
    for (const auto& [name, first] : seen)
      if (name == key)
        throw InputError(at(entry.first) + ": key '" + shown + "' is given twice (first at " + at(first) + ")");
    seen.emplace_back(key, entry.first);
    const KeySpec* k = find_key(schema_, spec_path);
    if (k && !k->alias.empty()) k = find_key(schema_, k->alias); // an operation's section, checked as the case's
    if (!k) {
      std::string known;
      for (const KeySpec& s : schema_)
        if (parent_of(s.path) == spec_prefix) known += (known.empty() ? "" : ", ") + leaf_of(s.path);
      throw InputError(at(entry.first) + ": unknown key '" + shown + "' (known keys here: " + known + ")");
    }
    check_value(entry.second, *k, shown);
  }
  for (const KeySpec& s : schema_)
    if (s.required && parent_of(s.path) == spec_prefix && !node[leaf_of(s.path)])
      throw InputError(at(node) + ": missing key '" + join(shown_prefix, leaf_of(s.path)) + "': expected " +
                       expectation(s) + " — " + s.doc);
}

void CheckedYaml::check_value(const YAML::Node& value, const KeySpec& k, const std::string& shown) const {
  // The value, or the one entry of a list that is wrong, named in the message.
  auto wrong = [&](const YAML::Node& at) {
    fail(at, shown, "value " + shown_value(at) + " is not valid; expected " + expectation(k));
  };
  switch (k.type) {
  case KeyType::map:
    check(value, k.path, shown);
    return;
  case KeyType::list:
    if (!value.IsSequence() || value.size() == 0)
      fail(value, shown, "expected a non-empty list, found " + shown_value(value));
    for (std::size_t i = 0; i < value.size(); ++i)
      check(value[i], k.path + "[]", shown + "[" + std::to_string(i) + "]");
    return;
  case KeyType::string:
    if (!value.IsScalar()) wrong(value);
    if (!k.choices.empty() && std::find(k.choices.begin(), k.choices.end(), value.Scalar()) == k.choices.end())
      wrong(value);
    return;
  case KeyType::name: {
    if (!value.IsScalar()) wrong(value);
    const std::string& text = value.Scalar();
    const bool allowed = std::all_of(text.begin(), text.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
    if (text.empty() || text.size() > 64 || !allowed || text == "." || text == "..") wrong(value);
    return;
  }
  case KeyType::boolean:
    if (!value.IsScalar() || (value.Scalar() != "true" && value.Scalar() != "false")) wrong(value);
    return;
  case KeyType::vector3:
    if (!value.IsSequence() || value.size() != 3) wrong(value);
    for (const auto& c : value) {
      if (c.IsNull()) continue;
      const auto v = parse_number(c);
      if (!v || *v < k.min || *v > k.max) wrong(c);
    }
    return;
  case KeyType::numbers: {
    // One number stands for a list of one.
    if (!(value.IsScalar() || (value.IsSequence() && value.size() > 0))) wrong(value);
    auto check_entry = [&](const YAML::Node& c) {
      const auto v = parse_number(c);
      if (!v || *v < k.min || *v > k.max || (k.min_exclusive && *v == k.min)) wrong(c);
    };
    if (value.IsScalar())
      check_entry(value);
    else
      for (const auto& c : value)
        check_entry(c);
    return;
  }
  case KeyType::integer:
  case KeyType::number: {
    const auto v = parse_number(value);
    if (!v) wrong(value);
    if (k.type == KeyType::integer && *v != std::floor(*v)) wrong(value);
    if (*v < k.min || *v > k.max || (k.min_exclusive && *v == k.min)) wrong(value);
    return;
  }
  }
}

double CheckedYaml::number(const YAML::Node& map, const std::string& key, const std::string& spec_path) const {
  const YAML::Node v = map[key];
  if (v) return *parse_number(v);
  const KeySpec& k = spec(spec_path);
  if (k.default_value.empty()) fail(map, key, "missing; expected " + expectation(k) + " — " + k.doc);
  return std::stod(k.default_value);
}

int CheckedYaml::integer(const YAML::Node& map, const std::string& key, const std::string& spec_path) const {
  return static_cast<int>(number(map, key, spec_path));
}

std::string CheckedYaml::text(const YAML::Node& map, const std::string& key, const std::string& spec_path) const {
  const YAML::Node v = map[key];
  return v ? v.Scalar() : spec(spec_path).default_value;
}

bool CheckedYaml::boolean(const YAML::Node& map, const std::string& key, const std::string& spec_path) const {
  return text(map, key, spec_path) == "true";
}

std::array<std::optional<double>, 3> CheckedYaml::partial_vector(const YAML::Node& map, const std::string& key) const {
  std::array<std::optional<double>, 3> out;
  const YAML::Node v = map[key];
  if (!v) return out;
  for (int c = 0; c < 3; ++c)
    if (!v[c].IsNull()) out[c] = parse_number(v[c]);
  return out;
}

std::vector<double> CheckedYaml::numbers(const YAML::Node& map, const std::string& key) const {
  std::vector<double> out;
  const YAML::Node list = map[key];
  if (list && list.IsScalar()) return {*parse_number(list)};
  for (const auto& c : list)
    out.push_back(*parse_number(c));
  return out;
}

mesh::Point CheckedYaml::vector(const YAML::Node& map, const std::string& key, const std::string& spec_path) const {
  const YAML::Node v = map[key];
  if (!v) {
    const KeySpec& k = spec(spec_path);
    if (k.default_value.empty()) fail(map, key, "missing; expected " + expectation(k) + " — " + k.doc);
    const YAML::Node d = YAML::Load(k.default_value);
    return {d[0].as<double>(), d[1].as<double>(), d[2].as<double>()};
  }
  for (int c = 0; c < 3; ++c)
    if (v[c].IsNull()) fail(v, key, "all three components are needed here");
  return {*parse_number(v[0]), *parse_number(v[1]), *parse_number(v[2])};
}

thermal::PropertyTable read_table(const CheckedYaml& doc, const YAML::Node& item, const std::string& values_key,
                                  const std::string& at_key, const std::string& shown) {
  const std::vector<double> values = doc.numbers(item, values_key);
  const std::vector<double> at = doc.numbers(item, at_key);
  if (values.size() == 1) return thermal::PropertyTable(values.front());
  if (at.size() != values.size())
    doc.fail(item[values_key], (shown.empty() ? "" : shown + ".") + values_key,
             std::to_string(values.size()) + " values need as many entries in '" + at_key + "' (" +
                 std::to_string(at.size()) + " given)");
  for (std::size_t i = 1; i < at.size(); ++i)
    if (!(at[i] > at[i - 1])) doc.fail(item[at_key], (shown.empty() ? "" : shown + ".") + at_key, "must increase");
  return thermal::PropertyTable(at, values);
}

} // namespace anvil::scene

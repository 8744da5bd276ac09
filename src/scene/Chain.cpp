#include "anvil/scene/Chain.h"

#include "anvil/core/input_file.h"

#include "case_document.h"
#include "checked_yaml.h"
#include "schema_keys.h"

#include <algorithm>
#include <cmath>

namespace anvil::scene {
namespace {

/// The kind to_string names `type` (checked by the schema), else forge.
OperationKind operation_kind(const std::string& type) {
  for (OperationKind kind : {OperationKind::transfer, OperationKind::dwell, OperationKind::cool, OperationKind::trim})
    if (type == to_string(kind)) return kind;
  return OperationKind::forge;
}

/// The document operation `op` runs: the top-level keys with the
/// operation's sections over them, a list replaced, a map key by key. A
/// transfer, a cool and a trim lie on no die of the top level.
YAML::Node operation_document(const YAML::Node& root, const YAML::Node& op, OperationKind kind) {
  YAML::Node merged(YAML::NodeType::Map);
  const bool own_dies_only =
      kind == OperationKind::transfer || kind == OperationKind::cool || kind == OperationKind::trim;
  for (const auto& entry : root) {
    const std::string key = entry.first.Scalar();
    if (key == "operations" || (own_dies_only && key == "dies")) continue;
    const YAML::Node own = op[key];
    if (own && own.IsMap() && entry.second.IsMap()) {
      YAML::Node combined(YAML::NodeType::Map);
      for (const auto& inner : entry.second)
        if (!own[inner.first.Scalar()]) combined[inner.first.Scalar()] = inner.second;
      for (const auto& inner : own)
        combined[inner.first.Scalar()] = inner.second;
      merged[key] = combined;
    } else {
      merged[key] = own ? own : entry.second;
    }
  }
  for (const auto& section : schema_keys::kOperationSections)
    if (op[section.name] && !root[section.name]) merged[section.name] = op[section.name];
  return merged;
}

Placement read_place(const CheckedYaml& doc, const YAML::Node& op) {
  Placement p;
  const YAML::Node place = op["place"];
  if (!place) return p;
  p.flip = doc.boolean(place, "flip", "operations[].place.flip");
  p.turn = doc.number(place, "turn", "operations[].place.turn");
  p.move = doc.vector(place, "move", "operations[].place.move");
  p.rest = doc.boolean(place, "rest", "operations[].place.rest");
  return p;
}

TrimSpec read_trim(const CheckedYaml& doc, const YAML::Node& op, const std::string& shown) {
  TrimSpec t;
  const YAML::Node trim = op["trim"];
  if (!trim) doc.fail(op, shown + ".trim", "missing: a trim operation needs its cut ('line' or 'stl')");
  if (static_cast<bool>(trim["line"]) == static_cast<bool>(trim["stl"]))
    doc.fail(trim, shown + ".trim", "give exactly one cut: 'line' (x1, y1, x2, y2, ...) or 'stl' (a closed surface)");
  if (trim["stl"]) {
    t.stl_file = doc.input_file(trim, "stl", shown + ".trim", kMaxStlBytes);
    return t;
  }
  const std::vector<double> xy = doc.numbers(trim, "line");
  if (xy.size() % 2 != 0 || xy.size() < 6)
    doc.fail(trim["line"], shown + ".trim.line",
             std::to_string(xy.size()) + " numbers: a closed line needs pairs x, y of at least three points");
  for (std::size_t i = 0; i < xy.size(); i += 2)
    t.line.emplace_back(xy[i], xy[i + 1]);
  double area = 0.0; // shoelace: a line of points all in a row encloses nothing
  for (std::size_t i = 0; i < t.line.size(); ++i) {
    const Eigen::Vector2d& a = t.line[i];
    const Eigen::Vector2d& b = t.line[(i + 1) % t.line.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  if (!(std::abs(area) > 0.0)) doc.fail(trim["line"], shown + ".trim.line", "the line encloses no area");
  return t;
}

} // namespace

const char* to_string(OperationKind kind) {
  switch (kind) {
  case OperationKind::forge:
    return "forge";
  case OperationKind::transfer:
    return "transfer";
  case OperationKind::dwell:
    return "dwell";
  case OperationKind::cool:
    return "cool";
  case OperationKind::trim:
    return "trim";
  }
  return "?";
}

Chain read_chain(const std::string& path, const std::vector<std::string>& overrides) {
  const CheckedYaml doc(path, case_schema(), overrides);
  const YAML::Node& root = doc.root();
  Chain chain;
  chain.path = path;
  const YAML::Node list = root["operations"];
  if (!list) {
    Operation whole;
    whole.input = read_case_document(doc, overrides);
    chain.operations.push_back(std::move(whole));
    return chain;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node op = list[i];
    const std::string shown = "operations[" + std::to_string(i) + "]";
    Operation o;
    o.name = op["name"].Scalar();
    o.source = doc.at(op);
    for (const Operation& other : chain.operations)
      if (other.name == o.name) doc.fail(op["name"], shown + ".name", "operation '" + o.name + "' is named twice");
    o.kind = operation_kind(doc.text(op, "type", "operations[].type"));
    const std::string kind = to_string(o.kind);
    if (o.kind == OperationKind::trim) {
      o.trim = read_trim(doc, op, shown);
      for (const auto& section : schema_keys::kOperationSections)
        if (std::string(section.name) != "output" && std::string(section.name) != "remeshing")
          doc.forbid(op, section.name, shown, "a trim (a cut, no time loop)");
    } else {
      doc.forbid(op, "trim", shown, "type '" + kind + "' (only a trim cuts)");
    }
    if (o.kind == OperationKind::cool || o.kind == OperationKind::trim)
      doc.forbid(op, "dies", shown, "type '" + kind + "' (in air)");
    if (o.kind != OperationKind::forge && o.kind != OperationKind::trim && !root["thermal"])
      doc.fail(op, shown + ".type",
               "a " + kind +
                   " is heat alone: the case needs a 'thermal' section (at the top level: a chain is "
                   "thermal throughout or not at all)");
    if (op["thermal"] && !root["thermal"])
      doc.fail(op["thermal"], shown + ".thermal",
               "a chain is thermal throughout or not at all: give 'thermal' at the top level");
    if (op["output"] && op["output"]["directory"])
      doc.fail(op["output"]["directory"], shown + ".output.directory",
               "an operation writes into the chain's folder (NN-name): give output.directory at the top level");
    if (op["output"] && op["output"]["flow_lines"])
      doc.fail(op["output"]["flow_lines"], shown + ".output.flow_lines",
               "flow lines follow the material through the whole chain: give them at the top level");
    o.place = read_place(doc, op);
    YAML::Node document = operation_document(root, op, o.kind);
    if (o.kind == OperationKind::trim) {
      // A trim has no time loop; the keys that need one (thermal,
      // remeshing) are read as for any operation, then the time dropped.
      document["time"] = YAML::Load("{stop: {time: 1}}");
    }
    o.input = read_case_document(doc.with_root(document), overrides);
    if (o.kind == OperationKind::trim) {
      o.input.time = TimeSpec{};
      o.input.remeshing.enabled = true;
    } else if (!o.input.time.enabled) {
      doc.fail(op, shown, "missing key 'time': an operation runs over time (give it here or at the top level)");
    }
    if (o.place.rest && o.input.dies.empty())
      doc.fail(op["place"]["rest"], shown + ".place.rest", "the operation has no die to rest the part on");
    chain.operations.push_back(std::move(o));
  }
  return chain;
}

} // namespace anvil::scene

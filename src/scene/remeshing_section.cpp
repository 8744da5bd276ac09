#include "remeshing_section.h"

#include <cstdio>

namespace anvil::scene {
namespace {

/// remeshing.size_boxes of the remeshing section `r`: each box's corners,
/// size and the die it follows (by name, among the dies read before).
void read_size_boxes(const CheckedYaml& doc, const YAML::Node& r, Case& c) {
  RemeshSpec& m = c.remeshing;
  for_each_entry(r["size_boxes"], "remeshing.size_boxes", [&](const YAML::Node& n, const std::string& shown) {
    if (!m.adaptive) doc.fail(n, shown, "a size box shapes the adaptive size field: set remeshing.size: adaptive");
    SizeBox b;
    const mesh::Point low = doc.vector(n, "min", "remeshing.size_boxes[].min");
    const mesh::Point high = doc.vector(n, "max", "remeshing.size_boxes[].max");
    if (!(low.array() < high.array()).all()) doc.fail(n, shown, "'min' must be below 'max' in x, y and z");
    b.box = Eigen::AlignedBox3d(low, high);
    b.size = doc.number(n, "size", "remeshing.size_boxes[].size");
    if (m.smallest_size > 0.0 && b.size < m.smallest_size) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "%g mm is below remeshing.smallest_size (%g mm), the smallest edge a remesh makes", b.size,
                    m.smallest_size);
      doc.fail(n["size"], shown + ".size", text);
    }
    if (const YAML::Node die = n["die"]) {
      for (std::size_t d = 0; d < c.dies.size(); ++d)
        if (c.dies[d].name == die.Scalar()) b.die = static_cast<int>(d);
      if (b.die < 0) doc.fail(die, shown + ".die", "no die is named '" + die.Scalar() + "'");
    }
    m.size_boxes.push_back(b);
  });
}

} // namespace

void read_remeshing(const CheckedYaml& doc, Case& c) {
  const YAML::Node r = doc.root()["remeshing"];
  if (!r) return;
  if (!c.time.enabled) doc.fail(r, "remeshing", "remeshing needs a 'time' section (it happens between increments)");
  RemeshSpec& m = c.remeshing;
  m.enabled = true;
  m.quality = doc.number(r, "quality", "remeshing.quality");
  m.every = doc.integer(r, "every", "remeshing.every");
  m.die_penetration = doc.number(r, "die_penetration", "remeshing.die_penetration");
  m.die_overlap = doc.number(r, "die_overlap", "remeshing.die_overlap");
  if (r["element_size"]) m.element_size = doc.number(r, "element_size", "remeshing.element_size");
  m.feature_angle = doc.number(r, "feature_angle", "remeshing.feature_angle");
  m.iterations = doc.integer(r, "iterations", "remeshing.iterations");
  m.adaptive = doc.text(r, "size", "remeshing.size") == "adaptive";
  if (r["smallest_size"]) m.smallest_size = doc.number(r, "smallest_size", "remeshing.smallest_size");
  m.max_nodes = doc.integer(r, "max_nodes", "remeshing.max_nodes");
  m.time_limit = doc.number(r, "time_limit", "remeshing.time_limit");
  m.check_load = doc.boolean(r, "check_load", "remeshing.check_load");
  m.local = doc.boolean(r, "local", "remeshing.local");
  // The adaptive size field resolves the die features where they meet the
  // body; the split keeps them resolved between its remeshes.
  m.split_sunk_edges =
      r["split_sunk_edges"] ? doc.boolean(r, "split_sunk_edges", "remeshing.split_sunk_edges") : m.adaptive;
  read_size_boxes(doc, r, c);
}

} // namespace anvil::scene

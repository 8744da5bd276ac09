// Runs a case into a fresh temporary folder and reads back what it wrote
// (loads.csv, summary.json, checkpoint.h5), for tests.
#pragma once
#include "test_common.h"

#include "anvil/io/Checkpoint.h"
#include "anvil/io/RunResults.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/RunState.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using anvil::io::LoadRow;

struct RunOutputs {
  std::string directory;

  /// Rows of loads.csv for one surface, in order.
  std::vector<LoadRow> loads(const std::string& surface) const { return anvil::io::read_loads(directory, surface); }

  /// The first number after "key": in summary.json.
  double summary_number(const std::string& key) const { return anvil::io::read_summary_number(directory, key); }

  /// The last checkpoint (time-stepping runs write one at the end).
  anvil::scene::RunState final_state() const { return anvil::io::read_checkpoint(directory + "/checkpoint.h5"); }
};

/// Runs `c` into <tmp>/<name> (emptied first).
inline RunOutputs run_case(const anvil::scene::Case& c, const std::string& name) {
  const auto out = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(out);
  anvil::run::run(c, {out.string()});
  return {out.string()};
}

/// A case of homogeneous compression whose answer is known: a 10 mm C45
/// cube (quarter model by its symmetry planes x = 0, y = 0) between
/// frictionless plates, the top one moving down at 10 mm/s for `stop_time`
/// s, meshed at `element_size`; `extra` (YAML, whole top-level sections)
/// asks for what the test checks. Written to <tmp>/`name`.yaml; its path.
inline std::string homogeneous_compression_case(const std::string& name, double element_size, double stop_time,
                                                const std::string& extra) {
  const std::string path = (std::filesystem::temp_directory_path() / (name + ".yaml")).string();
  std::ofstream(path) << "anvil: 1\n"
                         "title: homogeneous compression of a cube between frictionless plates\n"
                         "bodies:\n"
                         "  - name: block\n"
                         "    material: "
                      << source_path("materials/steel_c45_1100C.yaml") << "\n"
                      << "    mesh: {generate: box, size: [10, 10, 10], element_size: " << element_size << "}\n"
                      << "boundary:\n"
                         "  - {name: symmetry_x, type: symmetry, plane: {point: [0, 0, 0], normal: [1, 0, 0]}}\n"
                         "  - {name: symmetry_y, type: symmetry, plane: {point: [0, 0, 0], normal: [0, 1, 0]}}\n"
                         "  - {name: support, type: frictionless_plate, plane: {point: [0, 0, 0], normal: [0, 0, 1]}}\n"
                         "  - {name: press, type: frictionless_plate, plane: {point: [0, 0, 10], normal: [0, 0, 1]}, "
                         "velocity: [0, 0, -10]}\n"
                         "time:\n"
                         "  stroke_increment: 0.25\n"
                         "  stop: {time: "
                      << stop_time << "}\n"
                      << extra;
  return path;
}

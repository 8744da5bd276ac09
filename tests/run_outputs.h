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

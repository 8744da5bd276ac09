// Runs a case into a fresh temporary folder and reads back what it wrote
// (loads.csv, summary.json, checkpoint.h5), for tests.
#pragma once
#include "test_common.h"

#include "anvil/scene/Case.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Simulation.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

struct LoadRow {
  int increment;
  double time, stroke;
  Eigen::Vector3d force;
};

struct RunOutputs {
  std::string directory;

  /// Rows of loads.csv for one surface, in order.
  std::vector<LoadRow> loads(const std::string& surface) const {
    std::ifstream in(directory + "/loads.csv");
    std::vector<LoadRow> rows;
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
      std::vector<std::string> cols;
      std::istringstream s(line);
      for (std::string col; std::getline(s, col, ',');) cols.push_back(col);
      REQUIRE(cols.size() == 7);
      if (cols[2] != surface) continue;
      rows.push_back({std::stoi(cols[0]), std::stod(cols[1]), std::stod(cols[3]),
                      {std::stod(cols[4]), std::stod(cols[5]), std::stod(cols[6])}});
    }
    return rows;
  }

  /// The first number after "key": in summary.json.
  double summary_number(const std::string& key) const {
    std::ifstream in(directory + "/summary.json");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("\"" + key + "\": ");
    REQUIRE(at != std::string::npos);
    return std::stod(text.substr(at + key.size() + 4));
  }

  /// The last checkpoint (time-stepping runs write one at the end).
  anvil::scene::RunState final_state() const { return anvil::scene::read_checkpoint(directory + "/checkpoint.h5"); }
};

/// Runs `c` into <tmp>/<name> (emptied first).
inline RunOutputs run_case(const anvil::scene::Case& c, const std::string& name) {
  const auto out = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(out);
  anvil::scene::run(c, {out.string()});
  return {out.string()};
}

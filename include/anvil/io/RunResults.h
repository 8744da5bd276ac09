// Reading back what a run wrote (loads.csv, summary.json): for the tests and
// for tools/study, which judge runs by their outputs as a user would.
#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

namespace anvil::io {

/// One row of loads.csv.
struct LoadRow {
  int increment = 0;
  double time = 0.0;   ///< s, end of the increment
  double stroke = 0.0; ///< mm, of the surface, end of the increment
  Eigen::Vector3d force = Eigen::Vector3d::Zero(); ///< N, on the body's model (quarter model: a quarter)
};

/// The rows of `directory`/loads.csv for one surface, in order. Throws
/// InputError naming file and line when the file is missing or malformed.
std::vector<LoadRow> read_loads(const std::string& directory, const std::string& surface);

/// The first number after "key": in `directory`/summary.json. Throws
/// InputError when the key is absent.
double read_summary_number(const std::string& directory, const std::string& key);

} // namespace anvil::io

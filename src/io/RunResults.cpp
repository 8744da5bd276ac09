#include "anvil/io/RunResults.h"

#include "anvil/core/error.h"

#include <fstream>
#include <iterator>
#include <sstream>

namespace anvil::io {

std::vector<LoadRow> read_loads(const std::string& directory, const std::string& surface) {
  const std::string path = directory + "/loads.csv";
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  std::vector<LoadRow> rows;
  std::string line;
  std::getline(in, line); // header
  for (int number = 2; std::getline(in, line); ++number) {
    std::vector<std::string> cols;
    std::istringstream split(line);
    for (std::string col; std::getline(split, col, ',');) cols.push_back(col);
    try {
      if (cols.size() != 7) throw std::invalid_argument("columns");
      if (cols[2] != surface) continue;
      rows.push_back({std::stoi(cols[0]), std::stod(cols[1]), std::stod(cols[3]),
                      {std::stod(cols[4]), std::stod(cols[5]), std::stod(cols[6])}});
    } catch (const std::exception&) {
      throw InputError(where(path, number) +
                       ": expected increment,time_s,surface,stroke_mm,Fx_N,Fy_N,Fz_N, got '" + line + "'");
    }
  }
  return rows;
}

double read_summary_number(const std::string& directory, const std::string& key) {
  const std::string path = directory + "/summary.json";
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string quoted = "\"" + key + "\": ";
  const auto at = text.find(quoted);
  if (at == std::string::npos) throw InputError(path + ": no key '" + key + "'");
  try {
    return std::stod(text.substr(at + quoted.size()));
  } catch (const std::exception&) {
    throw InputError(path + ": key '" + key + "' is not a number");
  }
}

} // namespace anvil::io

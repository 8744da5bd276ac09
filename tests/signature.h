// A case's regression signature: per written increment (each .vtu of the
// bodies), the stroke, the load on every load surface, the volume, the
// largest ε̄ and the Newton iterations, read from what the run wrote as a
// user would. Shared by the regression test and tools/update_signatures.
#pragma once
#include "anvil/core/error.h"
#include "anvil/io/RunResults.h"
#include "anvil/run/Simulation.h"
#include "anvil/run/chain.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Chain.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace signature {

/// Runs the case at `path` as the signature does, into `directory` (emptied
/// first), and returns the folder of the run it signs. A time-stepping case
/// runs its first 10 increments (the whole runs are the hard tier's), any
/// other as it is. A chain (docs/chains.md) runs to its first forging
/// operation, that one for its first 10 increments, where the chain stops:
/// what follows a forging is the hard tier's (tests/hard), and the chains'
/// own mechanics the verification tier's.
inline std::string run(const std::string& path, const std::string& directory) {
  std::filesystem::remove_all(directory);
  const anvil::scene::Chain chain = anvil::scene::read_chain(path);
  if (!chain.is_chain()) {
    const anvil::scene::Case& c = chain.operations.front().input;
    anvil::run::run(c.time.enabled ? anvil::scene::read_case(path, {"time.max_increments=10"}) : c, {directory});
    return directory;
  }
  for (std::size_t k = 0; k < chain.operations.size(); ++k)
    if (chain.operations[k].kind == anvil::scene::OperationKind::forge) {
      const std::string cut = "operations[" + std::to_string(k) + "].time.max_increments=10";
      anvil::run::run_chain(anvil::scene::read_chain(path, {cut}), {directory});
      return directory + "/" + anvil::run::operation_folder(chain, static_cast<int>(k));
    }
  throw anvil::InputError(path + ": a chain without a forging operation has no signature (no load)");
}

struct Row {
  int increment = 0;
  double stroke = 0.0;       ///< mm, of the first load surface
  double volume = 0.0;       ///< mm³, all bodies
  double max_strain = 0.0;   ///< largest ε̄
  int newton = 0;            ///< Newton iterations of the increment
  std::vector<double> loads; ///< press load |Fz| (N) per surface, in `Signature::surfaces` order
};

struct Signature {
  std::vector<std::string> surfaces;
  std::vector<Row> rows;
};

/// The signature of the run in `directory`.
inline Signature of_run(const std::string& directory) {
  Signature sig;
  // loads.csv: io::kLoadsHeader
  std::map<int, std::map<std::string, std::pair<double, double>>> loads; // increment → surface → (stroke, |Fz|)
  std::ifstream csv(directory + "/loads.csv");
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = anvil::io::csv_fields(line);
    if (f.size() != anvil::io::kLoadsColumns)
      throw anvil::InputError(directory + "/loads.csv: a row without " + std::to_string(anvil::io::kLoadsColumns) +
                              " fields: " + line);
    if (std::find(sig.surfaces.begin(), sig.surfaces.end(), f[2]) == sig.surfaces.end()) sig.surfaces.push_back(f[2]);
    const double force = std::abs(std::stod(f[6])); // the press load (LoadRecord::press_load)
    loads[std::stoi(f[0])][f[2]] = {std::stod(f[3]), force};
  }
  // summary.json: "iterations_per_increment": {"newton": [n1, n2, ...]
  std::ifstream json(directory + "/summary.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  const auto list = text.find("\"newton\": [");
  if (list == std::string::npos)
    throw anvil::InputError(directory + "/summary.json: no Newton iterations per increment");
  std::vector<int> newton;
  std::istringstream numbers(text.substr(list + 11, text.find(']', list) - list - 11));
  for (std::string n; std::getline(numbers, n, ',');)
    newton.push_back(std::stoi(n));
  for (const anvil::io::WrittenIncrement& w : anvil::io::read_written_increments(directory)) {
    Row row{w.increment, 0.0, w.volume, w.max_equivalent_strain, newton.at(w.increment - 1), {}};
    const auto& at = loads.at(w.increment);
    row.stroke = at.at(sig.surfaces.front()).first;
    for (const std::string& s : sig.surfaces)
      row.loads.push_back(at.at(s).second);
    sig.rows.push_back(row);
  }
  return sig;
}

inline std::string to_csv(const Signature& sig) {
  std::ostringstream out;
  out.precision(10);
  out << "increment,stroke_mm,volume_mm3,max_strain,newton";
  for (const std::string& s : sig.surfaces)
    out << ",load_" << s << "_N";
  out << "\n";
  for (const Row& r : sig.rows) {
    out << r.increment << "," << r.stroke << "," << r.volume << "," << r.max_strain << "," << r.newton;
    for (double f : r.loads)
      out << "," << f;
    out << "\n";
  }
  return out.str();
}

/// Reads a signature written by to_csv. Throws InputError.
inline Signature read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw anvil::InputError(path + ": no reference signature (tools/update_signatures writes it)");
  Signature sig;
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = anvil::io::csv_fields(line);
  for (std::size_t k = 5; k < header.size(); ++k)
    sig.surfaces.push_back(header[k].substr(5, header[k].size() - 7));
  while (std::getline(in, line)) {
    const std::vector<std::string> f = anvil::io::csv_fields(line);
    if (f.size() != header.size()) throw anvil::InputError(path + ": a row of another width: " + line);
    Row r{std::stoi(f[0]), std::stod(f[1]), std::stod(f[2]), std::stod(f[3]), std::stoi(f[4]), {}};
    for (std::size_t k = 5; k < f.size(); ++k)
      r.loads.push_back(std::stod(f[k]));
    sig.rows.push_back(r);
  }
  return sig;
}

} // namespace signature

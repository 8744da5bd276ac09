#include "anvil/solver/KeptSetUp.h"

#include "anvil/core/processes.h"

namespace anvil::solver {

KeptSetUp gather_kept(KeptSetUp own) {
  if (processes::count() == 1) return own;
  // A process without entries (its part of another run's record) sends none.
  std::vector<double> entries;
  if (!own.entries.empty()) entries = std::move(own.entries.front());
  std::vector<std::vector<double>> all = processes::gather(entries);
  std::vector<double> patterns;
  for (const std::vector<double>& p : processes::gather(own.patterns))
    patterns.insert(patterns.end(), p.begin(), p.end());
  if (!processes::root()) return {};
  // Rank 0's record decides: every process's solver keeps a set-up or none alike.
  own.entries.clear();
  own.patterns.clear();
  if (!entries.empty() || !patterns.empty()) {
    own.entries = std::move(all);
    own.patterns = std::move(patterns);
  }
  return own;
}

} // namespace anvil::solver

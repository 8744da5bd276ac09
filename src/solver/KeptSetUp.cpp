#include "anvil/solver/KeptSetUp.h"

#include "anvil/core/processes.h"

namespace anvil::solver {

KeptSetUp gather_kept(KeptSetUp own) {
  if (processes::count() == 1) return own;
  // Every process has a record or none alike: their solvers take the same
  // decisions (each set-up and fallback is decided on reduced numbers).
  const std::vector<double> entries = own.entries.empty() ? std::vector<double>() : std::move(own.entries.front());
  std::vector<std::vector<double>> all = processes::gather(entries);
  std::vector<double> patterns;
  for (const std::vector<double>& p : processes::gather(own.patterns))
    patterns.insert(patterns.end(), p.begin(), p.end());
  if (!processes::root() || own.empty()) return {};
  own.entries = std::move(all);
  own.patterns = std::move(patterns);
  return own;
}

} // namespace anvil::solver

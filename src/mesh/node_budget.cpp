#include "anvil/mesh/node_budget.h"

#include "anvil/core/error.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace anvil::mesh {

double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

double affordable_nodes() {
  const double memory = physical_memory();
  constexpr double kIndexLimit = 2147483647.0 / 4.0; // 4 unknowns a node, 32-bit row indices
  return std::min(memory > 0.0 ? memory / kRunBytesPerNode : kIndexLimit, kIndexLimit);
}

void check_node_budget(double nodes, const std::string& where) {
  const double memory = physical_memory();
  const double affordable = affordable_nodes();
  if (!(nodes <= affordable)) {
    char text[400];
    std::snprintf(text, sizeof text,
                  ": would make about %.3g nodes; a run needs about %.0f kB a node (%.3g GB) and this machine has "
                  "%.3g GB of memory, enough for about %.3g nodes",
                  nodes, kRunBytesPerNode / 1e3, nodes * kRunBytesPerNode / 1e9, memory / 1e9, affordable);
    throw InputError(where + text);
  }
}

} // namespace anvil::mesh

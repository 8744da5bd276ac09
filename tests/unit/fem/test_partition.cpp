// The partition of a mesh among processes (fem::Partition): what the
// distributed assembly relies on, checked for 1 to 4 processes.
#include "anvil/fem/Partition.h"
#include "anvil/mesh/generators.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace anvil;

TEST_CASE("a partition gives each element to one process and each process a contiguous block of its own nodes",
          "[unit][partition]") {
  const mesh::TetMesh box = mesh::make_box({0, 0, 0}, {3, 2, 1}, std::array<int, 3>{9, 6, 3});
  for (int processes = 1; processes <= 4; ++processes) {
    INFO(processes << " processes");
    std::vector<int> element_owners(box.tets.size(), 0), node_owners(box.nodes.size(), 0);
    int next_first = 0;
    for (int process = 0; process < processes; ++process) {
      const fem::Partition p = fem::partition_mesh(box, processes, process);
      // The numbering is a permutation and `node` its inverse.
      for (int n = 0; n < box.node_count(); ++n)
        REQUIRE(p.node[p.number[n]] == n);
      // Owned blocks follow one another from 0.
      REQUIRE(p.first == next_first);
      REQUIRE(p.end > p.first);
      next_first = p.end;
      for (int e : p.elements)
        ++element_owners[e];
      // Every node a process owns is a node of one of its elements.
      std::vector<char> in_part(box.nodes.size(), 0);
      for (int e : p.elements)
        for (int v : box.tets[e])
          in_part[v] = 1;
      for (int n = 0; n < box.node_count(); ++n)
        if (p.owns(n)) {
          REQUIRE(in_part[n]);
          ++node_owners[n];
        }
      // Balanced elements: the bisection splits in proportion.
      const double share = static_cast<double>(box.tets.size()) / processes;
      CHECK(std::abs(static_cast<double>(p.elements.size()) - share) <= 1.0);
    }
    CHECK(next_first == box.node_count());
    CHECK(std::all_of(element_owners.begin(), element_owners.end(), [](int k) { return k == 1; }));
    CHECK(std::all_of(node_owners.begin(), node_owners.end(), [](int k) { return k == 1; }));
  }
}

// The active set of a penalty contact term (contact/ActiveSet.h): checked at
// Newton's convergence, updated beyond its tolerance, a cycle between two
// sets ended by their union.
#include "test_common.h"

#include "anvil/contact/ActiveSet.h"

#include <vector>

using anvil::contact::ActiveSet;

namespace {

std::vector<int> members(const ActiveSet& set) {
  std::vector<int> in;
  for (std::size_t i = 0; i < set.size(); ++i)
    if (set[i]) in.push_back(static_cast<int>(i));
  return in;
}

} // namespace

TEST_CASE(
    "An active set that agrees with its gap velocities at convergence is kept, and one beyond the tolerance changes",
    "[unit][contact]") {
  ActiveSet set;
  set.resize(3);
  set.set_tolerance(0.1);
  set.start({1.0, 1.0, -1.0}); // closing, closing, opening
  CHECK(members(set) == std::vector<int>{0, 1});
  CHECK(set.consistent({0.5, -0.05, -0.05})); // within the tolerance: a touching node stays, a free one stays free
  CHECK(!set.consistent({0.5, -0.5, 0.5}));   // tensile node 1 released, node 2 penetrating added
  CHECK(members(set) == std::vector<int>{0, 2});
}

TEST_CASE("A cycle between two active sets at convergence ends with their union, accepted once Newton converges",
          "[unit][contact]") {
  // Node 2 at the edge of contact: tensile with it (released), penetrating
  // without it (added), over and over but for the cycle rule.
  const std::vector<double> with_node_2{1.0, 1.0, -0.5}, without_node_2{1.0, 1.0, 0.5};
  ActiveSet set;
  set.resize(3);
  set.set_tolerance(0.1);
  set.start({1.0, 1.0, 1.0});
  REQUIRE(members(set) == std::vector<int>{0, 1, 2});
  CHECK(!set.consistent(with_node_2)); // converged with {0, 1, 2}: node 2 is released
  CHECK(members(set) == std::vector<int>{0, 1});
  // Converged with {0, 1}: node 2 asks back in, a set already converged
  // with: the union {0, 1, 2}, one more Newton run ...
  CHECK(!set.consistent(without_node_2));
  CHECK(members(set) == std::vector<int>{0, 1, 2});
  CHECK(set.consistent(with_node_2)); // ... whose result is accepted, node 2's tension and all
  CHECK(members(set) == std::vector<int>{0, 1, 2});
  // A new increment starts without the history.
  set.start({1.0, 1.0, 1.0});
  CHECK(!set.consistent(with_node_2));
}

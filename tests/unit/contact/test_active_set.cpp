// The active set of a penalty contact term (contact/ActiveSet.h): checked at
// Newton's convergence, updated beyond its tolerance, a cycle between two
// sets ended by their union, a release that penetrates at once held;
// near convergence, moved only to a set not yet had in the increment.
#include "test_common.h"

#include "anvil/contact/ActiveSet.h"

#include <vector>

using anvil::contact::ActiveSet;

namespace {

/// Accepted iterates at `gap` until the set no longer follows them.
void freeze(ActiveSet& set, const std::vector<double>& gap) {
  while (set.following())
    set.accept(gap, "nodes");
}

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
  CHECK(
      set.consistent({0.5, -0.05, -0.05}, true)); // within the tolerance: a touching node stays, a free one stays free
  CHECK(!set.consistent({0.5, -0.5, 0.5}, true)); // tensile node 1 released, node 2 penetrating added
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
  CHECK(!set.consistent(with_node_2, true)); // converged with {0, 1, 2}: node 2 is released
  CHECK(members(set) == std::vector<int>{0, 1});
  // Converged with {0, 1}: node 2 asks back in, a set already converged
  // with: the union {0, 1, 2}, one more Newton run ...
  CHECK(!set.consistent(without_node_2, true));
  CHECK(members(set) == std::vector<int>{0, 1, 2});
  CHECK(set.consistent(with_node_2, true)); // ... whose result is accepted, node 2's tension and all
  CHECK(members(set) == std::vector<int>{0, 1, 2});
  // A new increment starts without the history.
  set.start({1.0, 1.0, 1.0});
  CHECK(!set.consistent(with_node_2, true));
}

TEST_CASE("Near convergence an active set moves beyond the last step's reach to a set it has not had, and leaves a "
          "return to the check at convergence",
          "[unit][contact]") {
  // A contact zone's edge receding: node 2 tensile, then node 1 once 2 is free.
  ActiveSet set;
  set.resize(3);
  set.set_tolerance(0.1);
  set.start({1.0, 1.0, 1.0});
  freeze(set, {1.0, 1.0, 0.3}); // from here on only the checks change it
  set.accept({1.0, 1.0, -0.3}, "nodes");
  // h of node 2 is -0.3 but the last step moved it by 0.6: it may yet be in contact.
  CHECK(set.consistent({1.0, 1.0, -0.3}, false));
  CHECK(members(set) == std::vector<int>{0, 1, 2});
  set.accept({1.0, 1.0, -0.25}, "nodes");
  CHECK(!set.consistent({1.0, 1.0, -0.25}, false)); // beyond the tolerance by more than the step: released at once
  CHECK(members(set) == std::vector<int>{0, 1});
  set.accept({1.0, -0.5, -0.5}, "nodes"); // node 2 separates: its release stands
  set.accept({1.0, -0.5, 0.5}, "nodes");
  set.accept({1.0, -0.5, 0.5}, "nodes");
  CHECK(!set.consistent({1.0, -0.5, 0.5}, false)); // node 1 released; node 2 asks back in, to a set not had
  CHECK(members(set) == std::vector<int>{0, 2});
  // The set {0, 1} was had: a move back to it waits for convergence ...
  set.accept({1.0, 0.0, 0.5}, "nodes");
  set.accept({1.0, 1.0, -0.5}, "nodes");
  set.accept({1.0, 1.0, -0.5}, "nodes");
  CHECK(set.consistent({1.0, 1.0, -0.5}, false));
  CHECK(members(set) == std::vector<int>{0, 2});
  // ... where it is taken, and the cycle rule counts only converged sets:
  // {0, 2} converged, {0, 1} not yet.
  CHECK(!set.consistent({1.0, 1.0, -0.5}, true));
  CHECK(members(set) == std::vector<int>{0, 1});
  CHECK(set.consistent({1.0, 1.0, -0.05}, true));
}

TEST_CASE("A constraint a check releases that penetrates at the next iterate is put back and held for the increment",
          "[unit][contact]") {
  // Node 2 against a die corner: tensile within the set, and once released
  // the first step drives it into the die.
  ActiveSet set;
  set.resize(3);
  set.set_tolerance(0.1);
  set.start({1.0, 1.0, 1.0});
  freeze(set, {1.0, 1.0, 1.0});
  CHECK(!set.consistent({1.0, 1.0, -0.5}, true)); // converged: node 2 tensile, released
  CHECK(members(set) == std::vector<int>{0, 1});
  set.accept({1.0, 1.0, 0.5}, "nodes"); // penetrating one step on: back in
  CHECK(set.last_changes() == 1);
  CHECK(members(set) == std::vector<int>{0, 1, 2});
  CHECK(set.consistent({1.0, 1.0, -0.5}, true)); // held: its tension is accepted
  CHECK(set.consistent({1.0, 1.0, -0.5}, false));
  CHECK(members(set) == std::vector<int>{0, 1, 2});

  // Only the first iterate after the release decides; a new increment forgets the hold.
  set.start({1.0, 1.0, 1.0});
  freeze(set, {1.0, 1.0, 1.0});
  CHECK(!set.consistent({1.0, 1.0, -0.5}, true));
  set.accept({1.0, 1.0, -0.05}, "nodes"); // not penetrating: the release stands
  set.accept({1.0, 1.0, 0.5}, "nodes");   // frozen: a later penetration waits for the check
  CHECK(set.last_changes() == 0);
  CHECK(members(set) == std::vector<int>{0, 1});
}

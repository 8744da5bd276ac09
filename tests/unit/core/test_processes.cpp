// processes::share_out: each item computed once, by one process, and every
// process given every value, bit for bit as one process computes them; inside
// on_root's work rank 0 computes them all alone. On one process (the unit
// tier) the plain case; the mpi tier runs these tests on 2 and 3 processes.
#include "test_common.h"

#include "anvil/core/processes.h"

#include <cmath>
#include <vector>

using namespace anvil;

namespace {

/// Item i's two values: round-off-heavy numbers, so that any change of sum shows.
void item_values(int i, double* values) {
  values[0] = std::sin(0.1 * i) / 3.0;
  values[1] = std::exp(-0.01 * i) * 1e-7 + 1.0 / (i + 1.0);
}

} // namespace

TEST_CASE("share_out: every process gets every value, each computed once", "[unit][processes]") {
  constexpr int kItems = 101;
  std::vector<double> computed_here(kItems, 0.0);
  const std::vector<double> values = processes::share_out(kItems, 2, [&](int i, double* out) {
    item_values(i, out);
    computed_here[i] += 1.0;
  });
  REQUIRE(values.size() == 2 * kItems);
  for (int i = 0; i < kItems; ++i) {
    double expected[2];
    item_values(i, expected);
    CHECK(values[2 * i] == expected[0]); // the same bits: the other processes add zeros
    CHECK(values[2 * i + 1] == expected[1]);
  }
  processes::sum(computed_here);
  for (int i = 0; i < kItems; ++i)
    CHECK(computed_here[i] == 1.0);
}

TEST_CASE("share_out inside on_root: rank 0 computes every item alone", "[unit][processes]") {
  constexpr int kItems = 7;
  const bool whole = processes::on_root_answer([&] {
    int calls = 0;
    const std::vector<double> values = processes::share_out(kItems, 2, [&](int i, double* out) {
      item_values(i, out);
      ++calls;
    });
    double expected[2];
    item_values(kItems - 1, expected);
    return calls == kItems && values[2 * kItems - 1] == expected[1];
  });
  CHECK(whole);
}

// A Newton that runs out of its iteration budget while its residual falls
// gets a second budget at the same Δt before the increment is cut, and goes
// on with the same state: runs whose round-off (another process count,
// another thread count) puts one increment just past the budget keep their
// increments at the same strokes and follow the same Newton path.
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/scene/Case.h"
#include "run_outputs.h"

#include <algorithm>
#include <cmath>

using namespace anvil;

TEST_CASE("Newton past its budget with a falling residual finishes the increment at the same stroke", "[hard]") {
  log::set_quiet(true);
  // The upsetting's third increment, where the billet's bulge rolls onto the
  // dies, takes 19 Newton iterations, 9 before its active set first changes:
  // a budget of 6 runs out on the way.
  const std::string path = source_path("cases/upsetting.yaml");
  const scene::Case roomy = scene::read_case(path, {"time.max_increments=3"});
  scene::Case tight = roomy;
  tight.newton.max_iterations = 6;
  const RunOutputs a = run_case(roomy, "anvil_newton_budget_roomy");
  const RunOutputs b = run_case(tight, "anvil_newton_budget_6");
  REQUIRE(file_text(b.directory + "/anvil.log").find("a second budget") != std::string::npos); // it did run out
  const std::vector<LoadRow> ra = a.loads("top"), rb = b.loads("top");
  REQUIRE(ra.size() == 4); // the loads at the start of each increment, and at the stroke the run ends on
  REQUIRE(rb.size() == ra.size());
  double peak = 0.0;
  for (const LoadRow& r : ra)
    peak = std::max(peak, std::abs(r.force.z()));
  for (std::size_t i = 0; i < ra.size(); ++i) {
    INFO("row " << i << ": " << rb[i].force.z() << " N against " << ra[i].force.z() << " N");
    // Not cut: the same Δt, so the same stroke (a cut moves it by half an
    // increment, 0.075 mm; 1e-9 is the file's round-off).
    CHECK(std::abs(rb[i].stroke - ra[i].stroke) <= 1e-9 * ra[i].stroke);
    // One Newton path: the second budget goes on with the first's active
    // set, phase and forcing (1e-9 is the file's round-off).
    CHECK(std::abs(rb[i].force.z() - ra[i].force.z()) <= 1e-9 * peak);
  }
}

// Ring compression 6:3:2 to 50 %: the inner diameter grows
// without friction (exactly as sqrt(H0/H): the flow is homogeneous), and
// shrinks more as the Tresca factor m̄ rises (Male & Cockcroft 1964).
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/mesh/generators.h"
#include "anvil/scene/Case.h"
#include "run_outputs.h"

#include <cmath>
#include <vector>

using namespace anvil;

namespace {

/// Smallest and largest final radius of the nodes that started on the inner
/// surface, for the ring case with Tresca factor `factor` on both dies.
std::pair<double, double> inner_radius_range(double factor) {
  const std::string change = "dies[].friction.factor=" + std::to_string(factor);
  scene::Case c = scene::read_case(source_path("cases/ring_compression.yaml"), {change});
  c.write_vtk = false;
  const scene::MeshSpec& m = c.bodies.front().mesh;
  const mesh::TetMesh start = mesh::make_quarter_ring(m.radius, m.inner_radius, m.height, m.element_size);
  const RunOutputs out = run_case(c, "anvil_ring_" + std::to_string(factor));
  CHECK(out.loads("top").back().stroke == Approx(5.0).epsilon(1e-9));
  const scene::RunState end = out.final_state();
  REQUIRE(end.mesh.nodes.size() == start.nodes.size());
  double smallest = 1e300, largest = 0.0;
  for (std::size_t n = 0; n < start.nodes.size(); ++n) {
    if (std::abs(std::hypot(start.nodes[n].x(), start.nodes[n].y()) - m.inner_radius) > 1e-9) continue;
    const double r = std::hypot(end.mesh.nodes[n].x(), end.mesh.nodes[n].y());
    smallest = std::min(smallest, r), largest = std::max(largest, r);
  }
  return {smallest, largest};
}

} // namespace

TEST_CASE("ring compression: the inner diameter grows without friction and shrinks with m = 0.3 and 0.5",
          "[verification]") {
  log::set_quiet(true);
  constexpr double kInner = 7.5, kHeight = 10.0, kFinalHeight = 5.0; // cases/ring_compression.yaml
  const std::vector<double> factors{0.0, 0.1, 0.3, 0.5};
  std::vector<double> change;
  for (double factor : factors) {
    const auto [smallest, largest] = inner_radius_range(factor);
    change.push_back(smallest / kInner - 1.0);
    INFO("m = " << factor << ": inner radius " << smallest << " to " << largest << " mm");
    CHECK(smallest > 0.0);
    if (factor == 0.0) {
      // Homogeneous flow: the P1 field is exact, so the bound is the volume
      // change (radius ∝ sqrt(volume)) and the 0.5 % radius bound.
      const double exact = kInner * std::sqrt(kHeight / kFinalHeight);
      CHECK(std::abs(smallest - exact) / exact < 0.005);
      CHECK(std::abs(largest - exact) / exact < 0.005);
    }
  }
  INFO("inner-diameter change at m = 0, 0.1, 0.3, 0.5: " << change[0] << ", " << change[1] << ", " << change[2] << ", "
                                                         << change[3]);
  CHECK(change[0] > 0.0);
  CHECK(change[1] < change[0]);
  CHECK(change[2] < change[1]);
  CHECK(change[3] < change[2]);
  CHECK(change[2] < 0.0);
  CHECK(change[3] < 0.0);
  WARN("ring: inner-diameter change " << 100 * change[0] << " %, " << 100 * change[1] << " %, " << 100 * change[2]
                                      << " %, " << 100 * change[3] << " % at m = 0, 0.1, 0.3, 0.5");
}

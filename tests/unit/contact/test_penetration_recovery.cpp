// The velocity gap of die contact, h = −(v − v_die)·n − δ₀/t: an open gap
// closes within Δt, a penetration is removed over at least the nominal step
// and no faster than the recovery speed (ContactIncrement::closing_time), so
// halving Δt does not hasten the push-out.
#include "anvil/contact/RigidContact.h"
#include "anvil/fem/DofMap.h"
#include "anvil/mesh/generators.h"

#include <catch2/catch.hpp>
#include <limits>

using namespace anvil;

namespace {

/// Contact pressure σn (MPa) of the candidate on `node` moving at `velocity_z`
/// (mm/s, every other node at rest), in an increment Δt.
double pressure(const mesh::TetMesh& block, const die::DieSurface& die, int node, double velocity_z, double time_step,
                double recovery_speed = std::numeric_limits<double>::infinity()) {
  contact::RigidContact contact;
  contact.search(block, {{&die, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), {}}}, 1.0);
  const double penalty = 10.0, nominal_step = 1.0;
  contact.set_increment({.time_step = time_step,
                         .penalty = penalty,
                         .regularisation = 1e-3,
                         .gap_tolerance = 1e-9,
                         .recovery_time = nominal_step,
                         .recovery_speed = recovery_speed});
  Eigen::VectorXd nodal = Eigen::VectorXd::Zero(fem::kDofsPerNode * block.node_count());
  nodal[fem::kDofsPerNode * node + 2] = velocity_z;
  for (std::size_t i = 0; i < contact.candidates().size(); ++i)
    if (contact.candidates()[i].node == node) return contact.pressure(static_cast<int>(i), nodal);
  FAIL("node " << node << " is not a contact candidate");
  return 0.0;
}

} // namespace

TEST_CASE("A node inside a die is pushed out over the nominal step and no faster than the recovery speed, an open gap "
          "closes within the step",
          "[unit][contact]") {
  // A unit cube on the die z = 0 (die below, outward normal +z); one bottom
  // corner 0.2 mm inside, another 0.1 mm above.
  mesh::TetMesh block = mesh::make_box({0, 0, 0}, {1, 1, 1}, {1, 1, 1});
  int inside = -1, above = -1;
  for (int i = 0; i < block.node_count(); ++i) {
    if (block.nodes[i] == mesh::Point(0, 0, 0)) inside = i;
    if (block.nodes[i] == mesh::Point(1, 1, 0)) above = i;
  }
  REQUIRE(inside >= 0);
  REQUIRE(above >= 0);
  block.nodes[inside].z() = -0.2;
  block.nodes[above].z() = 0.1;
  const die::PlaneSurface die({0, 0, 0}, {0, 0, 1}, 10.0);
  // Penetration, at rest: σn = ρ |δ₀| / max(Δt, nominal) = 10 × 0.2 / 1 at
  // Δt = 1 and at Δt = 0.25 (within Δt it would be 8).
  CHECK(pressure(block, die, inside, 0.0, 1.0) == Approx(2.0).epsilon(1e-12));
  CHECK(pressure(block, die, inside, 0.0, 0.25) == Approx(2.0).epsilon(1e-12));
  // Open gap, closing at 0.2 mm/s: h = 0.2 − 0.1/Δt, σn = ρ h = 1 at Δt = 1;
  // at Δt = 0.25 the node does not reach the die (h < 0, released).
  CHECK(pressure(block, die, above, -0.2, 1.0) == Approx(1.0).epsilon(1e-12));
  CHECK(pressure(block, die, above, -0.2, 0.25) == 0.0);
  // A recovery speed of 0.05 mm/s: 0.2 mm inside takes 4 s, not the nominal
  // 1 s, so σn = 10 × 0.2 / 4; an open gap does not see it.
  CHECK(pressure(block, die, inside, 0.0, 1.0, 0.05) == Approx(0.5).epsilon(1e-12));
  CHECK(pressure(block, die, above, -0.2, 1.0, 0.05) == Approx(1.0).epsilon(1e-12));
}

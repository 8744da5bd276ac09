// The directions a penalty holds at a node (solver/held_directions.h): a
// contact node's die normal leaves the velocity AMG's modes, the body's own
// flow does not, a node held in every direction keeps none.
#include "test_common.h"

#include "anvil/solver/held_directions.h"

using anvil::solver::free_directions;
using anvil::solver::kHeldDominance;

namespace {
/// A node's velocity block: the viscous part η I plus a penalty ρ n nᵀ.
Eigen::Matrix3d block(double eta, double rho, const Eigen::Vector3d& n) {
  return eta * Eigen::Matrix3d::Identity() + rho * n * n.transpose();
}
} // namespace

TEST_CASE("a penalty far above a node's couplings holds its normal, and only it", "[unit]") {
  const double eta = 2.0, couplings = 2.5; // an interior node: its block about its couplings
  const Eigen::Vector3d n = Eigen::Vector3d(1.0, 2.0, -0.5).normalized(); // a drafted wall: not along an axis
  const Eigen::Matrix3d free = free_directions(block(eta, 1000.0, n), couplings);
  // Exactly the projector off n, to round-off of the 3×3 eigensolver.
  CHECK((free - (Eigen::Matrix3d::Identity() - n * n.transpose())).norm() < 1e-12);
  CHECK((free * n).norm() < 1e-12);
}

TEST_CASE("a node of the body's own flow keeps every direction", "[unit]") {
  const Eigen::Vector3d n(0.0, 0.0, 1.0);
  // No penalty, and a penalty just below the threshold: nothing held.
  CHECK(free_directions(block(2.0, 0.0, n), 2.5) == Eigen::Matrix3d::Identity());
  CHECK(free_directions(block(1.0, kHeldDominance - 2.0, n), 1.0) == Eigen::Matrix3d::Identity());
}

TEST_CASE("a sticking node keeps no direction, and an unsymmetric block is read by its symmetric part", "[unit]") {
  // Sticking friction's penalty on the tangential velocity and the contact
  // penalty on the normal: ρ I.
  CHECK(free_directions(block(1.0, 0.0, Eigen::Vector3d::UnitX()) * 500.0, 1.0).norm() < 1e-12);
  // A node without couplings to other nodes (a row the case fixes) is held whatever its block.
  CHECK(free_directions(Eigen::Matrix3d::Identity(), 0.0).norm() < 1e-12);
  // Coulomb friction's tangent is unsymmetric: the skew part moves no eigenvector.
  const Eigen::Vector3d n = Eigen::Vector3d(0.0, 1.0, 1.0).normalized();
  Eigen::Matrix3d skew;
  skew << 0.0, 3.0, 0.0, -3.0, 0.0, 0.0, 0.0, 0.0, 0.0;
  const Eigen::Matrix3d free = free_directions(block(1.0, 1000.0, n) + skew, 1.0);
  CHECK((free - (Eigen::Matrix3d::Identity() - n * n.transpose())).norm() < 1e-12);
}

#include "anvil/solver/held_directions.h"

#include <Eigen/Eigenvalues>

namespace anvil::solver {

Eigen::Matrix3d free_directions(const Eigen::Matrix3d& block, double couplings) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(0.5 * (block + block.transpose()));
  Eigen::Matrix3d projector = Eigen::Matrix3d::Identity();
  for (int e = 0; e < 3; ++e)
    if (eigen.eigenvalues()[e] > kHeldDominance * couplings)
      projector -= eigen.eigenvectors().col(e) * eigen.eigenvectors().col(e).transpose();
  return projector;
}

} // namespace anvil::solver

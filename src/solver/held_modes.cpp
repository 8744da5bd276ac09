#include "held_modes.h"

#include "anvil/fem/DofMap.h"
#include "anvil/solver/held_directions.h"
#include "petsc_check.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace anvil::solver::petsc {

namespace {

constexpr const char* kDoing = "setting the velocity block's near-null space";

/// The projector onto the directions left free at the node whose velocity
/// rows start at `row` (held_directions.h).
Eigen::Matrix3d free_directions_at(Mat system, PetscInt row) {
  Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
  double couplings = 0.0;
  for (int c = 0; c < 3; ++c) {
    PetscInt entries = 0;
    const PetscInt* columns = nullptr;
    const PetscScalar* values = nullptr;
    check(MatGetRow(system, row + c, &entries, &columns, &values), kDoing);
    double outside = 0.0;
    for (PetscInt k = 0; k < entries; ++k) {
      const PetscInt column = columns[k];
      if (column % fem::kDofsPerNode == 3) continue; // a pressure
      if (column >= row && column < row + 3)
        block(c, column - row) = values[k];
      else
        outside += std::abs(values[k]);
    }
    couplings = std::max(couplings, outside);
    check(MatRestoreRow(system, row + c, &entries, &columns, &values), kDoing);
  }
  return free_directions(block, couplings);
}

} // namespace

MatNullSpace held_rigid_body_modes(Mat system, Vec coordinates, int count) {
  MatNullSpace rigid = nullptr;
  check(MatNullSpaceCreateRigidBody(coordinates, &rigid), kDoing); // translations first
  const Vec* rigid_modes = nullptr;
  check(MatNullSpaceGetVecs(rigid, nullptr, nullptr, &rigid_modes), kDoing);
  std::vector<Vec> modes(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    check(VecDuplicate(rigid_modes[k], &modes[k]), kDoing);
    check(VecCopy(rigid_modes[k], modes[k]), kDoing);
  }
  check(MatNullSpaceDestroy(&rigid), kDoing);

  PetscInt first_row = 0, local = 0;
  check(MatGetOwnershipRange(system, &first_row, nullptr), kDoing);
  check(VecGetLocalSize(coordinates, &local), kDoing);
  std::array<PetscScalar*, 6> values{};
  for (int k = 0; k < count; ++k)
    check(VecGetArray(modes[k], &values[k]), kDoing);
  for (PetscInt node = 0; node < local / 3; ++node) {
    const Eigen::Matrix3d free = free_directions_at(system, first_row + fem::kDofsPerNode * node);
    for (int k = 0; k < count; ++k) {
      Eigen::Map<Eigen::Vector3d> at(values[k] + 3 * node);
      at = free * at;
    }
  }
  for (int k = 0; k < count; ++k)
    check(VecRestoreArray(modes[k], &values[k]), kDoing);

  // Gram-Schmidt, twice for round-off: MatNullSpaceCreate wants orthonormal vectors.
  for (int k = 0; k < count; ++k) {
    for (int pass = 0; pass < 2; ++pass)
      for (int j = 0; j < k; ++j) {
        PetscScalar dot = 0.0;
        check(VecDot(modes[j], modes[k], &dot), kDoing);
        check(VecAXPY(modes[k], -dot, modes[j]), kDoing);
      }
    check(VecNormalize(modes[k], nullptr), kDoing);
  }
  MatNullSpace held = nullptr;
  check(MatNullSpaceCreate(PetscObjectComm(reinterpret_cast<PetscObject>(coordinates)), PETSC_FALSE, count,
                           modes.data(), &held),
        kDoing);
  for (Vec& mode : modes)
    check(VecDestroy(&mode), kDoing);
  return held;
}

} // namespace anvil::solver::petsc

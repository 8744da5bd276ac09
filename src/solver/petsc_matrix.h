// A PETSc AIJ view of the assembled tangent (fem::SparseMatrix, compressed
// rows with 32-bit indices): no copy, the Mat reads the Eigen arrays. The
// view follows the storage: when the assembler rebuilds the pattern the
// arrays move, and the next wrap() makes a new Mat.
#pragma once
#include "anvil/fem/Assembler.h"
#include "petsc_check.h"

#include <petscmat.h>

namespace anvil::solver::petsc {

static_assert(sizeof(PetscInt) == sizeof(fem::SparseMatrix::StorageIndex), "PETSc must use 32-bit indices");
static_assert(sizeof(PetscScalar) == sizeof(double), "PETSc must use real double scalars");

class MatrixView {
public:
  MatrixView() = default;
  ~MatrixView() { MatDestroy(&mat_); }
  MatrixView(const MatrixView&) = delete;
  MatrixView& operator=(const MatrixView&) = delete;

  /// Points the Mat at `a`'s arrays (a new Mat when they moved) and tells
  /// PETSc its values changed. Returns true when the Mat is new.
  bool wrap(const fem::SparseMatrix& a) {
    const bool moved = !mat_ || a.outerIndexPtr() != outer_ || a.innerIndexPtr() != inner_ || a.valuePtr() != values_ ||
                       a.rows() != rows_;
    if (moved) {
      MatDestroy(&mat_);
      outer_ = a.outerIndexPtr(), inner_ = a.innerIndexPtr(), values_ = a.valuePtr(),
      rows_ = static_cast<PetscInt>(a.rows());
      check(MatCreateSeqAIJWithArrays(PETSC_COMM_WORLD, rows_, rows_, const_cast<PetscInt*>(outer_),
                                      const_cast<PetscInt*>(inner_), const_cast<PetscScalar*>(values_), &mat_),
            "wrapping the tangent matrix");
      check(MatSetBlockSize(mat_, fem::kDofsPerNode), "setting the matrix block size");
    } else {
      // The values were written in place: assembling again bumps the Mat's
      // state, so preconditioners built on the old values see the change.
      check(MatAssemblyBegin(mat_, MAT_FINAL_ASSEMBLY), "updating the tangent matrix");
      check(MatAssemblyEnd(mat_, MAT_FINAL_ASSEMBLY), "updating the tangent matrix");
    }
    return moved;
  }
  Mat mat() const { return mat_; }

private:
  Mat mat_ = nullptr;
  const int* outer_ = nullptr;
  const int* inner_ = nullptr;
  const double* values_ = nullptr;
  PetscInt rows_ = 0;
};

/// A PETSc Vec without storage of its own: place() lends it an Eigen
/// vector's array for one call (no copy).
class VectorSlot {
public:
  VectorSlot() = default;
  ~VectorSlot() { VecDestroy(&vec_); }
  VectorSlot(const VectorSlot&) = delete;
  VectorSlot& operator=(const VectorSlot&) = delete;

  /// While a Placed lives, vec() reads and writes `v`.
  class Placed {
  public:
    Placed(VectorSlot& slot, const Eigen::VectorXd& v) : slot_(slot) {
      if (!slot_.vec_ || slot_.size_ != v.size()) {
        VecDestroy(&slot_.vec_);
        slot_.size_ = v.size();
        check(VecCreateSeqWithArray(PETSC_COMM_WORLD, 1, static_cast<PetscInt>(v.size()), nullptr, &slot_.vec_),
              "creating a vector");
      }
      check(VecPlaceArray(slot_.vec_, v.data()), "placing a vector");
    }
    ~Placed() { VecResetArray(slot_.vec_); }
    Placed(const Placed&) = delete;
    Placed& operator=(const Placed&) = delete;
    Vec vec() const { return slot_.vec_; }

  private:
    VectorSlot& slot_;
  };

private:
  Vec vec_ = nullptr;
  long size_ = -1;
};

} // namespace anvil::solver::petsc

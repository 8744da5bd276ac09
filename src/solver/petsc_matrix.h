// PETSc views of the assembled tangent (fem::SparseMatrix, compressed rows
// with 32-bit indices) and of the whole-system vectors every process keeps.
// One process: no copy, the Mat and Vec read the Eigen arrays. Several
// (fem::Partition): the Mat is a distributed AIJ matrix whose pattern is the
// entries of this process's elements (MatSetPreallocationCOO, in the
// partition's numbering) and whose values are sent at each update
// (MatSetValuesCOO sums what several processes give one entry); a Vec holds
// this process's rows, copied in from and gathered back into the whole vector.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/fem/Assembler.h"
#include "anvil/fem/Partition.h"
#include "petsc_check.h"

#include <petscmat.h>

#include <algorithm>
#include <span>
#include <vector>

namespace anvil::solver::petsc {

static_assert(sizeof(PetscInt) == sizeof(fem::SparseMatrix::StorageIndex), "PETSc must use 32-bit indices");
static_assert(sizeof(PetscScalar) == sizeof(double), "PETSc must use real double scalars");

/// Row or column of the distributed system of mesh dof `dof`.
inline PetscInt system_index(const fem::Partition& p, int dof) {
  return fem::kDofsPerNode * p.number[dof / fem::kDofsPerNode] + dof % fem::kDofsPerNode;
}

class MatrixView {
public:
  /// The creation of a Mat (a new pattern: once per mesh while the solver
  /// lives) is timed as `timers`' "matrix pattern".
  MatrixView(const fem::Partition& partition, Timers& timers) : partition_(partition), timers_(timers) {}
  ~MatrixView() { MatDestroy(&mat_); }
  MatrixView(const MatrixView&) = delete;
  MatrixView& operator=(const MatrixView&) = delete;

  /// Points the Mat at `a`'s values (a new Mat when its arrays moved) and
  /// tells PETSc they changed. Returns true when the Mat is new.
  bool wrap(const fem::SparseMatrix& a) {
    const bool moved = !mat_ || a.outerIndexPtr() != outer_ || a.innerIndexPtr() != inner_ || a.valuePtr() != values_ ||
                       a.rows() != rows_ || a.nonZeros() != entries_;
    if (moved) {
      Timers::Scope scope(timers_, "matrix pattern");
      MatDestroy(&mat_);
      outer_ = a.outerIndexPtr(), inner_ = a.innerIndexPtr(), values_ = a.valuePtr(),
      rows_ = static_cast<PetscInt>(a.rows()), entries_ = a.nonZeros();
      if (partition_.distributed())
        create_distributed(a);
      else
        check(MatCreateSeqAIJWithArrays(PETSC_COMM_WORLD, rows_, rows_, const_cast<PetscInt*>(outer_),
                                        const_cast<PetscInt*>(inner_), const_cast<PetscScalar*>(values_), &mat_),
              "wrapping the tangent matrix");
      check(MatSetBlockSize(mat_, fem::kDofsPerNode), "setting the matrix block size");
    }
    if (partition_.distributed()) {
      check(MatSetValuesCOO(mat_, values_, INSERT_VALUES), "sending the tangent's entries");
    } else if (!moved) {
      // The values were written in place: assembling again bumps the Mat's
      // state, so preconditioners built on the old values see the change.
      check(MatAssemblyBegin(mat_, MAT_FINAL_ASSEMBLY), "updating the tangent matrix");
      check(MatAssemblyEnd(mat_, MAT_FINAL_ASSEMBLY), "updating the tangent matrix");
    }
    return moved;
  }
  /// Gives the wrapped Mat other `entries`, in the order of the last
  /// wrapped matrix's (on one process the Mat reads that matrix's array:
  /// they are written there).
  void put(std::span<const double> entries) {
    if (partition_.distributed()) {
      check(MatSetValuesCOO(mat_, entries.data(), INSERT_VALUES), "sending the tangent's entries");
      return;
    }
    PetscScalar* values = nullptr;
    check(MatSeqAIJGetArray(mat_, &values), "writing the tangent's entries");
    std::copy(entries.begin(), entries.end(), values);
    check(MatSeqAIJRestoreArray(mat_, &values), "writing the tangent's entries");
  }
  Mat mat() const { return mat_; }

private:
  void create_distributed(const fem::SparseMatrix& a) {
    std::vector<PetscInt> rows, columns; // handed over: PETSc may reorder them
    rows.reserve(static_cast<std::size_t>(a.nonZeros()));
    columns.reserve(static_cast<std::size_t>(a.nonZeros()));
    for (int r = 0; r < a.rows(); ++r)
      for (int k = outer_[r]; k < outer_[r + 1]; ++k) {
        rows.push_back(system_index(partition_, r));
        columns.push_back(system_index(partition_, inner_[k]));
      }
    const PetscInt local = fem::kDofsPerNode * partition_.owned_count();
    check(MatCreate(PETSC_COMM_WORLD, &mat_), "creating the distributed tangent");
    check(MatSetSizes(mat_, local, local, rows_, rows_), "creating the distributed tangent");
    check(MatSetType(mat_, MATAIJ), "creating the distributed tangent");
    check(MatSetPreallocationCOO(mat_, static_cast<PetscCount>(rows.size()), rows.data(), columns.data()),
          "creating the distributed tangent");
  }

  const fem::Partition& partition_;
  Timers& timers_;
  Mat mat_ = nullptr;
  const int* outer_ = nullptr;
  const int* inner_ = nullptr;
  const double* values_ = nullptr;
  PetscInt rows_ = 0;
  long entries_ = 0;
};

/// A Vec of the system: in() gives it a whole vector's values, out() takes
/// them back (a solution).
class VectorSlot {
public:
  explicit VectorSlot(const fem::Partition& partition) : partition_(partition) {}
  ~VectorSlot() {
    release();
    VecDestroy(&vec_);
    VecScatterDestroy(&gather_);
    VecDestroy(&whole_);
  }
  VectorSlot(const VectorSlot&) = delete;
  VectorSlot& operator=(const VectorSlot&) = delete;

  /// The Vec with the values of `v` (4 × nodes); on one process it reads
  /// and writes v's own array until out() or the next in().
  Vec in(const Eigen::VectorXd& v) {
    release();
    if (!vec_ || size_ != v.size()) create(v.size());
    if (!partition_.distributed()) {
      check(VecPlaceArray(vec_, v.data()), "placing a vector");
      placed_ = true;
      return vec_;
    }
    PetscScalar* x = nullptr;
    check(VecGetArray(vec_, &x), "filling a vector");
    const int first = fem::kDofsPerNode * partition_.first;
    for (int k = 0; k < fem::kDofsPerNode * partition_.owned_count(); ++k) {
      const int row = first + k;
      x[k] = v[fem::kDofsPerNode * partition_.node[row / fem::kDofsPerNode] + row % fem::kDofsPerNode];
    }
    check(VecRestoreArray(vec_, &x), "filling a vector");
    return vec_;
  }
  /// x ← the Vec's values, every process the whole vector; `x` is the
  /// vector given to in().
  void out(Eigen::VectorXd& x) {
    if (!partition_.distributed()) return release();
    read_whole(gathered(), x);
  }
  /// Several processes: the Vec's rows gathered, the whole system on each
  /// process (a sequential Vec owned by the slot, valid until the next call).
  Vec gathered() {
    if (!gather_) check(VecScatterCreateToAll(vec_, &gather_, &whole_), "creating a vector");
    check(VecScatterBegin(gather_, vec_, whole_, INSERT_VALUES, SCATTER_FORWARD), "gathering a vector");
    check(VecScatterEnd(gather_, vec_, whole_, INSERT_VALUES, SCATTER_FORWARD), "gathering a vector");
    return whole_;
  }
  /// x ← `whole`, a sequential Vec of every row of the system (in the
  /// partition's numbering), put back into the mesh's dof order.
  void read_whole(Vec whole, Eigen::VectorXd& x) const {
    const PetscScalar* y = nullptr;
    check(VecGetArrayRead(whole, &y), "reading a solution");
    for (long row = 0; row < x.size(); ++row)
      x[fem::kDofsPerNode * partition_.node[row / fem::kDofsPerNode] + row % fem::kDofsPerNode] = y[row];
    check(VecRestoreArrayRead(whole, &y), "reading a solution");
  }

private:
  void release() {
    if (placed_) VecResetArray(vec_);
    placed_ = false;
  }
  void create(long size) {
    VecDestroy(&vec_);
    VecScatterDestroy(&gather_);
    VecDestroy(&whole_);
    size_ = size;
    if (!partition_.distributed()) {
      check(VecCreateSeqWithArray(PETSC_COMM_WORLD, 1, static_cast<PetscInt>(size), nullptr, &vec_),
            "creating a vector");
      return;
    }
    check(VecCreateMPI(PETSC_COMM_WORLD, fem::kDofsPerNode * partition_.owned_count(), static_cast<PetscInt>(size),
                       &vec_),
          "creating a vector");
  }

  const fem::Partition& partition_;
  Vec vec_ = nullptr;
  VecScatter gather_ = nullptr; ///< several processes: the whole vector to each (made at the first out())
  Vec whole_ = nullptr;
  long size_ = -1;
  bool placed_ = false;
};

} // namespace anvil::solver::petsc

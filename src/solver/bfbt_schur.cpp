#include "bfbt_schur.h"

#include "petsc_check.h"

namespace anvil::solver::petsc {

BfbtSchur::~BfbtSchur() {
  KSPDestroy(&laplacian_);
  MatDestroy(&inverse_blocks_);
  for (Vec* v : {&velocity_[0], &velocity_[1], &pressure_[0], &pressure_[1]})
    VecDestroy(v);
}

void BfbtSchur::attach(PC pc) {
  check(PCSetType(pc, PCSHELL), "setting up the BFBT Schur preconditioner");
  check(PCShellSetContext(pc, this), "setting up the BFBT Schur preconditioner");
  check(PCShellSetSetUp(pc, set_up), "setting up the BFBT Schur preconditioner");
  check(PCShellSetApply(pc, apply), "setting up the BFBT Schur preconditioner");
  check(PCShellSetName(pc, "stabilised BFBT (anvil)"), "setting up the BFBT Schur preconditioner");
}

PetscErrorCode BfbtSchur::set_up(PC pc) {
  PetscFunctionBeginUser;
  BfbtSchur* self = nullptr;
  PetscCall(PCShellGetContext(pc, &self));
  Mat schur = nullptr, selfp = nullptr;
  PetscCall(PCGetOperators(pc, &schur, &selfp));
  PetscCall(MatSchurComplementGetSubMatrices(schur, &self->k_, nullptr, &self->bt_, &self->b_, &self->minus_c_));
  if (!self->laplacian_) {
    const char* prefix = nullptr;
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), &self->laplacian_));
    PetscCall(KSPSetOptionsPrefix(self->laplacian_, prefix));
    PetscCall(KSPAppendOptionsPrefix(self->laplacian_, "bfbt_"));
    PetscCall(KSPSetType(self->laplacian_, KSPPREONLY));
    PC multigrid = nullptr;
    PetscCall(KSPGetPC(self->laplacian_, &multigrid));
    PetscCall(PCSetType(multigrid, PCML));
    PetscCall(KSPSetFromOptions(self->laplacian_));
    PetscCall(MatCreateVecs(self->k_, &self->velocity_[0], &self->velocity_[1]));
    PetscCall(MatCreateVecs(selfp, &self->pressure_[0], &self->pressure_[1]));
  }
  PetscCall(KSPSetOperators(self->laplacian_, selfp, selfp));
  PetscCall(KSPSetUp(self->laplacian_));
  PetscCall(MatDestroy(&self->inverse_blocks_));
  PetscCall(MatCreate(PetscObjectComm(reinterpret_cast<PetscObject>(pc)), &self->inverse_blocks_));
  PetscCall(MatSetType(self->inverse_blocks_, MATAIJ));
  PetscCall(MatInvertBlockDiagonalMat(self->k_, self->inverse_blocks_));
  PetscFunctionReturn(0);
}

PetscErrorCode BfbtSchur::apply(PC pc, Vec r, Vec y) {
  PetscFunctionBeginUser;
  BfbtSchur* self = nullptr;
  PetscCall(PCShellGetContext(pc, &self));
  Vec z = self->pressure_[0], t = self->pressure_[1], u = self->velocity_[0], w = self->velocity_[1];
  // With selfp = −L and M = B D⁻¹ K D⁻¹ Bᵀ + C: z = selfp⁻¹ r = −L⁻¹ r,
  // t = M z, y = −selfp⁻¹ t = −L⁻¹ M L⁻¹ r = Ŝ⁻¹ r.
  PetscCall(KSPSolve(self->laplacian_, r, z));
  PetscCall(MatMult(self->bt_, z, w));
  PetscCall(MatMult(self->inverse_blocks_, w, u));
  PetscCall(MatMult(self->k_, u, w));
  PetscCall(MatMult(self->inverse_blocks_, w, u));
  PetscCall(MatMult(self->b_, u, t));
  PetscCall(MatMult(self->minus_c_, z, y));
  PetscCall(VecAXPY(t, -1.0, y));
  PetscCall(KSPSolve(self->laplacian_, t, y));
  PetscCall(VecScale(y, -1.0));
  PetscFunctionReturn(0);
}

} // namespace anvil::solver::petsc

// Private to src/solver: the stabilised BFBT approximation of the Schur
// complement S = −C − B K⁻¹ Bᵀ of the condensed MINI system (Elman, Howle,
// Shadid, Shuttleworth, Tuminaro 2006, SIAM J. Sci. Comput. 27; with the
// stabilisation C as in Elman, Howle, Shadid, Silvester, Tuminaro 2007,
// SIAM J. Sci. Comput. 30):
//   Ŝ⁻¹ = −L⁻¹ (B D⁻¹ K D⁻¹ Bᵀ + C) L⁻¹,   L = B D⁻¹ Bᵀ + C,
// D the block diagonal of K (each node's 3×3 block), exact when K is block
// diagonal. A contact node's block holds the penalty ρA n nᵀ, stiff along
// the die's normal alone: D⁻¹ leaves the node free to slide, where diag(K)
// would hold it on drafted walls and fillets. Unlike the viscosity-scaled
// mass matrix, Ŝ follows the lubrication modes of a layer squeezed between
// dies (the pressure of a friction hill), whose Schur complement is far
// below M_p/η. L is PETSc's "selfp" matrix (its negative), formed with the
// same blocks (KrylovSolver's default ainv_type blockdiag); one AMG V-cycle
// (ML by default, options prefix fieldsplit_1_bfbt_) stands for each L⁻¹.
#pragma once
#include <petscksp.h>

namespace anvil::solver::petsc {

class BfbtSchur {
public:
  BfbtSchur() = default;
  ~BfbtSchur();
  BfbtSchur(const BfbtSchur&) = delete;
  BfbtSchur& operator=(const BfbtSchur&) = delete;

  /// Makes `pc`, the PC of the Schur-complement KSP of a fieldsplit whose
  /// Schur preconditioning matrix is selfp, a shell that applies Ŝ⁻¹ (set up
  /// with the PC, whenever the fieldsplit's operators change).
  void attach(PC pc);

private:
  static PetscErrorCode set_up(PC pc);
  static PetscErrorCode apply(PC pc, Vec r, Vec y);

  KSP laplacian_ = nullptr;                                          ///< one V-cycle on selfp = −L
  Mat k_ = nullptr, bt_ = nullptr, b_ = nullptr, minus_c_ = nullptr; ///< blocks of S (not owned)
  Mat inverse_blocks_ = nullptr;                                     ///< D⁻¹
  Vec velocity_[2] = {nullptr, nullptr}, pressure_[2] = {nullptr, nullptr};
};

} // namespace anvil::solver::petsc

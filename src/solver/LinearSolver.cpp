#include "anvil/solver/LinearSolver.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/solver/BlockPreconditioner.h"
#include "anvil/solver/MumpsSolver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>
#include <unsupported/Eigen/IterativeSolvers>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace anvil::solver {

namespace {
/// The SuiteSparse and Eigen direct solvers take compressed columns; 64-bit
/// indices, so UMFPACK runs its long version (the int one fails past ~2 GB of factors).
using ColumnMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, long>;
} // namespace

struct LinearSolver::Backend {
  std::optional<KrylovSolver> krylov;
  std::optional<MumpsSolver> mumps;
  ColumnMatrix columns; ///< copy of the tangent for the comparison solvers
  Eigen::UmfPackLU<ColumnMatrix> umfpack;
  Eigen::CholmodSimplicialLDLT<ColumnMatrix, Eigen::Lower> cholmod;
  Eigen::SimplicialLDLT<ColumnMatrix, Eigen::Lower, Eigen::AMDOrdering<long>> eigen;
  Eigen::MINRES<fem::SparseMatrix, Eigen::Lower | Eigen::Upper, BlockPreconditioner> minres;
};

LinearSolverKind linear_solver_kind(const std::string& name) {
  if (name == "fgmres") return LinearSolverKind::fgmres;
  if (name == "mumps") return LinearSolverKind::mumps;
  if (name == "umfpack") return LinearSolverKind::umfpack;
  if (name == "cholmod_ldlt") return LinearSolverKind::cholmod_ldlt;
  if (name == "eigen_ldlt") return LinearSolverKind::eigen_ldlt;
  if (name == "minres") return LinearSolverKind::minres;
  if (name == "auto") return LinearSolverKind::automatic;
  throw InputError("unknown linear solver '" + name +
                   "' (expected auto, fgmres, mumps, umfpack, cholmod_ldlt, eigen_ldlt or minres)");
}

SchurApproximation schur_approximation(const std::string& name) {
  if (name == "bfbt") return SchurApproximation::bfbt;
  if (name == "mass") return SchurApproximation::mass;
  throw InputError("unknown Schur-complement approximation '" + name + "' (expected bfbt or mass)");
}

std::string to_string(LinearSolverKind kind) {
  switch (kind) {
  case LinearSolverKind::fgmres:
    return "fgmres";
  case LinearSolverKind::mumps:
    return "mumps";
  case LinearSolverKind::umfpack:
    return "umfpack";
  case LinearSolverKind::cholmod_ldlt:
    return "cholmod_ldlt";
  case LinearSolverKind::eigen_ldlt:
    return "eigen_ldlt";
  case LinearSolverKind::minres:
    return "minres";
  case LinearSolverKind::automatic:
    return "auto";
  }
  return "?";
}

LinearSolverKind resolve(LinearSolverKind kind, int unknowns) {
  if (kind != LinearSolverKind::automatic) return kind;
  return unknowns > kDirectSolverLimit ? LinearSolverKind::fgmres : LinearSolverKind::mumps;
}

LinearSolver::LinearSolver(const LinearSolverSettings& settings, int unknowns, const fem::Partition& partition,
                           Timers& timers)
    : settings_(settings), unknowns_(unknowns), partition_(partition), timers_(timers) {
  restart();
  if (partition_.distributed() && kind_ != LinearSolverKind::fgmres && kind_ != LinearSolverKind::mumps)
    throw InputError("solver.linear_solver '" + to_string(kind_) + "' runs on one process; with " +
                     std::to_string(partition_.processes) + " processes (mpirun) choose auto, fgmres or mumps");
}
LinearSolver::~LinearSolver() = default;

void LinearSolver::restart() {
  kind_ = resolve(settings_.kind, unknowns_);
  if (kind_ == LinearSolverKind::fgmres && backend_ && backend_->krylov) {
    backend_->krylov->restart(); // the pattern stays: PETSc's distributed one is dear to make
  } else {
    // A workspace MUMPS had to raise stays raised: the same matrices need it again.
    const int workspace = backend_ && backend_->mumps ? backend_->mumps->workspace_percent() : 0;
    backend_ = std::make_unique<Backend>();
    if (kind_ == LinearSolverKind::fgmres)
      backend_->krylov.emplace(settings_.schur, settings_.velocity_block, partition_, timers_);
    if (kind_ == LinearSolverKind::mumps) backend_->mumps.emplace(partition_, timers_, workspace);
    backend_->minres.setMaxIterations(20000);
  }
  analysed_ = false;
  setup_rate_ = 0.0;
  refresh_ = true;
  reused_ = false;
  boundary_ = {};
  boundary_source_ = {};
}

namespace {
template <class Solver> bool factorize_with(Solver& s, const ColumnMatrix& a, bool& analysed, int& analyses) {
  if (!analysed) {
    s.analyzePattern(a);
    analysed = true;
    ++analyses;
  }
  s.factorize(a);
  return s.info() == Eigen::Success;
}

/// A solve on a kept set-up may take this many set-ups' cost in iterations
/// beyond what the set-up's first solve took (LinearSolver::solve).
constexpr double kStaleSetups = 2.0;

/// A Newton step that changes the velocity by more than this (|Δv|/|v|)
/// changes the tangent with it (a viscoplastic law's viscosity follows the
/// strain rate as ε̄̇^(m−1)): the set-up kept from before it is made anew.
/// Kept, about a quarter of the solves after such steps on the closed-die
/// runs went stale, against almost none after shorter steps
/// (tools/stale_setups, docs/linear-solve.md).
constexpr double kLongNewtonStep = 0.03;

/// Decades of residual reduction to `reduction` (at least one).
double decades(double reduction) {
  return std::max(1.0, -std::log10(std::max(reduction, 1e-300)));
}

/// Decades of residual reduction a solve made (at least one).
double decades(const KrylovOutcome& k) {
  return decades(k.reduction);
}

/// Iterations per decade of residual reduction: comparable between solves
/// to different tolerances.
double rate(const KrylovOutcome& k) {
  return k.iterations / decades(k);
}

/// A 52-bit hash (FNV-1a, exact in a double) of `a`'s pattern.
double pattern_hash(const fem::SparseMatrix& a) {
  std::uint64_t h = 14695981039346656037ull;
  auto add = [&h](std::uint64_t v) {
    h ^= v;
    h *= 1099511628211ull;
  };
  add(static_cast<std::uint64_t>(a.rows()));
  add(static_cast<std::uint64_t>(a.nonZeros()));
  for (Eigen::Index r = 0; r <= a.outerSize(); ++r)
    add(static_cast<std::uint64_t>(a.outerIndexPtr()[r]));
  for (Eigen::Index k = 0; k < a.nonZeros(); ++k)
    add(static_cast<std::uint64_t>(a.innerIndexPtr()[k]));
  return static_cast<double>(h >> 12);
}
} // namespace

void LinearSolver::set_krylov_operator(const fem::SparseMatrix& a, const SaddlePointData& data, bool reuse) {
  backend_->krylov->set_operator(a, data, reuse);
  reused_ = reuse;
  if (reuse) return;
  ++setups_;
  setup_rate_ = 0.0; // measured by the next solve
  if (!settings_.reuse_preconditioner) return;
  // The set-up kept at the boundary keeps its source until the next
  // increment_ended (a swap: the copy below reuses the older storage).
  if (boundary_.kept && !boundary_.replaced) {
    std::swap(source_, boundary_source_);
    boundary_.replaced = true;
  }
  source_.entries.assign(a.valuePtr(), a.valuePtr() + a.nonZeros());
  source_.pattern = pattern_hash(a);
  source_.nodes.assign(data.nodes.begin(), data.nodes.end());
  source_.pressure_mass.assign(data.pressure_mass.data(), data.pressure_mass.data() + data.pressure_mass.size());
}

void LinearSolver::increment_ended() {
  boundary_.kept = kind_ == LinearSolverKind::fgmres && settings_.reuse_preconditioner && analysed_ && !refresh_;
  boundary_.direct = kind_ == LinearSolverKind::mumps && resolve(settings_.kind, unknowns_) == LinearSolverKind::fgmres;
  boundary_.setup_rate = setup_rate_;
  boundary_.extra_iterations = extra_iterations_;
  if (boundary_.replaced) boundary_source_ = SetUpSource{}; // its memory back
  boundary_.replaced = false;
}

void LinearSolver::resume_with(KeptSetUp kept) {
  // This process's part becomes the boundary's, as if the run had just
  // accepted the checkpoint's increment: stopped again before an increment
  // ends, the run checkpoints it again.
  resuming_ = settings_.reuse_preconditioner && !kept.entries.empty();
  const auto p = static_cast<std::size_t>(partition_.process);
  boundary_ = {.kept = resuming_ && kept.entries.size() == static_cast<std::size_t>(partition_.processes) &&
                       kept.patterns.size() == kept.entries.size(),
               .replaced = false,
               .direct = kept.direct_fallback,
               .setup_rate = kept.setup_rate,
               .extra_iterations = kept.extra_iterations};
  if (boundary_.kept)
    source_ = {std::move(kept.entries[p]), kept.patterns[p], std::move(kept.nodes), std::move(kept.pressure_mass)};
  if (boundary_.direct) take_over_direct(); // the run it resumes had MUMPS solve
}

KeptSetUp LinearSolver::kept_set_up() const {
  KeptSetUp kept;
  kept.direct_fallback = boundary_.direct;
  if (!boundary_.kept) return kept;
  const SetUpSource& source = boundary_.replaced ? boundary_source_ : source_;
  kept.entries = {source.entries};
  kept.patterns = {source.pattern};
  kept.nodes = source.nodes;
  kept.pressure_mass = source.pressure_mass;
  kept.setup_rate = boundary_.setup_rate;
  kept.extra_iterations = boundary_.extra_iterations;
  return kept;
}

bool LinearSolver::set_up_as_resumed(const fem::SparseMatrix& a, const SaddlePointData& data) {
  resuming_ = false;
  const bool fits = boundary_.kept && source_.pattern == pattern_hash(a) &&
                    source_.entries.size() == static_cast<std::size_t>(a.nonZeros()) &&
                    source_.nodes.size() == data.nodes.size() &&
                    source_.pressure_mass.size() == static_cast<std::size_t>(data.pressure_mass.size());
  // Set up together or not at all: each process checks its own part.
  if (processes::minimum(fits ? 1 : 0) == 0) {
    log::info("    linear solver: the checkpoint's preconditioner was set up on another matrix pattern (other "
              "processes or contact couplings); set up anew");
    return false;
  }
  const Eigen::Map<const Eigen::VectorXd> mass(source_.pressure_mass.data(),
                                               static_cast<Eigen::Index>(source_.pressure_mass.size()));
  const Eigen::VectorXd pressure_mass = mass;
  backend_->krylov->set_up_from(a, source_.entries, SaddlePointData{source_.nodes, pressure_mass, data.parts});
  ++setups_;
  set_krylov_operator(a, data, true);
  setup_rate_ = boundary_.setup_rate;
  extra_iterations_ = boundary_.extra_iterations;
  return true;
}

void LinearSolver::take_over_direct() {
  backend_->krylov.reset();
  backend_->mumps.emplace(partition_, timers_);
  kind_ = LinearSolverKind::mumps;
}

void LinearSolver::newton_step(double relative_change) {
  if (relative_change > kLongNewtonStep) refresh_ = true;
}

bool LinearSolver::factorize(const fem::SparseMatrix& a, const SaddlePointData& data) {
  matrix_ = &a;
  data_.reset();
  data_.emplace(data);
  Backend& b = *backend_;
  switch (kind_) {
  case LinearSolverKind::fgmres: {
    if (!(resuming_ && set_up_as_resumed(a, data)))
      set_krylov_operator(a, data, settings_.reuse_preconditioner && analysed_ && !refresh_);
    refresh_ = false;
    if (!analysed_) ++analyses_;
    analysed_ = true;
    return true;
  }
  case LinearSolverKind::mumps:
    if (!analysed_) ++analyses_;
    analysed_ = true;
    ++setups_;
    return b.mumps->factorize(a);
  case LinearSolverKind::minres:
    if (!analysed_) {
      std::vector<char> component(static_cast<std::size_t>(a.rows()));
      for (std::size_t d = 0; d < component.size(); ++d)
        component[d] = static_cast<char>(d % fem::kDofsPerNode);
      b.minres.preconditioner().set_components(std::move(component));
      analysed_ = true;
      ++analyses_;
    }
    b.minres.compute(a);
    return b.minres.info() == Eigen::Success;
  default:
    break;
  }
  ++setups_;
  b.columns = a;
  switch (kind_) {
  case LinearSolverKind::umfpack:
    return factorize_with(b.umfpack, b.columns, analysed_, analyses_);
  case LinearSolverKind::cholmod_ldlt:
    return factorize_with(b.cholmod, b.columns, analysed_, analyses_);
  case LinearSolverKind::eigen_ldlt:
    return factorize_with(b.eigen, b.columns, analysed_, analyses_);
  default:
    return false; // automatic is resolved in the constructor
  }
}

bool LinearSolver::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, double relative_tolerance) {
  Backend& b = *backend_;
  iterations_ = 0;
  switch (kind_) {
  case LinearSolverKind::fgmres: {
    // On a kept set-up, a solve that has run kStaleSetups set-ups' worth of iterations
    // past what a fresh one takes (at the rate after the set-up) is stopped
    // and done again on a new set-up: the kept one has gone stale (contact
    // nodes joined the active set). Measured over both closed-die cases on 1
    // and 2 processes: 76 solves went past this budget, 41 to 500 iterations
    // (7,803 in all); stopped, their new set-ups solved in 5-23 (11.7 on
    // average), 5,488 iterations with each set-up counted at its cost.
    const int budget = reused_ ? static_cast<int>(std::ceil(setup_rate_ * decades(relative_tolerance) +
                                                            kStaleSetups * settings_.setup_cost))
                               : std::numeric_limits<int>::max();
    KrylovOutcome k = b.krylov->solve(rhs, x, relative_tolerance, budget);
    iterations_ = k.iterations;
    if (!k.converged && reused_) { // a kept preconditioner may have gone stale: set it up again first
      log::detail("    linear solver: the kept preconditioner stopped after %d iterations (%s); set up again",
                  k.iterations, k.reason.c_str());
      set_krylov_operator(*matrix_, *data_, false);
      k = b.krylov->solve(rhs, x, relative_tolerance);
      iterations_ += k.iterations;
    }
    if (k.converged) {
      if (setup_rate_ == 0.0) {
        setup_rate_ = std::max(rate(k), 1e-3);
        extra_iterations_ = 0.0;
      } else {
        extra_iterations_ += std::max(0.0, k.iterations - setup_rate_ * decades(k));
        if (extra_iterations_ > settings_.setup_cost) refresh_ = true;
      }
      return true;
    }
    log::info("    linear solver: FGMRES stopped after %d iterations (%s, residual reduced to %.2e of %.2e asked); "
              "MUMPS (direct) takes over for the rest of this mesh",
              k.iterations, k.reason.c_str(), k.reduction, relative_tolerance);
    take_over_direct();
    ++setups_;
    if (!b.mumps->factorize(*matrix_)) return false;
    b.mumps->solve(rhs, x);
    return true;
  }
  case LinearSolverKind::mumps:
    b.mumps->solve(rhs, x);
    return true;
  case LinearSolverKind::umfpack:
    x = b.umfpack.solve(rhs);
    return b.umfpack.info() == Eigen::Success;
  case LinearSolverKind::cholmod_ldlt:
    x = b.cholmod.solve(rhs);
    return b.cholmod.info() == Eigen::Success;
  case LinearSolverKind::eigen_ldlt:
    x = b.eigen.solve(rhs);
    return b.eigen.info() == Eigen::Success;
  case LinearSolverKind::minres:
    b.minres.setTolerance(relative_tolerance);
    x = b.minres.solve(rhs);
    iterations_ = static_cast<int>(b.minres.iterations());
    return b.minres.info() == Eigen::Success;
  case LinearSolverKind::automatic:
    break;
  }
  return false;
}

} // namespace anvil::solver

// Newton-Raphson with line search on (v, p) for one increment of one body
// (docs/design.md §2): exact consistent tangent of the condensed MINI system, an
// inexact (Krylov) or direct linear solve, convergence on the force
// residual, the incompressibility residual and the velocity increment, each
// printed per iteration.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/fem/Assembler.h"
#include "anvil/solver/LinearSolver.h"
#include "anvil/solver/NodalTerm.h"

#include <span>
#include <string>
#include <vector>

namespace anvil::solver {

/// Defaults measured with tools/study on cases/upsetting.yaml (docs/linear-solve.md): below a residual of 1e-6 the
/// press load changes by less than 2e-6 of itself, and asking |Δv|/|v| < 1e-8 besides costs 45 % more Newton iterations
/// for a load change of 2e-8.
struct NewtonSettings {
  double tolerance = 1e-6; ///< relative force and div residuals
  /// |Δv|/|v| of the last step. A linear problem (linear laws, contact
  /// without friction or sticking, active set unchanged) needs none after a
  /// full step: that step is the solution to the linear solve's accuracy.
  double increment_tolerance = 1e-4;
  /// Largest Krylov tolerance of an inexact Newton step (Eisenstat-Walker).
  double krylov_tolerance_max = 1e-2;
  int max_iterations = 30;
  int max_line_search_cuts = 10; ///< step halvings per iteration
  bool verbose = true;           ///< one log line per iteration
};

struct NewtonIteration {
  double force_residual; ///< |r_v| / force scale (-)
  double flux_residual;  ///< |r_p| / flux scale (-)
  double increment;      ///< |Δv| / |v| (-)
  double step;           ///< line-search step length taken
};

/// The force residual of `iterations` fell, overall and over their second
/// half: more iterations may converge.
inline bool residual_falling(std::span<const NewtonIteration> iterations) {
  if (iterations.size() < 2) return false;
  const double last = iterations.back().force_residual;
  return last < iterations.front().force_residual && last < iterations[iterations.size() / 2].force_residual;
}

struct NewtonReport {
  bool converged = false;
  std::vector<NewtonIteration> iterations;
  int linear_iterations = 0;      ///< Krylov iterations of all the solves (0 for a direct solver)
  std::string failure;            ///< why it stopped, when not converged
  bool out_of_iterations = false; ///< stopped at the iteration budget (not a failed solve or a non-finite residual)
  bool interrupted = false;       ///< abandoned for SIGINT or SIGTERM (core/interrupt)

  /// Stopped at the budget while its force residual fell: its last iterate
  /// is a better start than its first (residual_falling).
  bool on_its_way() const { return out_of_iterations && residual_falling(iterations); }
};

/// What one increment solves for, besides the unknowns.
struct IncrementProblem {
  const mesh::TetMesh& mesh;                       ///< the solver's elements at the geometry of the increment
  const fem::ElementLaws& laws;                    ///< per element
  const std::vector<material::PointState>& states; ///< per element; empty = default state
  const Eigen::VectorXd& nodal_forces;             ///< external nodal forces (N), 4 × nodes
  fem::BodyForce body_force;
  std::vector<NodalTerm*> nodal_terms; ///< contact with dies, between bodies
  double reference_velocity = 0.0;     ///< mm/s; 0 = largest prescribed velocity
  double reference_force = 0.0;        ///< N; residuals are measured against at least this load
};

class IncrementSolver {
public:
  /// For the elements of `mesh` (the problems it solves carry the mesh, its
  /// nodes where the increment starts); `prescribed` marks dofs (4 × nodes,
  /// see DofMap) whose values are imposed. The processes of a run share the
  /// mesh's system (fem::Partition); every one of them returns the same unknowns.
  IncrementSolver(const mesh::TetMesh& mesh, std::vector<char> prescribed, const LinearSolverSettings& linear,
                  Timers& timers);

  /// Solves for the free unknowns of `unknowns` (prescribed entries are kept
  /// as given), starting from their current values.
  NewtonReport solve(const IncrementProblem& problem, const NewtonSettings& settings, fem::BodyUnknowns& unknowns);
  /// One body of one law, without contact: `nodal_forces` are external nodal forces (N), 4 × nodes.
  NewtonReport solve(const mesh::TetMesh& mesh, const material::Material& law,
                     const std::vector<material::PointState>& states, const Eigen::VectorXd& nodal_forces,
                     const fem::BodyForce& body_force, const NewtonSettings& settings, fem::BodyUnknowns& unknowns) {
    const fem::ElementLaws laws(mesh.tets.size(), &law);
    return solve(IncrementProblem{mesh, laws, states, nodal_forces, body_force, {}}, settings, unknowns);
  }

  /// Residual of the last evaluation, 4 × nodes: at prescribed dofs it is the
  /// reaction (N) that the constraint exerts, with the sign of an internal force.
  const Eigen::VectorXd& residual() const { return residual_; }
  const fem::DofMap& dofs() const { return assembler_.dofs(); }
  int free_count() const { return dofs().free_count(); }
  const LinearSolver& linear_solver() const { return linear_solver_; }
  void restart_linear_solver() { linear_solver_.restart(); }                        ///< see LinearSolver::restart
  KeptSetUp kept_set_up() const { return linear_solver_.kept_set_up(); }            ///< see LinearSolver
  void resume_with(KeptSetUp kept) { linear_solver_.resume_with(std::move(kept)); } ///< see LinearSolver
  void increment_ended() { linear_solver_.increment_ended(); }                      ///< see LinearSolver
  /// The elements are integrated by the rule of this degree (fem::tet_quadrature: 5 or 6).
  void set_quadrature_degree(int degree) { assembler_.set_quadrature_degree(degree); }

private:
  /// Squared residual norms, absolute: velocity rows (N²), pressure rows
  /// ((mm³/s)²), bubble rows (N²).
  struct Merit {
    double force_sq, flux_sq, bubble_sq;
  };
  /// Assembles residual and tangent at `unknowns`. With `same_elements` the
  /// unknowns and element tangents are those of the last evaluation and only
  /// the nodal terms changed (a new contact set): the elements' part kept
  /// from it is used again, the same bits as assembling it anew.
  Merit evaluate(const IncrementProblem& problem, const fem::BodyUnknowns& unknowns, bool same_elements = false);
  /// Force scale (N): the largest of the reaction norm, the contact force
  /// norm and the applied load norm.
  double force_scale(const IncrementProblem& problem) const;
  /// Tangents of the next evaluations: Newton's far phase (rate sensitivity
  /// floored, kFarSensitivity) or the consistent tangent.
  void set_tangent_phase(const IncrementProblem& problem, bool far);
  /// The next evaluation is the line search's trial at `step` from the last
  /// iterate: Newton's own directions (fem/strain_rate_dual.h,
  /// contact/FrictionDual.h) move with it.
  void set_line_search_step(const IncrementProblem& problem, double step);

  fem::Partition partition_;
  std::vector<char> owned_nodes_; ///< per node, 1 when this process owns its rows; empty on one process
  fem::Assembler assembler_;
  LinearSolver linear_solver_;
  Timers& timers_;
  std::vector<int> parts_; ///< per node, its body (mesh::connected_parts), for SaddlePointData
  Eigen::VectorXd residual_;
  Eigen::VectorXd nodal_term_residual_; ///< the nodal terms' part of residual_
  Eigen::VectorXd element_residual_;    ///< the elements' part of residual_ (with nodal terms only)
  double element_bubble_sq_ = 0.0;      ///< and its bubble residual
  std::vector<NodeBlock> blocks_;
  int bad_element_ = -1;
};

} // namespace anvil::solver

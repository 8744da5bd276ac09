#include "anvil/solver/IncrementSolver.h"

#include "anvil/core/error.h"
#include "anvil/core/interrupt.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/mesh/TetMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace anvil::solver {

using fem::kDofsPerNode;

namespace {
/// Relative tolerance of the Krylov solve of a Newton step (inexact Newton,
/// Eisenstat & Walker 1996, SIAM J. Sci. Comput. 17, choice 2 with γ = 0.9,
/// α = 2 and its safeguard): loose while the residual is far from the
/// solution, tight as Newton converges quadratically; never tighter than
/// what brings the residual to half the Newton tolerance. A linear problem is
/// solved in one step to a tenth of the tolerance. While a contact active
/// set follows the iterates (`set_unsettled`), the set is a step function of
/// the direction, and a loose solve lets the preconditioner (another one on
/// another number of processes) choose it. Measured on hot_upsetting and
/// upsetting_sticking over 1, 2 and 3 processes: at 1e-2 the runs picked
/// other sets and parted (4e-3 of the load). At 1e-3 they picked the same
/// ones with the rigid-body modes as the velocity AMG's near-null space,
/// but not with the modes less the held directions (held_directions.h):
/// hot_upsetting's die landing on its chilled face then released other
/// nodes at the third iterate on one process than on two (173 against 175
/// contact nodes at 1.46 mm, 3e-3 of the load). At 1e-4 they agree; it
/// cost upsetting 7 % of wall time, and the hub flange 2 %, where it took
/// fewer Newton iterations (5.4 against 6.1 an increment; tools/bench_case).
/// The first solve after the set changed is held to the same tolerance
/// (`set_unsettled` too): its residual and the one before belong to two
/// problems, so Eisenstat-Walker's ratio says nothing, and the clamp's loose
/// 1e-2 met the changed node's own force in 1-7 Krylov iterations and left
/// the flow's answer to it unsolved. On the connecting rod's increment 83
/// (8.19 mm) each of three such changes then cost 4-7 Newton iterations of
/// half steps (23 for the increment; 15 with the tight solve).
double krylov_tolerance(const NewtonSettings& settings, bool linear_problem, bool set_unsettled, double residual,
                        double previous_residual, double previous_forcing) {
  constexpr double kGamma = 0.9, kSmallest = 1e-12, kSetFollowing = 1e-4;
  const double no_oversolve = 0.5 * settings.tolerance / std::max(residual, 1e-300);
  double forcing = settings.krylov_tolerance_max;
  if (linear_problem)
    forcing = 0.1 * settings.tolerance / std::max(residual, 1e-300);
  else if (previous_residual > 0.0) {
    const double ratio = residual / previous_residual;
    forcing = kGamma * ratio * ratio;
    if (const double safeguard = kGamma * previous_forcing * previous_forcing; safeguard > 0.1)
      forcing = std::max(forcing, safeguard);
    forcing = std::max(forcing, no_oversolve);
  }
  if (set_unsettled) forcing = std::min(forcing, kSetFollowing);
  return std::isfinite(forcing) ? std::clamp(forcing, kSmallest, settings.krylov_tolerance_max) : kSmallest;
}

/// Newton's far phase. A power law (material s ∝ ε̄̇^m, friction τ ∝ |w|^q)
/// has a consistent tangent along the current rate that is m (q) times its
/// secant: a Newton step that must lower a rate overshoots it (a step that
/// lowers the stress by a fraction f lowers the rate by f/m, past zero for
/// f > m), and the line search then halves step after step. An increment
/// that starts far from its solution (relative residual above kFarStart: a
/// flash forming, a die landing) builds its tangents with the sensitivity
/// raised to kFarSensitivity (between the secant, 1, and the consistent
/// tangent; still symmetric positive definite) until the residual falls
/// below kNearSolution; the residual itself is unchanged, so Newton
/// converges to the same solution, and the consistent tangent gives the
/// quadratic end. An increment that starts near (most increments of a
/// steady stroke) keeps the consistent tangent throughout: the far phase
/// would add an iteration to each. Measured on closed_die_flash's last 15
/// increments (m = 0.17, Tresca q = 0; MUMPS): 24.5 Newton iterations per
/// increment on average, 38 at most, with the consistent tangent
/// throughout; 12.3 with the far phase on the material alone, 8.7 and 13 at
/// most with it on material and friction. Every increment in the far phase
/// (kFarStart = 0): the same there, but cases/upsetting.yaml took 225
/// iterations instead of 173 (185 with kFarStart = 0.1). An increment whose
/// first step the line search cuts to kFarCut or less starts far too,
/// whatever its residual: after a local remesh, hot_closed_die_flash's
/// increment 32 started at 0.045, took steps of 1/8 and 1/4, then a dozen
/// half steps, 26 Newton iterations in all; 17 from its second iteration in
/// the far phase.
constexpr double kFarSensitivity = 0.5, kNearSolution = 1e-2, kFarStart = 0.1, kFarCut = 0.25;
/// The stiffened tangent only guards against overshoot: when two full steps
/// in a row lower the residual by less than this factor each, it is itself
/// the slow part (a linear rate of 0.9-0.96 for 20 steps, measured in
/// hot_closed_die_flash after a remesh), and the consistent tangent takes
/// over for the rest of the increment.
constexpr double kFarStall = 0.8;

std::string format_tolerance(double tolerance) {
  char text[16];
  std::snprintf(text, sizeof text, "%.1e", tolerance);
  return text;
}

/// Largest velocity component magnitude of a nodal vector (4 × nodes).
double max_velocity(const Eigen::VectorXd& nodal) {
  double v = 0.0;
  for (long d = 0; d < nodal.size(); ++d)
    if (d % kDofsPerNode != 3) v = std::max(v, std::abs(nodal[d]));
  return v;
}

/// True while a contact term's active set still follows the iterates (not yet frozen).
bool set_follows(const IncrementProblem& problem) {
  return std::any_of(problem.nodal_terms.begin(), problem.nodal_terms.end(),
                     [](const NodalTerm* term) { return term->set_follows_iterates(); });
}
} // namespace

IncrementSolver::IncrementSolver(const mesh::TetMesh& mesh, std::vector<char> prescribed,
                                 const LinearSolverSettings& linear, Timers& timers)
    : partition_(fem::partition_mesh(mesh, processes::count(), processes::rank())),
      assembler_(mesh, fem::DofMap(std::move(prescribed)), partition_),
      linear_solver_(linear, assembler_.dofs().free_count(), partition_, timers), timers_(timers),
      parts_(mesh::connected_parts(mesh)) {
  if (!partition_.distributed()) return;
  owned_nodes_.resize(mesh.nodes.size());
  for (int node = 0; node < mesh.node_count(); ++node)
    owned_nodes_[node] = partition_.owns(node);
}

IncrementSolver::Merit IncrementSolver::evaluate(const IncrementProblem& problem, const fem::BodyUnknowns& unknowns,
                                                 bool same_elements) {
  const fem::DofMap& dofs = assembler_.dofs();
  Merit m{0.0, 0.0, 0.0};
  if (same_elements && !problem.nodal_terms.empty()) {
    residual_ = element_residual_;
    m.bubble_sq = element_bubble_sq_;
    assembler_.restore_element_tangent();
  } else {
    Timers::Scope scope(timers_, "assembly");
    fem::AssemblyResult r = assembler_.assemble(problem.mesh, problem.laws, problem.states, unknowns,
                                                problem.nodal_forces, problem.body_force, true);
    residual_ = std::move(r.residual);
    bad_element_ = r.bad_element;
    m.bubble_sq = r.bubble_residual_sq;
    if (!problem.nodal_terms.empty()) { // kept for an evaluation under another contact set
      element_residual_ = residual_;
      element_bubble_sq_ = m.bubble_sq;
      assembler_.keep_element_tangent();
    }
  }
  if (!problem.nodal_terms.empty()) {
    Timers::Scope scope(timers_, "contact");
    nodal_term_residual_.setZero(residual_.size());
    blocks_.clear();
    const std::vector<char>* rows = owned_nodes_.empty() ? nullptr : &owned_nodes_;
    for (NodalTerm* term : problem.nodal_terms)
      term->add(unknowns.nodal, nodal_term_residual_, &blocks_, rows);
    processes::sum({nodal_term_residual_.data(), static_cast<std::size_t>(nodal_term_residual_.size())});
    residual_ += nodal_term_residual_;
    for (const NodeBlock& b : blocks_)
      assembler_.add_velocity_block(b.row_node, b.col_node, b.tangent);
  } else
    nodal_term_residual_.resize(0);
  assembler_.finish_tangent();
  for (int d = 0; d < dofs.dof_count(); ++d) {
    if (dofs.prescribed(d)) continue;
    (d % kDofsPerNode == 3 ? m.flux_sq : m.force_sq) += residual_[d] * residual_[d];
  }
  return m;
}

void IncrementSolver::set_tangent_phase(const IncrementProblem& problem, bool far) {
  const double floor = far ? kFarSensitivity : 0.0;
  assembler_.set_tangent_sensitivity_floor(floor);
  for (NodalTerm* term : problem.nodal_terms)
    term->set_tangent_sensitivity_floor(floor);
}

void IncrementSolver::set_line_search_step(const IncrementProblem& problem, double step) {
  assembler_.set_dual_step(step);
  for (NodalTerm* term : problem.nodal_terms)
    term->set_line_search_step(step);
}

double IncrementSolver::force_scale(const IncrementProblem& problem) const {
  const Eigen::VectorXd& nodal_forces = problem.nodal_forces;
  const fem::DofMap& dofs = assembler_.dofs();
  double reaction_sq = 0.0;
  for (int d = 0; d < dofs.dof_count(); ++d)
    if (dofs.prescribed(d) && d % kDofsPerNode != 3) reaction_sq += residual_[d] * residual_[d];
  double applied_sq = 0.0;
  for (int d = 0; d < dofs.dof_count(); ++d)
    if (d % kDofsPerNode != 3) applied_sq += nodal_forces[d] * nodal_forces[d];
  // A body at rest (a billet between dies that let go) has no load of its
  // own: the reference force keeps the measure finite.
  return std::max(
      {std::sqrt(reaction_sq), std::sqrt(applied_sq), nodal_term_residual_.norm(), problem.reference_force, 1e-300});
}

NewtonReport IncrementSolver::solve(const IncrementProblem& problem, const NewtonSettings& settings,
                                    fem::BodyUnknowns& unknowns) {
  NewtonReport report;
  const mesh::TetMesh& mesh = problem.mesh;
  const fem::DofMap& dofs = assembler_.dofs();
  const int n = dofs.dof_count();
  const double body_volume = std::abs(mesh::volume(mesh));

  // Predictor: a near-rigid-plastic law started from rest sees huge viscosities
  // wherever the guess is still, and Newton crawls. One solve with each
  // nonlinear law replaced by the Newtonian law of its secant viscosity at a
  // reference rate (|v|max / body size) gives a start in the quadratic basin.
  bool at_rest = true;
  for (int d = 0; d < n && at_rest; ++d)
    if (!dofs.prescribed(d) && unknowns.nodal[d] != 0.0) at_rest = false;
  const double reference_velocity =
      problem.reference_velocity > 0.0 ? problem.reference_velocity : max_velocity(unknowns.nodal);
  const bool nonlinear = std::any_of(problem.laws.begin(), problem.laws.end(),
                                     [](const material::Material* law) { return !law->is_linear(); });
  if (at_rest && nonlinear && reference_velocity > 0.0) {
    const double reference_rate = reference_velocity / std::cbrt(body_volume);
    const material::PointState state = problem.states.empty() ? material::PointState{} : problem.states.front();
    // One stand-in per distinct law (a scene has a few), linear laws kept.
    std::vector<const material::Material*> distinct;
    std::vector<std::unique_ptr<material::NortonHoff>> stand_ins;
    fem::ElementLaws newtonian_laws(problem.laws.size());
    for (std::size_t e = 0; e < problem.laws.size(); ++e) {
      const material::Material* law = problem.laws[e];
      const auto known = std::find(distinct.begin(), distinct.end(), law);
      const std::size_t k = static_cast<std::size_t>(known - distinct.begin());
      if (known == distinct.end()) {
        distinct.push_back(law);
        stand_ins.push_back(law->is_linear() ? nullptr
                                             : std::make_unique<material::NortonHoff>(
                                                   law->secant_viscosity(reference_rate, state), 1.0, 0.0));
      }
      newtonian_laws[e] = stand_ins[k] ? stand_ins[k].get() : law;
    }
    NewtonSettings predictor = settings;
    predictor.max_iterations = 1; // linear laws: one Newton step is the solution (with an active
    predictor.verbose = false;    // contact set, one step of it is enough for a start)
    predictor.tolerance = 1e-2;   // a start, not an answer
    // Its Krylov solve is tight all the same: from this start Newton's active
    // set settles on one of the consistent sets, and a loose solve lets the
    // preconditioner, so the number of processes, choose which
    // (closed_die_flash on 3 processes found another at 1e-3). It is made
    // once, from rest.
    predictor.krylov_tolerance_max = std::min(settings.krylov_tolerance_max, 1e-5);
    Timers::Scope scope(timers_, "effect nonlinear_law (predictor)");
    const IncrementProblem newtonian_problem{mesh,
                                             newtonian_laws,
                                             problem.states,
                                             problem.nodal_forces,
                                             problem.body_force,
                                             problem.nodal_terms,
                                             reference_velocity,
                                             problem.reference_force};
    report.linear_iterations += solve(newtonian_problem, predictor, unknowns).linear_iterations;
    // Its preconditioner is the uniform viscosity's: kept for the law's
    // tangent, with its rigid zones, the first Newton solve took 42 Krylov
    // iterations at 13k nodes and 98 at 214k, against 14 and 25 on a set-up
    // of its own (docs/linear-solve.md).
    linear_solver_.operator_changed();
    if (settings.verbose)
      for (const auto& stand_in : stand_ins)
        if (stand_in)
          log::detail("    predictor: Newtonian solve at viscosity %.4g MPa.s (rate %.3g 1/s)", stand_in->consistency(),
                      reference_rate);
  }

  // Residuals are made relative: forces against the larger of the applied
  // loads and the reactions; fluxes (mm³/s) against |v|max × body area, both
  // refreshed as the field develops.
  const double area = std::pow(body_volume, 2.0 / 3.0);
  // |Δv| is measured against |v|, or against 1e-3 of the reference speed at
  // every node when the body is (nearly) at rest.
  const double velocity_floor_sq = std::max(1e-6 * reference_velocity * reference_velocity * mesh.node_count(), 1e-300);
  auto relative = [](const Merit& m, double force, double flux) {
    return (m.force_sq + m.bubble_sq) / (force * force) + m.flux_sq / (flux * flux);
  };

  if (!problem.nodal_terms.empty()) {
    std::vector<std::pair<int, int>> couplings;
    for (NodalTerm* term : problem.nodal_terms) {
      term->start(unknowns.nodal);
      const std::vector<std::pair<int, int>> own = term->couplings();
      couplings.insert(couplings.end(), own.begin(), own.end());
    }
    if (assembler_.set_couplings(couplings)) linear_solver_.pattern_changed();
  }
  bool far = false;         // the far phase of this increment (kFarStart), decided at its start
  int far_stalls = 0;       // full far-phase steps in a row that lowered the residual by less than kFarStall
  bool set_changed = false; // the last step changed the active set (its residuals compare two problems)
  set_tangent_phase(problem, false);
  assembler_.start_dual(nonlinear ? &unknowns : nullptr);
  const bool linear_problem = !nonlinear && std::all_of(problem.nodal_terms.begin(), problem.nodal_terms.end(),
                                                        [](const NodalTerm* term) { return term->linear(); });
  Merit merit = evaluate(problem, unknowns);
  double scale = force_scale(problem);
  // After a change of the active set: residual, tangent, merit and force
  // scale of the current iterate under the new set.
  auto evaluate_with_new_set = [&] {
    merit = evaluate(problem, unknowns, true);
    scale = force_scale(problem);
  };
  Eigen::VectorXd rhs(n), delta(n), bubble_delta;
  double previous_residual = -1.0, forcing = settings.krylov_tolerance_max;
  fem::BodyUnknowns trial;
  // The iteration budget applies per active set: a change of set at
  // convergence starts a new (short) Newton run, at most kMaxSetChanges times.
  // A set that runs out of its budget while the residual falls gets a second
  // one, once per solve: Newton goes on with the same state (active set,
  // phase, forcing), so a run whose round-off puts it just past the budget
  // follows the path of a run with a larger one.
  constexpr int kMaxSetChanges = 10;
  // A frozen active set is checked from this multiple of the tolerance on
  // (contact/ActiveSet.h), not only at convergence: where a contact zone's
  // edge recedes one node per check, each converged set cost the quadratic
  // tail from here to the tolerance. Measured on the connecting rod's whole
  // run: 244 of its 1,291 Newton iterations lay between the first iterate
  // below 1e-4 and a change at convergence (81 changes); checking from here,
  // 1,229 iterations, largest per increment 21 -> 20. From 1e-2 on (1e4 x):
  // 8.8 per increment against 8.9, with twice the set changes.
  constexpr double kSetCheck = 100.0;
  int phase_start = 0, set_changes = 0;
  bool second_budget = true;
  for (int it = 1;; ++it) {
    if (it - phase_start > settings.max_iterations) {
      const std::span<const NewtonIteration> phase(report.iterations.begin() + phase_start, report.iterations.end());
      if (!second_budget || !residual_falling(phase)) break;
      second_budget = false;
      phase_start += settings.max_iterations;
      log::info("  no convergence in %d Newton iterations, the residual falling (%.3g to %.3g): a second budget at "
                "the same time step",
                settings.max_iterations, phase.front().force_residual, phase.back().force_residual);
    }
    if (interrupt::requested()) { // the increment is abandoned: the run checkpoints the last accepted one
      report.failure = "interrupted";
      report.interrupted = true;
      return report;
    }
    if (bad_element_ >= 0) {
      report.failure = "element " + std::to_string(bad_element_ + 1) + " is inverted or flat";
      return report;
    }
    for (int d = 0; d < n; ++d)
      rhs[d] = dofs.prescribed(d) ? 0.0 : -residual_[d];
    // The relative residual Newton starts this step from (a body at rest with
    // no velocity scale has only its force part).
    const double flux_now = std::max(max_velocity(unknowns.nodal), reference_velocity) * area;
    const double residual_now = std::sqrt((merit.force_sq + merit.bubble_sq) / (scale * scale) +
                                          (flux_now > 0.0 ? merit.flux_sq / (flux_now * flux_now) : 0.0));
    if (far && !set_changed && residual_now > kFarStall * previous_residual && report.iterations.back().step == 1.0) {
      if (++far_stalls == 2) {
        far = false;
        set_tangent_phase(problem, false);
        merit = evaluate(problem, unknowns); // the same residual, the consistent tangent
        if (settings.verbose) log::detail("    far phase ended: its full steps lower the residual slowly");
      }
    } else {
      far_stalls = 0;
    }
    forcing = krylov_tolerance(settings, linear_problem, set_follows(problem) || set_changed, residual_now,
                               previous_residual, forcing);
    previous_residual = residual_now;
    const bool first_cut = it == 2 && !far && report.iterations.back().step <= kFarCut && residual_now > kNearSolution;
    if ((it == 1 && residual_now > kFarStart) || first_cut) { // this iterate's tangent again, stiffened
      if (first_cut && settings.verbose) log::detail("    far phase: the first step was cut");
      far = true;
      set_tangent_phase(problem, true);
      merit = evaluate(problem, unknowns);
    }
    // The tangent the line search below assembles is the next direction's.
    set_tangent_phase(problem, far && residual_now > kNearSolution);
    bool solved = false;
    {
      Timers::Scope scope(timers_, "solver setup");
      solved = linear_solver_.factorize(assembler_.tangent(),
                                        SaddlePointData{mesh.nodes, assembler_.pressure_mass(), parts_});
    }
    if (solved) {
      Timers::Scope scope(timers_, "solve");
      solved = linear_solver_.solve(rhs, delta, forcing);
    }
    if (!solved) {
      report.interrupted = interrupt::requested() != 0; // a Krylov solve stops for an interrupt too
      report.failure = report.interrupted
                           ? "interrupted"
                           : "the linear solver (" + to_string(linear_solver_.kind()) + ") failed on the tangent";
      return report;
    }
    report.linear_iterations += linear_solver_.iterations();
    for (int d = 0; d < n; ++d)
      if (dofs.prescribed(d)) delta[d] = 0.0; // decoupled rows: zero to the solve's accuracy, exactly zero here
    assembler_.bubble_increment(problem.mesh, delta, bubble_delta);

    // Backtracking line search on the squared relative residual (Armijo with
    // c = 1e-4; for the exact Newton direction its slope at step 0 is −2 × merit).
    // Each trial assembles the tangent too, so the accepted one is ready for the next iteration.
    // Start and trial are compared with one flux scale, the larger of the two
    // (a body starting at rest has none of its own).
    const Merit merit_start = merit;
    const double velocity_start = max_velocity(unknowns.nodal);
    double step = 1.0;
    for (int cut = 0;; ++cut) {
      trial.nodal = unknowns.nodal + step * delta;
      trial.bubble = unknowns.bubble + step * bubble_delta;
      set_line_search_step(problem, step);
      merit = evaluate(problem, trial);
      const double flux = std::max(std::max(velocity_start, max_velocity(trial.nodal)) * area, 1e-300);
      if (bad_element_ < 0 && relative(merit, scale, flux) <= (1.0 - 2e-4 * step) * relative(merit_start, scale, flux))
        break;
      if (cut == settings.max_line_search_cuts) break; // take the smallest step and let Newton go on
      step *= 0.5;
    }
    unknowns.nodal.swap(trial.nodal);
    unknowns.bubble.swap(trial.bubble);
    assembler_.accept_dual(unknowns);
    scale = force_scale(problem); // reactions follow the velocity field
    const double flux_scale = std::max(max_velocity(unknowns.nodal) * area, 1e-300);

    double velocity_sq = 0.0, delta_sq = 0.0;
    for (int d = 0; d < n; ++d)
      if (d % kDofsPerNode != 3) {
        velocity_sq += unknowns.nodal[d] * unknowns.nodal[d];
        delta_sq += step * step * delta[d] * delta[d];
      }
    const NewtonIteration record{std::sqrt(merit.force_sq + merit.bubble_sq) / scale,
                                 std::sqrt(merit.flux_sq) / flux_scale,
                                 std::sqrt(delta_sq / std::max(velocity_sq, velocity_floor_sq)), step};
    report.iterations.push_back(record);
    std::string note;
    set_changed = false;
    for (NodalTerm* term : problem.nodal_terms) {
      note += term->accept(unknowns.nodal);
      set_changed = set_changed || term->set_changed();
    }
    if (linear_solver_.iterative())
      note += "  (" + std::to_string(linear_solver_.iterations()) + " " + to_string(linear_solver_.kind()) +
              " iterations" + (linear_solver_.kept_preconditioner() ? "" : " on a new set-up") + ", tolerance " +
              format_tolerance(forcing) + ")";
    if (settings.verbose)
      log::detail("    newton %2d  force residual %.3e  div residual %.3e  |dv|/|v| %.3e  step %.3g%s", it,
                  record.force_residual, record.flux_residual, record.increment, record.step, note.c_str());
    if (!std::isfinite(record.force_residual + record.flux_residual + record.increment)) {
      report.failure = "the residual is not finite";
      return report;
    }
    // The residual, tangent and merit above are those of the set before
    // accept(): with a changed set the next direction and its line search
    // would see two problems (a step of 2^-10 and a lost iteration).
    if (set_changed) evaluate_with_new_set();
    if (nonlinear) linear_solver_.newton_step(record.increment); // a linear law's tangent does not follow the velocity
    // A full step of a linear problem is its solution: no further step to measure.
    const bool increment_small =
        record.increment <= settings.increment_tolerance || (linear_problem && step == 1.0 && !set_changed);
    const bool converged =
        record.force_residual <= settings.tolerance && record.flux_residual <= settings.tolerance && increment_small;
    const bool near_convergence = !set_changed && record.force_residual <= kSetCheck * settings.tolerance &&
                                  record.flux_residual <= kSetCheck * settings.tolerance && !set_follows(problem);
    if ((converged || near_convergence) && set_changes < kMaxSetChanges) {
      bool consistent = true;
      for (NodalTerm* term : problem.nodal_terms)
        consistent = term->consistent(unknowns.nodal, converged) && consistent;
      if (!consistent) {
        phase_start = it;
        ++set_changes;
        // The active set changed: the field belongs to another problem; go
        // on from it with the new set.
        evaluate_with_new_set();
        set_changed = true;
        if (settings.verbose)
          log::detail("    active set changed at %s: Newton goes on", converged ? "convergence" : "near convergence");
        continue;
      }
    }
    if (converged) {
      report.converged = true;
      return report;
    }
  }
  report.failure = "no convergence in " + std::to_string(settings.max_iterations) + " Newton iterations";
  report.out_of_iterations = true;
  return report;
}

} // namespace anvil::solver

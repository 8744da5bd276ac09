// Benchmark (not a test): one increment of a block 2L × 2L × L (mm) on a box
// mesh of about N nodes, solved by Newton to its tolerance with one linear
// solver. Prints one line: nodes, unknowns, Newton iterations and, per Newton
// iteration, assembly, solver set-up (preconditioner or factorisation), solve,
// Krylov iterations, then the peak memory of the process. One configuration
// per process, so the peak memory is its own; tools/bench_increment runs the
// table of the issue. Under mpirun the processes share the increment (as
// `anvil run` does): rank 0 prints, with the peak memory of each process;
// tools/bench_mpi runs that table.
//
// Problems:
//   newtonian    η = 1 MPa.s, squeezed between sticking plates (top at 1 mm/s);
//   norton_hoff  m = 0.1, K = 100 MPa.s^m, ε̄̇₀ = 1e-4 1/s: a flat punch over
//                the half x < L of the top face indents the block on a
//                sticking base; away from the punch the block is a rigid
//                zone (viscosity contrast about 3e3 at the regularisation).
//
//   anvil_bench PROBLEM NODES SOLVER [--newton N] [--schur bfbt|mass]
//               [--no-reuse] [--repeat R] [--threads T] [--verbose]
//               [PETSc options]
//   SOLVER: fgmres | mumps | umfpack | minres | cholmod_ldlt | eigen_ldlt | auto
//   --newton N   at most N Newton iterations (default 60): per-iteration
//                figures of a long solve without waiting for its end
//   --repeat R   solve the increment R times from the same start, each with
//                a new preconditioner, and give the figures of the last: a
//                warm increment, as a run's later ones (the first also pays
//                the kernel for each page of memory it touches first)
#include "anvil/core/Timers.h"
#include "anvil/core/blas_kernels.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/mesh/generators.h"
#include "anvil/scene/BoundaryCondition.h"
#include "anvil/solver/IncrementSolver.h"
#include "anvil/solver/PetscSession.h"

#include <sys/resource.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace anvil;

namespace {

struct Problem {
  mesh::TetMesh mesh;
  scene::ImposedConditions imposed;
  std::unique_ptr<material::Material> law;
};

Problem make_problem(const std::string& name, long target_nodes) {
  // (2n+1)²(n+1) ≈ target nodes.
  const int n = std::max(2, static_cast<int>(std::lround(std::cbrt(static_cast<double>(target_nodes) / 4.0))));
  const double length = 10.0;
  Problem p{
      mesh::make_box(mesh::Point::Zero(), mesh::Point(2 * length, 2 * length, length), {2 * n, 2 * n, n}), {}, {}};
  scene::BoundaryCondition bottom, top;
  bottom.kind = top.kind = scene::BoundaryKind::sticking_plate;
  bottom.faces.tag = 5;
  top.faces.tag = 6;
  bottom.velocity = {0.0, 0.0, 0.0};
  top.velocity = {0.0, 0.0, -1.0};
  if (name == "newtonian") {
    p.imposed = scene::impose(p.mesh, {bottom, top});
    p.law = std::make_unique<material::NortonHoff>(1.0, 1.0, 0.0);
  } else if (name == "norton_hoff") {
    p.imposed = scene::impose(p.mesh, {bottom});
    for (int node : scene::face_nodes(p.mesh, scene::select_faces(p.mesh, top.faces))) {
      if (p.mesh.nodes[node].x() > length + 1e-9) continue; // the punch covers x <= L
      for (int c = 0; c < 3; ++c) {
        p.imposed.prescribed[4 * node + c] = 1;
        p.imposed.values[4 * node + c] = c == 2 ? -1.0 : 0.0;
      }
    }
    p.law = std::make_unique<material::NortonHoff>(100.0, 0.1, 1e-4);
  } else {
    throw InputError("unknown problem '" + name + "' (expected newtonian or norton_hoff)");
  }
  return p;
}

constexpr const char* kUsage =
    "usage: anvil_bench newtonian|norton_hoff NODES SOLVER [--newton N] [--schur bfbt|mass] [--no-reuse] "
    "[--repeat R] [--threads T] [--verbose] [PETSc options]\n";

} // namespace

int main(int argc, char** argv) {
  anvil::blas_kernels::pin(argv); // the kernels of anvil run (docs/parallel-runs.md)
  if (argc < 4) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  try {
    solver::LinearSolverSettings linear{solver::linear_solver_kind(argv[3])};
    solver::NewtonSettings settings;
    settings.max_iterations = 60;
    settings.verbose = false;
    int threads = 0; // 0: TBB's choice (every core the process may use)
    int repeat = 1;
    std::vector<char*> petsc_arguments = {argv[0]};
    for (int i = 4; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--newton" && i + 1 < argc)
        settings.max_iterations = std::atoi(argv[++i]);
      else if (arg == "--schur" && i + 1 < argc)
        linear.schur = solver::schur_approximation(argv[++i]);
      else if (arg == "--threads" && i + 1 < argc)
        threads = std::atoi(argv[++i]);
      else if (arg == "--repeat" && i + 1 < argc)
        repeat = std::max(1, std::atoi(argv[++i]));
      else if (arg == "--no-reuse")
        linear.reuse_preconditioner = false;
      else if (arg == "--verbose")
        settings.verbose = true; // Newton's lines, for a look
      else if (solver::is_petsc_option_name(arg))
        petsc_arguments.push_back(argv[i]);
      else if (petsc_arguments.size() > 1)
        petsc_arguments.push_back(argv[i]); // a PETSc option's value
      else
        throw InputError("unknown argument '" + arg + "'\n" + kUsage);
    }
    int petsc_argc = static_cast<int>(petsc_arguments.size());
    petsc_arguments.push_back(nullptr);
    char** petsc_argv = petsc_arguments.data();
    solver::PetscSession petsc(petsc_argc, petsc_argv);
    const tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism,
                                           threads > 0 ? threads : tbb::info::default_concurrency());
    const Problem problem = make_problem(argv[1], std::atol(argv[2]));
    Timers timers;
    log::set_quiet(!settings.verbose);
    solver::IncrementSolver solver(problem.mesh, problem.imposed.prescribed, linear, timers);
    Timers before; // the timers before the last increment
    int setups_before = 0;
    solver::NewtonReport report;
    for (int r = 0; r < repeat; ++r) {
      if (r > 0) solver.restart_linear_solver();
      before = timers;
      setups_before = solver.linear_solver().setups();
      fem::BodyUnknowns unknowns{problem.imposed.values, Eigen::VectorXd::Zero(3 * problem.mesh.tet_count())};
      report = solver.solve(problem.mesh, *problem.law, {}, problem.imposed.nodal_forces, {}, settings, unknowns);
    }
    const auto seconds = [&](const char* phase) { return timers.seconds(phase) - before.seconds(phase); };

    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::vector<double> peaks(static_cast<std::size_t>(processes::count()), 0.0); // GB per process
    peaks[processes::rank()] = static_cast<double>(usage.ru_maxrss) / (1024.0 * 1024.0);
    processes::sum(peaks);
    std::string peak_text;
    for (double peak : peaks) {
      char text[16];
      std::snprintf(text, sizeof text, "%s%.2f", peak_text.empty() ? "" : "/", peak);
      peak_text += text;
    }
    if (!processes::root()) return report.converged ? 0 : 1;
    // The predictor of a nonlinear law is one more linear solve. The matrix's
    // pattern (distributed: the COO map of each process's entries) is made
    // once per mesh in a run: shown apart, not in the per-solve set-up.
    const bool predictor = !problem.law->is_linear();
    const double solves = static_cast<double>(report.iterations.size()) + (predictor ? 1.0 : 0.0);
    const double pattern = timers.seconds("matrix pattern"); // the first increment's
    const double setup = seconds("solver setup") - seconds("matrix pattern");
    const double total = seconds("assembly") + setup + seconds("solve");
    std::printf("%-11s nodes %7d  unknowns %8d  %-7s newton %2zu%s (%s)  per solve: assembly %6.2f s  setup %6.2f s  "
                "solve %6.2f s  total %6.2f s  krylov %5.1f  setups %d  increment %7.2f s  pattern %5.2f s  "
                "peak %s GB  processes %d\n",
                argv[1], problem.mesh.node_count(), solver.free_count(),
                solver::to_string(solver.linear_solver().kind()).c_str(), report.iterations.size(),
                predictor ? "+1" : "", report.converged ? "converged" : report.failure.c_str(),
                seconds("assembly") / solves, setup / solves, seconds("solve") / solves, total / solves,
                report.linear_iterations / solves, solver.linear_solver().setups() - setups_before,
                total + seconds("matrix pattern"), pattern, peak_text.c_str(), processes::count());
    return report.converged ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "anvil_bench: %s\n", e.what());
    return 3;
  }
}

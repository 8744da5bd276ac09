// Benchmark (not a test): one Newtonian increment of a block squeezed between
// sticking plates, on a box mesh of about N nodes. Prints nodes, unknowns,
// assembly time, factorisation + solve time per Newton iteration, Newton
// iterations and peak memory. One size per process, so the peak RSS is the
// size's own; tools/bench_increment runs the sizes.
//   anvil_bench NODES [auto|umfpack|cholmod_ldlt|eigen_ldlt]
#include "anvil/core/Timers.h"
#include "anvil/core/log.h"
#include "anvil/mesh/generators.h"
#include "anvil/scene/BoundaryCondition.h"
#include "anvil/solver/IncrementSolver.h"
#include "anvil/solver/PetscSession.h"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace anvil;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: anvil_bench NODES [auto|umfpack|cholmod_ldlt|eigen_ldlt|minres]\n");
    return 2;
  }
  solver::PetscSession petsc(argc, argv);
  const long target = std::atol(argv[1]);
  const solver::LinearSolverKind kind = solver::linear_solver_kind(argc > 2 ? argv[2] : "auto");
  // Block 2L × 2L × L (mm) with cells (2n, 2n, n): (2n+1)²(n+1) ≈ target nodes.
  const int n = std::max(2, static_cast<int>(std::lround(std::cbrt(static_cast<double>(target) / 4.0))));
  const mesh::TetMesh mesh = mesh::make_box(mesh::Point::Zero(), mesh::Point(20, 20, 10), {2 * n, 2 * n, n});

  scene::BoundaryCondition bottom, top;
  bottom.kind = top.kind = scene::BoundaryKind::sticking_plate;
  bottom.faces.tag = 5;
  top.faces.tag = 6;
  bottom.velocity = {0.0, 0.0, 0.0};
  top.velocity = {0.0, 0.0, -1.0};
  const scene::ImposedConditions imposed = scene::impose(mesh, {bottom, top});

  Timers timers;
  log::set_quiet(true);
  solver::IncrementSolver solver(mesh, imposed.prescribed, {kind}, timers);
  fem::BodyUnknowns unknowns{imposed.values, Eigen::VectorXd::Zero(3 * mesh.tet_count())};
  const material::NortonHoff newtonian(1.0, 1.0, 0.0);
  solver::NewtonSettings settings;
  settings.verbose = false;
  const auto report = solver.solve(newtonian, {}, imposed.nodal_forces, {}, settings, unknowns);

  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double iterations = static_cast<double>(report.iterations.size());
  const double assembly = timers.seconds("assembly") / iterations, solve = timers.seconds("solve") / iterations;
  std::printf("nodes %d  elements %d  unknowns %d  solver %s  newton %d (%s)  per iteration: assembly %.2f s, "
              "factorisation+solve %.2f s, total %.2f s  peak memory %.2f GB  (last solve: %d iterative steps)\n",
              mesh.node_count(), mesh.tet_count(), solver.free_count(), solver::to_string(solver.linear_solver().kind()).c_str(),
              static_cast<int>(iterations), report.converged ? "converged" : report.failure.c_str(), assembly, solve,
              assembly + solve, static_cast<double>(usage.ru_maxrss) / (1024.0 * 1024.0), report.linear_iterations);
  return report.converged ? 0 : 1;
}

// Two bars squeezed with a sticking interface (Fourment 2008 §5.1):
// squeezing force against a run 4 times finer than the finest mesh, over a
// sequence of meshes, matching (both bars h) and non-matching (upper bar one
// cell more per side), with master/slave and quasi-symmetric contact.
// Prints a Markdown table and writes DIR/bars_study.csv (default
// out/bars_study); tools/bars_study plots error against degrees of freedom
// and against wall time (DIR/bars_dofs.png, DIR/bars_time.png).
#include "anvil/core/blas_kernels.h"
#include "anvil/core/log.h"
#include "anvil/io/RunResults.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"
#include "anvil/solver/PetscSession.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct Result {
  double force = 0.0;     ///< N, squeezing force on the top plate
  double unknowns = 0.0;  ///< degrees of freedom (velocity and pressure)
  double wall_time = 0.0; ///< s
  int newton_iterations = 0;
};

/// One run with `lower_cells` and `upper_cells` cells across the 2 mm bar height.
Result run(int lower_cells, int upper_cells, const std::string& formulation, const std::string& out) {
  const anvil::scene::Case c =
      anvil::scene::read_case(std::string(ANVIL_SOURCE_DIR) + "/cases/two_bars.yaml",
                              {"bodies[0].mesh.element_size=" + std::to_string(2.0 / lower_cells),
                               "bodies[1].mesh.element_size=" + std::to_string(2.0 / upper_cells),
                               "contact_pairs[0].formulation=" + formulation});
  std::filesystem::remove_all(out);
  anvil::run::run(c, {out});
  return {anvil::io::read_loads(out, "top").back().force.z(), anvil::io::read_summary_number(out, "unknowns"),
          anvil::io::read_summary_number(out, "total"),
          static_cast<int>(anvil::io::read_summary_number(out, "newton_iterations"))};
}

} // namespace

int main(int argc, char** argv) {
  anvil::blas_kernels::pin(argv); // the kernels of anvil run (docs/parallel-runs.md)
  const std::string out = argc > 1 ? argv[1] : "out/bars_study";
  if (out == "--help" || out == "-h") {
    std::puts("usage: tools/bars_study [DIR]   (13 runs, a minute or two; writes DIR/bars_study.csv and two plots)");
    return 0;
  }
  int petsc_argc = 1; // the tool's own arguments are not PETSc's
  anvil::solver::PetscSession petsc(petsc_argc, argv);
  try {
    std::filesystem::create_directories(out);
    anvil::log::set_quiet(true);
    const int finest = 4; // cells across a bar's height; the reference has 4 × 4
    const Result reference = run(4 * finest, 4 * finest, "quasi_symmetric", out + "/run");
    std::printf("reference: %d cells across each bar, %.0f unknowns, %.6g N, %.1f s\n\n", 4 * finest,
                reference.unknowns, reference.force, reference.wall_time);
    std::ofstream csv(out + "/bars_study.csv");
    csv << "meshes,formulation,lower_cells,upper_cells,unknowns,wall_time_s,newton_iterations,force_N,error_percent\n";
    std::printf("| meshes (lower/upper cells) | formulation | unknowns | force | error | Newton | time |\n"
                "|---|---|---|---|---|---|---|\n");
    for (const char* meshes : {"matching", "non-matching"})
      for (const char* formulation : {"master_slave", "quasi_symmetric"})
        for (int cells = 1; cells <= finest; ++cells) {
          const int upper = std::string(meshes) == "matching" ? cells : cells + 1;
          const Result r = run(cells, upper, formulation, out + "/run");
          const double error = 100.0 * std::abs(r.force - reference.force) / reference.force;
          std::printf("| %s %d/%d | %s | %.0f | %.5g N | %.3f %% | %d | %.2f s |\n", meshes, cells, upper, formulation,
                      r.unknowns, r.force, error, r.newton_iterations, r.wall_time);
          std::fflush(stdout);
          csv << meshes << "," << formulation << "," << cells << "," << upper << "," << r.unknowns << "," << r.wall_time
              << "," << r.newton_iterations << "," << r.force << "," << error << "\n";
        }
    std::printf("results in %s/\n", out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bars_study: %s\n", e.what());
    return 1;
  }
  return 0;
}

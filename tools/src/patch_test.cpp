// The contact patch test table (Fourment 2008 §5.2): the four load
// cases × the mesh pairs × master/slave, quasi-symmetric and symmetric, with
// the relative error of the normal stress transmitted across the interface
// (max and RMS over the interface nodes of both bodies), the largest error of
// σzz inside the bodies, and the cost (wall time, Newton iterations).
// Prints a Markdown table and writes DIR/patch_test.csv (default out/patch_test_table).
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/solver/PetscSession.h"
#include "patch_test_cases.h"

#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "out/patch_test_table";
  if (out == "--help" || out == "-h") {
    std::puts("usage: tools/patch_test [DIR]   (runs 72 small cases, about a minute; writes DIR/patch_test.csv)");
    return 0;
  }
  int petsc_argc = 1; // the tool's own arguments are not PETSc's
  anvil::solver::PetscSession petsc(petsc_argc, argv);
  try {
    std::filesystem::create_directories(out);
    anvil::log::set_quiet(true);
    std::ofstream csv(out + "/patch_test.csv");
    csv << "case,meshes,formulation,interface_max,interface_rms,interior_max,interface_nodes,newton_iterations,wall_"
           "time_s\n";
    std::printf("| case | meshes (master/slave cells) | formulation | interface max | interface RMS | interior max | "
                "Newton | time |\n"
                "|---|---|---|---|---|---|---|---|\n");
    for (const auto& load : patch_test::load_cases())
      for (const auto& meshes : patch_test::mesh_pairs())
        for (const char* formulation : {"master_slave", "quasi_symmetric", "symmetric"}) {
          const patch_test::Errors e = patch_test::run(load, meshes, formulation, ANVIL_SOURCE_DIR, out + "/run");
          std::printf("| %s | %s | %s | %.2f %% | %.2f %% | %.2f %% | %d | %.2f s |\n", load.name, meshes.name,
                      formulation, 100 * e.interface_max, 100 * e.interface_rms, 100 * e.interior_max,
                      e.newton_iterations, e.wall_time);
          std::fflush(stdout);
          csv << '"' << load.name << "\",\"" << meshes.name << "\"," << formulation << "," << e.interface_max << ","
              << e.interface_rms << "," << e.interior_max << "," << e.interface_nodes << "," << e.newton_iterations
              << "," << e.wall_time << "\n";
        }
    std::printf("results in %s/\n", out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "patch_test: %s\n", e.what());
    return 1;
  }
  return 0;
}

// anvil_signature CASE.yaml OUT_DIR: runs a case as the regression test does
// (its first increments) into OUT_DIR and writes its signature (CSV) to
// OUT_DIR/signature.csv, not to stdout, where libraries print too (ML's
// geometric aggregation, on nodes of two bodies in contact at one place).
// tools/update_signatures calls it for every case.
#include "signature.h"
#include "anvil/core/blas_kernels.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/io/atomic_file.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"
#include "anvil/solver/PetscSession.h"

#include <cstdio>
#include <filesystem>

int main(int argc, char** argv) {
  anvil::blas_kernels::pin(argv); // the kernels of anvil run (docs/parallel-runs.md)
  if (argc != 3) {
    std::fputs("usage: anvil_signature CASE.yaml OUT_DIR\n", stderr);
    return 2;
  }
  int petsc_argc = 1; // the tool's own arguments are not PETSc's
  anvil::solver::PetscSession petsc(petsc_argc, argv);
  try {
    anvil::log::set_quiet(true);
    anvil::io::write_file_atomically((std::filesystem::path(argv[2]) / "signature.csv").string(),
                                     signature::to_csv(signature::of_run(signature::run(argv[1], argv[2]))));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "anvil_signature: %s: %s\n", argv[1], e.what());
    return 1;
  }
}

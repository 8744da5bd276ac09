// The test binaries' entry point: Catch2's runner inside a PETSc session, as
// anvil's own main() runs a case (the solvers live on PETSC_COMM_WORLD).
#define CATCH_CONFIG_RUNNER
#include "anvil/solver/PetscSession.h"

#include <catch2/catch.hpp>

int main(int argc, char** argv) {
  // PETSc reads no options from the test command line: Catch2 owns it.
  int petsc_argc = 1;
  char** petsc_argv = argv;
  anvil::solver::PetscSession petsc(petsc_argc, petsc_argv);
  return Catch::Session().run(argc, argv);
}

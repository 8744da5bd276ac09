// The test binaries' entry point: Catch2's runner inside a PETSc session, as
// anvil's own main() runs a case (the solvers live on PETSC_COMM_WORLD).
#define CATCH_CONFIG_RUNNER
#include "anvil/core/processes.h"
#include "anvil/solver/PetscSession.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

int main(int argc, char** argv) {
  // PETSc reads no options from the test command line: Catch2 owns it.
  int petsc_argc = 1;
  char** petsc_argv = argv;
  anvil::solver::PetscSession petsc(petsc_argc, petsc_argv);
  Catch::Session session;
  if (const int wrong = session.applyCommandLine(argc, argv); wrong != 0) return wrong;
  // A listing runs no test (and its reader may stop reading it: ctest's
  // check that a program lists its tests, grep -q).
  const Catch::Config& asked = session.config();
  if (asked.listTests() || asked.listTestNamesOnly() || asked.listTags() || asked.listReporters()) return session.run();
  // The tests write their runs under a folder of this program's own, given
  // to them as TMPDIR (std::filesystem::temp_directory_path, and the anvil
  // processes a test starts): with fixed names under /tmp, two test programs
  // running at once (two ctest runs side by side) wrote the same run folders
  // and one read the other's files, and its signatures failed. The processes
  // of an mpirun share rank 0's folder. It goes when every test passed and
  // stays, the error stream saying where, when one failed (and wrote there).
  std::string scratch;
  if (anvil::processes::root()) {
    scratch = (std::filesystem::temp_directory_path() / "anvil_tests.XXXXXX").string();
    if (!mkdtemp(scratch.data())) {
      std::perror(("tests: cannot make a folder " + scratch).c_str());
      scratch.clear();
    }
  }
  anvil::processes::broadcast(scratch);
  if (scratch.empty()) return 1;
  setenv("TMPDIR", scratch.c_str(), 1);
  const int failed = session.run();
  // Taken together, after every process's tests: none is still writing there.
  const bool all_passed = anvil::processes::maximum(failed) == 0;
  if (anvil::processes::root()) {
    std::error_code error;
    if (all_passed || std::filesystem::is_empty(scratch, error)) {
      // A child of a test can still be clearing its own files there: an
      // entry gone under remove_all stops it (ENOENT; the OpenBLAS kernels
      // test's anvil run, one run in a few), and it is tried again.
      for (int attempt = 0; attempt < 3; ++attempt)
        if (std::filesystem::remove_all(scratch, error); !error) break;
      if (error) std::fprintf(stderr, "tests: %s not removed: %s\n", scratch.c_str(), error.message().c_str());
    } else {
      std::fprintf(stderr, "tests: their runs are kept in %s\n", scratch.c_str());
    }
  }
  return failed;
}

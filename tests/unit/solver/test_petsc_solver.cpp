// The PETSc side of the linear solve as a user meets it: options from the
// case file, PETSc's failures in our words, the fallback to the direct
// solver when the Krylov method stagnates.
#include "run_outputs.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/solver/PetscSession.h"

#include <petscsys.h>

using namespace anvil;

namespace {
const std::string kDisc = "cases/squeeze_disc_newtonian.yaml";
}

TEST_CASE("solver.petsc_options must be PETSc options: an input error names the key", "[unit]") {
  try {
    scene::read_case(source_path(kDisc), {"solver.petsc_options='ksp_monitor -ksp_view'"});
    FAIL("accepted a value without an option name");
  } catch (const InputError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("solver.petsc_options") != std::string::npos);
    CHECK(message.find("'ksp_monitor'") != std::string::npos);
  }
  const auto options = solver::parse_petsc_options("-ksp_rtol 1e-3 -ksp_monitor -mat_shift -1e-2", "test");
  REQUIRE(options.size() == 3);
  CHECK(options[0] == std::pair<std::string, std::string>{"-ksp_rtol", "1e-3"});
  CHECK(options[1] == std::pair<std::string, std::string>{"-ksp_monitor", ""});
  CHECK(options[2] == std::pair<std::string, std::string>{"-mat_shift", "-1e-2"}); // a number is a value
}

TEST_CASE("a PETSc failure stops the run with a message in our words", "[unit]") {
  log::set_quiet(true);
  const scene::Case c = scene::read_case(
      source_path(kDisc), {"solver.linear_solver=fgmres", "solver.petsc_options='-fieldsplit_0_pc_type no_such_pc'"});
  try {
    run_case(c, "anvil_petsc_failure");
    FAIL("the run went through");
  } catch (const RunError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("PETSc failed while") != std::string::npos);
    CHECK(message.find("no_such_pc") != std::string::npos);
  }
}

TEST_CASE("FGMRES that stagnates hands over to MUMPS, and the case's PETSc options end with the run", "[unit]") {
  // Two FGMRES iterations cannot reach the Krylov tolerance on this disc:
  // MUMPS takes over and the load is the direct solver's (Newton 1e-10 in
  // both runs, so the loads agree to ~1e-10; asserted at 1e-8).
  log::set_quiet(true);
  const std::vector<std::string> tight = {"solver.tolerance=1e-10", "output.vtk=false"};
  std::vector<std::string> stagnating = tight;
  stagnating.insert(stagnating.end(), {"solver.linear_solver=fgmres", "solver.petsc_options='-ksp_max_it 2'"});
  const RunOutputs fallback = run_case(scene::read_case(source_path(kDisc), stagnating), "anvil_petsc_fallback");
  std::vector<std::string> direct = tight;
  direct.push_back("solver.linear_solver=mumps");
  const RunOutputs reference = run_case(scene::read_case(source_path(kDisc), direct), "anvil_petsc_direct");
  const double load = fallback.loads("top").back().force.z(), expected = reference.loads("top").back().force.z();
  INFO("after the fallback " << load << " N, MUMPS " << expected << " N");
  CHECK(std::abs(load - expected) <= 1e-8 * std::abs(expected));
  CHECK(file_text(fallback.directory + "/summary.json").find("\"linear_solver\": \"mumps\"") !=
        std::string::npos); // the solver in use at the end
  PetscBool left = PETSC_TRUE;
  PetscOptionsHasName(nullptr, nullptr, "-ksp_max_it", &left);
  CHECK(!left);
}

#include "anvil/solver/PetscSession.h"

#include "anvil/core/error.h"
#include "anvil/core/processes.h"
#include "petsc_check.h"

#include <petscsys.h>

#include <cctype>
#include <cstdlib>
#include <dlfcn.h>
#include <set>
#include <sstream>

namespace anvil::solver {
namespace {

bool g_active = false;
std::string g_last_error;
/// Options anvil put in the database itself (defaults), not the user's.
std::set<std::string> g_own_options;

/// Keeps the first message of an error (the innermost call) instead of
/// printing a traceback; PETSc then returns the code up the stack.
PetscErrorCode keep_message(MPI_Comm, int, const char* function, const char*, PetscErrorCode code, PetscErrorType type,
                            const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) {
    const char* generic = nullptr;
    PetscErrorMessage(code, &generic, nullptr);
    g_last_error = std::string(message && *message ? message : (generic ? generic : "unknown error")) + " (in " +
                   (function ? function : "?") + ")";
  }
  return code;
}

} // namespace

namespace petsc {

std::string last_error() {
  return g_last_error;
}

void check(PetscErrorCode code, const char* doing) {
  if (code == 0) return;
  std::string message = g_last_error.empty() ? "error code " + std::to_string(code) : g_last_error;
  g_last_error.clear();
  throw RunError(std::string("PETSc failed while ") + doing + ": " + message);
}

void check_options(PetscErrorCode code) {
  if (code == 0) return;
  std::string message = g_last_error.empty() ? "error code " + std::to_string(code) : g_last_error;
  g_last_error.clear();
  throw InputError("a PETSc option (command line or solver.petsc_options) is not valid: " + message);
}

} // namespace petsc

namespace {

/// One BLAS and OpenMP thread unless OPENBLAS_NUM_THREADS or OMP_NUM_THREADS
/// say otherwise: a multithreaded BLAS sums in an order that changes from run
/// to run (two outcomes in five runs of a remeshing case, 6e-7 apart), which
/// would make a resumed run end otherwise than the uninterrupted one; and its
/// threads would spin on the cores TBB assembles with. Found at run time:
/// the BLAS behind libblas.so.3 is Debian's choice (alternatives).
void one_blas_thread() {
  using SetThreads = void (*)(int);
  if (!std::getenv("OPENBLAS_NUM_THREADS"))
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
  if (!std::getenv("OMP_NUM_THREADS"))
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "omp_set_num_threads"))) set(1);
}

} // namespace

PetscSession::PetscSession(int& argc, char**& argv) {
  // A process started without a launcher is an MPI singleton, for which
  // Open MPI starts a daemon in case it spawns processes; Anvil never does,
  // and the daemon costs each start about 0.2 s (a test program: 0.68 s
  // against 0.45 s). A value the user set is kept.
  if (!processes::under_launcher()) setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) throw RunError("PETSc (MPI) could not be initialised");
  g_active = true;
  PetscPushErrorHandler(keep_message, nullptr);
  PetscPopSignalHandler();                  // a crash stays a crash with its own signal, not a PETSc banner
  set_default_option("-options_left", "0"); // unused options are reported by unused_options(), in our words
  one_blas_thread();
}

PetscSession::~PetscSession() {
  g_active = false;
  g_own_options.clear();
  PetscFinalize();
}

bool PetscSession::active() {
  return g_active;
}

std::vector<std::string> PetscSession::unused_options() {
  std::vector<std::string> unused;
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  if (PetscOptionsLeftGet(nullptr, &count, &names, &values) != 0) return unused;
  for (PetscInt i = 0; i < count; ++i) {
    const std::string name = std::string("-") + names[i];
    if (!g_own_options.count(name)) unused.push_back(name);
  }
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
  return unused;
}

bool is_petsc_option_name(const std::string& token) {
  if (token.size() < 2 || token[0] != '-') return false;
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return !(end && *end == '\0'); // -1e-3 is a value
}

void set_default_option(const std::string& name, const std::string& value) {
  PetscBool present = PETSC_FALSE;
  petsc::check(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &present), "reading the options database");
  if (present) return;
  petsc::check(PetscOptionsSetValue(nullptr, name.c_str(), value.empty() ? nullptr : value.c_str()),
               "setting a default option");
  g_own_options.insert(name);
}

std::vector<std::pair<std::string, std::string>> parse_petsc_options(const std::string& text,
                                                                     const std::string& source) {
  std::vector<std::pair<std::string, std::string>> options;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    if (is_petsc_option_name(token)) {
      options.emplace_back(token, "");
    } else if (options.empty() || !options.back().second.empty()) {
      throw InputError(source + ": '" + token +
                       "' is not a PETSc option (expected options such as '-ksp_monitor -fieldsplit_0_pc_type gamg')");
    } else {
      options.back().second = token;
    }
  }
  return options;
}

ScopedPetscOptions::ScopedPetscOptions(const std::string& text, const std::string& source) {
  for (const auto& [name, value] : parse_petsc_options(text, source)) {
    PetscBool present = PETSC_FALSE;
    petsc::check(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &present), "reading the options database");
    if (present && !g_own_options.count(name)) continue; // the command line wins
    petsc::check(PetscOptionsSetValue(nullptr, name.c_str(), value.empty() ? nullptr : value.c_str()),
                 "setting a case option");
    g_own_options.erase(name);
    set_.push_back(name);
  }
}

ScopedPetscOptions::~ScopedPetscOptions() {
  for (const std::string& name : set_)
    PetscOptionsClearValue(nullptr, name.c_str());
}

} // namespace anvil::solver

// PETSc (and through it MPI) for the lifetime of a program: main() makes one
// PetscSession before anything solves, and PETSc objects live on
// PETSC_COMM_WORLD, so a multi-process run reuses them unchanged. PETSc's
// own command-line options (-ksp_monitor, -fieldsplit_0_pc_type gamg, ...)
// are read from argv; a case adds its own with ScopedPetscOptions.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace anvil::solver {

class PetscSession {
public:
  /// PetscInitialize with the program's arguments (PETSc takes the options
  /// that start with one '-'; anvil's own are left to the caller). PETSc's
  /// error printing and signal handlers are switched off: failures reach the
  /// caller as RunError in our words.
  PetscSession(int& argc, char**& argv);
  ~PetscSession(); ///< PetscFinalize
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

  /// True between a PetscSession's construction and destruction.
  static bool active();
  /// PETSc options given on the command line that nothing read, for a warning.
  static std::vector<std::string> unused_options();
};

/// PETSc options in the options database for the lifetime of this object: a
/// case's (solver.petsc_options), or anvil's own for one solver's set-up
/// (KrylovSolver); an option also given on the command line or by a case
/// keeps that value. Takes "-name value -flag ..." text.
class ScopedPetscOptions {
public:
  /// Throws InputError naming `source` when the text is not a list of
  /// options (a value before any -name).
  ScopedPetscOptions(const std::string& text, const std::string& source);
  ~ScopedPetscOptions();
  ScopedPetscOptions(const ScopedPetscOptions&) = delete;
  ScopedPetscOptions& operator=(const ScopedPetscOptions&) = delete;

private:
  std::vector<std::string> set_; ///< names this object put in the database
};

/// Puts `name` = `value` in the options database unless it is there already
/// (the defaults anvil chooses for PETSc's nested solvers stay overridable).
void set_default_option(const std::string& name, const std::string& value);

/// True for "-name" (one or two leading dashes, not a number such as -1e-3).
bool is_petsc_option_name(const std::string& token);

/// Splits "-a 1 -b -c x" into (name, value) pairs ("" for a flag); a token
/// that is a number (-1e-3) is a value. Throws InputError naming `source`
/// when a value comes before any name.
std::vector<std::pair<std::string, std::string>> parse_petsc_options(const std::string& text,
                                                                     const std::string& source);

} // namespace anvil::solver

// PETSc calls inside the solver: an error code becomes a RunError that says
// what anvil was doing and what PETSc reported (PetscSession installs the
// handler that keeps PETSc's message instead of printing it).
#pragma once
#include <petscsys.h>

#include <string>

namespace anvil::solver::petsc {

/// PETSc's message for the last error (empty when none was recorded).
std::string last_error();

/// Throws RunError("PETSc failed while <doing>: <message>") when `code` != 0.
void check(PetscErrorCode code, const char* doing);

/// Throws InputError naming the PETSc options when `code` != 0: a call that
/// reads them fails on a value the user gave (anvil exits 3).
void check_options(PetscErrorCode code);

} // namespace anvil::solver::petsc

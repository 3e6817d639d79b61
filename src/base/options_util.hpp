// The options database as a record and as a check: all options as one string
// (stored with results), and unused options (typos) turned into an error.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// Every option set (command line and files), as "-name value" pairs.
PetscErrorCode OptionsAsString(std::string *all);

// The number of comma-separated values given to option `name` (0 when it is not given): the
// size to allocate before PetscOptionsRealArray, so that lists have no fixed limit.
PetscErrorCode OptionsListLength(const char *name, PetscInt *n);

// Errors out, naming them, when options of the program's own were set but never read (a typo
// or an option that the chosen task does not use); -allow_unused_options turns the error into
// a warning. PETSc's solver options left over (-ts_*, -snes_*, ...: a scene's -ts_rk_type under
// a later -ts_type cn) are a one-line note, unless strict_solver_options (a convergence
// configuration must run as written: there a typo is an error too). Options whose names start
// with one of ignore_prefixes (without the dash, e.g. "ts_") are not reported: a task that
// legitimately does not use them says so itself.
PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes = {}, bool strict_solver_options = false);

} // namespace beamimpact

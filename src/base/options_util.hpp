// The options database as a record and as a check: all options as one string
// (stored with results), and unused options (typos) turned into an error.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// Every option set (command line and files), as "-name value" pairs.
PetscErrorCode OptionsAsString(std::string *all);

// Errors out, naming them, when options were set but never read (a typo or an
// option that the chosen task/integrator does not use). -allow_unused_options
// turns the error into a warning.
// Options whose names start with one of ignore_prefixes (without the dash, e.g. "ts_")
// are not reported: a task that legitimately does not use them says so itself.
// The number of comma-separated values given to option `name` (0 when it is not given): the
// size to allocate before PetscOptionsRealArray, so that lists have no fixed limit.
PetscErrorCode OptionsListLength(const char *name, PetscInt *n);

PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes = {});

} // namespace beamimpact

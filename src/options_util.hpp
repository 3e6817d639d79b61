// The options database as a record and as a check: all options as one string
// (stored with results), and unused options (typos) turned into an error.
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// Every option set (command line and files), as "-name value" pairs.
PetscErrorCode OptionsAsString(std::string *all);

// Errors out, naming them, when options were set but never read (a typo or an
// option that the chosen task/integrator does not use). -allow_unused_options
// turns the error into a warning.
PetscErrorCode OptionsCheckUnused(MPI_Comm comm);

} // namespace beamimpact

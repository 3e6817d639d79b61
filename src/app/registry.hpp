// Everything the program registers once per process, before any option is read: the option
// table of every module (base/option_table.hpp), so that -help, the unknown-option check, the
// sweep's units and choices and the run record know every option. The executable calls it
// after SlepcInitialize; the tests' main calls it too.
#pragma once

#include <petscsys.h>

namespace beamimpact {

PetscErrorCode RegisterAll();

} // namespace beamimpact

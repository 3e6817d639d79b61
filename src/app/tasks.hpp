// The tasks the executable runs (-task impact|modes|sweep|convergence): each reads its
// modules' options, runs on the communicator it is given, prints a summary on its rank 0
// and writes one HDF5 file. The sweep and the convergence study live in src/studies.
#pragma once

#include "base/option_table.hpp"
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>

namespace beamimpact {

// Reads -task and -output (default <task>.h5; "none": no file) and runs the task; under -help
// only prints every option (PrintAllOptions).
PetscErrorCode RunTask(MPI_Comm comm);

// The task module's table: -task, -output, -output_overwrite, -allow_unused_options,
// -error_traceback (registered by app/registry.cpp).
const OptionModule &TaskOptionTable();

// -help: every reader of every task once (each prints its block; their errors ignored) and the
// PETSc options the program advertises; nothing is run or written. Prints only under -help.
PetscErrorCode PrintAllOptions(MPI_Comm comm);

PetscErrorCode TaskImpact(MPI_Comm comm, const std::string &output);
PetscErrorCode TaskModes(MPI_Comm comm, const std::string &output);

// One summary line of an impact.
PetscErrorCode ImpactPrintSummary(MPI_Comm comm, const Scenario &sc, const ImpactResult &r);

} // namespace beamimpact

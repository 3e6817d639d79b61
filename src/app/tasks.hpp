// The tasks the executable runs (-task impact|modes): each reads its modules'
// options, runs on the communicator it is given, prints a summary on its
// rank 0 and writes one HDF5 file.
#pragma once

#include "model/beam.hpp"
#include "model/contact.hpp"
#include "run/impact.hpp"
#include "io/results_h5.hpp"

#include <petscsys.h>

namespace beamimpact {

enum class Task { Impact = 0, Modes = 1, Sweep = 2, Convergence = 3 };

// Reads -task and -output, dispatches.
PetscErrorCode RunTask(MPI_Comm comm);

PetscErrorCode TaskImpact(MPI_Comm comm, const std::string &output);
PetscErrorCode TaskModes(MPI_Comm comm, const std::string &output);

// One summary line of an impact.
PetscErrorCode ImpactPrintSummary(MPI_Comm comm, const ImpactResult &r);

} // namespace beamimpact

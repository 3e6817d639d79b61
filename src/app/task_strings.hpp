// -strings_frame held -task modes: the string bed's modes in a held frame (docs/model.md, "The
// string bed"; issue 25's first slice), the membrane on a 2-D DMDA over the run's ranks.
//
//   mpiexec -n 4 beamimpact -options_file options/scenes/strings-modes.opts
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// Whether -task modes is the bed's: -strings_frame given and held.
PetscErrorCode TaskModesIsStringBed(MPI_Comm comm, PetscBool *bed);

// Reads -strings_*, -head_* and -modes_count, solves, prints the summary and writes the file
// (unless output is empty).
PetscErrorCode TaskStringBedModes(MPI_Comm comm, const std::string &output);

// Under -help: the bed's block.
PetscErrorCode StringBedHelpOptions(MPI_Comm comm);

} // namespace beamimpact

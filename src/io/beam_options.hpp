// The -beam_* options: geometry, material, section (uniform, profile or table), theory,
// supports, damping. One PetscOptionsBegin block; every range checked with a message naming
// the option (or the file and line) and the value.
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

namespace beamimpact {

// Reads the options, converts the parameter set to sections, checks every range.
PetscErrorCode BeamParamsFromOptions(MPI_Comm comm, BeamParams *p);

// Range and consistency checks, with messages naming the option and the value.
PetscErrorCode BeamParamsCheck(MPI_Comm comm, const BeamParams &p);

} // namespace beamimpact

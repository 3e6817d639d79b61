// The -ball_* options: mass, speed, contact law, and the characterisation of a ball as it is
// tested (rigid-wall COR and contact time at a test speed, an e(v) table). One
// PetscOptionsBegin block; every value checked with a message naming the option.
#pragma once

#include "model/contact.hpp"

#include <petscsys.h>

namespace beamimpact {

// Reads -ball_* options; checks ranges with messages naming option and value.
PetscErrorCode BallParamsFromOptions(MPI_Comm comm, BallParams *b);

} // namespace beamimpact

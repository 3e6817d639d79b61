// Where a ball may strike the beam: on it (0 <= x <= L) and not on a held point (a clamped
// or pinned support or inside -beam_clamp). One test for -impact_x and every sweep point.
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

namespace beamimpact {

// Where x (m) lies: on the beam and free to move, off the beam, or on a held point.
enum class ImpactPointWhere { Movable, OffBeam, Held };
ImpactPointWhere ImpactPointLocate(const BeamParams &beam, PetscReal x);

// Errors out on comm when x (m) is off the beam or held fixed. `what` names the value in
// the message, which reads "<what> is not allowed: ...", e.g. "-impact_x 0.2" (formatted
// with PetscSNPrintf, so numbers read as in PETSc's other messages).
PetscErrorCode ImpactPointCheck(MPI_Comm comm, const BeamParams &beam, PetscReal x, const char *what);

} // namespace beamimpact

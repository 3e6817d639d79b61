// Where a ball may strike the beam: on it (0 <= x <= L) and not on a held point (a clamped
// or pinned support or inside -beam_clamp); a racket's string bed anywhere inside its head's
// outline, and nowhere else off the frame's axis (z != 0). One test for -impact_x, -impact_z
// and every sweep point.
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

namespace beamimpact {

// Where (x, z) (m) lies: on the beam (or the bed) and free to move, off the beam (or off a
// racket's face), or on a held point.
enum class ImpactPointWhere { Movable, OffBeam, Held, OffFace };
ImpactPointWhere ImpactPointLocate(const BeamParams &beam, PetscReal x, PetscReal z = 0);

// Errors out on comm when x (m) is off the beam or held fixed. `what` names the value in
// the message, which reads "<what> is not allowed: ...", e.g. "-impact_x 0.2" (formatted
// with PetscSNPrintf, so numbers read as in PETSc's other messages).
PetscErrorCode ImpactPointCheck(MPI_Comm comm, const BeamParams &beam, PetscReal x, const char *what, PetscReal z = 0);

// -impact_z z != 0 (m) needs something it can strike off the frame's axis: a string bed (then
// inside its head: ImpactPointCheck) or the frame's roll (-beam_torsion, a lever arm z). Errors
// out on comm.
PetscErrorCode ImpactAcrossCheck(MPI_Comm comm, const BeamParams &beam, PetscReal z);

} // namespace beamimpact

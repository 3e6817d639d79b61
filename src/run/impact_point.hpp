// Where a ball may strike the beam: on it (0 <= x <= L) and not on a held point (a clamped
// or pinned support or inside -beam_clamp); a racket's string bed anywhere inside its head's
// outline, and nowhere else off the frame's axis (z != 0); a frame without a bed within its
// section's half-width (FrameHalfWidth). One test for -impact_x, -impact_z and every sweep point.
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

namespace beamimpact {

// How far off the frame's axis (m) a frame without a string bed can be struck at x (m): its
// section's half-width, b/2 of a uniform section of width b (-beam_width) or a round profile's
// radius there; where the section gives no width (-beam_mass with -beam_youngs_over_density,
// -beam_EI with -beam_mu, -beam_properties) half the frame's length (no racket's face is wider
// than the racket is long). *source (may be null) says which, in words.
PetscReal FrameHalfWidth(const BeamParams &beam, PetscReal x, const char **source = nullptr);

// Whether (x, z) (m) lies inside a string bed's outline (false without a bed).
bool ImpactOnBed(const BeamParams &beam, PetscReal x, PetscReal z);

// Where (x, z) (m) lies: on the beam (or the bed) and free to move, off the beam (or off a
// racket's face), or on a held point.
enum class ImpactPointWhere {
  Movable,
  OffBeam,
  Held,
  OffFace
};
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

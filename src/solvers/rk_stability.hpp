// Imaginary-axis stability of explicit Runge-Kutta tableaus: the largest y* with
// |R(iy)| <= 1 + 1e-12 for 0 <= y <= y*, so the scheme is stable on an undamped
// oscillation of frequency omega for dt <= y* / omega.
#pragma once

#include <petscsys.h>

namespace beamimpact {

// y* of the tableau (A: s x s row-major, b: s); 0 when stability holds only for y < 0.05,
// i.e. the scheme is unstable for undamped oscillation at any practical step (Euler, RK2).
PetscReal RKImaginaryStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b);

} // namespace beamimpact

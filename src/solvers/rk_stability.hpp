// Imaginary-axis stability of explicit Runge-Kutta tableaus: the largest y* with
// |R(iy)| <= 1 + 1e-12 for 0 <= y <= y*, so the scheme is stable on an undamped
// oscillation of frequency omega for dt <= y* / omega.
#pragma once

#include <petscsys.h>

namespace beamimpact {

// y* of the tableau (A: s x s row-major, b: s); 0 when stability holds only for y < 0.05,
// i.e. the scheme is unstable for undamped oscillation at any practical step (Euler, RK2).
PetscReal RKImaginaryStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b);

// The largest step dt (s) such that the tableau is stable (|R(dt lambda)| <= 1 + 1e-12) on every
// Rayleigh-damped mode of frequency w in (0, omega_max]: lambda = -zeta w +- w sqrt(zeta^2 - 1),
// zeta = alpha/(2 w) + beta w/2 (alpha in 1/s, beta in s). Overdamped modes (strong stiffness damping)
// have real eigenvalues up to ~beta omega_max^2: the step is then limited by the method's reach along
// the negative real axis (2.785/|lambda| for RK4), far below 1/omega_max. 0 when unstable at any
// practical step (below 0.05/max|lambda|).
PetscReal RKDampedStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b, PetscReal omega_max,
                                 PetscReal alpha, PetscReal beta);

} // namespace beamimpact

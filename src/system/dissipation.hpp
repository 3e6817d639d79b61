// The one dissipation rule: the energy dissipated by the beam's damping,
//
//   D(t) = int_0^t P dt,   P = v^T C v (W, ForceOperatorDissipationRate),
//
// accumulated over the steps an integrator keeps by the corrected trapezoidal (Hermite) rule
//
//   D += h/2 (P0 + P1) + h^2/12 (P0' - P1'),   P' = 2 a^T C v  (a: the acceleration of the equations),
//
// exact for cubics, O(h^5) per step: more accurate than any integrator used here, so the energy
// balance measures the integrator. Every stepper keeps one (the TS stepper, the leapfrog): it
// evaluates P and P' at the state after each step (Step), undoes the step with the integrator
// (RollBack), re-evaluates P' when the contact phase changed the acceleration at the current
// state (Restart), and continues from an exact state handed to it (Set). docs/design.md,
// "Damping and the dissipated energy".
#pragma once

#include <petscsys.h>

namespace beamimpact {

struct DissipationIntegral {
  PetscReal dissipated = 0, rate = 0, rate_dot = 0;                // J, W, W/s: at the current state
  PetscReal dissipated_prev = 0, rate_prev = 0, rate_dot_prev = 0; // at the start of the last step

  // The rate at t = 0 (or a restart's new acceleration): D unchanged.
  void Restart(PetscReal P, PetscReal Pdot)
  {
    rate     = P;
    rate_dot = Pdot;
  }
  // A step of length h (s) was taken; P, Pdot at its end.
  void Step(PetscReal h, PetscReal P, PetscReal Pdot)
  {
    dissipated_prev = dissipated;
    rate_prev       = rate;
    rate_dot_prev   = rate_dot;
    rate            = P;
    rate_dot        = Pdot;
    dissipated += 0.5 * h * (rate_prev + rate) + h * h / 12 * (rate_dot_prev - rate_dot);
  }
  // The last step undone.
  void RollBack()
  {
    dissipated = dissipated_prev;
    rate       = rate_prev;
    rate_dot   = rate_dot_prev;
  }
  // An exact state handed over (its D known); the rate follows with Restart.
  void Set(PetscReal D) { dissipated = dissipated_prev = D; }
};

} // namespace beamimpact

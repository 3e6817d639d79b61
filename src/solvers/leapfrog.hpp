// Benchmark baseline: a plain hand-written explicit leapfrog (Stormer-Verlet, velocity
// form) of the same semi-discrete system as the TS stepper (system/beam_system.hpp), at a
// fixed step, on plain arrays: the scheme the original paper used.
//
//   M y'' = -K y + g F(c),   m_b y_b'' = -F(c),   c = y_b - g^T y,
//
// with M^{-1} K stored once as the system's band divided by the dof masses. One step of
// size tau from (y, v, a):  v += tau/2 a;  y += tau v;  a = a(y);  v += tau/2 a  (one force
// evaluation). It is a Stepper (solvers/stepper.hpp): the run driver locates the contact
// events on it exactly as on a TS (re-steps onto the root, so no force kink lies inside a
// step and the scheme stays second order), and LeapfrogRun (run/impact.hpp) runs it.
//
// Stability: Stormer-Verlet is stable for omega_max dt < 2; omega_max is the same
// Gershgorin bound as the TS stepper's (BeamSystemMaxFrequencyBound with the contact
// stiffness), so dt_max = 2 / omega_max ~ h^2 / (2 sqrt(EI/mu)). Serial.
#pragma once

#include "model/contact.hpp"
#include "solvers/stepper.hpp"
#include "system/beam_system.hpp"

#include <memory>

namespace beamimpact {

// -leapfrog_* options.
struct LeapfrogParams {
  PetscReal dt          = -1;  // s, fixed step; <= 0: dt_fraction x the stability limit
  PetscReal dt_fraction = 0.9; // of the stability limit 2/omega_max, when dt is not given
};

PetscErrorCode LeapfrogParamsFromOptions(MPI_Comm comm, LeapfrogParams *p);

// Stability limit 2 / omega_max (s) of Stormer-Verlet on this system and ball struck through g.
PetscReal LeapfrogStableStep(const BeamSystem &sys, const ContactCoupling &g, const BallParams &ball);

// Creates the stepper at t = 0 (beam at rest, ball touching, moving at its speed); fills
// *info (ts_type "leapfrog", formulation "explicit", dt_stable, dt_nominal). A step above the
// stability limit or above 1/8 of the contact time is refused.
PetscErrorCode LeapfrogStepperCreate(const BeamSystem &sys, const ContactCoupling &g, const BallParams &ball, const ContactScales &scales, ContactState *contact, const LeapfrogParams &lp,
                                     std::unique_ptr<Stepper> *stepper, IntegratorInfo *info);

} // namespace beamimpact

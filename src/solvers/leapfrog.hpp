// Benchmark baseline: a plain hand-written explicit leapfrog (Stormer-Verlet, velocity
// form) of the same semi-discrete system as the TS stepper (system/beam_system.hpp), at a
// fixed step, on plain arrays: the scheme the original paper used.
//
//   M y'' = -f(y, y', t) + g F(c),   m_b y_b'' = -F(c),   c = y_b - g^T y,
//
// with f of the force operator (system/force_operator.hpp) in its affine form
// f = K y + C v + f(0, 0, t): M^{-1} K stored once from the operator's band divided by the dof
// masses, the drive f(0, 0, t) evaluated when the swing's frame moves. One step of size tau
// from (y, v, a):  v += tau/2 a;  y += tau v;  a = a(y);  v += tau/2 a  (one force evaluation).
// It is a Stepper (solvers/stepper.hpp): the run driver locates the contact events on it
// exactly as on a TS (re-steps onto the root, so no force kink lies inside a step and the
// scheme stays second order), and LeapfrogRun (run/impact.hpp) runs it.
//
// Stability: Stormer-Verlet is stable for omega_max dt < 2; omega_max is the same
// Gershgorin bound as the TS stepper's (BeamSystemMaxFrequencyBound with the contact
// stiffness), so dt_max = 2 / omega_max ~ h^2 / (2 sqrt(EI/mu)). Serial.
//
// Damping C (only when the beam is damped; the undamped path is the scheme above, unchanged):
// the force at the end of a step is evaluated with the half-step velocity
// v_{n+1/2} = (y_{n+1} - y_n)/tau for C's band (Rayleigh's beta K: explicit, as the
// central-difference scheme of structural dynamics) and trapezoidally for C's diagonal part
// (alpha M, a grip's dampers: v_{n+1} = (v_{n+1/2} + tau/2 f_{n+1}) / (1 + tau c_d/(2 m_d))). On a
// mode y'' + 2 zeta w y' + w^2 y = 0 of Rayleigh damping the scheme is
//   (1 + a) y_{n+1} - (2 - b - tau^2 w^2) y_n + (1 - a - b) y_{n-1} = 0,  a = tau alpha/2, b = tau beta w^2,
// whose roots lie in the unit circle (Jury) iff tau^2 w^2 + 2 tau beta w^2 <= 4, i.e.
//   tau <= (2/w)(sqrt(1 + zeta_b^2) - zeta_b),  zeta_b = beta w/2,
// decreasing in w, so the mode w = omega_max sets dt_max; the alpha part does not limit the
// step. (Had alpha been lagged too, zeta_b would be the full zeta = alpha/(2w) + beta w/2.)
// The lagged beta term makes the damping force first-order accurate (relative error
// ~ tau beta w^2 / 2 = tau zeta_b w on a mode); the alpha part and the undamped scheme are
// second order. The dissipated energy follows the dissipation rule (system/dissipation.hpp).
#pragma once

#include "base/option_table.hpp"
#include "model/contact.hpp"
#include "solvers/stepper.hpp"
#include "solvers/stepper_problem.hpp"
#include "system/beam_system.hpp"

#include <memory>

namespace beamimpact {

// -leapfrog_* options.
struct LeapfrogParams {
  PetscReal dt          = -1;  // s, fixed step; <= 0: dt_fraction x the stability limit
  PetscReal dt_fraction = 0.9; // of the stability limit 2/omega_max, when dt is not given
};

// -leapfrog_dt, -leapfrog_dt_fraction: the leapfrog module's table (app/registry.cpp registers
// it) and its reader.
const OptionModule &LeapfrogOptionTable();
PetscErrorCode      LeapfrogParamsFromOptions(MPI_Comm comm, LeapfrogParams *p);

// Stability limit (s) of Stormer-Verlet on this system and ball struck through g: 2 / omega_max,
// or (2/omega_max)(sqrt(1 + zeta^2) - zeta), zeta = beta omega_max / 2, with damping.
PetscReal LeapfrogStableStep(const BeamSystem &sys, const ContactCoupling &g, const BallParams &ball);

// Creates the stepper at t = 0 (beam undeformed, moving with p.beam_velocity; ball touching,
// moving at its speed; p.frame: the swing's, owned by the caller), serial (p.comm and p.ts_type
// unused); fills *info (ts_type "leapfrog", formulation "explicit", dt_stable, dt_nominal). A
// step above the stability limit or above 1/8 of the contact time is refused.
PetscErrorCode LeapfrogStepperCreate(const StepperProblem &p, const LeapfrogParams &lp,
                                     std::unique_ptr<Stepper> *stepper, IntegratorInfo *info);

} // namespace beamimpact

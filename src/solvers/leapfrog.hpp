// Benchmark baseline: a plain hand-written explicit leapfrog (Stormer-Verlet,
// velocity form) of the same semi-discrete model as ImpactRun (MODEL.md section
// 2), at a fixed step, on plain arrays: the scheme the original paper used.
//
//   M y'' = -K y + g F(c),   m_b y_b'' = -F(c),   c = y_b - g^T y,
//
// with the lumped masses M, the stiffness K (BeamStiffnessRow: the same 5-point
// rows, stored once as a banded array divided by the node mass), the same
// hat-function impact stencil g (BeamImpactStencil) and the same contact law and
// phases (contact.hpp). One step of size tau from (y, v, a):
//   v += tau/2 a;  y += tau v;  a = a(y);  v += tau/2 a      (one force evaluation).
//
// Contact events (contact start, maximum compression, reload, separation) are
// located exactly as ImpactRun locates them: after a step whose indicators
// (c / c_scale, dc/dt / v_i) crossed, the step is redone from its saved start
// with a shorter step tau, chosen by Illinois (regula falsi) iterations, until
// the indicator on the post-event side is below -impact_event_tol; the phase is
// switched there (ContactSwitch, so the unloading law sees the located c_max)
// and stepping continues from the event with the nominal step. No force kink
// lies inside a step, so the scheme stays second order through the events, and
// the recorded contact time, peak force and ACOR are those of the located
// states. The run stops -impact_window after the last separation (ImpactTimesOf).
//
// Stability: Stormer-Verlet is stable for omega_max dt < 2; omega_max is the same
// Gershgorin bound ImpactRun uses (BeamMaxFrequencyBound with the contact
// stiffness), so dt_max = 2 / omega_max ~ h^2 / (2 sqrt(EI/mu)). Serial.
#pragma once

#include "model/beam.hpp"
#include "model/contact.hpp"
#include "run/impact.hpp"

#include <petscsys.h>

namespace beamimpact {

// -leapfrog_* options.
struct LeapfrogParams {
  PetscReal dt          = -1;  // s, fixed step; <= 0: dt_fraction x the stability limit
  PetscReal dt_fraction = 0.9; // of the stability limit 2/omega_max, when dt is not given
};

PetscErrorCode LeapfrogParamsFromOptions(MPI_Comm comm, LeapfrogParams *p);

// Stability limit 2 / omega_max (s) of Stormer-Verlet on this beam and ball struck at
// x_imp (m); omega_max is BeamMaxFrequencyBound with the contact stiffness, as ImpactRun.
PetscReal LeapfrogStableStep(const BeamParams &beam, const BallParams &ball, PetscReal x_imp);

// Runs one impact; fills the same ImpactResult fields as ImpactRun (outcome,
// invariants, events, and cost: steps, event_steps (re-steps to locate events),
// function_evals (force evaluations), wall_time (time stepping only)); ts_type is
// "leapfrog", formulation "explicit". A step above the stability limit is refused.
PetscErrorCode LeapfrogRun(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, const LeapfrogParams &lp, ImpactResult *res);
struct Scenario;
PetscErrorCode LeapfrogRun(const Scenario &scenario, const LeapfrogParams &lp, ImpactResult *res);

} // namespace beamimpact

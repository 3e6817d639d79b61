// Generalized-alpha time stepper for second-order systems F(t, X, V, A) = 0
// (Chung & Hulbert 1993), registered as the TS type "alpha2" in place of PETSc's.
//
// Why: PETSc 3.18's TSALPHA2 computes the starting acceleration, at the first
// step and after every TSRestartStep(), from two half backward-Euler steps and
// divides by h instead of 2h (fixed upstream in 3.22). With -ts_alpha_radius
// < 1 the O(1) error in A costs an order: measured on x'' + omega^2 x = 0,
// 3.18's alpha2 converges at order ~0.95 from a single start and not at all
// with a restart every 7 steps; event restarts at every contact change make
// the application first order (tests/test_galpha2.cpp has the numbers).
//
// Method, per step t_n -> t_{n+1} = t_n + h (PETSc's convention for alpha_m,
// alpha_f: weights of the new values):
//   X_{n+1} = X_n + h V_n + h^2 ((1/2 - beta) A_n + beta A_{n+1})
//   V_{n+1} = V_n + h ((1 - gamma) A_n + gamma A_{n+1})
//   F(t_n + alpha_f h, X_n + alpha_f (X_{n+1} - X_n), V_n + alpha_f (V_{n+1} - V_n),
//     A_n + alpha_m (A_{n+1} - A_n)) = 0
// With the spectral radius at infinite frequency rho in [0, 1]
// (TSAlpha2SetRadius, -ts_alpha_radius):
//   alpha_m = (2 - rho)/(1 + rho), alpha_f = 1/(1 + rho),
//   gamma = 1/2 + alpha_m - alpha_f, beta = (1 + alpha_m - alpha_f)^2 / 4.
// rho = 1 (the default) is the trapezoidal rule / Newmark average acceleration
// (alpha_m = alpha_f = gamma = 1/2, beta = 1/4). TSAlpha2SetParams sets the
// four parameters directly; TSAlpha2GetParams reads them. Options:
// -ts_alpha_radius, -ts_alpha_alpha_m, -ts_alpha_alpha_f, -ts_alpha_gamma,
// -ts_alpha_beta (as PETSc's), and -ts_alpha_restart <shifted,exact>.
//
// Starting and restarting: A_n of this method is a second-order approximation
// of the acceleration at t_n + (alpha_f - alpha_m) h, not at t_n. At the first
// step, after TSRestartStep(), after TS2SetSolution() with new vectors, after
// a change of the parameters, and when re-stepping a rolled-back restart step,
// A is rebuilt from X and V alone:
//   shifted (default): tau = (alpha_f - alpha_m) h, solve for A
//       F(t + tau, X + tau V + tau^2 A / 2, V + tau A, A) = 0
//     with the TS's SNES and the user's I2Jacobian (any nonsingular mass).
//     This is a(t + tau) to second order for resolved modes and lands on the
//     damped eigenvector for unresolved ones (omega h >> 1), so restarts keep
//     order 2 however often they happen and add no high-frequency overshoot.
//     When tau = 0 (alpha_m = alpha_f, e.g. rho = 1) it is the exact formula.
//   exact: A = -F(t, X, V, 0), the consistent acceleration a(t). It needs unit
//     mass, dF/dA = I (checked once per setup with a random A; a clear error
//     otherwise). Order 2 for a fixed number of restarts only: each restart
//     with rho < 1 leaves an O(h^2) velocity error, so restarting every few
//     steps gives order 1; and unresolved modes overshoot by ~0.06 omega h.
//
// Other behaviour:
// - Rollback (TSRollBack) restores X, V and A of the start of the last step; a
//   following TSStep with any dt equals having taken that step directly.
// - The SNES unknown is the correction D = X_alpha - X_alpha(predicted), so the
//   SNES Jacobian is the user's dF/dU + shiftV dF/dV + shiftA dF/dA with
//   shiftV = gamma/(beta h), shiftA = alpha_m/(alpha_f beta h^2), and tiny
//   steps do not lose A to cancellation. V and A are updated after the solve,
//   not inside the residual, so -snes_type ksponly is exact for linear F.
// - Adaptivity: TSADAPTNONE is the intended use. For "basic"/"dsp" the local
//   error estimate is X_{n+1} minus the explicit Taylor predictor
//   X_n + h V_n + h^2 A_n / 2 (= beta h^2 (A_{n+1} - A_n), O(h^3), reported as
//   order 3): a conservative, displacement-only estimate.
// - TSInterpolate: cubic Hermite in X from (X_n, V_n, X_{n+1}, V_{n+1}).
//   TSSolve with TS_EXACTFINALTIME_INTERPOLATE interpolates X only (V stays at
//   the end of the last step): use TS_EXACTFINALTIME_MATCHSTEP.
// - ts->snes_its and ts->ksp_its count every SNES solve (steps and restarts).
//   The restart solve uses other shifts than the steps (and every dt change
//   changes the step's): do not lag the Jacobian across SNES solves.
// - Call TSRestartStep() after changing X or V between steps, and when the step
//   size jumps: without a restart, each jump of h leaves an O(h^2) error in V.
#pragma once

#include <petscts.h>

namespace beamimpact {

// How A is rebuilt at the first step and after a restart (see above).
enum class GAlpha2Restart {
  Shifted = 0,
  Exact   = 1
};

// Registers this integrator as TS type "alpha2" (TSALPHA2), replacing PETSc's
// for the whole program (PetscFunctionListAdd overwrites the entry; verified in
// 3.18.5). Call once after PetscInitialize, before any TSSetType or
// TSSetFromOptions that should pick it up: a TS that already has PETSc's alpha2
// keeps it (TSSetType returns early on an equal name). Calling again is harmless.
PetscErrorCode TSGAlpha2Register();

// Restart formula (-ts_alpha_restart). Errors if ts is not this type. Setting it, even to
// the same kind, makes the next exact restart check dF/dA = I again, as a new TS does (a TS
// reused for another run: solvers/ts_stepper.cpp).
PetscErrorCode TSGAlpha2SetRestart(TS ts, GAlpha2Restart kind);
PetscErrorCode TSGAlpha2GetRestart(TS ts, GAlpha2Restart *kind);

// The acceleration A the method carries at the current time (a borrowed Vec;
// do not modify). NULL until the first TSStep. Errors if ts is not this type.
PetscErrorCode TSGAlpha2GetAcceleration(TS ts, Vec *A);

} // namespace beamimpact

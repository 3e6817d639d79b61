// Generalized-alpha TS for second-order systems F(t, X, V, A) = 0, registered
// as "alpha2" to replace PETSc 3.18's TSALPHA2, whose starting acceleration is
// off by a factor 2 at the first step and at every restart. The method, its
// parameters and the restart formulas are documented in ts_galpha2.hpp; the
// implementation follows Chung & Hulbert, J. Appl. Mech. 60:371 (1993).
//
// Layout of one step (h = ts->time_step, t0 = ts->ptime, X = ts->vec_sol,
// V = ts->vec_dot, A = this type's acceleration):
//   1. on restart, rebuild A from (t0, X, V) (RebuildAcceleration);
//   2. predict the alpha-level state with A_{n+1} = A_n and solve
//      F(t0 + alpha_f h, Xp + D, Vp + shiftV D, A_n + shiftA D) = 0 for D;
//   3. A_{n+1} = A_n + D / (alpha_f beta h^2), then V_{n+1}, X_{n+1};
//   4. TSAdaptCheckStage / TSAdaptChoose; on rejection restore and retry.
// Both nonlinear solves (step and shifted restart) use the TS's SNES with the
// same residual: F(stage_time, Xp + D, Vp + shift_V D, Ap + shift_A D).
#include "solvers/ts_galpha2.hpp"

#include <petsc/private/tsimpl.h>

namespace beamimpact {

namespace {

// tau^2 coefficient of the shifted restart: X(t + tau) ~ X + tau V + c tau^2 A.
// c = 1/2 (Taylor) also maps unresolved modes onto the method's damped
// eigenvector, so a restart adds no high-frequency transient.
constexpr PetscReal kRestartTaylorC = 0.5;
// Relative tolerance of the unit-mass check F(A) - F(0) == A.
constexpr PetscReal kUnitMassTol = 1e-10;

const char *const kRestartNames[] = {"shifted", "exact", "GAlpha2Restart", "GALPHA2_RESTART_", nullptr};

struct GAlpha2 {
  // Method parameters (dimensionless).
  PetscReal      alpha_m, alpha_f, gamma, beta;
  PetscReal      radius; // rho_inf if set by radius, -1 if set by TSAlpha2SetParams
  GAlpha2Restart restart;

  // Carried state: A belongs to (ts->vec_sol, ts->vec_dot) at ts->ptime.
  Vec           A;
  PetscBool     have_A;
  PetscObjectId x_id, v_id; // the vectors A belongs to
  // The last completed step, for rollback, interpolation and the error estimate.
  Vec       X0, V0, A0; // state at its start (A0 is the A the step used)
  PetscReal t0, h;      // its start time (s) and size (s)
  PetscBool have_step;
  PetscBool step_restarted;  // A0 was rebuilt for this step's h
  PetscBool restart_pending; // rollback of such a step: rebuild again next step
  PetscBool unit_mass_checked;

  // Nonlinear solve: the residual is F(stage_time, Xp + D, Vp + shift_V D, Ap + shift_A D).
  PetscReal stage_time;       // s
  PetscReal shift_V, shift_A; // 1/s, 1/s^2
  Vec       D;                // SNES unknown
  Vec       Xp, Vp, Ap;       // evaluation state at D = 0
  Vec       Xs, Vs, As;       // evaluation state at the current D
  Vec       W1, W2;           // scratch
};

GAlpha2 *Data(TS ts) { return static_cast<GAlpha2 *>(ts->data); }

// ---------------------------------------------------------------- parameters

PetscErrorCode SetParams_GAlpha2(TS ts, PetscReal alpha_m, PetscReal alpha_f, PetscReal gamma, PetscReal beta)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  PetscCheck(alpha_m > 0 && alpha_f > 0, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_OUTOFRANGE,
             "TS alpha2: alpha_m = %g and alpha_f = %g must be positive", (double)alpha_m, (double)alpha_f);
  PetscCheck(gamma > 0 && beta > 0, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_OUTOFRANGE,
             "TS alpha2: gamma = %g and beta = %g must be positive", (double)gamma, (double)beta);
  // The carried A depends on the parameters (it approximates a(t + (alpha_f - alpha_m) h)): rebuild it.
  if (alpha_m != ga->alpha_m || alpha_f != ga->alpha_f || gamma != ga->gamma || beta != ga->beta)
    ga->have_A = PETSC_FALSE;
  ga->alpha_m = alpha_m;
  ga->alpha_f = alpha_f;
  ga->gamma   = gamma;
  ga->beta    = beta;
  ga->radius  = -1;
  if (PetscAbsReal(gamma - (0.5 + alpha_m - alpha_f)) > 1e-12)
    PetscCall(PetscInfo(ts, "alpha2: gamma != 1/2 + alpha_m - alpha_f, the method is first order\n"));
  PetscFunctionReturn(0);
}

PetscErrorCode SetRadius_GAlpha2(TS ts, PetscReal radius)
{
  PetscFunctionBeginUser;
  PetscCheck(radius >= 0 && radius <= 1, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_OUTOFRANGE,
             "TS alpha2: -ts_alpha_radius %g is outside [0, 1]", (double)radius);
  const PetscReal am = (2 - radius) / (1 + radius), af = 1 / (1 + radius);
  PetscCall(SetParams_GAlpha2(ts, am, af, 0.5 + am - af, 0.25 * (1 + am - af) * (1 + am - af)));
  Data(ts)->radius = radius;
  PetscFunctionReturn(0);
}

PetscErrorCode GetParams_GAlpha2(TS ts, PetscReal *alpha_m, PetscReal *alpha_f, PetscReal *gamma, PetscReal *beta)
{
  const GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  if (alpha_m) *alpha_m = ga->alpha_m;
  if (alpha_f) *alpha_f = ga->alpha_f;
  if (gamma) *gamma = ga->gamma;
  if (beta) *beta = ga->beta;
  PetscFunctionReturn(0);
}

PetscErrorCode SetRestart_GAlpha2(TS ts, GAlpha2Restart kind)
{
  PetscFunctionBeginUser;
  PetscCheck(kind == GAlpha2Restart::Shifted || kind == GAlpha2Restart::Exact, PetscObjectComm((PetscObject)ts),
             PETSC_ERR_ARG_OUTOFRANGE, "TS alpha2: unknown restart kind %d (valid: shifted, exact)", (int)kind);
  Data(ts)->restart           = kind;
  Data(ts)->unit_mass_checked = PETSC_FALSE; // the exact restart checks dF/dA = I again, as on a new TS
  PetscFunctionReturn(0);
}

PetscErrorCode GetRestart_GAlpha2(TS ts, GAlpha2Restart *kind)
{
  PetscFunctionBeginUser;
  *kind = Data(ts)->restart;
  PetscFunctionReturn(0);
}

PetscErrorCode GetAcceleration_GAlpha2(TS ts, Vec *A)
{
  PetscFunctionBeginUser;
  *A = Data(ts)->have_A ? Data(ts)->A : nullptr;
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------- nonlinear solve

// Xs, Vs, As at the SNES unknown D.
PetscErrorCode EvaluationState(TS ts, Vec D)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(ga->Xs, 1.0, D, ga->Xp));
  PetscCall(VecWAXPY(ga->Vs, ga->shift_V, D, ga->Vp));
  PetscCall(VecWAXPY(ga->As, ga->shift_A, D, ga->Ap));
  PetscFunctionReturn(0);
}

PetscErrorCode SNESFunction_GAlpha2(SNES, Vec D, Vec F, TS ts)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  PetscCall(EvaluationState(ts, D));
  PetscCall(TSComputeI2Function(ts, ga->stage_time, ga->Xs, ga->Vs, ga->As, F));
  PetscFunctionReturn(0);
}

PetscErrorCode SNESJacobian_GAlpha2(SNES, Vec D, Mat J, Mat P, TS ts)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  PetscCall(EvaluationState(ts, D));
  PetscCall(TSComputeI2Jacobian(ts, ga->stage_time, ga->Xs, ga->Vs, ga->As, ga->shift_V, ga->shift_A, J, P));
  PetscFunctionReturn(0);
}

// One SNES solve from D = 0; adds its iterations to the TS counters.
PetscErrorCode SolveForD(TS ts, PetscBool *converged)
{
  GAlpha2            *ga = Data(ts);
  PetscInt            its, lits;
  SNESConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(VecSet(ga->D, 0.0));
  PetscCall(SNESSolve(ts->snes, nullptr, ga->D));
  PetscCall(SNESGetIterationNumber(ts->snes, &its));
  PetscCall(SNESGetLinearSolveIterations(ts->snes, &lits));
  ts->snes_its += its;
  ts->ksp_its += lits;
  PetscCall(SNESGetConvergedReason(ts->snes, &reason));
  *converged = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(EvaluationState(ts, ga->D)); // the state the converged residual was evaluated at
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------- restart

// dF/dA == I at (t, X0, V0), tested with a random A; W1 = F(t, X0, V0, 0) on return.
PetscErrorCode CheckUnitMass(TS ts, PetscReal t)
{
  GAlpha2    *ga = Data(ts);
  PetscRandom rnd;
  PetscReal   f0, scale, err, atest;

  PetscFunctionBeginUser;
  PetscCall(VecSet(ga->Ap, 0.0));
  PetscCall(TSComputeI2Function(ts, t, ga->X0, ga->V0, ga->Ap, ga->W1));
  PetscCall(VecNorm(ga->W1, NORM_INFINITY, &f0));
  scale = PetscMax(f0, 1.0);
  PetscCall(PetscRandomCreate(PetscObjectComm((PetscObject)ts), &rnd));
  PetscCall(PetscRandomSetInterval(rnd, 0.5 * scale, 1.5 * scale));
  PetscCall(VecSetRandom(ga->As, rnd));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(TSComputeI2Function(ts, t, ga->X0, ga->V0, ga->As, ga->W2));
  PetscCall(VecAXPBYPCZ(ga->W2, -1.0, -1.0, 1.0, ga->W1, ga->As)); // F(A) - F(0) - A
  PetscCall(VecNorm(ga->W2, NORM_INFINITY, &err));
  PetscCall(VecNorm(ga->As, NORM_INFINITY, &atest));
  PetscCheck(err <= kUnitMassTol * (atest + f0), PetscObjectComm((PetscObject)ts), PETSC_ERR_SUP,
             "TS alpha2 (beamimpact generalized-alpha): the exact restart A = -F(t, X, V, 0) needs a residual with "
             "unit mass, dF/dA = I "
             "(write F = A + M^{-1}(...)); at t = %g, |F(A) - F(0) - A|_inf = %g for a random |A|_inf = %g. Scale the "
             "residual by M^{-1}, "
             "or use -ts_alpha_restart shifted with alpha_m != alpha_f (-ts_alpha_radius < 1), which takes any "
             "nonsingular mass",
             (double)t, (double)err, (double)atest);
  ga->unit_mass_checked = PETSC_TRUE;
  PetscCall(TSComputeI2Function(ts, t, ga->X0, ga->V0, ga->Ap, ga->W1)); // Ap is still 0
  PetscFunctionReturn(0);
}

// A0 from (t0, X0, V0) for a step of size h. On a failed solve, *ok = false
// and TSAdaptCheckStage has reduced the step (or set ts->reason).
PetscErrorCode RebuildAcceleration(TS ts, PetscReal t0, PetscReal h, PetscBool *ok)
{
  GAlpha2        *ga  = Data(ts);
  const PetscReal tau = (ga->alpha_f - ga->alpha_m) * h;

  PetscFunctionBeginUser;
  *ok = PETSC_TRUE;
  if (ga->restart == GAlpha2Restart::Exact || PetscAbsReal(ga->alpha_f - ga->alpha_m) < 1e-12) { // tau ~ 0: a(t) itself
    if (!ga->unit_mass_checked) PetscCall(CheckUnitMass(ts, t0)); // leaves W1 = F(t0, X0, V0, 0)
    else {
      PetscCall(VecSet(ga->Ap, 0.0));
      PetscCall(TSComputeI2Function(ts, t0, ga->X0, ga->V0, ga->Ap, ga->W1));
    }
    PetscCall(VecCopy(ga->W1, ga->A0));
    PetscCall(VecScale(ga->A0, -1.0));
    PetscFunctionReturn(0);
  }
  // Shifted: unknown D = c tau^2 A, evaluation state (X0 + tau V0 + D, V0 + D/(c tau), D/(c tau^2)).
  ga->stage_time = t0 + tau;
  ga->shift_V    = 1 / (kRestartTaylorC * tau);
  ga->shift_A    = 1 / (kRestartTaylorC * tau * tau);
  PetscCall(VecWAXPY(ga->Xp, tau, ga->V0, ga->X0));
  PetscCall(VecCopy(ga->V0, ga->Vp));
  PetscCall(VecSet(ga->Ap, 0.0));
  PetscCall(SolveForD(ts, ok));
  if (!*ok) {
    PetscCall(PetscInfo(ts, "alpha2: restart solve for the acceleration failed at t = %g\n", (double)t0));
    PetscCall(TSAdaptCheckStage(ts->adapt, ts, ga->stage_time, ga->Xs, ok));
    PetscFunctionReturn(0);
  }
  PetscCall(VecCopy(ga->As, ga->A0));
  PetscFunctionReturn(0);
}

// The stage of a step of size h from t0: predictor A_{n+1} = A_n at the alpha level, then the
// solve for the unknown D = X_alpha - Xp; *ok false when the solve or the stage check fails.
static PetscErrorCode StageSolve(TS ts, PetscReal t0, PetscReal h, PetscBool *ok)
{
  GAlpha2        *ga = Data(ts);
  const PetscReal am = ga->alpha_m, af = ga->alpha_f, g = ga->gamma, b = ga->beta;

  PetscFunctionBeginUser;
  ga->stage_time = t0 + af * h;
  ga->shift_V    = g / (b * h);
  ga->shift_A    = am / (af * b * h * h);
  PetscCall(VecCopy(ga->X0, ga->Xp));
  PetscCall(VecAXPBYPCZ(ga->Xp, af * h, 0.5 * af * h * h, 1.0, ga->V0, ga->A0));
  PetscCall(VecWAXPY(ga->Vp, af * h, ga->A0, ga->V0));
  PetscCall(VecCopy(ga->A0, ga->Ap));
  PetscCall(TSPreStage(ts, ga->stage_time));
  PetscCall(SolveForD(ts, ok));
  PetscCall(TSPostStage(ts, ga->stage_time, 0, &ga->Xs));
  PetscCall(TSAdaptCheckStage(ts->adapt, ts, ga->stage_time, ga->Xs, ok));
  PetscFunctionReturn(0);
}

// A_{n+1} from D, then V_{n+1}, X_{n+1} (the TS solution) from the Newmark formulas.
static PetscErrorCode NewmarkUpdate(TS ts, PetscReal h)
{
  GAlpha2        *ga = Data(ts);
  Vec             X = ts->vec_sol, V = ts->vec_dot;
  const PetscReal af = ga->alpha_f, g = ga->gamma, b = ga->beta;

  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(ga->A, 1 / (af * b * h * h), ga->D, ga->A0));
  PetscCall(VecCopy(ga->V0, V));
  PetscCall(VecAXPBYPCZ(V, h * (1 - g), h * g, 1.0, ga->A0, ga->A));
  PetscCall(VecCopy(ga->X0, X));
  PetscCall(VecAXPY(X, h, ga->V0));
  PetscCall(VecAXPBYPCZ(X, h * h * (0.5 - b), h * h * b, 1.0, ga->A0, ga->A));
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------- TS methods

PetscErrorCode TSStep_GAlpha2(TS ts)
{
  GAlpha2        *ga = Data(ts);
  Vec             X = ts->vec_sol, V = ts->vec_dot;
  const PetscReal t0 = ts->ptime;
  PetscObjectId   xid, vid;
  PetscInt        rejections = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetId((PetscObject)X, &xid));
  PetscCall(PetscObjectGetId((PetscObject)V, &vid));
  const PetscBool restart = (ts->steprestart || !ga->have_A || ga->restart_pending || xid != ga->x_id ||
                             vid != ga->v_id)
                            ? PETSC_TRUE
                            : PETSC_FALSE;
  ga->restart_pending     = PETSC_FALSE;
  ga->have_step           = PETSC_FALSE;
  PetscCall(VecCopy(X, ga->X0));
  PetscCall(VecCopy(V, ga->V0));
  if (!restart) PetscCall(VecCopy(ga->A, ga->A0));

  while (!ts->reason) {
    const PetscReal h  = ts->time_step;
    PetscBool       ok = PETSC_TRUE, accept = PETSC_TRUE;
    PetscReal       next_h = h;

    PetscCheck(h > 0, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_OUTOFRANGE,
               "TS alpha2: time step %g must be positive", (double)h);
    if (restart) PetscCall(RebuildAcceleration(ts, t0, h, &ok));
    if (ok) PetscCall(StageSolve(ts, t0, h, &ok));
    if (ok) {
      PetscCall(NewmarkUpdate(ts, h));
      ga->t0        = t0;
      ga->h         = h;
      ga->have_step = PETSC_TRUE; // for the error estimate inside TSAdaptChoose
      PetscCall(TSAdaptChoose(ts->adapt, ts, h, nullptr, &next_h, &accept));
      if (accept) {
        ts->ptime += h;
        ts->time_step      = next_h;
        ga->have_A         = PETSC_TRUE;
        ga->step_restarted = restart;
        ga->x_id           = xid;
        ga->v_id           = vid;
        PetscFunctionReturn(0);
      }
      ga->have_step = PETSC_FALSE;
      PetscCall(VecCopy(ga->X0, X));
      PetscCall(VecCopy(ga->V0, V));
      ts->time_step = next_h;
    }
    if (ts->reason) break; // set by TSAdaptCheckStage (too many solver failures)
    ts->reject++;
    if (ts->max_reject >= 0 && ++rejections > ts->max_reject) {
      ts->reason = TS_DIVERGED_STEP_REJECTED;
      PetscCall(PetscInfo(ts, "alpha2: step %" PetscInt_FMT " at t = %g rejected %" PetscInt_FMT " times\n", ts->steps,
                          (double)t0, rejections));
    }
  }
  // Failed: leave the TS at the start of the step.
  PetscCall(VecCopy(ga->X0, X));
  PetscCall(VecCopy(ga->V0, V));
  if (!restart) PetscCall(VecCopy(ga->A0, ga->A));
  else ga->have_A = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode TSRollBack_GAlpha2(TS ts)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  PetscCheck(ga->have_step, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER,
             "TS alpha2: no completed step to roll back");
  PetscCall(VecCopy(ga->X0, ts->vec_sol));
  PetscCall(VecCopy(ga->V0, ts->vec_dot));
  PetscCall(VecCopy(ga->A0, ga->A));
  // A0 of a restart step was built for that step's h: rebuild it for the next h.
  ga->restart_pending = ga->step_restarted;
  ga->have_step       = PETSC_FALSE;
  PetscFunctionReturn(0);
}

// Cubic Hermite interpolation of X over the last step.
PetscErrorCode TSInterpolate_GAlpha2(TS ts, PetscReal t, Vec U)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  PetscCheck(ga->have_step, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER,
             "TS alpha2: no completed step to interpolate in");
  const PetscReal s = (t - ga->t0) / ga->h, h = ga->h;
  PetscScalar     c[4] = {2 * s * s * s - 3 * s * s + 1, h * (s * s * s - 2 * s * s + s), -2 * s * s * s + 3 * s * s,
                          h * (s * s * s - s * s)};
  Vec             v[4] = {ga->X0, ga->V0, ts->vec_sol, ts->vec_dot};
  Vec             out  = (U == ts->vec_sol || U == ts->vec_dot) ? ga->W1 : U;
  PetscCall(VecSet(out, 0.0));
  PetscCall(VecMAXPY(out, 4, c, v));
  if (out != U) PetscCall(VecCopy(out, U));
  PetscFunctionReturn(0);
}

PetscErrorCode TSEvaluateWLTE_GAlpha2(TS ts, NormType wnormtype, PetscInt *order, PetscReal *wlte)
{
  GAlpha2  *ga = Data(ts);
  PetscReal wltea, wlter;

  PetscFunctionBeginUser;
  if (order) *order = 3;
  if (!ga->have_step) {
    *wlte = -1;
    PetscFunctionReturn(0);
  }
  // Explicit Taylor predictor X0 + h V0 + h^2/2 A0; its distance to X_{n+1} is beta h^2 (A_{n+1} - A_n).
  PetscCall(VecCopy(ga->X0, ga->W1));
  PetscCall(VecAXPBYPCZ(ga->W1, ga->h, 0.5 * ga->h * ga->h, 1.0, ga->V0, ga->A0));
  PetscCall(TSErrorWeightedNorm(ts, ts->vec_sol, ga->W1, wnormtype, wlte, &wltea, &wlter));
  PetscFunctionReturn(0);
}

PetscErrorCode TSReset_GAlpha2(TS ts)
{
  GAlpha2 *ga = Data(ts);

  PetscFunctionBeginUser;
  Vec *vecs[] = {&ga->A,  &ga->X0, &ga->V0, &ga->A0, &ga->D,  &ga->Xp, &ga->Vp,
                 &ga->Ap, &ga->Xs, &ga->Vs, &ga->As, &ga->W1, &ga->W2};
  for (Vec *v : vecs) PetscCall(VecDestroy(v));
  ga->have_A = ga->have_step = ga->restart_pending = ga->step_restarted = ga->unit_mass_checked = PETSC_FALSE;
  ga->x_id = ga->v_id = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode TSDestroy_GAlpha2(TS ts)
{
  PetscFunctionBeginUser;
  PetscCall(TSReset_GAlpha2(ts));
  PetscCall(PetscFree(ts->data));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSAlpha2SetRadius_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSAlpha2SetParams_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSAlpha2GetParams_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSGAlpha2SetRestart_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSGAlpha2GetRestart_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSGAlpha2GetAcceleration_C", nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode TSSetUp_GAlpha2(TS ts)
{
  GAlpha2     *ga = Data(ts);
  DM           dm;
  TSI2Function f2;

  PetscFunctionBeginUser;
  PetscCall(TSGetDM(ts, &dm));
  PetscCall(DMTSGetI2Function(dm, &f2, nullptr));
  PetscCheck(f2, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_WRONGSTATE,
             "TS alpha2 integrates F(t, X, V, A) = 0: set it with TSSetI2Function (and TSSetI2Jacobian, "
             "TS2SetSolution)");
  if (!ts->vec_dot) {
    PetscCall(PetscInfo(ts, "alpha2: no velocity given with TS2SetSolution, starting from V = 0\n"));
    PetscCall(VecDuplicate(ts->vec_sol, &ts->vec_dot));
    PetscCall(VecSet(ts->vec_dot, 0.0));
  }
  Vec *vecs[] = {&ga->A,  &ga->X0, &ga->V0, &ga->A0, &ga->D,  &ga->Xp, &ga->Vp,
                 &ga->Ap, &ga->Xs, &ga->Vs, &ga->As, &ga->W1, &ga->W2};
  for (Vec *v : vecs) {
    PetscCall(VecDestroy(v));
    PetscCall(VecDuplicate(ts->vec_sol, v));
  }
  ga->have_A = ga->have_step = ga->restart_pending = ga->unit_mass_checked = PETSC_FALSE;
  PetscCall(TSAdaptCandidatesClear(ts->adapt));
  PetscCall(TSAdaptCandidateAdd(ts->adapt, "galpha2", 2, 1, 1.0, 1.0, PETSC_TRUE));
  PetscCall(TSGetSNES(ts, &ts->snes));
  PetscFunctionReturn(0);
}

PetscErrorCode TSSetFromOptions_GAlpha2(TS ts, PetscOptionItems *PetscOptionsObject)
{
  GAlpha2  *ga     = Data(ts);
  PetscReal radius = ga->radius >= 0 ? ga->radius : 1, am = ga->alpha_m, af = ga->alpha_f, g = ga->gamma, b = ga->beta;
  PetscBool flg, fm, ff, fg, fb;
  PetscEnum kind = static_cast<PetscEnum>(static_cast<int>(ga->restart));

  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Generalized-alpha for second-order systems (beamimpact alpha2)");
  PetscCall(PetscOptionsReal("-ts_alpha_radius",
                             "Spectral radius at infinite frequency, in [0, 1] (1: no high-frequency damping)",
                             "TSAlpha2SetRadius", radius, &radius, &flg));
  if (flg) {
    PetscCall(SetRadius_GAlpha2(ts, radius));
    am = ga->alpha_m, af = ga->alpha_f, g = ga->gamma, b = ga->beta;
  }
  PetscCall(PetscOptionsReal("-ts_alpha_alpha_m", "Weight of A_{n+1} in the acceleration of the residual",
                             "TSAlpha2SetParams", am, &am, &fm));
  PetscCall(PetscOptionsReal("-ts_alpha_alpha_f", "Weight of X_{n+1}, V_{n+1} (and time) in the residual",
                             "TSAlpha2SetParams", af, &af, &ff));
  PetscCall(PetscOptionsReal("-ts_alpha_gamma", "Newmark gamma (second order: 1/2 + alpha_m - alpha_f)",
                             "TSAlpha2SetParams", g, &g, &fg));
  PetscCall(PetscOptionsReal("-ts_alpha_beta", "Newmark beta (second order: (1 + alpha_m - alpha_f)^2/4)",
                             "TSAlpha2SetParams", b, &b, &fb));
  if (fm || ff || fg || fb) PetscCall(SetParams_GAlpha2(ts, am, af, g, b));
  PetscCall(PetscOptionsEnum("-ts_alpha_restart",
                             "Acceleration at the first step and after TSRestartStep: shifted (order 2 under any "
                             "restarts) or exact (a(t), unit mass)",
                             "TSGAlpha2SetRestart", kRestartNames, kind, &kind, &flg));
  if (flg) PetscCall(SetRestart_GAlpha2(ts, static_cast<GAlpha2Restart>(static_cast<int>(kind))));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode TSView_GAlpha2(TS ts, PetscViewer viewer)
{
  const GAlpha2 *ga = Data(ts);
  PetscBool      ascii;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii) {
    if (ga->radius >= 0)
      PetscCall(PetscViewerASCIIPrintf(viewer,
                                       "  Generalized-alpha (beamimpact, Chung & Hulbert 1993), spectral radius %g\n",
                                       (double)ga->radius));
    else
      PetscCall(PetscViewerASCIIPrintf(viewer, "  Generalized-alpha (beamimpact, Chung & Hulbert 1993), parameters set "
                                               "directly\n"));
    PetscCall(PetscViewerASCIIPrintf(viewer, "  alpha_m %g, alpha_f %g, gamma %g, beta %g; restart acceleration: %s\n",
                                     (double)ga->alpha_m, (double)ga->alpha_f, (double)ga->gamma, (double)ga->beta,
                                     kRestartNames[static_cast<int>(ga->restart)]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TSCreate_GAlpha2(TS ts)
{
  GAlpha2 *ga;

  PetscFunctionBeginUser;
  ts->ops->reset          = TSReset_GAlpha2;
  ts->ops->destroy        = TSDestroy_GAlpha2;
  ts->ops->view           = TSView_GAlpha2;
  ts->ops->setup          = TSSetUp_GAlpha2;
  ts->ops->setfromoptions = TSSetFromOptions_GAlpha2;
  ts->ops->step           = TSStep_GAlpha2;
  ts->ops->rollback       = TSRollBack_GAlpha2;
  ts->ops->interpolate    = TSInterpolate_GAlpha2;
  ts->ops->evaluatewlte   = TSEvaluateWLTE_GAlpha2;
  ts->ops->snesfunction   = SNESFunction_GAlpha2;
  ts->ops->snesjacobian   = SNESJacobian_GAlpha2;
  ts->usessnes            = PETSC_TRUE;
  ts->default_adapt_type  = TSADAPTNONE;

  PetscCall(PetscNew(&ga)); // zeroed: no vectors, no state, restart = Shifted
  ts->data    = ga;
  ga->restart = GAlpha2Restart::Shifted;
  PetscCall(SetRadius_GAlpha2(ts, 1.0));

  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSAlpha2SetRadius_C", SetRadius_GAlpha2));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSAlpha2SetParams_C", SetParams_GAlpha2));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSAlpha2GetParams_C", GetParams_GAlpha2));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSGAlpha2SetRestart_C", SetRestart_GAlpha2));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSGAlpha2GetRestart_C", GetRestart_GAlpha2));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSGAlpha2GetAcceleration_C", GetAcceleration_GAlpha2));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TSGAlpha2Register()
{
  PetscFunctionBeginUser;
  PetscCall(TSRegister(TSALPHA2, TSCreate_GAlpha2));
  PetscFunctionReturn(0);
}

PetscErrorCode TSGAlpha2SetRestart(TS ts, GAlpha2Restart kind)
{
  PetscFunctionBeginUser;
  PetscValidHeaderSpecific(ts, TS_CLASSID, 1);
  PetscUseMethod(ts, "TSGAlpha2SetRestart_C", (TS, GAlpha2Restart), (ts, kind));
  PetscFunctionReturn(0);
}

PetscErrorCode TSGAlpha2GetRestart(TS ts, GAlpha2Restart *kind)
{
  PetscFunctionBeginUser;
  PetscValidHeaderSpecific(ts, TS_CLASSID, 1);
  PetscValidPointer(kind, 2);
  PetscUseMethod(ts, "TSGAlpha2GetRestart_C", (TS, GAlpha2Restart *), (ts, kind));
  PetscFunctionReturn(0);
}

PetscErrorCode TSGAlpha2GetAcceleration(TS ts, Vec *A)
{
  PetscFunctionBeginUser;
  PetscValidHeaderSpecific(ts, TS_CLASSID, 1);
  PetscValidPointer(A, 2);
  PetscUseMethod(ts, "TSGAlpha2GetAcceleration_C", (TS, Vec *), (ts, A));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

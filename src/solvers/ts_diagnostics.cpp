// Diagnostics of the TS stepper: a Newton convergence test that knows the round-off floor
// of the residual, and the explanation of a failed step (ts_problem.hpp).
#include "solvers/ts_problem.hpp"

#include <petscdmcomposite.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamimpact {

static PetscErrorCode TSCurrentSolution(const TSProblem &P, TS ts, Vec *X)
{
  PetscFunctionBeginUser;
  if (P.form == Formulation::SecondOrder) {
    Vec V;
    PetscCall(TS2GetSolution(ts, X, &V));
  } else PetscCall(TSGetSolution(ts, X));
  PetscFunctionReturn(0);
}

// Newton on the acceleration-scaled residual cannot go below its round-off floor
// ~ eps * omega_max^2 * max|y| (the stencil cancels terms of size omega_max^2 y), which on
// fine grids, stiff beams or after long flights exceeds rtol * |F_0|. Accept a residual
// within 100x that floor (after at least one iteration) instead of stalling.
PetscErrorCode TSConvergedWithRoundoffFloor(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                            SNESConvergedReason *reason, void *ctx)
{
  NewtonFloor &nf = *static_cast<NewtonFloor *>(ctx);

  PetscFunctionBeginUser;
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, NULL));
  if (*reason != SNES_CONVERGED_ITERATING || it < 1) PetscFunctionReturn(0);
  const TSProblem &P = *nf.P;
  const TSLayout  &L = P.L;
  Vec              X, Xb, Xr;
  PetscCall(TSCurrentSolution(P, nf.ts, &X));
  PetscCall(DMCompositeGetAccess(L.pack, X, &Xb, &Xr));
  const PetscScalar *x;
  PetscReal          ymax = 0;
  PetscCall(VecGetArrayRead(Xb, &x));
  for (PetscInt i = 0; i < L.xe - L.xs; ++i)
    for (PetscInt f = 0; f < L.fields; ++f) ymax = std::max(ymax, std::abs(x[i * L.dof + f]));
  PetscCall(VecRestoreArrayRead(Xb, &x));
  PetscCall(DMCompositeRestoreAccess(L.pack, X, &Xb, &Xr));
  if (L.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ymax, 1, MPIU_REAL, MPIU_MAX, L.comm));
  const PetscReal floor = 100 * PETSC_MACHINE_EPSILON * nf.omega2 * ymax * std::sqrt((PetscReal)P.sys->ndof);
  if (fnorm <= floor) *reason = SNES_CONVERGED_FNORM_ABS;
  PetscFunctionReturn(0);
}

// A failed Newton solve, explained from its residual history (recorded since set-up): the
// first Newton step removed almost all of the residual (the problem is linear within a
// contact phase) and what is left is round-off when the next steps made no progress, or it
// is within 10x the round-off estimate eps omega_max^2 |u| of the stiffness term.
static PetscErrorCode ExplainFailedSolve(const TSProblem &P, TS ts, const char *ts_type, PetscReal omega_max,
                                         TSConvergedReason reason)
{
  SNES                snes;
  PetscReal          *hist = nullptr, rtol, t;
  PetscInt           *hits = nullptr, nh = 0, its = 0;
  SNESConvergedReason sr;
  Vec                 X;
  PetscReal           unorm;

  PetscFunctionBeginUser;
  PetscCall(TSGetTime(ts, &t));
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetConvergenceHistory(snes, &hist, &hits, &nh));
  PetscCall(SNESGetConvergedReason(snes, &sr));
  PetscCall(SNESGetIterationNumber(snes, &its));
  PetscCall(SNESGetTolerances(snes, NULL, &rtol, NULL, NULL, NULL));
  const PetscReal f0 = nh > 0 ? hist[0] : 0, flast = nh > 0 ? hist[nh - 1] : 0;
  PetscReal       fmax_after = 0, fmin_later = std::numeric_limits<PetscReal>::max();
  for (PetscInt k = 1; k < nh; ++k) fmax_after = std::max(fmax_after, hist[k]);
  for (PetscInt k = 2; k < nh; ++k) fmin_later = std::min(fmin_later, hist[k]);
  PetscCall(TSCurrentSolution(P, ts, &X));
  PetscCall(VecNorm(X, NORM_2, &unorm));
  const PetscReal floor_est = PETSC_MACHINE_EPSILON * omega_max * omega_max * unorm;
  const bool      stalled   = nh >= 2 && f0 > 0 && hist[1] <= 1e-2 * f0 &&
                       ((nh >= 3 && fmin_later >= 0.1 * hist[1]) || flast <= 10 * floor_est);
  if (stalled)
    SETERRQ(P.L.comm, PETSC_ERR_NOT_CONVERGED,
            "time stepping stopped at t = %g s with -ts_type %s: the Newton iteration stalled at a residual norm of "
            "%.2e after its first step reduced it from %.2e (SNES %s after %" PetscInt_FMT
            " iterations): that is the round-off level of this grid (eps omega_max^2 |u| = %.1e with omega_max <= %.3g "
            "rad/s), above -snes_rtol %g x the initial norm, so the solve cannot converge; "
            "set -snes_atol %.0e (ten times the stalled residual)",
            (double)t, ts_type, (double)flast, (double)f0, SNESConvergedReasons[sr], its, (double)floor_est,
            (double)omega_max, (double)rtol, (double)(10 * fmax_after));
  SETERRQ(P.L.comm, PETSC_ERR_NOT_CONVERGED,
          "time stepping stopped at t = %g s with -ts_type %s: the nonlinear (Newton) solve failed (SNES %s after "
          "%" PetscInt_FMT
          " iterations, residual norm %.2e from %.2e); reduce -ts_dt or check -snes_* and -ksp_* options (%s)",
          (double)t, ts_type, SNESConvergedReasons[sr], its, (double)flast, (double)f0, TSConvergedReasons[reason]);
}

PetscErrorCode TSCheckStep(const TSProblem &P, TS ts, const char *ts_type, PetscReal omega_max)
{
  TSConvergedReason reason;
  PetscReal         t;

  PetscFunctionBeginUser;
  PetscCall(TSGetConvergedReason(ts, &reason));
  if (reason == TS_DIVERGED_NONLINEAR_SOLVE) PetscCall(ExplainFailedSolve(P, ts, ts_type, omega_max, reason));
  if (reason < 0) {
    const char *why = reason == TS_DIVERGED_STEP_REJECTED ? "too many steps were rejected by the error controller; "
                                                            "loosen -ts_rtol/-ts_atol or raise -ts_max_reject"
                                                          : "the integrator diverged";
    PetscCall(TSGetTime(ts, &t));
    SETERRQ(P.L.comm, PETSC_ERR_NOT_CONVERGED, "time stepping stopped at t = %g s with -ts_type %s: %s (%s)", (double)t,
            ts_type, why, TSConvergedReasons[reason]);
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The flight's TS, its landing locator and its samples. See flight_ts.hpp.
#include "solvers/flight_ts.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace beamimpact {

namespace {

constexpr PetscReal kLandingTol   = 1e-12; // m: |z| of the located landing state
constexpr PetscInt  kLocateMaxIts = 10;    // re-steps of one landing

struct FlightContext {
  const FlightModel *m      = nullptr;
  PetscInt           fevals = 0;
};

PetscErrorCode FlightRHSFunction(TS, PetscReal t, Vec U, Vec F, void *ptr)
{
  auto              *c = static_cast<FlightContext *>(ptr);
  const PetscScalar *u;
  PetscScalar       *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  PetscCall(VecGetArray(F, &f));
  FlightRHS(*c->m, t, u, f);
  c->fevals++;
  PetscCall(VecRestoreArray(F, &f));
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscFunctionReturn(0);
}

// The 6 x 6 Jacobian of the right-hand side by central differences (implicit types only; TS
// scales and shifts the matrix in place, so every entry is set each time).
PetscErrorCode FlightRHSJacobian(TS, PetscReal t, Vec U, Mat A, Mat B, void *ptr)
{
  auto              *c = static_cast<FlightContext *>(ptr);
  const PetscScalar *u;
  PetscReal          up[6], um[6], fp[6], fm[6];
  PetscInt           rows[6] = {0, 1, 2, 3, 4, 5};

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(U, &u));
  for (PetscInt j = 0; j < 6; ++j) {
    std::copy(u, u + 6, up);
    std::copy(u, u + 6, um);
    const PetscReal h = 1e-6 * std::max<PetscReal>(1, std::abs(u[j]));
    up[j] += h, um[j] -= h;
    FlightRHS(*c->m, t, up, fp);
    FlightRHS(*c->m, t, um, fm);
    c->fevals += 2;
    PetscScalar col[6];
    for (PetscInt i = 0; i < 6; ++i) col[i] = (fp[i] - fm[i]) / (up[j] - um[j]);
    PetscCall(MatSetValues(B, 6, rows, 1, &j, col, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(U, &u));
  PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
  if (A != B) {
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

bool TypeCanRollBack(const char *type)
{
  for (const char *t : {TSRK, TSTHETA, TSCN, TSBEULER, TSBDF, TSARKIMEX, TSROSW, TSALPHA, TSIRK})
    if (!std::strcmp(t, type)) return true;
  return false;
}

// The TS with the program's defaults (those of FlightTSOptionTable), then the options
// (-flight_ts_*, -flight_snes_*, ...). On comm: PETSC_COMM_SELF, but -help's on the task's.
PetscErrorCode FlightTSCreate(MPI_Comm comm, FlightContext *ctx, TS *ts)
{
  Mat  J;
  SNES snes;
  KSP  ksp;
  PC   pc;

  PetscFunctionBeginUser;
  PetscCall(TSCreate(comm, ts));
  PetscCall(TSSetOptionsPrefix(*ts, "flight_"));
  PetscCall(TSSetProblemType(*ts, TS_NONLINEAR));
  PetscCall(TSSetType(*ts, TSRK));
  PetscCall(TSRKSetType(*ts, TSRK5DP));
  PetscCall(TSSetRHSFunction(*ts, NULL, FlightRHSFunction, ctx));
  PetscCall(MatCreateDense(comm, PETSC_DECIDE, PETSC_DECIDE, 6, 6, NULL, &J));
  PetscCall(TSSetRHSJacobian(*ts, J, J, FlightRHSJacobian, ctx));
  PetscCall(MatDestroy(&J));
  PetscCall(TSSetTolerances(*ts, 1e-10, NULL, 1e-10, NULL));
  PetscCall(TSSetTimeStep(*ts, 1e-3));
  PetscCall(TSSetMaxTime(*ts, 60));
  PetscCall(TSSetExactFinalTime(*ts, TS_EXACTFINALTIME_STEPOVER));
  PetscCall(TSGetSNES(*ts, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(TSSetFromOptions(*ts));
  PetscFunctionReturn(0);
}

// The state of the TS and its acceleration, as the end of step s.
PetscErrorCode ReadStepEnd(TS ts, const FlightModel &m, FlightStep *s)
{
  Vec                U;
  const PetscScalar *u;

  PetscFunctionBeginUser;
  PetscCall(TSGetTime(ts, &s->t1));
  PetscCall(TSGetSolution(ts, &U));
  PetscCall(VecGetArrayRead(U, &u));
  std::copy(u, u + 6, s->u1);
  PetscCall(VecRestoreArrayRead(U, &u));
  FlightAcceleration(m, s->t1, s->u1 + 3, s->a1);
  PetscFunctionReturn(0);
}

// The step s ended below the ground: roll it back and re-step onto the landing (first guess
// from the interpolant, then Newton on the step size with dz/dt = vz), until |z| <= 1e-12 m.
// A re-step the adaptivity shortened is taken as it is: Newton continues from its state.
// On return s ends at the landing.
PetscErrorCode LocateLanding(TS ts, const FlightModel &m, FlightStep *s, FlightResult *r)
{
  PetscReal target = FlightStepGroundTime(*s);
  PetscInt  it     = 0;

  PetscFunctionBeginUser;
  for (; it < kLocateMaxIts; ++it) {
    PetscCall(TSRollBack(ts));
    PetscCall(TSSetTimeStep(ts, target - s->t0));
    PetscCall(TSStep(ts));
    r->locate_steps++;
    PetscCall(ReadStepEnd(ts, m, s));
    const PetscReal z = s->u1[2], vz = s->u1[5];
    if (std::abs(z) <= kLandingTol) break;
    PetscCheck(vz < 0, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "the flight's landing could not be located: the ball is not descending at t = %g s (height %g m)", (double)s->t1, (double)z);
    const PetscReal next = s->t1 - z / vz;
    if (std::abs(next - s->t1) <= 4 * PETSC_MACHINE_EPSILON * s->t1) break; // at the resolution of t
    target = next > s->t0 ? next : 0.5 * (s->t0 + s->t1);
  }
  r->landing_residual = std::abs(s->u1[2]);
  PetscCheck(r->landing_residual <= 1e-6, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED,
             "the flight's landing could not be located: the height is still %g m after %" PetscInt_FMT " re-steps at t = %g s (a tighter -flight_snes_rtol for an implicit -flight_ts_type?)",
             (double)s->u1[2], it, (double)s->t1);
  PetscFunctionReturn(0);
}

void SeriesAdd(FlightSeries *q, const FlightModel &m, PetscReal t, const PetscReal u[6])
{
  q->t.push_back(t);
  q->x.push_back(u[0]), q->y.push_back(u[1]), q->z.push_back(u[2]);
  q->vx.push_back(u[3]), q->vy.push_back(u[4]), q->vz.push_back(u[5]);
  q->spin.push_back(FlightSpinAt(m, t, std::sqrt(u[3] * u[3] + u[4] * u[4] + u[5] * u[5])));
}

// Samples at k dt in (t0, t1) (in (t0, t1] too when not the last step), from the interpolant.
void SeriesSample(FlightSeries *q, const FlightModel &m, const FlightStep &s, PetscReal dt, bool last)
{
  if (dt <= 0) return;
  for (PetscInt k = (PetscInt)std::floor(s.t0 / dt) + 1;; ++k) {
    const PetscReal t = k * dt;
    if (t > s.t1 || (last && t >= s.t1)) break;
    if (t <= s.t0) continue;
    PetscReal u[6];
    FlightStepInterpolate(s, t, u);
    SeriesAdd(q, m, t, u);
  }
}

PetscErrorCode IntegratorDescription(TS ts, FlightResult *r)
{
  TSType    type;
  PetscBool rk;

  PetscFunctionBeginUser;
  PetscCall(TSGetType(ts, &type));
  r->ts_type = type;
  PetscCall(PetscStrcmp(type, TSRK, &rk));
  if (rk) {
    TSRKType rk_type;
    PetscCall(TSRKGetType(ts, &rk_type));
    r->ts_type += std::string(" ") + rk_type;
  }
  PetscCall(TSGetTolerances(ts, &r->atol, NULL, &r->rtol, NULL));
  PetscCheck(TypeCanRollBack(type), PETSC_COMM_SELF, PETSC_ERR_SUP,
             "-flight_ts_type %s cannot roll back a step, so the landing cannot be located; use one that can: rk (the default, 5dp), cn, theta, beuler, bdf, arkimex, rosw, irk, alpha", type);
  PetscFunctionReturn(0);
}

// Steps ts (at u0 at t = 0) until the ball lands: samples, apex, the located landing.
PetscErrorCode FlightIntegrate(TS ts, const FlightModel &m, const PetscReal u0[6], const FlightSolveParams &p, FlightResult *r)
{
  PetscReal  max_time;
  FlightStep s;

  PetscFunctionBeginUser;
  PetscCall(IntegratorDescription(ts, r));
  PetscCall(TSGetMaxTime(ts, &max_time));
  PetscCall(TSSetUp(ts));
  std::copy(u0, u0 + 6, s.u0);
  FlightAcceleration(m, 0, u0 + 3, s.a0);
  r->apex = u0[2], r->apex_time = 0;
  SeriesAdd(&r->series, m, 0, u0);
  for (;;) {
    PetscCall(TSStep(ts));
    PetscCall(ReadStepEnd(ts, m, &s));
    if (s.u0[5] > 0 && s.u1[5] <= 0) FlightStepApex(s, &r->apex_time, &r->apex);
    if (s.u1[2] < 0 || (s.u1[2] == 0 && s.u1[5] < 0)) {
      if (s.u1[2] < 0) PetscCall(LocateLanding(ts, m, &s, r));
      SeriesSample(&r->series, m, s, p.series_dt, true);
      SeriesAdd(&r->series, m, s.t1, s.u1);
      break;
    }
    SeriesSample(&r->series, m, s, p.series_dt, false);
    PetscCheck(s.t1 < max_time, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "the ball has not landed after -flight_ts_max_time %g s (height %g m): raise it", (double)max_time, (double)s.u1[2]);
    s.t0 = s.t1;
    std::copy(s.u1, s.u1 + 6, s.u0);
    std::copy(s.a1, s.a1 + 3, s.a0);
  }
  r->landing = FlightLandingOf(u0, s.t1, s.u1);
  PetscCall(TSGetStepNumber(ts, &r->steps));
  PetscCall(TSGetStepRejections(ts, &r->rejected_steps));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FlightSolve(const FlightModel &m, const PetscReal u0[6], const FlightSolveParams &p, FlightResult *r)
{
  FlightContext  ctx;
  TS             ts;
  Vec            U;
  PetscScalar   *u;
  PetscLogDouble t_start, t_end;

  PetscFunctionBeginUser;
  PetscCheck(u0[2] > 0 || (u0[2] == 0 && u0[5] > 0), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "the ball starts %s (height %g m, vertical speed %g m/s): it cannot fly", u0[2] < 0 ? "below the ground" : "on the ground without going up",
             (double)u0[2], (double)u0[5]);
  PetscCall(PetscTime(&t_start));
  *r    = FlightResult();
  ctx.m = &m;
  PetscCall(FlightTSCreate(PETSC_COMM_SELF, &ctx, &ts));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 6, &U));
  PetscCall(VecGetArray(U, &u));
  std::copy(u0, u0 + 6, u);
  PetscCall(VecRestoreArray(U, &u));
  PetscCall(TSSetSolution(ts, U));
  PetscCall(TSSetTime(ts, 0));
  const PetscErrorCode ierr = FlightIntegrate(ts, m, u0, p, r);
  PetscCall(VecDestroy(&U)); // also after an error: the caller (a test, a sweep) goes on
  PetscCall(TSDestroy(&ts));
  PetscCall(ierr);
  r->function_evals = ctx.fevals;
  PetscCall(PetscTime(&t_end));
  r->wall_time = t_end - t_start;
  PetscFunctionReturn(0);
}

const OptionModule &FlightTSOptionTable()
{
  static const OptionModule m = {
    "flight_ts",
    "PETSc options of the flight's integrator, -task flight (PETSc's TS options with the prefix -flight_; the landing is located by the program)",
    {
      OptionChoice("-flight_ts_type", "Integrator of the flight: any type that can roll back a step", {"rk", "cn", "theta", "beuler", "bdf", "arkimex", "rosw", "irk", "alpha"}, "rk"),
      OptionText("-flight_ts_rk_type", "Runge-Kutta tableau of -flight_ts_type rk: 5dp (Dormand-Prince 5(4)), 3bs, 4, 5bs, 8vr, ...", "5dp"),
      OptionReal("-flight_ts_rtol", "1", "Relative tolerance of the local error (adaptive steps)", "1e-10", NonNegative()),
      OptionReal("-flight_ts_atol", "m, m/s", "Absolute tolerance of the local error, on the positions (m) and velocities (m/s)", "1e-10", NonNegative()),
      OptionReal("-flight_ts_dt", "s", "First step of an adaptive run; the step with -flight_ts_adapt_type none", "0.001", Positive()),
      OptionReal("-flight_ts_max_time", "s", "Longest flight: a ball not landed by then is an error", "60", Positive()),
      OptionChoice("-flight_ts_adapt_type", "Step size controller of the flight", {"none", "basic", "dsp"}, "basic"),
      OptionFlag("-flight_ts_monitor", "Print each step of the flight (time, step size)"),
    },
    true,
    {"-flight_ts_", "-flight_snes_", "-flight_ksp_", "-flight_pc_"},
  };
  return m;
}

PetscErrorCode FlightTSOptionsHelp(MPI_Comm comm)
{
  FlightContext ctx;
  FlightModel   m;
  TS            ts;

  PetscFunctionBeginUser;
  ctx.m = &m;
  PetscCall(FlightTSCreate(comm, &ctx, &ts));
  PetscCall(TSDestroy(&ts));
  PetscCall(OptionModulePrintHelp(comm, FlightTSOptionTable()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

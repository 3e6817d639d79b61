// The flight's TS, its landing locator and its samples. See flight_ts.hpp.
#include "solvers/flight_ts.hpp"

#include "base/memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// The defaults the flight's type needs, set before the options are read (which override them):
// the type itself (-flight_ts_type); theta, beuler, cn and alpha, which PETSc leaves without an
// adaptor though they estimate their error, the basic one (unless -flight_ts_adapt_type is
// given); irk, whose stage system is a MATKAIJ that PETSc 3.18 neither builds over a dense
// matrix (MatKAIJSetAIJ) nor factors, an AIJ Jacobian and its 6 s unknowns solved by GMRES to
// round-off (no preconditioner: the Krylov space of 6 s dimensions holds the exact solution).
// Every other type: the dense 6 x 6 Jacobian, factored by LU.
PetscErrorCode FlightTSTypeDefaults(MPI_Comm comm, TS ts, FlightContext *ctx)
{
  char      type[64] = TSRK;
  PetscBool given;
  TSAdapt   adapt;
  Mat       J;
  SNES      snes;
  KSP       ksp;
  PC        pc;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, "flight_", "-ts_type", type, sizeof type, NULL)); // one of the row's (checked)
  PetscCall(TSSetType(ts, type));
  PetscCall(PetscOptionsHasName(NULL, "flight_", "-ts_adapt_type", &given));
  for (const char *fixed : {TSTHETA, TSBEULER, TSCN, TSALPHA})
    if (!given && !std::strcmp(type, fixed)) {
      PetscCall(TSGetAdapt(ts, &adapt));
      PetscCall(TSAdaptSetType(adapt, TSADAPTBASIC));
    }
  const bool irk = !std::strcmp(type, TSIRK);
  if (irk)
    PetscCall(MatCreateAIJ(comm, PETSC_DECIDE, PETSC_DECIDE, 6, 6, 6, NULL, 6, NULL, &J)); // -help's on the task's comm
  else PetscCall(MatCreateDense(comm, PETSC_DECIDE, PETSC_DECIDE, 6, 6, NULL, &J));
  PetscCall(TSSetRHSJacobian(ts, J, J, FlightRHSJacobian, ctx));
  PetscCall(MatDestroy(&J));
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  if (irk) {
    PetscCall(KSPSetType(ksp, KSPGMRES));
    PetscCall(KSPGMRESSetRestart(ksp, 100));
    PetscCall(KSPSetTolerances(ksp, 1e-14, 1e-300, PETSC_DEFAULT, 100));
    PetscCall(PCSetType(pc, PCNONE));
  } else {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(PCSetType(pc, PCLU));
  }
  PetscFunctionReturn(0);
}

// The TS with the program's defaults (those of FlightTSOptionTable), then the options
// (-flight_ts_*, -flight_snes_*, ...), the table's rows checked first (a type, an adaptor, a
// step, a tolerance: named with the allowed values, where PETSc would not name the option).
// On comm: PETSC_COMM_SELF, but -help's on the task's.
PetscErrorCode FlightTSCreate(MPI_Comm comm, FlightContext *ctx, TS *ts)
{
  PetscFunctionBeginUser;
  PetscCall(OptionsCheckGiven(FlightTSOptionTable()));
  PetscCall(TSCreate(comm, ts));
  PetscCall(TSSetOptionsPrefix(*ts, "flight_"));
  PetscCall(TSSetProblemType(*ts, TS_NONLINEAR));
  PetscCall(TSSetType(*ts, TSRK));
  PetscCall(TSRKSetType(*ts, TSRK5DP));
  PetscCall(TSSetRHSFunction(*ts, NULL, FlightRHSFunction, ctx));
  PetscCall(TSSetTolerances(*ts, 1e-10, NULL, 1e-10, NULL));
  PetscCall(TSSetTimeStep(*ts, 1e-3));
  PetscCall(TSSetMaxTime(*ts, 60));
  PetscCall(TSSetExactFinalTime(*ts, TS_EXACTFINALTIME_STEPOVER));
  PetscCall(FlightTSTypeDefaults(comm, *ts, ctx));
  PetscCall(TSSetFromOptions(*ts));
  PetscFunctionReturn(0);
}

// Whether the type estimates its local error, so that an adaptor can hold rtol and atol: an rk
// tableau only with an embedded pair (1fe, 3 and 4 have none), irk never (its Gauss-Legendre
// methods have none); every other type allowed does.
PetscErrorCode FlightTSEstimatesError(TS ts, bool *estimates, std::string *type_text)
{
  TSType    type;
  PetscBool rk, irk;

  PetscFunctionBeginUser;
  PetscCall(TSGetType(ts, &type));
  *type_text = type;
  PetscCall(PetscStrcmp(type, TSIRK, &irk));
  *estimates = !irk;
  PetscCall(PetscStrcmp(type, TSRK, &rk));
  if (rk) {
    TSRKType         rk_type;
    const PetscReal *bembed = nullptr;
    PetscCall(TSRKGetType(ts, &rk_type));
    PetscCall(TSRKGetTableau(ts, NULL, NULL, NULL, NULL, &bembed, NULL, NULL, NULL));
    *type_text += std::string(" ") + rk_type;
    *estimates = bembed != nullptr;
  }
  PetscFunctionReturn(0);
}

// The flight's step control, decided before the set-up: adaptive, holding rtol and atol, wherever
// the type estimates its error (FlightTSTypeDefaults), else fixed at -flight_ts_dt, and the
// summary and the record say which. A tableau without an estimate takes no adaptor (refused,
// naming it); under a fixed step a given -flight_ts_rtol or -flight_ts_atol has no effect: a note.
PetscErrorCode FlightTSStepControl(TS ts, FlightResult *r)
{
  TSAdapt     adapt;
  PetscBool   given, none;
  bool        estimates = true;
  std::string why;

  PetscFunctionBeginUser;
  PetscCall(FlightTSEstimatesError(ts, &estimates, &r->ts_type));
  PetscCall(TSGetAdapt(ts, &adapt));
  PetscCall(PetscObjectTypeCompare((PetscObject)adapt, TSADAPTNONE, &none));
  PetscCall(PetscOptionsHasName(NULL, "flight_", "-ts_adapt_type", &given));
  if (!estimates) {
    PetscCheck(none || !given, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
               "-flight_ts_adapt_type %s is not allowed with -flight_ts_type %s: that method has no embedded error "
               "estimate to adapt the step by; use -flight_ts_adapt_type none (the fixed step "
               "-flight_ts_dt), or a method with one (rk with -flight_ts_rk_type 5dp, 3bs, 5bs, 8vr, 2a, ...; cn, "
               "theta, beuler, bdf, arkimex, rosw, alpha)",
               OptionWritten("-flight_ts_adapt_type").c_str(), r->ts_type.c_str());
    PetscCall(TSAdaptSetType(adapt, TSADAPTNONE));
    why = "-flight_ts_type " + r->ts_type + " has no error estimate";
  } else if (none) why = "-flight_ts_adapt_type none";
  r->fixed_step = !why.empty();
  PetscCall(TSGetTimeStep(ts, &r->dt));
  PetscCall(TSGetTolerances(ts, &r->atol, NULL, &r->rtol, NULL));
  char step[64];
  std::snprintf(step, sizeof step, "%g", (double)r->dt);
  const std::string fixed = r->fixed_step
                            ? "the flight's step is fixed, -flight_ts_dt " + std::string(step) + " s: " + why
                            : "";
  for (const char *tol : {"-flight_ts_rtol", "-flight_ts_atol"})
    OptionWithoutEffectSet(tol, fixed, {"-flight_ts_type", "-flight_ts_rk_type", "-flight_ts_adapt_type"});
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

// The state after a step is a number: a step too long for the drag (a fixed -flight_ts_dt of
// seconds) makes it grow without bound, and the run stops saying so, naming the step.
PetscErrorCode FlightStepCheck(const FlightStep &s, const FlightResult &r)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < 6; ++i)
    PetscCheck(std::isfinite(s.u1[i]), PETSC_COMM_SELF, PETSC_ERR_FP,
               "the flight's integration failed: the ball's state is not finite at t = %g s after a step of %g s%s",
               (double)s.t1, (double)(s.t1 - s.t0),
               r.fixed_step ? " (the fixed -flight_ts_dt is far too long for the drag: give a shorter one, or adaptive "
                              "steps: -flight_ts_adapt_type basic)"
                            : "");
  PetscFunctionReturn(0);
}

// The step s ended below the ground: roll it back and re-step onto the landing (first guess
// from the interpolant, then Newton on the step size with dz/dt = vz), until |z| <= 1e-12 m.
// A re-step the adaptivity shortened that still ends above the ground is an ordinary step
// (*landed false: the caller takes it and steps on; rolling it back would only shorten it again);
// one that ends below is rolled back as the first. On return with *landed, s ends at the landing.
PetscErrorCode LocateLanding(TS ts, const FlightModel &m, FlightStep *s, FlightResult *r, bool *landed)
{
  PetscReal target = FlightStepGroundTime(*s);
  PetscInt  it     = 0;

  PetscFunctionBeginUser;
  *landed = true;
  for (; it < kLocateMaxIts; ++it) {
    PetscCall(TSRollBack(ts));
    PetscCall(TSSetTimeStep(ts, target - s->t0));
    PetscCall(TSStep(ts));
    r->locate_steps++;
    PetscCall(ReadStepEnd(ts, m, s));
    PetscCall(FlightStepCheck(*s, *r));
    const PetscReal z = s->u1[2], vz = s->u1[5];
    if (std::abs(z) <= kLandingTol) break;
    const bool shortened = s->t1 < target - 4 * PETSC_MACHINE_EPSILON * target;
    if (shortened && z > 0) {
      *landed = false;
      PetscFunctionReturn(0);
    }
    if (shortened) { // below the ground again: from the interpolant of this shorter step
      target = FlightStepGroundTime(*s);
      continue;
    }
    PetscCheck(vz < 0, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED,
               "the flight's landing could not be located: the ball is not descending at t = %g s (height %g m)",
               (double)s->t1, (double)z);
    const PetscReal next = s->t1 - z / vz;
    if (std::abs(next - s->t1) <= 4 * PETSC_MACHINE_EPSILON * s->t1) break; // at the resolution of t
    target = next > s->t0 ? next : 0.5 * (s->t0 + s->t1);
  }
  r->landing_residual = std::abs(s->u1[2]);
  PetscCheck(r->landing_residual <= 1e-6, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED,
             "the flight's landing could not be located: the height is still %g m after %" PetscInt_FMT
             " re-steps at t = %g s%s",
             (double)s->u1[2], it, (double)s->t1,
             r->ts_type.rfind("rk", 0) == 0 ? "" : " (a tighter -flight_snes_rtol for the implicit -flight_ts_type?)");
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

// The most the series can hold: a sample every series_dt up to -flight_ts_max_time, and the launch
// and the landing, 8 numbers each (bytes; none without a series).
double FlightSeriesBytes(const FlightSolveParams &p, PetscReal max_time)
{
  if (!p.series) return 0;
  const double samples = 2 + (p.series_dt > 0 ? std::floor(max_time / p.series_dt) : 0);
  return samples * 8 * sizeof(PetscReal);
}

// Steps ts (at u0 at t = 0) until the ball lands: samples, apex, the located landing.
PetscErrorCode FlightIntegrate(TS ts, const FlightModel &m, const PetscReal u0[6], const FlightSolveParams &p,
                               FlightResult *r)
{
  PetscReal  max_time;
  FlightStep s;
  bool       landed = false;

  PetscFunctionBeginUser;
  PetscCall(TSGetMaxTime(ts, &max_time));
  PetscCall(TSSetUp(ts));
  std::copy(u0, u0 + 6, s.u0);
  FlightAcceleration(m, 0, u0 + 3, s.a0);
  r->apex = u0[2], r->apex_time = 0;
  if (p.series) SeriesAdd(&r->series, m, 0, u0);
  while (!landed) {
    PetscCall(TSStep(ts));
    PetscCall(ReadStepEnd(ts, m, &s));
    PetscCall(FlightStepCheck(s, *r));
    if (s.u1[2] < 0) PetscCall(LocateLanding(ts, m, &s, r, &landed));
    else landed = s.u1[2] == 0 && s.u1[5] < 0;
    if (s.u0[5] > 0 && s.u1[5] <= 0) FlightStepApex(s, &r->apex_time, &r->apex); // on the step as taken
    if (p.series) SeriesSample(&r->series, m, s, p.series_dt, landed);
    if (landed) break;
    PetscCheck(s.t1 < max_time, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
               "the ball has not landed after -flight_ts_max_time %g s (height %g m): raise it", (double)max_time,
               (double)s.u1[2]);
    s.t0 = s.t1;
    std::copy(s.u1, s.u1 + 6, s.u0);
    std::copy(s.a1, s.a1 + 3, s.a0);
  }
  if (p.series) SeriesAdd(&r->series, m, s.t1, s.u1);
  r->landing = FlightLandingOf(u0, s.t1, s.u1);
  PetscCheck(r->apex_time <= r->landing.hang_time && r->landing.hang_time > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "the flight's apex at %g s is not within its flight of %g s", (double)r->apex_time,
             (double)r->landing.hang_time);
  PetscCall(TSGetStepNumber(ts, &r->steps));
  PetscCall(TSGetStepRejections(ts, &r->rejected_steps));
  PetscFunctionReturn(0);
}

// The checks of the TS before a flight: its step control (FlightTSStepControl), the series
// within the memory limit.
PetscErrorCode FlightTSCheck(TS ts, const FlightSolveParams &p, FlightResult *r)
{
  PetscReal max_time;

  PetscFunctionBeginUser;
  PetscCall(FlightTSStepControl(ts, r));
  PetscCall(TSGetMaxTime(ts, &max_time));
  char what[200];
  std::snprintf(what, sizeof what, "-flight_series_dt %g s (a sample every %g s for up to -flight_ts_max_time %g s)",
                (double)p.series_dt, (double)p.series_dt, (double)max_time);
  PetscCall(MemoryCheck(PETSC_COMM_SELF, FlightSeriesBytes(p, max_time), what,
                        "give a larger -flight_series_dt (0: only the launch and the landing) or a shorter "
                        "-flight_ts_max_time"));
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
             "the ball starts %s (height %g m, vertical speed %g m/s): it cannot fly",
             u0[2] < 0 ? "below the ground" : "on the ground without going up", (double)u0[2], (double)u0[5]);
  PetscCheck(m.spin < FlightSpinMax(m.radius), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "the ball's spin of %g rad/s moves its surface at %g m/s, beyond the speed of sound in air (%g m/s), "
             "where no drag or lift model holds: it must be below %g rad/s for a radius of %g m",
             (double)m.spin, (double)(m.spin * m.radius), (double)kSpeedOfSound, (double)FlightSpinMax(m.radius),
             (double)m.radius);
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
  PetscErrorCode ierr = FlightTSCheck(ts, p, r);
  if (!ierr) ierr = FlightIntegrate(ts, m, u0, p, r);
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
    "PETSc options of the flight's integrator, -task flight (PETSc's TS options with the prefix -flight_; the landing "
    "is located by the program)",
    {
      [] {
        OptionSpec s = OptionChoice("-flight_ts_type",
                                    "Integrator of the flight: any type that can roll back a step (the landing is "
                                    "located by re-stepping)",
                                    {"rk", "cn", "theta", "beuler", "bdf", "arkimex", "rosw", "irk", "alpha"}, "rk");
        s.range_text = "the types that can roll back a step: the landing is located by re-stepping";
        return s;
      }(),
      OptionText("-flight_ts_rk_type",
                 "Runge-Kutta tableau of -flight_ts_type rk: 5dp (Dormand-Prince 5(4)), 3bs, 4, 5bs, 8vr, ...", "5dp"),
      OptionReal("-flight_ts_rtol", "1",
                 "Relative tolerance of the local error (adaptive steps: every type but an rk tableau without an "
                 "embedded pair, 1fe, 3, 4)",
                 "1e-10", NonNegative()),
      OptionReal("-flight_ts_atol", "m, m/s",
                 "Absolute tolerance of the local error, on the positions (m) and velocities (m/s)", "1e-10",
                 NonNegative()),
      OptionReal("-flight_ts_dt", "s",
                 "First step of an adaptive run; the fixed step with -flight_ts_adapt_type none or an rk tableau "
                 "without error estimate (1fe, 3, 4)",
                 "0.001", Positive()),
      OptionReal("-flight_ts_max_time", "s", "Longest flight: a ball not landed by then is an error", "60", Positive()),
      OptionChoice("-flight_ts_adapt_type",
                   "Step size controller of the flight: basic for every type that estimates its error (theta, beuler, "
                   "cn and alpha too); none: the fixed step -flight_ts_dt",
                   {"none", "basic", "dsp"}, "basic"),
      OptionFlag("-flight_ts_monitor", "Print each step of the flight (time, step size)"),
    },
    true,
    {"-flight_ts_", "-flight_snes_", "-flight_ksp_", "-flight_pc_"},
  };
  return m;
}

PetscErrorCode FlightTSCheckOptions(const FlightSolveParams &p)
{
  FlightContext ctx;
  FlightModel   m;
  FlightResult  r;
  TS            ts;

  PetscFunctionBeginUser;
  ctx.m = &m;
  PetscCall(FlightTSCreate(PETSC_COMM_SELF, &ctx, &ts));
  const PetscErrorCode ierr = FlightTSCheck(ts, p, &r);
  PetscCall(TSDestroy(&ts));
  PetscCall(ierr);
  PetscFunctionReturn(0);
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

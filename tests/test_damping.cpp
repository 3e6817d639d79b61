// Rayleigh damping C = alpha M + beta K of the beam (docs/model.md, "Damping"): the system's
// damping action and dissipation rate against formulas; a damped free vibration decays at
// zeta = alpha/(2 w) + beta w/2; the energy balance KE + U + W_ball + D with an explicit and
// an implicit integrator, converging with the step; momentum of a free beam with beta-damping;
// nothing changes without damping; the damped stability limits (leapfrog and RK).
#include "solvers/leapfrog.hpp"
#include "solvers/modes.hpp"
#include "solvers/rk_stability.hpp"
#include "test_helpers.hpp"

#include <petscts.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

BeamParams Damped(BeamParams p, double alpha, double beta)
{
  p.damping_mass      = alpha;
  p.damping_stiffness = beta;
  return p;
}

// K v from the band (the assembled matrix), for comparison with the factored action.
std::vector<double> BandApply(const BeamSystem &S, const std::vector<double> &v)
{
  std::vector<double>   f(S.ndof, 0.0);
  std::vector<PetscInt> cols(2 * S.bw + 1);
  std::vector<double>   vals(2 * S.bw + 1);
  for (PetscInt i = 0; i < S.ndof; ++i) {
    const PetscInt n = BeamSystemStiffnessRow(S, i, cols.data(), vals.data());
    for (PetscInt q = 0; q < n; ++q) f[i] += vals[q] * v[cols[q]];
  }
  return f;
}

} // namespace

TEST(DampingSystem, ApplyAndRateMatchFormulas)
{
  std::mt19937                           gen(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (auto sup : {std::make_pair(Support::Free, Support::Free), std::make_pair(Support::Clamped, Support::Free), std::make_pair(Support::Pinned, Support::Clamped)}) {
    const double     alpha = 7.0, beta = 3e-5;
    const BeamSystem S     = SystemOf(Damped(AluminiumBeam(0.6, 31, sup.first, sup.second), alpha, beta));
    ASSERT_TRUE(S.Damped());
    std::vector<double> v(S.ndof);
    for (PetscInt i = 0; i < S.ndof; ++i) v[i] = S.held[i] ? 0.0 : U(gen);
    std::vector<double> cv(S.ndof);
    BeamSystemDampingApply(S, v.data(), S.fields, 0, S.ndof, cv.data(), S.fields);
    const std::vector<double> kv = BandApply(S, v);
    double                    vcv = 0, scale = 0;
    for (PetscInt i = 0; i < S.ndof; ++i) {
      const double expect = S.held[i] ? 0.0 : alpha * S.mass[i] * v[i] + beta * kv[i];
      scale               = std::max(scale, std::abs(beta * kv[i]) + std::abs(alpha * S.mass[i] * v[i]));
      EXPECT_NEAR(cv[i], expect, 1e-12 * scale) << "dof " << i;
      vcv += v[i] * cv[i];
    }
    const double rate = BeamSystemDissipationRate(S, v.data(), S.fields, 0, S.ndof);
    EXPECT_GT(rate, 0.0);
    EXPECT_NEAR(rate, vcv, 1e-12 * rate);
    // Split over a partition of the dofs (as over ranks), the rate adds up.
    const PetscInt cut = S.ndof / 3;
    EXPECT_NEAR(BeamSystemDissipationRate(S, v.data(), S.fields, 0, cut) + BeamSystemDissipationRate(S, v.data(), S.fields, cut, S.ndof), rate, 1e-13 * rate);
  }
}

// K annihilates rigid motion in the factored form: beta-damping of a rigid velocity field is
// round-off relative to the damping force of a flexural one, and its rate is a sum of squares
// of round-off (>= 0, never negative by cancellation).
TEST(DampingSystem, StiffnessDampingOfRigidMotionIsRoundoff)
{
  const BeamSystem    S = SystemOf(Damped(AluminiumBeam(1.1, 41), 0.0, 1e-5));
  std::vector<double> v(S.ndof), w(S.ndof), cv(S.ndof), cw(S.ndof);
  for (PetscInt i = 0; i < S.ndof; ++i) {
    v[i] = 0.3 + 2.0 * S.NodeX(i);                       // translation + rotation
    w[i] = std::sin(M_PI * S.NodeX(i) / S.L * 3) * 2.3; // flexural, same size
  }
  BeamSystemDampingApply(S, v.data(), 1, 0, S.ndof, cv.data(), 1);
  BeamSystemDampingApply(S, w.data(), 1, 0, S.ndof, cw.data(), 1);
  double fv = 0, fw = 0, sum = 0;
  for (PetscInt i = 0; i < S.ndof; ++i) {
    fv = std::max(fv, std::abs(cv[i]));
    fw = std::max(fw, std::abs(cw[i]));
    sum += cv[i];
  }
  EXPECT_LT(fv, 1e-12 * fw);
  EXPECT_LT(std::abs(sum), 1e-12 * fw);
  const double r = BeamSystemDissipationRate(S, v.data(), 1, 0, S.ndof);
  EXPECT_GE(r, 0.0);
  EXPECT_LT(r, 1e-20 * BeamSystemDissipationRate(S, w.data(), 1, 0, S.ndof));
}

// A clamped-free beam struck near its tip rings after the ball has left; once the higher
// modes (more damped: beta w^2) have died out, the tip velocity is one damped mode whose
// logarithmic decrement gives zeta. Expected: alpha/(2 w1) + beta w1/2 with w1 the undamped
// discrete fundamental (SLEPc modes of the same system).
TEST(DampingDecay, FundamentalDecaysAtRayleighRate)
{
  const BeamParams base = AluminiumBeam(0.3, 41, Support::Clamped, Support::Free);
  ModesResult      modes;
  ASSERT_EQ(BeamModesCompute(PETSC_COMM_WORLD, SystemOf(base), 1, &modes), 0);
  const double w1 = modes.omega[0], T1 = 2 * M_PI / w1;
  const double zeta_a = 0.004, zeta_b = 0.01; // the alpha and beta parts at w1
  const double alpha = 2 * zeta_a * w1, beta = 2 * zeta_b / w1;
  ImpactParams ip;
  ip.x        = 0.28;
  ip.window   = 12 * T1;
  ip.max_time = 14 * T1;
  MonitorRequest mon;
  mon.velocity_at = {0.3};
  const ImpactResult r = RunImpact(PETSC_COMM_WORLD, Damped(base, alpha, beta), Superball(), ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}}, mon);
  PetscMPIInt        rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank != 0) return; // the series live on rank 0
  double t_sep = 0;
  for (const ContactEvent &e : r.events)
    if (e.kind == ContactEventKind::Separation) t_sep = e.time;
  ASSERT_GT(t_sep, 0.0);
  // Maxima of the tip velocity from 4 periods after the last separation, located by a parabola.
  const std::vector<double> &t = r.series.time, &v = r.series.velocity_at[0];
  std::vector<double>        tp, vp;
  for (size_t k = 1; k + 1 < t.size(); ++k) {
    if (t[k] < t_sep + 4 * T1 || !(v[k] > v[k - 1] && v[k] >= v[k + 1])) continue;
    const double h = t[k + 1] - t[k], a = 0.5 * (v[k + 1] - 2 * v[k] + v[k - 1]), b = 0.5 * (v[k + 1] - v[k - 1]);
    const double s = -b / (2 * a);
    tp.push_back(t[k] + s * h);
    vp.push_back(v[k] + b * s + a * s * s);
  }
  ASSERT_GE(tp.size(), 6u);
  const double span = tp.back() - tp.front(), periods = (double)(tp.size() - 1);
  const double rate = std::log(vp.front() / vp.back()) / span; // zeta w
  const double wd = 2 * M_PI * periods / span, w = std::sqrt(wd * wd + rate * rate);
  const double zeta_meas = rate / w, zeta_formula = alpha / (2 * w1) + beta * w1 / 2;
  printf("decay: w1 = %.6g rad/s (measured %.6g), zeta measured %.6g, formula %.6g (rel. diff %.2e), %d periods\n", w1, w, zeta_meas, zeta_formula, (zeta_meas - zeta_formula) / zeta_formula, (int)periods);
  EXPECT_NEAR(w / w1, 1.0, 1e-3);
  EXPECT_NEAR(zeta_meas / zeta_formula, 1.0, 1e-3);
}

namespace {

// The default free beam with Rayleigh damping that takes a sizeable share of the energy.
ImpactResult DampedImpact(const Options &ts, double alpha = 20, double beta = 2e-6)
{
  ImpactParams ip;
  ip.x      = 0.55;
  ip.window = 0.01;
  return RunImpact(PETSC_COMM_WORLD, Damped(AluminiumBeam(1.1, 41), alpha, beta), Superball(), ip, ts);
}

} // namespace

// KE_ball + W_ball + KE_beam + U_beam + D is conserved to the integrator's accuracy: the
// error falls with the step at the integrator's order (events located, D by a 4th-order rule).
TEST(DampingEnergy, BalanceConvergesExplicitAndImplicit)
{
  struct Case {
    const char *type, *sub;
    double      dt, tol, ratio; // coarse step (s), bound on |error| there, minimal error ratio for a halved step
  };
  for (const Case &c : {Case{"rk", "4", 2e-5, 3e-8, 12.0}, Case{"cn", "", 5e-6, 4e-7, 3.8}, Case{"alpha2", "", 5e-6, 4e-7, 3.8}}) {
    double err[2];
    for (int l = 0; l < 2; ++l) {
      char dt[32];
      snprintf(dt, sizeof(dt), "%.17g", c.dt / (1 << l));
      Options o = {{"-ts_type", c.type}, {"-ts_dt", dt}, {"-ts_adapt_type", "none"}};
      if (*c.sub) o.push_back({"-ts_rk_type", c.sub});
      const ImpactResult r = DampedImpact(o);
      EXPECT_GT(r.damping_fraction, 0.1);
      EXPECT_NEAR(r.damping_fraction * 0.5 * 0.042, r.beam_dissipated_end, 1e-15);
      err[l] = std::abs(r.energy_error);
    }
    printf("energy balance %s%s: dt %.3g -> %.2e, dt/2 -> %.2e (ratio %.1f)\n", c.type, c.sub, c.dt, err[0], err[1], err[0] / err[1]);
    EXPECT_LT(err[0], c.tol) << c.type;
    EXPECT_GT(err[0] / err[1], c.ratio) << c.type;
  }
}

// C = beta K exerts no resultant and no moment: momentum of the free beam and ball is conserved
// to round-off as without damping (the energy is not: D > 0).
TEST(DampingMomentum, StiffnessDampingConservesMomentumOfFreeBeam)
{
  for (const Options &o : {Options{{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}}, Options{{"-ts_type", "rk"}, {"-ts_rk_type", "4"}}, Options{{"-ts_type", "alpha2"}, {"-ts_dt", "5e-6"}}}) {
    const ImpactResult r = DampedImpact(o, 0.0, 1e-5);
    EXPECT_GT(r.damping_fraction, 1e-3);
    EXPECT_LT(std::abs(r.linear_momentum_error), 1e-13) << o[0].second;
    EXPECT_LT(std::abs(r.angular_momentum_error), 1e-13) << o[0].second;
  }
}

// The program's default solve for an implicit type (the beam's LU kept per shift, the contact
// by Sherman-Morrison) is the exact inverse of the Jacobian on a damped beam in the second-order
// form too: alpha2 on a linear problem takes one Newton iteration a step, as -pc_type lu does,
// and the same result. (The kept factor once lacked shiftV C: Newton then took ~11 iterations a
// step with beta = 1e-4 s and stalled at 2 ms, the stability matrix's damped-beta x alpha2.)
TEST(DampingSecondOrder, DefaultSolveIsExactLikeLU)
{
  const Options base{{"-ts_type", "alpha2"}, {"-ts_alpha_radius", "0.8"}, {"-ts_dt", "1.09842e-5"}};
  Options       lu = base;
  lu.push_back({"-pc_type", "lu"});
  for (double beta : {2e-6, 1e-4}) {
    const ImpactResult d = DampedImpact(base, 2.0, beta), a = DampedImpact(lu, 2.0, beta);
    ASSERT_GT(d.steps, 100) << "beta " << beta;
    EXPECT_LE(d.nonlinear_its, a.nonlinear_its) << "beta " << beta;
    EXPECT_LE(d.nonlinear_its, d.steps + d.event_steps + 20) << "one Newton iteration a step; beta " << beta;
    EXPECT_NEAR(d.acor, a.acor, 1e-10) << "beta " << beta;
  }
}

// Without damping nothing is computed or recorded: alpha = beta = 0 given explicitly is the
// undamped run to the bit, and a vanishing damping changes the result continuously.
TEST(DampingOff, ZeroDampingIsTheUndampedRun)
{
  ImpactParams ip;
  ip.x      = 0.55;
  ip.window = 0.01;
  MonitorRequest mon;
  mon.energy          = PETSC_TRUE;
  const Options    cn = {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}};
  const BeamParams p  = AluminiumBeam(1.1, 41);
  const ImpactResult r0 = RunImpact(PETSC_COMM_WORLD, p, Superball(), ip, cn, mon);
  const ImpactResult r1 = RunImpact(PETSC_COMM_WORLD, Damped(p, 0.0, 0.0), Superball(), ip, cn, mon);
  const ImpactResult r2 = RunImpact(PETSC_COMM_WORLD, Damped(p, 0.0, 1e-13), Superball(), ip, cn, mon);
  PetscMPIInt size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  EXPECT_EQ(r0.acor, r1.acor);
  if (size == 1) {
    EXPECT_EQ(r0.energy_error, r1.energy_error);
  } else { // the parallel LU (MUMPS) repeats a run only to round-off
    EXPECT_NEAR(r0.energy_error, r1.energy_error, 1e-13);
  }
  EXPECT_EQ(r0.steps, r1.steps);
  EXPECT_EQ(r0.jacobian_assemblies, r1.jacobian_assemblies);
  EXPECT_EQ(r1.beam_dissipated_end, 0.0);
  EXPECT_TRUE(r1.series.beam_dissipated.empty());
  EXPECT_NEAR(r2.acor, r0.acor, 1e-9);
  EXPECT_GT(r2.beam_dissipated_end, 0.0);
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    EXPECT_EQ(r2.series.beam_dissipated.size(), r2.series.time.size());
  }
}

// Leapfrog: the bound (2/w)(sqrt(1 + zeta^2) - zeta), zeta = beta w/2, is what the stepper uses;
// heavy damping (zeta_max = 1: the bound is 0.41 of the undamped 2/w) just under it stays
// bounded and balances its energy; a step between it and 2/w is refused.
TEST(DampingLeapfrog, StableStepBoundAndRunJustUnderIt)
{
  const BeamParams      base = AluminiumBeam(1.1, 41);
  const BallParams      ball = Superball();
  const BeamSystem      S0   = SystemOf(base);
  const ContactCoupling g    = BeamSystemCoupling(S0, 0.55);
  const double          w    = BeamSystemMaxFrequencyBound(S0, g, ContactScalesOf(S0, ball).stiffness, ball.mass);
  EXPECT_NEAR(LeapfrogStableStep(S0, g, ball), 2 / w, 1e-15 * 2 / w);
  for (double zeta : {0.05, 1.0, 5.0}) {
    const BeamParams p   = Damped(base, 3.0, 2 * zeta / w);
    const BeamSystem S   = SystemOf(p);
    const double     dts = LeapfrogStableStep(S, g, ball), formula = 2 / w * (std::sqrt(1 + zeta * zeta) - zeta);
    EXPECT_NEAR(dts / formula, 1.0, 1e-12) << zeta;
    if (zeta != 1.0) continue;
    ImpactParams ip;
    ip.x      = 0.55;
    ip.window = 0.01;
    Scenario       sc{p, ball, ip, MonitorRequest()};
    LeapfrogParams lp;
    lp.dt_fraction = 0.99;
    ImpactResult r;
    ASSERT_EQ(LeapfrogRun(sc, lp, &r), 0);
    EXPECT_NEAR(r.dt_stable, formula, 1e-12 * formula);
    EXPECT_TRUE(std::isfinite(r.acor));
    EXPECT_GT(r.damping_fraction, 0.01);
    EXPECT_LT(std::abs(r.energy_error), 1e-2);
    printf("leapfrog zeta_max = 1: dt = %.4g s (bound %.4g s, undamped 2/w = %.4g s), energy balance error %.2e, damping %.3f of the incident energy\n", r.dt_nominal, formula, 2 / w, r.energy_error,
           r.damping_fraction);
    lp.dt = 0.5 * (formula + 2 / w);
    ASSERT_EQ(PetscPushErrorHandler(PetscReturnErrorHandler, NULL), 0);
    EXPECT_NE(LeapfrogRun(sc, lp, &r), 0) << "a step above the damped bound is refused";
    ASSERT_EQ(PetscPopErrorHandler(), 0);
  }
}

// RK: the damped limit reduces to y*/w without damping, and with heavy beta-damping (the top
// mode overdamped, eigenvalue ~ -beta w^2) to the real-axis limit of RK4, 2.7853 / (beta w^2).
TEST(DampingRK, DampedStabilityBound)
{
  const double A[16] = {0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0}, b[4] = {1. / 6, 1. / 3, 1. / 3, 1. / 6};
  const double w = 1e5, ystar = RKImaginaryStabilityBound(4, A, b);
  EXPECT_NEAR(RKDampedStabilityBound(4, A, b, w, 0.0, 0.0) * w / ystar, 1.0, 1e-3);
  const double beta = 2 * 20 / w; // zeta_max = 20
  EXPECT_NEAR(RKDampedStabilityBound(4, A, b, w, 0.0, beta) * beta * w * w / 2.785293, 1.0, 2e-3);
  EXPECT_GT(RKDampedStabilityBound(4, A, b, w, 0.0, 1e-3 / w), 0.99 * ystar / w) << "light damping does not lower the limit";
}

// The grid-scale mode x'' + beta w^2 x' + w^2 x = 0 stepped by PETSc's own TSRK 4 at a fixed step:
// the amplitude max(|x|, |x'|/w) after `steps` steps from x = 1, x' = 0.
static double StepTopModeRK4(double w, double beta, double dt, PetscInt steps)
{
  struct Mode {
    double w, beta;
  } mode{w, beta};
  auto rhs = [](TS, PetscReal, Vec U, Vec F, void *ctx) -> PetscErrorCode {
    const Mode        *m = static_cast<Mode *>(ctx);
    const PetscScalar *u;
    PetscScalar       *f;
    PetscFunctionBeginUser;
    PetscCall(VecGetArrayRead(U, &u));
    PetscCall(VecGetArray(F, &f));
    f[0] = u[1];
    f[1] = -m->w * m->w * u[0] - m->beta * m->w * m->w * u[1];
    PetscCall(VecRestoreArray(F, &f));
    PetscCall(VecRestoreArrayRead(U, &u));
    PetscFunctionReturn(0);
  };
  TS  ts;
  Vec U;
  PetscCallAbort(PETSC_COMM_SELF, VecCreateSeq(PETSC_COMM_SELF, 2, &U));
  PetscCallAbort(PETSC_COMM_SELF, VecSetValue(U, 0, 1.0, INSERT_VALUES));
  PetscCallAbort(PETSC_COMM_SELF, VecSetValue(U, 1, 0.0, INSERT_VALUES));
  PetscCallAbort(PETSC_COMM_SELF, TSCreate(PETSC_COMM_SELF, &ts));
  PetscCallAbort(PETSC_COMM_SELF, TSSetType(ts, TSRK));
  PetscCallAbort(PETSC_COMM_SELF, TSRKSetType(ts, TSRK4));
  PetscCallAbort(PETSC_COMM_SELF, TSSetRHSFunction(ts, NULL, rhs, &mode));
  PetscCallAbort(PETSC_COMM_SELF, TSSetTimeStep(ts, dt));
  PetscCallAbort(PETSC_COMM_SELF, TSSetMaxSteps(ts, steps));
  PetscCallAbort(PETSC_COMM_SELF, TSSetMaxTime(ts, 1e30));
  PetscCallAbort(PETSC_COMM_SELF, TSSetExactFinalTime(ts, TS_EXACTFINALTIME_STEPOVER));
  PetscCallAbort(PETSC_COMM_SELF, TSSolve(ts, U));
  const PetscScalar *u;
  PetscCallAbort(PETSC_COMM_SELF, VecGetArrayRead(U, &u));
  const double norm = std::max(std::abs(u[0]), std::abs(u[1]) / w);
  PetscCallAbort(PETSC_COMM_SELF, VecRestoreArrayRead(U, &u));
  PetscCallAbort(PETSC_COMM_SELF, TSDestroy(&ts));
  PetscCallAbort(PETSC_COMM_SELF, VecDestroy(&U));
  return norm;
}

// Strong stiffness damping (zeta_max = 1000, as -beam_damping_stiffness 1e-2 on the default grid
// gives ~230): the limit is RK4's real-axis reach 2.785 over the fast real eigenvalue
// w (zeta + sqrt(zeta^2 - 1)), not 0 ("-ts_dt 0 is not allowed" before); PETSc's RK4 on the top
// mode decays just below it and grows just above it.
TEST(DampingRK, StrongDampingLimitIsTheRealAxisReach)
{
  const double A[16] = {0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0}, b[4] = {1. / 6, 1. / 3, 1. / 3, 1. / 6};
  const double w = 1e5, zeta = 1000, beta = 2 * zeta / w, fast = w * (zeta + std::sqrt(zeta * zeta - 1));
  const double dt = RKDampedStabilityBound(4, A, b, w, 0.0, beta);
  ASSERT_GT(dt, 0.0);
  EXPECT_NEAR(dt * fast / 2.785293563, 1.0, 1e-6);
  EXPECT_LT(StepTopModeRK4(w, beta, 0.99 * dt, 4000), 1.5) << "unstable below the computed limit";
  EXPECT_GT(StepTopModeRK4(w, beta, 1.01 * dt, 4000), 1e6) << "stable above the computed limit: the limit is too low";
}

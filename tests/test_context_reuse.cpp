// The integrator's per-structure context (solvers/ts_stepper.hpp): a run on a reused TS,
// layout and vectors gives every column of the results table bit for bit as a run on a
// freshly built one, whatever ran on the context before (another contact point, another
// ball, a run cut short), for explicit, IMEX, implicit and second-order types, fixed and
// adaptive; a run on another grid or with other integrator options builds its own context.
// The implicit types' beam factorizations are kept across points (a point with the same step
// keeps the nominal step's factor) and the rank-one solve agrees with the assembled LU (-pc_type lu);
// where its Sherman-Morrison step breaks down, the solve falls back to the assembled LU.
// Runs at np1, and a few at np2 (MUMPS, a distributed layout).
#include "run/results_table.hpp"
#include "model/contact.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/ts_modal.hpp"
#include "solvers/ts_problem.hpp"
#include "solvers/ts_stepper.hpp"
#include "test_helpers.hpp"

#include <petscdm.h>

#include <cstring>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

// The paper's 1.1 m beam (N = 41, or `nodes`) and the linear superball, at x with speed v.
Scenario Scene(PetscReal x, PetscReal v, PetscInt nodes = 41, const char *ball = "options/base/superball-linear.opts")
{
  Scenario sc;
  test::ReadScene({"options/base/aluminium-6mm.opts", ball}, {{"-beam_length", "1.1"}, {"-beam_nodes", std::to_string(nodes)}}, &sc.beam, &sc.ball);
  sc.impact.x      = x;
  sc.ball.speed    = v;
  sc.impact.window = 1e-3;
  return sc;
}

ImpactResult RunImpact(const Scenario &sc, const Opts &ts)
{
  for (auto &kv : ts) EXPECT_EQ(PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()), 0);
  ImpactResult r;
  EXPECT_EQ(ImpactRun(PETSC_COMM_WORLD, sc, &r), 0);
  for (auto &kv : ts) EXPECT_EQ(PetscOptionsClearValue(NULL, kv.first.c_str()), 0);
  return r;
}

PetscInt Reused()
{
  PetscInt built, reused;
  TSStepperContextCounts(&built, &reused);
  return reused;
}

// Every column but the wall-clock time, bit for bit (NaN where both are NaN).
void ExpectSameRow(const ImpactResult &a, const ImpactResult &b, const std::string &what)
{
  for (const ResultColumn &c : ImpactResultColumns()) {
    if (!std::strcmp(c.name, "wall_time")) continue;
    const double x = c.Get(a), y = c.Get(b);
    if (std::isnan(x) && std::isnan(y)) continue;
    EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << what << ": " << c.name << " " << x << " fresh, " << y << " on a reused context";
  }
  EXPECT_EQ(a.ts_type, b.ts_type) << what;
  EXPECT_EQ(a.dt_nominal, b.dt_nominal) << what;
}

// A point on a context that another point (another impact point and ball speed) ran on
// before, against the same point on a fresh context.
void ExpectReuseIsFresh(const Opts &ts, const char *ball = "options/base/superball-linear.opts")
{
  const std::string what = ts[0].second + (ts.size() > 1 ? " " + ts[1].first + " " + ts[1].second : "");
  const Scenario    a = Scene(0.825, 1.0, 41, ball), b = Scene(0.3, 2.5, 41, ball);
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  const ImpactResult fresh = RunImpact(b, ts);
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  (void)RunImpact(a, ts);
  const PetscInt     before = Reused();
  const ImpactResult again  = RunImpact(b, ts);
  EXPECT_EQ(Reused(), before + 1) << what << ": the second point did not reuse the first one's context";
  ExpectSameRow(fresh, again, what);
  EXPECT_GT(fresh.steps, 0) << what;
}

} // namespace

TEST(ContextReuse, ExplicitFixedStep) { ExpectReuseIsFresh({{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}}); }
TEST(ContextReuse, ExplicitAdaptive) { ExpectReuseIsFresh({{"-ts_type", "rk"}, {"-ts_rk_type", "5dp"}, {"-ts_rtol", "1e-7"}, {"-ts_atol", "1e-10"}}); }
TEST(ContextReuse, ImplicitFixedStep) { ExpectReuseIsFresh({{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}}); }
TEST(ContextReuse, ImplicitAdaptiveMultistep) { ExpectReuseIsFresh({{"-ts_type", "bdf"}, {"-ts_rtol", "1e-6"}, {"-ts_atol", "1e-9"}}); }
TEST(ContextReuse, IMEX) { ExpectReuseIsFresh({{"-ts_type", "arkimex"}, {"-ts_dt", "1e-5"}, {"-ts_adapt_type", "none"}}); }
TEST(ContextReuse, SecondOrder) { ExpectReuseIsFresh({{"-ts_type", "alpha2"}, {"-ts_dt", "2e-5"}}); }
// A nonlinear law: the contact stiffness changes at every Newton iteration (the rank-one term).
TEST(ContextReuse, ImplicitNonlinearLaw) { ExpectReuseIsFresh({{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}}, "options/base/superball-hysteresis.opts"); }
TEST(ContextReuse, SecondOrderNonlinearLaw) { ExpectReuseIsFresh({{"-ts_type", "alpha2"}, {"-ts_dt", "2e-5"}}, "options/base/superball-hysteresis.opts"); }
// -ts_type modal: the modes (shared), gamma and the static correction set for each point; a
// truncated basis (-modal_tolerance 1e-4 keeps the modes below ~11 kHz: the static correction
// at each point) and every mode.
TEST(ContextReuse, Modal) { ExpectReuseIsFresh({{"-ts_type", "modal"}, {"-modal_tolerance", "1e-4"}}); }
TEST(ContextReuse, ModalNonlinearLaw) { ExpectReuseIsFresh({{"-ts_type", "modal"}, {"-ts_modal_order", "2"}}, "options/base/superball-hysteresis.opts"); }
// -ts_type modal: a point after another with the same ball (the same nominal step) folds its
// gamma_k into the parts of that step's weights the first point kept (ts_modal.cpp, StepShapes)
// instead of computing them: bit for bit its fresh run, undamped and damped (each mode's exact
// damped response), at order 4 and 2.
TEST(ContextReuse, ModalNominalStepShapes)
{
  for (const char *order : {"4", "2"})
    for (PetscReal alpha : {0.0, 2.0}) {
      const Opts  ts   = {{"-ts_type", "modal"}, {"-ts_modal_order", order}};
      std::string what = std::string("modal order ") + order + (alpha > 0 ? ", damped" : "");
      Scenario    a = Scene(0.825, 1.0), b = Scene(0.3, 1.0);
      for (Scenario *sc : {&a, &b}) sc->beam.damping_mass = alpha, sc->beam.damping_stiffness = alpha > 0 ? 2e-6 : 0.0;
      ASSERT_EQ(TSStepperContextCacheClear(), 0);
      const PetscInt     folds0 = TSModalFoldCount();
      const ImpactResult fresh  = RunImpact(b, ts);
      EXPECT_EQ(TSModalFoldCount(), folds0) << what << ": a fresh run folded weights it had no shapes for";
      ASSERT_EQ(TSStepperContextCacheClear(), 0);
      (void)RunImpact(a, ts);
      const PetscInt     folds1 = TSModalFoldCount();
      const ImpactResult again  = RunImpact(b, ts);
      EXPECT_GT(TSModalFoldCount(), folds1) << what << ": the second point did not fold its weights from the first's shapes";
      ASSERT_EQ(fresh.dt_nominal, again.dt_nominal) << what;
      ExpectSameRow(fresh, again, what);
      if (alpha > 0) EXPECT_GT(again.beam_dissipated_end, 0.0) << what; // the damped modes dissipate
      else EXPECT_EQ(again.beam_dissipated_end, 0.0) << what;          // the undamped ones nothing
    }
}

TEST(ContextReuse, AssembledLU) { ExpectReuseIsFresh({{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}, {"-pc_type", "lu"}}); }

// Another beam on the same grid (a sweep over the thickness): the context is reused, but not
// the factors of the first beam's Jacobian (nor, -ts_type modal, its modes); the second beam's
// run is its fresh run bit for bit.
TEST(ContextReuse, ImplicitAnotherBeamOnTheSameGrid)
{
  for (const Opts &cn : {Opts{{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}}, Opts{{"-ts_type", "modal"}}}) {
  Scenario   thick;
  test::ReadScene({"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, {{"-beam_length", "1.1"}, {"-beam_nodes", "41"}, {"-beam_thickness", "0.01"}}, &thick.beam, &thick.ball);
  thick.impact.x      = 0.3;
  thick.ball.speed    = 2.5;
  thick.impact.window = 1e-3;
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  const ImpactResult fresh = RunImpact(thick, cn);
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  (void)RunImpact(Scene(0.825, 1.0), cn);
  const PetscInt     before = Reused();
  const ImpactResult again  = RunImpact(thick, cn);
  EXPECT_EQ(Reused(), before + 1) << cn[0].second;
  ExpectSameRow(fresh, again, "a thicker beam after the 6 mm one, " + cn[0].second);
  }
}

// The beam's factorizations are the context's: a second point at the same step factors fewer
// shifts than the first (the nominal step's is kept; only event-location steps the first point
// did not take are new), and a third at the same point as the second none at all.
TEST(ContextReuse, BeamFactorizationsKept)
{
  const Opts cn = {{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}};
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  PetscInt           f0 = TSStepperBeamFactorizations();
  (void)RunImpact(Scene(0.825, 1.0), cn);
  const PetscInt     first = TSStepperBeamFactorizations() - f0;
  f0                       = TSStepperBeamFactorizations();
  const ImpactResult b     = RunImpact(Scene(0.3, 2.5), cn);
  const PetscInt     second = TSStepperBeamFactorizations() - f0;
  f0                        = TSStepperBeamFactorizations();
  const ImpactResult again  = RunImpact(Scene(0.3, 2.5), cn);
  const PetscInt     third  = TSStepperBeamFactorizations() - f0;
  EXPECT_GE(first, 1);
  EXPECT_LT(second, first) << "the second point refactored the nominal step's beam matrix";
  EXPECT_LE(third, second);
  EXPECT_LT(third, b.jacobian_assemblies) << "every change of the Jacobian was a factorization";
  ExpectSameRow(b, again, "the same point again");
}

// The rank-one solve (the beam's LU, the contact by Sherman-Morrison) against the LU of the
// assembled Jacobian (-pc_type lu): the same Newton iterates up to round-off, for a law whose
// stiffness changes with the compression, first and second order.
TEST(ContextReuse, RankOneAgreesWithAssembledLU)
{
  for (const char *type : {"cn", "alpha2", "bdf"}) {
    const Scenario sc = Scene(0.3, 2.5, 41, "options/base/superball-hysteresis.opts");
    Opts           ts = {{"-ts_type", type}, {"-ts_dt", "2e-5"}};
    ASSERT_EQ(TSStepperContextCacheClear(), 0);
    const ImpactResult r = RunImpact(sc, ts);
    ts.push_back({"-pc_type", "lu"});
    const ImpactResult a = RunImpact(sc, ts);
    EXPECT_NEAR(r.acor, a.acor, 1e-12) << type;
    EXPECT_NEAR(r.contact_time / a.contact_time, 1, 1e-11) << type;
    EXPECT_NEAR(r.peak_force / a.peak_force, 1, 1e-11) << type;
    EXPECT_EQ(r.nonlinear_its, a.nonlinear_its) << type;
    EXPECT_EQ(r.jacobian_assemblies, a.jacobian_assemblies) << type;
  }
}

// Another grid or other integrator options: a context of their own (none reused); the same
// again: reused.
TEST(ContextReuse, KeyedByGridAndOptions)
{
  const Opts rk4 = {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}};
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  (void)RunImpact(Scene(0.825, 1.0), rk4);
  PetscInt n = Reused();
  (void)RunImpact(Scene(0.825, 1.0, 61), rk4);
  EXPECT_EQ(Reused(), n) << "a 61-node beam reused the 41-node beam's context";
  Opts rk3 = rk4;
  rk3[1].second = "3";
  (void)RunImpact(Scene(0.825, 1.0), rk3);
  EXPECT_EQ(Reused(), n) << "-ts_rk_type 3 reused the context of -ts_rk_type 4";
  (void)RunImpact(Scene(0.5, 1.5), rk4);
  EXPECT_EQ(Reused(), n + 1) << "the 41-node rk4 context was not reused";
}

// A run that stops on an error leaves no context behind for the next run: the next run on the
// same key builds a fresh one and gives the fresh run's numbers.
TEST(ContextReuse, ARunThatFailedIsNotReused)
{
  const Opts rk4 = {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}};
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  const ImpactResult fresh = RunImpact(Scene(0.3, 2.5), rk4);
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  Scenario bad = Scene(0.825, 1.0);
  bad.monitor.segment       = PETSC_TRUE; // a segment monitored until after the run's end: an error once stepped
  bad.monitor.segment_x0    = 0.2;
  bad.monitor.segment_x1    = 0.4;
  bad.monitor.segment_until = 10;
  for (auto &kv : rk4) ASSERT_EQ(PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()), 0);
  ImpactResult r;
  PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
  const PetscErrorCode ierr = ImpactRun(PETSC_COMM_WORLD, bad, &r);
  PetscPopErrorHandler();
  for (auto &kv : rk4) ASSERT_EQ(PetscOptionsClearValue(NULL, kv.first.c_str()), 0);
  EXPECT_NE(ierr, 0) << "-monitor_segment_until beyond the run did not stop it";
  const PetscInt     n     = Reused();
  const ImpactResult again = RunImpact(Scene(0.3, 2.5), rk4);
  EXPECT_EQ(Reused(), n) << "the context of a run that failed was reused";
  ExpectSameRow(fresh, again, "after a failed run");
}

// The rank-one solve on its own: the PCSHELL apply of cn's first-order Jacobian J = B + kc u v^T
// on a 21-node beam, the linear superball in contact at x = 0.3 m. Each solve is checked by its
// residual with J applied as the shell (B x + kc u v^T x, not the Sherman-Morrison formula).
// The kept factor is then broken as an inaccurate or non-finite B^-1 u would break it: its
// v^T w set so that 1 + kc v^T w vanishes, then to NaN. The solve must fall back to the
// assembled LU (still J z = b, every entry finite); without the checks z is inf or NaN.
TEST(RankOneSolve, BreakdownFallsBackToTheAssembledLU)
{
  const MPI_Comm comm = PETSC_COMM_WORLD;
  BeamSystem     sys  = SystemOf(AluminiumBeam(1.1, 21));
  ContactState   contact;
  TSProblem      P;
  contact.phase = ContactPhase::Loading;
  P.sys         = &sys;
  P.g           = BeamSystemCoupling(sys, 0.3);
  P.ball        = Superball("linear");
  P.contact     = &contact;
  P.form        = Formulation::Implicit;
  P.jac.contact = true;
  ASSERT_EQ(TSLayoutCreate(comm, sys.nodes, sys.fields, sys.GhostNodes(), true, &P.L), 0);
  TS   ts;
  SNES snes;
  KSP  ksp;
  PC   pc;
  ASSERT_EQ(TSCreate(comm, &ts), 0);
  ASSERT_EQ(TSSetType(ts, TSCN), 0);
  ASSERT_EQ(TSSetDM(ts, P.L.pack), 0);
  ASSERT_EQ(TSSetIFunction(ts, NULL, TSIFunctionBeam, &P), 0);
  ASSERT_EQ(TSGetSNES(ts, &snes), 0);
  ASSERT_EQ(SNESGetKSP(snes, &ksp), 0);
  ASSERT_EQ(KSPSetType(ksp, KSPPREONLY), 0);
  ASSERT_EQ(KSPGetPC(ksp, &pc), 0);
  ASSERT_EQ(TSJacobianSetDefaultPC(P, pc), 0);
  ASSERT_EQ(TSJacobianInstall(P, ts), 0);
  ASSERT_EQ(PCSetOperators(pc, P.jac.J, P.jac.J), 0); // as the SNES would
  Vec U, Udot, b, z, r;
  ASSERT_EQ(DMCreateGlobalVector(P.L.pack, &U), 0);
  for (Vec *x : {&Udot, &b, &z, &r}) ASSERT_EQ(VecDuplicate(U, x), 0);
  ASSERT_EQ(VecZeroEntries(U), 0);
  ASSERT_EQ(VecZeroEntries(Udot), 0);
  if (P.L.rank == 0) { // 0.1 mm into the beam: in contact
    ASSERT_EQ(VecSetValue(U, P.L.BallIndex(0), 1e-4, INSERT_VALUES), 0);
  }
  PetscInt lo, hi;
  ASSERT_EQ(VecGetOwnershipRange(b, &lo, &hi), 0);
  for (PetscInt i = lo; i < hi; ++i) ASSERT_EQ(VecSetValue(b, i, 1.0 + 0.01 * (i % 7), INSERT_VALUES), 0);
  for (Vec x : {U, b}) {
    ASSERT_EQ(VecAssemblyBegin(x), 0);
    ASSERT_EQ(VecAssemblyEnd(x), 0);
  }
  ASSERT_EQ(TSIJacobianBeam(ts, 0.0, U, Udot, 2 / 1e-5, P.jac.J, P.jac.J, &P), 0); // cn at dt = 1e-5 s: shift 2/dt
  ASSERT_GT(P.jac.kc, 0.0);
  // The relative residual |J z - b| / |b| of a solve, and whether z is finite.
  auto solve = [&](PetscReal *res, bool *finite) {
    PetscReal nb, nr, nz;
    ASSERT_EQ(PCApply(pc, b, z), 0);
    ASSERT_EQ(MatMult(P.jac.J, z, r), 0);
    ASSERT_EQ(VecAXPY(r, -1.0, b), 0);
    ASSERT_EQ(VecNorm(b, NORM_INFINITY, &nb), 0);
    ASSERT_EQ(VecNorm(r, NORM_INFINITY, &nr), 0);
    ASSERT_EQ(VecNorm(z, NORM_1, &nz), 0);
    *res    = nr / nb;
    *finite = std::isfinite(nz);
  };
  PetscReal res;
  bool      finite;
  solve(&res, &finite);
  EXPECT_TRUE(finite && res < 1e-10) << "the rank-one solve: residual " << res;
  EXPECT_EQ(P.jac.fallbacks, 0) << "a sound rank-one solve fell back";
  BeamFactor     &f  = *P.jac.current;
  const PetscReal vw = f.vw;
  f.vw               = -1 / P.jac.kc; // 1 + kc v^T w = 0 (or round-off)
  solve(&res, &finite);
  EXPECT_TRUE(finite && res < 1e-10) << "a vanishing Sherman-Morrison denominator: residual " << res << (finite ? "" : ", not finite");
  EXPECT_EQ(P.jac.fallbacks, 1) << "the vanishing denominator did not fall back";
  f.vw = NAN; // a non-finite B^-1 u
  solve(&res, &finite);
  EXPECT_TRUE(finite && res < 1e-10) << "a non-finite v^T B^-1 u: residual " << res << (finite ? "" : ", not finite");
  EXPECT_EQ(P.jac.fallbacks, 2);
  f.vw = vw;
  solve(&res, &finite);
  EXPECT_TRUE(finite && res < 1e-10) << "restored: residual " << res;
  EXPECT_EQ(P.jac.fallbacks, 2) << "the restored factor fell back";
  PetscReal den;
  EXPECT_TRUE(RankOneDenominator(4.0, 0.25, &den) && den == 2.0);
  EXPECT_FALSE(RankOneDenominator(1e6, -1e-6 * (1 + 1e-10), &den)) << "1 + kc vw = -1e-10: cancelled to 1e-10, beyond sqrt(eps)";
  EXPECT_FALSE(RankOneDenominator(INFINITY, 1e-6, &den));
  for (Vec *x : {&U, &Udot, &b, &z, &r}) VecDestroy(x);
  TSDestroy(&ts);
  TSJacobianDestroy(P);
  TSLayoutDestroy(&P.L);
}

namespace {

// The cache of the beam's modes on this rank emptied of the bases of sys (four others pushed in).
void EvictModes(const BeamSystem &sys)
{
  for (PetscInt count : {5, 6, 7, 8}) {
    ModalTruncation                  t;
    std::shared_ptr<const BeamModes> m;
    t.modes = ModalModes::Count;
    t.count = count;
    ASSERT_EQ(BeamModesShared(PETSC_COMM_SELF, sys, t, &m), 0);
  }
}

} // namespace

// -modal_modes auto whose cut-off pi / (T sqrt(tol)) lies above the highest mode's bound is the
// dense decomposition of every mode whatever the contact time T: a sweep's points, whose
// approach speeds and so contact times differ, share one basis (before: the cut-offs compared
// exactly, a decomposition at every point, the sweet zone's dominant cost after the free flight,
// issue 38), the basis a fresh decomposition gives bit for bit; a cut-off below the bound still
// truncates, in a basis of its own.
TEST(ContextReuse, ModesSharedAcrossContactTimesAboveEveryMode)
{
  const BeamSystem sys = SystemOf(AluminiumBeam(1.1, 41));
  ModalTruncation  a, b, low; // -modal_modes auto, -modal_tolerance 1e-9: cut-offs of 1e9 rad/s and more
  a.contact_time   = 1e-4;
  b.contact_time   = 1.3e-4;
  low.contact_time = 1e-3;
  low.tolerance    = 1e-2; // 3e4 rad/s: below the beam's highest modes
  std::shared_ptr<const BeamModes> ma, mb, ml, fresh;
  PetscInt                         c0, r0, c1, r1;
  EvictModes(sys);
  BeamModesCacheCounts(&c0, &r0);
  ASSERT_EQ(BeamModesShared(PETSC_COMM_SELF, sys, a, &ma), 0);
  ASSERT_EQ(BeamModesShared(PETSC_COMM_SELF, sys, b, &mb), 0);
  BeamModesCacheCounts(&c1, &r1);
  EXPECT_EQ(mb.get(), ma.get()) << "another contact time decomposed the beam again";
  EXPECT_EQ(c1 - c0, 1);
  EXPECT_EQ(r1 - r0, 1);
  EXPECT_FALSE(ma->truncated);
  ASSERT_EQ(BeamModesShared(PETSC_COMM_SELF, sys, low, &ml), 0);
  EXPECT_NE(ml.get(), ma.get());
  EXPECT_LT(ml->Count(), ma->Count()) << "a cut-off below the highest modes keeps fewer";
  EvictModes(sys);
  ASSERT_EQ(BeamModesShared(PETSC_COMM_SELF, sys, b, &fresh), 0);
  ASSERT_NE(fresh.get(), ma.get());
  ASSERT_EQ(fresh->B.omega.size(), ma->B.omega.size());
  ASSERT_EQ(fresh->B.Phi.size(), ma->B.Phi.size());
  EXPECT_EQ(std::memcmp(fresh->B.omega.data(), ma->B.omega.data(), sizeof(PetscReal) * ma->B.omega.size()), 0);
  EXPECT_EQ(std::memcmp(fresh->B.Phi.data(), ma->B.Phi.data(), sizeof(PetscReal) * ma->B.Phi.size()), 0);
}

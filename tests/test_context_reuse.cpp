// The integrator's per-structure context (solvers/ts_stepper.hpp): a run on a reused TS,
// layout and vectors gives every column of the results table bit for bit as a run on a
// freshly built one, whatever ran on the context before (another contact point, another
// ball, a run cut short), for explicit, IMEX, implicit and second-order types, fixed and
// adaptive; a run on another grid or with other integrator options builds its own context.
// The implicit types' beam factorizations are kept across points (a point with the same step
// keeps the nominal step's factor) and the rank-one solve agrees with the assembled LU (-pc_type lu).
// Runs at np1, and a few at np2 (MUMPS, a distributed layout).
#include "run/results_table.hpp"
#include "solvers/ts_stepper.hpp"
#include "test_helpers.hpp"

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
TEST(ContextReuse, AssembledLU) { ExpectReuseIsFresh({{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}, {"-pc_type", "lu"}}); }

// Another beam on the same grid (a sweep over the thickness): the context is reused, but not
// the factors of the first beam's Jacobian; the second beam's run is its fresh run bit for bit.
TEST(ContextReuse, ImplicitAnotherBeamOnTheSameGrid)
{
  const Opts cn   = {{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}};
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
  EXPECT_EQ(Reused(), before + 1);
  ExpectSameRow(fresh, again, "a thicker beam after the 6 mm one");
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

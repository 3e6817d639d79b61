// Time-integration convergence through the contact events (-task convergence's
// machinery): observed orders on short studies against the exact modal reference
// (linear spring, coarse grid N = 21, to the first separation), the modal reference
// against a tight-tolerance run, the order and Richardson formulas, and the
// isolation of one configuration's options from the next.
#include "studies/convergence.hpp"
#include "run/modal_reference.hpp"
#include "run/reference.hpp"
#include "test_helpers.hpp"

#include <cmath>
#include <string>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

using Scene = Scenario;

// The default beam on a coarse grid, struck at its centre, followed to the first separation.
Scene Coarse()
{
  Scene s;
  s.beam          = AluminiumBeam(1.1, 21);
  s.ball          = Superball();
  s.impact.x      = 0.55;
  s.impact.window = 0;
  return s;
}

ConvergencePlan QuietPlan()
{
  ConvergencePlan plan;
  plan.repeats = 1;
  plan.quiet   = PETSC_TRUE;
  return plan;
}

// Runs the configuration given as options text over its sequence; returns the
// observed ACOR order (least squares) and the runs.
ConvergenceOrder StudyOrder(const std::string &text, std::vector<ConvergenceRun> *runs_out = nullptr)
{
  const Scene          s    = Coarse();
  const ConvergencePlan plan = QuietPlan();
  ConvergenceConfig    cfg;
  EXPECT_EQ(ConvergenceConfigLoad(PETSC_COMM_WORLD, "", text, &cfg), 0) << text;
  ConvergenceReference ref;
  EXPECT_EQ(ConvergenceReferenceCompute(PETSC_COMM_WORLD, plan, s, &ref), 0);
  std::vector<ConvergenceRun> runs;
  EXPECT_EQ(ConvergenceRunConfig(PETSC_COMM_WORLD, plan, cfg, s, ref, &runs), 0);
  EXPECT_EQ((PetscInt)runs.size(), cfg.seq.count);
  for (auto &r : runs) {
    EXPECT_FALSE(r.failed) << text << ": level " << r.level << ": " << r.message;
    EXPECT_EQ(r.result.contacts, ref.result.contacts) << text;
  }
  if (runs_out) *runs_out = runs;
  return ConvergenceOrderOf(cfg, runs, 1e-12, &ConvergenceRun::acor_error);
}

std::string Pairwise(const ConvergenceOrder &o)
{
  std::string s;
  for (PetscReal p : o.pairwise) s += " " + std::to_string(p);
  return s;
}

} // namespace

TEST(ConvergenceFormulas, ObservedOrderOfAPowerLaw)
{
  const std::vector<PetscReal> h = {1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5};
  std::vector<PetscReal>       e;
  for (PetscReal x : h) e.push_back(3.0 * std::pow(x, 2.5));
  const ConvergenceOrder o = ConvergenceObservedOrder(h, e, 0);
  EXPECT_NEAR(o.lsq, 2.5, 1e-12);
  EXPECT_EQ(o.used, 5);
  EXPECT_TRUE(std::isnan(o.pairwise[0]));
  for (size_t k = 1; k < h.size(); ++k) EXPECT_NEAR(o.pairwise[k], 2.5, 1e-12);
  // Errors at or below the floor (round-off) are left out of the fit.
  e[4]                     = 1e-16;
  const ConvergenceOrder f = ConvergenceObservedOrder(h, e, 1e-14);
  EXPECT_EQ(f.used, 4);
  EXPECT_NEAR(f.lsq, 2.5, 1e-12);
  EXPECT_TRUE(std::isnan(f.pairwise[4]));
}

TEST(ConvergenceFormulas, RichardsonRecoversTheLimitAndTheOrder)
{
  auto      A = [](PetscReal h) { return 1.25 + 0.7 * h * h * h; };
  PetscReal p, A0;
  ASSERT_TRUE(ConvergenceRichardson(A(0.1), A(0.05), A(0.025), 2.0, &p, &A0));
  EXPECT_NEAR(p, 3.0, 1e-9);
  EXPECT_NEAR(A0, 1.25, 1e-12);
  EXPECT_FALSE(ConvergenceRichardson(1.0, 1.1, 0.9, 2.0, &p, &A0)) << "differences that do not shrink are not asymptotic";
}

// Second-order methods through the located contact events: >= 1.8.
TEST(ConvergenceOrders, SecondOrderMethods)
{
  const std::vector<std::pair<const char *, std::string>> configs = {
    {"cn", "-ts_type cn -convergence_dt 1e-4,2,4"},
    {"bdf2", "-ts_type bdf -ts_bdf_order 2 -ts_adapt_type none -convergence_dt 1e-4,2,4"},
    {"alpha2 rho 0.8", "-ts_type alpha2 -ts_alpha_radius 0.8 -convergence_dt 1e-4,2,4"},
    {"leapfrog", "-convergence_method leapfrog -convergence_dt 2e-5,2,4"},
  };
  for (auto &c : configs) {
    const ConvergenceOrder o = StudyOrder(c.second);
    EXPECT_EQ(o.used, 4) << c.first;
    EXPECT_GE(o.lsq, 1.8) << c.first << ": pairwise" << Pairwise(o);
    EXPECT_GE(o.pairwise.back(), 1.8) << c.first << ": pairwise" << Pairwise(o);
  }
}

// Higher-order methods at their order through the events (within 0.3).
TEST(ConvergenceOrders, HigherOrderMethodsAtTheirOrder)
{
  struct Expect {
    const char *name;
    std::string text;
    double      order;
  };
  const std::vector<Expect> configs = {
    {"rk4", "-ts_type rk -ts_rk_type 4 -ts_adapt_type none -convergence_dt 5e-5,2,4", 4},
    {"arkimex 3", "-ts_type arkimex -ts_arkimex_type 3 -ts_adapt_type none -convergence_dt 2e-4,2,4", 3},
    {"arkimex 4", "-ts_type arkimex -ts_arkimex_type 4 -ts_adapt_type none -convergence_dt 2e-4,2,4", 4},
    {"rosw ra34pw2", "-ts_type rosw -ts_rosw_type ra34pw2 -ts_adapt_type none -convergence_dt 2e-4,2,4", 3},
  };
  for (auto &c : configs) {
    const ConvergenceOrder o = StudyOrder(c.text);
    EXPECT_EQ(o.used, 4) << c.name;
    EXPECT_NEAR(o.lsq, c.order, 0.3) << c.name << ": pairwise" << Pairwise(o);
    EXPECT_NEAR(o.pairwise.back(), c.order, 0.3) << c.name << ": pairwise" << Pairwise(o);
  }
}

// The exact reference against Dormand-Prince 5(4) at a very tight tolerance, off-centre and
// with the default window after separation (the free flight of ball and beam included).
TEST(ModalReference, MatchesATightToleranceRun)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball();
  for (double x : {0.55, 0.9}) {
    ImpactParams ip;
    ip.x = x;
    ImpactResult modal;
    ASSERT_EQ(ModalReferenceRun(Scenario{beam, ball, ip, MonitorRequest()}, &modal), 0);
    const ImpactResult run = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "rk"}, {"-ts_rk_type", "5dp"}, {"-ts_rtol", "1e-12"}, {"-ts_atol", "1e-15"}});
    EXPECT_NEAR(modal.acor, run.acor, 1e-9) << "x = " << x;
    EXPECT_NEAR(modal.contact_time, run.contact_time, 1e-9 * run.contact_time) << "x = " << x;
    EXPECT_NEAR(modal.peak_force, run.peak_force, 1e-9 * run.peak_force) << "x = " << x;
    EXPECT_EQ(modal.contacts, run.contacts) << "x = " << x;
  }
}

// Each run gets its own options database: nothing of a configuration is left in the
// shared database, and a setting of one configuration does not reach the next.
TEST(ConvergenceOptions, ConfigurationsDoNotLeak)
{
  std::vector<ConvergenceRun> rk4, rk_default;
  StudyOrder("-ts_type rk -ts_rk_type 4 -ts_adapt_type none -convergence_dt_stable 0.9,2,1", &rk4);
  for (const char *name : {"-ts_type", "-ts_rk_type", "-ts_adapt_type", "-ts_dt", "-convergence_dt_stable"}) {
    PetscBool has;
    ASSERT_EQ(PetscOptionsHasName(NULL, NULL, name, &has), 0);
    EXPECT_FALSE(has) << name << " was left in the options database";
  }
  StudyOrder("-ts_type rk -ts_adapt_type none -convergence_dt_stable 0.9,2,1", &rk_default);
  ASSERT_EQ(rk4.size(), 1u);
  ASSERT_EQ(rk_default.size(), 1u);
  EXPECT_NEAR(rk4[0].dt / rk4[0].result.dt_stable, 0.9, 1e-9);
  EXPECT_NEAR(rk_default[0].dt / rk_default[0].result.dt_stable, 0.9, 1e-9);
  // rk4's imaginary-axis bound is 2.83, the default 3bs's 1.73: the second run did not see -ts_rk_type 4.
  EXPECT_NEAR(rk4[0].result.dt_stable / rk_default[0].result.dt_stable, 2.8284 / 1.7321, 0.01);
}

TEST(ConvergenceOptions, ATypoInAConfigurationFailsItsRunNamingTheOption)
{
  const Scene           s    = Coarse();
  const ConvergencePlan plan = QuietPlan();
  ConvergenceConfig     cfg;
  ASSERT_EQ(ConvergenceConfigLoad(PETSC_COMM_WORLD, "", "-ts_type cn -ts_theta_thetaa 0.5 -convergence_dt 1e-4,2,1", &cfg), 0);
  ConvergenceReference ref;
  ASSERT_EQ(ConvergenceReferenceCompute(PETSC_COMM_WORLD, plan, s, &ref), 0);
  std::vector<ConvergenceRun> runs;
  ASSERT_EQ(PetscPushErrorHandler(PetscReturnErrorHandler, NULL), 0);
  const PetscErrorCode ierr = ConvergenceRunConfig(PETSC_COMM_WORLD, plan, cfg, s, ref, &runs);
  ASSERT_EQ(PetscPopErrorHandler(), 0);
  ASSERT_EQ(ierr, 0) << "a failing level is recorded, not fatal";
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_TRUE(runs[0].failed);
  EXPECT_NE(runs[0].message.find("ts_theta_thetaa"), std::string::npos) << runs[0].message;
  PetscBool has;
  ASSERT_EQ(PetscOptionsHasName(NULL, NULL, "-ts_theta_thetaa", &has), 0);
  EXPECT_FALSE(has);
}

TEST(ConvergenceOptions, AConfigurationNeedsExactlyOneSequence)
{
  ConvergenceConfig cfg;
  ASSERT_EQ(PetscPushErrorHandler(PetscReturnErrorHandler, NULL), 0);
  const PetscErrorCode none = ConvergenceConfigLoad(PETSC_COMM_WORLD, "", "-ts_type cn", &cfg);
  const PetscErrorCode two  = ConvergenceConfigLoad(PETSC_COMM_WORLD, "", "-ts_type cn -convergence_dt 1e-4,2,3 -convergence_tol 1e-4,10,3", &cfg);
  const PetscErrorCode bad  = ConvergenceConfigLoad(PETSC_COMM_WORLD, "", "-ts_type cn -convergence_dt 1e-4,0.5,3", &cfg);
  ASSERT_EQ(PetscPopErrorHandler(), 0);
  EXPECT_NE(none, 0);
  EXPECT_NE(two, 0);
  EXPECT_NE(bad, 0) << "a divisor below 1 is refused";
  ASSERT_EQ(ConvergenceConfigLoad(PETSC_COMM_WORLD, "", "-ts_type rk -convergence_tol 1e-4,10,3", &cfg), 0);
  EXPECT_EQ(cfg.seq.kind, ConvergenceSequenceKind::Tolerance);
  EXPECT_NEAR(cfg.seq.value(2), 1e-6, 1e-20);
}

// The reference methods, one registry: -reference offers ts and modal, a study modal and run; the
// study's default is the first that applies (modal for the linear law, run for the hysteretic
// ball); modal says why it does not apply, naming the option.
TEST(ReferenceRegistry, MethodsChoicesAndWhenTheyApply)
{
  EXPECT_EQ(ReferenceMethodNames(false), (std::vector<std::string>{"ts", "modal"}));
  EXPECT_EQ(ReferenceMethodNames(true), (std::vector<std::string>{"modal", "run"}));
  ASSERT_NE(ReferenceMethodFind("run"), nullptr);
  EXPECT_EQ(ReferenceMethodFind("nope"), nullptr);
  Scene       lin = Coarse(), hyst = Coarse(), grip = Coarse();
  std::string why;
  hyst.ball = Superball("hysteresis");
  BeamGrip hands;
  hands.x_a = 0, hands.x_b = 0.1, hands.stiffness = 1e5;
  grip.beam = WithGrip(grip.beam, hands);
  EXPECT_STREQ(ReferenceMethodDefault(lin)->name, "modal");
  EXPECT_STREQ(ReferenceMethodDefault(hyst)->name, "run");
  EXPECT_TRUE(ReferenceMethodFind("modal")->applies(lin, &why)) << why;
  EXPECT_FALSE(ReferenceMethodFind("modal")->applies(hyst, &why));
  EXPECT_NE(why.find("-ball_law linear"), std::string::npos) << why;
  EXPECT_FALSE(ReferenceMethodFind("modal")->applies(grip, &why));
  EXPECT_NE(why.find("-grip"), std::string::npos) << why;
  for (const ReferenceMethod *m : ReferenceMethods()) EXPECT_TRUE(m->impact || m->study) << m->name;
  // -reference reads the choice from the registry; a name it does not hold is refused.
  const ReferenceMethod *m = nullptr;
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-reference", "modal"));
  EXPECT_EQ(0, ReferenceMethodFromOptions(PETSC_COMM_WORLD, &m));
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-reference", "run"));
  ASSERT_EQ(PetscPushErrorHandler(PetscReturnErrorHandler, NULL), 0);
  const PetscErrorCode bad = ReferenceMethodFromOptions(PETSC_COMM_WORLD, &m);
  ASSERT_EQ(PetscPopErrorHandler(), 0);
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-reference"));
  EXPECT_NE(bad, 0) << "run is a study's reference, not -reference's";
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-reference", "modal"));
  EXPECT_EQ(0, ReferenceMethodFromOptions(PETSC_COMM_WORLD, &m));
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-reference"));
  ASSERT_NE(m, nullptr);
  EXPECT_STREQ(m->name, "modal");
}

// The run reference estimates its own error by Richardson extrapolation: against the exact
// modal solution of the same scene, the estimate is the error it makes, and the observed order
// is the configuration's (RK4).
TEST(ReferenceRegistry, RunReferenceEstimatesItsOwnError)
{
  char path[] = "/tmp/beamimpact-reference-XXXXXX";
  int  fd     = mkstemp(path);
  ASSERT_GE(fd, 0);
  const std::string text = "-ts_type rk\n-ts_rk_type 4\n-ts_adapt_type none\n-convergence_dt 5e-5,2,3\n";
  ASSERT_EQ((ssize_t)text.size(), write(fd, text.data(), text.size()));
  close(fd);
  const Scene     s    = Coarse();
  ConvergencePlan plan = QuietPlan();
  ConvergenceReference modal, run;
  ASSERT_EQ(ConvergenceReferenceCompute(PETSC_COMM_WORLD, plan, s, &modal), 0);
  EXPECT_EQ(modal.method, "modal");
  EXPECT_EQ(modal.acor_error, 0.0) << "exact: no estimated error";
  plan.reference      = "run";
  plan.reference_file = path;
  ASSERT_EQ(ConvergenceReferenceCompute(PETSC_COMM_WORLD, plan, s, &run), 0);
  unlink(path);
  const double actual = std::abs(run.result.acor - modal.result.acor);
  PetscPrintf(PETSC_COMM_WORLD, "run reference (rk4, 3 levels): ACOR error %.3e, its Richardson estimate %.3e, observed order %.3f\n", actual, (double)run.acor_error, (double)run.observed_order);
  EXPECT_GT(actual, 1e-12) << "the configuration is coarse enough to have an error";
  EXPECT_GT(run.acor_error / actual, 0.5) << "estimate " << run.acor_error << ", actual " << actual;
  EXPECT_LT(run.acor_error / actual, 2.0) << "estimate " << run.acor_error << ", actual " << actual;
  EXPECT_NEAR(run.observed_order, 4.0, 0.3);
  EXPECT_EQ(ConvergenceReferenceLabel(plan), std::string(path));
}

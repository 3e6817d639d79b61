// -ts_type irk (PETSc's TSIRK, Gauss-Legendre) with its stage system preconditioned by the
// stage matrix's LU (solvers/irk_stage_pc.hpp):
//   * the stage matrix's entries are those of the KAIJ I_n x S + J x T (formula, a 2 x 2 case
//     written out by hand);
//   * the paper's beam converges to the exact modal reference (-reference modal) at order 4
//     (2 stages): the errors at two steps and their ratio;
//   * the swinging R161 (options/bats/r161.opts, 85 nodes, the linear 2e6 N/m baseball; it broke
//     down at every solve without the preconditioner and ended "cut off in contact") completes
//     head-on and oblique, and agrees with the modal reference;
//   * about one GMRES iteration per Newton iteration (an upper bound with margin);
//   * the same impact on one rank and on all (np2);
//   * the barrel shell (-beam_shell, the aluminium bat of options/scenes) completes and agrees
//     with cn at a small step.
#include "run/reference.hpp"
#include "run/scenario.hpp"
#include "solvers/irk_stage_pc.hpp"
#include "solvers/ts_stepper.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace beamimpact;
using beamimpact::test::LinearBallR161;
using beamimpact::test::ReadScene;

namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

Options Irk(const char *dt, const char *stages = "2")
{
  return {{"-ts_type", "irk"}, {"-ts_irk_nstages", stages}, {"-ts_adapt_type", "none"}, {"-ts_dt", dt}};
}

using test::RunWith;

// LinearBallR161 (test_helpers.hpp) with the ball at 40 m/s; to the first separation.
Scenario SwingingR161()
{
  Scenario sc   = LinearBallR161();
  sc.ball.speed = 40;
  return sc;
}

ImpactResult Reference(const Scenario &sc)
{
  const ReferenceMethod *modal = ReferenceMethodFind("modal");
  std::string            why;
  EXPECT_TRUE(modal->applies(sc, &why)) << why;
  ReferenceSolution ref;
  EXPECT_EQ(0, modal->run(PETSC_COMM_WORLD, sc, ReferenceSettings(), &ref));
  return ref.result;
}

} // namespace

// Row r s + i, column c s + j of I_n x S + J x T: J_rc T_ij + (r == c) S_ij, with the Gauss
// 2-stage S = A^-1 (dt = 1): A = [[1/4, 1/4 - sqrt3/6], [1/4 + sqrt3/6, 1/4]], det A = 1/12,
// A^-1 = [[3, 2 sqrt3 - 3], [-3 - 2 sqrt3, 3]]; T = I (null) or a full T.
TEST(IrkStageMatrix, EntriesAreTheKAIJs)
{
  const PetscReal   r3   = std::sqrt(3.0);
  const PetscScalar S[4] = {3, -3 - 2 * r3, 2 * r3 - 3, 3}; // column-major
  EXPECT_EQ(IrkStageEntry(2, S, nullptr, 0, 0, 7.0, true), 10.0);
  EXPECT_EQ(IrkStageEntry(2, S, nullptr, 1, 0, 7.0, true), -3 - 2 * r3); // T = I: J only on i == j
  EXPECT_EQ(IrkStageEntry(2, S, nullptr, 0, 1, 7.0, true), 2 * r3 - 3);
  EXPECT_EQ(IrkStageEntry(2, S, nullptr, 1, 0, 7.0, false), 0.0);      // off the block diagonal: J T only
  EXPECT_EQ(IrkStageEntry(2, S, nullptr, 1, 1, 7.0, false), 7.0);
  const PetscScalar T[4] = {1, 2, 3, 4}; // [[1, 3], [2, 4]]
  EXPECT_EQ(IrkStageEntry(2, S, T, 0, 1, 5.0, false), 15.0);
  EXPECT_EQ(IrkStageEntry(2, S, T, 1, 0, 5.0, true), 10.0 - 3 - 2 * r3);
}

// The paper's beam (1.1 m aluminium, N = 41, free) and the linear superball at 1 m/s, 0.9 m:
// order 4 against the exact modal reference (measured acor errors -3.72e-8, -2.41e-9,
// -1.51e-10, -9.49e-12 at 4e-5, 2e-5, 1e-5, 5e-6 s: ratios 15.5, 15.9, 15.9), one GMRES
// iteration per Newton iteration (the stage LU is exact).
TEST(IrkPaperBeam, OrderFourAgainstTheModalReference)
{
  Scenario sc;
  sc.beam              = test::AluminiumBeam(1.1, 41);
  sc.ball              = test::Superball();
  sc.impact.x          = 0.9;
  sc.impact.window     = 0;
  const ImpactResult e = Reference(sc);
  const PetscInt     f0 = IrkStagePCFactorizations();
  const ImpactResult c = RunWith(PETSC_COMM_WORLD, sc, Irk("2e-5")), f = RunWith(PETSC_COMM_WORLD, sc, Irk("1e-5"));
  EXPECT_GT(IrkStagePCFactorizations(), f0);
  for (const ImpactResult *r : {&c, &f}) {
    EXPECT_FALSE(r->ended_in_contact);
    EXPECT_EQ(r->failed_solves, 0);
    EXPECT_GE(r->nonlinear_its, r->steps);
    EXPECT_LE(r->linear_its, r->nonlinear_its + r->nonlinear_its / 2) << "GMRES iterations per Newton iteration";
  }
  const PetscReal ec = c.acor - e.acor, ef = f.acor - e.acor;
  EXPECT_LT(std::abs(ef), 1e-9) << "irk at 1e-5 s against the reference";
  EXPECT_GT(ec / ef, 13.0) << "order 4: " << ec << " then " << ef;
  EXPECT_LT(ec / ef, 19.0) << "order 4: " << ec << " then " << ef;
}

// The swinging bat head-on: irk completes (it used to end cut off in contact, every GMRES solve
// broken down at 60 iterations), about one GMRES iteration per Newton iteration, and the
// batted-ball speed agrees with the exact one. Measured errors 7.29e-5, -1.93e-5, -9.74e-7,
// 7.6e-9, 4.05e-8, -4.2e-10 m/s at 3.2e-5 ... 1e-6 s: no clean order on this stiff grid (its
// highest modes have omega dt >> 1, where a Gauss method's stage order 2 governs), so a bound.
TEST(IrkSwingingBat, HeadOnAgreesWithTheModalReference)
{
  const Scenario     sc = SwingingR161();
  const ImpactResult e  = Reference(sc);
  const ImpactResult c = RunWith(PETSC_COMM_WORLD, sc, Irk("4e-6")), f = RunWith(PETSC_COMM_WORLD, sc, Irk("2e-6"));
  for (const ImpactResult *r : {&c, &f}) {
    EXPECT_FALSE(r->ended_in_contact);
    EXPECT_EQ(r->contacts, 1);
    EXPECT_EQ(r->failed_solves, 0);
    EXPECT_GE(r->nonlinear_its, r->steps);
    EXPECT_LE(r->linear_its, r->nonlinear_its + r->nonlinear_its / 2) << "GMRES iterations per Newton iteration (measured 1.09 and 1.05)";
    EXPECT_LT(std::abs(r->bbs - e.bbs), 2e-9 * e.bbs) << "irk at " << r->dt_nominal << " s against the reference";
    EXPECT_NEAR(r->contact_time, e.contact_time, 1e-6 * e.contact_time);
  }
}

// Oblique (an undercut of 1.5 cm, 150 rad/s of backspin, mu 0.5, e_T 0.3, the second plane
// flexible): irk completes, and its normal outputs agree with the reference.
TEST(IrkSwingingBat, ObliqueCompletesAndAgrees)
{
  Scenario sc             = SwingingR161();
  sc.impact.offset        = 0.015;
  sc.ball.spin            = 150;
  sc.ball.friction        = 0.5;
  sc.ball.tangential_cor  = 0.3;
  const ImpactResult e    = Reference(sc);
  const ImpactResult r    = RunWith(PETSC_COMM_WORLD, sc, Irk("2e-6"));
  EXPECT_FALSE(r.ended_in_contact);
  EXPECT_LE(r.linear_its, 2 * r.nonlinear_its);
  EXPECT_NEAR(r.bbs, e.bbs, 1e-6 * e.bbs);
  EXPECT_NEAR(test::Col(r, "exit_speed"), test::Col(e, "exit_speed"), 1e-4 * test::Col(e, "exit_speed"));
  EXPECT_NEAR(test::Col(r, "spin"), test::Col(e, "spin"), 1e-3 * std::abs(test::Col(e, "spin")));
}

// The same impact on one rank and on all (the stage LU by MUMPS on more than one).
TEST(IrkParallel, SameOnOneAndAllRanks)
{
  const Scenario     sc   = SwingingR161();
  const ImpactResult all  = RunWith(PETSC_COMM_WORLD, sc, Irk("4e-6"));
  const ImpactResult self = RunWith(PETSC_COMM_SELF, sc, Irk("4e-6"));
  EXPECT_FALSE(all.ended_in_contact);
  EXPECT_NEAR(all.bbs, self.bbs, 1e-10 * self.bbs);
  EXPECT_NEAR(all.contact_time, self.contact_time, 1e-10 * self.contact_time);
  EXPECT_NEAR(all.peak_force, self.peak_force, 1e-9 * self.peak_force);
  EXPECT_EQ(all.steps, self.steps);
  EXPECT_LE(all.linear_its, 2 * all.nonlinear_its);
}

// A reused context (a sweep's next point on the same grid and options): the new point's J in
// TSIRK's stage matrix (IrkStageNewJacobian; TSSetIJacobian had handed the SNES J itself and
// the next step failed), so the point runs as on a fresh context, bit for bit (one rank: on two,
// MUMPS's solves differ in the last bits between two fresh runs already).
TEST(IrkSwingingBat, ReusedContextIsAFreshOne)
{
  const Scenario a = SwingingR161();
  Scenario       b = SwingingR161();
  b.impact.x       = 0.6;
  b.ball.speed     = 30;
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  const ImpactResult fresh = RunWith(PETSC_COMM_WORLD, b, Irk("4e-6"));
  ASSERT_EQ(TSStepperContextCacheClear(), 0);
  (void)RunWith(PETSC_COMM_WORLD, a, Irk("4e-6"));
  PetscInt built0, reused0, built1, reused1;
  TSStepperContextCounts(&built0, &reused0);
  const ImpactResult again = RunWith(PETSC_COMM_WORLD, b, Irk("4e-6"));
  TSStepperContextCounts(&built1, &reused1);
  EXPECT_EQ(reused1, reused0 + 1) << "the second point did not reuse the first one's context";
  EXPECT_EQ(again.bbs, fresh.bbs);
  EXPECT_EQ(again.contact_time, fresh.contact_time);
  EXPECT_EQ(again.peak_force, fresh.peak_force);
  EXPECT_EQ(again.steps, fresh.steps);
  EXPECT_EQ(again.nonlinear_its, fresh.nonlinear_its);
  EXPECT_EQ(again.linear_its, fresh.linear_its);
}

// The barrel wall as a shell (-beam_shell; the stability matrix's shell-thin row): the aluminium
// bat, Timoshenko, the linear superball at 1 m/s, 0.66 m. Unpreconditioned GMRES broke down at
// every solve from t = 3.66 ms of its 4.40 ms contact; with the stage LU irk completes (7 LU
// factorizations in all), with one or two GMRES iterations per Newton iteration, and agrees
// with cn at a quarter of its step (its acor with the modal reference, the wall's modes
// included, to 5.5e-10: measured, not run here, the reference takes a minute).
TEST(IrkShell, CompletesAndAgreesWithCrankNicolson)
{
  Scenario sc;
  ReadScene({"options/bats/aluminium-bat.opts"}, {{"-beam_theory", "timoshenko"}, {"-beam_shell", "true"}}, &sc.beam, &sc.ball);
  sc.ball              = test::Superball();
  sc.impact.x          = 0.66;
  sc.impact.window     = 0;
  const PetscInt     f0 = IrkStagePCFactorizations();
  const ImpactResult r  = RunWith(PETSC_COMM_WORLD, sc, Irk("1e-5"));
  const PetscInt     nf = IrkStagePCFactorizations() - f0;
  const ImpactResult cn = RunWith(PETSC_COMM_WORLD, sc, {{"-ts_type", "cn"}, {"-ts_dt", "2.5e-6"}});
  std::printf("shell: irk acor %.12f cn %.12f diff %.3e, contact time %.9e cn %.9e; irk %d steps, %d Newton, %d GMRES iterations, %d LU\n", (double)r.acor, (double)cn.acor, (double)(r.acor - cn.acor),
              (double)r.contact_time, (double)cn.contact_time, (int)r.steps, (int)r.nonlinear_its, (int)r.linear_its, (int)nf);
  EXPECT_FALSE(r.ended_in_contact);
  EXPECT_EQ(r.failed_solves, 0);
  EXPECT_LE(r.linear_its, 2 * r.nonlinear_its) << "GMRES iterations per Newton iteration (measured 1.49)";
  EXPECT_LE(nf, 20) << "the stage matrix refactored only when the step or the contact's phase changes";
  EXPECT_NEAR(r.acor, cn.acor, 5e-8); // measured 5.5e-9 (cn's own error)
  EXPECT_NEAR(r.contact_time, cn.contact_time, 1e-6 * cn.contact_time);
}

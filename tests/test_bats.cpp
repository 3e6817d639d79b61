// Real bats in play: the R161 wood bat (options/bats/r161.opts) struck at 70 cm by the
// baseball preset (options/balls/baseball.opts) at 40 m/s, Euler-Bernoulli and Timoshenko:
// invariants, ranks, integrators, and the exact modal reference.
#include "io/beam_options.hpp"
#include "io/ball_options.hpp"
#include "run/modal_reference.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace beamimpact;
using beamimpact::test::RunImpact;

namespace {

// Reads beam and ball from options files (as a user's command line would) in a private
// options database, from the repository root (the files' relative paths start there).
void ReadScene(const std::vector<std::string> &files, const std::vector<std::pair<std::string, std::string>> &extra, BeamParams *beam, BallParams *ball)
{
  PetscOptions o;
  char         cwd[4096];
  ASSERT_NE(nullptr, getcwd(cwd, sizeof cwd));
  ASSERT_EQ(0, chdir(BEAMIMPACT_SOURCE_DIR));
  ASSERT_EQ(0, PetscOptionsCreate(&o));
  for (const std::string &f : files) ASSERT_EQ(0, PetscOptionsInsertFile(PETSC_COMM_WORLD, o, f.c_str(), PETSC_TRUE));
  for (auto &kv : extra) ASSERT_EQ(0, PetscOptionsSetValue(o, kv.first.c_str(), kv.second.c_str()));
  ASSERT_EQ(0, PetscOptionsPush(o));
  EXPECT_EQ(0, BeamParamsFromOptions(PETSC_COMM_WORLD, beam));
  EXPECT_EQ(0, BallParamsFromOptions(PETSC_COMM_WORLD, ball));
  ASSERT_EQ(0, PetscOptionsPop());
  ASSERT_EQ(0, PetscOptionsDestroy(&o));
  ASSERT_EQ(0, chdir(cwd));
}

struct Bat {
  BeamParams   beam;
  BallParams   ball;
  ImpactParams ip;
};

Bat R161Baseball(const char *theory, PetscInt nodes = 85)
{
  Bat b;
  ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", theory}, {"-beam_nodes", std::to_string(nodes)}}, &b.beam, &b.ball);
  b.ip.x      = 0.7;
  b.ip.window = 0; // to the first separation
  return b;
}

const std::vector<std::pair<std::string, std::string>> kRK4 = {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-7"}};

} // namespace

// The bat is free at both ends and the ball's force is internal: linear and angular momentum
// (the latter with the sections' spin for Timoshenko) are conserved to round-off.
TEST(BatInPlay, MomentumConservedToRoundOff)
{
  for (const char *theory : {"euler", "timoshenko"}) {
    const Bat          b = R161Baseball(theory);
    const ImpactResult r = RunImpact(PETSC_COMM_WORLD, b.beam, b.ball, b.ip, kRK4);
    EXPECT_EQ(1, r.contacts) << theory;
    EXPECT_LT(std::abs(r.linear_momentum_error), 1e-12) << theory;
    EXPECT_LT(std::abs(r.angular_momentum_error), 1e-12) << theory;
    EXPECT_LT(std::abs(r.energy_error), 1e-8) << theory;                     // rk4 at 1/3500 of the contact
    EXPECT_GT(r.acor, 0.15) << theory;                                         // a wood bat at rest, 70 cm: e_A ~ 0.2
    EXPECT_LT(r.acor, 0.25) << theory;
  }
}

// The same impact on all ranks and on one: the DMDA distribution changes nothing.
TEST(BatInPlay, SameACOROnOneAndAllRanks)
{
  for (const char *theory : {"euler", "timoshenko"}) {
    const Bat          b    = R161Baseball(theory);
    const ImpactResult all  = RunImpact(PETSC_COMM_WORLD, b.beam, b.ball, b.ip, kRK4);
    const ImpactResult self = RunImpact(PETSC_COMM_SELF, b.beam, b.ball, b.ip, kRK4);
    EXPECT_NEAR(all.acor, self.acor, 1e-12) << theory;
    EXPECT_NEAR(all.contact_time, self.contact_time, 1e-12 * self.contact_time) << theory;
    EXPECT_EQ(all.steps, self.steps) << theory;
  }
}

// Integrators of different families and orders agree to their accuracy; the Timoshenko bat
// is a different beam (shear and rotary inertia), a few per mil apart at 70 cm.
TEST(BatInPlay, IntegratorsAgree)
{
  std::vector<PetscReal> acor_theory;
  for (const char *theory : {"euler", "timoshenko"}) {
    const Bat          b  = R161Baseball(theory);
    const ImpactResult rk = RunImpact(PETSC_COMM_WORLD, b.beam, b.ball, b.ip, kRK4);
    const ImpactResult cn = RunImpact(PETSC_COMM_WORLD, b.beam, b.ball, b.ip, {{"-ts_type", "cn"}, {"-ts_dt", "1e-7"}});
    const ImpactResult a2 = RunImpact(PETSC_COMM_WORLD, b.beam, b.ball, b.ip, {{"-ts_type", "alpha2"}, {"-ts_dt", "1e-7"}});
    EXPECT_NEAR(rk.acor, cn.acor, 2e-5) << theory;
    EXPECT_NEAR(rk.acor, a2.acor, 2e-5) << theory;
    EXPECT_NEAR(rk.contact_time, cn.contact_time, 1e-4 * rk.contact_time) << theory;
    acor_theory.push_back(rk.acor);
  }
  EXPECT_GT(std::abs(acor_theory[0] - acor_theory[1]), 1e-3);
  EXPECT_LT(std::abs(acor_theory[0] - acor_theory[1]), 2e-2);
}

// A linear ball on the Timoshenko bat: the exact modal solution (no time step) and RK4 agree
// to RK4's accuracy, through both separation and the first contact's peak.
TEST(BatInPlay, TimoshenkoModalReference)
{
  Bat b;
  ReadScene({"options/bats/r161.opts", "options/base/superball-linear.opts"}, {{"-beam_theory", "timoshenko"}, {"-beam_nodes", "85"}}, &b.beam, &b.ball);
  b.ip.x      = 0.7;
  b.ip.window = 0;
  ImpactResult exact;
  ASSERT_EQ(0, ModalReferenceRun(Scenario{b.beam, b.ball, b.ip, MonitorRequest()}, &exact));
  const ImpactResult rk = RunImpact(PETSC_COMM_WORLD, b.beam, b.ball, b.ip, {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-6"}});
  EXPECT_NEAR(exact.acor, rk.acor, 1e-9);
  EXPECT_NEAR(exact.contact_time, rk.contact_time, 1e-7 * exact.contact_time);
  EXPECT_NEAR(exact.peak_force, rk.peak_force, 1e-7 * exact.peak_force);
}

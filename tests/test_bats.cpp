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

using beamimpact::test::ReadScene;

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

// ---------------------------------------------------------------- the bat in play

namespace {

Scenario Swinging(const Bat &b, PetscReal V_cm, PetscReal Omega)
{
  Scenario sc(b.beam, b.ball, b.ip);
  sc.swing.bat_speed            = V_cm;
  sc.swing.bat_angular_velocity = Omega;
  return sc;
}

ImpactResult RunScenario(MPI_Comm comm, const Scenario &sc, const std::vector<std::pair<std::string, std::string>> &ts)
{
  for (auto &kv : ts) EXPECT_EQ(0, PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()));
  ImpactResult r;
  EXPECT_EQ(0, ImpactRun(comm, sc, &r));
  for (auto &kv : ts) EXPECT_EQ(0, PetscOptionsClearValue(NULL, kv.first.c_str()));
  return r;
}

} // namespace

// A rigid motion is free (K annihilates it), so a swinging free bat gives BBS = e_A v_ball +
// (1 + e_A) V(x), e_A the ACOR of the bat at rest hit at v_ball + V(x): the swinging run
// integrates its own initial state, the identity checks it. Nathan's game case on the R161
// (both theories, the baseball preset with its e(v) table) and the paper's beam with the
// linear superball; to 1e-6 relative at tight settings.
TEST(BatInPlay, SwingingBatIdentity)
{
  struct Case {
    const char *what;
    Bat         bat;
    PetscReal   V_cm, Omega;
  };
  Bat paper;
  ReadScene({"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, {{"-beam_length", "1.1"}}, &paper.beam, &paper.ball);
  paper.ip.x = 0.9, paper.ip.window = 0;
  const Case cases[] = {{"R161 Euler-Bernoulli", R161Baseball("euler"), 24, 51}, {"R161 Timoshenko", R161Baseball("timoshenko"), 24, 51}, {"paper beam", paper, 0.5, 1.5}};
  for (const Case &c : cases) {
    const BeamRigidBody body = BeamRigidBodyOf(c.bat.beam);
    const Scenario      sw   = Swinging(c.bat, c.V_cm, c.Omega);
    const PetscReal     V_x  = c.V_cm + c.Omega * (c.bat.ip.x - body.x_cm);
    Bat                 rest = c.bat;
    rest.ball.speed          = c.bat.ball.speed + V_x;
    const auto         ts    = std::vector<std::pair<std::string, std::string>>{{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "5e-8"}};
    const ImpactResult s     = RunScenario(PETSC_COMM_WORLD, sw, ts);
    const ImpactResult r     = RunScenario(PETSC_COMM_WORLD, Scenario(rest.beam, rest.ball, rest.ip), ts);
    const PetscReal    bbs   = r.acor * c.bat.ball.speed + (1 + r.acor) * V_x;
    EXPECT_NEAR(bbs, s.bbs, 1e-6 * std::abs(bbs)) << c.what;
    EXPECT_NEAR(r.acor, s.collision_efficiency, 1e-6) << c.what;
    EXPECT_EQ(r.contacts, s.contacts) << c.what;
    EXPECT_NEAR(r.contact_time, s.contact_time, 1e-6 * r.contact_time) << c.what;
    EXPECT_LT(std::abs(s.linear_momentum_error), 1e-11) << c.what; // the swinging bat's momentum is conserved too
    EXPECT_LT(std::abs(s.angular_momentum_error), 1e-11) << c.what;
  }
}

// The exact modal reference takes the swinging state too: the identity to round-off.
TEST(BatInPlay, SwingingBatModalReference)
{
  Bat paper;
  ReadScene({"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, {{"-beam_length", "1.1"}}, &paper.beam, &paper.ball);
  paper.ip.x = 0.9, paper.ip.window = 0;
  const Scenario sw  = Swinging(paper, 0.5, 1.5);
  const PetscReal V_x = 0.5 + 1.5 * (0.9 - 0.55);
  Bat rest = paper;
  rest.ball.speed += V_x;
  ImpactResult s, r;
  ASSERT_EQ(0, ModalReferenceRun(sw, &s));
  ASSERT_EQ(0, ModalReferenceRun(Scenario(rest.beam, rest.ball, rest.ip), &r));
  EXPECT_NEAR(r.acor * 1.0 + (1 + r.acor) * V_x, s.bbs, 1e-10);
  EXPECT_NEAR(r.acor, s.collision_efficiency, 1e-10);
  EXPECT_LT(std::abs(s.energy_error), 1e-10);
}

// A very stiff pivoted bat is the rigid pivoted body: e_A = (e - r)/(1 + r), BBCOR = e, with
// r = m_b (x - x_p)^2 / I_p (a ball of wall COR e = 0.5 and the linear spring, e = 1).
TEST(BatInPlay, StiffPivotedBatIsTheRigidRig)
{
  BeamParams beam = test::WallBeam(1e9, 1.0, 85);
  beam.length = 0.84, beam.left = beam.right = Support::Free;
  beam.has_pivot = true, beam.pivot_x = 0.15;
  beam.pivot_x   = BeamPivotNode(beam) * beam.length / (beam.nodes - 1);
  ImpactParams ip;
  ip.x = 0.7, ip.window = 0;
  for (const double e : {0.5, 1.0}) {
    BallParams ball;
    ball.mass = 0.145, ball.speed = 10;
    BallParamsUseLaw(&ball, ContactLawFind(e < 1 ? "hysteresis" : "linear")); // m = 1
    BallValueSet(&ball, e < 1 ? "k1" : "k", 1e6);
    if (e < 1) BallValueSet(&ball, "n", BallExponentFromCor(1, e));
    const PivotRig     rig = PivotRigOf(BeamRigidBodyOf(beam), beam.pivot_x, ball.mass, ip.x);
    const ImpactResult res = RunScenario(PETSC_COMM_WORLD, Scenario(beam, ball, ip), {{"-ts_type", "cn"}, {"-ts_dt", "2e-6"}});
    EXPECT_NEAR((e - rig.recoil_factor) / (1 + rig.recoil_factor), res.collision_efficiency, 2e-4) << "e = " << e;
    EXPECT_NEAR(e, res.bbcor, 3e-4) << "e = " << e;
    EXPECT_NEAR(rig.recoil_factor, res.recoil_factor, 1e-15);
    if (e == 1.0) { // the exact reference on the same rig
      ImpactResult exact;
      ASSERT_EQ(0, ModalReferenceRun(Scenario(beam, ball, ip), &exact));
      EXPECT_NEAR(1.0, exact.bbcor, 3e-4);
    }
  }
}

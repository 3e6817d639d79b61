// The hands (-grip): a spring-damper per metre of handle tying the bat to the swing's rigid
// frame. (a) a uniform grip over a uniform beam: both rigid modes become mass-spring modes at
// sqrt(k'/mu) = sqrt(k L / M); (b) the energy balance closes with the grip's stored energy, its
// damper (in D) and the hands' work, at rest and swinging, TS and leapfrog; (c) the swinging-bat
// identity holds with e_A of the gripped bat at rest (the grip ties to the moving frame) and
// not with e_A of the free bat; (d) a grip of zero strength changes nothing.
#include "io/ball_options.hpp"
#include "io/beam_options.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/modes.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace beamimpact;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

// The paper's beam (1.1 m aluminium, free-free) and the linear superball at 1 m/s, read from the
// options files as a command line would, plus `extra`.
void Paper(const Opts &extra, BeamParams *beam, BallParams *ball)
{
  Opts all{{"-beam_length", "1.1"}};
  all.insert(all.end(), extra.begin(), extra.end());
  test::ReadScene({"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, all, beam, ball);
}

ImpactResult RunSc(const Scenario &sc, const Opts &ts) { return test::RunWith(PETSC_COMM_WORLD, sc, ts); }

const Opts    kRK4  = {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-6"}};
const Opts    kGrip = {{"-grip", "0,0.15"}, {"-grip_stiffness", "1e5"}, {"-grip_damping", "100"}};

} // namespace

// (a) k' and mu uniform over the whole beam: K_grip = k'/mu M, so the two rigid modes are
// mass-spring modes at sqrt(k'/mu) = sqrt(k L / M) (checked on K itself: the modes solver refuses a grip).
TEST(Grip, UniformGripRigidModesAreMassSpring)
{
  BeamParams beam;
  BallParams ball;
  Paper({{"-grip", "0,1.1"}, {"-grip_stiffness", "2e4"}}, &beam, &ball);
  BeamSystem  sys, free_sys;
  std::string why;
  ASSERT_TRUE(BeamSystemBuild(beam, &sys, &why));
  BeamParams nogrip = beam;
  nogrip.grip       = BeamGrip();
  ASSERT_TRUE(BeamSystemBuild(nogrip, &free_sys, &why));
  // the rigid motions are exact eigenvectors of the gripped K: K r = (k'/mu) M r
  const PetscReal w0 = std::sqrt(beam.grip.stiffness * beam.length / (beam.mu * beam.length));
  for (const auto &r : {BeamSystemRigidVelocity(sys, 1.0, 0.0), BeamSystemRigidVelocity(sys, 0.0, 1.0)}) {
    std::vector<PetscReal> f(sys.ndof);
    BeamSystemStiffnessApply(sys, r.data(), sys.fields, 0, sys.ndof, f.data(), sys.fields);
    for (PetscInt d = 0; d < sys.ndof; ++d) EXPECT_NEAR(f[d], w0 * w0 * sys.mass[d] * r[d], 1e-9 * w0 * w0 * sys.mass[d]);
  }
  ModesResult m;
  EXPECT_NE(0, BeamModesCompute(PETSC_COMM_SELF, sys, 4, &m)) << "the modes solver refuses a grip (not yet supported)";
}

// (b) KE + U + W_ball + D + U_grip - W_hands = const, to the integrator's accuracy, at rest and
// swinging, with Rayleigh damping too, for the TS (rk4, cn, alpha2) and the leapfrog.
TEST(Grip, EnergyBalanceWithGripDamping)
{
  BeamParams beam;
  BallParams ball;
  Opts       o = kGrip;
  o.push_back({"-grip_mass", "0.2"});
  o.push_back({"-beam_damping_stiffness", "1e-6"});
  Paper(o, &beam, &ball);
  ImpactParams ip;
  ip.x      = 0.9;
  ip.window = 5e-3;
  for (bool swing : {false, true}) {
    Scenario sc(beam, ball, ip);
    if (swing) sc.swing.bat_speed = 0.5, sc.swing.bat_angular_velocity = 1.5;
    const ImpactResult r = RunSc(sc, kRK4);
    EXPECT_LT(std::abs(r.energy_error), 1e-9) << "rk4, swing " << swing;
    EXPECT_GT(r.beam_dissipated_end, 0);
    EXPECT_GT(r.grip_force_peak, 0);
    if (swing) EXPECT_NE(r.hand_work_end, 0.0);
    else EXPECT_EQ(r.hand_work_end, 0.0);
    const ImpactResult c = RunSc(sc, {{"-ts_type", "cn"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}});
    EXPECT_LT(std::abs(c.energy_error), 1e-5) << "cn, swing " << swing;
    const ImpactResult a = RunSc(sc, {{"-ts_type", "alpha2"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}});
    EXPECT_LT(std::abs(a.energy_error), 1e-5) << "alpha2, swing " << swing;
    LeapfrogParams lp;
    lp.dt = 2e-6;
    ImpactResult l;
    ASSERT_EQ(0, LeapfrogRun(sc, lp, &l));
    EXPECT_LT(std::abs(l.energy_error), 1e-4) << "leapfrog, swing " << swing;
    EXPECT_NEAR(l.bbs, r.bbs, 1e-4 * std::abs(r.bbs)) << "leapfrog against rk4, swing " << swing;
  }
}

// (c) In the swing's frame the gripped problem is the gripped bat at rest hit at v + V(x): the
// identity BBS = e_A v + (1 + e_A) V(x) holds with e_A of the gripped bat at rest (a check of
// the frame term), not with e_A of the free bat. The slow superball (contact ~4 ms) on the
// paper's beam, a hand-held grip of 15 cm at one end.
TEST(Grip, SwingingIdentityNeedsTheGrippedBatsACOR)
{
  BeamParams gripped, free_beam;
  BallParams ball;
  Paper({{"-grip", "0,0.15"}, {"-grip_stiffness", "1e6"}, {"-grip_damping", "500"}}, &gripped, &ball);
  free_beam      = gripped;
  free_beam.grip = BeamGrip();
  ImpactParams ip;
  ip.x                = 0.9;
  ip.window           = 0; // to the first separation
  const PetscReal V_x = 0.5 + 1.5 * (0.9 - 0.55);
  Scenario        sw(gripped, ball, ip);
  sw.swing.bat_speed = 0.5, sw.swing.bat_angular_velocity = 1.5;
  BallParams fast = ball;
  fast.speed += V_x;
  const ImpactResult s  = RunSc(sw, kRK4);
  const ImpactResult rg = RunSc(Scenario(gripped, fast, ip), kRK4);
  const ImpactResult rf = RunSc(Scenario(free_beam, fast, ip), kRK4);
  const PetscReal    bbs_g = rg.acor * ball.speed + (1 + rg.acor) * V_x, bbs_f = rf.acor * ball.speed + (1 + rf.acor) * V_x;
  EXPECT_NEAR(bbs_g, s.bbs, 1e-9 * s.bbs);
  EXPECT_GT(std::abs(bbs_f - s.bbs), 1e-6 * s.bbs) << "the free bat's e_A does not describe the gripped swing";
  PetscPrintf(PETSC_COMM_WORLD, "gripped swing: bbs %.9g; identity with the gripped e_A %.9g (diff %.2e), with the free e_A %.9g (diff %.2e)\n", (double)s.bbs, (double)bbs_g,
              (double)(bbs_g - s.bbs), (double)bbs_f, (double)(bbs_f - s.bbs));
}

// (d) A grip of zero stiffness, damping and mass is no grip: the same bits.
TEST(Grip, ZeroGripChangesNothing)
{
  BeamParams beam, none;
  BallParams ball;
  Paper({{"-grip", "0,0.15"}}, &beam, &ball);
  none      = beam;
  none.grip = BeamGrip();
  ImpactParams ip;
  ip.x                 = 0.9;
  ip.window            = 0;
  const ImpactResult a = RunSc(Scenario(beam, ball, ip), kRK4), b = RunSc(Scenario(none, ball, ip), kRK4);
  EXPECT_EQ(a.acor, b.acor);
  EXPECT_EQ(a.contact_time, b.contact_time);
  EXPECT_EQ(a.peak_force, b.peak_force);
}

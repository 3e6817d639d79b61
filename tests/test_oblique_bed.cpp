// An oblique impact on a racket's string bed (run/oblique.hpp, docs/model.md section 13 "On the
// string bed"; MODEL.md section 17): a tennis ball (options/balls/tennis-ball-fast.opts) at 25 m/s
// on the Pure Drive's bed in a held frame (the head clamped, as in Cross's and Lindsey's
// experiments), 31 nodes along the head, -ts_type modal.
//   * the in-plane model alone (model/oblique.hpp, BedInPlaneOf; model/string_bed.hpp): the two
//     points' modes against the two-body oscillator (omega^2 = k (1/m_s + 1/M_t)), their
//     completeness at the strings (sum gamma^2 = 1/m_s), the slide's static compliance 1/k; the
//     default stiffness n T (1/a + 1/b) on a rectangle;
//   * frictionless: no spin, the tangential speed kept, the normal run the head-on run at
//     v cos(angle) bit for bit, the rebound angle atan(tan(angle) / e_n);
//   * the mains locked (-impact_tangential_plane rigid) against a very stiff in-plane bed;
//   * the rolling limit of a gripping ball on the locked bed: omega2 R = v_t2 = v_t1 / (1 + alpha);
//   * the ball's angular momentum about the contact point kept whatever friction did;
//   * snapback: the sliding mains give back what they stored, and the ball leaves spinning faster
//     than rolling, and faster than off the locked bed (Cross; Lindsey's lubricated strings);
//   * the brush (-bat_speed_face): the angle in the face's frame (Galilean along the face);
//   * the refusals: -impact_angle off a bed, -impact_offset on one.
#include "model/oblique.hpp"
#include "model/string_bed.hpp"
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include "system/parts/bed.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace beamimpact;
using beamimpact::test::ReadScene;
using beamimpact::test::RunWith;

namespace {

using Extra = std::vector<std::pair<std::string, std::string>>;

const Extra kModal = {{"-ts_type", "modal"}};

// The Pure Drive's bed in a held frame, struck at the head's centre at 25 m/s and `angle` deg.
Scenario HeldBed(PetscReal angle, const Extra &extra = {})
{
  Scenario sc;
  Extra    e = {{"-strings_frame", "held"}, {"-beam_torsion", "0"}, {"-strings_nodes", "31"}, {"-strings_patch_radius", "0.03"}, {"-ball_speed", "25"}};
  e.insert(e.end(), extra.begin(), extra.end());
  ReadScene({"options/bats/racket-pure-drive.opts", "options/balls/tennis-ball-fast.opts"}, e, &sc.beam, &sc.ball);
  sc.impact.x      = 0.1675; // the head's centre (a held frame: from the head's end)
  sc.impact.angle  = angle;
  sc.impact.window = 0;
  return sc;
}

// The ball's velocity along t (the face's z) after the impact, from the exit columns.
PetscReal TangentialExit(const ImpactResult &r) { return test::Col(r, "exit_speed") * std::sin(test::Col(r, "launch_angle") * M_PI / 180); }
PetscReal NormalExit(const ImpactResult &r) { return test::Col(r, "exit_speed") * std::cos(test::Col(r, "launch_angle") * M_PI / 180); }

} // namespace

// The frame of mass M_t and the strings m_s on a spring k: the two-body oscillator's frequency,
// the modes' completeness at the strings (Phi Phi^T = M^-1: sum gamma_k^2 = 1/m_s) and the
// slide's static compliance (its share squared over omega^2 = 1/k); a held frame, one mode.
TEST(BedInPlane, ModesOfTheFrameAndTheStrings)
{
  BedInPlaneModel b;
  b.frame_mass = 0.35, b.strings_mass = 4e-4, b.stiffness = 1.2e4;
  PetscInt        rigid = -1;
  TangentialPlane p     = BedInPlaneOf(b, &rigid);
  ASSERT_EQ(1, rigid);
  ASSERT_EQ(2u, p.omega.size());
  EXPECT_EQ(0.0, p.omega[0]);
  EXPECT_NEAR(p.omega[1], std::sqrt(b.stiffness * (b.frame_mass + b.strings_mass) / (b.frame_mass * b.strings_mass)), 1e-12 * p.omega[1]);
  EXPECT_NEAR(p.gamma[0] * p.gamma[0] + p.gamma[1] * p.gamma[1], 1 / b.strings_mass, 1e-12 / b.strings_mass);
  p.z[1] = 1;
  const PetscReal s = BedInPlaneSlide(b, p); // the slide per unit z_1: its compliance s^2 / omega^2
  EXPECT_NEAR(s * s / (p.omega[1] * p.omega[1]), 1 / b.stiffness, 1e-12 / b.stiffness);
  b.frame_mass = PETSC_INFINITY;
  p            = BedInPlaneOf(b, &rigid);
  ASSERT_EQ(0, rigid);
  ASSERT_EQ(1u, p.omega.size());
  EXPECT_NEAR(p.omega[0], std::sqrt(b.stiffness / b.strings_mass), 1e-12 * p.omega[0]);
  EXPECT_NEAR(p.gamma[0] * p.gamma[0], 1 / b.strings_mass, 1e-12 / b.strings_mass);
}

// A rectangular head 0.30 x 0.20 m struck 5 cm along from its centre: the struck main runs 0.20 m
// and 0.10 m to its ends; mains 15 mm apart under a patch of 3 cm: 4 of them.
TEST(BedInPlane, DefaultStiffnessFromTheTension)
{
  StringBedParams p;
  p.shape = HeadShape::Rectangle, p.head_length = 0.30, p.head_width = 0.20, p.tension = 250, p.spacing = 0.015, p.linear_density = 1.5e-3;
  const StringBedInPlane s = StringBedInPlaneOf(p, 0.05, 0.03, 0.03);
  EXPECT_NEAR(4.0, s.mains, 1e-12);
  EXPECT_NEAR(4 * 250 * (1 / 0.2 + 1 / 0.1), s.stiffness, 1e-9);
  EXPECT_NEAR(4 * 1.5e-3 * 0.3 / 3, s.mass, 1e-15);
}

// Without friction nothing acts along the face: no spin, v_t kept, the normal run the head-on
// run at v cos(angle) bit for bit, and the rebound angle atan(tan(angle) / e_n) (a held frame:
// e_n = acor).
TEST(ObliqueBed, FrictionlessIsSpecular)
{
  const PetscReal    angle = 30;
  const ImpactResult r     = RunWith(PETSC_COMM_WORLD, HeldBed(angle, {{"-ball_friction", "0"}}), kModal);
  Scenario           head  = HeldBed(0);
  head.ball.speed          = 25 * std::cos(angle * M_PI / 180);
  const ImpactResult h     = RunWith(PETSC_COMM_WORLD, head, kModal);
  EXPECT_EQ(0.0, test::Col(r, "spin"));
  EXPECT_EQ(0.0, test::Col(r, "friction_dissipated"));
  EXPECT_NEAR(TangentialExit(r), 25 * std::sin(angle * M_PI / 180), 1e-12 * 25);
  EXPECT_EQ(r.acor, h.acor);
  EXPECT_NEAR(test::Col(r, "launch_angle"), std::atan(std::tan(angle * M_PI / 180) / h.acor) * 180 / M_PI, 1e-10);
}

// The mains locked (the rigid-surface model on the held frame) against a bed whose mains slide
// on a spring 1e4 times the default's: the same spin, speed and angle to the slide's share.
TEST(ObliqueBed, StiffInPlaneBedIsTheRigidSurface)
{
  for (const char *e_T : {"", "0.3"}) {
    Extra e = {{"-ball_friction", "0.4"}, {"-ball_spin", "400"}};
    if (*e_T) e.push_back({"-ball_tangential_cor", e_T});
    Extra stiff = e, locked = e;
    stiff.push_back({"-strings_inplane_stiffness", "1e8"});
    Scenario sl = HeldBed(40, locked);
    sl.impact.tangential_rigid = PETSC_TRUE;
    const ImpactResult a = RunWith(PETSC_COMM_WORLD, HeldBed(40, stiff), kModal), b = RunWith(PETSC_COMM_WORLD, sl, kModal);
    EXPECT_NEAR(test::Col(a, "spin"), test::Col(b, "spin"), 2e-3 * std::abs(test::Col(b, "spin"))) << "e_T " << e_T;
    EXPECT_NEAR(test::Col(a, "exit_speed"), test::Col(b, "exit_speed"), 2e-4 * test::Col(b, "exit_speed")) << "e_T " << e_T;
    EXPECT_NEAR(test::Col(a, "launch_angle"), test::Col(b, "launch_angle"), 0.02) << "e_T " << e_T;
    EXPECT_LT(test::Col(a, "strings_slide_peak"), 1e-5);
  }
}

// A gripping ball (ample friction) on the locked bed leaves rolling: omega2 R = v_t2 =
// v_t1 / (1 + alpha), with a rigid grip and with e_T = 0.
TEST(ObliqueBed, RollingLimitOfAGrippingBall)
{
  for (const char *e_T : {"", "0"}) {
    Extra e = {{"-ball_friction", "3"}};
    if (*e_T) e.push_back({"-ball_tangential_cor", e_T});
    Scenario sc                = HeldBed(30, e);
    sc.impact.tangential_rigid = PETSC_TRUE;
    const ImpactResult r       = RunWith(PETSC_COMM_WORLD, sc, kModal);
    const PetscReal    v_t1 = 25 * std::sin(30 * M_PI / 180), alpha = sc.ball.inertia_factor, R = sc.ball.radius;
    const PetscReal    tol = *e_T ? 1e-6 : 1e-12;
    EXPECT_NEAR(TangentialExit(r), v_t1 / (1 + alpha), tol * v_t1) << "e_T " << e_T;
    EXPECT_NEAR(test::Col(r, "spin") * R, v_t1 / (1 + alpha), tol * v_t1) << "e_T " << e_T;
  }
}

// Friction and the normal force both act at the contact point of a flat face: the ball's angular
// momentum about it, I omega + m R v_t, is kept whatever the contact did (grip, slip, the mains'
// slide), with spin in or out and the mains free or locked.
TEST(ObliqueBed, BallAngularMomentumAboutTheContactKept)
{
  for (const char *plane : {"flexible", "rigid"})
    for (PetscReal spin : {400.0, -200.0}) {
      Scenario sc = HeldBed(40, {{"-ball_friction", "0.4"}, {"-ball_tangential_cor", "0.2"}});
      sc.ball.spin               = spin;
      sc.impact.tangential_rigid = std::string(plane) == "rigid" ? PETSC_TRUE : PETSC_FALSE;
      const ImpactResult r       = RunWith(PETSC_COMM_WORLD, sc, kModal);
      const PetscReal    m = sc.ball.mass, R = sc.ball.radius, I = sc.ball.inertia_factor * m * R * R;
      const PetscReal    L0 = I * (-spin) + m * R * 25 * std::sin(40 * M_PI / 180), L1 = I * test::Col(r, "spin") + m * R * TangentialExit(r);
      EXPECT_NEAR(L1, L0, 1e-12 * m * R * 25) << plane << " spin " << spin;
      EXPECT_GT(test::Col(r, "friction_dissipated"), 0) << plane;
      EXPECT_GT(NormalExit(r), 0) << plane;
    }
}

// Snapback: with a rigid grip the locked bed leaves the ball rolling (omega2 R = v_t2); the
// mains that slide store energy while the ball grips and give it back before it leaves, so
// it leaves spinning faster than rolling ("over-spin") and faster than off the locked bed, for
// the same friction (Cross; Kawazoe & Okimoto's and Lindsey's lubricated strings). The slide's
// spring holds at most k s_peak^2 / 2 (the mains' mass is small: at the largest slide nearly all
// their energy is strain) and its force k s is about the friction's mu F_n at most (the mains'
// own inertia rings about it: measured 1.07 mu F_peak).
TEST(ObliqueBed, SnapbackGivesMoreSpinThanTheLockedBed)
{
  const Extra e    = {{"-ball_friction", "0.4"}, {"-ball_spin", "400"}};
  Scenario    lock = HeldBed(40, e);
  lock.impact.tangential_rigid = PETSC_TRUE;
  const Scenario     slide     = HeldBed(40, e);
  const ImpactResult a = RunWith(PETSC_COMM_WORLD, lock, kModal), b = RunWith(PETSC_COMM_WORLD, slide, kModal);
  const PetscReal    R = slide.ball.radius;
  EXPECT_NEAR(test::Col(a, "spin") * R, TangentialExit(a), 1e-10 * 25); // the locked bed: rolling
  EXPECT_GT(test::Col(b, "spin") * R, 1.5 * TangentialExit(b));          // over-spin
  EXPECT_GT(test::Col(b, "spin"), 1.5 * test::Col(a, "spin"));
  EXPECT_GT(test::Col(b, "strings_inplane_energy_returned"), 0.9 * test::Col(b, "strings_inplane_energy_peak"));
  const StringBedParams &s = *StringBedOf(slide.beam);
  const PetscReal k = StringBedInPlaneOf(s, 0, 0, 0.03).stiffness, sp = test::Col(b, "strings_slide_peak");
  EXPECT_NEAR(test::Col(b, "strings_inplane_energy_peak"), 0.5 * k * sp * sp, 0.02 * test::Col(b, "strings_inplane_energy_peak"));
  EXPECT_LT(k * sp, 1.1 * 0.4 * b.peak_force);
  EXPECT_GT(k * sp, 0.2 * b.peak_force); // the friction's force, not a sliver of it
}

// The brush (-bat_speed_face V): along the face the model is Galilean, so a ball coming in along
// the normal at v onto a face moving at V is, in the face's frame, a ball at v' = hypot(v, V) and
// the angle atan(-V/v) onto a face at rest: the same spin and slide, the lab's tangential exit the
// face frame's plus V (a locked and a sliding bed).
TEST(ObliqueBed, BrushIsTheAngleInTheFacesFrame)
{
  const PetscReal V = 8, v = 25;
  for (PetscBool rigid : {PETSC_FALSE, PETSC_TRUE}) {
    Scenario brushed                = HeldBed(0, {{"-ball_friction", "0.4"}});
    brushed.swing.face_speed        = V;
    brushed.impact.tangential_rigid = rigid;
    Scenario angled                 = HeldBed(-std::atan(V / v) * 180 / M_PI, {{"-ball_friction", "0.4"}});
    angled.ball.speed               = std::hypot(v, V);
    angled.impact.tangential_rigid  = rigid;
    const ImpactResult a = RunWith(PETSC_COMM_WORLD, brushed, kModal), b = RunWith(PETSC_COMM_WORLD, angled, kModal);
    EXPECT_LT(test::Col(a, "spin"), -50) << "topspin from the brush, rigid " << rigid;
    EXPECT_NEAR(test::Col(a, "spin"), test::Col(b, "spin"), 1e-9 * std::abs(test::Col(b, "spin"))) << "rigid " << rigid;
    EXPECT_NEAR(TangentialExit(a), TangentialExit(b) + V, 1e-9 * v) << "rigid " << rigid;
    EXPECT_NEAR(NormalExit(a), NormalExit(b), 1e-9 * v) << "rigid " << rigid;
    if (!rigid) { EXPECT_NEAR(test::Col(a, "strings_slide_peak"), test::Col(b, "strings_slide_peak"), 1e-9 * test::Col(b, "strings_slide_peak")); }
  }
}

TEST(ObliqueBed, Refusals)
{
  ASSERT_EQ(0, PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ImpactResult r;
  Scenario     bat;
  ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", "euler"}, {"-beam_nodes", "41"}}, &bat.beam, &bat.ball);
  bat.impact.x     = 0.7;
  bat.impact.angle = 20;
  EXPECT_NE(0, ImpactRun(PETSC_COMM_WORLD, bat, &r)); // no string bed: -impact_angle is a bed's
  Scenario bed      = HeldBed(20);
  bed.impact.offset = 0.01;
  EXPECT_NE(0, ImpactRun(PETSC_COMM_WORLD, bed, &r)); // a bat's offset on a flat face
  EXPECT_EQ(0, PetscPopErrorHandler());
}

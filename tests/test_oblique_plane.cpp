// The bat flexible in its second plane (model/oblique.hpp TangentialPlane, run/oblique.cpp):
//   * a mode under a linear force against its closed forms (rest, constant and ramp loads); a
//     damped mode (under-, critically, over-damped, a damped rigid mode) against a fine rk4
//     integration of its equation, on both sides of the series' threshold; a mode under a cubic
//     force (phi_1 ... phi_4) against rk4, and the cubic Hermite of F_n exact for a cubic;
//   * driven by the cubic Hermite of a half-sine F_n and its rate, the impulse converges at order
//     4 in the pieces (rigid bat and the R161's plane; linear pieces: order 2);
//   * a plane of one rigid mode of mass M_t is the rigid bat of effective mass M_t: the same
//     impulse as the rigid model's closed-form slip and Runge-Kutta grip (an independent solver);
//   * a plane of no modes is a massive fixed target: rolling, v_t' = v_t / (1 + alpha);
//   * a rigid grip on one mode (a held bed's mains) is the ball and the mode as one oscillator;
//   * on the free R161 bat in its modes: momentum and angular momentum of ball + bat along t
//     conserved to round-off, and the energy balance with the tangential contact's term.
#include "model/oblique.hpp"
#include "run/oblique.hpp"
#include "run/scenario.hpp"
#include "system/structure_part.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace beamimpact;

namespace {

TangentialModel Baseball(PetscReal mu, PetscReal l)
{
  TangentialModel m;
  m.ball_mass    = 0.145;
  m.ball_radius  = 0.0369;
  m.ball_inertia = 0.4 * m.ball_mass * m.ball_radius * m.ball_radius;
  m.bat_radius   = 0.033;
  m.friction     = mu;
  m.compliance_length = l;
  return m;
}

PetscReal HalfSine(PetscReal t, PetscReal T, PetscReal P) { return t <= 0 || t >= T ? 0.0 : P * M_PI / (2 * T) * std::sin(M_PI * t / T); }

void FeedRigid(const TangentialModel &m, PetscReal T, PetscReal P, int n, TangentialState *s)
{
  for (int k = 0; k < n; ++k) TangentialAdvance(m, T * k / n, T * (k + 1) / n, HalfSine(T * k / n, T, P), HalfSine(T * (k + 1) / n, T, P), s);
}

void FeedPlane(const TangentialModel &m, PetscReal T, PetscReal P, int n, TangentialPlane *p, TangentialState *s)
{
  for (int k = 0; k < n; ++k) TangentialAdvanceFlexible(m, T * k / n, T * (k + 1) / n, HalfSine(T * k / n, T, P), HalfSine(T * (k + 1) / n, T, P), p, s);
}

} // namespace

TEST(TangentialPlane, ModeUnderLinearForce)
{
  const PetscReal w = 3000, tau = 1.3e-3;
  PetscReal       q, qd;
  TangentialModeForced(w, 0, 0, 5, 0, tau, &q, &qd); // a constant load from rest
  EXPECT_NEAR(q, 5 * (1 - std::cos(w * tau)) / (w * w), 1e-15);
  EXPECT_NEAR(qd, 5 * std::sin(w * tau) / w, 1e-14);
  TangentialModeForced(w, 0, 0, 0, 7, tau, &q, &qd); // a ramp: q = f1 (w t - sin w t) / w^3
  EXPECT_NEAR(q, 7 * (w * tau - std::sin(w * tau)) / (w * w * w), 1e-15);
  TangentialModeForced(w, 0, 0, 0, 7, 1e-6, &q, &qd); // w tau below 0.2: the series
  EXPECT_NEAR(q / (7 * 1e-18 / 6), 1 - 0.003 * 0.003 / 20, 1e-12);
  TangentialModeForced(w, 2e-3, 0.5, 0, 0, tau, &q, &qd); // free: the energy kept
  EXPECT_NEAR(qd * qd + w * w * q * q, 0.25 + w * w * 4e-6, 1e-12);
  TangentialModeForced(0, 1, 2, 3, 4, 0.5, &q, &qd); // rigid
  EXPECT_NEAR(q, 1 + 2 * 0.5 + 3 * 0.125 + 4 * 0.125 / 6, 1e-15);
  EXPECT_NEAR(qd, 2 + 3 * 0.5 + 4 * 0.125, 1e-15);
}

// One rigid mode, gamma = 1/sqrt(M_t): the plane is a rigid body of mass M_t at the point.
namespace {

// z'' + 2 sigma z' + w^2 z = f0 + f1 s integrated by classical rk4 with n steps (an independent
// check of the closed forms).
void DampedModeRK4(PetscReal w, PetscReal sg, PetscReal z, PetscReal zd, PetscReal f0, PetscReal f1, PetscReal tau, int n, PetscReal *q, PetscReal *qd)
{
  const PetscReal h = tau / n;
  auto            acc = [&](PetscReal s, PetscReal y, PetscReal v) { return f0 + f1 * s - 2 * sg * v - w * w * y; };
  for (int i = 0; i < n; ++i) {
    const PetscReal s = i * h;
    const PetscReal k1y = zd, k1v = acc(s, z, zd);
    const PetscReal k2y = zd + 0.5 * h * k1v, k2v = acc(s + 0.5 * h, z + 0.5 * h * k1y, zd + 0.5 * h * k1v);
    const PetscReal k3y = zd + 0.5 * h * k2v, k3v = acc(s + 0.5 * h, z + 0.5 * h * k2y, zd + 0.5 * h * k2v);
    const PetscReal k4y = zd + h * k3v, k4v = acc(s + h, z + h * k3y, zd + h * k3v);
    z += h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
    zd += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  *q = z, *qd = zd;
}

} // namespace

TEST(TangentialPlane, DampedModeUnderLinearForce)
{
  struct Case {
    PetscReal w, sigma;
  };
  // under-, critically and over-damped, a damped rigid mode, a lightly damped one
  for (Case c : {Case{3000, 300}, Case{3000, 3000}, Case{3000, 30000}, Case{0, 50}, Case{3000, 1e-3}}) {
    for (PetscReal tau : {2e-5, 1.3e-3}) { // tau (w + 2 sigma) below and above the series' threshold 0.5 (but for the rigid mode)
      PetscReal q, qd, qr, qdr;
      TangentialModeForced(c.w, c.sigma, 2e-3, 0.5, 5, 7e3, tau, &q, &qd);
      DampedModeRK4(c.w, c.sigma, 2e-3, 0.5, 5, 7e3, tau, 200000, &qr, &qdr);
      EXPECT_NEAR(q, qr, 1e-11 * (std::abs(qr) + 1e-9)) << "w " << c.w << " sigma " << c.sigma << " tau " << tau;
      EXPECT_NEAR(qd, qdr, 1e-10 * (std::abs(qdr) + 1e-6)) << "w " << c.w << " sigma " << c.sigma << " tau " << tau;
    }
  }
  PetscReal q0, qd0, q1, qd1; // sigma -> 0: the undamped closed form
  TangentialModeForced(3000, 0, 2e-3, 0.5, 5, 7e3, 1.3e-3, &q0, &qd0);
  TangentialModeForced(3000, 1e-12, 2e-3, 0.5, 5, 7e3, 1.3e-3, &q1, &qd1);
  EXPECT_NEAR(q1, q0, 1e-12 * std::abs(q0));
  EXPECT_NEAR(qd1, qd0, 1e-12 * std::abs(qd0));
}
namespace {

// z'' + 2 sigma z' + w^2 z = f(s), f a cubic, by classical rk4 with n steps (independent of the
// phi-functions).
void CubicModeRK4(PetscReal w, PetscReal sg, PetscReal z, PetscReal zd, const PetscReal c[4], PetscReal tau, int n, PetscReal *q, PetscReal *qd)
{
  const PetscReal h = tau / n;
  auto acc = [&](PetscReal s, PetscReal y, PetscReal v) { return c[0] + c[1] * s + c[2] * s * s + c[3] * s * s * s - 2 * sg * v - w * w * y; };
  for (int i = 0; i < n; ++i) {
    const PetscReal s = i * h;
    const PetscReal k1y = zd, k1v = acc(s, z, zd);
    const PetscReal k2y = zd + 0.5 * h * k1v, k2v = acc(s + 0.5 * h, z + 0.5 * h * k1y, zd + 0.5 * h * k1v);
    const PetscReal k3y = zd + 0.5 * h * k2v, k3v = acc(s + 0.5 * h, z + 0.5 * h * k2y, zd + 0.5 * h * k2v);
    const PetscReal k4y = zd + h * k3v, k4v = acc(s + h, z + h * k3y, zd + h * k3v);
    z += h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
    zd += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  *q = z, *qd = zd;
}

} // namespace

// A mode under a cubic force (the phi-functions phi_1 ... phi_4): against rk4 for undamped,
// under-, critically and over-damped, rigid and damped rigid modes, on both sides of the series'
// threshold |tau A| = 1; with c2 = c3 = 0 the linear closed forms.
TEST(TangentialPlane, ModeUnderCubicForce)
{
  struct Case {
    PetscReal w, sigma;
  };
  ForceCubic f;
  f.c[0] = 5, f.c[1] = 7e3, f.c[2] = -4e6, f.c[3] = 2e9;
  for (Case c : {Case{3000, 0}, Case{3000, 300}, Case{3000, 3000}, Case{3000, 30000}, Case{0, 0}, Case{0, 50}, Case{3000, 1e-3}}) {
    for (PetscReal tau : {2e-5, 1.3e-3}) {
      PetscReal q, qd, qr, qdr;
      TangentialModeForced(c.w, c.sigma, 2e-3, 0.5, f, tau, &q, &qd);
      CubicModeRK4(c.w, c.sigma, 2e-3, 0.5, f.c, tau, 200000, &qr, &qdr);
      EXPECT_NEAR(q, qr, 1e-11 * (std::abs(qr) + 1e-9)) << "w " << c.w << " sigma " << c.sigma << " tau " << tau;
      EXPECT_NEAR(qd, qdr, 1e-10 * (std::abs(qdr) + 1e-6)) << "w " << c.w << " sigma " << c.sigma << " tau " << tau;
      ForceCubic lin;
      lin.c[0] = 5, lin.c[1] = 7e3;
      TangentialModeForced(c.w, c.sigma, 2e-3, 0.5, lin, tau, &q, &qd);
      TangentialModeForced(c.w, c.sigma, 2e-3, 0.5, 5, 7e3, tau, &qr, &qdr);
      EXPECT_NEAR(q, qr, 1e-13 * (std::abs(qr) + 1e-9)) << "linear: w " << c.w << " sigma " << c.sigma << " tau " << tau;
      EXPECT_NEAR(qd, qdr, 1e-12 * (std::abs(qdr) + 1e-6)) << "linear: w " << c.w << " sigma " << c.sigma << " tau " << tau;
    }
  }
}

// The cubic Hermite of F_n: exact for a cubic, and its shift is the same cubic.
TEST(TangentialPlane, HermiteNormalForce)
{
  auto            F = [](PetscReal t) { return 3 + 2e4 * t - 5e7 * t * t + 8e10 * t * t * t; };
  auto            dF = [](PetscReal t) { return 2e4 - 1e8 * t + 2.4e11 * t * t; };
  const PetscReal h = 2e-4;
  const ForceCubic H = ForceCubic::Hermite(h, F(0), F(h), dF(0), dF(h));
  for (PetscReal s : {0.0, 0.3 * h, h}) {
    EXPECT_NEAR(H(s), F(s), 1e-12 * std::abs(F(s)));
    EXPECT_NEAR(H.Rate(s), dF(s), 1e-12 * std::abs(dF(0)));
    EXPECT_NEAR(H.Shift(0.3 * h)(s - 0.3 * h), F(s), 1e-12 * std::abs(F(s)));
  }
  EXPECT_NEAR(H.Integral(h), 3 * h + 1e4 * h * h - 5e7 / 3 * h * h * h + 2e10 * h * h * h * h, 1e-14);
}

namespace {

PetscReal HalfSineRate(PetscReal t, PetscReal T, PetscReal P) { return t < 0 || t > T ? 0.0 : P * M_PI / (2 * T) * M_PI / T * std::cos(M_PI * t / T); }

// The impulse of the tangential contact under the half-sine F_n in n pieces, Hermite (rates) or
// linear; flexible: the plane of the free R161's modes (plane), else the rigid bat of mass 0.9 kg.
PetscReal HalfSineImpulse(const TangentialModel &m, const TangentialPlane *plane, int n, bool rates)
{
  const PetscReal T = 0.8e-3, P = 2 * 0.145 * 35, u0 = 6;
  TangentialModel mr = m;
  mr.bat_mass        = 0.9;
  TangentialPlane p;
  if (plane) p = *plane, p.ball_side = u0;
  TangentialState s = plane ? TangentialFlexibleStart(m, p) : TangentialStart(mr, u0);
  for (int k = 0; k < n; ++k) {
    const PetscReal t0 = T * k / n, t1 = T * (k + 1) / n, F0 = HalfSine(t0, T, P), F1 = HalfSine(t1, T, P);
    const PetscReal d0 = rates ? HalfSineRate(t0, T, P) : (F1 - F0) / (t1 - t0), d1 = rates ? HalfSineRate(t1, T, P) : (F1 - F0) / (t1 - t0);
    if (plane) TangentialAdvanceFlexible(m, t0, t1, F0, F1, d0, d1, &p, &s);
    else TangentialAdvance(mr, t0, t1, F0, F1, d0, d1, &s);
  }
  return s.impulse;
}

} // namespace

// The tangential contact driven by the cubic Hermite of F_n and its rate converges at order 4 in
// the pieces (errors against 1600 pieces at 10 and 20: a ratio near 16; linear pieces: near 4), for
// the rigid bat (closed-form slip, rk4 grip) and the bat's plane in its modes, with slip and
// grip and a compliant contact.
TEST(TangentialPlane, HermiteNormalForceConvergesAtOrderFour)
{
  Scenario sc;
  test::ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", "euler"}, {"-beam_nodes", "45"}}, &sc.beam, &sc.ball);
  BeamSystem  sys;
  std::string why;
  ASSERT_TRUE(BeamSystemBuild(sc.beam, &sys, &why)) << why;
  const ContactCoupling g = BeamSystemCoupling(sys, 0.7);
  ObliqueBeam           beam;
  beam.sys              = &sys;
  beam.g                = &g;
  beam.truncation.modes = ModalModes::All;
  TangentialPlane plane;
  PetscInt        rigid = 0;
  ASSERT_EQ(0, ObliquePlaneBuild(beam, {}, &plane, &rigid));
  for (const TangentialPlane *pl : {(const TangentialPlane *)nullptr, (const TangentialPlane *)&plane}) {
    const TangentialModel m   = Baseball(0.3, 2e-3);
    const PetscReal       ref = HalfSineImpulse(m, pl, 1600, true);
    for (bool rates : {true, false}) {
      const PetscReal ec = HalfSineImpulse(m, pl, 10, rates) - ref, ef = HalfSineImpulse(m, pl, 20, rates) - ref;
      const PetscReal lo = rates ? 11 : 3, hi = rates ? 22 : 5.5;
      EXPECT_GT(std::abs(ec / ef), lo) << (pl ? "plane" : "rigid") << (rates ? " Hermite: " : " linear: ") << ec << " then " << ef << " (impulse " << ref << ")";
      EXPECT_LT(std::abs(ec / ef), hi) << (pl ? "plane" : "rigid") << (rates ? " Hermite: " : " linear: ") << ec << " then " << ef << " (impulse " << ref << ")";
    }
  }
}

TEST(TangentialPlane, OneRigidModeIsTheRigidBat)
{
  const PetscReal M_t = 0.9, T = 0.8e-3, P = 2 * 0.145 * 35, u0 = 6;
  for (PetscReal mu : {0.1, 0.5, 100.0}) {
    for (PetscReal l : {0.0, 2e-3}) {
      TangentialModel rigid = Baseball(mu, l);
      rigid.bat_mass        = M_t;
      TangentialState a     = TangentialStart(rigid, u0);
      FeedRigid(rigid, T, P, 800, &a);
      TangentialPlane p;
      p.omega = {0.0};
      p.gamma = {1 / std::sqrt(M_t)};
      p.z = p.zd = {0.0};
      p.ball_side = u0;
      TangentialState b = TangentialFlexibleStart(Baseball(mu, l), p);
      FeedPlane(Baseball(mu, l), T, P, 800, &p, &b);
      // (100 sub-steps per radian of the compliant grip: 6e-6 apart; 1000: below 1e-6)
      EXPECT_NEAR(b.impulse, a.impulse, 1e-5 * std::abs(a.impulse) + 1e-14) << "mu " << mu << " l " << l;
      EXPECT_EQ(b.switches.size(), a.switches.size()) << "mu " << mu << " l " << l;
      // momentum: the ball's J against the bat's
      EXPECT_NEAR(b.impulse + std::sqrt(M_t) * p.zd[0], 0.0, 1e-14 * P) << "mu " << mu << " l " << l;
    }
  }
}

// A rigid grip (no compliance) on a mode without static flexibility: the mains of a held string
// bed, mass m on their in-plane spring k, gripped by the ball's side (effective mass m_e) from a
// common speed V0 under ample friction. Together they are one oscillator, m + m_e on k:
// w(t) = V0 cos(Omega t), Omega = sqrt(k / (m + m_e)), and the ball's impulse m_e (w - V0). The
// grip's force is a cubic on each sub-step fixed by u' = u'' = 0 at its start and u held at its
// end (model/oblique.cpp RigidGripForce): exact to 1e-9 here, where a constant force per step
// (the scheme before) was 1e-3 off at this step and converged at order 2 (docs/convergence.md).
TEST(TangentialPlane, RigidGripOnAModeIsTheJoinedOscillator)
{
  TangentialModel m  = Baseball(1e6, 0);
  const PetscReal me = 1 / (1 / m.ball_mass + m.ball_radius * m.ball_radius / m.ball_inertia);
  const PetscReal ms = 0.01, k = 1e5, V0 = 2.0, T = 1e-3, Omega = std::sqrt(k / (ms + me));
  for (int n : {10, 40}) {
    TangentialPlane p;
    p.omega     = {std::sqrt(k / ms)};
    p.gamma     = {1 / std::sqrt(ms)};
    p.z         = {0.0};
    p.zd        = {V0 * std::sqrt(ms)}; // the point's speed gamma z' = V0
    p.ball_side = V0;                   // gripped: u = 0
    TangentialState s = TangentialFlexibleStart(m, p);
    for (int j = 0; j < n; ++j) TangentialAdvanceFlexible(m, T * j / n, T * (j + 1) / n, 50.0, 50.0, &p, &s);
    EXPECT_TRUE(s.switches.empty()) << n << " steps: the grip held throughout";
    EXPECT_NEAR(p.ball_side, V0 * std::cos(Omega * T), 1e-9 * V0) << n << " steps";
    EXPECT_NEAR(s.impulse, me * V0 * (std::cos(Omega * T) - 1), 1e-9 * me * V0) << n << " steps";
    EXPECT_NEAR(p.ball_side - p.PointVelocity(), 0.0, 1e-12 * V0) << n << " steps: u stays 0";
  }
}

// No modes: a massive fixed target. Ample friction, no compliance: rolling.
TEST(TangentialPlane, NoModesRollsOnAFixedTarget)
{
  for (PetscReal alpha : {0.4, 0.55}) {
    TangentialModel m = Baseball(1e6, 0);
    m.ball_inertia    = alpha * m.ball_mass * m.ball_radius * m.ball_radius;
    TangentialPlane p;
    p.ball_side       = 8.0;
    TangentialState s = TangentialFlexibleStart(m, p);
    FeedPlane(m, 0.7e-3, 2 * m.ball_mass * 30, 40, &p, &s);
    const TangentialBodies b = TangentialBodiesAfter(m, TangentialBodies{8.0, 0, 0, 0}, s.impulse);
    EXPECT_NEAR(b.v_ball, 8.0 / (1 + alpha), 1e-12) << alpha;
    EXPECT_NEAR(b.spin, b.v_ball / m.ball_radius, 1e-9) << alpha;
  }
}

// The free R161 bat (Euler-Bernoulli, 85 nodes) in its modes, struck 70 cm from the knob with
// a half-sine normal force: ball + bat along t keep their momentum and their angular momentum
// about x = 0 to round-off (the rigid modes take the force exactly), and the energy of the
// ball, the roll and the plane's modes falls by the tangential contact's term (integral -F_t u
// by Gauss on each sub-step: a balance, not an identity).
TEST(TangentialPlane, FreeBatConservesMomentumAndBalancesEnergy)
{
  Scenario sc;
  test::ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", "euler"}, {"-beam_nodes", "85"}}, &sc.beam, &sc.ball);
  BeamSystem  sys;
  std::string why;
  ASSERT_TRUE(BeamSystemBuild(sc.beam, &sys, &why)) << why;
  const PetscReal       x_c = 0.7;
  const ContactCoupling g   = BeamSystemCoupling(sys, x_c);
  ObliqueBeam           beam;
  beam.sys              = &sys;
  beam.g                = &g;
  beam.truncation.modes = ModalModes::All;
  for (PetscReal l : {0.0, 5e-3}) {
    for (PetscReal mu : {0.2, 0.6}) {
      TangentialModel m = Baseball(mu, l);
      m.bat_roll_inertia = 4e-4; // kg m^2: the roll of a wood bat
      TangentialPlane p;
      PetscInt        rigid = 0;
      ASSERT_EQ(0, ObliquePlaneBuild(beam, std::vector<PetscReal>(sys.ndof, -3.0), &p, &rigid)); // the bat moving at 3 m/s along -t
      EXPECT_EQ(rigid, 2);
      const TangentialBodies b0{9.0, -150, 0, 0};
      p.ball_side       = b0.v_ball - m.ball_radius * b0.spin - m.bat_radius * b0.roll;
      PetscReal P0, L0, P1, L1;
      ASSERT_EQ(0, ObliquePlaneMomenta(beam, p, &P0, &L0));
      const PetscReal E0 = TangentialKineticEnergy(m, b0) + p.ModeEnergy();
      TangentialState s  = TangentialFlexibleStart(m, p);
      FeedPlane(m, 0.8e-3, 2 * m.ball_mass * 40, 400, &p, &s);
      for (int k = 0; k < 20; ++k) TangentialAdvanceFlexible(m, 0.8e-3 + 1e-4 * k, 0.8e-3 + 1e-4 * (k + 1), 0, 0, &p, &s); // ringing after it
      ASSERT_EQ(0, ObliquePlaneMomenta(beam, p, &P1, &L1));
      TangentialModel ball = m;
      ball.bat_mass        = PETSC_INFINITY;
      const TangentialBodies b1 = TangentialBodiesAfter(ball, b0, s.impulse);
      const PetscReal        scale = m.ball_mass * 9.0;
      EXPECT_NEAR(m.ball_mass * b1.v_ball + P1, m.ball_mass * b0.v_ball + P0, 1e-13 * scale) << "l " << l << " mu " << mu;
      EXPECT_NEAR(m.ball_mass * x_c * b1.v_ball + L1, m.ball_mass * x_c * b0.v_ball + L0, 1e-13 * scale) << "l " << l << " mu " << mu;
      // about the bat's axis: the ball's spin and orbit and the bat's roll (ball on its surface)
      const PetscReal Rs = m.ball_radius + m.bat_radius;
      EXPECT_NEAR(m.ball_inertia * b1.spin + m.ball_mass * Rs * b1.v_ball + m.bat_roll_inertia * b1.roll, m.ball_inertia * b0.spin + m.ball_mass * Rs * b0.v_ball, 1e-13 * scale * Rs);
      const PetscReal E1 = TangentialKineticEnergy(m, b1) + p.ModeEnergy();
      if (l == 0) { EXPECT_GT(s.dissipated, 0) << "mu " << mu; } // sliding only (a compliant grip's spring, its stiffness F_n / l changing, can give or take)
      EXPECT_NEAR(E0 - E1, s.dissipated, 1e-6 * E0) << "l " << l << " mu " << mu << ": the energy taken " << s.dissipated;
    }
  }
}

// The same free bat with an undamped tuned absorber at the knob (-absorber 0.05,0.05,150,0, a
// registered part's point mass): its mass moves in the plane's modes too, so ball + bat +
// absorber keep their momentum and angular momentum along t to round-off (the absorber's share
// left out, they were off by about its mass's share of the impulse).
TEST(TangentialPlane, FreeBatWithAnAbsorberConservesMomentum)
{
  Scenario sc;
  test::ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", "euler"}, {"-beam_nodes", "85"}}, &sc.beam, &sc.ball);
  PartOptionValues v;
  v.given["-absorber"] = {0.05, 0.05, 150, 0};
  std::shared_ptr<const PartParams> q;
  std::string                       why;
  ASSERT_TRUE(StructurePartFind("absorber")->Configure(v, sc.beam, &q, &why)) << why;
  sc.beam.parts.Set("absorber", q);
  BeamSystem sys;
  ASSERT_TRUE(BeamSystemBuild(sc.beam, &sys, &why)) << why;
  ASSERT_FALSE(sys.rigid_points.empty());
  const PetscReal       x_c = 0.7;
  const ContactCoupling g   = BeamSystemCoupling(sys, x_c);
  ObliqueBeam           beam;
  beam.sys              = &sys;
  beam.g                = &g;
  beam.truncation.modes = ModalModes::All;
  TangentialModel m     = Baseball(0.6, 0);
  m.bat_roll_inertia    = 4e-4;
  TangentialPlane p;
  PetscInt        rigid = 0;
  ASSERT_EQ(0, ObliquePlaneBuild(beam, std::vector<PetscReal>(sys.ndof, -3.0), &p, &rigid));
  const TangentialBodies b0{9.0, -150, 0, 0};
  p.ball_side = b0.v_ball - m.ball_radius * b0.spin - m.bat_radius * b0.roll;
  PetscReal P0, L0, P1, L1;
  ASSERT_EQ(0, ObliquePlaneMomenta(beam, p, &P0, &L0));
  TangentialState s = TangentialFlexibleStart(m, p);
  FeedPlane(m, 0.8e-3, 2 * m.ball_mass * 40, 400, &p, &s);
  ASSERT_EQ(0, ObliquePlaneMomenta(beam, p, &P1, &L1));
  TangentialModel ball = m;
  ball.bat_mass        = PETSC_INFINITY;
  const TangentialBodies b1    = TangentialBodiesAfter(ball, b0, s.impulse);
  const PetscReal        scale = m.ball_mass * 9.0;
  EXPECT_NEAR(m.ball_mass * b1.v_ball + P1, m.ball_mass * b0.v_ball + P0, 1e-13 * scale);
  EXPECT_NEAR(m.ball_mass * x_c * b1.v_ball + L1, m.ball_mass * x_c * b0.v_ball + L0, 1e-13 * scale);
}

// The same free bat damped in proportion to its stiffness (-beam_damping_stiffness: the rigid
// modes undamped, the flexible ones decaying, the highest over-damped): momentum and angular
// momentum still conserved to round-off, and the energy falls by the tangential contact's term
// plus what the modes' damping took (TangentialPlane::damped, > 0).
TEST(TangentialPlane, DampedBatBalancesEnergy)
{
  Scenario sc;
  test::ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", "euler"}, {"-beam_nodes", "85"}, {"-beam_damping_stiffness", "2e-6"}}, &sc.beam, &sc.ball);
  BeamSystem  sys;
  std::string why;
  ASSERT_TRUE(BeamSystemBuild(sc.beam, &sys, &why)) << why;
  const PetscReal       x_c = 0.7;
  const ContactCoupling g   = BeamSystemCoupling(sys, x_c);
  ObliqueBeam           beam;
  beam.sys              = &sys;
  beam.g                = &g;
  beam.truncation.modes = ModalModes::All;
  TangentialModel m     = Baseball(0.6, 5e-3);
  m.bat_roll_inertia    = 4e-4;
  TangentialPlane p;
  PetscInt        rigid = 0;
  ASSERT_EQ(0, ObliquePlaneBuild(beam, std::vector<PetscReal>(sys.ndof, -3.0), &p, &rigid));
  ASSERT_EQ(p.sigma.size(), p.omega.size());
  EXPECT_EQ(p.sigma[0], 0); // rigid: undamped
  EXPECT_GT(p.sigma.back(), p.omega.back()); // the top mode over-damped
  const TangentialBodies b0{9.0, -150, 0, 0};
  p.ball_side = b0.v_ball - m.ball_radius * b0.spin - m.bat_radius * b0.roll;
  PetscReal P0, L0, P1, L1;
  ASSERT_EQ(0, ObliquePlaneMomenta(beam, p, &P0, &L0));
  const PetscReal E0 = TangentialKineticEnergy(m, b0) + p.ModeEnergy();
  TangentialState s  = TangentialFlexibleStart(m, p);
  FeedPlane(m, 0.8e-3, 2 * m.ball_mass * 40, 400, &p, &s);
  for (int k = 0; k < 20; ++k) TangentialAdvanceFlexible(m, 0.8e-3 + 1e-4 * k, 0.8e-3 + 1e-4 * (k + 1), 0, 0, &p, &s);
  ASSERT_EQ(0, ObliquePlaneMomenta(beam, p, &P1, &L1));
  TangentialModel ball = m;
  ball.bat_mass        = PETSC_INFINITY;
  const TangentialBodies b1 = TangentialBodiesAfter(ball, b0, s.impulse);
  const PetscReal        scale = m.ball_mass * 9.0;
  EXPECT_NEAR(m.ball_mass * b1.v_ball + P1, m.ball_mass * b0.v_ball + P0, 1e-13 * scale);
  EXPECT_NEAR(m.ball_mass * x_c * b1.v_ball + L1, m.ball_mass * x_c * b0.v_ball + L0, 1e-13 * scale);
  const PetscReal E1 = TangentialKineticEnergy(m, b1) + p.ModeEnergy();
  EXPECT_GT(p.damped, 0);
  EXPECT_NEAR(E0 - E1, s.dissipated + p.damped, 1e-6 * E0) << "friction " << s.dissipated << " damping " << p.damped;
}

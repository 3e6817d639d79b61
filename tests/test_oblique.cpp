// The oblique impact's tangential contact (model/oblique) against closed forms:
//   * frictionless: no tangential impulse, no spin; with e = 1 on a fixed target the ball
//     leaves at the mirror reflection about the line of centres (launch angle 2 theta);
//   * ample friction without tangential compliance on a massive fixed target: rolling,
//     v_t' = v_t / (1 + alpha), w' = v_t' / R (any normal force history);
//   * finite friction without compliance: the impulse mu P_n while it slides (the slide does
//     not end), the grip time where mu integral F_n = m_e |u0|;
//   * with compliance and ample friction on a fixed target over a contact of the wall time:
//     the tangential restitution e_T the spring was set from;
//   * the energy balance with the frictional term (the kinetic energy lost = the dissipation
//     + the spring's energy), momentum and angular momentum about the bat's axis of ball + free
//     bat conserved by the impulse.
#include "model/oblique.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace beamimpact;

namespace {

// A half-sine normal force of duration T and impulse P (a linear ball on a fixed wall), as
// n samples, fed to the tangential contact.
void FeedHalfSine(const TangentialModel &m, PetscReal T, PetscReal P, int n, TangentialState *s)
{
  const PetscReal F_max = P * M_PI / (2 * T);
  auto            F     = [&](PetscReal t) { return t <= 0 || t >= T ? 0.0 : F_max * std::sin(M_PI * t / T); };
  for (int k = 0; k < n; ++k) {
    const PetscReal t0 = T * k / n, t1 = T * (k + 1) / n;
    TangentialAdvance(m, t0, t1, F(t0), F(t1), s);
  }
}

TangentialModel Baseball(PetscReal mu, PetscReal l)
{
  TangentialModel m;
  m.ball_mass    = 0.145;
  m.ball_radius  = 0.0369;
  m.ball_inertia = 0.4 * m.ball_mass * m.ball_radius * m.ball_radius;
  m.bat_radius   = 0.033;
  m.friction     = mu;
  m.compliance_length = l;
  return m; // a fixed, held target: bat_mass and bat_roll_inertia infinite
}

} // namespace

TEST(ObliqueGeometry, AngleFromOffset)
{
  const ObliqueGeometry g = ObliqueGeometryOf(0.02, 0.0369, 0.033);
  EXPECT_NEAR(std::sin(g.theta), 0.02 / 0.0699, 1e-15);
  EXPECT_NEAR(g.cos_theta * g.cos_theta + g.sin_theta * g.sin_theta, 1.0, 1e-15);
  const ObliqueGeometry h = ObliqueGeometryOf(0, 0.0369, 0.033);
  EXPECT_EQ(h.cos_theta, 1.0); // exactly: a head-on hit is today's
  EXPECT_EQ(h.sin_theta, 0.0);
}

TEST(ObliqueLimits, FrictionlessMirrorReflection)
{
  const TangentialModel m = Baseball(0, 0);
  const ObliqueGeometry g = ObliqueGeometryOf(0.025, m.ball_radius, m.bat_radius);
  const PetscReal       v = 30, v_t0 = v * g.sin_theta;
  TangentialState       s = TangentialStart(m, v_t0);
  FeedHalfSine(m, 1e-3, 2 * m.ball_mass * v * g.cos_theta, 50, &s);
  EXPECT_EQ(s.impulse, 0.0);
  const TangentialBodies b = TangentialBodiesAfter(m, TangentialBodies{v_t0, 0, 0, 0}, s.impulse);
  EXPECT_EQ(b.spin, 0.0);
  const ObliqueExit e = ObliqueExitOf(g, v * g.cos_theta, b.v_ball); // e = 1 along n
  EXPECT_NEAR(e.launch_angle, 2 * g.theta * 180 / M_PI, 1e-12);
  EXPECT_NEAR(e.speed, v, 1e-12);
}

TEST(ObliqueLimits, AmpleFrictionRigidGripRolls)
{
  for (PetscReal alpha : {0.4, 0.55, 2.0 / 3.0}) {
    TangentialModel m = Baseball(1e6, 0);
    m.ball_inertia    = alpha * m.ball_mass * m.ball_radius * m.ball_radius;
    const PetscReal v_t0 = 8.0;
    TangentialState s    = TangentialStart(m, v_t0);
    FeedHalfSine(m, 0.7e-3, 2 * m.ball_mass * 30, 40, &s);
    const TangentialBodies b = TangentialBodiesAfter(m, TangentialBodies{v_t0, 0, 0, 0}, s.impulse);
    EXPECT_NEAR(b.v_ball, v_t0 / (1 + alpha), 1e-12) << "alpha " << alpha;
    EXPECT_NEAR(b.spin, b.v_ball / m.ball_radius, 1e-9) << "alpha " << alpha;
    ASSERT_EQ(s.switches.size(), 1u);
    EXPECT_EQ(s.switches[0].to, TangentialPhase::Grip);
  }
}

TEST(ObliqueLimits, FiniteFrictionSlidesThenGrips)
{
  // mu P_n < m_e |u0|: slides throughout, J = -mu P_n.
  TangentialModel m  = Baseball(0.1, 0);
  const PetscReal P  = 2 * m.ball_mass * 30, T = 1e-3, u0 = 30; // m_e u0 = 1.24 N s > mu P = 0.87 N s
  TangentialState s  = TangentialStart(m, u0);
  FeedHalfSine(m, T, P, 400, &s);
  // The samples' trapezoid impulse, which is what the piecewise-linear force carries.
  EXPECT_NEAR(s.impulse, -m.friction * s.normal_impulse, 1e-12 * P);
  EXPECT_TRUE(s.switches.empty());
  // mu P_n > m_e |u0|: grips where mu integral_0^t F_n = m_e u0 (half-sine: closed form).
  m                   = Baseball(0.4, 0);
  const PetscReal m_e = m.EffectiveMass();
  TangentialState g   = TangentialStart(m, 3.0);
  FeedHalfSine(m, T, P, 2000, &g);
  ASSERT_EQ(g.switches.size(), 1u);
  // integral_0^t F = P/2 (1 - cos(pi t/T)) (the linear pieces differ by O(h^2)).
  const PetscReal t_grip = T / M_PI * std::acos(1 - 2 * m_e * 3.0 / (m.friction * P));
  EXPECT_NEAR(g.switches[0].time, t_grip, 1e-6 * T);
  EXPECT_NEAR(g.impulse, -m_e * 3.0, 1e-12);
}

TEST(ObliqueLimits, GripUnderConstantLoadIsHarmonic)
{
  // k_t = F / l constant: the grip oscillates at w = sqrt(F / (l m_e)), u = u0 cos(w t).
  TangentialModel m   = Baseball(1e6, 0);
  m.compliance_length = 1e-3;
  const PetscReal F = 2e4, m_e = m.EffectiveMass(), w = std::sqrt(F / (m.compliance_length * m_e)), T = 1.7 / w;
  TangentialState s = TangentialStart(m, 0.0); // grips from the start
  s.u               = 4.0;
  for (int k = 0; k < 10; ++k) TangentialAdvance(m, T * k / 10, T * (k + 1) / 10, F, F, &s);
  EXPECT_NEAR(s.u, 4.0 * std::cos(w * T), 1e-8 * 4.0);
  EXPECT_NEAR(s.xi, 4.0 / w * std::sin(w * T), 1e-8 * 4.0 / w);
  EXPECT_TRUE(s.switches.empty());
  // Below the limit mu l the spring never slips; a lower friction makes it slip where |xi| = mu l.
  m.friction        = 0.5 * 4.0 / w / m.compliance_length; // the limit at half the amplitude
  TangentialState q = TangentialStart(m, 0.0);
  q.u               = 4.0;
  for (int k = 0; k < 10; ++k) TangentialAdvance(m, T * k / 10, T * (k + 1) / 10, F, F, &q);
  ASSERT_FALSE(q.switches.empty());
  EXPECT_NEAR(q.switches[0].time, std::asin(0.5) / w, 1e-7 / w); // RK4 at 40 steps a radian
}

TEST(ObliqueLimits, ComplianceGivesItsTangentialRestitution)
{
  for (PetscReal e_T : {0.0, 0.3, 0.6}) {
    const PetscReal T = 0.8e-3, P = 2 * 0.145 * 30;
    TangentialModel m = Baseball(1e4, 0);
    // The contact's own force, as samples.
    const int              n = 400;
    std::vector<PetscReal> t(n + 1), F(n + 1);
    for (int k = 0; k <= n; ++k) t[k] = T * k / n, F[k] = k == 0 || k == n ? 0 : P * M_PI / (2 * T) * std::sin(M_PI * k / n);
    m.compliance_length = TangentialComplianceLength(m.EffectiveMass(), e_T, t, F);
    ASSERT_GT(m.compliance_length, 0);
    const PetscReal u0 = 5.0;
    TangentialState s  = TangentialStart(m, u0);
    for (int k = 0; k < n; ++k) TangentialAdvance(m, t[k], t[k + 1], F[k], F[k + 1], &s);
    EXPECT_NEAR(-s.u / u0, e_T, 1e-4) << "e_T " << e_T; // ample friction: a grip throughout but at the ends
    // More spin than rolling for e_T > 0: the impulse (1 + e_T) m_e u0.
    EXPECT_NEAR(s.impulse, -(1 + e_T) * m.EffectiveMass() * u0, 1e-4 * m.EffectiveMass() * u0) << "e_T " << e_T;
  }
}

// The length is the root on the first branch (the tangential oscillation's phase below pi): every
// branch's root reverses u by e_T, the next one at a phase 2 pi - arccos(-e_T), a length over 5
// times shorter. Its phase integral sqrt(F / (l m_e)) dt is within 25 % of arccos(-e_T) (the
// slowly varying limit). Guards the root finder (bisection to 25 %, then Illinois: issue 38; a
// regula falsi over the whole bracket found a root of another branch on the R161's contact).
TEST(ObliqueLimits, ComplianceOnTheFirstBranch)
{
  for (PetscReal e_T : {0.0, 0.3, 0.6, 0.9}) {
    const PetscReal        T = 0.8e-3, P = 2 * 0.145 * 30;
    const TangentialModel  m = Baseball(1e4, 0);
    const int              n = 400;
    std::vector<PetscReal> t(n + 1), F(n + 1), dF(n + 1);
    for (int k = 0; k <= n; ++k) {
      t[k]  = T * k / n;
      F[k]  = P * M_PI / (2 * T) * std::sin(M_PI * k / n);
      dF[k] = P * M_PI / (2 * T) * M_PI / T * std::cos(M_PI * k / n);
    }
    const PetscReal l = TangentialComplianceLength(m.EffectiveMass(), e_T, t, F, dF);
    PetscReal       phase = 0; // integral sqrt(F / (l m_e)) dt, trapezoidal
    for (int k = 0; k < n; ++k) phase += 0.5 * (t[k + 1] - t[k]) * (std::sqrt(std::max<PetscReal>(F[k], 0)) + std::sqrt(std::max<PetscReal>(F[k + 1], 0))) / std::sqrt(l * m.EffectiveMass());
    EXPECT_NEAR(phase / std::acos(-e_T), 1, 0.25) << "e_T " << e_T << ": l " << l;
  }
}

TEST(ObliqueBalance, EnergyWithFriction)
{
  // A free bat (effective mass, roll) and a compliant contact that grips and slips.
  for (PetscReal mu : {0.05, 0.3, 2.0}) {
    TangentialModel m  = Baseball(mu, 0);
    m.bat_mass         = 0.6;
    m.bat_roll_inertia = 3e-4;
    m.compliance_length = 2e-4; // an e_T of about 0.3 on this contact
    const TangentialBodies b0{9.0, -150.0, -6.0, 0.0};
    const PetscReal        u0 = (b0.v_ball - m.ball_radius * b0.spin) - (b0.v_bat + m.bat_radius * b0.roll);
    TangentialState        s  = TangentialStart(m, u0);
    FeedHalfSine(m, 0.8e-3, 2 * m.ball_mass * 35, 300, &s);
    const TangentialBodies b1 = TangentialBodiesAfter(m, b0, s.impulse);
    const PetscReal        E0 = TangentialKineticEnergy(m, b0), E1 = TangentialKineticEnergy(m, b1);
    EXPECT_GT(s.dissipated, 0) << "mu " << mu;
    // The kinetic energy lost: friction's, less the work of the spring's changing stiffness
    // (its energy is 0 at the end: F_n = 0). RK4 in the grip: to its accuracy.
    EXPECT_NEAR(E0 - E1, s.dissipated - s.stiffness_work, 1e-7 * E0) << "mu " << mu;
    // The slip speed the impulse gives is the one the contact followed.
    const PetscReal u1 = (b1.v_ball - m.ball_radius * b1.spin) - (b1.v_bat + m.bat_radius * b1.roll);
    EXPECT_NEAR(u1, s.u, 1e-12 * std::abs(u0));
    // Momentum along t and angular momentum about the bat's axis of ball + free bat.
    const PetscReal r = m.ball_radius + m.bat_radius;
    auto            p = [&](const TangentialBodies &b) { return m.ball_mass * b.v_ball + m.bat_mass * b.v_bat; };
    auto            L = [&](const TangentialBodies &b) { return m.ball_inertia * b.spin + r * m.ball_mass * b.v_ball + m.bat_roll_inertia * b.roll; };
    EXPECT_NEAR(p(b1), p(b0), 1e-15 * m.ball_mass * 10);
    EXPECT_NEAR(L(b1), L(b0), 1e-15 * m.ball_mass * 10 * r * 10);
  }
}

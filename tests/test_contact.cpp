// Contact laws and the rigid-body formula against closed forms.
//
// Every registered law (model/contact_laws/) is checked here as it is registered, with nothing
// written for it: its stiffness is the derivative of its force, its stored energy the integral
// of its force, W continuous at the branch switch, and its rigid-wall closed forms (maximum
// compression, contact time, coefficient of restitution) and scales agree with the ball
// integrated against a wall under the law's own force (RK4, the switch and the separation
// bisected onto their roots). The laws' own formulas are then checked against the physics
// (the linear spring's pi sqrt(m/k), the hysteretic ball's e^2 = (m+1)/(n+1) and cycle loss).
#include "model/contact.hpp"
#include "model/rigid.hpp"
#include "run/events.hpp"
#include "wall_bounce.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <string>

using namespace beamimpact;
using beamimpact::test::Bounce;
using beamimpact::test::WallBounce;

namespace {

BallParams BallWithLaw(const char *name)
{
  BallParams b;
  BallParamsUseLaw(&b, ContactLawFind(name));
  return b;
}

// The ball bouncing under its law's force (ContactForce), with the phases of a contact as the
// program switches them (ContactBegin, loading; ContactSwitch to unloading at the maximum
// compression); `steps` steps over c_max/v.
WallBounce BounceUnderTheLaw(const BallParams &b, double v, int steps = 20000)
{
  ContactState s;
  ContactBegin(b, &s, v);
  return Bounce([&](double c) { return ContactForce(b, s, c); }, [&](double c) { ContactSwitch(b, &s, ContactPhase::Unloading, c); }, b.mass, v, ContactWallMaxCompression(b, v) / v / steps);
}

} // namespace

TEST(ContactLaws, RegistryNamesOptionsAndDefaults)
{
  const std::vector<const ContactLaw *> &laws = ContactLaws();
  ASSERT_GE(laws.size(), 2u);
  EXPECT_STREQ(BallParams().law->Name(), "linear") << "the default ball is the paper's linear spring";
  EXPECT_EQ(ContactLawFind("HYSTERESIS"), ContactLawFind("hysteresis"));
  EXPECT_EQ(ContactLawFind("rubber"), nullptr);
  std::set<std::string> names, options;
  for (const ContactLaw *law : laws) {
    EXPECT_TRUE(names.insert(law->Name()).second) << "two laws named " << law->Name();
    EXPECT_EQ(ContactLawFind(law->Name()), law);
    int numbers = 0;
    for (const OptionSpec &row : law->Options()) {
      EXPECT_EQ(row.name.rfind("-ball_", 0), 0u) << row.name;
      EXPECT_TRUE(options.insert(row.name).second) << row.name << " belongs to two laws";
      EXPECT_FALSE(row.help.empty()) << row.name;
      if (row.kind != OptionKind::Real) continue;
      EXPECT_FALSE(row.unit.empty()) << row.name << ": every number has its unit";
      ++numbers;
    }
    EXPECT_LE(numbers, kContactLawMaxValues);
  }
  // A law's parameters are its rows, with the rows' defaults.
  const BallParams h = BallWithLaw("hysteresis");
  EXPECT_EQ(BallValue(h, "k1"), 2e4);
  EXPECT_EQ(BallValue(h, "-ball_m"), 1.0);
  EXPECT_EQ(BallValue(h, "n"), 1.768);
  EXPECT_EQ(BallValue(h, "cor"), 0.0) << "not given";
  EXPECT_TRUE(std::isnan(BallValue(h, "k"))) << "-ball_k is the linear law's";
  BallParams l = BallWithLaw("linear");
  EXPECT_EQ(BallValue(l, "k"), 2e4);
  EXPECT_TRUE(BallValueSet(&l, "k", 3e4));
  EXPECT_EQ(ContactLinearStiffness(l), 3e4);
  EXPECT_FALSE(BallValueSet(&l, "k1", 1.0));
}

// F' = dF/dc, stored energy = integral of F, W continuous at the switch, for every law on both
// branches (a switch at c_s, then the unloading branch below it).
TEST(ContactLaws, StiffnessAndStoredEnergyAreTheDerivativeAndIntegralOfTheForce)
{
  for (const ContactLaw *law : ContactLaws()) {
    BallParams   b = BallWithLaw(law->Name());
    ContactState s;
    ContactBegin(b, &s, b.speed);
    const double cs = ContactCompressionScale(b);
    for (int branch = 0; branch < 2; ++branch) {
      for (double f : {0.2, 0.55, 0.9}) {
        const double c = f * cs, h = 1e-6 * cs;
        const double fd = (ContactForce(b, s, c + h) - ContactForce(b, s, c - h)) / (2 * h);
        EXPECT_NEAR(ContactStiffness(b, s, c), fd, 1e-6 * std::abs(fd)) << law->Name() << " branch " << branch << " c = " << c;
        // Simpson's rule on [0, c] (fine enough for c^p with p >= 1 to 1e-9).
        const int N = 2000;
        double    q = ContactForce(b, s, 0) + ContactForce(b, s, c);
        for (int i = 1; i < N; ++i) q += (i % 2 ? 4 : 2) * ContactForce(b, s, c * i / N);
        q *= c / N / 3;
        EXPECT_NEAR(ContactStoredEnergy(b, s, c), q, 1e-8 * q) << law->Name() << " branch " << branch;
        EXPECT_NEAR(ContactForce(b, s, -c), -ContactForce(b, s, c), 1e-14 * std::abs(ContactForce(b, s, c))) << law->Name() << ": odd in c inside a contact";
      }
      if (branch == 0) {
        const double W = ContactWork(b, s, cs), F = ContactForce(b, s, cs);
        ContactSwitch(b, &s, ContactPhase::Unloading, cs);
        EXPECT_NEAR(ContactWork(b, s, cs), W, 1e-13 * W) << law->Name() << ": W continuous at the switch";
        EXPECT_NEAR(ContactForce(b, s, cs), F, 1e-12 * F) << law->Name() << ": F continuous at the switch";
      }
    }
    s.phase = ContactPhase::Separated;
    EXPECT_EQ(ContactForce(b, s, cs), 0.0);
    EXPECT_EQ(ContactStiffness(b, s, cs), 0.0);
    EXPECT_EQ(ContactStoredEnergy(b, s, cs), 0.0);
  }
}

// The closed forms every law states against the ball integrated on a wall under its own
// force, at three speeds; the scales and the stability bound from them.
TEST(ContactLaws, WallClosedFormsAgreeWithTheIntegratedBounce)
{
  for (const ContactLaw *law : ContactLaws()) {
    for (double v : {0.3, 1.0, 7.0}) {
      BallParams b = BallWithLaw(law->Name());
      b.speed      = v;
      const WallBounce w = BounceUnderTheLaw(b, v);
      EXPECT_NEAR(w.max_compression / ContactWallMaxCompression(b, v), 1.0, 1e-7) << law->Name() << " v = " << v;
      EXPECT_NEAR(w.loading_time / ContactWallLoadingTime(b, v), 1.0, 1e-6) << law->Name() << " v = " << v;
      EXPECT_NEAR(w.contact_time / ContactWallTime(b, v), 1.0, 1e-6) << law->Name() << " v = " << v;
      EXPECT_NEAR(w.cor, BallCorAt(b, v), 1e-7) << law->Name() << " v = " << v;
      if (ContactElastic(b)) EXPECT_NEAR(w.cor, 1.0, 1e-7) << law->Name() << " is elastic: it returns the ball at its speed";
      else EXPECT_LT(w.cor, 1.0 - 1e-3) << law->Name() << " is lossy";
      EXPECT_EQ(ContactHasHysteresis(b), std::abs(ContactWallUnloadingTime(b, v) / ContactWallLoadingTime(b, v) - 1) > 1e-9) << law->Name();
      // Scales at the incident speed: the wall's compression, a contact time within a factor
      // 1.5 of the wall's, and a stiffness bound above dF/dc over the whole bounce.
      EXPECT_NEAR(ContactCompressionScale(b) / w.max_compression, 1.0, 1e-7) << law->Name();
      EXPECT_GT(ContactTimeScale(b), w.contact_time / 1.5) << law->Name();
      EXPECT_LT(ContactTimeScale(b), w.contact_time * 1.5) << law->Name();
      ContactState s;
      ContactBegin(b, &s, v);
      for (int branch = 0; branch < 2; ++branch) {
        for (double f : {0.1, 0.5, 1.0}) EXPECT_GE(ContactStiffnessBound(b), ContactStiffness(b, s, f * w.max_compression)) << law->Name();
        ContactSwitch(b, &s, ContactPhase::Unloading, w.max_compression);
      }
    }
  }
}

TEST(ContactLaws, LinearMeansForceProportionalToCompression)
{
  for (const ContactLaw *law : ContactLaws()) {
    const BallParams b = BallWithLaw(law->Name());
    ContactState     s, u;
    const double     c = ContactCompressionScale(b);
    ContactSwitch(b, &u, ContactPhase::Unloading, 1.5 * c);
    bool proportional = true; // on both branches
    for (const ContactState &q : {s, u}) proportional = proportional && std::abs(ContactForce(b, q, 0.5 * c) / ContactForce(b, q, c) - 0.5) < 1e-12;
    EXPECT_EQ(ContactLinear(b), proportional) << law->Name();
    if (ContactLinear(b)) EXPECT_NEAR(ContactForce(b, u, c), ContactLinearStiffness(b) * c, 1e-14 * ContactForce(b, u, c));
    else EXPECT_TRUE(std::isnan(ContactLinearStiffness(b)));
  }
}

TEST(ContactLaw, LinearSpringForceEnergyAndWallTime)
{
  BallParams   b; // k = 2e4 N/m, 42 g
  ContactState s;
  EXPECT_DOUBLE_EQ(ContactForce(b, s, 1e-3), 20.0);
  EXPECT_DOUBLE_EQ(ContactStiffness(b, s, 1e-3), 2e4);
  EXPECT_DOUBLE_EQ(ContactStoredEnergy(b, s, 1e-3), 0.5 * 2e4 * 1e-6);
  EXPECT_NEAR(ContactWallTime(b, 1.0), M_PI * std::sqrt(0.042 / 2e4), 1e-15) << "half a period of the ball on the spring";
  EXPECT_NEAR(ContactWallTime(b, 9.0), M_PI * std::sqrt(0.042 / 2e4), 1e-15) << "whatever the speed";
  EXPECT_NEAR(ContactCompressionScale(b), std::sqrt(0.042 / 2e4), 1e-15);
  EXPECT_EQ(BallCorAt(b, 3.0), 1.0);
  EXPECT_TRUE(ContactElastic(b) && ContactLinear(b) && !ContactHasHysteresis(b));
}

// On a rigid wall the ball stores 1/2 m v^2 = k1 c^(m+1)/(m+1) while loading and returns
// k2 c_max^(n+1)/(n+1) while unloading: e^2 = (m+1)/(n+1) whatever the speed.
TEST(ContactLaw, HysteresisReturnsRestitutionSquaredOnAWall)
{
  for (double speed : {0.1, 1.0, 40.0}) {
    BallParams b = BallWithLaw("hysteresis"); // k1 = 2e4, m = 1, n = 1.768
    b.speed      = speed;
    const double E_in  = 0.5 * b.mass * speed * speed;
    const double c_max = ContactCompressionScale(b);
    ContactState s;
    ContactBegin(b, &s, speed);
    EXPECT_NEAR(ContactStoredEnergy(b, s, c_max), E_in, 1e-12 * E_in);
    const double W_before = ContactWork(b, s, c_max);
    ContactSwitch(b, &s, ContactPhase::Unloading, c_max);
    EXPECT_NEAR(ContactWork(b, s, c_max), W_before, 1e-12 * E_in) << "W must be continuous at the switch";
    EXPECT_NEAR(ContactForce(b, s, c_max), 2e4 * c_max, 1e-12 * 2e4 * c_max) << "force continuous at c_max";
    const double E_out = ContactStoredEnergy(b, s, c_max);
    EXPECT_NEAR(E_out / E_in, 2 / 2.768, 1e-12);
    EXPECT_NEAR(std::sqrt(E_out / E_in), BallCorAt(b, speed), 1e-12);
    // After unloading to c = 0 everything not returned is dissipated: the cycle loss formula.
    EXPECT_NEAR(ContactWork(b, s, 0.0), ContactCycleLoss(b, c_max), 1e-12 * E_in);
    EXPECT_NEAR(ContactWork(b, s, 0.0), E_in - E_out, 1e-12 * E_in);
  }
}

// A reload (the compression growing again before the ball left, as a ringing barrel wall makes
// it): the ball climbs back along the curve it unloaded on, without loss and without a jump of
// the force, to the last maximum; beyond it the loading branch. So a loop inside the cycle loses
// nothing, and a cycle to c2 with an inner loop loses what one cycle to c2 loses (the area
// between k1 c^m and the unloading curve from c2). The rule it replaced jumped to k1 c^m at the
// reload (the force up by (c1/c_r)^(n-m) and the dissipated energy down).
TEST(ContactLaw, HysteresisReloadClimbsTheUnloadingCurveWithoutLoss)
{
  const BallParams b = BallWithLaw("hysteresis"); // k1 = 2e4, m = 1, n = 1.768
  const double     c1 = 1e-3, cr = 0.6e-3, c2 = 1.3e-3, k1 = 2e4;
  ContactState     s;
  ContactBegin(b, &s, 1.0);
  const auto dissipated = [&](double c) { return ContactWork(b, s, c) - ContactStoredEnergy(b, s, c); };
  ContactSwitch(b, &s, ContactPhase::Unloading, c1);
  const double F_unload = ContactForce(b, s, 0.5e-3), F_r = ContactForce(b, s, cr), D_r = dissipated(cr), W_r = ContactWork(b, s, cr);
  ContactSwitch(b, &s, ContactPhase::Loading, cr); // the reload
  EXPECT_NEAR(ContactForce(b, s, cr), F_r, 1e-12 * F_r) << "the force must not jump at a reload";
  EXPECT_NEAR(ContactWork(b, s, cr), W_r, 1e-12 * W_r);
  EXPECT_NEAR(dissipated(cr), D_r, 1e-12 * W_r) << "the ball gives back none of what it dissipated";
  ContactSwitch(b, &s, ContactPhase::Unloading, 0.9e-3); // a maximum below the knee: the same curve
  EXPECT_NEAR(ContactForce(b, s, 0.5e-3), F_unload, 1e-12 * F_unload);
  EXPECT_NEAR(dissipated(0.9e-3), D_r, 1e-12 * W_r) << "a loop inside the cycle is elastic";
  ContactSwitch(b, &s, ContactPhase::Loading, 0.7e-3); // reload again, past the knee c1 this time
  for (double c : {0.8e-3, 0.99e-3, 1.01e-3, 1.2e-3}) {
    const double h = 1e-10, fd = (ContactForce(b, s, c + h) - ContactForce(b, s, c - h)) / (2 * h);
    EXPECT_NEAR(ContactStiffness(b, s, c), fd, 1e-5 * std::abs(fd)) << c;
    const int    n = 2000; // Simpson: the stored energy is the integral of the force along the path
    double       I = 0;
    for (int i = 0; i <= n; ++i) {
      const double x = 0.7e-3 + (c - 0.7e-3) * i / n;
      I += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * ContactForce(b, s, x);
    }
    I *= (c - 0.7e-3) / (3 * n);
    EXPECT_NEAR(ContactStoredEnergy(b, s, c) - ContactStoredEnergy(b, s, 0.7e-3), I, 1e-7 * I) << c; // Simpson over the kink at c1: 3e-9
  }
  EXPECT_NEAR(ContactForce(b, s, 1.2e-3), k1 * 1.2e-3, 1e-12 * k1 * 1.2e-3) << "beyond the knee: the loading branch";
  ContactSwitch(b, &s, ContactPhase::Unloading, c2);
  EXPECT_NEAR(ContactForce(b, s, c2), k1 * c2, 1e-12 * k1 * c2);
  EXPECT_NEAR(ContactWork(b, s, 0.0), ContactCycleLoss(b, c2), 1e-12 * ContactCycleLoss(b, c2)) << "the inner loops lost nothing";
  ContactBegin(b, &s, 1.0); // a new contact: the ball has recovered
  ContactSwitch(b, &s, ContactPhase::Loading, 0.0);
  EXPECT_NEAR(ContactForce(b, s, 0.5e-3), k1 * 0.5e-3, 1e-12 * k1 * 0.5e-3);
}

TEST(ContactLaw, HysteresisStiffnessIsTheDerivativeOfTheForce)
{
  const BallParams b = BallWithLaw("hysteresis");
  ContactState     s;
  ContactSwitch(b, &s, ContactPhase::Unloading, 1.2e-3);
  for (double c : {2e-4, 7e-4, 1.1e-3}) {
    const double h = 1e-9, fd = (ContactForce(b, s, c + h) - ContactForce(b, s, c - h)) / (2 * h);
    EXPECT_NEAR(ContactStiffness(b, s, c), fd, 1e-6 * std::abs(fd));
  }
  EXPECT_TRUE(ContactHasHysteresis(b) && !ContactElastic(b) && !ContactLinear(b));
}

TEST(RigidBody, EffectiveMassAndLimits)
{
  const double M = 0.57, L = 1.1, I = M * L * L / 12;
  EXPECT_DOUBLE_EQ(RigidEffectiveMass(M, I, 0.0), M);                   // at the centre of mass
  EXPECT_NEAR(RigidEffectiveMass(M, I, L / 2), M / 4, 1e-15);            // at an end: M/(1+3)
  EXPECT_NEAR(RigidACOR(1e-9, M, 0.0), 1.0, 1e-8);                       // light ball, no loss
  EXPECT_NEAR(RigidACOR(0.042, 0.042, 0.0), 0.0, 1e-15);                 // equal masses stop
  EXPECT_LT(RigidACOR(1.0, 0.5, 0.0), 0.0);                              // heavy ball keeps going
  EXPECT_NEAR(RigidACOR(1e-9, 1.0, 0.19), std::sqrt(0.81), 1e-8);        // wall with loss: e = sqrt(1-f)
  EXPECT_TRUE(std::isnan(RigidACOR(0.042, 0.1, 0.9)));                   // more loss than energy
}

// Eq. (11) and its forced fit against the collision itself: a ball (m, speed 1) rebounding at
// -e from a free mass M_e at rest gives it M_e V = m (1 + e) (momentum), and the collision has
// lost f = 1 - (m e^2 + M_e V^2) / m of the incident energy (a collision: f >= 0 and the ball
// not faster than the body, -e <= V). Both formulas must return that pair (e, f), each from
// the other.
TEST(RigidBody, Equation11AndItsForcedFitAgreeWithMomentumAndEnergy)
{
  const double m = 0.042;
  for (double Me : {0.01, 0.1, 0.3, 1.0})
    for (double e : {-0.3, 0.0, 0.2, 0.45, 0.7}) {
      const double V = m * (1 + e) / Me, f = 1 - (m * e * e + Me * V * V) / m;
      if (f < 0 || -e > V) continue; // energy created, or the ball passing through the body: not a collision
      EXPECT_NEAR(RigidACOR(m, Me, f), e, 1e-12) << "M_e = " << Me << ", f = " << f;
      EXPECT_NEAR(RigidForcedLossFraction(m, Me, e), f, 1e-12) << "M_e = " << Me << ", e = " << e;
    }
}

// The Hertz ball F = k c^(3/2) on a rigid wall (power law p = 3/2): c_max = ((p+1) m v^2/(2k))^(1/(p+1))
// and t = 2 (c_max/v) B(1/(p+1), 1/2)/(p+1) (the Beta function from tgamma here), e = 1; the
// law's closed forms and an RK4 bounce under F = k c^(3/2) written here must both give them,
// and the contact time falls with speed as v^(-1/5).
TEST(ContactLaw, HertzOnARigidWallAgainstTheClosedForm)
{
  const double p = 1.5;
  for (double k : {5e5, 3e7})
    for (double v : {0.5, 1.0, 10.0, 40.0}) {
      BallParams b = BallWithLaw("hertz");
      b.mass       = 0.145;
      b.speed      = v;
      ASSERT_TRUE(BallValueSet(&b, "hertz_k", k));
      const double c_max = std::pow((p + 1) * b.mass * v * v / (2 * k), 1 / (p + 1));
      const double a = 1 / (p + 1), beta = std::tgamma(a) * std::tgamma(0.5) / std::tgamma(a + 0.5);
      const double tau = 2 * c_max / v * beta / (p + 1);
      EXPECT_NEAR(ContactWallMaxCompression(b, v) / c_max, 1.0, 1e-14);
      EXPECT_NEAR(ContactWallTime(b, v) / tau, 1.0, 1e-13);
      EXPECT_EQ(BallCorAt(b, v), 1.0);
      const WallBounce w = Bounce([&](double c) { return c > 0 ? k * std::pow(c, p) : -k * std::pow(-c, p); }, [](double) {}, b.mass, v, c_max / v / 20000);
      EXPECT_NEAR(w.max_compression / c_max, 1.0, 1e-9) << "k = " << k << ", v = " << v;
      EXPECT_NEAR(w.contact_time / tau, 1.0, 1e-8) << "k = " << k << ", v = " << v;
      EXPECT_NEAR(w.cor, 1.0, 1e-9);
      EXPECT_NEAR(ContactWallTime(b, v) / ContactWallTime(b, 1.0), std::pow(v, -0.2), 1e-13);
      ContactState s;
      EXPECT_NEAR(ContactForce(b, s, c_max), k * std::pow(c_max, 1.5), 1e-13 * k * std::pow(c_max, 1.5));
      EXPECT_NEAR(ContactStoredEnergy(b, s, c_max), 0.5 * b.mass * v * v, 1e-13 * b.mass * v * v) << "all the kinetic energy stored at c_max";
    }
  const BallParams b = BallWithLaw("hertz");
  EXPECT_TRUE(ContactElastic(b) && !ContactLinear(b) && !ContactHasHysteresis(b));
  EXPECT_EQ(BallValue(b, "hertz_k"), 5e5);
}

namespace {

// A stepper of time alone for the event locator: the indicator of a falling event (a
// separation, post side c <= 0) is te - t, but a re-step shorter than 1e-3 s lands `bias`
// higher (on the pre side past te): the same time reached by another path gives another
// sign, as round-off does on a grid beyond double precision (N = 40961). Every step must be
// of positive length.
class PathStepper : public Stepper {
public:
  PetscReal t = 0, t0 = 0, h = 1, te = 1, bias = 0;
  PetscInt  bad_steps = 0;
  MPI_Comm       Comm() const override { return PETSC_COMM_SELF; }
  std::string    Method() const override { return "a path-dependent stepper"; }
  std::string    StepOption() const override { return "-none"; }
  PetscReal      Time() const override { return t; }
  PetscErrorCode Step(PetscReal dt) override
  {
    if (!(dt > 0)) bad_steps++;
    t0 = t, h = dt, t += dt;
    return 0;
  }
  PetscErrorCode RollBack() override { return t = t0, 0; }
  PetscErrorCode Restart() override { return 0; }
  PetscErrorCode NextStep(PetscReal *dt) override { return *dt = 1, 0; }
  PetscErrorCode Compression(PetscReal *c, PetscReal *cdot) override
  {
    *c    = te - t + (h < 1e-3 ? bias : 0.0);
    *cdot = -1;
    return 0;
  }
  PetscErrorCode ViewBegin(StateView *) override { return 0; }
  PetscErrorCode ViewEnd(StateView *) override { return 0; }
  PetscErrorCode GatherFields(PetscInt, PetscInt, std::vector<PetscReal> *) override { return 0; }
  PetscErrorCode Counts(StepperCounts *) override { return 0; }
  std::string    EnergyGrowthCause() const override { return ""; }
  PetscErrorCode SetState(PetscReal, const FullState &) override { return 0; }
};

} // namespace

// The bracket closes on its pre side (the step to the bracket's post end lands short of the
// root by another path): the locator steps on past it, never by a step of length 0 (cn at
// N = 40961 took one and stopped on a NaN residual), and ends on the post side or on the root
// (within the tolerance), within a few of its least steps (1e-4 of the crossed step) of where
// this path crosses.
TEST(ContactEvents, ABracketClosedOnItsPreSideIsSteppedPast)
{
  PathStepper     st;
  const PetscReal ta = 1.0 - 5e-4, min_step = 1e-4 * (5e-4 + 7.5e-8);
  st.bias = 3 * min_step;
  st.t0   = ta;
  st.t    = 1.0 + 7.5e-8; // the crossed step's end, on the post side
  st.h    = st.t - ta;
  EventIndicators a, b;
  a.c = st.te - ta;
  b.c = st.te - st.t;
  PetscInt steps = 0;
  auto     indicators = [&st](EventIndicators *g) { return st.Compression(&g->c, &g->cdot); };
  PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
  const PetscErrorCode ierr = EventLocate(st, ContactEventKind::Separation, ta, a.c, b.c, 1e-12, indicators, &steps);
  PetscPopErrorHandler();
  EXPECT_EQ(ierr, 0) << "the event was not located";
  EXPECT_EQ(st.bad_steps, 0) << "a step of length <= 0";
  EventIndicators g;
  indicators(&g);
  EXPECT_LE(g.c, 1e-12) << "the locator ended on the pre side, farther from the root than its tolerance";
  EXPECT_NEAR(st.t, st.te + st.bias, 2 * min_step);
}

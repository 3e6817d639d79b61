// Contact laws and the rigid-body formula against closed forms.
#include "model/contact.hpp"
#include "model/rigid.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace beamimpact;

TEST(ContactLaw, LinearSpringForceEnergyAndWallTime)
{
  BallParams   b; // k = 2e4 N/m, 42 g
  ContactState s;
  EXPECT_DOUBLE_EQ(ContactForce(b, s, 1e-3), 20.0);
  EXPECT_DOUBLE_EQ(ContactStiffness(b, s, 1e-3), 2e4);
  EXPECT_DOUBLE_EQ(ContactStoredEnergy(b, s, 1e-3), 0.5 * 2e4 * 1e-6);
  EXPECT_NEAR(ContactWallTimeLinear(b), M_PI * std::sqrt(0.042 / 2e4), 1e-15);
  EXPECT_NEAR(ContactCompressionScale(b), std::sqrt(0.042 / 2e4), 1e-15);
  s.phase = ContactPhase::Separated;
  EXPECT_EQ(ContactForce(b, s, 1e-3), 0.0);
  EXPECT_EQ(ContactStiffness(b, s, 1e-3), 0.0);
}

// On a rigid wall the ball stores 1/2 m v^2 = k1 c^(m+1)/(m+1) while loading and returns
// k2 c_max^(n+1)/(n+1) while unloading: e^2 = (m+1)/(n+1) whatever the speed.
TEST(ContactLaw, HysteresisReturnsRestitutionSquaredOnAWall)
{
  for (double speed : {0.1, 1.0, 40.0}) {
    BallParams b;
    b.law   = ContactLawKind::Hysteresis;
    b.speed = speed;
    const double E_in  = 0.5 * b.mass * speed * speed;
    const double c_max = ContactCompressionScale(b);
    ContactState s;
    EXPECT_NEAR(ContactStoredEnergy(b, s, c_max), E_in, 1e-12 * E_in);
    const double W_before = ContactWork(b, s, c_max);
    ContactSwitch(b, &s, ContactPhase::Unloading, c_max);
    EXPECT_NEAR(ContactWork(b, s, c_max), W_before, 1e-12 * E_in) << "W must be continuous at the switch";
    EXPECT_NEAR(ContactForce(b, s, c_max), b.k1 * std::pow(c_max, b.m), 1e-12 * b.k1 * c_max) << "force continuous at c_max";
    const double E_out = ContactStoredEnergy(b, s, c_max);
    EXPECT_NEAR(E_out / E_in, (b.m + 1) / (b.n + 1), 1e-12);
    EXPECT_NEAR(std::sqrt(E_out / E_in), ContactWallRestitution(b), 1e-12);
    // After unloading to c = 0 everything not returned is dissipated: the cycle loss formula.
    EXPECT_NEAR(ContactWork(b, s, 0.0), ContactCycleLoss(b, c_max), 1e-12 * E_in);
    EXPECT_NEAR(ContactWork(b, s, 0.0), E_in - E_out, 1e-12 * E_in);
  }
}

TEST(ContactLaw, HysteresisStiffnessIsTheDerivativeOfTheForce)
{
  BallParams b;
  b.law = ContactLawKind::Hysteresis;
  ContactState s;
  ContactSwitch(b, &s, ContactPhase::Unloading, 1.2e-3);
  for (double c : {2e-4, 7e-4, 1.1e-3}) {
    const double h = 1e-9, fd = (ContactForce(b, s, c + h) - ContactForce(b, s, c - h)) / (2 * h);
    EXPECT_NEAR(ContactStiffness(b, s, c), fd, 1e-6 * std::abs(fd));
  }
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

TEST(RigidBody, ForcedLossFractionInvertsEquation11)
{
  for (double f : {0.0, 0.2, 0.6})
    for (double Me : {0.1, 0.3, 1.0}) EXPECT_NEAR(RigidForcedLossFraction(0.042, Me, RigidACOR(0.042, Me, f)), f, 1e-12);
}

// The exact modal reference against a tight-tolerance TS run of the same semi-discrete
// model (to 1e-9), the wall and rigid-body limits, and energy conservation.
#include "run/modal_reference.hpp"
#include "model/rigid.hpp"
#include "test_helpers.hpp"

#include <cmath>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {
ImpactResult Modal(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip)
{
  ImpactResult r;
  EXPECT_EQ(ModalReferenceRun(Scenario{beam, ball, ip, MonitorRequest()}, &r), 0);
  return r;
}
const std::vector<std::pair<std::string, std::string>> TIGHT = {{"-ts_type", "rk"}, {"-ts_rk_type", "5dp"}, {"-ts_rtol", "1e-13"}, {"-ts_atol", "1e-15"}};
} // namespace

TEST(ModalReference, MatchesATightRunToOneInABillion)
{
  struct Case {
    BeamParams beam;
    double     x;
    PetscInt   contacts;
  };
  const std::vector<Case> cases = {{AluminiumBeam(1.1, 41), 0.9, 1}, {AluminiumBeam(1.1, 41), 0.55, 1}, {AluminiumBeam(0.3, 41, Support::Clamped, Support::Free), 0.29, 2}};
  for (const Case &c : cases) {
    ImpactParams ip;
    ip.x                   = c.x;
    const BallParams   b   = Superball();
    const ImpactResult ref = Modal(c.beam, b, ip);
    const ImpactResult ts  = RunImpact(PETSC_COMM_SELF, c.beam, b, ip, TIGHT);
    EXPECT_EQ(ref.contacts, c.contacts) << "x = " << c.x;
    EXPECT_EQ(ts.contacts, ref.contacts);
    EXPECT_NEAR(ts.acor, ref.acor, 1e-9) << "x = " << c.x;
    EXPECT_NEAR(ts.contact_time, ref.contact_time, 1e-9 * ref.contact_time);
    EXPECT_NEAR(ts.peak_force, ref.peak_force, 1e-9 * ref.peak_force);
    EXPECT_NEAR(ts.max_compression, ref.max_compression, 1e-9 * ref.max_compression);
    EXPECT_NEAR(ts.contact_time_total, ref.contact_time_total, 1e-8 * ref.contact_time_total);
    EXPECT_LT(std::abs(ref.energy_error), 1e-10);
  }
}

TEST(ModalReference, WallLimit)
{
  const BeamParams wall = WallBeam(1e12, 1e7);
  ImpactParams ip;
  ip.x                 = 0.55;
  const BallParams   b = Superball();
  const ImpactResult r = Modal(wall, b, ip);
  EXPECT_NEAR(r.contact_time / (M_PI * std::sqrt(b.mass / b.k)), 1.0, 1e-6);
  EXPECT_NEAR(r.acor, 1.0, 1e-6);
  EXPECT_NEAR(r.peak_force / (b.speed * std::sqrt(b.mass * b.k)), 1.0, 1e-6);
}

TEST(ModalReference, RigidBeamLimitFollowsEquation11)
{
  BeamParams beam = AluminiumBeam(1.1, 41);
  beam.EI *= 1e6; // stiffer still and the dense eigen-solve loses accuracy (see modal_reference.hpp)
  const BeamOperator op = BeamOperatorBuild(beam);
  double             M = 0, I = 0;
  for (PetscInt i = 0; i < op.N; ++i) M += op.mass[i];
  for (PetscInt i = 0; i < op.N; ++i) I += op.mass[i] * std::pow(i * op.h - beam.length / 2, 2);
  for (double x : {0.55, 0.7, 0.95, 1.1}) {
    ImpactParams ip;
    ip.x                 = x;
    ip.window            = 1e-3;
    const BallParams   b = Superball();
    const ImpactResult r = Modal(beam, b, ip);
    EXPECT_NEAR(r.acor, RigidACOR(b.mass, RigidEffectiveMass(M, I, x - beam.length / 2), 0.0), 2e-4) << "x = " << x;
  }
}

TEST(ModalReference, RefusesTheHystereticLaw)
{
  ImpactParams ip;
  ImpactResult r;
  ASSERT_EQ(PetscPushErrorHandler(PetscReturnErrorHandler, NULL), 0);
  EXPECT_NE(ModalReferenceRun(Scenario{AluminiumBeam(1.1), Superball(ContactLawKind::Hysteresis), ip, MonitorRequest()}, &r), 0);
  ASSERT_EQ(PetscPopErrorHandler(), 0);
}

// Two fields a node (field 1 an uncoupled copy of the beam, masses x3, that the ball does not
// touch): the reference on the two-field system is the one-field reference, single and double
// contacts alike; the coupling goes through the deflection dofs, not node indices.
TEST(ModalReference, TwoFieldSystemGivesTheOneFieldResult)
{
  struct Case {
    BeamParams beam;
    double     x;
  };
  for (const Case &c : {Case{AluminiumBeam(1.1, 41), 0.9}, Case{AluminiumBeam(0.3, 41, Support::Clamped, Support::Free), 0.29}}) {
    ImpactParams ip;
    ip.x                 = c.x;
    const Scenario   sc  = {c.beam, Superball(), ip, MonitorRequest()};
    const BeamSystem one = SystemOf(c.beam);
    ImpactResult     r1, r2;
    ASSERT_EQ(ModalReferenceRunSystem(sc, one, &r1), 0);
    ASSERT_EQ(ModalReferenceRunSystem(sc, TwoFieldCopies(one, 3.0), &r2), 0);
    EXPECT_EQ(r1.contacts, r2.contacts) << "x = " << c.x;
    EXPECT_EQ(r1.events.size(), r2.events.size());
    EXPECT_NEAR(r1.acor, r2.acor, 1e-11);
    EXPECT_NEAR(r1.contact_time, r2.contact_time, 1e-11 * r1.contact_time);
    EXPECT_NEAR(r1.contact_time_total, r2.contact_time_total, 1e-11 * r1.contact_time_total);
    EXPECT_NEAR(r1.peak_force, r2.peak_force, 1e-11 * r1.peak_force);
    EXPECT_NEAR(r1.beam_kinetic_end + r1.beam_strain_end, r2.beam_kinetic_end + r2.beam_strain_end, 1e-10 * (r1.beam_kinetic_end + r1.beam_strain_end));
    EXPECT_LT(std::abs(r2.energy_error), 1e-10);
  }
}

// The modal integrator -ts_type modal (src/solvers/ts_modal.hpp) through the impact driver:
// observed order 2 and 4 of the ACOR against the exact modal reference (linear ball, paper
// beam, N = 41 and 161), no stability limit from the beam (a step 100x the RK4 limit runs and
// converges), the hysteretic ball against a tight rk run, the energy balance, the events of
// the 30 cm clamped double impact, and the same result on 1 and 2 ranks.
#include "run/modal_reference.hpp"
#include "test_helpers.hpp"

#include <cmath>
#include <string>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

ImpactResult Modal(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, int order, double dt)
{
  return RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "modal"}, {"-ts_modal_order", std::to_string(order)}, {"-ts_dt", std::to_string(dt)}});
}

ImpactResult Reference(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip)
{
  ImpactResult r;
  EXPECT_EQ(ModalReferenceRun(Scenario{beam, ball, ip, MonitorRequest()}, &r), 0);
  return r;
}

ImpactParams Centre()
{
  ImpactParams ip;
  ip.x      = 0.55;
  ip.window = 0;
  return ip;
}

} // namespace

TEST(TSModal, ObservedOrder)
{
  for (PetscInt N : {41, 161}) {
    const BeamParams   beam = AluminiumBeam(1.1, N);
    const ImpactResult ref  = Reference(beam, Superball(), Centre());
    for (int order : {2, 4}) {
      const double dt0 = order == 2 ? 1e-4 : 1e-4;
      double       e[3];
      for (int l = 0; l < 3; ++l) {
        const ImpactResult r = Modal(beam, Superball(), Centre(), order, dt0 / (1 << l));
        EXPECT_EQ(r.contacts, ref.contacts);
        e[l] = std::abs(r.acor - ref.acor);
      }
      const double p = std::log2(e[0] / e[2]) / 2;
      EXPECT_NEAR(p, order, 0.6) << "N = " << N << " order " << order << ": errors " << e[0] << " " << e[1] << " " << e[2];
      EXPECT_LT(e[2], order == 2 ? 1e-5 : 1e-7);
    }
  }
}

TEST(TSModal, NoStabilityLimitFromTheBeam)
{
  const BeamParams   beam = AluminiumBeam(1.1, 161);
  const ImpactResult ref  = Reference(beam, Superball(), Centre());
  const ImpactResult rk   = RunImpact(PETSC_COMM_WORLD, beam, Superball(), Centre(), {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}});
  ASSERT_GT(rk.dt_stable, 0);
  double prev = 1;
  for (double f : {100.0, 50.0, 25.0}) {
    const ImpactResult r = Modal(beam, Superball(), Centre(), 4, f * rk.dt_stable);
    const double       e = std::abs(r.acor - ref.acor);
    EXPECT_LT(e, 1e-4) << f << " x the RK4 limit";
    EXPECT_LT(e, prev) << f << " x the RK4 limit";
    EXPECT_LT(std::abs(r.energy_error), 1e-4);
    prev = e;
  }
}

TEST(TSModal, HystereticBallAsTightRK)
{
  const BeamParams   beam = AluminiumBeam(1.1, 41);
  const BallParams   ball = Superball("hysteresis");
  const ImpactResult rk   = RunImpact(PETSC_COMM_WORLD, beam, ball, Centre(), {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}});
  const ImpactResult m    = Modal(beam, ball, Centre(), 4, 2.5e-5);
  EXPECT_EQ(m.contacts, rk.contacts);
  EXPECT_NEAR(m.acor, rk.acor, 1e-7);
  EXPECT_LT(std::abs(m.energy_error), 1e-7);
}

TEST(TSModal, EnergyBalance)
{
  const ImpactResult r = Modal(AluminiumBeam(1.1, 41), Superball(), Centre(), 4, 5e-5);
  EXPECT_LT(std::abs(r.energy_error), 1e-7);
}

// The 30 cm clamped beam struck at 29 cm catches the ball again: as many contacts as the
// exact reference, at its times.
TEST(TSModal, DoubleImpactEvents)
{
  const BeamParams beam = AluminiumBeam(0.3, 41, Support::Clamped, Support::Free);
  ImpactParams     ip;
  ip.x                   = 0.29;
  const ImpactResult ref = Reference(beam, Superball(), ip);
  const ImpactResult m   = Modal(beam, Superball(), ip, 4, 5e-5);
  EXPECT_GE(ref.contacts, 2);
  EXPECT_EQ(m.contacts, ref.contacts);
  EXPECT_NEAR(m.acor, ref.acor, 1e-6);
}

// Run on 1 and 2 ranks (the physical Vec distributed, the modal state on every rank).
TEST(TSModalParallel, SameAsReference)
{
  const BeamParams   beam = AluminiumBeam(1.1, 41);
  const ImpactResult ref  = Reference(beam, Superball(), Centre());
  const ImpactResult m    = Modal(beam, Superball(), Centre(), 4, 5e-5);
  EXPECT_NEAR(m.acor, ref.acor, 1e-8);
  EXPECT_EQ(m.contacts, ref.contacts);
}

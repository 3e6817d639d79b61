// One impact through the PETSc TS problem, against closed forms and invariants:
// the wall limit, the rigid-body limit (Eq. 11), energy and momentum, and the
// same answer on 1 and 2 ranks. Runs at np1 and np2.
#include "model/contact.hpp"
#include "model/rigid.hpp"
#include "test_helpers.hpp"

#include <cmath>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {
const std::vector<std::pair<std::string, std::string>> CN_FINE = {{"-ts_type", "cn"}, {"-ts_dt", "1e-6"}};

BeamParams Wall() { return WallBeam(1e10, 1e5); }
} // namespace

TEST(WallLimit, LinearSpringContactTimeAndACOR)
{
  const BallParams   ball = Superball();
  ImpactParams       ip;
  ip.x                 = 0.55;
  const ImpactResult r = RunImpact(PETSC_COMM_WORLD, Wall(), ball, ip, CN_FINE);
  const double       T = M_PI * std::sqrt(ball.mass / BallValue(ball, "k"));
  EXPECT_NEAR(r.contact_time / T, 1.0, 1e-4);
  EXPECT_NEAR(r.acor, 1.0, 1e-4);
  EXPECT_NEAR(r.acor_corrected, 0.85, 1e-4);
  EXPECT_NEAR(r.peak_force / (ball.speed * std::sqrt(ball.mass * BallValue(ball, "k"))), 1.0, 1e-4);
  EXPECT_NEAR(r.max_compression / (ball.speed * std::sqrt(ball.mass / BallValue(ball, "k"))), 1.0, 1e-4);
  EXPECT_EQ(r.contacts, 1);
}

TEST(WallLimit, HysteresisRestitutionAndCycleLoss)
{
  const BallParams ball = Superball("hysteresis");
  ImpactParams     ip;
  ip.x                 = 0.55;
  const ImpactResult r = RunImpact(PETSC_COMM_WORLD, Wall(), ball, ip, CN_FINE);
  EXPECT_NEAR(r.acor, std::sqrt((BallValue(ball, "m") + 1) / (BallValue(ball, "n") + 1)), 1e-4);
  EXPECT_NEAR(r.acor_corrected, r.acor, 0) << "no extra correction with the hysteretic ball";
  EXPECT_NEAR(r.ball_dissipated_end / ContactCycleLoss(ball, r.max_compression), 1.0, 1e-4);
  const double E_in = 0.5 * ball.mass * ball.speed * ball.speed;
  EXPECT_NEAR(r.acor * r.acor, 1 - r.ball_dissipated_end / E_in, 1e-4);
  EXPECT_EQ(r.contacts, 1);
}

// A very stiff free beam: Eq. (11) with f = 0, with the beam's discrete mass and inertia.
TEST(RigidBeamLimit, StiffFreeBeamFollowsEquation11)
{
  BeamParams beam = AluminiumBeam(1.1, 41);
  beam.EI *= 1e6;
  const BeamSystem sys = SystemOf(beam);
  double           M = 0, I = 0;
  for (PetscInt i = 0; i < sys.nodes; ++i) M += sys.mass[i];
  for (PetscInt i = 0; i < sys.nodes; ++i) I += sys.mass[i] * std::pow(i * sys.h - beam.length / 2, 2);
  EXPECT_NEAR(I / (M * beam.length * beam.length / 12), 1.0, 2e-3) << "discrete inertia close to M L^2/12";
  for (double x : {0.55, 0.8, 1.0}) {
    for (double ball_mass : {0.042, 2.0}) { // 2 kg: heavier than the beam, the ACOR is negative
      BallParams ball = Superball();
      ball.mass       = ball_mass;
      ImpactParams ip;
      ip.x                  = x;
      ip.window             = 1e-3;
      const ImpactResult r  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, CN_FINE);
      const double       e  = RigidACOR(ball.mass, RigidEffectiveMass(M, I, x - beam.length / 2), 0.0);
      const double       ec = RigidACOR(ball.mass, RigidEffectiveMass(M, M * beam.length * beam.length / 12, x - beam.length / 2), 0.0);
      EXPECT_NEAR(r.acor, e, 2e-4) << "x = " << x << " m_b = " << ball_mass;
      EXPECT_NEAR(r.acor, ec, 3e-3) << "continuum inertia, x = " << x;
      if (ball_mass > 1) {
        EXPECT_LT(r.acor, 0);
      }
      EXPECT_EQ(r.contacts, 1);
    }
  }
}

// Linear spring on the flexible free beam: energy (with the ball's work) is conserved by
// Crank-Nicolson to round-off and by RK4 to its truncation error; linear and angular
// momentum to round-off by both (they are linear invariants of the semi-discrete system).
TEST(Invariants, EnergyAndMomentumWithTheLinearSpring)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball();
  ImpactParams     ip;
  ip.x = 0.9;
  {
    const ImpactResult r = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}});
    EXPECT_LT(std::abs(r.energy_error), 1e-9);
    EXPECT_LT(std::abs(r.linear_momentum_error), 1e-12);
    EXPECT_LT(std::abs(r.angular_momentum_error), 1e-12);
    EXPECT_GT(r.beam_kinetic_end + r.beam_strain_end, 0.05 * 0.5 * ball.mass) << "the beam vibrates";
  }
  {
    const ImpactResult r = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-5"}});
    EXPECT_LT(std::abs(r.energy_error), 1e-5);
    EXPECT_LT(std::abs(r.linear_momentum_error), 1e-12);
    EXPECT_LT(std::abs(r.angular_momentum_error), 1e-12);
  }
}

// With the hysteretic ball the total including the dissipated work is conserved to the
// integrator's accuracy (the unloading force is nonlinear, so Crank-Nicolson is no longer
// exact): the error falls at second order, and the energy series adds up at every step.
TEST(Invariants, HysteresisEnergyBalanceEveryStep)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball("hysteresis");
  ImpactParams     ip;
  ip.x     = 0.9;
  ip.window = 5e-3;
  MonitorRequest mon;
  mon.energy            = PETSC_TRUE;
  mon.ball              = PETSC_TRUE;
  const ImpactResult r  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}}, mon);
  const double       E0 = 0.5 * ball.mass * ball.speed * ball.speed;
  EXPECT_LT(std::abs(r.energy_error), 1e-5);
  const ImpactResult r2 = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "2.5e-6"}});
  EXPECT_NEAR(r.energy_error / r2.energy_error, 4.0, 0.8) << "second-order energy error";
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    ASSERT_GT(r.series.time.size(), 100u);
    double max_dev = 0, min_diss = 0;
    for (size_t k = 0; k < r.series.time.size(); ++k) {
      const double sum = r.series.ball_kinetic[k] + r.series.ball_stored[k] + r.series.ball_dissipated[k] + r.series.beam_kinetic[k] + r.series.beam_strain[k];
      max_dev          = std::max(max_dev, std::abs(sum - E0) / E0);
      min_diss         = std::min(min_diss, r.series.ball_dissipated[k]);
    }
    EXPECT_NEAR(max_dev, std::abs(r.energy_error), 2e-6);
    EXPECT_LT(max_dev, 1e-5);
    EXPECT_GE(min_diss, -1e-12 * E0);
    EXPECT_GT(r.ball_dissipated_end, 0.01 * E0);
  }
}

// The same impact on the whole communicator (DMDA distributed) and on each rank alone.
TEST(Parallel, SameACOROnOneAndAllRanks)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball();
  ImpactParams     ip;
  ip.x      = 0.9;
  ip.window = 5e-3;
  for (auto opts : std::vector<std::vector<std::pair<std::string, std::string>>>{{{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-5"}},
                                                                                   {{"-ts_type", "cn"}, {"-ts_dt", "1e-5"}}}) {
    const ImpactResult all  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, opts);
    const ImpactResult self = RunImpact(PETSC_COMM_SELF, beam, ball, ip, opts);
    EXPECT_NEAR(all.acor, self.acor, 1e-10) << opts[0].second;
    EXPECT_NEAR(all.contact_time, self.contact_time, 1e-10 * self.contact_time);
    EXPECT_NEAR(all.peak_force, self.peak_force, 1e-9 * self.peak_force);
    EXPECT_EQ(all.contacts, self.contacts);
    EXPECT_EQ(all.steps, self.steps);
  }
}

// Snapshots land exactly on the requested times; velocity monitors have one value per step.
TEST(Monitors, SnapshotsAndPointVelocities)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball();
  ImpactParams     ip;
  ip.x      = 0.55;
  ip.window = 2e-3;
  MonitorRequest mon;
  mon.snapshot_times   = {0.0, 1e-3, 3.3e-3};
  mon.velocity_at      = {0.0, 1.1};
  const ImpactResult r = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "1e-5"}}, mon);
  PetscMPIInt        rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    ASSERT_EQ(r.series.snapshot_time.size(), 3u);
    for (double y : r.series.snapshot_y[0]) EXPECT_EQ(y, 0.0);
    ASSERT_EQ(r.series.snapshot_y[1].size(), 41u);
    EXPECT_GT(r.series.snapshot_y[1][20], 0.0) << "the struck centre moves in +y";
    EXPECT_NEAR(r.series.snapshot_y[1][10], r.series.snapshot_y[1][30], 1e-12) << "symmetric impact, symmetric beam";
    ASSERT_EQ(r.series.velocity_at.size(), 2u);
    EXPECT_EQ(r.series.velocity_at[0].size(), r.series.time.size());
    EXPECT_NEAR(r.series.velocity_at[0].back(), r.series.velocity_at[1].back(), 1e-12);
    EXPECT_TRUE(r.series.force.empty()) << "only what was asked for is recorded";
  }
}

// Near the free tip of the 30 cm beam clamped at x = 0 the vibrating beam comes back and
// strikes the ball again: the run continues after the first separation and counts it.
TEST(DoubleImpact, ClampedThirtyCentimetreBeamNearTheTip)
{
  const BeamParams beam = AluminiumBeam(0.3, 41, Support::Clamped, Support::Free);
  const BallParams ball = Superball();
  ImpactParams     ip;
  ip.x                 = 0.29;
  const ImpactResult r = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}});
  EXPECT_GE(r.contacts, 2);
  PetscInt starts = 0, separations = 0;
  double   last_sep = -1;
  for (const ContactEvent &e : r.events) {
    if (e.kind == ContactEventKind::ContactStart) {
      starts++;
      EXPECT_GT(e.time, last_sep) << "a contact starts only after the previous one ended";
    }
    if (e.kind == ContactEventKind::Separation) {
      separations++;
      last_sep = e.time;
      EXPECT_NEAR(e.compression, 0.0, 1e-9) << "separation located at c = 0";
    }
  }
  EXPECT_EQ(starts, r.contacts);
  EXPECT_EQ(separations, r.contacts);
  EXPECT_LT(r.contact_time, r.contact_time_total);
  EXPECT_LT(std::abs(r.energy_error), 1e-9);
  // Away from the tip the same beam gives a single contact.
  ip.x                  = 0.15;
  const ImpactResult r1 = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}});
  EXPECT_EQ(r1.contacts, 1);
}

// Where the incident energy went: ball loss + beam translation + rotation + vibration +
// the ball's rebound kinetic energy add up to the incident energy; a rigid beam does not vibrate.
TEST(EnergyPartition, FractionsAddUpAndRigidBeamDoesNotVibrate)
{
  const BallParams ball = Superball("hysteresis");
  ImpactParams     ip;
  ip.x                   = 0.9;
  const BeamParams flex  = AluminiumBeam(1.1, 41);
  const ImpactResult r   = RunImpact(PETSC_COMM_WORLD, flex, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}});
  const double       sum = r.ball_loss_fraction + r.translation_fraction + r.rotation_fraction + r.vibration_fraction + r.acor * r.acor;
  EXPECT_NEAR(sum, 1.0 + r.energy_error, 1e-12);
  EXPECT_GT(r.vibration_fraction, 0.1) << "the flexible beam keeps a good part in vibration";
  BeamParams stiff = flex;
  stiff.EI *= 1e6;
  ip.window              = 1e-3;
  const ImpactResult rr  = RunImpact(PETSC_COMM_WORLD, stiff, ball, ip, {{"-ts_type", "cn"}, {"-ts_dt", "1e-6"}});
  EXPECT_LT(std::abs(rr.vibration_fraction), 1e-3);
  EXPECT_NEAR(rr.ball_loss_fraction + rr.translation_fraction + rr.rotation_fraction + rr.acor * rr.acor, 1.0, 2e-3);
}

// Option lists have no fixed length: 300 snapshot times and 200 velocity points are all kept
// (they were silently cut at 256 and 64).
TEST(Monitors, ListsOfAnyLength)
{
  std::string times, points;
  for (int k = 0; k < 300; ++k) times += (k ? "," : "") + std::to_string(1e-5 * k);
  for (int k = 0; k < 200; ++k) points += (k ? "," : "") + std::to_string(1.1 * k / 199);
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-snapshot_times", times.c_str()));
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-monitor_velocity_at", points.c_str()));
  MonitorRequest m;
  EXPECT_EQ(0, MonitorRequestFromOptions(PETSC_COMM_WORLD, AluminiumBeam(1.1, 41), &m));
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-snapshot_times"));
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-monitor_velocity_at"));
  ASSERT_EQ(300u, m.snapshot_times.size());
  ASSERT_EQ(200u, m.velocity_at.size());
  EXPECT_NEAR(2.99e-3, m.snapshot_times.back(), 1e-15);
  EXPECT_NEAR(1.1, m.velocity_at.back(), 1e-6);
}

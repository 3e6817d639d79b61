// One impact through the PETSc TS problem, against closed forms and invariants:
// the wall limit, the rigid-body limit (Eq. 11), energy and momentum, and the
// same answer on 1 and 2 ranks. Runs at np1 and np2.
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "model/contact.hpp"
#include "model/rigid.hpp"
#include "model/swing.hpp"
#include "run/results_table.hpp"
#include "studies/sweep.hpp"
#include "test_helpers.hpp"

#include <hdf5.h>

#include <cmath>
#include <map>
#include <set>

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
  // The vibration is what the outcome computes as a remainder (the beam's energy less its rigid
  // parts, from the state's dofs and momenta); the energies the modal free flight gives each mode
  // (from its modal coordinates) must add up to it, and its two rigid modes are the translation
  // and the rotation. (This assertion used to add the fractions to 1 + energy_error: true of any
  // remainder whatever the vibration.)
  ASSERT_EQ("modal", r.after_used);
  ASSERT_EQ((size_t)flex.nodes, r.mode_energies.size()) << "at N = 41 every mode is kept";
  ASSERT_TRUE(r.mode_energies[0].rigid && r.mode_energies[1].rigid && !r.mode_energies[2].rigid);
  PetscReal flexible = 0;
  for (size_t k = 2; k < r.mode_energies.size(); ++k) flexible += r.mode_energies[k].fraction;
  EXPECT_NEAR(r.vibration_fraction, flexible, 1e-11);
  EXPECT_NEAR(r.translation_fraction, r.mode_energies[0].fraction, 1e-12);
  EXPECT_NEAR(r.rotation_fraction, r.mode_energies[1].fraction, 1e-12);
  EXPECT_NEAR(r.mode_energies[0].energy, r.mode_energies[0].fraction * 0.5 * ball.mass * ball.speed * ball.speed, 1e-15);
  EXPECT_GT(r.vibration_fraction, 0.1) << "the flexible beam keeps a good part in vibration";
  EXPECT_GT(r.mode_energies[2].fraction, r.mode_energies[6].fraction) << "struck at 0.9 m, the fundamental carries more than the fifth mode";
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

// ---------------------------------------------------------------------------------------------
// The results table: every column once, with a unit; NaN exactly where a column does not apply,
// in the run's result, in an impact file and in a sweep file.
// ---------------------------------------------------------------------------------------------

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

// /results of an HDF5 file: each dataset's values (as doubles; a string dataset: none) and its
// unit attribute ("" when it has none).
struct FileColumn {
  std::vector<double> v;
  std::string         unit;
  long long           applies = -1; // the attribute applies of an impact file's column (-1: none)
};
std::map<std::string, FileColumn> ReadResults(const std::string &path)
{
  std::map<std::string, FileColumn> out;
  hid_t                             f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << path;
  if (f < 0) return out;
  hid_t      g = H5Gopen2(f, "results", H5P_DEFAULT);
  H5G_info_t info;
  H5Gget_info(g, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    hid_t       d = H5Dopen2(g, name, H5P_DEFAULT);
    hid_t       t = H5Dget_type(d);
    FileColumn &c = out[name];
    if (H5Tget_class(t) == H5T_INTEGER || H5Tget_class(t) == H5T_FLOAT) {
      hid_t sp = H5Dget_space(d);
      c.v.resize((size_t)H5Sget_simple_extent_npoints(sp));
      if (!c.v.empty()) H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, c.v.data());
      H5Sclose(sp);
    }
    if (H5Aexists(d, "applies") > 0) {
      hid_t a = H5Aopen(d, "applies", H5P_DEFAULT);
      H5Aread(a, H5T_NATIVE_LLONG, &c.applies);
      H5Aclose(a);
    }
    if (H5Aexists(d, "unit") > 0) {
      hid_t             a  = H5Aopen(d, "unit", H5P_DEFAULT);
      hid_t             at = H5Aget_type(a);
      std::vector<char> buf(H5Tget_size(at) + 1, 0);
      H5Aread(a, at, buf.data());
      c.unit = buf.data();
      H5Tclose(at);
      H5Aclose(a);
    }
    H5Tclose(t);
    H5Dclose(d);
  }
  H5Gclose(g);
  H5Fclose(f);
  return out;
}

// The scenario of the paper's 1.1 m beam (N = 41) with the superball, and extra options.
Scenario PaperScene(const Opts &extra, const char *ball = "options/base/superball-linear.opts")
{
  Scenario sc;
  Opts     all{{"-beam_length", "1.1"}};
  all.insert(all.end(), extra.begin(), extra.end());
  test::ReadScene({"options/base/aluminium-6mm.opts", ball}, all, &sc.beam, &sc.ball);
  sc.impact.x      = 0.825;
  sc.impact.window = 1e-3;
  return sc;
}

const Opts kCN = {{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}};

ImpactResult RunScene(const Scenario &sc)
{
  for (auto &kv : kCN) EXPECT_EQ(PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()), 0);
  ImpactResult r;
  EXPECT_EQ(ImpactRun(PETSC_COMM_WORLD, sc, &r), 0);
  for (auto &kv : kCN) EXPECT_EQ(PetscOptionsClearValue(NULL, kv.first.c_str()), 0);
  return r;
}

// Every column of the table is NaN in row `row` of the file exactly where it does not apply to sc,
// and every /results dataset has a unit.
void ExpectFileFollowsTable(const std::string &what, const std::map<std::string, FileColumn> &file, const Scenario &sc, size_t row)
{
  for (auto &kv : file) EXPECT_FALSE(kv.second.unit.empty()) << what << ": /results/" << kv.first << " has no unit";
  for (const ResultColumn &c : ImpactResultColumns()) {
    const auto it = file.find(c.name);
    ASSERT_NE(it, file.end()) << what << ": no /results/" << c.name;
    ASSERT_GT(it->second.v.size(), row) << what << ": " << c.name;
    EXPECT_EQ(it->second.unit, c.unit) << what << ": " << c.name;
    if (it->second.applies >= 0) {
      EXPECT_EQ(it->second.applies == 1, c.Applies(sc)) << what << ": the attribute applies of /results/" << c.name;
    }
    EXPECT_EQ(std::isnan(it->second.v[row]), !c.Applies(sc)) << what << ": /results/" << c.name << " = " << it->second.v[row] << " where it " << (c.Applies(sc) ? "applies" : "does not apply")
                                                           << " (" << c.applies_text << ")";
  }
}

} // namespace

// Each column once, named, with a unit and a description; a count always applies (it cannot be
// NaN); every column but the stepper's counts and settings is computed by the outcome.
TEST(ResultsTable, EveryColumnDefinedOnce)
{
  std::set<std::string> names;
  for (const ResultColumn &c : ImpactResultColumns()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
    EXPECT_STRNE(c.unit, "") << c.name;
    EXPECT_STRNE(c.description, "") << c.name;
    EXPECT_STRNE(c.applies_text, "") << c.name;
    EXPECT_EQ((c.real != nullptr) + (c.count != nullptr) + (c.flag != nullptr) + (c.keyed >= 0), 1) << c.name;
    if (c.integer) { EXPECT_EQ(c.applies, &ResultAlways) << c.name << ": a count cannot be NaN"; }
    EXPECT_EQ(ImpactResultColumn(c.name), &c);
  }
  for (const char *cost : {"steps", "event_steps", "function_evals", "wall_time", "dt_nominal", "dt_stable"}) EXPECT_EQ(ImpactResultColumn(cost)->compute, nullptr) << cost;
  for (const char *physics : {"acor", "beam_dissipated_end", "damping_fraction", "rigid_acor", "bbcor", "segment_kinetic_peak"}) EXPECT_NE(ImpactResultColumn(physics)->compute, nullptr) << physics;
}

// One impact in each kind of scenario: the file written for it follows the table, and the
// columns that apply say what their formulas do.
TEST(ResultsTable, ImpactFileNaNExactlyWhereAColumnDoesNotApply)
{
  struct Case {
    const char *what;
    Opts        options;
  };
  const std::vector<Case> cases = {
    {"free beam at rest", {}},
    {"clamped end", {{"-beam_left", "clamped"}}},
    {"free pivot", {{"-beam_pivot", "0.275"}}},
    {"pivot and a pinned end", {{"-beam_pivot", "0.275"}, {"-beam_right", "pinned"}}},
    {"pivot and a clamped region", {{"-beam_pivot", "0.275"}, {"-beam_clamp", "0,0.1"}}},
    {"grip", {{"-grip", "0,0.15"}, {"-grip_stiffness", "1e5"}, {"-grip_damping", "100"}}},
    {"mass damping", {{"-beam_damping_mass", "2"}}},
  };
  char dir[] = "/tmp/beamimpact-results-XXXXXX";
  ASSERT_NE(nullptr, mkdtemp(dir));
  const double E_in = 0.5 * 0.042 * 1.0 * 1.0;
  for (size_t k = 0; k < cases.size() + 2; ++k) {
    Scenario    sc   = PaperScene(k < cases.size() ? cases[k].options : Opts{});
    std::string what = k < cases.size() ? cases[k].what : k == cases.size() ? "swinging bat" : "-monitor_segment";
    if (k == cases.size()) sc.swing.bat_speed = 0.5;
    if (k == cases.size() + 1) sc.monitor.segment = PETSC_TRUE, sc.monitor.segment_x0 = 0.9, sc.monitor.segment_x1 = 1.1;
    const ImpactResult r = RunScene(sc);
    for (const ResultColumn &c : ImpactResultColumns()) EXPECT_EQ(std::isnan(c.Get(r)), !c.Applies(sc)) << what << ": " << c.name;
    const std::string path = std::string(dir) + "/impact" + std::to_string(k) + ".h5";
    RunRecord         rec;
    ASSERT_EQ(0, RunRecordBuild(sc, &r, &rec));
    ASSERT_EQ(0, ResultsWriteImpactFile(PETSC_COMM_WORLD, path, rec, {r}, sc));
    PetscMPIInt rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank == 0) ExpectFileFollowsTable(what, ReadResults(path), sc, 0);
    // What the columns that apply say.
    EXPECT_TRUE(std::isfinite(r.beam_dissipated_end) && std::isfinite(r.damping_fraction)) << what << ": the dissipated energy is in every result";
    EXPECT_EQ(r.damping_fraction, r.beam_dissipated_end / E_in) << what;
    if (!sc.beam.parts.Has("grip") && sc.beam.damping_mass == 0) {
      EXPECT_EQ(r.beam_dissipated_end, 0.0) << what << ": an undamped beam dissipates nothing, a true 0";
    } else {
      EXPECT_GT(r.beam_dissipated_end, 0.0) << what;
    }
    if (ResultFreePivot(sc)) { EXPECT_NEAR(r.bbcor, r.collision_efficiency * (1 + r.recoil_factor) + r.recoil_factor, 1e-14) << what; }
    if (ResultFreeBeamAtRest(sc)) { // the forced fit is the loss fraction that makes Eq. (11) give acor_corrected
      const BeamRigidBody b  = BeamRigidBodyOf(sc.beam);
      const PetscReal     Me = RigidEffectiveMass(b.mass, b.inertia_cm, std::abs(sc.impact.x - b.x_cm));
      EXPECT_NEAR(RigidACOR(sc.ball.mass, Me, r.rigid_forced_loss_fraction), r.acor_corrected, 1e-12) << what;
      EXPECT_NEAR(r.rigid_acor, RigidACOR(sc.ball.mass, Me, 0.0), 1e-15) << what;
    }
    if (ResultMomentumInvariant(sc)) { EXPECT_LT(std::abs(r.linear_momentum_error), 1e-11) << what << ": momentum is an invariant here"; }
    EXPECT_TRUE(std::isfinite(r.scales.contact_time_scale) && r.scales.contact_time_scale > 0) << what;
  }
  // The cases the issue names: no BBCOR where the rig cannot turn freely, no rigid-body model for a held beam.
  EXPECT_TRUE(std::isnan(RunScene(PaperScene(cases[3].options)).bbcor));
  EXPECT_TRUE(std::isnan(RunScene(PaperScene(cases[1].options)).rigid_forced_loss_fraction));
}

// The impact's scales (root attributes of an impact file): T_r and the compression scale of the
// contact, for the linear spring against the free beam: T_c sqrt(M / (M + m_b)), T_c = pi sqrt(m_b/k),
// and v_i sqrt(m_b/k). (The ball's rigid-wall values are the law's, in the run record.)
TEST(ResultsTable, ScalesOfTheImpact)
{
  const Scenario     lin = PaperScene({});
  const ImpactResult r   = RunScene(lin);
  const PetscReal    k   = BallValue(lin.ball, "k");
  EXPECT_NEAR(r.scales.compression_scale, lin.ball.speed * std::sqrt(lin.ball.mass / k), 1e-15);
  const PetscReal M = lin.beam.mu * lin.beam.length; // the free beam's whole mass
  EXPECT_NEAR(r.scales.contact_time_scale, M_PI * std::sqrt(lin.ball.mass / k) * std::sqrt(M / (M + lin.ball.mass)), 1e-12 * r.scales.contact_time_scale);
  EXPECT_GT(r.contact_time, 0.5 * r.scales.contact_time_scale) << "the scale is the contact's order of magnitude";
  EXPECT_LT(r.contact_time, 2.0 * r.scales.contact_time_scale);
}

// A sweep's file: the same table, NaN exactly where a column does not apply, every /results
// dataset with a unit (its own columns, and the reason text, included); a damped sweep has the
// dissipated energy; a pivot held by a pinned end has no BBCOR.
TEST(ResultsTable, SweepFileNaNExactlyWhereAColumnDoesNotApply)
{
  char dir[] = "/tmp/beamimpact-sweep-XXXXXX";
  ASSERT_NE(nullptr, mkdtemp(dir));
  struct Case {
    const char *what;
    Opts        options;
  };
  const std::vector<Case> cases = {{"damped free beam", {{"-beam_damping_mass", "1"}, {"-beam_damping_stiffness", "1e-6"}}},
                                   {"pivot and a pinned end", {{"-beam_pivot", "0.275"}, {"-beam_right", "pinned"}}}};
  char cwd[4096];
  ASSERT_NE(nullptr, getcwd(cwd, sizeof cwd));
  ASSERT_EQ(0, chdir(BEAMIMPACT_SOURCE_DIR));
  for (size_t k = 0; k < cases.size(); ++k) {
    const std::string path = std::string(dir) + "/sweep" + std::to_string(k) + ".h5";
    Opts o = {{"-options_file", "options/base/aluminium-6mm.opts"}, {"-options_file", "options/base/superball-linear.opts"}, {"-beam_length", "1.1"}, {"-sweep_x", "0.55,0.825"},
              {"-sweep_quiet", ""}, {"-impact_window", "1e-3"}, {"-ts_type", "cn"}, {"-ts_dt", "2e-5"}};
    o.insert(o.end(), cases[k].options.begin(), cases[k].options.end());
    PetscOptions db;
    ASSERT_EQ(0, PetscOptionsCreate(&db));
    for (auto &kv : o) {
      if (kv.first == "-options_file") ASSERT_EQ(0, OptionsFileInsert(PETSC_COMM_WORLD, db, kv.second));
      else ASSERT_EQ(0, PetscOptionsSetValue(db, kv.first.c_str(), kv.second.empty() ? NULL : kv.second.c_str()));
    }
    ASSERT_EQ(0, PetscOptionsPush(db));
    EXPECT_EQ(0, TaskSweep(PETSC_COMM_WORLD, path)) << cases[k].what;
    ASSERT_EQ(0, PetscOptionsPop());
    ASSERT_EQ(0, PetscOptionsDestroy(&db));
    PetscMPIInt rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank != 0) continue;
    Scenario sc = PaperScene(cases[k].options);
    const auto file = ReadResults(path);
    ASSERT_EQ(file.at("status").v.size(), 2u);
    for (size_t row = 0; row < 2; ++row) {
      EXPECT_EQ(file.at("status").v[row], 0.0) << cases[k].what;
      sc.impact.x = file.at("x").v[row];
      ExpectFileFollowsTable(cases[k].what, file, sc, row);
    }
    if (k == 0) { EXPECT_GT(file.at("beam_dissipated_end").v[0], 0.0) << "a damped sweep has its dissipated energy"; }
    if (k == 1) { EXPECT_TRUE(std::isnan(file.at("bbcor").v[0])) << "no BBCOR for a rig that cannot turn freely"; }
  }
  ASSERT_EQ(0, chdir(cwd));
}

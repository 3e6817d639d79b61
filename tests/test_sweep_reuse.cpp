// A sweep point redoes only what changes with it (studies/sweep.hpp, SweepReuse): a point on
// the structure of the one before reads only its own axes' options (io/scenario_options.hpp,
// ScenarioReading::reuse) and runs on the structure's system (run/impact.hpp, ImpactStructure).
// Its row is bit for bit the row of the same point read and built from nothing (every column
// but the wall time); an axis that changes the structure (beam_nodes, a beam property, the
// integrator) reads everything and builds the system again, and its rows differ as the
// structures do; a shell whose contact radius follows the ball's speed builds a system a point.
#include "io/options_files.hpp"
#include "io/scenario_options.hpp"
#include "run/results_table.hpp"
#include "studies/sweep.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>

using namespace beamimpact;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

// The options of `o` pushed as the database (files first, as given), popped at scope end.
struct Database {
  PetscOptions db = nullptr;
  char         cwd[4096];
  explicit Database(const Opts &o)
  {
    EXPECT_NE(nullptr, getcwd(cwd, sizeof cwd));
    EXPECT_EQ(0, chdir(BEAMIMPACT_SOURCE_DIR));
    EXPECT_EQ(0, PetscOptionsCreate(&db));
    for (auto &kv : o) {
      if (kv.first == "-options_file") EXPECT_EQ(0, OptionsFileInsert(PETSC_COMM_WORLD, db, kv.second));
      else EXPECT_EQ(0, PetscOptionsSetValue(db, kv.first.c_str(), kv.second.empty() ? NULL : kv.second.c_str()));
    }
    EXPECT_EQ(0, PetscOptionsPush(db));
  }
  ~Database()
  {
    EXPECT_EQ(0, PetscOptionsPop());
    EXPECT_EQ(0, PetscOptionsDestroy(&db));
    EXPECT_EQ(0, chdir(cwd));
  }
};

Opts PaperSweep(const std::string &sweep, const Opts &more = {})
{
  Opts o = {{"-options_file", "options/base/aluminium-6mm.opts"}, {"-options_file", "options/base/superball-linear.opts"}, {"-beam_length", "1.1"}, {"-impact_window", "1e-3"}, {"-sweep", sweep}};
  o.insert(o.end(), more.begin(), more.end());
  return o;
}

struct Rows {
  std::vector<std::vector<double>> rows;
  SweepReuse                       reuse;
};

// Every case of the sweep run in order, with a rank's reuse (as the farm runs them) or each
// read and built afresh (reuse off).
Rows RunAll(bool reuse)
{
  SweepPlan plan;
  Rows      out;
  EXPECT_EQ(0, SweepPlanFromOptions(PETSC_COMM_WORLD, &plan));
  for (PetscInt i = 0; i < plan.cases(); ++i) {
    std::vector<double> row;
    std::string         reason;
    ImpactResult        result;
    EXPECT_EQ(0, SweepCaseRun(PETSC_COMM_WORLD, plan, i, &row, &reason, &result, reuse ? &out.reuse : nullptr));
    out.rows.push_back(row);
  }
  return out;
}

size_t WallTimeColumn(size_t axes)
{
  size_t c = 2 + axes; // case_index, the axes, status
  for (const ResultColumn &rc : ImpactResultColumns()) {
    if (!std::strcmp(rc.name, "wall_time")) return c;
    ++c;
  }
  return (size_t)-1;
}

// Row by row, every column but the wall time, bit for bit (NaN where both are NaN).
void ExpectSameRows(const Rows &a, const Rows &b, size_t axes, const std::string &what)
{
  ASSERT_EQ(a.rows.size(), b.rows.size()) << what;
  const size_t wall = WallTimeColumn(axes);
  for (size_t r = 0; r < a.rows.size(); ++r) {
    ASSERT_EQ(a.rows[r].size(), b.rows[r].size()) << what;
    EXPECT_EQ(a.rows[r][1 + axes], 0.0) << what << ": row " << r << " failed";
    for (size_t c = 0; c < a.rows[r].size(); ++c) {
      if (c == wall) continue;
      const double x = a.rows[r][c], y = b.rows[r][c];
      if (std::isnan(x) && std::isnan(y)) continue;
      EXPECT_EQ(0, std::memcmp(&x, &y, sizeof x)) << what << ": row " << r << ", column " << c << ": " << x << " against " << y;
    }
  }
}

size_t Column(const char *name, size_t axes)
{
  size_t c = 2 + axes;
  for (const ResultColumn &rc : ImpactResultColumns()) {
    if (!std::strcmp(rc.name, name)) return c;
    ++c;
  }
  return (size_t)-1;
}

} // namespace

TEST(SweepReuse, AxesOfTheScenarioParts)
{
  EXPECT_EQ(ScenarioPartOf("impact_x"), (unsigned)ScenarioImpact);
  EXPECT_EQ(ScenarioPartOf("-impact_offset"), (unsigned)ScenarioImpact);
  EXPECT_EQ(ScenarioPartOf("ball_speed"), (unsigned)ScenarioBall);
  EXPECT_EQ(ScenarioPartOf("ball_k"), (unsigned)ScenarioBall) << "a law's option is the ball's";
  EXPECT_EQ(ScenarioPartOf("bat_speed"), (unsigned)ScenarioSwing);
  EXPECT_EQ(ScenarioPartOf("beam_nodes"), (unsigned)ScenarioAll) << "the structure";
  EXPECT_EQ(ScenarioPartOf("beam_thickness"), (unsigned)ScenarioAll);
  EXPECT_EQ(ScenarioPartOf("ts_type"), (unsigned)ScenarioAll) << "not the scenario's: read all, the safe answer";
  EXPECT_EQ(ScenarioPartOf("no_such_option"), (unsigned)ScenarioAll);
}

// The point's axes only (impact point x ball speed x ball mass): one whole reading, one system,
// every row the fresh one's, for an explicit, an implicit and the modal integrator.
TEST(SweepReuse, PointAxesRowsAreTheFreshOnes)
{
  for (const char *ts : {"rk4", "cn", "modal"}) {
    Opts more = {{"-ts_type", std::strcmp(ts, "rk4") ? ts : "rk"}};
    if (!std::strcmp(ts, "rk4")) more.push_back({"-ts_rk_type", "4"}), more.push_back({"-ts_dt", "2e-6"}), more.push_back({"-ts_adapt_type", "none"});
    if (!std::strcmp(ts, "cn")) more.push_back({"-ts_dt", "2e-5"});
    Database   d(PaperSweep("impact_x=0.3:1.0:3,ball_speed=1;2,ball_mass=0.03;0.05", more));
    const Rows fresh = RunAll(false), kept = RunAll(true);
    ExpectSameRows(kept, fresh, 3, ts);
    EXPECT_EQ(kept.reuse.scenario.full, 1) << ts;
    EXPECT_EQ(kept.reuse.scenario.partial, 11) << ts;
    EXPECT_EQ(kept.reuse.systems, 1) << ts << ": one structure, one system";
  }
}

// An axis that changes the structure: a whole reading and a new system at each of its values
// (the last axis varies fastest), the rows the fresh ones, and different between structures.
TEST(SweepReuse, StructureAxisRebuilds)
{
  struct Case {
    const char *sweep, *what;
  };
  for (const Case &c : {Case{"beam_nodes=41;61,impact_x=0.4:0.9:3", "beam_nodes"}, Case{"beam_thickness=0.006;0.008,impact_x=0.4:0.9:3", "beam_thickness"},
                        Case{"ts_dt=2e-5;1e-5,impact_x=0.4:0.9:3", "ts_dt"}}) { // the integrator's: a new context key too (ImpactStructure)
    Database   d(PaperSweep(c.sweep, {{"-ts_type", "modal"}}));
    const Rows fresh = RunAll(false), kept = RunAll(true);
    ExpectSameRows(kept, fresh, 2, c.what);
    EXPECT_EQ(kept.reuse.scenario.full, 2) << c.what;
    EXPECT_EQ(kept.reuse.scenario.partial, 4) << c.what;
    EXPECT_EQ(kept.reuse.systems, 2) << c.what << ": a system per structure";
    const size_t acor = Column("acor", 2);
    ASSERT_LT(acor, kept.rows[0].size());
    for (size_t r = 0; r < 3; ++r) EXPECT_NE(kept.rows[r][acor], kept.rows[r + 3][acor]) << c.what << ": the same point on the two structures";
  }
}

// A shell's default contact radius follows the approach speed (model/shell.hpp): a ball speed
// axis changes the system at every point, so each builds its own.
TEST(SweepReuse, ShellRadiusFollowsTheBall)
{
  Database d({{"-options_file", "options/bats/aluminium-bat.opts"}, {"-options_file", "options/balls/baseball.opts"}, {"-beam_theory", "timoshenko"}, {"-beam_shell", ""}, {"-beam_nodes", "41"},
              {"-ts_type", "modal"}, {"-impact_window", "5e-4"}, {"-sweep", "ball_speed=20;30;40,impact_x=0.6;0.7"}});
  const Rows fresh = RunAll(false), kept = RunAll(true);
  ExpectSameRows(kept, fresh, 2, "shell");
  EXPECT_EQ(kept.reuse.scenario.full, 1);
  EXPECT_EQ(kept.reuse.systems, 3) << "one system per contact radius (per ball speed)";
}

// A sweep's point keeps no energy per mode at the end (ImpactParams::mode_energies: only -task
// impact's file writes /modes_energy), while the same impact run alone has one per kept mode.
TEST(SweepReuse, PointsSkipTheModeEnergies)
{
  Database  d(PaperSweep("impact_x=0.3"));
  SweepPlan plan;
  ASSERT_EQ(0, SweepPlanFromOptions(PETSC_COMM_WORLD, &plan));
  std::vector<double> row;
  std::string         reason;
  ImpactResult        point, alone;
  ASSERT_EQ(0, SweepCaseRun(PETSC_COMM_WORLD, plan, 0, &row, &reason, &point, nullptr));
  EXPECT_GT(point.contacts, 0);
  EXPECT_TRUE(point.mode_energies.empty());
  Scenario sc;
  ASSERT_EQ(0, ScenarioFromOptions(PETSC_COMM_WORLD, &sc));
  sc.impact.x = 0.3;
  ASSERT_EQ(0, ImpactRun(PETSC_COMM_WORLD, sc, &alone));
  EXPECT_FALSE(alone.mode_energies.empty()) << "the impact alone ends in a modal free flight";
  EXPECT_EQ(point.acor, alone.acor);
}

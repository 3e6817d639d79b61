// The case batch (studies/case_batch.hpp): a case's key is its complete option text (exact values,
// the fixed options, not the study's own); its row is the run's (a ball on a wall: the linear
// spring's contact time pi sqrt(m/k) and e = 1; a uniform free beam: its mass, centre, moments of
// inertia and the free-free beta L); a case known is never run again (a duplicate in a batch, a
// second batch, a batch created again from the journals of one that stopped or from the file it
// wrote); the rows on all ranks are those each rank computes alone.
#include "studies/case_batch.hpp"

#include "io/results_h5.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace beamimpact;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

// The options of `o` pushed as the database, popped at scope end.
struct Database {
  PetscOptions db = nullptr;
  explicit Database(const Opts &o)
  {
    EXPECT_EQ(0, PetscOptionsCreate(&db));
    for (auto &kv : o) EXPECT_EQ(0, PetscOptionsSetValue(db, kv.first.c_str(), kv.second.empty() ? NULL : kv.second.c_str()));
    EXPECT_EQ(0, PetscOptionsPush(db));
  }
  ~Database()
  {
    EXPECT_EQ(0, PetscOptionsPop());
    EXPECT_EQ(0, PetscOptionsDestroy(&db));
  }
};

// A ball on a wall: the paper's beam clamped at both ends and made enormously heavy.
const Opts kWall = {{"-beam_density", "1e12"}, {"-beam_left", "clamped"}, {"-beam_right", "clamped"}, {"-beam_nodes", "11"}, {"-ts_type", "modal"}, {"-ball_law", "linear"},
                    {"-ball_mass", "0.042"}, {"-impact_x", "0.5"}};

CaseBatchSettings Settings(const char *task, std::vector<std::string> columns, const std::string &store = "")
{
  CaseBatchSettings s;
  s.task         = CaseTaskFind(task);
  s.columns      = std::move(columns);
  s.store        = store;
  s.own_prefixes = {"fit_", "tao_"};
  return s;
}

// A scratch file name shared by every rank (rank 0's pid).
std::string Scratch(const char *name)
{
  int pid = (int)getpid();
  MPI_Bcast(&pid, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  return "/tmp/beamimpact-test-case-batch-" + std::to_string(pid) + "-" + name;
}

void RemoveStore(const std::string &store)
{
  PetscMPIInt rank;
  MPI_Barrier(PETSC_COMM_WORLD);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    std::string cmd = "rm -rf '" + store + "' '" + store + ".parts'";
    EXPECT_EQ(0, std::system(cmd.c_str()));
  }
  MPI_Barrier(PETSC_COMM_WORLD);
}

} // namespace

TEST(CaseBatch, KeyIsTheCompleteOptionText)
{
  Database  d({{"-beam_nodes", "21"}, {"-ball_speed", "2"}, {"-fit_quiet", ""}});
  CaseBatch b;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"acor"}), &b));
  const CaseOptions c = {{"impact_x", 0.3}, {"ball_k", 2e4}};
  std::string       text;
  const std::string key = CaseBatchKey(b, c, &text);
  EXPECT_EQ(64u, key.size());
  EXPECT_EQ(key, CaseBatchKey(b, {{"ball_k", 2e4}, {"impact_x", 0.3}})); // the order of the settings does not matter
  EXPECT_NE(key, CaseBatchKey(b, {{"impact_x", std::nextafter(0.3, 1.0)}, {"ball_k", 2e4}})); // one ulp does
  EXPECT_NE(std::string::npos, text.find("-impact_x 0.29999999999999999\n"));                  // %.17g
  EXPECT_NE(std::string::npos, text.find("-beam_nodes 21\n"));                                  // the fixed options
  EXPECT_EQ(std::string::npos, text.find("fit_quiet"));                                        // not the study's own
  EXPECT_NE(key, CaseBatchKey(b, {{"impact_x", 0.3}, {"ball_k", 2e4}, {"ball_speed", 2.5}}));   // a case's setting replaces the given value
  ASSERT_EQ(0, CaseBatchDestroy(&b));
  Database  other(Opts{{"-beam_nodes", "41"}});
  CaseBatch b41;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"acor"}), &b41));
  EXPECT_NE(key, CaseBatchKey(b41, c)); // another fixed option, another case
  CaseBatch modes;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("modes", {"mass"}), &modes));
  EXPECT_NE(CaseBatchKey(b41, c), CaseBatchKey(modes, c)); // another task or columns, another case
  ASSERT_EQ(0, CaseBatchDestroy(&modes));
  ASSERT_EQ(0, CaseBatchDestroy(&b41));
}

TEST(CaseBatch, ImpactRowsOnAWallAndEachCaseOnce)
{
  Database                 d(kWall);
  CaseBatch                b;
  std::vector<CaseRow>     rows;
  std::vector<CaseOptions> cases;
  for (double k : {1e4, 4e4})
    for (double v : {1.0, 3.0}) cases.push_back({{"ball_k", k}, {"ball_speed", v}});
  cases.push_back(cases[1]); // a duplicate: one run
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"acor", "contact_time"}), &b));
  ASSERT_EQ(0, CaseBatchRun(b, cases, &rows));
  ASSERT_EQ(cases.size(), rows.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    ASSERT_EQ(SweepOk, rows[i].status) << rows[i].reason;
    EXPECT_NEAR(1.0, rows[i].values[0], 1e-6);                                                   // e = 1 on a wall
    EXPECT_NEAR(M_PI * std::sqrt(0.042 / cases[i][0].value), rows[i].values[1], 1e-6 * rows[i].values[1]); // pi sqrt(m/k)
  }
  EXPECT_EQ(4, b.counts.computed);
  EXPECT_EQ(1, b.counts.reused);
  std::vector<CaseRow> again;
  ASSERT_EQ(0, CaseBatchRun(b, cases, &again)); // all known
  EXPECT_EQ(4, b.counts.computed);
  for (size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(rows[i].values, again[i].values);
  ASSERT_EQ(0, CaseBatchDestroy(&b));
}

TEST(CaseBatch, ModesRowsOfAUniformFreeBeam)
{
  const double E = 7e10, rho = 2700, a = 0.006, w = 0.032, bl = 4.730040744862704; // free-free beta_1 L
  Database     d({{"-beam_youngs_modulus", "7e10"}, {"-beam_density", "2700"}, {"-beam_thickness", "0.006"}, {"-beam_width", "0.032"}, {"-beam_nodes", "161"}});
  CaseBatch    b;
  std::vector<CaseRow> rows;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("modes", {"frequency_1", "mass", "centre_of_mass", "moment_of_inertia", "swingweight", "bending_frequency_1"}), &b));
  ASSERT_EQ(0, CaseBatchRun(b, {{{"beam_length", 0.5}}, {{"beam_length", 1.0}}}, &rows));
  for (size_t i = 0; i < 2; ++i) {
    const double L = 0.5 * (double)(i + 1), M = rho * a * w * L, EI = E * w * a * a * a / 12, mu = rho * a * w;
    ASSERT_EQ(SweepOk, rows[i].status) << rows[i].reason;
    EXPECT_NEAR(bl * bl * std::sqrt(EI / (mu * std::pow(L, 4))) / (2 * M_PI), rows[i].values[0], 2e-4 * rows[i].values[0]);
    EXPECT_NEAR(M, rows[i].values[1], 1e-12 * M);
    EXPECT_NEAR(L / 2, rows[i].values[2], 1e-12);
    EXPECT_NEAR(M * L * L / 12, rows[i].values[3], 1e-12 * M * L * L);
    EXPECT_NEAR(M * L * L / 12 + M * (L / 2 - 0.1) * (L / 2 - 0.1), rows[i].values[4], 1e-12 * M * L * L);
    EXPECT_EQ(rows[i].values[0], rows[i].values[5]); // a plain beam's modes are all bending
  }
  ASSERT_EQ(0, CaseBatchDestroy(&b));
}

TEST(CaseBatch, ResumesFromItsJournalsAndItsFile)
{
  Database                 d(kWall);
  const std::string        store = Scratch("resume.h5");
  std::vector<CaseOptions> cases = {{{"ball_k", 1e4}}, {{"ball_k", 2e4}}, {{"ball_k", 3e4}}};
  std::vector<CaseRow>     first, second;
  RemoveStore(store);
  CaseBatch b;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"contact_time"}, store), &b));
  ASSERT_EQ(0, CaseBatchRun(b, cases, &first));
  ASSERT_EQ(0, CaseBatchDestroy(&b)); // stopped before its file: the journals keep the rows
  CaseBatch again;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"contact_time"}, store), &again));
  EXPECT_EQ(3, again.counts.loaded_journal);
  cases.push_back({{"ball_k", 4e4}});
  ASSERT_EQ(0, CaseBatchRun(again, cases, &second));
  EXPECT_EQ(1, again.counts.computed); // only the new case
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(first[i].values, second[i].values);
  // The study's file holds every row: the journals go, and a new batch loads the file.
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    const hid_t file = H5Fcreate(store.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(0, CaseBatchWrite(again, file));
    H5Fclose(file);
  }
  ASSERT_EQ(0, CaseBatchFinish(again));
  ASSERT_EQ(0, CaseBatchDestroy(&again));
  CaseBatch from_file;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"contact_time"}, store), &from_file));
  EXPECT_EQ(4, from_file.counts.loaded);
  EXPECT_EQ(0, from_file.counts.loaded_journal);
  ASSERT_EQ(0, CaseBatchRun(from_file, cases, &first));
  EXPECT_EQ(0, from_file.counts.computed);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(second[i].values, first[i].values);
  ASSERT_EQ(0, CaseBatchDestroy(&from_file));
  CaseBatch other_columns; // a file of other columns: nothing loaded
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"acor"}, store), &other_columns));
  EXPECT_EQ(0, other_columns.counts.loaded);
  ASSERT_EQ(0, CaseBatchDestroy(&other_columns));
  RemoveStore(store);
}

TEST(CaseBatch, RowsOnAllRanksAreEachRanksOwn)
{
  Database                 d({{"-beam_nodes", "21"}, {"-ts_type", "modal"}, {"-ball_law", "linear"}});
  std::vector<CaseOptions> cases;
  for (double x : {0.2, 0.4, 0.6, 0.8, 1.0})
    for (double k : {1e4, 3e4}) cases.push_back({{"impact_x", x}, {"ball_k", k}});
  CaseBatch world, self;
  std::vector<CaseRow> shared, alone;
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_WORLD, Settings("impact", {"acor", "contact_time", "peak_force"}), &world));
  ASSERT_EQ(0, CaseBatchRun(world, cases, &shared));
  ASSERT_EQ(0, CaseBatchCreate(PETSC_COMM_SELF, Settings("impact", {"acor", "contact_time", "peak_force"}), &self));
  ASSERT_EQ(0, CaseBatchRun(self, cases, &alone));
  for (size_t i = 0; i < cases.size(); ++i) {
    ASSERT_EQ(SweepOk, shared[i].status) << shared[i].reason;
    EXPECT_EQ(alone[i].values, shared[i].values) << CaseOptionsText(cases[i]); // bit for bit
  }
  ASSERT_EQ(0, CaseBatchDestroy(&self));
  ASSERT_EQ(0, CaseBatchDestroy(&world));
}

// -task sweep: plan, case runner, task farm, journal and HDF5 store. See sweep.hpp.
//
// On disk, for -output F:
//   F          the results: root attributes (parameters, options, progress) and
//              /results/<column> with one row per finished case, ordered by
//              case index; rewritten only as F.tmp + fsync + rename(), so F is
//              always a complete HDF5 file (readable by h5py/h5dump at any time).
//   F.parts/   while a sweep runs: lock (flock by rank 0: one sweep per file),
//              run<R>-rank<r>.bin, the journal of the group leader on world rank
//              r in run (attempt) R: a header with the parameter signature, then
//              one self-checking record per finished case, appended with a
//              single write(). A record cut by kill -9 fails its checksum and is
//              ignored (that case is simply computed again).
// A rerun of the same command reads F and the journals, checks that they were
// written with the same parameters, rewrites F with every row found, and
// computes only the missing cases. At the end rank 0 gathers this run's rows
// over MPI, writes the complete F and removes F.parts.
#include "studies/sweep.hpp"

#include "io/impact_point.hpp"
#include "io/options_util.hpp"
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "io/scenario_options.hpp"
#include "io/text.hpp"
#include "model/rigid.hpp"

#include <hdf5.h>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <thread>

namespace beamimpact {

// ---------------------------------------------------------------------------
// Plan
// ---------------------------------------------------------------------------

PetscInt SweepPlan::cases() const
{
  if (axes.empty()) return 0;
  PetscInt n = 1;
  for (auto &a : axes) n *= (PetscInt)a.values.size();
  return n;
}

std::vector<PetscReal> SweepPlan::CaseValues(PetscInt index) const
{
  std::vector<PetscReal> v(axes.size());
  for (size_t k = axes.size(); k-- > 0;) {
    const PetscInt n = (PetscInt)axes[k].values.size();
    v[k]             = axes[k].values[index % n];
    index /= n;
  }
  return v;
}

static bool ParseReal(const std::string &text, PetscReal *v)
{
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char *end;
  errno          = 0;
  const double d = std::strtod(t.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(d)) return false;
  *v = d;
  return true;
}

bool SweepParsePoints(const std::string &spec_in, std::vector<PetscReal> *values, std::string *why)
{
  const std::string spec = Trim(spec_in);
  values->clear();
  if (spec.find(':') != std::string::npos) {
    std::vector<std::string> parts;
    std::stringstream        ss(spec);
    std::string              p;
    while (std::getline(ss, p, ':')) parts.push_back(p);
    if (parts.size() != 3) {
      *why = "a range is start:stop:count (three numbers separated by ':')";
      return false;
    }
    PetscReal a, b;
    if (!ParseReal(parts[0], &a) || !ParseReal(parts[1], &b)) {
      *why = "start and stop of start:stop:count must be numbers (m)";
      return false;
    }
    const std::string c = Trim(parts[2]);
    char             *end;
    errno        = 0;
    const long n = c.empty() ? -1 : std::strtol(c.c_str(), &end, 10);
    if (c.empty() || *end != '\0' || errno == ERANGE || n < 0 || n > 100000000) {
      *why = "count of start:stop:count must be a whole number >= 0";
      return false;
    }
    // Rounded to 15 significant digits, so that 0:1.1:111 gives exactly the
    // doubles of 0, 0.01, ..., 1.1 (what -impact_x 0.55 gives), not 1 ulp off.
    for (long k = 0; k < n; ++k) {
      const double raw = k == n - 1 && n > 1 ? b : a + (double)k * ((b - a) / (double)std::max(1L, n - 1));
      char         text[64];
      std::snprintf(text, sizeof(text), "%.15g", raw);
      values->push_back(std::strtod(text, nullptr));
    }
    return true;
  }
  std::stringstream ss(spec);
  std::string       p;
  while (std::getline(ss, p, ',')) {
    PetscReal v;
    if (!ParseReal(p, &v)) {
      *why = "'" + Trim(p) + "' is not a number; a list is x1,x2,... (m)";
      return false;
    }
    values->push_back(v);
  }
  if (!spec.empty() && spec.back() == ',') {
    *why = "empty entry at the end of the list";
    return false;
  }
  return true;
}

PetscErrorCode SweepPlanFromOptions(MPI_Comm comm, const BeamParams &beam, SweepPlan *plan)
{
  std::vector<char> buf(1 << 20, 0);
  PetscBool         set_x = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Sweep: many impacts farmed out over MPI ranks (-task sweep)", "beamimpact");
  PetscCall(PetscOptionsString("-sweep_x", "Impact points (m): start:stop:count (both ends included) or x1,x2,...", "", buf.data(), buf.data(), buf.size(), &set_x));
  PetscCall(PetscOptionsInt("-sweep_ranks_per_case", "Ranks that solve one impact together (the beam's DMDA is distributed over them)", "", plan->ranks_per_case, &plan->ranks_per_case, NULL));
  PetscCall(PetscOptionsReal("-rigid_loss_fraction", "Loss fraction f of the rigid-body model, Eq. (11), for the rigid_acor column", "", plan->rigid_loss_fraction, &plan->rigid_loss_fraction, NULL));
  PetscCall(PetscOptionsBool("-sweep_quiet", "No progress or summary lines (errors are still reported)", "", plan->quiet, &plan->quiet, NULL));
  PetscCall(PetscOptionsBool("-sweep_restart", "Discard an existing -output file and its journal and start the sweep over", "", plan->restart, &plan->restart, NULL));
  PetscCall(PetscOptionsReal("-sweep_progress_interval", "Seconds between progress lines on rank 0", "", plan->progress_interval, &plan->progress_interval, NULL));
  PetscCall(PetscOptionsReal("-sweep_write_interval", "Minimum seconds between rewrites of -output while the sweep runs (0: as often as a 5% cost cap on rank 0 allows)", "", plan->write_interval,
                             &plan->write_interval, NULL));
  PetscOptionsEnd();

  PetscCheck(set_x, comm, PETSC_ERR_ARG_WRONG, "-task sweep needs the impact points: -sweep_x start:stop:count (both ends included) or -sweep_x x1,x2,... (m), e.g. -sweep_x 0:%g:111", (double)beam.length);
  plan->x_spec = Trim(buf.data());
  PetscCheck(!plan->x_spec.empty(), comm, PETSC_ERR_ARG_WRONG, "-sweep_x needs a value: start:stop:count (both ends included) or x1,x2,... (m), e.g. -sweep_x 0:%g:111", (double)beam.length);
  SweepAxis   x{"x", "m", {}};
  std::string why;
  PetscCheck(SweepParsePoints(plan->x_spec, &x.values, &why), comm, PETSC_ERR_ARG_WRONG, "-sweep_x %s is not allowed: %s", plan->x_spec.c_str(), why.c_str());
  PetscCheck(!x.values.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_x %s gives no impact points: a sweep needs at least one (count >= 1 in start:stop:count)", plan->x_spec.c_str());
  for (size_t k = 0; k < x.values.size(); ++k) {
    char what[128];
    PetscCall(PetscSNPrintf(what, sizeof(what), "-sweep_x point %d, x = %g,", (int)k, (double)x.values[k]));
    PetscCall(ImpactPointCheck(comm, beam, x.values[k], what));
  }
  plan->axes = {x};
  PetscCheck(plan->ranks_per_case >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_ranks_per_case %" PetscInt_FMT " is not allowed: at least 1", plan->ranks_per_case);
  PetscCheck(plan->rigid_loss_fraction >= 0 && plan->rigid_loss_fraction < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-rigid_loss_fraction %g is not allowed: a fraction of the incident energy, 0 <= f < 1",
             (double)plan->rigid_loss_fraction);
  PetscCheck(plan->progress_interval > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_progress_interval %g is not allowed: it must be > 0 (s)", (double)plan->progress_interval);
  PetscCheck(plan->write_interval >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_write_interval %g is not allowed: it must be >= 0 (s)", (double)plan->write_interval);
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// Case runner
// ---------------------------------------------------------------------------

Scenario SweepCaseFor(const SweepPlan &plan, const Scenario &base, PetscInt index)
{
  Scenario                     c = base;
  const std::vector<PetscReal> v = plan.CaseValues(index);
  for (size_t k = 0; k < plan.axes.size(); ++k) {
    if (plan.axes[k].name == "x") c.impact.x = v[k];
    // Further axes (ball speed, beam length, ...) set their field here.
  }
  return c;
}

const std::vector<SweepColumn> &SweepColumns()
{
  static const std::vector<SweepColumn> cols = [] {
    std::vector<SweepColumn> c;
    c.push_back({"case_index", "1", false});
    for (auto &rc : ImpactResultColumns()) c.push_back({rc.name, rc.unit, std::string(rc.name) == "wall_time"});
    c.push_back({"rigid_acor", "1", false});
    c.push_back({"rigid_forced_loss_fraction", "1", false});
    return c;
  }();
  return cols;
}

PetscErrorCode SweepCaseRun(MPI_Comm comm, const SweepPlan &plan, const Scenario &base, PetscInt index, std::vector<double> *row, ImpactResult *result)
{
  const Scenario c = SweepCaseFor(plan, base, index);

  PetscFunctionBeginUser;
  PetscCall(ImpactRun(comm, c.beam, c.ball, c.impact, c.monitor, result));
  const ImpactResult &r = *result;
  // Rigid-body model, Eq. (11): uniform beam of mass M = mu L about its centre.
  const PetscReal M = c.beam.mu * c.beam.length, I_cm = M * c.beam.length * c.beam.length / 12.0;
  const PetscReal M_e = RigidEffectiveMass(M, I_cm, std::abs(r.x - 0.5 * c.beam.length));
  row->clear();
  row->push_back((double)index);
  for (auto &rc : ImpactResultColumns()) row->push_back(rc.get(r));
  row->push_back(RigidACOR(c.ball.mass, M_e, plan.rigid_loss_fraction));
  row->push_back(RigidForcedLossFraction(c.ball.mass, M_e, r.acor_corrected));
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// Task farm
// ---------------------------------------------------------------------------

enum FarmCounter { FarmNext = 0, FarmDone = 1 };

static PetscErrorCode FarmFetchAdd(TaskFarm &f, FarmCounter which, int64_t add, int64_t *old)
{
  int64_t result = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, f.win));
  PetscCallMPI(MPI_Fetch_and_op(&add, &result, MPI_INT64_T, 0, (MPI_Aint)which, add ? MPI_SUM : MPI_NO_OP, f.win));
  PetscCallMPI(MPI_Win_unlock(0, f.win));
  if (old) *old = result;
  PetscFunctionReturn(0);
}

PetscErrorCode TaskFarmCreate(MPI_Comm world, PetscInt ranks_per_case, TaskFarm *farm)
{
  PetscFunctionBeginUser;
  farm->world = world;
  PetscCallMPI(MPI_Comm_rank(world, &farm->world_rank));
  PetscCallMPI(MPI_Comm_size(world, &farm->world_size));
  PetscCheck(ranks_per_case >= 1 && ranks_per_case <= farm->world_size, world, PETSC_ERR_ARG_OUTOFRANGE,
             "-sweep_ranks_per_case %" PetscInt_FMT " is not allowed with %d MPI ranks: use 1 <= ranks_per_case <= %d", ranks_per_case, farm->world_size, farm->world_size);
  farm->ranks_per_case = ranks_per_case;
  farm->groups         = farm->world_size / ranks_per_case;
  const int color      = farm->world_rank < farm->groups * ranks_per_case ? (int)(farm->world_rank / ranks_per_case) : MPI_UNDEFINED;
  PetscCallMPI(MPI_Comm_split(world, color, farm->world_rank, &farm->group));
  if (farm->group != MPI_COMM_NULL) {
    PetscCallMPI(MPI_Comm_rank(farm->group, &farm->group_rank));
    PetscCallMPI(MPI_Comm_size(farm->group, &farm->group_size));
  }
  MPI_Info info;
  PetscCallMPI(MPI_Info_create(&info));
  PetscCallMPI(MPI_Info_set(info, "accumulate_ops", "same_op_no_op"));
  const MPI_Aint bytes = farm->world_rank == 0 ? (MPI_Aint)(2 * sizeof(int64_t)) : 0;
  PetscCallMPI(MPI_Win_allocate(bytes, sizeof(int64_t), info, world, &farm->base, &farm->win));
  PetscCallMPI(MPI_Info_free(&info));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskFarmDestroy(TaskFarm *farm)
{
  PetscFunctionBeginUser;
  if (farm->win != MPI_WIN_NULL) PetscCallMPI(MPI_Win_free(&farm->win));
  if (farm->group != MPI_COMM_NULL) PetscCallMPI(MPI_Comm_free(&farm->group));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskFarmRun(TaskFarm &farm, PetscInt ntasks, const std::function<PetscErrorCode(MPI_Comm, PetscInt)> &run, const std::function<PetscErrorCode(PetscInt)> &between)
{
  int64_t done = 0;

  PetscFunctionBeginUser;
  if (farm.world_rank == 0) {
    PetscCallMPI(MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, farm.win));
    static_cast<int64_t *>(farm.base)[FarmNext] = 0;
    static_cast<int64_t *>(farm.base)[FarmDone] = 0;
    PetscCallMPI(MPI_Win_unlock(0, farm.win));
  }
  PetscCallMPI(MPI_Barrier(farm.world));
  if (farm.group != MPI_COMM_NULL) {
    for (;;) {
      int64_t t = -1;
      if (farm.group_rank == 0) {
        PetscCall(FarmFetchAdd(farm, FarmNext, 1, &t));
        if (t >= ntasks) t = -1;
      }
      if (farm.group_size > 1) PetscCallMPI(MPI_Bcast(&t, 1, MPI_INT64_T, 0, farm.group));
      if (t < 0) break;
      PetscCall(run(farm.group, (PetscInt)t));
      if (farm.group_rank == 0) PetscCall(FarmFetchAdd(farm, FarmDone, 1, &done));
      if (farm.world_rank == 0) PetscCall(between((PetscInt)done + 1));
    }
  }
  // Out of tasks: wait for the others with growing sleeps (an idle rank must
  // not spin in MPI and take a core from a working one).
  // The longest nap grows with the number of ranks so that rank 0 answers at
  // most a few thousand polls per second.
  const double nap_max = std::min(1.0, 2e-2 * std::ceil(farm.world_size / 64.0));
  double       nap     = 2e-4;
  for (;;) {
    PetscCall(FarmFetchAdd(farm, FarmDone, 0, &done));
    if (farm.world_rank == 0) PetscCall(between((PetscInt)done));
    if (done >= ntasks) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(farm.world_rank == 0 ? std::min(nap, 2e-2) : nap));
    nap = std::min(nap_max, nap * 1.5);
  }
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// Journal: per-leader append-only files of self-checking records
// ---------------------------------------------------------------------------

namespace {

uint64_t Fnv1a(const void *data, size_t n, uint64_t h = 1469598103934665603ULL)
{
  const unsigned char *p = static_cast<const unsigned char *>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

const char     JournalMagic[8] = {'B', 'I', 'S', 'W', 'J', 'N', 'L', '1'};
const uint32_t RecordMagic     = 0x574f5253u;

struct JournalHeader {
  char     magic[8];
  uint64_t signature;
  uint32_t ncols;
  uint32_t reserved;
  uint64_t check; // Fnv1a of the fields above
};

size_t RecordBytes(uint32_t ncols) { return 2 * sizeof(uint32_t) + ncols * sizeof(double) + sizeof(uint64_t); }

bool WriteAll(int fd, const void *data, size_t n)
{
  const char *p = static_cast<const char *>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    n -= (size_t)w;
  }
  return true;
}

std::string JournalName(const std::string &parts, int run, int rank)
{
  char name[64];
  std::snprintf(name, sizeof(name), "/run%06d-rank%06d.bin", run, rank);
  return parts + name;
}

// Appends rows to one journal file (opened on the first row).
struct JournalWriter {
  std::string path;
  uint64_t    signature = 0;
  uint32_t    ncols     = 0;
  int         fd        = -1;

  bool        failed    = false; // warned once; the rows still reach the file at the end

  // A journal that cannot be written is not fatal: the row is also kept in
  // memory and gathered at the end; only a resume after a crash would lose it.
  void Warn(const char *what)
  {
    if (!failed) {
      int rank;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      std::fprintf(stderr, "beamimpact: warning: rank %d cannot %s the sweep journal %s (%s): its points are kept in memory and written at the end, but would be computed again after a crash (is -output on a filesystem every rank sees?)\n", rank, what, path.c_str(), std::strerror(errno));
    }
    failed = true;
    if (fd >= 0) ::close(fd);
    fd = -1;
  }

  PetscErrorCode Append(const std::vector<double> &row)
  {
    PetscFunctionBeginUser;
    PetscCheck(row.size() == ncols, PETSC_COMM_SELF, PETSC_ERR_PLIB, "sweep row has %zu columns, the journal %u", row.size(), ncols);
    if (failed) PetscFunctionReturn(0);
    if (fd < 0) {
      fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
      if (fd < 0) {
        Warn("create");
        PetscFunctionReturn(0);
      }
      JournalHeader h;
      std::memset(&h, 0, sizeof(h));
      std::memcpy(h.magic, JournalMagic, sizeof(h.magic));
      h.signature = signature;
      h.ncols     = ncols;
      h.check     = Fnv1a(&h, offsetof(JournalHeader, check));
      if (!WriteAll(fd, &h, sizeof(h))) {
        Warn("write");
        PetscFunctionReturn(0);
      }
    }
    std::vector<char> rec(RecordBytes(ncols));
    uint32_t          head[2] = {RecordMagic, ncols};
    std::memcpy(rec.data(), head, sizeof(head));
    std::memcpy(rec.data() + sizeof(head), row.data(), ncols * sizeof(double));
    const uint64_t check = Fnv1a(rec.data(), rec.size() - sizeof(uint64_t));
    std::memcpy(rec.data() + rec.size() - sizeof(uint64_t), &check, sizeof(check));
    // One write() per record: a kill leaves whole records and at most one cut one.
    if (!WriteAll(fd, rec.data(), rec.size())) Warn("write");
    PetscFunctionReturn(0);
  }
  void Close()
  {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

// Reads the complete, valid records of one journal file, from where it stopped
// last time (a record still being written is read next time).
struct JournalReader {
  std::string path;
  off_t       offset     = 0;
  bool        header_ok  = false;
  bool        stopped    = false; // a bad record: ignore the rest of the file
  uint64_t    signature  = 0;

  enum Status { Ok, Missing, WrongParameters };

  Status ReadNew(uint64_t expected_signature, uint32_t ncols, PetscInt ncases, std::map<PetscInt, std::vector<double>> *rows, PetscInt *added)
  {
    if (stopped) return Ok;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Missing;
    struct stat st;
    if (::fstat(fd, &st) != 0) {
      ::close(fd);
      return Missing;
    }
    std::vector<char> data((size_t)std::max<off_t>(0, st.st_size - offset));
    size_t            got = 0;
    while (got < data.size()) {
      const ssize_t r = ::pread(fd, data.data() + got, data.size() - got, offset + (off_t)got);
      if (r <= 0) break;
      got += (size_t)r;
    }
    ::close(fd);
    data.resize(got);
    size_t pos = 0;
    if (!header_ok) {
      if (data.size() < sizeof(JournalHeader)) return Ok; // not yet written
      JournalHeader h;
      std::memcpy(&h, data.data(), sizeof(h));
      if (std::memcmp(h.magic, JournalMagic, sizeof(h.magic)) != 0 || h.check != Fnv1a(&h, offsetof(JournalHeader, check))) {
        stopped = true;
        return Ok;
      }
      signature = h.signature;
      if (h.signature != expected_signature || h.ncols != ncols) return WrongParameters;
      header_ok = true;
      pos       = sizeof(JournalHeader);
    }
    const size_t rb = RecordBytes(ncols);
    while (pos + rb <= data.size()) {
      const char *r = data.data() + pos;
      uint32_t    head[2];
      uint64_t    check;
      std::memcpy(head, r, sizeof(head));
      std::memcpy(&check, r + rb - sizeof(uint64_t), sizeof(check));
      if (head[0] != RecordMagic || head[1] != ncols || check != Fnv1a(r, rb - sizeof(uint64_t))) {
        stopped = true;
        break;
      }
      std::vector<double> row(ncols);
      std::memcpy(row.data(), r + sizeof(head), ncols * sizeof(double));
      const double idx = row[0];
      if (!(idx >= 0 && idx < ncases && idx == std::floor(idx))) {
        stopped = true;
        break;
      }
      if (rows->emplace((PetscInt)idx, std::move(row)).second && added) ++*added;
      pos += rb;
    }
    offset += (off_t)pos;
    return Ok;
  }
};

bool ParseJournalName(const char *name, int *run, int *rank)
{
  char tail[8] = "";
  return std::sscanf(name, "run%d-rank%d.%7s", run, rank, tail) == 3 && std::string(tail) == "bin";
}

// ---------------------------------------------------------------------------
// Parameter signature: what must be equal for a resume
// ---------------------------------------------------------------------------

// Options that do not change any number in the file.
bool OptionIsVolatile(const std::string &name)
{
  static const std::set<std::string> exact    = {"output", "sweep_quiet", "sweep_restart", "sweep_progress_interval", "sweep_write_interval", "error_traceback", "allow_unused_options", "help", "version"};
  static const char *const           prefix[] = {"log_", "malloc", "info", "options_", "on_error", "mpi_", "viewer_", "ts_monitor", "ts_adapt_monitor", "snes_monitor", "ksp_monitor", "ts_view", "snes_view", "ksp_view"};
  if (exact.count(name)) return true;
  for (const char *p : prefix)
    if (name.compare(0, std::strlen(p), p) == 0) return true;
  return false;
}

// "-name value -name2 -name3 value3 ..." (PetscOptionsGetAll, sorted) -> name -> value.
std::map<std::string, std::string> ParseOptions(const std::string &all)
{
  std::map<std::string, std::string> m;
  std::stringstream                  ss(all);
  std::string                        tok, name;
  auto is_name = [](const std::string &t) { return t.size() > 1 && t[0] == '-' && (std::isalpha((unsigned char)t[1]) || t[1] == '_'); };
  while (ss >> tok) {
    if (is_name(tok)) {
      name    = tok.substr(1);
      m[name] = "";
    } else if (!name.empty()) m[name] += (m[name].empty() ? "" : " ") + tok;
  }
  return m;
}

std::string CheckedOptions(const std::string &all)
{
  std::string out;
  for (auto &kv : ParseOptions(all)) {
    if (OptionIsVolatile(kv.first)) continue;
    out += "-" + kv.first + (kv.second.empty() ? "" : " " + kv.second) + " ";
  }
  return out;
}

// Attributes that change while a sweep runs, or with options that do not matter.
bool AttributeIsVolatile(const std::string &key) { return key == "options" || key == "sweep_cases_done" || key == "sweep_complete"; }

struct AttrMaps {
  std::map<std::string, double>      num;
  std::map<std::string, std::string> str;
};

AttrMaps SignatureMaps(const RunRecord &rec)
{
  AttrMaps m;
  for (auto &kv : rec.numbers)
    if (!AttributeIsVolatile(kv.first)) m.num[kv.first] = kv.second;
  for (auto &kv : rec.strings)
    if (!AttributeIsVolatile(kv.first)) m.str[kv.first] = kv.second;
  return m;
}

uint64_t SignatureHash(const AttrMaps &m)
{
  uint64_t h = Fnv1a("beamimpact-sweep", 16);
  for (auto &kv : m.num) {
    h = Fnv1a(kv.first.data(), kv.first.size(), h);
    h = Fnv1a(&kv.second, sizeof(double), h);
  }
  for (auto &kv : m.str) {
    h = Fnv1a(kv.first.data(), kv.first.size() + 1, h);
    h = Fnv1a(kv.second.data(), kv.second.size() + 1, h);
  }
  return h;
}

std::string ShortValue(const std::string &s) { return s.size() > 60 ? s.substr(0, 57) + "..." : s; }

// Human-readable differences between the stored and the current signature.
std::string SignatureDiff(const AttrMaps &file, const AttrMaps &now)
{
  std::vector<std::string> d;
  char                     buf[512];
  std::set<std::string>    keys;
  for (auto &kv : file.num) keys.insert(kv.first);
  for (auto &kv : now.num) keys.insert(kv.first);
  for (auto &k : keys) {
    if (AttributeIsVolatile(k)) continue;
    const auto a = file.num.find(k), b = now.num.find(k);
    if (a != file.num.end() && b != now.num.end() && (a->second == b->second || (std::isnan(a->second) && std::isnan(b->second)))) continue;
    std::snprintf(buf, sizeof(buf), "%s: %s in the file, %s now", k.c_str(), a == file.num.end() ? "absent" : std::to_string(a->second).c_str(), b == now.num.end() ? "absent" : std::to_string(b->second).c_str());
    if (a != file.num.end() && b != now.num.end()) std::snprintf(buf, sizeof(buf), "%s: %.10g in the file, %.10g now", k.c_str(), a->second, b->second);
    d.push_back(buf);
  }
  keys.clear();
  for (auto &kv : file.str) keys.insert(kv.first);
  for (auto &kv : now.str) keys.insert(kv.first);
  for (auto &k : keys) {
    if (AttributeIsVolatile(k)) continue;
    const auto a = file.str.find(k), b = now.str.find(k);
    if (a != file.str.end() && b != now.str.end() && a->second == b->second) continue;
    if (k == "sweep_checked_options" && a != file.str.end() && b != now.str.end()) {
      const auto            fo = ParseOptions(a->second), no = ParseOptions(b->second);
      std::set<std::string> names;
      for (auto &kv : fo) names.insert(kv.first);
      for (auto &kv : no) names.insert(kv.first);
      for (auto &n : names) {
        const auto x = fo.find(n), y = no.find(n);
        if (x != fo.end() && y != no.end() && x->second == y->second) continue;
        std::snprintf(buf, sizeof(buf), "option -%s: %s in the file, %s now", n.c_str(), x == fo.end() ? "not set" : ("'" + x->second + "'").c_str(), y == no.end() ? "not set" : ("'" + y->second + "'").c_str());
        d.push_back(buf);
      }
      continue;
    }
    std::snprintf(buf, sizeof(buf), "%s: %s in the file, %s now", k.c_str(), a == file.str.end() ? "absent" : ("'" + ShortValue(a->second) + "'").c_str(), b == now.str.end() ? "absent" : ("'" + ShortValue(b->second) + "'").c_str());
    d.push_back(buf);
  }
  std::string out;
  for (size_t i = 0; i < d.size() && i < 12; ++i) out += "\n  " + d[i];
  if (d.size() > 12) out += "\n  ... (" + std::to_string(d.size() - 12) + " more)";
  return out;
}

// ---------------------------------------------------------------------------
// HDF5: atomic rewrite and read-back
// ---------------------------------------------------------------------------

std::string DirName(const std::string &path)
{
  const size_t s = path.find_last_of('/');
  return s == std::string::npos ? std::string(".") : s == 0 ? std::string("/") : path.substr(0, s);
}

bool FsyncPath(const std::string &path, bool dir)
{
  const int fd = ::open(path.c_str(), (dir ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0 || (dir && errno == EINVAL);
  ::close(fd);
  return ok;
}

// Silences HDF5's own error printing in a scope (we report errors ourselves).
struct H5Quiet {
  H5E_auto2_t func;
  void       *data;
  H5Quiet()
  {
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  }
  ~H5Quiet() { H5Eset_auto2(H5E_DEFAULT, func, data); }
};

herr_t CollectAttribute(hid_t loc, const char *name, const H5A_info_t *, void *op)
{
  AttrMaps   *m     = static_cast<AttrMaps *>(op);
  hid_t       a     = H5Aopen(loc, name, H5P_DEFAULT);
  hid_t       t     = H5Aget_type(a);
  hid_t       s     = H5Aget_space(a);
  H5T_class_t cls   = H5Tget_class(t);
  hssize_t    count = H5Sget_simple_extent_npoints(s);
  if ((cls == H5T_FLOAT || cls == H5T_INTEGER) && count == 1) {
    double v = 0;
    if (H5Aread(a, H5T_NATIVE_DOUBLE, &v) >= 0) m->num[name] = v;
  } else if (cls == H5T_STRING && count == 1) {
    if (H5Tis_variable_str(t) > 0) {
      char *p  = nullptr;
      hid_t mt = H5Tcopy(H5T_C_S1);
      H5Tset_size(mt, H5T_VARIABLE);
      if (H5Aread(a, mt, &p) >= 0 && p) {
        m->str[name] = p;
        H5free_memory(p);
      }
      H5Tclose(mt);
    } else {
      std::vector<char> buf(H5Tget_size(t) + 1, 0);
      if (H5Aread(a, t, buf.data()) >= 0) m->str[name] = std::string(buf.data());
    }
  }
  H5Sclose(s);
  H5Tclose(t);
  H5Aclose(a);
  return 0;
}

bool ReadDataset(hid_t g, const char *name, std::vector<double> *v)
{
  if (H5Lexists(g, name, H5P_DEFAULT) <= 0) return false;
  hid_t ds = H5Dopen2(g, name, H5P_DEFAULT);
  if (ds < 0) return false;
  hid_t          s = H5Dget_space(ds);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  v->assign((size_t)std::max<hssize_t>(0, n), 0.0);
  const bool ok = n <= 0 || H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v->data()) >= 0;
  H5Sclose(s);
  H5Dclose(ds);
  return ok;
}

// Rank 0's view of the output: the record, the rows known so far, the journals
// of the current run, progress and live rewrites.
struct SweepStore {
  std::string                             output, parts;
  RunRecord                               record; // without the progress attributes
  AttrMaps                                signature;
  uint64_t                                signature_hash = 0;
  uint32_t                                ncols          = 0;
  PetscInt                                ncases         = 0;
  std::map<PetscInt, std::vector<double>> rows;
  std::vector<JournalReader>              live; // this run's journals
  int                                     lock_fd = -1;
  // Progress and live rewrites.
  PetscInt already = 0, todo = 0, rows_written = -1;
  double   t_start = 0, last_progress = 0, last_write = 0, write_cost = 0;
};

} // namespace

static PetscErrorCode StoreWrite(SweepStore &S, const SweepPlan &plan)
{
  const std::string tmp = S.output + ".tmp";
  const double      t0  = MPI_Wtime();

  PetscFunctionBeginUser;
  {
    H5Quiet quiet;
    hid_t   file = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot create %s (directory missing or not writable?)", S.output.c_str(), tmp.c_str());
    RunRecord rec = S.record;
    rec.add("sweep_cases_done", (double)S.rows.size());
    rec.add("sweep_complete", (double)((PetscInt)S.rows.size() == S.ncases));
    PetscCall(H5WriteAttributes(file, rec));
    hid_t g = H5Gcreate2(file, "results", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const auto &cols = SweepColumns();
    for (size_t c = 0; c < cols.size(); ++c) {
      std::vector<double> v;
      v.reserve(S.rows.size());
      for (auto &kv : S.rows) v.push_back(kv.second[c]);
      PetscCall(H5WriteDataset1D(g, cols[c].name.c_str(), v, cols[c].unit.c_str()));
    }
    H5Gclose(g);
    // The plan: every axis's value for every case (also those not yet done).
    hid_t gp = H5Gcreate2(file, "sweep", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    for (size_t k = 0; k < plan.axes.size(); ++k) {
      std::vector<double> v(S.ncases);
      for (PetscInt i = 0; i < S.ncases; ++i) v[i] = plan.CaseValues(i)[k];
      PetscCall(H5WriteDataset1D(gp, plan.axes[k].name.c_str(), v, plan.axes[k].unit.c_str()));
    }
    H5Gclose(gp);
    PetscCheck(H5Fclose(file) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: writing %s failed (disk full?)", S.output.c_str(), tmp.c_str());
  }
  PetscCheck(FsyncPath(tmp, false), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: fsync of %s failed (%s)", S.output.c_str(), tmp.c_str(), std::strerror(errno));
  PetscCheck(std::rename(tmp.c_str(), S.output.c_str()) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: cannot rename %s onto it (%s)", S.output.c_str(), tmp.c_str(), std::strerror(errno));
  FsyncPath(DirName(S.output), true);
  S.rows_written = (PetscInt)S.rows.size();
  S.last_write   = MPI_Wtime();
  S.write_cost   = S.last_write - t0;
  PetscFunctionReturn(0);
}

static PetscErrorCode WrongParameters(const SweepStore &S, const std::string &what, const std::string &diff)
{
  PetscFunctionBeginUser;
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
          "-output %s: %s was written by a sweep with different parameters, so it cannot be resumed:%s\n"
          "Rerun with the same options to resume it, add -sweep_restart to discard it and start over, or choose another -output.",
          S.output.c_str(), what.c_str(), diff.c_str());
  PetscFunctionReturn(0);
}

// Loads the rows of an existing output file after checking its parameters.
static PetscErrorCode StoreLoadFile(SweepStore &S)
{
  struct stat st;

  PetscFunctionBeginUser;
  if (::stat(S.output.c_str(), &st) != 0) PetscFunctionReturn(0);
  H5Quiet quiet;
  PetscCheck(H5Fis_hdf5(S.output.c_str()) > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-output %s exists and is not an HDF5 file; add -sweep_restart to overwrite it or choose another -output", S.output.c_str());
  hid_t file = H5Fopen(S.output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s exists but cannot be opened as HDF5; add -sweep_restart to overwrite it or choose another -output", S.output.c_str());
  AttrMaps a;
  H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, NULL, CollectAttribute, &a);
  if (a.str["task"] != "sweep") {
    H5Fclose(file);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-output %s holds no sweep (it was written by -task %s); add -sweep_restart to overwrite it or choose another -output", S.output.c_str(),
            a.str["task"].empty() ? "impact or modes" : a.str["task"].c_str());
  }
  AttrMaps stored;
  for (auto &kv : a.num)
    if (!AttributeIsVolatile(kv.first)) stored.num[kv.first] = kv.second;
  for (auto &kv : a.str)
    if (!AttributeIsVolatile(kv.first)) stored.str[kv.first] = kv.second;
  if (SignatureHash(stored) != S.signature_hash) {
    H5Fclose(file);
    PetscCall(WrongParameters(S, "the file", SignatureDiff(stored, S.signature)));
  }
  hid_t g = H5Gopen2(file, "results", H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-output %s has no /results group; add -sweep_restart to overwrite it", S.output.c_str());
  const auto                      &cols = SweepColumns();
  std::vector<std::vector<double>> data(cols.size());
  for (size_t c = 0; c < cols.size(); ++c) {
    const bool ok = ReadDataset(g, cols[c].name.c_str(), &data[c]);
    PetscCheck(ok && data[c].size() == data[0].size(), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-output %s: /results/%s is missing or has the wrong length; add -sweep_restart to overwrite it", S.output.c_str(),
               cols[c].name.c_str());
  }
  H5Gclose(g);
  H5Fclose(file);
  for (size_t r = 0; r < data[0].size(); ++r) {
    const double idx = data[0][r];
    if (!(idx >= 0 && idx < S.ncases && idx == std::floor(idx))) continue;
    std::vector<double> row(cols.size());
    for (size_t c = 0; c < cols.size(); ++c) row[c] = data[c][r];
    S.rows.emplace((PetscInt)idx, std::move(row));
  }
  PetscFunctionReturn(0);
}

static void RemoveJournals(const SweepStore &S, bool also_lock)
{
  DIR *d = ::opendir(S.parts.c_str());
  if (!d) return;
  std::vector<std::string> names;
  while (dirent *e = ::readdir(d)) {
    int run, rank;
    if (ParseJournalName(e->d_name, &run, &rank)) names.push_back(e->d_name);
  }
  ::closedir(d);
  for (auto &n : names) ::unlink((S.parts + "/" + n).c_str());
  if (also_lock) {
    ::unlink((S.parts + "/lock").c_str());
    ::rmdir(S.parts.c_str());
  }
}

// Rank 0: lock the output, load what is done (file and journals), rewrite the
// file with all of it, drop the old journals. Returns the next run number.
static PetscErrorCode StorePrepare(SweepStore &S, const SweepPlan &plan, int *run)
{
  PetscFunctionBeginUser;
  if (::mkdir(S.parts.c_str(), 0755) != 0) PetscCheck(errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot create the journal directory %s (%s)", S.output.c_str(), S.parts.c_str(), std::strerror(errno));
  S.lock_fd = ::open((S.parts + "/lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  PetscCheck(S.lock_fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot create %s/lock (%s)", S.output.c_str(), S.parts.c_str(), std::strerror(errno));
  PetscCheck(::flock(S.lock_fd, LOCK_EX | LOCK_NB) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s is being written by another sweep that is still running (%s/lock is held); wait for it or choose another -output",
             S.output.c_str(), S.parts.c_str());
  if (plan.restart) {
    RemoveJournals(S, false);
    ::unlink(S.output.c_str());
  } else PetscCall(StoreLoadFile(S));
  // Journals of earlier runs (killed before they finished).
  *run = 0;
  DIR *d = ::opendir(S.parts.c_str());
  PetscCheck(d, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot read %s", S.output.c_str(), S.parts.c_str());
  std::vector<std::string> names;
  while (dirent *e = ::readdir(d)) {
    int r, rank;
    if (ParseJournalName(e->d_name, &r, &rank)) {
      names.push_back(e->d_name);
      *run = std::max(*run, r);
    }
  }
  ::closedir(d);
  std::sort(names.begin(), names.end());
  for (auto &n : names) {
    JournalReader j;
    j.path = S.parts + "/" + n;
    if (j.ReadNew(S.signature_hash, S.ncols, S.ncases, &S.rows, nullptr) == JournalReader::WrongParameters)
      PetscCall(WrongParameters(S, "the journal " + j.path, "\n  (its parameter signature differs from the current one)"));
  }
  // One file holding everything found; only then are the old journals redundant.
  PetscCall(StoreWrite(S, plan));
  RemoveJournals(S, false);
  *run += 1;
  PetscFunctionReturn(0);
}

static std::string Points(PetscInt n) { return std::to_string((long long)n) + (n == 1 ? " point" : " points"); }

static std::string FormatDuration(double s)
{
  char buf[64];
  if (!std::isfinite(s)) return "?";
  if (s < 60) std::snprintf(buf, sizeof(buf), "%.0f s", s);
  else if (s < 3600) std::snprintf(buf, sizeof(buf), "%d min %02d s", (int)(s / 60), (int)std::fmod(s, 60));
  else std::snprintf(buf, sizeof(buf), "%d h %02d min", (int)(s / 3600), (int)std::fmod(s / 60, 60));
  return buf;
}

// Rank 0 between its cases: a progress line every -sweep_progress_interval and
// a rewrite of the file with the journaled rows every -sweep_write_interval.
static PetscErrorCode StorePoll(SweepStore &S, const SweepPlan &plan, PetscInt done)
{
  const double now = MPI_Wtime();

  PetscFunctionBeginUser;
  if (!plan.quiet && now - S.last_progress >= plan.progress_interval && done < S.todo) {
    const double rate = done / (now - S.t_start);
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT, "sweep: %" PetscInt_FMT "/%" PetscInt_FMT " points (%.0f%%)  %.3g points/s  ETA %s\n", S.already + done, S.ncases,
                           100.0 * (S.already + done) / S.ncases, rate, rate > 0 ? FormatDuration((S.todo - done) / rate).c_str() : "?"));
    std::fflush(PETSC_STDOUT);
    S.last_progress = now;
  }
  // Live rewrites cost rank 0 at most ~5% of its time.
  const double interval = std::max(plan.write_interval, 20 * S.write_cost);
  if (now - S.last_write >= interval && done < S.todo) {
    PetscInt added = 0;
    for (auto &j : S.live) j.ReadNew(S.signature_hash, S.ncols, S.ncases, &S.rows, &added);
    if ((PetscInt)S.rows.size() != S.rows_written) PetscCall(StoreWrite(S, plan));
    S.last_write = MPI_Wtime();
    S.write_cost = S.last_write - now; // reading the journals included
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TaskSweep(MPI_Comm comm, const std::string &output)
{
  PetscMPIInt rank, size;
  Scenario    base;
  SweepPlan   plan;
  TaskFarm    farm;
  SweepStore  S;
  ImpactResult probe;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCheck(!output.empty(), comm, PETSC_ERR_ARG_WRONG, "-task sweep writes its results to a file: give -output FILE.h5 (not 'none')");
  {
    // The other -impact_* options are shared by every case; the point is set
    // per case from -sweep_x, so -impact_x would be silently meaningless: refuse it
    // (like any other unused option). Read the options with a valid point in its place.
    char            given[256] = "";
    PetscBool       has        = PETSC_FALSE;
    ScenarioReading how;
    how.after_bodies = [&](const Scenario &bodies) -> PetscErrorCode {
      char x0[64];
      PetscFunctionBeginUser;
      PetscCall(SweepPlanFromOptions(comm, bodies.beam, &plan));
      PetscCall(PetscOptionsGetString(NULL, NULL, "-impact_x", given, sizeof(given), &has));
      std::snprintf(x0, sizeof(x0), "%.17g", (double)plan.axes[0].values[0]);
      PetscCall(PetscOptionsSetValue(NULL, "-impact_x", x0));
      PetscFunctionReturn(0);
    };
    PetscCall(ScenarioFromOptions(comm, how, &base));
    PetscCall(PetscOptionsClearValue(NULL, "-impact_x"));
    PetscCheck(!(base.monitor.ball || base.monitor.energy || !base.monitor.velocity_at.empty() || !base.monitor.snapshot_times.empty()), comm, PETSC_ERR_ARG_INCOMP,
               "-task sweep records no time series or snapshots (-monitor_ball, -monitor_energy, -monitor_velocity_at, -snapshot_times): run -task impact at the points of interest; only -monitor_segment (its peak is a column) works in a sweep");
    PetscCheck(!has, comm, PETSC_ERR_ARG_INCOMP, "-impact_x %s has no effect with -task sweep: the impact points come from -sweep_x; remove -impact_x", given);
  }
  PetscCall(TaskFarmCreate(comm, plan.ranks_per_case, &farm));

  // A probe on rank 0's group before any work: sets up the integrator for the
  // first point and steps 1 ns, so that bad or unused options stop the sweep
  // here with one message, and the file can record the integrator.
  if (farm.group != MPI_COMM_NULL && rank < plan.ranks_per_case) {
    Scenario c                    = SweepCaseFor(plan, base, 0);
    c.impact.max_time             = 1e-9;
    c.impact.check_unused_options = PETSC_TRUE;
    c.impact.report_setup         = plan.quiet ? PETSC_FALSE : PETSC_TRUE; // integrator, step, warnings: once
    PetscCall(ImpactRun(farm.group, c.beam, c.ball, c.impact, MonitorRequest(), &probe));
  }

  S.output = output;
  S.parts  = output + ".parts";
  S.ncases = plan.cases();
  S.ncols  = (uint32_t)SweepColumns().size();
  int                   run = 0;
  std::vector<PetscInt> todo;
  if (rank == 0) {
    std::string options, columns;
    PetscCall(OptionsAsString(&options));
    for (auto &c : SweepColumns()) columns += (columns.empty() ? "" : ",") + c.name;
    PetscCall(RunRecordBuild(base, &probe, &S.record));
    S.record.add("task", "sweep");
    S.record.add("sweep_x", plan.x_spec);
    S.record.add("sweep_axes", "x");
    S.record.add("sweep_ranks_per_case", (double)plan.ranks_per_case);
    S.record.add("rigid_loss_fraction", plan.rigid_loss_fraction);
    S.record.add("sweep_cases_total", (double)S.ncases);
    S.record.add("sweep_columns", columns);
    S.record.add("sweep_checked_options", CheckedOptions(options));
    S.signature      = SignatureMaps(S.record);
    S.signature_hash = SignatureHash(S.signature);
    PetscCall(StorePrepare(S, plan, &run));
    for (PetscInt i = 0; i < S.ncases; ++i)
      if (!S.rows.count(i)) todo.push_back(i);
  }
  PetscInt ntodo = (PetscInt)todo.size();
  PetscCallMPI(MPI_Bcast(&ntodo, 1, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&run, 1, MPI_INT, 0, comm));
  todo.resize(ntodo);
  if (ntodo) PetscCallMPI(MPI_Bcast(todo.data(), ntodo, MPIU_INT, 0, comm));

  if (rank == 0) {
    S.already = S.ncases - ntodo;
    S.todo    = ntodo;
    for (PetscMPIInt r = 0; r < farm.groups * plan.ranks_per_case; r += (PetscMPIInt)plan.ranks_per_case) {
      JournalReader j;
      j.path = JournalName(S.parts, run, r);
      S.live.push_back(j);
    }
    if (!plan.quiet) {
      const auto &x = plan.axes[0].values;
      char        range[128]; // PetscPrintf would write 0 as "0."
      std::snprintf(range, sizeof(range), "x from %g to %g m", (double)*std::min_element(x.begin(), x.end()), (double)*std::max_element(x.begin(), x.end()));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: %s, %s, on %d rank(s): %" PetscInt_FMT " group(s) of %" PetscInt_FMT "%s; ts %s (%s)\n", Points(S.ncases).c_str(), range, size, farm.groups, plan.ranks_per_case,
                            size % plan.ranks_per_case ? " (the ranks left over stay idle)" : "", probe.ts_type.c_str(), probe.formulation.c_str()));
      if (S.already && ntodo) PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: resuming %s: %" PetscInt_FMT " of %" PetscInt_FMT " points already done, %" PetscInt_FMT " to compute\n", output.c_str(), S.already, S.ncases, ntodo));
      std::fflush(PETSC_STDOUT);
    }
  }

  // The farm: each group takes the next pending case; its leader journals the row.
  JournalWriter journal;
  journal.path      = JournalName(S.parts, run, rank);
  journal.signature = S.signature_hash;
  PetscCallMPI(MPI_Bcast(&journal.signature, 1, MPI_UINT64_T, 0, comm));
  journal.ncols = (uint32_t)SweepColumns().size();
  std::vector<double> mine; // this rank's rows (group leaders), gathered on rank 0 at the end
  PetscInt            computed = 0;
  double              busy     = 0; // s, in cases (load balance: busy / farm time)
  double              t0       = MPI_Wtime();
  S.t_start = S.last_progress = t0;
  if (ntodo > 0) {
    auto run_case = [&](MPI_Comm group, PetscInt t) -> PetscErrorCode {
      const PetscInt      index = todo[t];
      std::vector<double> row;
      ImpactResult        result;
      PetscFunctionBeginUser;
      const double   tc   = MPI_Wtime();
      PetscErrorCode ierr = SweepCaseRun(group, plan, base, index, &row, &result);
      busy += MPI_Wtime() - tc;
      if (ierr) {
        const std::string msg = LastErrorMessage(ierr);
        const double      x   = plan.CaseValues(index)[0];
        // main() reports errors of world rank 0 only: other group leaders say it here.
        if (rank != 0 && farm.group_rank == 0) {
          std::fprintf(stderr, "beamimpact: error: sweep point %" PetscInt_FMT " (x = %g m) on rank %d: %s\n", index, x, rank, msg.c_str());
          std::fflush(stderr);
        }
        SETERRQ(PETSC_COMM_SELF, ierr, "sweep point %" PetscInt_FMT " (x = %g m): %s", index, x, msg.c_str());
      }
      if (farm.group_rank == 0) {
        PetscCall(journal.Append(row));
        mine.insert(mine.end(), row.begin(), row.end());
        ++computed;
      }
      PetscFunctionReturn(0);
    };
    auto between = [&](PetscInt done) -> PetscErrorCode { return StorePoll(S, plan, done); };
    PetscCall(TaskFarmRun(farm, ntodo, run_case, between));
  }
  const double farm_time = MPI_Wtime() - t0;
  journal.Close();
  PetscCall(TaskFarmDestroy(&farm));

  // Gather this run's rows on rank 0 (the journals need not be visible there).
  {
    PetscMPIInt              n = (PetscMPIInt)mine.size();
    std::vector<PetscMPIInt> counts(size), displs(size);
    PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
    std::vector<double> all;
    if (rank == 0) {
      size_t total = 0;
      for (PetscMPIInt r = 0; r < size; ++r) {
        displs[r] = (PetscMPIInt)total;
        total += counts[r];
      }
      all.resize(total);
    }
    PetscCallMPI(MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm));
    if (rank == 0) {
      for (size_t p = 0; p + S.ncols <= all.size(); p += S.ncols) S.rows[(PetscInt)all[p]] = std::vector<double>(all.begin() + p, all.begin() + p + S.ncols);
      PetscCheck((PetscInt)S.rows.size() == S.ncases, PETSC_COMM_SELF, PETSC_ERR_PLIB, "sweep ended with %zu of %" PetscInt_FMT " rows", S.rows.size(), S.ncases);
      PetscCall(StoreWrite(S, plan));
      RemoveJournals(S, true);
      ::close(S.lock_fd);
    }
  }
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : &computed, &computed, 1, MPIU_INT, MPI_SUM, 0, comm));
  double busy_sum = 0, busy_min = 0;
  PetscCallMPI(MPI_Reduce(&busy, &busy_sum, 1, MPI_DOUBLE, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(&busy, &busy_min, 1, MPI_DOUBLE, MPI_MIN, 0, comm));
  const double elapsed = MPI_Wtime() - t0;
  if (rank == 0 && !plan.quiet) {
    if (ntodo == 0) PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: all %" PetscInt_FMT " points were already done; nothing to compute\n", S.ncases));
    else {
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: computed %s in %.3f s (%.4g points/s) on %d rank(s), %" PetscInt_FMT " already done\n", Points(computed).c_str(), elapsed, computed / elapsed, size,
                            S.already));
      // Load balance: the share of the farm's time the ranks spent in cases
      // (below 100%: waiting for the last cases, journaling, live rewrites).
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: ranks busy %.1f%% of the time on average, %.1f%% the least busy\n", 100 * busy_sum / (size * farm_time), 100 * busy_min / farm_time));
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s (%s)\n", output.c_str(), Points(S.ncases).c_str()));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// -task sweep: the case runner and the task (options, probe, store, farm, report).
// See sweep.hpp.
#include "studies/sweep.hpp"

#include "base/options_util.hpp"
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "io/scenario_options.hpp"
#include "io/text.hpp"
#include "model/rigid.hpp"
#include "studies/sweep_farm.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

// ---------------------------------------------------------------------------
// Case runner
// ---------------------------------------------------------------------------

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
  PetscCall(ImpactRun(comm, c, result));
  const ImpactResult &r = *result;
  // Rigid-body model, Eq. (11), with the beam's own mass, centre of mass and inertia (for the
  // paper's uniform beam: M = mu L, I_cm = M L^2 / 12 about its centre).
  const BeamRigidBody body = BeamRigidBodyOf(c.beam);
  const PetscReal     M_e  = RigidEffectiveMass(body.mass, body.inertia_cm, std::abs(r.x - body.x_cm));
  row->clear();
  row->push_back((double)index);
  for (auto &rc : ImpactResultColumns()) row->push_back(rc.get(r));
  row->push_back(RigidACOR(c.ball.mass, M_e, plan.rigid_loss_fraction));
  row->push_back(RigidForcedLossFraction(c.ball.mass, M_e, r.acor_corrected));
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// The task
// ---------------------------------------------------------------------------

namespace {

// Rank 0's progress lines.
struct SweepProgress {
  PetscInt ncases = 0, already = 0, todo = 0; // cases: all, done before this run, to compute
  double   t_start = 0, last = 0;             // s (MPI_Wtime)
};

// What this rank did: the rows it computed as a group leader (gathered on rank 0 at
// the end), their number, and its time in cases (load balance: busy / farm time).
struct SweepShare {
  std::vector<double> rows;
  PetscInt            computed = 0;
  double              busy     = 0; // s
};

std::string Points(PetscInt n) { return std::to_string((long long)n) + (n == 1 ? " point" : " points"); }

std::string FormatDuration(double s)
{
  char buf[64];
  if (!std::isfinite(s)) return "?";
  if (s < 60) std::snprintf(buf, sizeof(buf), "%.0f s", s);
  else if (s < 3600) std::snprintf(buf, sizeof(buf), "%d min %02d s", (int)(s / 60), (int)std::fmod(s, 60));
  else std::snprintf(buf, sizeof(buf), "%d h %02d min", (int)(s / 3600), (int)std::fmod(s / 60, 60));
  return buf;
}

// The base scenario and the plan (read after the beam and ball, against which its points
// are checked). The other -impact_* options are shared by every case, but an axis's own
// option (-impact_x) would be silently meaningless: it is refused (like any other unused
// option), and the rest is read with the axis's first point in its place.
PetscErrorCode SweepReadOptions(MPI_Comm comm, Scenario *base, SweepPlan *plan)
{
  ScenarioReading how;

  PetscFunctionBeginUser;
  how.after_bodies = [&](const Scenario &bodies) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(SweepPlanFromOptions(comm, bodies, plan));
    for (const SweepAxis &a : plan->axes) {
      const std::string opt = std::string("-") + a.type->name;
      char              given[256] = "", first[64];
      PetscBool         has;
      PetscCall(PetscOptionsGetString(NULL, NULL, opt.c_str(), given, sizeof(given), &has));
      PetscCheck(!has, comm, PETSC_ERR_ARG_INCOMP, "%s %s has no effect with -task sweep: the %s come from -sweep_%s; remove %s", opt.c_str(), given, a.type->points, a.type->column, opt.c_str());
      std::snprintf(first, sizeof(first), "%.17g", (double)a.values[0]);
      PetscCall(PetscOptionsSetValue(NULL, opt.c_str(), first));
    }
    PetscFunctionReturn(0);
  };
  PetscCall(ScenarioFromOptions(comm, how, base));
  for (const SweepAxis &a : plan->axes) PetscCall(PetscOptionsClearValue(NULL, (std::string("-") + a.type->name).c_str()));
  const MonitorRequest &m = base->monitor;
  PetscCheck(!(m.ball || m.energy || !m.velocity_at.empty() || !m.snapshot_times.empty()), comm, PETSC_ERR_ARG_INCOMP,
             "-task sweep records no time series or snapshots (-monitor_ball, -monitor_energy, -monitor_velocity_at, -snapshot_times): run -task impact at the points of interest; only -monitor_segment (its peak is a column) works in a sweep");
  PetscFunctionReturn(0);
}

// A probe on rank 0's group before any work: sets up the integrator for the
// first point and steps 1 ns, so that bad or unused options stop the sweep
// here with one message, and the file can record the integrator.
PetscErrorCode SweepProbe(const TaskFarm &farm, const SweepPlan &plan, const Scenario &base, ImpactResult *probe)
{
  PetscFunctionBeginUser;
  if (farm.group != MPI_COMM_NULL && farm.world_rank < plan.ranks_per_case) {
    Scenario c                    = SweepCaseFor(plan, base, 0);
    c.impact.max_time             = 1e-9;
    c.impact.check_unused_options = PETSC_TRUE;
    c.impact.report_setup         = plan.quiet ? PETSC_FALSE : PETSC_TRUE; // integrator, step, warnings: once
    c.monitor                     = MonitorRequest();
    PetscCall(ImpactRun(farm.group, c, probe));
  }
  PetscFunctionReturn(0);
}

// The file's root attributes: the scenario, the probe's integrator and the plan.
PetscErrorCode SweepRecordBuild(const Scenario &base, const SweepPlan &plan, const ImpactResult &probe, RunRecord *rec)
{
  std::string options, columns, axes;

  PetscFunctionBeginUser;
  PetscCall(OptionsAsString(&options));
  for (auto &c : SweepColumns()) columns += (columns.empty() ? "" : ",") + c.name;
  for (auto &a : plan.axes) axes += (axes.empty() ? "" : ",") + std::string(a.type->column);
  PetscCall(RunRecordBuild(base, &probe, rec));
  rec->add("task", "sweep");
  for (auto &a : plan.axes) rec->add(std::string("sweep_") + a.type->column, a.spec);
  rec->add("sweep_axes", axes);
  rec->add("sweep_ranks_per_case", (double)plan.ranks_per_case);
  rec->add("rigid_loss_fraction", plan.rigid_loss_fraction);
  rec->add("sweep_cases_total", (double)plan.cases());
  rec->add("sweep_columns", columns);
  rec->add("sweep_checked_options", SweepCheckedOptions(options));
  PetscFunctionReturn(0);
}

// Rank 0 opens the store (resuming what is done) and follows this run's journals; every
// rank learns the cases still to compute and this run's number.
PetscErrorCode SweepStart(const TaskFarm &farm, const std::string &output, const Scenario &base, const SweepPlan &plan, const ImpactResult &probe, SweepStore *S, std::vector<PetscInt> *todo, int *run)
{
  PetscFunctionBeginUser;
  *run = 0;
  todo->clear();
  if (farm.world_rank == 0) {
    RunRecord                record;
    std::vector<PetscMPIInt> leaders;
    PetscCall(SweepRecordBuild(base, plan, probe, &record));
    SweepStoreInit(output, plan, SweepColumns(), record, S);
    PetscCall(SweepStoreOpen(*S, run));
    for (PetscInt i = 0; i < S->ncases; ++i)
      if (!S->rows.count(i)) todo->push_back(i);
    for (PetscMPIInt r = 0; r < farm.groups * plan.ranks_per_case; r += (PetscMPIInt)plan.ranks_per_case) leaders.push_back(r);
    SweepStoreFollow(*S, *run, leaders);
  }
  PetscInt ntodo = (PetscInt)todo->size();
  PetscCallMPI(MPI_Bcast(&ntodo, 1, MPIU_INT, 0, farm.world));
  PetscCallMPI(MPI_Bcast(run, 1, MPI_INT, 0, farm.world));
  todo->resize(ntodo);
  if (ntodo) PetscCallMPI(MPI_Bcast(todo->data(), ntodo, MPIU_INT, 0, farm.world));
  PetscFunctionReturn(0);
}

// Rank 0: what is about to run.
PetscErrorCode SweepAnnounce(const TaskFarm &farm, const SweepPlan &plan, const ImpactResult &probe, const SweepProgress &P, const std::string &output)
{
  std::string range;

  PetscFunctionBeginUser;
  if (farm.world_rank != 0 || plan.quiet) PetscFunctionReturn(0);
  for (auto &a : plan.axes) {
    char text[128]; // PetscPrintf would write 0 as "0."
    std::snprintf(text, sizeof(text), "%s from %g to %g %s", a.type->column, (double)*std::min_element(a.values.begin(), a.values.end()), (double)*std::max_element(a.values.begin(), a.values.end()), a.type->unit);
    range += (range.empty() ? "" : ", ") + std::string(text);
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: %s, %s, on %d rank(s): %" PetscInt_FMT " group(s) of %" PetscInt_FMT "%s; ts %s (%s)\n", Points(P.ncases).c_str(), range.c_str(), farm.world_size, farm.groups,
                        plan.ranks_per_case, farm.world_size % plan.ranks_per_case ? " (the ranks left over stay idle)" : "", probe.ts_type.c_str(), probe.formulation.c_str()));
  if (P.already && P.todo)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: resuming %s: %" PetscInt_FMT " of %" PetscInt_FMT " points already done, %" PetscInt_FMT " to compute\n", output.c_str(), P.already, P.ncases, P.todo));
  std::fflush(PETSC_STDOUT);
  PetscFunctionReturn(0);
}

// Rank 0 between its cases: a progress line every -sweep_progress_interval and
// a rewrite of the file with the journaled rows every -sweep_write_interval.
PetscErrorCode SweepPoll(SweepStore &S, SweepProgress &P, const SweepPlan &plan, PetscInt done)
{
  const double now = MPI_Wtime();

  PetscFunctionBeginUser;
  if (done >= P.todo) PetscFunctionReturn(0);
  if (!plan.quiet && now - P.last >= plan.progress_interval) {
    const double rate = done / (now - P.t_start);
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT, "sweep: %" PetscInt_FMT "/%" PetscInt_FMT " points (%.0f%%)  %.3g points/s  ETA %s\n", P.already + done, P.ncases, 100.0 * (P.already + done) / P.ncases,
                           rate, rate > 0 ? FormatDuration((P.todo - done) / rate).c_str() : "?"));
    std::fflush(PETSC_STDOUT);
    P.last = now;
  }
  PetscCall(SweepStoreRefresh(S));
  PetscFunctionReturn(0);
}

// The farm: each group takes the next pending case; its leader journals the row and
// keeps it for the gather at the end.
PetscErrorCode SweepRunCases(TaskFarm &farm, const SweepPlan &plan, const Scenario &base, const std::vector<PetscInt> &todo, int run, const std::string &output, SweepStore &S, SweepProgress &P, SweepShare *mine)
{
  SweepJournalWriter journal;
  const PetscMPIInt  rank = farm.world_rank;

  PetscFunctionBeginUser;
  journal.path      = SweepJournalName(output, run, rank);
  journal.signature = S.signature_hash;
  PetscCallMPI(MPI_Bcast(&journal.signature, 1, MPI_UINT64_T, 0, farm.world));
  journal.ncols = (uint32_t)SweepColumns().size();
  auto run_case = [&](MPI_Comm group, PetscInt t) -> PetscErrorCode {
    const PetscInt      index = todo[t];
    std::vector<double> row;
    ImpactResult        result;
    PetscFunctionBeginUser;
    const double   tc   = MPI_Wtime();
    PetscErrorCode ierr = SweepCaseRun(group, plan, base, index, &row, &result);
    mine->busy += MPI_Wtime() - tc;
    if (ierr) {
      const std::string msg = LastErrorMessage(ierr);
      // main() reports errors of world rank 0 only: other group leaders say it here.
      if (rank != 0 && farm.group_rank == 0) {
        std::fprintf(stderr, "beamimpact: error: sweep point %" PetscInt_FMT " (%s) on rank %d: %s\n", index, SweepCaseText(plan, index, false).c_str(), rank, msg.c_str());
        std::fflush(stderr);
      }
      SETERRQ(PETSC_COMM_SELF, ierr, "sweep point %" PetscInt_FMT " (%s): %s", index, SweepCaseText(plan, index, true).c_str(), msg.c_str());
    }
    if (farm.group_rank == 0) {
      PetscCall(journal.Append(row));
      mine->rows.insert(mine->rows.end(), row.begin(), row.end());
      ++mine->computed;
    }
    PetscFunctionReturn(0);
  };
  auto between = [&](PetscInt done) -> PetscErrorCode { return SweepPoll(S, P, plan, done); };
  if (!todo.empty()) PetscCall(TaskFarmRun(farm, (PetscInt)todo.size(), run_case, between));
  journal.Close();
  PetscFunctionReturn(0);
}

// Rank 0 gathers this run's rows over MPI (the journals need not be visible there) and
// writes the complete file.
PetscErrorCode SweepGather(MPI_Comm comm, const std::vector<double> &mine, SweepStore &S)
{
  PetscMPIInt              rank, size;
  std::vector<double>      all;
  PetscMPIInt              n = (PetscMPIInt)mine.size();
  std::vector<PetscMPIInt> counts, displs;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  counts.resize(size);
  displs.resize(size);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
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
    PetscCall(SweepStoreClose(S));
  }
  PetscFunctionReturn(0);
}

// Rank 0: what was computed, how fast, and how evenly the ranks were loaded.
PetscErrorCode SweepReport(MPI_Comm comm, const SweepPlan &plan, const SweepShare &mine, const SweepProgress &P, double t0, double farm_time, const std::string &output)
{
  PetscMPIInt rank, size;
  PetscInt    computed = mine.computed;
  double      busy_sum = 0, busy_min = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : &computed, &computed, 1, MPIU_INT, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(&mine.busy, &busy_sum, 1, MPI_DOUBLE, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(&mine.busy, &busy_min, 1, MPI_DOUBLE, MPI_MIN, 0, comm));
  const double elapsed = MPI_Wtime() - t0;
  if (rank != 0 || plan.quiet) PetscFunctionReturn(0);
  if (P.todo == 0) PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: all %" PetscInt_FMT " points were already done; nothing to compute\n", P.ncases));
  else {
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: computed %s in %.3f s (%.4g points/s) on %d rank(s), %" PetscInt_FMT " already done\n", Points(computed).c_str(), elapsed, computed / elapsed, size, P.already));
    // Load balance: the share of the farm's time the ranks spent in cases
    // (below 100%: waiting for the last cases, journaling, live rewrites).
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: ranks busy %.1f%% of the time on average, %.1f%% the least busy\n", 100 * busy_sum / (size * farm_time), 100 * busy_min / farm_time));
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s (%s)\n", output.c_str(), Points(P.ncases).c_str()));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TaskSweep(MPI_Comm comm, const std::string &output)
{
  Scenario              base;
  SweepPlan             plan;
  TaskFarm              farm;
  SweepStore            store;
  ImpactResult          probe;
  std::vector<PetscInt> todo;
  int                   run = 0;
  SweepProgress         progress;
  SweepShare            mine;

  PetscFunctionBeginUser;
  PetscCheck(!output.empty(), comm, PETSC_ERR_ARG_WRONG, "-task sweep writes its results to a file: give -output FILE.h5 (not 'none')");
  PetscCall(SweepReadOptions(comm, &base, &plan));
  PetscCall(TaskFarmCreate(comm, plan.ranks_per_case, &farm));
  PetscCall(SweepProbe(farm, plan, base, &probe));
  PetscCall(SweepStart(farm, output, base, plan, probe, &store, &todo, &run));
  progress.ncases  = plan.cases();
  progress.todo    = (PetscInt)todo.size();
  progress.already = progress.ncases - progress.todo;
  PetscCall(SweepAnnounce(farm, plan, probe, progress, output));
  const double t0  = MPI_Wtime();
  progress.t_start = progress.last = t0;
  PetscCall(SweepRunCases(farm, plan, base, todo, run, output, store, progress, &mine));
  const double farm_time = MPI_Wtime() - t0;
  PetscCall(TaskFarmDestroy(&farm));
  PetscCall(SweepGather(comm, mine.rows, store));
  PetscCall(SweepReport(comm, plan, mine, progress, t0, farm_time, output));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// -task sweep: the case runner and the task (options, probe, store, farm, report).
// See sweep.hpp.
#include "studies/sweep.hpp"

#include "base/option_table.hpp"
#include "base/options_util.hpp"
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "io/scenario_options.hpp"
#include "io/sha256.hpp"
#include "io/text.hpp"
#include "model/shell.hpp"
#include "run/outcome.hpp"
#include "solvers/ts_stepper.hpp"
#include "studies/sweep_farm.hpp"
#include "studies/sweep_notes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>

namespace beamimpact {

// ---------------------------------------------------------------------------
// Case runner
// ---------------------------------------------------------------------------

std::vector<SweepColumn> SweepColumns(const SweepPlan &plan)
{
  std::vector<SweepColumn> c;
  c.push_back({"case_index", "1", false, true, {}, "the point's index in the plan (the first axis slowest)"});
  for (const SweepAxis &a : plan.axes)
    c.push_back(
      {a.name, a.unit, false, false, a.labels, "the point's value of -" + a.name + " (a text axis: its label)"});
  c.push_back(
    {"status", "1", false, true, {}, "0: ok; else a code (below), its numbers NaN: a failed run or no impact"});
  for (auto &rc : ImpactResultColumns())
    c.push_back({rc.name, rc.unit, std::string(rc.name) == "wall_time", rc.integer, {}, rc.description});
  return c;
}

int SweepStatusOfError(PetscErrorCode ierr)
{
  switch (ierr) {
  case PETSC_ERR_NOT_CONVERGED:
    return SweepNotConverged;
  case PETSC_ERR_FP:
    return SweepNotFinite;
  case PETSC_ERR_ARG_OUTOFRANGE:
  case PETSC_ERR_ARG_WRONG:
  case PETSC_ERR_ARG_INCOMP:
  case PETSC_ERR_ARG_UNKNOWN_TYPE: // a text value the set-up does not know:
  case PETSC_ERR_USER: // -ts_rk_type 9x, PETSc's "Unknown option 9x for -ts_rk_type. Available options: ..."
  case PETSC_ERR_USER_INPUT:
  case PETSC_ERR_SUP:
    return SweepRefused;
  default:
    return SweepFailedOther;
  }
}

PetscErrorCode SweepCaseRun(MPI_Comm comm, const SweepPlan &plan, PetscInt index, std::vector<double> *row,
                            std::string *reason, ImpactResult *result, SweepReuse *reuse)
{
  Scenario       c;
  int            status = SweepOk;
  PetscErrorCode ierr   = 0;

  PetscFunctionBeginUser;
  // The case's options stay set while it runs (the integrator reads its own from them).
  ierr = SweepCaseScenario(comm, plan, index, true, &c, &status, reason, reuse ? &reuse->scenario : nullptr);
  if (!ierr && status == SweepOk) {
    c.impact.rigid_loss_fraction = plan.rigid_loss_fraction; // the rigid_acor column's f
    c.impact.mode_energies       = PETSC_FALSE;              // the points' files are rows: no /modes_energy
    ImpactStructure *structure   = nullptr;
    if (reuse) { // the structure's system, unless this point is on another beam
      const std::vector<PetscReal> key = c.beam.parts.SystemKey(); // the parts' values at the point (a shell's a, the
                                                                   // bed's disc): follow the ball
      if (!reuse->scenario.last_partial || key.size() != reuse->part_key.size() ||
          (!key.empty() && std::memcmp(key.data(), reuse->part_key.data(), key.size() * sizeof key[0]) != 0))
        reuse->structure = ImpactStructure();
      reuse->part_key = key;
      structure       = &reuse->structure;
    }
    const BeamSystem *kept = structure ? structure->sys.get() : nullptr;
    ierr                   = ImpactRun(comm, c, result, structure);
    if (structure && structure->sys && structure->sys.get() != kept) ++reuse->systems;
    if (ierr) {
      status  = SweepStatusOfError(ierr);
      *reason = SweepErrorReason(ierr);
      ierr    = 0;
    } else if (result->ended_in_contact) { // a contact cut short by -impact_max_time: no number
      status  = SweepCutInContact;
      *reason = ImpactCutOffReason(c, *result);
    }
  }
  PetscCall(SweepCaseOptionsClear(plan));
  PetscCall(ierr);
  const double                 nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PetscReal> v   = plan.CaseValues(index);
  row->clear();
  row->push_back((double)index);
  row->insert(row->end(), v.begin(), v.end());
  row->push_back((double)status);
  if (status == SweepOk) {
    for (auto &rc : ImpactResultColumns())
      row->push_back(rc.Get(*result)); // the results table, NaN where a column does not apply
    reason->clear();
  } else row->resize(row->size() + ImpactResultColumns().size(), nan);
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// The task
// ---------------------------------------------------------------------------

namespace {

int g_exit_status = 0; // SweepExitStatus()

// Rank 0's progress lines.
struct SweepProgress {
  PetscInt ncases = 0, already = 0, todo = 0; // cases: all, done before this run, to compute
  double   t_start = 0, last = 0;             // s (MPI_Wtime)
  bool     cost_said = false;                 // the expected time was judged (first progress line)
};

// What this rank did: the rows it computed as a group leader (gathered on rank 0 at
// the end) and the reasons of those that failed, their number, and its time in cases
// (load balance: busy / farm time) and in the farm's own work (hand-out, journal, rewrites).
struct SweepShare {
  std::vector<double>             rows;
  std::map<PetscInt, std::string> reasons;
  PetscInt                        computed = 0, failed = 0, shown = 0;
  double                          busy = 0, journal = 0, handout = 0; // s
  PetscInt reuse[3] = {0, 0, 0}; // scenarios read whole, point's parts only; systems built (SweepReuse)
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

// Where the points that cannot run are, in words: "off the racket's face (outside the head's
// outline)", "off the beam", "held fixed", joined by "or", each with its count when there are several kinds.
static std::string SkippedText(const std::map<int, PetscInt> &skipped)
{
  std::string text;
  for (const auto &kv : skipped) {
    const char *where = kv.first == SweepOffFace
                        ? "off the racket's face (outside the head's outline, where there are no strings)"
                      : kv.first == SweepOffBeam   ? "off the beam"
                      : kv.first == SweepHeldPoint ? "held fixed (a clamped or pinned end, -beam_clamp)"
                                                   : SweepStatusName(kv.first);
    text += (text.empty() ? "" : " or ") + std::string(where) +
            (skipped.size() > 1 ? " (" + Points(kv.second) + ")" : "");
  }
  return text;
}

// The plan, and every case's scenario read before any work, as the case runner reads it:
// a value its option does not allow stops the sweep here with the option's own message
// (an impact point off the beam or held fixed does not: that case becomes a failed row).
// *base is the scenario of the first case that can run; *candidates the first few such
// cases (for the probe).
PetscErrorCode SweepReadOptions(MPI_Comm comm, Scenario *base, SweepPlan *plan, std::vector<PetscInt> *candidates)
{
  PetscBool help = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(SweepPlanFromOptions(comm, plan));
  if (!plan->sampled.empty() && !plan->exceedance.empty()) { // its columns: the numeric results and the sampled axes
    std::vector<std::string> numeric;
    std::vector<UqCondition> conds;
    std::string              why;
    for (const SweepColumn &c : SweepColumns(*plan))
      if (c.labels.empty() && !c.timing && c.name != "case_index" && c.name != "status" &&
          std::none_of(plan->axes.begin(), plan->axes.end(),
                       [&](const SweepAxis &a) { return a.name == c.name && !a.sampled; }))
        numeric.push_back(c.name);
    PetscCheck(UqConditionsParse(plan->exceedance, numeric, &conds, &why), comm, PETSC_ERR_ARG_WRONG,
               "-sweep_exceedance \"%s\" is not allowed: %s", plan->exceedance.c_str(), why.c_str());
  }
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  const PetscInt n = help ? 1 : plan->cases(); // -help: print the options once
  candidates->clear();
  SweepScenarioCache      cache; // the structure's scenario: a point reads only its own parts again
  const double            t0 = MPI_Wtime();
  std::map<int, PetscInt> skipped;   // the points that cannot run, by status (off the beam, held, off the face)
  std::string             first_why; // the first one's reason
  for (PetscInt i = 0; i < n; ++i) {
    if (i == 1000 && n > 1000000) { // a huge plan: its set-up (every point's options read and checked) is announced
      const double per = (MPI_Wtime() - t0) / i;
      PetscCall(PetscPrintf(comm,
                            "sweep: %" PetscInt_FMT
                            " points planned: checking every point's options takes about %.3g s (%.2g ms a point) "
                            "before the first run; fewer points (a coarser -sweep_x or -sweep) shorten it\n",
                            n, per * (double)n, per * 1e3));
    }
    Scenario       c;
    int            status;
    std::string    reason;
    PetscErrorCode ierr = SweepCaseScenario(comm, *plan, i, true, &c, &status, &reason, &cache);
    PetscCall(SweepCaseOptionsClear(*plan));
    if (ierr) {
      const std::string msg = LastErrorMessage(ierr);
      SETERRQ(comm, ierr, "-task sweep point %" PetscInt_FMT " (%s): %s", i, SweepCaseText(*plan, i, false).c_str(),
              msg.c_str());
    }
    if (status != SweepOk) {
      if (skipped.empty()) first_why = reason;
      ++skipped[status];
      continue;
    }
    if (candidates->empty()) *base = c;
    if (candidates->size() < 8) candidates->push_back(i);
  }
  PetscCheck(!candidates->empty() || help, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-task sweep: no point of the sweep can run: every impact point is %s (point 0: %s: %s)",
             SkippedText(skipped).c_str(), SweepCaseText(*plan, 0, true).c_str(), first_why.c_str());
  const MonitorRequest &m = base->monitor;
  PetscCheck(!(m.ball || m.energy || !m.velocity_at.empty() || !m.snapshot_times.empty()), comm, PETSC_ERR_ARG_INCOMP,
             "-task sweep records no time series or snapshots (-monitor_ball, -monitor_energy, -monitor_velocity_at, "
             "-snapshot_times): run -task impact at the points of interest; only -monitor_segment (its peak is a "
             "column) works in a sweep");
  PetscFunctionReturn(0);
}

// An axis the probe's impact did not read: refused, saying why. An option of the program that
// an impact does not read with these options (an option of -task flight or -task modes, a
// PETSc option of another -ts_type) is named with its module's title; any other name is not an
// option of this program at all.
static PetscErrorCode SweepAxisReadCheck(MPI_Comm comm, const SweepPlan &plan, const SweepAxis &a)
{
  PetscBool used = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsUsed(NULL, a.name.c_str(), &used)); // the database keeps names without the dash
  if (used) PetscFunctionReturn(0);
  const char         *which  = a.name == "impact_x" && !plan.sweep_x.empty() ? "-sweep_x:" : "-sweep";
  const OptionModule *module = OptionModuleOf(a.name);
  PetscCheck(!module, comm, PETSC_ERR_ARG_WRONG,
             "%s %s=%s is not allowed: -%s is an option of this program, but the impact a sweep runs at each point "
             "(-task sweep farms -task impact) does not read it with these "
             "options; it belongs to: %s",
             which, a.name.c_str(), a.spec.c_str(), a.name.c_str(), module->title.c_str());
  SETERRQ(comm, PETSC_ERR_ARG_WRONG,
          "%s %s=%s is not allowed: -%s is not an option of this program (nothing read it with these options); an axis "
          "is an option without its dash, e.g. impact_x, ball_speed, beam_thickness, beam_nodes, ts_dt, ts_type, "
          "beam_theory",
          which, a.name.c_str(), a.spec.c_str(), a.name.c_str());
}

// A probe on rank 0's group before any work: sets up the integrator for the first case that
// can run and steps 1 ns, so that bad or unused options stop the sweep here with one
// message, an axis that no part of the program reads is refused, and the file can record
// the integrator. A case whose set-up fails (e.g. an explicit step above its stability
// limit at that point) hands the probe to the next of the candidates.
PetscErrorCode SweepProbe(const TaskFarm &farm, const SweepPlan &plan, const std::vector<PetscInt> &candidates,
                          ImpactResult *probe)
{
  PetscErrorCode first_ierr = 0;
  std::string    first_msg;
  PetscInt       first_case = -1;

  PetscFunctionBeginUser;
  if (farm.group == MPI_COMM_NULL || farm.world_rank >= plan.ranks_per_case) PetscFunctionReturn(0);
  for (size_t k = 0; k < candidates.size(); ++k) {
    Scenario    c;
    int         status;
    std::string reason;
    PetscCall(SweepCaseScenario(farm.group, plan, candidates[k], true, &c, &status, &reason));
    c.impact.full_max_time = c.impact.max_time > 0 ? c.impact.max_time : -1; // the cost estimates: a whole point's
    c.impact.max_time      = 1e-9;
    c.impact.check_unused_options = PETSC_FALSE;                                    // below, once the axes are checked
    c.impact.report_setup         = plan.quiet || k > 0 ? PETSC_FALSE : PETSC_TRUE; // integrator, step, warnings: once
    c.monitor                     = MonitorRequest();
    PetscErrorCode ierr           = ImpactRun(farm.group, c, probe);
    if (ierr) {
      if (!first_ierr) {
        first_ierr = ierr;
        first_msg  = LastErrorMessage(ierr);
        first_case = candidates[k];
      }
      PetscCall(SweepCaseOptionsClear(plan));
      continue;
    }
    for (const SweepAxis &a : plan.axes) PetscCall(SweepAxisReadCheck(farm.group, plan, a));
    // An axis that changes nothing: every point the same (unless another axis varies what it needs).
    for (const OptionWithoutEffect &o : OptionsWithoutEffect()) {
      bool varied = false;
      for (const SweepAxis &a : plan.axes)
        varied = varied || std::find(o.needs.begin(), o.needs.end(), "-" + a.name) != o.needs.end();
      for (const SweepAxis &a : plan.axes)
        PetscCheck(varied || o.name != "-" + a.name, farm.group, PETSC_ERR_ARG_WRONG,
                   "-sweep %s=%s is not allowed: %s has no effect in this sweep (%s), so every point would be the same",
                   a.name.c_str(), a.spec.c_str(), o.name.c_str(), o.why.c_str());
    }
    std::vector<std::string> axes; // an option that acts at other points is no note
    for (const SweepAxis &a : plan.axes) axes.push_back("-" + a.name);
    PetscCall(OptionsCheckUnused(farm.group, {}, false, axes));
    PetscCall(SweepCaseOptionsClear(plan));
    PetscFunctionReturn(0);
  }
  SETERRQ(farm.group, first_ierr,
          "-task sweep: the first %zu points that can run all failed to start; point %" PetscInt_FMT " (%s): %s",
          candidates.size(), first_case, SweepCaseText(plan, first_case, true).c_str(), first_msg.c_str());
}

// The options set that the probe's impact did not read ("-ts_theta_theta -modes_count"): the
// options this run calls unused, which change no number. Every point reads what the probe read
// unless an axis is text (a -ts_type, -beam_theory or -strings_frame axis changes what is read):
// then none is listed.
static PetscErrorCode SweepUnusedOptions(const SweepPlan &plan, std::string *unused)
{
  PetscInt n;
  char   **names, **values;

  PetscFunctionBeginUser;
  unused->clear();
  for (const SweepAxis &a : plan.axes)
    if (a.Text()) PetscFunctionReturn(0);
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) *unused += (unused->empty() ? "-" : " -") + std::string(names[i]);
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscFunctionReturn(0);
}

// The file's root attributes: the scenario, the probe's integrator and the plan.
PetscErrorCode SweepRecordBuild(const Scenario &base, const SweepPlan &plan, const ImpactResult &probe, RunRecord *rec)
{
  std::string options, columns, axes, units, kinds;

  PetscFunctionBeginUser;
  PetscCall(OptionsAsString(&options));
  for (auto &c : SweepColumns(plan)) columns += (columns.empty() ? "" : ",") + c.name;
  for (auto &a : plan.axes) {
    axes += (axes.empty() ? "" : ",") + a.name;
    units += (units.empty() ? "" : ",") + a.unit;
    kinds += (kinds.empty() ? "" : ",") + std::string(a.Text() ? "text" : "number");
  }
  PetscCall(RunRecordBuild(base, &probe, rec));
  rec->add("task", "sweep");
  if (!plan.sweep.empty()) rec->add("sweep", plan.sweep);
  if (!plan.sweep_x.empty()) rec->add("sweep_x", plan.sweep_x);
  rec->add("sweep_axes", axes);
  rec->add("sweep_axis_units", units);
  rec->add("sweep_axis_kinds", kinds);
  for (auto &a : plan.axes) rec->add("sweep_count_" + a.name, a.values.size());
  rec->add("sweep_ranks_per_case", plan.ranks_per_case);
  rec->add("rigid_loss_fraction", plan.rigid_loss_fraction);
  rec->add("sweep_cases_total", plan.cases());
  if (!plan.sampled
         .empty()) { // the sample: its options, and a digest of its values (a CSV's contents, the generator's)
    rec->add("sweep_samples", plan.samples);
    rec->add("sweep_sampling", SampleDesignName(plan.design));
    rec->add("sweep_seed", plan.seed);
    rec->add("sweep_sobol", plan.sobol ? 1 : 0);
    Sha256 h;
    h.Update(plan.sample_rows.data(), plan.sample_rows.size() * sizeof(double));
    rec->add("sweep_sample_sha256", h.HexDigest());
  }
  rec->add("sweep_columns", columns);
  rec->add("sweep_checked_options", SweepCheckedOptions(options));
  std::string unused; // what the probe's impact did not read: a resume may add or drop them (sweep_store.hpp)
  PetscCall(SweepUnusedOptions(plan, &unused));
  if (!unused.empty()) rec->add("sweep_unused_options", unused);
  PetscFunctionReturn(0);
}

// Rank 0's part of SweepStart: the store opened (resuming what is done), this run's journals
// followed, the cases still to compute.
static PetscErrorCode SweepStartStore(const TaskFarm &farm, const std::string &output, const Scenario &base,
                                      const SweepPlan &plan, const ImpactResult &probe, SweepStore *S,
                                      std::vector<PetscInt> *todo, int *run)
{
  RunRecord                record;
  std::vector<PetscMPIInt> leaders;

  PetscFunctionBeginUser;
  PetscCall(SweepRecordBuild(base, plan, probe, &record));
  SweepStoreInit(output, plan, SweepColumns(plan), record, S);
  PetscCall(SweepStoreOpen(*S, run));
  for (PetscInt i = 0; i < S->ncases; ++i)
    if (!S->rows.count(i)) todo->push_back(i);
  for (PetscMPIInt r = 0; r < farm.groups * plan.ranks_per_case; r += (PetscMPIInt)plan.ranks_per_case)
    leaders.push_back(r);
  SweepStoreFollow(*S, *run, leaders);
  PetscFunctionReturn(0);
}

// Rank 0 opens the store and every rank learns the cases still to compute and this run's
// number. A store refused or failed on rank 0 (other parameters, a full disk at the first
// write) fails every rank here, together: rank 0's message is the run's (app/main.cpp), no
// rank is left waiting for the others (which would end in MPI_Abort and the launcher's noise).
PetscErrorCode SweepStart(const TaskFarm &farm, const std::string &output, const Scenario &base, const SweepPlan &plan,
                          const ImpactResult &probe, SweepStore *S, std::vector<PetscInt> *todo, int *run)
{
  PetscErrorCode ierr = 0;

  PetscFunctionBeginUser;
  *run = 0;
  todo->clear();
  if (farm.world_rank == 0) ierr = SweepStartStore(farm, output, base, plan, probe, S, todo, run);
  PetscInt failed = ierr ? 1 : 0;
  PetscCallMPI(MPI_Bcast(&failed, 1, MPIU_INT, 0, farm.world));
  PetscCall(ierr);
  PetscCheck(!failed, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
             "-output %s: rank 0 could not open the sweep's file (its message is the run's)", output.c_str());
  PetscInt ntodo = (PetscInt)todo->size();
  PetscCallMPI(MPI_Bcast(&ntodo, 1, MPIU_INT, 0, farm.world));
  PetscCallMPI(MPI_Bcast(run, 1, MPI_INT, 0, farm.world));
  todo->resize(ntodo);
  if (ntodo) PetscCallMPI(MPI_Bcast(todo->data(), ntodo, MPIU_INT, 0, farm.world));
  PetscFunctionReturn(0);
}

// Rank 0: what is about to run.
PetscErrorCode SweepAnnounce(const TaskFarm &farm, const SweepPlan &plan, const ImpactResult &probe,
                             const SweepProgress &P, const std::string &output)
{
  std::string range;
  bool        ts_axis = false; // an axis changes the integrator: the one named is the first point's

  PetscFunctionBeginUser;
  if (farm.world_rank != 0 || plan.quiet) PetscFunctionReturn(0);
  for (auto &a : plan.axes) {
    char              text[256]; // PetscPrintf would write 0 as "0."
    const std::string unit = a.unit.empty() || a.unit == "1" ? "" : " " + a.unit;
    std::snprintf(text, sizeof(text), "%s from %g to %g%s (%zu)", a.name.c_str(),
                  (double)*std::min_element(a.values.begin(), a.values.end()),
                  (double)*std::max_element(a.values.begin(), a.values.end()), unit.c_str(), a.values.size());
    std::string labels;
    for (const std::string &l : a.labels) labels += (labels.empty() ? "" : ", ") + l;
    range += (range.empty() ? "" : " x ") +
             (a.Text() ? a.name + " " + labels + " (" + std::to_string(a.labels.size()) + ")" : std::string(text));
    if (a.name.compare(0, 3, "ts_") == 0) ts_axis = true;
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF,
                        "sweep: %s, %s, on %d rank(s): %" PetscInt_FMT " group(s) of %" PetscInt_FMT
                        "%s; ts %s (%s)%s\n",
                        Points(P.ncases).c_str(), range.c_str(), farm.world_size, farm.groups, plan.ranks_per_case,
                        farm.world_size % plan.ranks_per_case ? " (the ranks left over stay idle)" : "",
                        probe.ts_type.c_str(), probe.formulation.c_str(), ts_axis ? " at the first point" : ""));
  for (auto &a : plan.axes)
    if (a.overrides)
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: the axis %s overrides -%s %s given in the options\n",
                            a.name.c_str(), a.name.c_str(), a.given.c_str()));
  if (P.already && P.todo)
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "sweep: resuming %s: %" PetscInt_FMT " of %" PetscInt_FMT
                          " points already done, %" PetscInt_FMT " to compute\n",
                          output.c_str(), P.already, P.ncases, P.todo));
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
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT,
                           "sweep: %" PetscInt_FMT "/%" PetscInt_FMT " points (%.0f%%)  %.3g points/s  ETA %s\n",
                           P.already + done, P.ncases, 100.0 * (P.already + done) / P.ncases, rate,
                           rate > 0 ? FormatDuration((P.todo - done) / rate).c_str() : "?"));
    if (!P.cost_said && rate > 0 && (P.todo - done) / rate > plan.cost_warn)
      PetscCall(
        PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT,
                     "cost: %" PetscInt_FMT
                     " points to compute at %.3g s a point (measured over the first %" PetscInt_FMT
                     "): expected %s more; to shorten it: fewer points (a coarser -sweep_x or -sweep), more "
                     "MPI ranks, or a cheaper -ts_type/-ts_dt/-beam_nodes; a killed sweep resumes where it stopped\n",
                     P.todo, 1 / rate, done, FormatDuration((P.todo - done) / rate).c_str()));
    P.cost_said = true;
    std::fflush(PETSC_STDOUT);
    P.last = now;
  }
  PetscCall(SweepStoreRefresh(S));
  PetscFunctionReturn(0);
}

// The farm: each group takes the next pending case; its leader journals the row (a failed
// case too) and keeps it for the gather at the end.
PetscErrorCode SweepRunCases(TaskFarm &farm, const SweepPlan &plan, const std::vector<PetscInt> &todo, int run,
                             const std::string &output, SweepStore &S, SweepProgress &P, SweepShare *mine)
{
  SweepJournalWriter journal;
  const PetscMPIInt  rank = farm.world_rank;
  const int          show = 20; // failure lines per rank

  PetscFunctionBeginUser;
  journal.path      = SweepJournalName(output, run, rank);
  journal.signature = S.signature_hash;
  PetscCallMPI(MPI_Bcast(&journal.signature, 1, MPI_UINT64_T, 0, farm.world));
  journal.ncols = (uint32_t)SweepColumns(plan).size();
  SweepReuse reuse; // the structure's scenario and system, kept across this rank's points
  auto       run_case = [&](MPI_Comm group, PetscInt t) -> PetscErrorCode {
    const PetscInt      index = todo[t];
    std::vector<double> row;
    std::string         reason;
    ImpactResult        result;
    PetscFunctionBeginUser;
    const double tc = MPI_Wtime();
    PetscCall(SweepCaseRun(group, plan, index, &row, &reason, &result, &reuse));
    SweepNotesPointDone(farm.group_rank == 0); // its notes, counted once for the sweep
    const double tj = MPI_Wtime();
    mine->busy += tj - tc;
    if (farm.group_rank == 0) {
      const int status = (int)row[1 + plan.axes.size()];
      if (SweepFailed(status)) {
        ++mine->failed;
        mine->reasons[index] = reason;
        if (mine->shown < show) {
          const std::string point = SweepCaseText(plan, index, false);
          std::fprintf(stderr, "sweep: point %" PetscInt_FMT " (%s) failed, status %d (%s): %s\n", index, point.c_str(),
                             status, SweepStatusName(status), reason.c_str());
          if (++mine->shown == show)
            std::fprintf(stderr,
                               "sweep: further failed points of rank %d are not shown (see /results/status and "
                                     "/results/reason)\n",
                               rank);
          std::fflush(stderr);
        }
      }
      PetscCall(journal.Append(row, reason));
      mine->rows.insert(mine->rows.end(), row.begin(), row.end());
      ++mine->computed;
    }
    mine->journal += MPI_Wtime() - tj;
    PetscFunctionReturn(0);
  };
  auto between = [&](PetscInt done) -> PetscErrorCode { return SweepPoll(S, P, plan, done); };
  SweepNotesCollect();
  if (!todo.empty()) PetscCall(TaskFarmRun(farm, (PetscInt)todo.size(), run_case, between));
  journal.Close();
  mine->reuse[0] = reuse.scenario.full;
  mine->reuse[1] = reuse.scenario.partial;
  mine->reuse[2] = reuse.systems;
  PetscFunctionReturn(0);
}

// Rank 0 gathers this run's rows and reasons over MPI (the journals need not be visible
// there) and writes the complete file; its failure is every rank's.
PetscErrorCode SweepGather(MPI_Comm comm, const SweepShare &mine, SweepStore &S)
{
  PetscMPIInt              rank, size;
  std::vector<double>      all;
  std::vector<char>        text, all_text;
  std::vector<PetscMPIInt> counts, displs, tcounts, tdispls;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  // Reasons as "index\treason\n" lines (a reason is one line).
  for (auto &kv : mine.reasons) {
    const std::string line = std::to_string((long long)kv.first) + "\t" + kv.second + "\n";
    text.insert(text.end(), line.begin(), line.end());
  }
  PetscMPIInt n = (PetscMPIInt)mine.rows.size(), nt = (PetscMPIInt)text.size();
  counts.resize(size);
  displs.resize(size);
  tcounts.resize(size);
  tdispls.resize(size);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Gather(&nt, 1, MPI_INT, tcounts.data(), 1, MPI_INT, 0, comm));
  if (rank == 0) {
    size_t total = 0, ttotal = 0;
    for (PetscMPIInt r = 0; r < size; ++r) {
      displs[r]  = (PetscMPIInt)total;
      tdispls[r] = (PetscMPIInt)ttotal;
      total += counts[r];
      ttotal += tcounts[r];
    }
    all.resize(total);
    all_text.resize(ttotal);
  }
  PetscCallMPI(
    MPI_Gatherv(mine.rows.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm));
  PetscCallMPI(
    MPI_Gatherv(text.data(), nt, MPI_CHAR, all_text.data(), tcounts.data(), tdispls.data(), MPI_CHAR, 0, comm));
  if (rank == 0) {
    for (size_t p = 0; p + S.ncols <= all.size(); p += S.ncols)
      S.rows[(PetscInt)all[p]] = std::vector<double>(all.begin() + p, all.begin() + p + S.ncols);
    size_t p = 0;
    while (p < all_text.size()) {
      size_t tab = p, end = p;
      while (tab < all_text.size() && all_text[tab] != '\t') ++tab;
      end = tab;
      while (end < all_text.size() && all_text[end] != '\n') ++end;
      if (tab < end)
        S.reasons[(PetscInt)std::strtoll(std::string(all_text.begin() + p, all_text.begin() + tab).c_str(), nullptr,
                                         10)] = std::string(all_text.begin() + tab + 1, all_text.begin() + end);
      p = end + 1;
    }
    if ((PetscInt)S.rows.size() == S.ncases)
      PetscCall(SweepUqCompute(S, &S.uq)); // a sampled sweep's statistics, written with the file
  }
  // The complete file: a failed write (a full disk) fails every rank together (rank 0's message)
  PetscErrorCode ierr   = rank == 0 ? SweepStoreClose(S) : 0;
  PetscInt       failed = ierr ? 1 : 0;
  PetscCallMPI(MPI_Bcast(&failed, 1, MPIU_INT, 0, comm));
  PetscCall(ierr);
  PetscCheck(!failed, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "rank 0 could not write the sweep's file (its message is the run's)");
  PetscFunctionReturn(0);
}

// What the ranks did, gathered on rank 0 (the failed count on every rank).
struct SweepTally {
  PetscInt    computed = 0, failed = 0, off_face = 0; // points
  PetscInt    absurd = 0, absurd_wall = 0;            // points: compression beyond the radius, a wall pushed too far
  double      busy_sum = 0, busy_min = 0, journal_sum = 0, handout_sum = 0; // s (the ranks' sums, the least busy)
  PetscInt    contexts[2] = {0, 0};    // the integrator's per-structure contexts built, and the runs that reused one
  PetscInt    reuse[3]    = {0, 0, 0}; // the points' readings and systems (all ranks)
  std::string by_status;               // "2 with status 3 (diverged), ..."
};

// Rank 0's count of the file's rows by status: failed (by status), off the face, absurd.
void SweepTallyRows(const SweepStore &S, SweepTally *T)
{
  std::map<int, PetscInt> count;
  int                     beyond = -1, wall = -1; // the columns compression_beyond_radius and wall_deflection_large
  for (size_t c = 0; c < S.columns.size(); ++c) {
    if (S.columns[c].name == "compression_beyond_radius") beyond = (int)c;
    if (S.columns[c].name == "wall_deflection_large") wall = (int)c;
  }
  for (auto &kv : S.rows) {
    const double st = kv.second[S.status_column];
    if (SweepFailed(st)) {
      ++T->failed;
      ++count[(int)st];
    } else if (st == SweepOffFace) ++T->off_face;
    else {
      if (beyond >= 0 && kv.second[beyond] == 1) ++T->absurd;
      if (wall >= 0 && kv.second[wall] == 1) ++T->absurd_wall;
    }
  }
  for (auto &kv : count)
    T->by_status += (T->by_status.empty() ? "" : ", ") + std::to_string((long long)kv.second) + " with status " +
                    std::to_string(kv.first) + " (" + SweepStatusName(kv.first) + ")";
}

// The ranks' counts and times reduced to rank 0; the failed count broadcast to every rank.
PetscErrorCode SweepTallyGather(MPI_Comm comm, const SweepShare &mine, const SweepStore &S, SweepTally *T)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  T->computed = mine.computed;
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : &T->computed, &T->computed, 1, MPIU_INT, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(&mine.busy, &T->busy_sum, 1, MPI_DOUBLE, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(&mine.busy, &T->busy_min, 1, MPI_DOUBLE, MPI_MIN, 0, comm));
  PetscCallMPI(MPI_Reduce(&mine.journal, &T->journal_sum, 1, MPI_DOUBLE, MPI_SUM, 0, comm));
  PetscCallMPI(MPI_Reduce(&mine.handout, &T->handout_sum, 1, MPI_DOUBLE, MPI_SUM, 0, comm));
  TSStepperContextCounts(&T->contexts[0], &T->contexts[1]);
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : T->contexts, T->contexts, 2, MPIU_INT, MPI_SUM, 0, comm));
  for (int k = 0; k < 3; ++k) T->reuse[k] = mine.reuse[k];
  PetscCallMPI(MPI_Reduce(rank == 0 ? MPI_IN_PLACE : T->reuse, T->reuse, 3, MPIU_INT, MPI_SUM, 0, comm));
  if (rank == 0 && S.status_column >= 0) SweepTallyRows(S, T);
  PetscCallMPI(MPI_Bcast(&T->failed, 1, MPIU_INT, 0, comm));
  PetscFunctionReturn(0);
}

// Rank 0, unless quiet: what was computed, how fast, how evenly the ranks were loaded and what
// the farm cost (journal appends on the leaders; rank 0's hand-outs, progress and rewrites).
PetscErrorCode SweepPrintCost(const SweepProgress &P, const SweepTally &T, const SweepStore &S, double setup,
                              double elapsed, double farm_time, PetscMPIInt size)
{
  const PetscInt  computed = T.computed;
  const double    busy_sum = T.busy_sum, busy_min = T.busy_min, journal_sum = T.journal_sum;
  const double    handout_sum = T.handout_sum;
  const PetscInt *contexts = T.contexts, *reuse = T.reuse;

  PetscFunctionBeginUser;
  if (P.todo == 0)
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "sweep: all %" PetscInt_FMT " points were already done; nothing to compute\n", P.ncases));
  else {
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "sweep: computed %s in %.3f s (%.4g points/s) on %d rank(s), %" PetscInt_FMT
                          " already done\n",
                          Points(computed).c_str(), elapsed, computed / elapsed, size, P.already));
    // Load balance: the share of the farm's time the ranks spent in cases
    // (below 100%: waiting for the last cases, journaling, live rewrites).
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "sweep: ranks busy %.1f%% of the time on average, %.1f%% the least busy\n",
                          100 * busy_sum / (size * farm_time), 100 * busy_min / farm_time));
    // The farm's own cost per point: the rest of the ranks' time (hand-out, waiting for
    // the counter, journal, rank 0's progress lines and rewrites, the last cases' tail).
    // (hand-out: the counter and the broadcast in a group; journal: the leaders' appends;
    // rewrites: rank 0's live rewrites of the file; the rest: waiting for the last cases).
    if (computed > 0)
      PetscCall(
        PetscPrintf(PETSC_COMM_SELF,
                    "sweep: per point: compute %.4g ms; farm overhead %.4g ms (%.2f%% of the ranks' time): hand-out "
                    "%.4g ms, journal %.4g ms, rewrites %.4g ms (%d), idle at the end %.4g ms; set-up %.3f s\n",
                    1e3 * busy_sum / computed, 1e3 * (size * farm_time - busy_sum) / computed,
                    100 * (size * farm_time - busy_sum) / (size * farm_time), 1e3 * handout_sum / computed,
                    1e3 * journal_sum / computed, 1e3 * S.write_total / computed, S.writes,
                    1e3 * (size * farm_time - busy_sum - handout_sum - journal_sum - S.write_total) / computed, setup));
    if (computed > 0) // solvers/ts_stepper.hpp: a point on a structure already run reuses its TS, layout and vectors
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "sweep: integrator contexts: %" PetscInt_FMT " built, %" PetscInt_FMT
                            " runs reused one (all ranks, the probe included)\n",
                            contexts[0], contexts[1]));
    if (computed > 0) // studies/sweep.hpp, SweepReuse: a point on the structure of the one before reads only its own
                      // options and reuses the system
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "sweep: per structure: %" PetscInt_FMT " points read every option, %" PetscInt_FMT
                            " only their own axes' (ball, bat, impact, ...); %" PetscInt_FMT
                            " beam system(s) built (all ranks)\n",
                            reuse[0], reuse[1], reuse[2]));
  }
  PetscFunctionReturn(0);
}

// Rank 0, also with -sweep_quiet: the points that failed, fell off the face or mean nothing physically.
PetscErrorCode SweepPrintWarnings(const SweepProgress &P, const SweepTally &T)
{
  const PetscInt failed = T.failed, off_face = T.off_face, absurd = T.absurd, absurd_wall = T.absurd_wall;

  PetscFunctionBeginUser;
  if (failed)
    PetscCall(
      PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT,
                   "sweep: %" PetscInt_FMT " of %" PetscInt_FMT
                   " points failed: %s; their rows have status != 0, the reason in /results/reason and NaN numbers\n",
                   failed, P.ncases, T.by_status.c_str()));
  if (off_face) // a map over a racket's face: the product of its axes reaches beyond the head's outline
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT,
                           "sweep: %" PetscInt_FMT " of %" PetscInt_FMT
                           " points are off the racket's face (outside the head's outline): no impact there, status %d "
                           "and NaN numbers; not failed\n",
                           off_face, P.ncases, (int)SweepOffFace));
  // Points whose numbers exist but mean nothing physically (-ball_radius given): counted like
  // the failed ones, also with -sweep_quiet.
  if (absurd)
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT,
                           "sweep: %" PetscInt_FMT " of %" PetscInt_FMT
                           " points compressed the ball beyond its radius (-ball_radius): physically absurd, the "
                           "contact law far outside its range; "
                           "their rows have status 0 but compression_beyond_radius = 1 in /results: leave them out of "
                           "plots and fits\n",
                           absurd, P.ncases));
  if (absurd_wall)
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDOUT,
                           "sweep: %" PetscInt_FMT " of %" PetscInt_FMT
                           " points pushed the barrel wall in by more than %g of its radius: physically absurd, the "
                           "wall's linear model far outside its range; "
                           "their rows have status 0 but wall_deflection_large = 1 in /results: leave them out of "
                           "plots and fits\n",
                           absurd_wall, P.ncases, (double)kWallDeflectionLimit));
  PetscFunctionReturn(0);
}

// Rank 0: the report of the sweep (cost unless quiet, the failed and absurd points always);
// every rank learns the number of failed points (the exit status).
PetscErrorCode SweepReport(MPI_Comm comm, const SweepPlan &plan, const SweepShare &mine, const SweepProgress &P,
                           double setup, double t0, double farm_time, const std::string &output, const SweepStore &S,
                           PetscInt *failed_total)
{
  PetscMPIInt rank, size;
  SweepTally  T;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(SweepTallyGather(comm, mine, S, &T));
  *failed_total        = T.failed;
  const double elapsed = MPI_Wtime() - t0;
  if (rank != 0) PetscFunctionReturn(0);
  if (!plan.quiet) PetscCall(SweepPrintCost(P, T, S, setup, elapsed, farm_time, size));
  PetscCall(SweepPrintWarnings(P, T));
  if (!plan.quiet) PetscCall(SweepUqPrint(S, S.uq));
  if (!plan.quiet) PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s (%s)\n", output.c_str(), Points(P.ncases).c_str()));
  PetscFunctionReturn(0);
}

} // namespace

// Releases the output's lock when the task returns early (an error anywhere after the store
// was opened); after SweepStoreClose there is nothing left to release.
struct SweepStoreGuard {
  SweepStore &store;
  explicit SweepStoreGuard(SweepStore &s) : store(s) { }
  ~SweepStoreGuard() { SweepStoreRelease(store); }
  SweepStoreGuard(const SweepStoreGuard &)            = delete;
  SweepStoreGuard &operator=(const SweepStoreGuard &) = delete;
};

int SweepExitStatus() { return g_exit_status; }

PetscErrorCode TaskSweep(MPI_Comm comm, const std::string &output)
{
  Scenario              base;
  SweepPlan             plan;
  TaskFarm              farm;
  SweepStore            store;
  SweepStoreGuard       release(store); // an error return releases the lock rank 0 took
  ImpactResult          probe;
  std::vector<PetscInt> todo, candidates;
  int                   run = 0;
  SweepProgress         progress;
  SweepShare            mine;
  PetscInt              failed = 0;

  PetscFunctionBeginUser;
  g_exit_status        = 0;
  const double t_setup = MPI_Wtime();
  struct NotesGuard {
    ~NotesGuard() { SweepNotesAbandon(); } // an error return: PETSc's printer back
  } notes_guard;
  PetscCall(SweepNotesBegin()); // each point's notes said once for the sweep (studies/sweep_notes.hpp)
  PetscCheck(!output.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task sweep writes its results to a file: give -output FILE.h5 (not 'none')");
  PetscCall(SweepReadOptions(comm, &base, &plan, &candidates));
  PetscCall(TaskFarmCreate(comm, plan.ranks_per_case, &farm));
  PetscCall(SweepProbe(farm, plan, candidates, &probe));
  PetscCall(SweepStart(farm, output, base, plan, probe, &store, &todo, &run));
  progress.ncases  = plan.cases();
  progress.todo    = (PetscInt)todo.size();
  progress.already = progress.ncases - progress.todo;
  PetscCall(SweepAnnounce(farm, plan, probe, progress, output));
  const double t0  = MPI_Wtime();
  progress.t_start = progress.last = t0;
  PetscCall(SweepRunCases(farm, plan, todo, run, output, store, progress, &mine));
  const double farm_time = MPI_Wtime() - t0;
  mine.handout           = farm.handout;
  PetscCall(TaskFarmDestroy(&farm));
  PetscCall(SweepGather(comm, mine, store));
  PetscCall(SweepNotesEnd(comm, progress.todo));
  PetscCall(SweepReport(comm, plan, mine, progress, t0 - t_setup, t0, farm_time, output, store, &failed));
  g_exit_status = failed ? 2 : 0;
  PetscFunctionReturn(0);
}

} // namespace beamimpact

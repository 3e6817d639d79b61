// Task drivers and the table -task chooses from. See tasks.hpp.
#include "app/tasks.hpp"

#include "app/docs_markdown.hpp"
#include "app/task_flight.hpp"
#include "app/task_strings.hpp"
#include "base/memory.hpp"
#include "base/option_table.hpp"
#include "base/options_util.hpp"
#include "io/bat_maker_options.hpp"
#include "io/racket_maker_options.hpp"
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "io/scenario_options.hpp"
#include "io/xdmf.hpp"
#include "run/impact_point.hpp"
#include "run/outcome.hpp"
#include "run/reference.hpp"
#include "run/stage.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/modes.hpp"
#include "solvers/petsc_options.hpp"
#include "studies/convergence.hpp"
#include "studies/design.hpp"
#include "studies/fit.hpp"
#include "studies/sweep.hpp"
#include "studies/sweep_plan.hpp"
#include "solvers/leapfrog.hpp"
#include "system/structure_part.hpp"

#include <petscts.h>
#include <slepceps.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace beamimpact {

namespace {

// The tasks, in the order -help lists them; the first is the default.
struct TaskEntry {
  const char *name;
  PetscErrorCode (*run)(MPI_Comm comm, const std::string &output);
};
const TaskEntry Tasks[] = {
  {"impact", TaskImpact}, {"modes", TaskModes}, {"sweep", TaskSweep},   {"convergence", TaskConvergence},
  {"flight", TaskFlight}, {"fit", TaskFit},     {"design", TaskDesign},
};

// The task's file, when -output names one (not 'none'): its run record, the file, and a line
// saying where it went.
template <class Record, class Write>
PetscErrorCode TaskWriteOutput(MPI_Comm comm, const std::string &output, Record record, Write write)
{
  RunRecord rec;

  PetscFunctionBeginUser;
  if (output.empty()) PetscFunctionReturn(0);
  ImpactStageScope stage(ImpactStage::Output);
  PetscCall(record(&rec));
  PetscCall(write(rec));
  PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  PetscFunctionReturn(0);
}

} // namespace

// The summary line: columns of the results table (their values and units), by the short labels
// the line has always used; "steps" counts the event re-steps too.
static std::string ImpactSummaryLine(const ImpactResult &r)
{
  struct Item {
    const char *label, *column, *format;
  };
  static const Item items[] = {{"x", "x", "%.4f"},
                               {"acor", "acor", "%.6f"},
                               {"acor_corrected", "acor_corrected", "%.6f"},
                               {"contact_time", "contact_time", "%.4e"},
                               {"peak_force", "peak_force", "%.4e"},
                               {"max_compression", "max_compression", "%.4e"},
                               {"contacts", "contacts", "%.0f"},
                               {"steps", "steps", "%.0f"},
                               {"rejected", "rejected_steps", "%.0f"},
                               {"failed", "failed_solves", "%.0f"},
                               {"fevals", "function_evals", "%.0f"},
                               {"wall", "wall_time", "%.3e"}};
  std::string       line;
  for (const Item &it : items) {
    const ResultColumn *c = ImpactResultColumn(it.column);
    char                value[64];
    std::snprintf(value, sizeof value, it.format,
                  c->Get(r) + (std::strcmp(it.column, "steps") == 0 ? (double)r.event_steps : 0.0));
    line += (line.empty() ? "" : "  ") + std::string(it.label) + " " + value +
            (std::strcmp(c->unit, "1") ? " " + std::string(c->unit) : "");
  }
  return line;
}

namespace {

// The lines of the stages after the contact that apply (run/stage.hpp: an oblique impact's, the
// flight's), from their columns.
PetscErrorCode StageSummary(MPI_Comm comm, const Scenario &sc, const ImpactResult &r)
{
  PetscFunctionBeginUser;
  for (const RunStage *stage : RunStages()) {
    if (!stage->Applies(sc)) continue;
    std::vector<double> values;
    for (const StageColumn &c : stage->Columns()) values.push_back(ImpactResultColumn(c.name)->Get(r));
    for (const char *name : stage->SummaryColumns()) values.push_back(ImpactResultColumn(name)->Get(r));
    PetscCall(PetscPrintf(comm, "%s", stage->Summary(sc, values).c_str()));
  }
  PetscFunctionReturn(0);
}

} // namespace

// A part's columns' values in r, in Columns()'s order, then SummaryColumns()'s.
static std::vector<double> PartSummaryValues(const StructurePart &part, const ImpactResult &r)
{
  std::vector<double> values;
  for (const PartColumn &c : part.Columns()) values.push_back(ImpactResultColumn(c.name)->Get(r));
  for (const char *name : part.SummaryColumns()) values.push_back(ImpactResultColumn(name)->Get(r));
  return values;
}

static PartPoint SummaryPoint(const Scenario &sc)
{
  PartPoint at;
  at.ball = &sc.ball, at.x = sc.impact.x, at.z = sc.impact.z;
  return at;
}

// Each registered part present: its summary line (first: those before the pivot rig's lines).
static PetscErrorCode PartSummaries(MPI_Comm comm, const Scenario &sc, const ImpactResult &r, bool first)
{
  PetscFunctionBeginUser;
  for (const StructurePart *part : StructureParts()) {
    const PartParams *q = sc.beam.parts.Find(part->Name());
    if (!q || part->SummaryFirst() != first) continue;
    const std::string line = part->SummaryAt(*q, PartSummaryValues(*part, r), SummaryPoint(sc));
    if (!line.empty()) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  }
  PetscFunctionReturn(0);
}

// Each registered part present: its warning on the outcome (StructurePart::Warning: the barrel
// wall's displacement beyond its linear range).
static PetscErrorCode PartWarnings(MPI_Comm comm, const Scenario &sc, const ImpactResult &r)
{
  PetscFunctionBeginUser;
  for (const StructurePart *part : StructureParts()) {
    const PartParams *q = sc.beam.parts.Find(part->Name());
    if (!q) continue;
    const std::string line = part->Warning(*q, sc.beam, PartSummaryValues(*part, r), SummaryPoint(sc));
    if (!line.empty()) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactPrintSummary(MPI_Comm comm, const Scenario &sc, const ImpactResult &r)
{
  PetscFunctionBeginUser;
  char modal[96] = ""; // the modal engine's modes kept and cut-off (docs/model.md §12)
  if (r.modal.kept > 0 && std::isfinite(r.modal.cutoff))
    std::snprintf(modal, sizeof modal, "  modes %d/%d cut-off %.4g Hz", (int)r.modal.kept, (int)r.modal.free_dofs,
                  (double)r.modal.cutoff);
  else if (r.modal.kept > 0)
    std::snprintf(modal, sizeof modal, "  modes %d/%d", (int)r.modal.kept,
                  (int)r.modal.free_dofs); // no cut-off chose them
  PetscCall(PetscPrintf(comm, "%s%s%s\n", ImpactSummaryLine(r).c_str(), modal,
                        r.ended_in_contact ? "  (ended in contact: raise -impact_max_time)" : ""));
  const size_t asked = sc.monitor.snapshot_times.size(), taken = r.series.snapshot_time.size();
  if (taken < asked) {
    std::string late;
    for (size_t q = taken; q < asked && q < taken + 8; ++q)
      late += (late.empty() ? "" : ", ") + std::to_string(sc.monitor.snapshot_times[q]).substr(0, 10);
    PetscCall(PetscPrintf(comm,
                          "note: %zu of the -snapshot_times (%s%s) are after the run's end at t = %.6g s and were not "
                          "recorded; a longer -impact_window or -impact_max_time reaches them\n",
                          asked - taken, late.c_str(), asked - taken > 8 ? ", ..." : "", (double)r.final_time));
  }
  const std::string absurd = CompressionBeyondRadiusText(sc, r);
  if (!absurd.empty()) PetscCall(PetscPrintf(comm, "%s\n", absurd.c_str()));
  PetscCall(PartWarnings(comm, sc, r));
  const std::string energy = ImpactEnergyShareText(sc, r); // where it went (docs/model.md section 4)
  if (!energy.empty()) PetscCall(PetscPrintf(comm, "%s\n", energy.c_str()));
  if (r.beam_dissipated_end > 0) // a damped beam
    PetscCall(PetscPrintf(comm, "beam damping dissipated %.4e J (%.4f of E_in); energy balance error %.1e\n",
                          (double)r.beam_dissipated_end, (double)r.damping_fraction, (double)r.energy_error));
  if (sc.swing.Swings())
    PetscCall(PetscPrintf(comm,
                          "swinging bat (V_cm %g m/s, Omega %g rad/s): batted-ball speed %.4f m/s, collision "
                          "efficiency q %.6f; bat after: V_cm %.4f m/s, Omega %.4f rad/s\n",
                          (double)sc.swing.bat_speed, (double)sc.swing.bat_angular_velocity, (double)r.bbs,
                          (double)r.collision_efficiency, (double)r.bat_speed_end, (double)r.bat_angular_velocity_end));
  PetscCall(StageSummary(comm, sc, r));
  PetscCall(PartSummaries(comm, sc, r, true)); // the bed's line keeps its place
  if (ResultFreePivot(sc)) {
    const PivotRig rig = PivotRigOf(BeamRigidBodyOf(sc.beam), sc.beam.pivot_x, sc.ball.mass, r.x);
    PetscCall(
      PetscPrintf(comm,
                  "pivot at %.4f m: I_p %.5f kg m^2, recoil factor r %.6f, e_A %.6f, BBCOR = e_A (1 + r) + r = %.6f\n",
                  (double)sc.beam.pivot_x, (double)rig.inertia_pivot, (double)r.recoil_factor,
                  (double)r.collision_efficiency, (double)r.bbcor));
  } else if (sc.beam.has_pivot)
    PetscCall(PetscPrintf(comm,
                          "pivot at %.4f m, but the beam is also held (%s): it cannot turn freely about the pivot, so "
                          "no recoil factor or BBCOR is reported (NaN in /results: they describe a "
                          "rig free to turn about its pivot); e_A %.6f\n",
                          (double)sc.beam.pivot_x, PivotHeldText(sc).c_str(), (double)r.collision_efficiency));
  PetscCall(PartSummaries(comm, sc, r, false));
  PetscFunctionReturn(0);
}

// One line on the beam as a rigid body: what a scale and a balance measure.
PetscErrorCode PrintBeamBody(MPI_Comm comm, const BeamParams &beam)
{
  const BeamRigidBody b = BeamRigidBodyOf(beam);
  PetscFunctionBeginUser;
  bool body = true; // a part's own line first (the bed's); a held frame is not a body
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = beam.parts.Find(part->Name())) {
      const std::string line = part->Heading(*q, &body);
      if (!line.empty()) PetscCall(PetscPrintf(comm, "%s\n", line.c_str()));
    }
  if (!body) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(comm,
                        "beam: %s section%s%s, mass %.4f kg, centre of mass %.4f m from x = 0, moment of inertia %.5f "
                        "kg m^2 about it, %.5f kg m^2 about x = 0",
                        SectionSourceName(beam.section.source), beam.section.file.empty() ? "" : " ",
                        beam.section.file.c_str(), (double)b.mass, (double)b.x_cm, (double)b.inertia_cm,
                        (double)b.inertia_end));
  for (const StructurePart *part : StructureParts()) // each registered part present: its words on the body
    if (const PartParams *q = beam.parts.Find(part->Name()))
      PetscCall(PetscPrintf(comm, "%s", part->Describe(*q, b).c_str()));
  PetscCall(PetscPrintf(comm, "\n"));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskImpact(MPI_Comm comm, const std::string &output)
{
  Scenario               sc;
  const ReferenceMethod *method;
  ReferenceSolution      sol;
  std::string            why;

  PetscFunctionBeginUser;
  PetscCall(ScenarioFromOptions(comm, &sc));
  PetscCall(PrintBeamBody(comm, sc.beam));
  PetscCall(ReferenceMethodFromOptions(comm, &method)); // -reference: ts (the default), modal, ...
  PetscCheck(method->applies(sc, &why), comm, PETSC_ERR_SUP, "-reference %s %s", method->name, why.c_str());
  sc.impact.check_unused_options = PETSC_TRUE;
  sc.impact.report_setup         = PETSC_TRUE; // integrator, step and stability limit before the run
  PetscCall(method->run(comm, sc, ReferenceSettings(), &sol));
  const ImpactResult &res = sol.result;
  const std::string   cut = ImpactCutOffReason(sc, res); // no number from a contact cut short
  PetscCheck(cut.empty(), comm, PETSC_ERR_ARG_INCOMP, "%s", cut.c_str());
  PetscCall(ImpactPrintSummary(comm, sc, res));
  PetscCall(TaskWriteOutput(
    comm, output, [&](RunRecord *rec) { return RunRecordBuild(sc, &res, rec); },
    [&](const RunRecord &rec) { return ResultsWriteImpactFile(comm, output, rec, {res}, sc); }));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskModes(MPI_Comm comm, const std::string &output)
{
  BeamParams                          beam;
  ModesParams                         mp;
  ModesResult                         modes;
  BeamSystem                          op;
  std::vector<std::vector<PetscReal>> shapes;
  std::string                         why;

  PetscFunctionBeginUser;
  PetscBool bed; // -strings_frame held: the string bed's modes (app/task_strings.hpp)
  PetscCall(TaskModesIsStringBed(comm, &bed));
  if (bed) {
    PetscCall(TaskStringBedModes(comm, output));
    PetscFunctionReturn(0);
  }
  PetscCall(BeamParamsFromOptions(comm, &beam));
  PetscCheck(BeamSystemBuild(beam, &op, &why), comm, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  PetscCall(ModesParamsFromOptions(comm, &mp, &op));
  PetscCall(BeamModesCompute(comm, op, mp.count, &modes, &shapes));
  PetscCall(OptionsCheckUnused(comm)); // after the solve: the eigensolver reads its -modes_eps_*, -modes_st_* options
  PetscCall(PrintBeamBody(comm, beam));
  const bool wall = !modes.shell_n.empty() ||
                    !modes.part.empty(); // a barrel wall, a roll or a string bed: each mode's family
  PetscCall(PetscPrintf(comm,
                        "modes of the %g m beam (%s, %s-%s, N = %" PetscInt_FMT
                        ", %s):\n  mode  frequency (Hz)  period (ms)  %snodes (m)\n",
                        (double)beam.length, beam.theory.c_str(), SupportName(beam.left), SupportName(beam.right),
                        beam.nodes, modes.method.c_str(), wall ? "family   " : ""));
  int rigid = 0, flexible = 0; // numbered apart: mode 1 is the fundamental, the rigid ones r1, r2
  for (size_t q = 0; q < modes.frequency.size(); ++q) {
    std::string nodes;
    if (modes.omega[q] != 0 && !(!modes.shell_n.empty() && modes.shell_n[q] != 0) &&
        !(!modes.part.empty() &&
          modes.part[q] != 0)) // a wall's, roll's or bed's mode (not the beam's account): no bending nodes
      for (PetscReal x : ModeNodes(shapes[q], beam.length / (beam.nodes - 1)))
        nodes += " " + std::to_string(x).substr(0, 6);
    const std::string number = modes.omega[q] == 0 ? "r" + std::to_string(++rigid) : std::to_string(++flexible);
    std::string       family = modes.shell_n.empty()
                               ? ""
                               : (modes.shell_n[q] == 0 ? " bending "
                                                        : " shell n=" + std::to_string((long long)modes.shell_n[q]));
    if (!modes.part
           .empty()) { // a roll field or a string bed: the part with most of the mode's kinetic energy, and its share
      char text[64];
      std::snprintf(text, sizeof text, " %-8s %3.0f%% ", StructureAccountName(modes.part[q]),
                    (double)(100 * modes.part_share[q]));
      family = text;
    }
    PetscCall(PetscPrintf(comm, "  %4s  %14.4f  %11.4f %s%s\n", number.c_str(), (double)modes.frequency[q],
                          (double)modes.period[q] * 1e3, family.c_str(),
                          modes.omega[q] == 0 ? " (rigid)" : nodes.c_str()));
  }
  auto record = [&](RunRecord *rec) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(RunRecordBuild(beam, rec));
    rec->add("modes_count", mp.count); // -modes_count: the modes computed, rigid ones included
    rec->add("modes_rigid_count", (PetscInt)modes.rigid_count);
    PetscFunctionReturn(0);
  };
  PetscCall(TaskWriteOutput(comm, output, record, [&](const RunRecord &rec) {
    return ResultsWriteModesFile(comm, output, rec, modes, shapes, beam);
  }));
  PetscFunctionReturn(0);
}

namespace {
PetscErrorCode RunTaskOptions(MPI_Comm comm, PetscInt *task, std::string *out, std::string *markdown = nullptr);

// Every reader of every task, once, their own checks skipped (their errors ignored): under
// -help each prints its block; defaults may not make a runnable sweep, and that is not what
// -help is asked.
PetscErrorCode ReadEveryOption(MPI_Comm comm)
{
  Scenario               sc;
  const ReferenceMethod *method;
  ModesParams            mp;
  SweepPlan              plan;
  ConvergencePlan        cp;
  LeapfrogParams         lp;
  ModalTruncation        modal_modes;
  TS                     ts;

  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  (void)ScenarioFromOptions(comm, &sc);
  (void)ReferenceMethodFromOptions(comm, &method);
  (void)ModesParamsFromOptions(comm, &mp, nullptr);
  (void)SweepPlanFromOptions(comm, &plan);
  (void)ConvergencePlanFromOptions(comm, sc, &cp);
  (void)LeapfrogParamsFromOptions(comm, &lp);
  (void)ModalTruncationFromOptions(comm, &modal_modes);
  (void)FlightHelpOptions(comm);      // -flight_*, -air_*, the flight TS's -flight_ts_*
  (void)StringBedHelpOptions(comm);   // -strings_*, -head_*
  (void)BatMakerHelpOptions(comm);    // -bat_* of a bat by its maker's numbers
  (void)RacketMakerHelpOptions(comm); // -racket_* of a racket by its maker's numbers
  (void)FitHelpOptions(comm);         // -fit_*, TAO's -tao_*
  (void)DesignHelpOptions(comm);      // -design_*
  if (!TSCreate(comm, &ts)) { // PETSc's own integrator options (-ts_type, -ts_dt, ...), as for the program's default
                              // -ts_type rk
    (void)TSSetType(ts, TSRK);
    (void)TSSetFromOptions(ts);
    (void)TSDestroy(&ts);
  }
  EPS eps; // SLEPc's eigensolver options of -task modes (-modes_eps_*, -modes_st_*)
  if (!EPSCreate(comm, &eps)) {
    (void)EPSSetOptionsPrefix(eps, "modes_");
    (void)EPSSetFromOptions(eps);
    (void)EPSDestroy(&eps);
  }
  PetscCall(PetscPopErrorHandler());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode PrintAllOptions(MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCall(RunTaskOptions(comm, nullptr, nullptr));
  PetscCall(ReadEveryOption(comm));
  PetscCall(OptionModulePrintHelp(comm, PetscSolverOptionTable()));
  PetscCall(
    PetscPrintf(comm, "\n-help lists every option of every task above, with its default; nothing was run or written.\n"
                      "Not in the blocks above: -log_view (PETSc's profile, by the stages beamimpact: set-up, contact, "
                      "free flight, output (also a sweep's rewrites of its file)\n"
                      "and modal reference (-reference modal)).\n"));
  PetscFunctionReturn(0);
}

namespace {

// -output may name no input of the run (an options file, an include, a table an option names):
// the same file (inode) as any of them is refused.
PetscErrorCode OutputCheckNotAnInput(MPI_Comm comm, const std::string &out)
{
  std::vector<InputFile> inputs;
  struct stat            o, i;

  PetscFunctionBeginUser;
  if (stat(out.c_str(), &o) != 0) PetscFunctionReturn(0);
  PetscCall(RunInputFiles(&inputs));
  for (const InputFile &f : inputs)
    PetscCheck(stat(f.path.c_str(), &i) != 0 || i.st_dev != o.st_dev || i.st_ino != o.st_ino, comm, PETSC_ERR_FILE_OPEN,
               "-output %s is not allowed: it is an input of this run (%s %s); it would be replaced by the results. "
               "Give another -output",
               out.c_str(), f.option.c_str(), f.path.c_str());
  PetscFunctionReturn(0);
}

// A sweep running onto out holds out.parts/lock (studies/sweep_store.hpp): no task replaces
// its file meanwhile, -output_overwrite or not.
PetscErrorCode OutputCheckNotLocked(MPI_Comm comm, const std::string &out)
{
  const std::string lock = out + ".parts/lock";
  int               held = 0;
  PetscMPIInt       rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) { // one rank tries: two trying at once would each see the other's attempt as a holder
    const int fd = open(lock.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
      held = flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
      close(fd); // releases the lock if this took it
    }
  }
  PetscCallMPI(MPI_Bcast(&held, 1, MPI_INT, 0, comm)); // rank 0's try done before the sweep's own lock
  PetscCheck(!held, comm, PETSC_ERR_FILE_OPEN,
             "-output %s is being written by another sweep that is still running (%s is held); wait for it or choose "
             "another -output",
             out.c_str(), lock.c_str());
  PetscFunctionReturn(0);
}

// What -output names, by lstat (a link not followed). A new name or a regular file is written;
// a symbolic link to a regular file is followed (out becomes the file it names, which the
// results replace; the link stays); anything else is refused, naming what it is: a device (as
// root, /dev/null would have been replaced by the file), a FIFO or a socket (the file is written
// whole beside its place and renamed there, never streamed), a directory, a link to one of them
// or to nothing. OutputCheck notes a followed link once the file passed its checks.
PetscErrorCode OutputCheckKind(MPI_Comm comm, std::string *out, const char *task)
{
  struct stat st, target;

  PetscFunctionBeginUser;
  if (lstat(out->c_str(), &st) != 0) PetscFunctionReturn(0); // a new name
  if (S_ISLNK(st.st_mode)) {
    PetscCheck(stat(out->c_str(), &target) == 0, comm, PETSC_ERR_FILE_OPEN,
               "-output %s is not allowed: it is a symbolic link to nothing (a name that does not exist); give the "
               "file's own name",
               out->c_str());
    char             *real     = realpath(out->c_str(), NULL); // NULL for a link into /proc (/dev/stdout: a pipe)
    const std::string resolved = real ? real : "";
    free(real);
    PetscCheck(S_ISREG(target.st_mode), comm, PETSC_ERR_FILE_OPEN,
               "-output %s is not allowed: it is a symbolic link to %s%s, not a file; beamimpact writes only to a "
               "regular file or a new name%s",
               out->c_str(), resolved.empty() ? "" : (resolved + ", ").c_str(), FileKind(target.st_mode),
               S_ISDIR(target.st_mode) ? "" : " (-output none writes nothing)");
    PetscCheck(!resolved.empty(), comm, PETSC_ERR_FILE_OPEN,
               "-output %s is not allowed: the file its symbolic link names cannot be resolved; give the file's own "
               "name",
               out->c_str());
    *out = resolved;
    PetscFunctionReturn(0);
  }
  PetscCheck(!S_ISDIR(st.st_mode), comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: it is a directory; give a file name (e.g. %s%s%s.h5)", out->c_str(),
             out->c_str(), out->back() == '/' ? "" : "/", task);
  PetscCheck(S_ISREG(st.st_mode), comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: it is %s, not a file; beamimpact writes its results whole beside it and "
             "renames them into place, which would replace %s itself. Use -output none to write nothing",
             out->c_str(), FileKind(st.st_mode),
             S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode) ? "the FIFO or socket" : "the device");
  PetscFunctionReturn(0);
}

// No -output inside a sweep's journal directory F.parts (its lock and journals, studies/sweep_store.hpp):
// the directory it is in, links resolved, is refused when it is named F.parts and holds a lock
// or F exists beside it (a directory that merely ends in .parts is anyone's).
PetscErrorCode OutputCheckNotInParts(MPI_Comm comm, const std::string &out, const std::string &dir)
{
  char             *real      = realpath(dir.c_str(), NULL);
  const std::string canonical = real ? real : dir;
  const std::string ext       = ".parts";
  struct stat       st;

  PetscFunctionBeginUser;
  free(real);
  const size_t      slash = canonical.find_last_of('/');
  const std::string base  = slash == std::string::npos ? canonical : canonical.substr(slash + 1);
  if (base.size() <= ext.size() || base.compare(base.size() - ext.size(), ext.size(), ext) != 0) PetscFunctionReturn(0);
  const std::string file  = canonical.substr(0, canonical.size() - ext.size());
  const bool        sweep = lstat((canonical + "/lock").c_str(), &st) == 0 || lstat(file.c_str(), &st) == 0;
  PetscCheck(!sweep, comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: it is inside %s, the journal directory of a sweep writing %s (its lock and "
             "its journals live there); give a name outside it",
             out.c_str(), canonical.c_str(), file.c_str());
  PetscFunctionReturn(0);
}

// The snapshots' XDMF description beside -output (io/xdmf.hpp: out.xmf for out.h5), when the run
// may write one (-task impact with -snapshot_times): refused before any work if that path is
// not a regular file (a directory, a device, a FIFO, a link: FileKind) or a file this program did
// not write (an empty one may be replaced).
PetscErrorCode OutputCheckDescription(MPI_Comm comm, const std::string &out, const char *task)
{
  PetscBool   snapshots = PETSC_FALSE;
  struct stat st;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-snapshot_times", &snapshots));
  const std::string x = XdmfPathFor(out);
  if (std::strcmp(task, "impact") != 0 || !snapshots || lstat(x.c_str(), &st) != 0) PetscFunctionReturn(0);
  PetscCheck(S_ISREG(st.st_mode), comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: the description of its snapshots goes to %s, which is %s, not a file; "
             "give another -output",
             out.c_str(), x.c_str(), FileKind(st.st_mode));
  PetscCheck(st.st_size == 0 || XdmfFileOurs(x), comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: the description of its snapshots would replace %s, which exists and is not "
             "an XDMF file of beamimpact; give another -output, or remove the file first",
             out.c_str(), x.c_str());
  PetscFunctionReturn(0);
}

// -output: refused before any work if it cannot be written (empty name, missing or read-only
// directory), if it is not a regular file or a new name (OutputCheckKind: a link to a regular file
// is followed, out then names that file), if it is inside a sweep's F.parts, an input of the run
// or a file a running sweep holds, if it is a file of another program (not an HDF5 results file
// of beamimpact: a text file, another program's HDF5), or if it would replace a file another task
// wrote (without -output_overwrite); and if the snapshots' description beside it would replace
// something else than a file of ours (OutputCheckDescription). An empty file is refused too (it may
// be another program's lock or marker); -output none is the way to write nothing.
PetscErrorCode OutputCheck(MPI_Comm comm, std::string *out, const char *task)
{
  PetscBool       overwrite = PETSC_FALSE;
  ResultsFileInfo info;
  PetscFunctionBeginUser;
  if (out->empty()) PetscFunctionReturn(0);
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-output_overwrite", &overwrite, NULL));
  const std::string given = *out;
  PetscCall(OutputCheckKind(comm, out, task));
  const size_t      slash = out->find_last_of('/');
  const std::string dir   = slash == std::string::npos ? "." : (slash == 0 ? "/" : out->substr(0, slash));
  PetscCheck(access(dir.c_str(), W_OK) == 0, comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: the directory %s does not exist or is not writable", given.c_str(),
             dir.c_str());
  PetscCall(OutputCheckNotInParts(comm, given, dir));
  PetscCall(OutputCheckNotAnInput(comm, *out));
  PetscCall(OutputCheckNotLocked(comm, *out));
  PetscCall(ResultsFileInspect(*out, &info));
  PetscCheck(!info.exists || info.size != 0, comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: it exists and is empty, not a results file of beamimpact (an empty file may "
             "be another program's lock or marker); -task %s will not replace it "
             "(-output_overwrite neither): give another -output, remove the file first, or -output none to write "
             "nothing",
             given.c_str(), task);
  PetscCheck(!info.exists || info.Ours(), comm, PETSC_ERR_FILE_OPEN,
             "-output %s is not allowed: it exists and is %s, not a results file of beamimpact; -task %s will not "
             "replace it (-output_overwrite neither): give another -output, or remove the file first",
             given.c_str(), info.hdf5 ? "an HDF5 file of another program" : "not an HDF5 file", task);
  PetscCheck(info.task.empty() || info.task == task || overwrite, comm, PETSC_ERR_FILE_OPEN,
             "-output %s holds the results of -task %s: -task %s will not replace them (give another -output, or "
             "-output_overwrite)",
             given.c_str(), info.task.c_str(), task);
  PetscCall(OutputCheckDescription(comm, *out, task));
  if (given != *out)
    PetscCall(
      PetscPrintf(comm,
                  "note: -output %s is a symbolic link: the results go to the file it names, %s (the link stays)\n",
                  given.c_str(), out->c_str()));
  PetscFunctionReturn(0);
}

} // namespace

const OptionModule &TaskOptionTable()
{
  static const OptionModule m = [] {
    std::vector<std::string> names;
    for (const TaskEntry &e : Tasks) names.push_back(e.name);
    return OptionModule{
      "task",
      "beamimpact: task and output",
      {
        OptionChoice("-task", "What to compute", names, Tasks[0].name),
        OptionText("-output", "HDF5 file to write (default: <task>.h5; 'none' writes nothing): a regular file or a new "
                              "name, never a device, FIFO, socket, "
                              "directory, empty file or a file inside a sweep's FILE.h5.parts; a link to a results "
                              "file is followed"),
        OptionFlag("-output_overwrite", "Let -output replace a file another task wrote"),
        OptionFlag("-allow_unused_options",
                   "An unknown option (read by no task: a typo) becomes a warning instead of an error"),
        OptionFlag("-error_traceback", "PETSc's full traceback on errors instead of the one-line message"),
        OptionChoice("-help_markdown",
                     "Print a reference generated from the program's tables, as Markdown, and run nothing: "
                     "options (every option's row, docs/options.md) or results (every task's columns, "
                     "docs/results.md)",
                     {"options", "results"}, "options"),
        OptionReal("-max_memory", "GB",
                   "Refuse a run whose largest allocations (a grid's state and modes, the flight's series) are "
                   "estimated beyond this (default half of the physical memory)",
                   "",
                   Positive()), // no fixed default: the machine's
      },
    };
  }();
  return m;
}

namespace {

// -task, -output, -output_overwrite, -allow_unused_options, -error_traceback, -help_markdown,
// -max_memory (task and output null: only read, as for -help; -allow_unused_options,
// -error_traceback and -max_memory are acted on by the unused-option check, main and the memory
// checks, and read here for -help and the run record). *markdown: the reference -help_markdown
// asks for, "" when not given.
PetscErrorCode RunTaskOptions(MPI_Comm comm, PetscInt *task, std::string *out, std::string *markdown)
{
  const OptionModule &T = TaskOptionTable();
  PetscInt            t = 0;
  std::string         output, reference = "options";
  PetscBool           set_output, set_reference, flag = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-task", &t, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-output", &output, &set_output));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-output_overwrite", &flag, NULL));
  flag = PETSC_FALSE;
  PetscCall(OptionsRead(PetscOptionsObject, T, "-allow_unused_options", &flag, NULL));
  flag = PETSC_FALSE;
  PetscCall(OptionsRead(PetscOptionsObject, T, "-error_traceback", &flag, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-help_markdown", &reference, &set_reference));
  PetscReal max_gb = MemoryLimit() / 1e9; // checked here (> 0), used where an estimate is checked (base/memory.hpp)
  PetscCall(OptionsRead(PetscOptionsObject, T, "-max_memory", &max_gb, NULL));
  PetscOptionsEnd();
  if (markdown) *markdown = set_reference ? reference : std::string();
  if (task) *task = t;
  if (out) {
    PetscCheck(!set_output || !output.empty(), comm, PETSC_ERR_ARG_WRONG,
               "-output needs a file name (or 'none' to write nothing); it was given empty");
    *out = set_output ? output : std::string(Tasks[t].name) + ".h5";
    if (*out == "none") out->clear();
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode RunTask(MPI_Comm comm)
{
  PetscInt    task;
  std::string out;
  PetscBool   help = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) {
    PetscCall(PrintAllOptions(comm));
    PetscFunctionReturn(0);
  }
  std::string markdown;
  PetscCall(RunTaskOptions(comm, &task, &out, &markdown));
  if (!markdown.empty()) { // a reference generated from the tables (docs/options.md, docs/results.md)
    PetscCall(DocsPrintMarkdown(comm, markdown));
    PetscFunctionReturn(0);
  }
  PetscCall(OutputCheck(comm, &out, Tasks[task].name));
  PetscCall(Tasks[task].run(comm, out));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

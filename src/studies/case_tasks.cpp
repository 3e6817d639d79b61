// The task kinds a case of a batch runs (studies/case_batch.hpp): one impact (the sweep's case
// runner, the columns of the results table), the structure's modes and rigid-body numbers (a tap
// test, a scale, a balance, a swingweight scale), and the batted ball's flight alone. Each reads
// its columns through one lookup; a new kind is one entry in CaseTasks().
#include "studies/case_batch.hpp"

#include "base/option_table.hpp"
#include "io/beam_options.hpp"
#include "io/flight_options.hpp"
#include "io/string_bed_options.hpp"
#include "run/results_table.hpp"
#include "solvers/flight_ts.hpp"
#include "solvers/modes.hpp"
#include "solvers/string_bed_modes.hpp"
#include "system/parts/bed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace beamimpact {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The first case a rank runs on a whole reading of its options: every setting that is an option
// of the program must have been read by some reader (else it changes nothing: a column of the
// data naming another task's option). PETSc's own options (-ts_*) are not checked here.
void CheckSettingsRead(const SweepPlan &plan, const char *task, CaseRunState *state, CaseRow *row)
{
  if (state->checked || row->status != SweepOk) return;
  state->checked = true;
  for (const SweepAxis &a : plan.axes) {
    const std::string name = "-" + a.name;
    if (OptionSpecFind(name) && !OptionIsPetsc(name) && !OptionsUsed().count(name)) {
      row->status = SweepRefused;
      row->reason = name + " is not read by -task " + task + " (an option of another task? it would change nothing)";
      std::fill(row->values.begin(), row->values.end(), kNaN);
      return;
    }
  }
}

// ---------------------------------------------------------------------------
// impact: the results table (run/results_table.hpp)
// ---------------------------------------------------------------------------

bool ImpactColumn(const std::string &name, std::string *unit, std::string *why)
{
  const ResultColumn *c = ImpactResultColumn(name);
  if (c) {
    *unit = c->unit;
    return true;
  }
  *why = "the columns of an impact are those of its results table: " + ImpactResultColumnNames();
  return false;
}

PetscErrorCode ImpactCaseRun(MPI_Comm comm, const SweepPlan &plan, const std::vector<std::string> &columns,
                             CaseRunState *state, CaseRow *row)
{
  std::vector<double> sweep_row;
  ImpactResult        result;

  PetscFunctionBeginUser;
  PetscCall(SweepCaseRun(comm, plan, 0, &sweep_row, &row->reason, &result, &state->impact));
  row->status = (int)sweep_row[1 + plan.axes.size()];
  row->values.assign(columns.size(), kNaN);
  if (row->status == SweepOk)
    for (size_t k = 0; k < columns.size(); ++k) row->values[k] = ImpactResultColumn(columns[k])->Get(result);
  if (!state->impact.scenario.last_partial) CheckSettingsRead(plan, "impact", state, row);
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// modes: the flexible modes' frequencies and the structure as a rigid body
// ---------------------------------------------------------------------------

// A frequency column: "frequency_3" (the third flexible mode), "bending_frequency_1", ... (a
// family is an energy account's name, StructureAccountName): the family ("" for any) and k (>= 1);
// false when name is none.
bool ParseFrequency(const std::string &name, std::string *family, int *k)
{
  for (PetscInt a = -1; a < StructureAccountCount(); ++a) {
    const std::string f    = a < 0 ? "" : StructureAccountName(a);
    const std::string head = f + (f.empty() ? "" : "_") + "frequency_";
    if (name.compare(0, head.size(), head) != 0 || name.size() == head.size()) continue;
    char      *end = nullptr;
    const long v   = std::strtol(name.c_str() + head.size(), &end, 10);
    if (*end || v < 1 || v > 10000) return false;
    *family = f;
    *k      = (int)v;
    return true;
  }
  return false;
}

// The rigid-body columns: name -> (unit, value of the body).
struct BodyColumn {
  const char *name, *unit;
  double (*get)(const BeamRigidBody &b);
};
const BodyColumn kBodyColumns[] = {
  {"mass", "kg", [](const BeamRigidBody &b) { return (double)b.mass; }},
  {"centre_of_mass", "m", [](const BeamRigidBody &b) { return (double)b.x_cm; }},
  {"moment_of_inertia", "kg m^2", [](const BeamRigidBody &b) { return (double)b.inertia_cm; }},
  {"inertia_end", "kg m^2", [](const BeamRigidBody &b) { return (double)b.inertia_end; }},
  {"inertia_roll", "kg m^2", [](const BeamRigidBody &b) { return (double)b.inertia_roll; }},
  {"swingweight", "kg m^2",
   [](const BeamRigidBody &b) { return (double)(b.inertia_cm + b.mass * (b.x_cm - 0.1) * (b.x_cm - 0.1)); }},
};

bool ModesColumn(const std::string &name, std::string *unit, std::string *why)
{
  std::string family;
  int         k;
  if (ParseFrequency(name, &family, &k)) {
    *unit = "Hz";
    return true;
  }
  for (const BodyColumn &c : kBodyColumns)
    if (name == c.name) {
      *unit = c.unit;
      return true;
    }
  std::string families; // each energy account's
  for (PetscInt a = 0; a < StructureAccountCount(); ++a)
    families += std::string(a ? ", " : "") + StructureAccountName(a) + "_frequency_K";
  *why = "the columns of -task modes are frequency_K (the K-th flexible mode), " + families +
         " (the K-th of the modes whose kinetic energy is mostly in that part), mass, centre_of_mass (from x = 0), "
         "moment_of_inertia (about the centre of mass), "
         "inertia_end (about x = 0), inertia_roll (about the axis), swingweight (about x = 0.1 m: a "
         "racket's with its butt at x = 0)";
  return false;
}

// The family of mode q: the energy account holding most of its kinetic energy (a mode with a
// family detail, ModesResult::shell_n: the account of the part that gives it, the wall's).
std::string ModeFamily(const ModesResult &m, size_t q)
{
  if (!m.part.empty()) return StructureAccountName(m.part[q]);
  if (!m.shell_n.empty() && m.shell_n[q] != 0) return StructureAccountName(m.detail_account);
  return StructureAccountName(0);
}

// The modes the columns need: -modes_count when given, else the rigid ones and a margin above the
// highest mode asked for (a family's K-th mode may lie above the K-th of all).
PetscInt ModesCount(const BeamSystem &op, const std::vector<std::string> &columns)
{
  PetscInt  count = 0;
  PetscBool set   = PETSC_FALSE;
  PetscOptionsGetInt(NULL, NULL, "-modes_count", &count, &set);
  if (set) return count;
  int most = 1;
  for (const std::string &c : columns) {
    std::string family;
    int         k;
    if (ParseFrequency(c, &family, &k)) most = std::max(most, family.empty() ? k : 3 * k);
  }
  return std::min(BeamFreeDofCount(op), BeamSystemRigidCount(op) + (PetscInt)most + 4);
}

// The columns of one modes run; a frequency beyond the modes computed fails the row.
void ModesValues(const ModesResult &modes, const BeamRigidBody &body, PetscInt count,
                 const std::vector<std::string> &columns, CaseRow *row)
{
  row->values.assign(columns.size(), kNaN);
  for (size_t k = 0; k < columns.size(); ++k) {
    std::string family;
    int         want;
    if (ParseFrequency(columns[k], &family, &want)) {
      int seen = 0;
      for (size_t q = 0; q < modes.frequency.size() && std::isnan(row->values[k]); ++q)
        if (modes.omega[q] != 0 && (family.empty() || ModeFamily(modes, q) == family) && ++seen == want)
          row->values[k] = modes.frequency[q];
      if (std::isnan(row->values[k])) // not a failure: the row may not measure it (the reason says why it is NaN)
        row->reason += (row->reason.empty() ? "" : "; ") + columns[k] + " is not among the " +
                       std::to_string((long long)count) + " modes computed (a larger -modes_count?)";
      continue;
    }
    for (const BodyColumn &c : kBodyColumns)
      if (columns[k] == c.name) row->values[k] = c.get(body);
  }
}

// A string bed in a held frame (-strings_frame held, as -task modes computes it): its modes are
// all the strings'; it has no body (the rigid-body columns are NaN).
PetscErrorCode HeldBedModes(MPI_Comm comm, const std::vector<std::string> &columns, CaseRow *row)
{
  StringBedParams p;
  StringBedModes  modes;
  PetscInt        count = 0;
  PetscBool       set   = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(StringBedParamsFromOptions(comm, &p));
  for (const std::string &c : columns) {
    std::string family;
    int         k;
    if (ParseFrequency(c, &family, &k)) count = std::max(count, (PetscInt)k);
  }
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-modes_count", &count, &set));
  PetscCall(StringBedModesCompute(comm, StringBedGrid(p), StringBedMembrane(p), std::max<PetscInt>(count, 1), &modes));
  ModesResult m; // as a beam's modes: every one the strings', none rigid
  m.omega     = modes.omega;
  m.frequency = modes.frequency;
  m.part.assign(modes.frequency.size(), StructureAccountOf(BedPart()));
  ModesValues(m, BeamRigidBody(), (PetscInt)modes.frequency.size(), columns, row);
  for (size_t k = 0; k < columns.size(); ++k)
    for (const BodyColumn &c : kBodyColumns)
      if (columns[k] == c.name) row->values[k] = kNaN; // a held bed is no body
  PetscFunctionReturn(0);
}

PetscErrorCode ModesCompute(MPI_Comm comm, const std::vector<std::string> &columns, CaseRow *row, bool *held)
{
  BeamParams  beam;
  BeamSystem  op;
  ModesResult modes;
  std::string why;
  PetscBool   given = PETSC_FALSE, bed = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-strings_frame", &given));
  if (given) PetscCall(StringBedRequested(comm, &bed));
  if (bed) { // as -task modes decides (app/task_strings.hpp): the bed in a held frame
    StringBedParams p;
    PetscCall(StringBedParamsFromOptions(comm, &p));
    if (p.Held()) {
      *held = true;
      PetscCall(HeldBedModes(comm, columns, row));
      PetscFunctionReturn(0);
    }
  }
  PetscCall(BeamParamsFromOptions(comm, &beam));
  PetscCheck(BeamSystemBuild(beam, &op, &why), comm, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  const PetscInt count = ModesCount(op, columns);
  PetscCall(BeamModesCompute(comm, op, count, &modes));
  ModesValues(modes, BeamRigidBodyOf(beam), count, columns, row);
  PetscFunctionReturn(0);
}

PetscErrorCode ModesCaseRun(MPI_Comm comm, const SweepPlan &plan, const std::vector<std::string> &columns,
                            CaseRunState *state, CaseRow *row)
{
  PetscFunctionBeginUser;
  bool held = false; // a held string bed reads none of the frame's options: not a whole reading
  PetscCall(SweepCaseOptionsSet(plan, 0));
  const PetscErrorCode ierr = ModesCompute(comm, columns, row, &held);
  if (ierr) {
    row->status = SweepStatusOfError(ierr);
    row->reason = SweepErrorReason(ierr);
    row->values.assign(columns.size(), kNaN);
  } else if (!held) CheckSettingsRead(plan, "modes", state, row);
  PetscCall(SweepCaseOptionsClear(plan));
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// flight: the batted ball's flight alone (-task flight)
// ---------------------------------------------------------------------------

struct FlightColumn {
  const char *name, *unit;
  double (*get)(const FlightResult &r);
};
const FlightColumn kFlightColumns[] = {
  {"distance", "m", [](const FlightResult &r) { return (double)r.landing.distance; }},
  {"hang_time", "s", [](const FlightResult &r) { return (double)r.landing.hang_time; }},
  {"landing_speed", "m/s", [](const FlightResult &r) { return (double)r.landing.landing_speed; }},
  {"landing_angle", "deg", [](const FlightResult &r) { return (double)r.landing.landing_angle; }},
  {"bearing", "deg", [](const FlightResult &r) { return (double)r.landing.bearing; }},
  {"apex", "m", [](const FlightResult &r) { return (double)r.apex; }},
  {"apex_time", "s", [](const FlightResult &r) { return (double)r.apex_time; }},
};

bool FlightColumnOf(const std::string &name, std::string *unit, std::string *why)
{
  std::string names;
  for (const FlightColumn &c : kFlightColumns) {
    if (name == c.name) {
      *unit = c.unit;
      return true;
    }
    names += (names.empty() ? "" : ", ") + std::string(c.name);
  }
  *why = "the columns of -task flight are " + names;
  return false;
}

PetscErrorCode FlightCompute(MPI_Comm comm, const std::vector<std::string> &columns, CaseRow *row)
{
  FlightParams      p;
  FlightSolveParams s;
  FlightResult      r;
  PetscReal         u0[6];

  PetscFunctionBeginUser;
  PetscCall(FlightParamsFromOptions(comm, &p, &s));
  const FlightModel m = FlightModelOf(p);
  FlightInitialState(p.launch, u0);
  PetscCall(FlightSolve(m, u0, s, &r));
  row->values.assign(columns.size(), kNaN);
  for (size_t k = 0; k < columns.size(); ++k)
    for (const FlightColumn &c : kFlightColumns)
      if (columns[k] == c.name) row->values[k] = c.get(r);
  PetscFunctionReturn(0);
}

PetscErrorCode FlightCaseRun(MPI_Comm comm, const SweepPlan &plan, const std::vector<std::string> &columns,
                             CaseRunState *state, CaseRow *row)
{
  PetscFunctionBeginUser;
  PetscCall(SweepCaseOptionsSet(plan, 0));
  const PetscErrorCode ierr = FlightCompute(comm, columns, row);
  if (ierr) {
    row->status = SweepStatusOfError(ierr);
    row->reason = SweepErrorReason(ierr);
    row->values.assign(columns.size(), kNaN);
  } else CheckSettingsRead(plan, "flight", state, row);
  PetscCall(SweepCaseOptionsClear(plan));
  PetscFunctionReturn(0);
}

const CaseTask kImpactTask = {"impact", "one impact (-task impact): the columns of its results table", ImpactColumn,
                              ImpactCaseRun};
const CaseTask kModesTask  = {"modes",
                              "the structure's modes and rigid-body numbers (-task modes): a tap test, a scale, a "
                               "balance",
                              ModesColumn, ModesCaseRun};
const CaseTask kFlightTask = {"flight", "the batted ball's flight alone (-task flight)", FlightColumnOf, FlightCaseRun};

} // namespace

const std::vector<const CaseTask *> &CaseTasks()
{
  static const std::vector<const CaseTask *> tasks = {&kImpactTask, &kModesTask, &kFlightTask};
  return tasks;
}

const CaseTask *CaseTaskFind(const std::string &name)
{
  for (const CaseTask *t : CaseTasks())
    if (name == t->name) return t;
  return nullptr;
}

std::string CaseTaskNames()
{
  std::string out;
  for (const CaseTask *t : CaseTasks()) out += (out.empty() ? "" : ", ") + std::string(t->name);
  return out;
}

} // namespace beamimpact

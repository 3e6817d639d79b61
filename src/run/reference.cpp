// The registry of the methods that solve one impact, and the run layer's two: the configured time
// integrator and the exact modal solution. See reference.hpp.
#include "run/reference.hpp"

#include "base/options_util.hpp"
#include "run/impact_problem.hpp"
#include "run/modal_reference.hpp"
#include "run/scenario.hpp"

namespace beamimpact {

namespace {

std::vector<const ReferenceMethod *> &Registry()
{
  static std::vector<const ReferenceMethod *> methods;
  return methods;
}

bool Always(const Scenario &, std::string *why)
{
  if (why) why->clear();
  return true;
}

std::string NameOnly(const char *name) { return name; }

bool ModalApplies(const Scenario &sc, std::string *why) { return ModalReferenceApplies(sc, why); }

// ts: the PETSc TS as -ts_* configure it (solvers/ts_stepper.hpp).
PetscErrorCode TimeSteppingRun(MPI_Comm comm, const Scenario &sc, const ReferenceSettings &, ReferenceSolution *sol)
{
  PetscFunctionBeginUser;
  PetscCall(ImpactRun(comm, sc, &sol->result));
  sol->method = "ts";
  PetscFunctionReturn(0);
}

// modal: no integrator, so neither monitors nor integrator options.
PetscErrorCode ModalRun(MPI_Comm comm, const Scenario &sc, const ReferenceSettings &, ReferenceSolution *sol)
{
  PetscFunctionBeginUser;
  PetscCheck(!sc.monitor.any() && sc.monitor.snapshot_times.empty(), comm, PETSC_ERR_SUP,
             "-reference modal records no time series or snapshots: remove the -monitor_*/-snapshot_times options");
  // The problem (run/impact_problem.hpp): an oblique impact's run along the normal, whose F_n(t)
  // drives the tangential contact and the bat's second plane, as for a stepped run; the truncation
  // (-modal_modes: the truncated model's exact solution; not given: every mode, the dense one),
  // read before the check of unused options.
  ImpactProblem pb;
  PetscCall(ImpactProblemBuild(comm, sc, ImpactMethod::ModalReference, nullptr, &pb));
  if (sc.impact.check_unused_options)
    PetscCall(OptionsCheckUnused(comm, {"ts_", "snes_", "ksp_", "pc_"})); // integrator options have no effect here
  PetscCall(ModalReferenceRun(comm, pb.sc, pb.truncation, &sol->result)); // collective on the run's comm (its modes)
  if (sc.impact.report_setup)
    PetscCall(PetscPrintf(comm, "ts %s (%s)  dt %.3e s\n", sol->result.ts_type.c_str(), sol->result.formulation.c_str(),
                          (double)sol->result.dt_nominal));
  sol->method = "modal";
  PetscFunctionReturn(0);
}

} // namespace

const ReferenceMethod kReferenceTimeStepping = {
  "ts",
  "integrate with the PETSc TS (-ts_type and its options)",
  true,
  false,
  false,
  Always,
  TimeSteppingRun,
  [](const ReferenceSettings &) { return NameOnly("ts"); },
};

const ReferenceMethod kReferenceModal = {
  "modal",
  "the exact modal solution (linear spring, no grip; Rayleigh damping allowed; no time step, only round-off; an "
  "oblique impact's tangential contact from F_n at 20000 samples per contact)",
  true,
  true,
  true,
  ModalApplies,
  ModalRun,
  [](const ReferenceSettings &) { return NameOnly("modal"); },
};

void ReferenceMethodRegister(const ReferenceMethod *m)
{
  for (const ReferenceMethod *q : Registry())
    if (q == m || std::string(q->name) == m->name) return;
  Registry().push_back(m);
}

const std::vector<const ReferenceMethod *> &ReferenceMethods() { return Registry(); }

const ReferenceMethod *ReferenceMethodFind(const std::string &name)
{
  for (const ReferenceMethod *m : Registry())
    if (name == m->name) return m;
  return nullptr;
}

std::vector<std::string> ReferenceMethodNames(bool study)
{
  std::vector<std::string> names;
  for (const ReferenceMethod *m : Registry())
    if (study ? m->study : m->impact) names.push_back(m->name);
  return names;
}

std::string ReferenceMethodHelp(bool study)
{
  std::string s;
  for (const ReferenceMethod *m : Registry())
    if (study ? m->study : m->impact) s += (s.empty() ? "" : "; ") + std::string(m->name) + ": " + m->help;
  return s;
}

const ReferenceMethod *ReferenceMethodDefault(const Scenario &sc)
{
  for (const ReferenceMethod *m : Registry())
    if (m->study && m->applies(sc, nullptr)) return m;
  return nullptr;
}

const OptionModule &ReferenceOptionModule()
{
  static const OptionModule m = [] {
    OptionModule                   r{"reference", "Impact task: the method that solves it (-task impact)", {}};
    const std::vector<std::string> names = ReferenceMethodNames(false);
    r.options.push_back(OptionChoice("-reference", ("How the impact is solved: " + ReferenceMethodHelp(false)).c_str(),
                                     names, names.empty() ? "" : names[0].c_str()));
    r.options.push_back(OptionReal("-reference_max_memory", "GB",
                                   "-reference modal: refuse a beam whose dense modal matrices need more than this "
                                   "(default -max_memory's limit: half of the physical memory)",
                                   "", Positive())); // no fixed default: the machine's
    return r;
  }();
  return m;
}

PetscErrorCode ReferenceMethodFromOptions(MPI_Comm comm, const ReferenceMethod **method)
{
  const OptionModule &m      = ReferenceOptionModule();
  PetscInt            index  = 0;
  PetscReal           max_gb = ModalReferenceMemoryLimit() / 1e9;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, m.title.c_str(), "beamimpact");
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-reference", &index, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-reference_max_memory", &max_gb, NULL));
  PetscOptionsEnd();
  *method = ReferenceMethodFind(ReferenceMethodNames(false)[index]);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

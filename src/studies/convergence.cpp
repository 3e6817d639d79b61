// -task convergence: the task, over the plan, the execution, the analysis and the output.
// See convergence.hpp.
#include "studies/convergence.hpp"

#include "base/options_util.hpp"
#include "io/scenario_options.hpp"

namespace beamimpact {

namespace {

// The scenario and the plan. The integrators come from the configuration files only.
PetscErrorCode ConvergenceReadOptions(MPI_Comm comm, Scenario *sc, ConvergencePlan *plan)
{
  ScenarioReading how;
  PetscBool       has;

  PetscFunctionBeginUser;
  how.monitors = false; // the runs record no time series: -monitor_* is reported unused
  PetscCall(ScenarioFromOptions(comm, how, sc));
  PetscCall(ConvergencePlanFromOptions(comm, *sc, plan));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_type", &has));
  PetscCheck(!has, comm, PETSC_ERR_ARG_WRONG,
             "-ts_type is not used by -task convergence: the integrators come from the -convergence_configs files; "
             "options common to every run go in a file given with -convergence_common_options FILE "
             "(a scene file that sets an integrator, such as options/base/default-scene.opts, cannot be used here)");
  PetscCall(OptionsCheckUnused(comm));
  PetscFunctionReturn(0);
}

// The temporal study: reference, every configuration's runs, orders, cost at the target.
PetscErrorCode TemporalStudy(MPI_Comm comm, const Scenario &sc, const ConvergencePlan &plan, ConvergenceReference *ref,
                             std::vector<std::vector<ConvergenceRun>> *all, RunRecord *summary)
{
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "convergence study: N = %" PetscInt_FMT
                        ", x = %g m, %s law, window %g s after separation, %" PetscInt_FMT
                        " repeat(s) per level (fewer once a level took -convergence_repeat_budget)\n",
                        sc.beam.nodes, (double)sc.impact.x, ContactLawName(sc.ball.law), (double)times.window,
                        plan.repeats));
  PetscCall(ConvergenceReferenceCompute(comm, plan, sc, ref));
  PetscCall(ConvergencePrintReference(comm, plan, *ref));
  PetscCall(ConvergenceRunConfigs(comm, plan, plan.configs, sc, *ref, all));
  if (!plan.quiet)
    for (size_t c = 0; c < plan.configs.size(); ++c)
      for (const ConvergenceRun &run : (*all)[c]) PetscCall(ConvergencePrintRun(comm, plan.configs[c], run));
  PetscCall(ConvergencePrintOrders(comm, plan, *all));
  PetscCall(ConvergencePrintCostAtTarget(comm, plan, *all, summary));
  PetscFunctionReturn(0);
}

// The spatial study, with its continuum limit and observed orders.
PetscErrorCode SpatialStudy(MPI_Comm comm, const Scenario &sc, const ConvergencePlan &plan, ConvergenceSpatial *sp)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "\nspatial study (reference %s at each N):\n", ConvergenceReferenceLabel(plan).c_str()));
  PetscCall(
    ConvergenceSpatialRuns(comm, plan, sc, sp, [&](PetscInt N, const ConvergenceReference &ref) -> PetscErrorCode {
      PetscFunctionBeginUser;
      if (!plan.quiet) PetscCall(ConvergencePrintSpatialLevel(comm, N, sc.beam.length / (N - 1), ref));
      PetscFunctionReturn(0);
    }));
  ConvergenceSpatialAnalyse(sp);
  PetscCall(ConvergencePrintSpatial(comm, *sp));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TaskConvergence(MPI_Comm comm, const std::string &output)
{
  Scenario                                 sc;
  ConvergencePlan                          plan;
  RunRecord                                record, summary;
  ConvergenceReference                     ref;
  std::vector<std::vector<ConvergenceRun>> all;
  ConvergenceSpatial                       sp;

  PetscFunctionBeginUser;
  PetscCall(ConvergenceReadOptions(comm, &sc, &plan));
  PetscCall(ConvergenceRecordBuild(sc, plan, &record));
  if (!plan.configs.empty()) PetscCall(TemporalStudy(comm, sc, plan, &ref, &all, &summary));
  if (!plan.spatial_nodes.empty()) PetscCall(SpatialStudy(comm, sc, plan, &sp));
  if (!output.empty()) {
    PetscCall(
      ConvergenceFileWrite(comm, output, record, plan, plan.configs.empty() ? nullptr : &ref, all, summary, &sp));
    PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// -task convergence, the execution: the reference, the configurations' runs and the spatial
// study's references. See convergence_runs.hpp.
#include "studies/convergence_runs.hpp"

#include "base/options_util.hpp"
#include "io/beam_options.hpp"
#include "io/text.hpp"
#include "run/outcome.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/rk_stability.hpp"
#include "studies/convergence_analysis.hpp"

#include <petscts.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamimpact {

namespace {

const PetscReal NaN = std::numeric_limits<PetscReal>::quiet_NaN();

// Explicit stability limit (s) of a configuration: Stormer-Verlet 2/omega_max, or
// y*/omega_max of the rk tableau selected by the run's options (as ImpactRun computes it).
PetscErrorCode StableStep(const ConvergenceConfig &cfg, const Scenario &sc, PetscReal *dt)
{
  PetscFunctionBeginUser;
  BeamSystem  sys;
  std::string why;
  PetscCheck(BeamSystemBuild(sc.beam, &sys, &why), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  const PetscReal lf = LeapfrogStableStep(sys, BeamSystemCoupling(sys, sc.impact.x, sc.impact.z),
                                          sc.ball); // 2 / omega_max
  if (cfg.method == "leapfrog") {
    *dt = lf;
    PetscFunctionReturn(0);
  }
  char      type[64] = "", rktype[64] = "";
  PetscBool set_type, set_rk;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-ts_type", type, sizeof(type), &set_type));
  PetscCheck(set_type && std::string(type) == TSRK, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "configuration %s: -convergence_dt_stable needs -ts_type rk (or -convergence_method leapfrog); it has "
             "-ts_type %s",
             cfg.name.c_str(), set_type ? type : "(none)");
  PetscCall(PetscOptionsGetString(NULL, NULL, "-ts_rk_type", rktype, sizeof(rktype), &set_rk));
  TS               ts;
  PetscInt         s;
  const PetscReal *A, *b;
  PetscCall(TSCreate(PETSC_COMM_SELF, &ts));
  PetscCall(TSSetType(ts, TSRK));
  if (set_rk) PetscCall(TSRKSetType(ts, rktype));
  PetscCall(TSRKGetTableau(ts, &s, &A, &b, NULL, NULL, NULL, NULL, NULL));
  const PetscReal ystar = RKImaginaryStabilityBound(s, A, b);
  PetscCall(TSDestroy(&ts));
  PetscCheck(ystar > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "configuration %s: -ts_rk_type %s is unstable for undamped oscillation at any step", cfg.name.c_str(),
             set_rk ? rktype : "(default)");
  *dt = ystar * lf / 2 * (1 - 1e-12);
  PetscFunctionReturn(0);
}

// One run of one level in the (pushed) database of the configuration.
PetscErrorCode RunInPushedOptions(MPI_Comm comm, const ConvergenceConfig &cfg, const Scenario &sc_in, ImpactResult *res)
{
  PetscFunctionBeginUser;
  Scenario sc                    = sc_in;
  sc.impact.check_unused_options = PETSC_TRUE;
  sc.impact
    .strict_solver_options = PETSC_TRUE;       // a configuration runs as written: a misspelt -ts_ option fails its runs
  sc.monitor               = MonitorRequest(); // no time series
  if (cfg.method == "leapfrog") {
    LeapfrogParams lp;
    PetscCall(LeapfrogParamsFromOptions(comm, &lp));
    PetscCall(OptionsCheckUnused(comm, {}, true));
    PetscCall(LeapfrogRun(sc, lp, res));
  } else {
    PetscCall(ImpactRun(comm, sc, res));
  }
  PetscFunctionReturn(0);
}

// One run of one level: a fresh database with the configuration and this level's
// step or tolerance, pushed for the run, popped and destroyed after it (even on
// failure). Sets run->level, dt, rtol, atol; the outcome goes to *res and the run's
// error code (0 on success) to *run_err, with run->failed and run->message on failure.
PetscErrorCode RunLevelOnce(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceConfig &cfg, PetscInt level,
                            const Scenario &sc, ConvergenceRun *run, ImpactResult *res, PetscErrorCode *run_err)
{
  PetscOptions o;

  PetscFunctionBeginUser;
  run->level = level;
  PetscCall(ConvergenceConfigOptionsCreate(comm, cfg, plan.common_file, &o));
  for (const char *k : ConvergenceConfigKeys()) PetscCall(PetscOptionsClearValue(o, k));
  const PetscReal v     = cfg.seq.value(level);
  const char     *dtkey = cfg.method == "leapfrog" ? "-leapfrog_dt" : "-ts_dt";
  PetscCall(PetscOptionsPush(o));
  PetscErrorCode ierr = 0;
  switch (cfg.seq.kind) {
  case ConvergenceSequenceKind::Step:
    run->dt = v;
    break;
  case ConvergenceSequenceKind::StableFraction: {
    PetscReal dts = 0;
    ierr          = StableStep(cfg, sc, &dts);
    run->dt       = v * dts;
  } break;
  case ConvergenceSequenceKind::Tolerance:
    run->rtol = v;
    run->atol = v * cfg.atol_factor;
    break;
  }
  if (!ierr) {
    if (cfg.seq.kind == ConvergenceSequenceKind::Tolerance) {
      ierr = PetscOptionsSetValue(o, "-ts_rtol", ConvergenceFormat("%.17g", run->rtol).c_str());
      if (!ierr) ierr = PetscOptionsSetValue(o, "-ts_atol", ConvergenceFormat("%.17g", run->atol).c_str());
    } else ierr = PetscOptionsSetValue(o, dtkey, ConvergenceFormat("%.17g", run->dt).c_str());
  }
  if (!ierr) ierr = RunInPushedOptions(comm, cfg, sc, res);
  PetscCall(PetscOptionsPop());
  PetscCall(PetscOptionsDestroy(&o));
  *run_err = ierr;
  if (ierr) {
    run->failed  = true;
    run->message = LastErrorMessage(ierr);
  } else if (res->ended_in_contact) { // a contact cut short by -impact_max_time: no number (as -task impact)
    *run_err     = PETSC_ERR_ARG_INCOMP;
    run->failed  = true;
    run->message = ImpactCutOffReason(sc, *res);
  }
  PetscFunctionReturn(0);
}

// The step measures of a finished run.
void FinishRun(const ConvergenceConfig &cfg, ConvergenceRun *run)
{
  if (run->failed) return;
  if (cfg.seq.kind == ConvergenceSequenceKind::Tolerance) run->dt = run->result.dt_nominal;
  run->mean_step = run->result.steps > 0 ? run->result.final_time / run->result.steps : NaN;
}

// The reference method "run": the reference configuration over its sequence, one run per level
// (the common options of the study inserted into each); the finest level is the reference and
// its own error the Richardson estimate from the last three levels (ratio: the divisor).
PetscErrorCode RunReferenceRun(MPI_Comm comm, const Scenario &sc, const ReferenceSettings &settings,
                               ReferenceSolution *ref)
{
  ConvergenceConfig cfg;
  ConvergencePlan   p;

  PetscFunctionBeginUser;
  PetscCall(ConvergenceConfigLoad(comm, settings.config_file, "", &cfg));
  p.repeats     = 1;
  p.common_file = settings.common_file;
  std::vector<PetscReal> acor, tc, pf;
  for (PetscInt k = 0; k < cfg.seq.count; ++k) {
    ConvergenceRun run;
    PetscErrorCode err;
    PetscCall(RunLevelOnce(comm, p, cfg, k, sc, &run, &run.result, &err));
    PetscCheck(!err, comm, PETSC_ERR_NOT_CONVERGED,
               "the reference configuration %s failed at level %" PetscInt_FMT ": %s", settings.config_file.c_str(), k,
               run.message.c_str());
    acor.push_back(run.result.acor);
    tc.push_back(run.result.contact_time);
    pf.push_back(run.result.peak_force);
    ref->result = run.result;
  }
  ref->method = cfg.name;
  PetscReal p_tc, p_pf;
  ref->acor_error         = ConvergenceRichardsonError(acor, cfg.seq.divisor, false, &ref->observed_order);
  ref->contact_time_error = ConvergenceRichardsonError(tc, cfg.seq.divisor, true, &p_tc);
  ref->peak_force_error   = ConvergenceRichardsonError(pf, cfg.seq.divisor, true, &p_pf);
  PetscFunctionReturn(0);
}

bool RunReferenceApplies(const Scenario &, std::string *why)
{
  if (why) why->clear();
  return true;
}

std::string RunReferenceLabel(const ReferenceSettings &settings) { return settings.config_file; }

} // namespace

const ReferenceMethod kReferenceRun = {
  "run",
  "a tight run of the configuration -convergence_reference_config at its own sequence: the finest level, its error "
  "estimated by Richardson extrapolation from the last three",
  false,
  true,
  false,
  RunReferenceApplies,
  RunReferenceRun,
  RunReferenceLabel,
};

PetscErrorCode ConvergenceReferenceCompute(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &sc,
                                           ConvergenceReference *ref)
{
  PetscFunctionBeginUser;
  *ref                          = ConvergenceReference();
  const ReferenceMethod *method = ReferenceMethodFind(plan.reference);
  PetscCheck(method && method->study, comm, PETSC_ERR_ARG_WRONG,
             "-convergence_reference %s is not allowed: it takes %s", plan.reference.c_str(),
             ReferenceMethodHelp(true).c_str());
  const double wall = MPI_Wtime();
  PetscCall(method->run(comm, sc, ConvergenceReferenceSettings(plan), ref));
  ref->wall_time = MPI_Wtime() - wall;
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceRunConfigs(MPI_Comm comm, const ConvergencePlan &plan,
                                     const std::vector<ConvergenceConfig> &cfgs, const Scenario &sc,
                                     const ConvergenceReference &ref, std::vector<std::vector<ConvergenceRun>> *all)
{
  std::vector<std::vector<PetscReal>> spent(cfgs.size());

  PetscFunctionBeginUser;
  all->assign(cfgs.size(), {});
  for (size_t c = 0; c < cfgs.size(); ++c) {
    (*all)[c].resize(cfgs[c].seq.count);
    spent[c].assign(cfgs[c].seq.count, 0.0);
  }
  // Repeats are interleaved (every level of every configuration once, then again), so
  // a burst of load on the machine does not spoil all the repeats of one level.
  for (PetscInt r = 0; r < plan.repeats; ++r) {
    for (size_t c = 0; c < cfgs.size(); ++c) {
      for (PetscInt k = 0; k < cfgs[c].seq.count; ++k) {
        ConvergenceRun &run = (*all)[c][k];
        if (r > 0 && (run.failed || spent[c][k] >= plan.repeat_budget)) continue;
        ImpactResult   res;
        PetscErrorCode err;
        const double   w0 = MPI_Wtime();
        PetscCall(RunLevelOnce(comm, plan, cfgs[c], k, sc, &run, &res, &err));
        spent[c][k] += MPI_Wtime() - w0;
        if (err) continue;
        if (r == 0) {
          run.result        = res;
          run.wall_time_max = res.wall_time;
        } else {
          run.result.wall_time = std::min(run.result.wall_time, res.wall_time);
          run.wall_time_max    = std::max(run.wall_time_max, res.wall_time);
        }
      }
    }
  }
  for (size_t c = 0; c < cfgs.size(); ++c)
    for (auto &run : (*all)[c]) {
      FinishRun(cfgs[c], &run);
      ConvergenceMeasureAgainst(ref, &run);
    }
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceRunConfig(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceConfig &cfg,
                                    const Scenario &sc, const ConvergenceReference &ref,
                                    std::vector<ConvergenceRun> *runs)
{
  std::vector<std::vector<ConvergenceRun>> all;

  PetscFunctionBeginUser;
  PetscCall(ConvergenceRunConfigs(comm, plan, {cfg}, sc, ref, &all));
  *runs = all[0];
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceSpatialRuns(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &base,
                                      ConvergenceSpatial                                                          *sp,
                                      const std::function<PetscErrorCode(PetscInt, const ConvergenceReference &)> &done)
{
  PetscFunctionBeginUser;
  *sp = ConvergenceSpatial();
  for (PetscInt N : plan.spatial_nodes) {
    Scenario sc   = base;
    sc.beam.nodes = N;
    PetscCall(BeamParamsCheck(comm, sc.beam));
    ConvergenceReference ref;
    PetscCall(ConvergenceReferenceCompute(comm, plan, sc, &ref));
    sp->nodes.push_back(N);
    sp->h.push_back(sc.beam.length / (N - 1));
    sp->acor.push_back(ref.result.acor);
    sp->contact_time.push_back(ref.result.contact_time);
    sp->peak_force.push_back(ref.result.peak_force);
    if (done) PetscCall(done(N, ref));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

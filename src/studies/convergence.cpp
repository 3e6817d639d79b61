// -task convergence: configurations, sequences, reference, runs, observed orders,
// the spatial study and the HDF5 file. See convergence.hpp.
#include "studies/convergence.hpp"

#include "solvers/leapfrog.hpp"
#include "run/modal_reference.hpp"
#include "run/outcome.hpp"
#include "run/scenario.hpp"
#include "solvers/rk_stability.hpp"
#include "base/options_util.hpp"
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "io/scenario_options.hpp"
#include "io/options_files.hpp"
#include "io/text.hpp"

#include <hdf5.h>
#include <petscts.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace beamimpact {

namespace {

const PetscReal NaN = std::numeric_limits<PetscReal>::quiet_NaN();

const char *const SequenceNames[]  = {"dt", "dt_stable", "tol"};
const char *const ReferenceNames[] = {"modal", "run", "ConvergenceReferenceKind", "CONVERGENCE_REFERENCE_", nullptr};

// The -convergence_* keys a configuration file may hold (removed from the run's database).
const char *const ConfigKeys[] = {"-convergence_dt", "-convergence_dt_stable", "-convergence_tol", "-convergence_order", "-convergence_atol_factor", "-convergence_name", "-convergence_method"};

std::string BaseName(const std::string &path)
{
  std::string b = path.substr(path.find_last_of('/') + 1);
  if (b.size() > 5 && b.compare(b.size() - 5, 5, ".opts") == 0) b.resize(b.size() - 5);
  return b;
}

std::vector<std::string> SplitList(const std::string &s)
{
  std::vector<std::string> out;
  std::stringstream        ss(s);
  std::string              p;
  while (std::getline(ss, p, ',')) {
    p = Trim(p);
    if (!p.empty()) out.push_back(p);
  }
  return out;
}

// The header of an options file: its leading comment lines, joined.
std::string FileDescription(const std::string &file)
{
  std::ifstream in(file);
  std::string   line, text;
  while (std::getline(in, line)) {
    const size_t a = line.find_first_not_of(" \t");
    if (a == std::string::npos) continue;
    if (line[a] != '#') break;
    const std::string t = CommentText(line);
    if (!t.empty()) text += (text.empty() ? "" : " ") + t;
  }
  return text;
}

// A fresh options database holding a configuration: the common options file (if
// any) first, then the configuration's file and text, which win over it. The common
// options are marked used: they apply to the runs where they mean something (a
// factorization ordering means nothing to an explicit method).
PetscErrorCode ConfigOptionsCreate(MPI_Comm comm, const ConvergenceConfig &cfg, const std::string &common_file, PetscOptions *o)
{
  std::vector<std::string> common;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsCreate(o));
  if (!common_file.empty()) {
    PetscOptions c;
    PetscInt     n;
    char       **names, **values;
    PetscCall(PetscOptionsCreate(&c));
    PetscCall(OptionsFileInsert(comm, c, common_file));
    PetscCall(PetscOptionsLeftGet(c, &n, &names, &values)); // nothing was read yet: every option
    for (PetscInt i = 0; i < n; ++i) common.push_back(std::string("-") + names[i]);
    PetscCall(PetscOptionsLeftRestore(c, &n, &names, &values));
    PetscCall(PetscOptionsDestroy(&c));
    PetscCall(OptionsFileInsert(comm, *o, common_file));
  }
  if (!cfg.file.empty()) PetscCall(OptionsFileInsert(comm, *o, cfg.file));
  if (!cfg.text.empty()) PetscCall(PetscOptionsInsertString(*o, cfg.text.c_str()));
  for (auto &name : common) {
    PetscBool has;
    PetscCall(PetscOptionsHasName(*o, NULL, name.c_str(), &has)); // marks it used
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ReadSequence(MPI_Comm comm, PetscOptions o, const ConvergenceConfig &cfg, const char *key, ConvergenceSequenceKind kind, ConvergenceSequence *seq, PetscBool *set)
{
  PetscReal v[3] = {0, 0, 0};
  PetscInt  n    = 3;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetRealArray(o, NULL, key, v, &n, set));
  if (!*set) PetscFunctionReturn(0);
  const char *where = cfg.file.empty() ? cfg.name.c_str() : cfg.file.c_str();
  PetscCheck(n == 3, comm, PETSC_ERR_ARG_WRONG, "%s %s: %s takes three numbers first,divisor,count (got %" PetscInt_FMT ")", where, key, key, n);
  PetscCheck(v[0] > 0 && std::isfinite(v[0]), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s %g,%g,%g is not allowed: the first value must be > 0", where, key, (double)v[0], (double)v[1], (double)v[2]);
  PetscCheck(kind != ConvergenceSequenceKind::StableFraction || v[0] <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s %g,...: the first step is a fraction of the stability limit, 0 < fraction <= 1", where, key, (double)v[0]);
  PetscCheck(v[1] > 1 && std::isfinite(v[1]), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s %g,%g,%g is not allowed: the divisor must be > 1", where, key, (double)v[0], (double)v[1], (double)v[2]);
  PetscCheck(v[2] >= 1 && v[2] <= 40 && v[2] == std::floor(v[2]), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s %g,%g,%g is not allowed: the count must be a whole number in [1, 40]", where, key, (double)v[0], (double)v[1],
             (double)v[2]);
  seq->kind    = kind;
  seq->first   = v[0];
  seq->divisor = v[1];
  seq->count   = (PetscInt)v[2];
  PetscFunctionReturn(0);
}

// Explicit stability limit (s) of a configuration: Stormer-Verlet 2/omega_max, or
// y*/omega_max of the rk tableau selected by the run's options (as ImpactRun computes it).
PetscErrorCode StableStep(const ConvergenceConfig &cfg, const Scenario &sc, PetscReal *dt)
{
  PetscFunctionBeginUser;
  BeamSystem  sys;
  std::string why;
  PetscCheck(BeamSystemBuild(sc.beam, &sys, &why), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  const PetscReal lf = LeapfrogStableStep(sys, BeamSystemCoupling(sys, sc.impact.x), sc.ball); // 2 / omega_max
  if (cfg.method == "leapfrog") {
    *dt = lf;
    PetscFunctionReturn(0);
  }
  char      type[64] = "", rktype[64] = "";
  PetscBool set_type, set_rk;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-ts_type", type, sizeof(type), &set_type));
  PetscCheck(set_type && std::string(type) == TSRK, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "configuration %s: -convergence_dt_stable needs -ts_type rk (or -convergence_method leapfrog); it has -ts_type %s", cfg.name.c_str(),
             set_type ? type : "(none)");
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
  PetscCheck(ystar > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "configuration %s: -ts_rk_type %s is unstable for undamped oscillation at any step", cfg.name.c_str(), set_rk ? rktype : "(default)");
  *dt = ystar * lf / 2 * (1 - 1e-12);
  PetscFunctionReturn(0);
}

// One run of one level in the (pushed) database of the configuration.
PetscErrorCode RunInPushedOptions(MPI_Comm comm, const ConvergenceConfig &cfg, const Scenario &sc_in, ImpactResult *res)
{
  PetscFunctionBeginUser;
  Scenario sc                    = sc_in;
  sc.impact.check_unused_options = PETSC_TRUE;
  sc.impact.strict_solver_options = PETSC_TRUE; // a configuration runs as written: a misspelt -ts_ option fails its runs
  sc.monitor                     = MonitorRequest(); // no time series
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

std::string Format(const char *fmt, double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), fmt, v);
  return buf;
}

// One run of one level: a fresh database with the configuration and this level's
// step or tolerance, pushed for the run, popped and destroyed after it (even on
// failure). Sets run->level, dt, rtol, atol; the outcome goes to *res and the run's
// error code (0 on success) to *run_err, with run->failed and run->message on failure.
PetscErrorCode RunLevelOnce(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceConfig &cfg, PetscInt level, const Scenario &sc, ConvergenceRun *run, ImpactResult *res, PetscErrorCode *run_err)
{
  PetscOptions o;

  PetscFunctionBeginUser;
  run->level = level;
  PetscCall(ConfigOptionsCreate(comm, cfg, plan.common_file, &o));
  for (const char *k : ConfigKeys) PetscCall(PetscOptionsClearValue(o, k));
  const PetscReal v     = cfg.seq.value(level);
  const char     *dtkey = cfg.method == "leapfrog" ? "-leapfrog_dt" : "-ts_dt";
  PetscCall(PetscOptionsPush(o));
  PetscErrorCode ierr = 0;
  switch (cfg.seq.kind) {
  case ConvergenceSequenceKind::Step: run->dt = v; break;
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
      ierr = PetscOptionsSetValue(o, "-ts_rtol", Format("%.17g", run->rtol).c_str());
      if (!ierr) ierr = PetscOptionsSetValue(o, "-ts_atol", Format("%.17g", run->atol).c_str());
    } else ierr = PetscOptionsSetValue(o, dtkey, Format("%.17g", run->dt).c_str());
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

void MeasureAgainst(const ConvergenceReference &ref, ConvergenceRun *run)
{
  const ImpactResult &r = run->result, &R = ref.result;
  if (run->failed) {
    run->acor_error = run->contact_time_error = run->peak_force_error = run->max_compression_error = run->energy_error = NaN;
    return;
  }
  run->acor_error            = std::abs(r.acor - R.acor);
  run->contact_time_error    = std::abs(r.contact_time - R.contact_time) / R.contact_time;
  run->peak_force_error      = std::abs(r.peak_force - R.peak_force) / R.peak_force;
  run->max_compression_error = std::abs(r.max_compression - R.max_compression) / R.max_compression;
  run->energy_error          = std::abs(r.energy_error);
}

PetscErrorCode PrintRun(MPI_Comm comm, const ConvergenceConfig &cfg, const ConvergenceRun &run)
{
  PetscFunctionBeginUser;
  const std::string what = cfg.seq.kind == ConvergenceSequenceKind::Tolerance ? Format("rtol %.2e", run.rtol) : Format("dt %.3e", run.dt);
  if (run.failed) {
    PetscCall(PetscPrintf(comm, "  %-14s L%-2" PetscInt_FMT " %-14s FAILED: %s\n", cfg.name.c_str(), run.level, what.c_str(), run.message.c_str()));
    PetscFunctionReturn(0);
  }
  const ImpactResult &r = run.result;
  PetscCall(PetscPrintf(comm,
                        "  %-14s L%-2" PetscInt_FMT " %-14s acor_err %.2e  tc_err %.2e  pf_err %.2e  E_err %.2e  wall %.3e s  steps %" PetscInt_FMT " (+%" PetscInt_FMT " ev, %" PetscInt_FMT
                        " rej)  fevals %" PetscInt_FMT "  jac %" PetscInt_FMT "/%" PetscInt_FMT "  lin %" PetscInt_FMT "\n",
                        cfg.name.c_str(), run.level, what.c_str(), (double)run.acor_error, (double)run.contact_time_error, (double)run.peak_force_error, (double)run.energy_error, (double)r.wall_time, r.steps,
                        r.event_steps, r.rejected_steps, r.function_evals, r.jacobian_evals, r.jacobian_assemblies, r.linear_its));
  PetscFunctionReturn(0);
}

std::string OrderText(const ConvergenceOrder &o)
{
  std::string s;
  for (size_t k = 1; k < o.pairwise.size(); ++k) s += std::isfinite(o.pairwise[k]) ? Format(" %.2f", o.pairwise[k]) : std::string(" -");
  return s;
}

} // namespace

const char *ConvergenceSequenceName(ConvergenceSequenceKind k) { return SequenceNames[static_cast<int>(k)]; }

PetscReal ConvergenceSequence::value(PetscInt level) const { return first / std::pow(divisor, (PetscReal)level); }

ConvergenceOrder ConvergenceOrderOf(const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs, PetscReal floor, PetscReal ConvergenceRun::*err)
{
  std::vector<PetscReal> h, e;
  for (auto &r : runs) {
    h.push_back(r.failed ? NaN : ConvergenceStepOf(cfg, r));
    e.push_back(r.*err);
  }
  return ConvergenceObservedOrder(h, e, floor);
}

PetscReal ConvergenceStepOf(const ConvergenceConfig &cfg, const ConvergenceRun &run)
{
  return cfg.seq.kind == ConvergenceSequenceKind::Tolerance ? run.mean_step : run.dt;
}

ConvergenceOrder ConvergenceObservedOrder(const std::vector<PetscReal> &h, const std::vector<PetscReal> &e, PetscReal floor)
{
  ConvergenceOrder o;
  const size_t     n  = std::min(h.size(), e.size());
  auto             ok = [&](size_t k) { return std::isfinite(h[k]) && h[k] > 0 && std::isfinite(e[k]) && e[k] > floor; };
  o.pairwise.assign(n, NaN);
  for (size_t k = 1; k < n; ++k)
    if (ok(k) && ok(k - 1) && h[k] != h[k - 1]) o.pairwise[k] = std::log(e[k - 1] / e[k]) / std::log(h[k - 1] / h[k]);
  PetscReal sx = 0, sy = 0, sxx = 0, sxy = 0;
  PetscInt  m  = 0;
  for (size_t k = 0; k < n; ++k) {
    if (!ok(k)) continue;
    const PetscReal x = std::log(h[k]), y = std::log(e[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    m++;
  }
  o.used = m;
  const PetscReal den = m * sxx - sx * sx;
  o.lsq               = m >= 2 && den > 0 ? (m * sxy - sx * sy) / den : NaN;
  return o;
}

bool ConvergenceRichardson(PetscReal A1, PetscReal A2, PetscReal A3, PetscReal r, PetscReal *p, PetscReal *A0)
{
  const PetscReal d12 = A1 - A2, d23 = A2 - A3;
  *p  = NaN;
  *A0 = A3;
  if (!(r > 1) || d23 == 0 || d12 == 0 || !std::isfinite(d12) || !std::isfinite(d23)) return d23 == 0 && std::isfinite(A3);
  const PetscReal q = d12 / d23;
  if (!(q > 1)) return false; // differences must shrink, with one sign
  *p  = std::log(q) / std::log(r);
  *A0 = A3 - d23 / (std::pow(r, *p) - 1);
  return true;
}

PetscErrorCode ConvergenceConfigLoad(MPI_Comm comm, const std::string &file, const std::string &text, ConvergenceConfig *cfg)
{
  PetscOptions o;
  char         buf[PETSC_MAX_PATH_LEN];
  PetscBool    set;

  PetscFunctionBeginUser;
  *cfg      = ConvergenceConfig();
  cfg->file = file;
  cfg->text = text;
  cfg->name = file.empty() ? "config" : BaseName(file);
  if (!file.empty()) {
    std::ifstream in(file);
    PetscCheck(in.good(), comm, PETSC_ERR_FILE_OPEN, "cannot read the configuration file %s (a path on the command line is relative to the working directory, one in an options file to that file's directory)", file.c_str());
    cfg->description = FileDescription(file);
  }
  PetscCall(ConfigOptionsCreate(comm, *cfg, "", &o));
  const char *where = file.empty() ? "configuration" : file.c_str();
  PetscCall(PetscOptionsGetString(o, NULL, "-convergence_name", buf, sizeof(buf), &set));
  if (set) cfg->name = buf;
  PetscCall(PetscOptionsGetString(o, NULL, "-convergence_method", buf, sizeof(buf), &set));
  if (set) cfg->method = buf;
  PetscCheck(cfg->method == "ts" || cfg->method == "leapfrog", comm, PETSC_ERR_ARG_WRONG, "%s: -convergence_method %s is not allowed: use ts (a PETSc TS configuration) or leapfrog (the Stormer-Verlet baseline)", where,
             cfg->method.c_str());
  PetscCall(PetscOptionsGetReal(o, NULL, "-convergence_order", &cfg->expected_order, NULL));
  PetscCall(PetscOptionsGetReal(o, NULL, "-convergence_atol_factor", &cfg->atol_factor, NULL));
  PetscCheck(cfg->atol_factor > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: -convergence_atol_factor %g is not allowed: it must be > 0", where, (double)cfg->atol_factor);
  PetscBool s_dt, s_st, s_tol;
  PetscCall(ReadSequence(comm, o, *cfg, "-convergence_dt", ConvergenceSequenceKind::Step, &cfg->seq, &s_dt));
  PetscCall(ReadSequence(comm, o, *cfg, "-convergence_dt_stable", ConvergenceSequenceKind::StableFraction, &cfg->seq, &s_st));
  PetscCall(ReadSequence(comm, o, *cfg, "-convergence_tol", ConvergenceSequenceKind::Tolerance, &cfg->seq, &s_tol));
  PetscCheck((int)s_dt + (int)s_st + (int)s_tol == 1, comm, PETSC_ERR_ARG_WRONG,
             "%s: a configuration needs exactly one sequence: -convergence_dt first,divisor,count (fixed steps, s), -convergence_dt_stable first,divisor,count (fractions of the explicit stability limit) or "
             "-convergence_tol first,divisor,count (adaptive rtol); it has %d",
             where, (int)s_dt + (int)s_st + (int)s_tol);
  PetscCheck(!(cfg->method == "leapfrog" && s_tol), comm, PETSC_ERR_ARG_WRONG, "%s: the leapfrog baseline has a fixed step: use -convergence_dt or -convergence_dt_stable, not -convergence_tol", where);
  {
    PetscBool has_ts_dt, has_tol;
    PetscCall(PetscOptionsHasName(o, NULL, "-ts_dt", &has_ts_dt));
    PetscCall(PetscOptionsHasName(o, NULL, "-ts_rtol", &has_tol));
    PetscCheck(!has_ts_dt || s_tol, comm, PETSC_ERR_ARG_WRONG, "%s: -ts_dt is set by the sequence (-convergence_dt); do not give it in the file", where);
    PetscCheck(!has_tol, comm, PETSC_ERR_ARG_WRONG, "%s: -ts_rtol and -ts_atol are set by the sequence (-convergence_tol); do not give them in the file", where);
  }
  for (const char *k : ConfigKeys) PetscCall(PetscOptionsClearValue(o, k));
  {
    char *all;
    PetscCall(PetscOptionsGetAll(o, &all));
    cfg->options = Trim(all);
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscOptionsDestroy(&o));
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergencePlanFromOptions(MPI_Comm comm, const BallParams &ball, ConvergencePlan *plan)
{
  std::vector<char> configs(1 << 16, 0), spatial(4096, 0);
  char              common[PETSC_MAX_PATH_LEN] = "";
  char              reffile[PETSC_MAX_PATH_LEN];
  PetscEnum         refkind = (PetscEnum)(ContactLinear(ball) ? ConvergenceReferenceKind::Modal : ConvergenceReferenceKind::Run);
  PetscBool         set_configs = PETSC_FALSE, set_spatial = PETSC_FALSE, set_common = PETSC_FALSE;

  PetscFunctionBeginUser;
  std::snprintf(reffile, sizeof(reffile), "%s", plan->reference_file.c_str());
  PetscOptionsBegin(comm, NULL, "Convergence study: integrators against the exact reference (-task convergence)", "beamimpact");
  PetscCall(PetscOptionsString("-convergence_configs", "Integrator configurations: options files a.opts,b.opts,... (each with its sequence, see docs/convergence.md)", "", configs.data(), configs.data(), configs.size(),
                               &set_configs));
  PetscCall(PetscOptionsInt("-convergence_repeats", "Runs per level; the wall time is the minimum", "", plan->repeats, &plan->repeats, NULL));
  PetscCall(PetscOptionsReal("-convergence_repeat_budget", "Seconds: a level is not repeated once its runs took this long (long runs time well once)", "", plan->repeat_budget, &plan->repeat_budget, NULL));
  PetscCall(PetscOptionsEnum("-convergence_reference", "Reference: modal (exact, linear spring) or run (-convergence_reference_config, Richardson-estimated)", "", ReferenceNames, refkind, &refkind, NULL));
  PetscCall(PetscOptionsString("-convergence_reference_config", "Configuration of the reference run (finest level = reference; error from the last three)", "", reffile, reffile, sizeof(reffile), NULL));
  PetscCall(PetscOptionsString("-convergence_spatial_nodes", "Spatial study: N1,N2,... (h halving: 41,81,161,321,641)", "", spatial.data(), spatial.data(), spatial.size(), &set_spatial));
  PetscCall(PetscOptionsReal("-convergence_target", "ACOR error at which the cost of each configuration is compared (the targets)", "", plan->target, &plan->target, NULL));
  PetscCall(PetscOptionsReal("-convergence_error_floor", "Errors at or below this are round-off and left out of order fits", "", plan->error_floor, &plan->error_floor, NULL));
  PetscCall(PetscOptionsString("-convergence_common_options", "Options file inserted into every run before the configuration's own (not checked for use)", "", common, common, sizeof(common), &set_common));
  PetscCall(PetscOptionsBool("-convergence_quiet", "Print only the tables, not every run", "", plan->quiet, &plan->quiet, NULL));
  PetscOptionsEnd();
  plan->reference      = (ConvergenceReferenceKind)refkind;
  plan->reference_file = reffile;
  if (set_common) {
    plan->common_file = common;
    std::ifstream in(plan->common_file);
    PetscCheck(in.good(), comm, PETSC_ERR_FILE_OPEN, "-convergence_common_options %s: cannot read this options file", common);
  }
  PetscCheck(plan->repeats >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-convergence_repeats %" PetscInt_FMT " is not allowed: at least 1", plan->repeats);
  PetscCheck(plan->repeat_budget >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-convergence_repeat_budget %g is not allowed: it must be >= 0 (s)", (double)plan->repeat_budget);
  PetscCheck(plan->target > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-convergence_target %g is not allowed: it must be > 0", (double)plan->target);
  PetscCheck(plan->error_floor >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-convergence_error_floor %g is not allowed: it must be >= 0", (double)plan->error_floor);
  PetscCheck(!(plan->reference == ConvergenceReferenceKind::Modal && !ContactLinear(ball)), comm, PETSC_ERR_ARG_INCOMP,
             "-convergence_reference modal needs the linear spring (-ball_law linear): the %s ball is nonlinear; use -convergence_reference run", ContactLawName(ball.law));
  plan->configs.clear();
  if (set_configs)
    for (const std::string &f : SplitList(configs.data())) {
      ConvergenceConfig cfg;
      PetscCall(ConvergenceConfigLoad(comm, f, "", &cfg));
      for (auto &c : plan->configs) PetscCheck(c.name != cfg.name, comm, PETSC_ERR_ARG_WRONG, "-convergence_configs: two configurations are named %s: give one a -convergence_name", cfg.name.c_str());
      plan->configs.push_back(cfg);
    }
  plan->spatial_nodes.clear();
  if (set_spatial)
    for (const std::string &s : SplitList(spatial.data())) {
      char      *end;
      const long n = std::strtol(s.c_str(), &end, 10);
      PetscCheck(*end == '\0' && n >= 5 && n <= 100000, comm, PETSC_ERR_ARG_OUTOFRANGE, "-convergence_spatial_nodes: '%s' is not allowed: node counts are whole numbers >= 5", s.c_str());
      PetscCheck(plan->spatial_nodes.empty() || n > plan->spatial_nodes.back(), comm, PETSC_ERR_ARG_WRONG, "-convergence_spatial_nodes must increase (got %ld after %" PetscInt_FMT ")", n, plan->spatial_nodes.back());
      plan->spatial_nodes.push_back((PetscInt)n);
    }
  PetscCheck(!plan->configs.empty() || !plan->spatial_nodes.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task convergence needs -convergence_configs a.opts,b.opts,... (integrator configurations, e.g. options/convergence/*.opts) and/or -convergence_spatial_nodes N1,N2,...");
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceReferenceCompute(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &sc, ConvergenceReference *ref)
{
  PetscFunctionBeginUser;
  *ref              = ConvergenceReference();
  const double wall = MPI_Wtime();
  if (plan.reference == ConvergenceReferenceKind::Modal) {
    PetscCall(ModalReferenceRun(sc, &ref->result));
    ref->method = "modal";
  } else {
    ConvergenceConfig cfg;
    PetscCall(ConvergenceConfigLoad(comm, plan.reference_file, "", &cfg));
    ConvergencePlan p = plan;
    p.repeats         = 1;
    std::vector<PetscReal> acor, tc, pf;
    for (PetscInt k = 0; k < cfg.seq.count; ++k) {
      ConvergenceRun run;
      PetscErrorCode err;
      PetscCall(RunLevelOnce(comm, p, cfg, k, sc, &run, &run.result, &err));
      PetscCheck(!err, comm, PETSC_ERR_NOT_CONVERGED, "the reference configuration %s failed at level %" PetscInt_FMT ": %s", plan.reference_file.c_str(), k, run.message.c_str());
      acor.push_back(run.result.acor);
      tc.push_back(run.result.contact_time);
      pf.push_back(run.result.peak_force);
      ref->result = run.result;
    }
    ref->method = cfg.name;
    // Richardson from the last three levels (ratio: the sequence's divisor).
    const size_t n   = acor.size();
    auto         est = [&](const std::vector<PetscReal> &A, bool relative, PetscReal *p) -> PetscReal {
      *p = NaN;
      if (n < 2) return NaN;
      const PetscReal scale = relative ? std::abs(A[n - 1]) : 1.0;
      if (n < 3) return std::abs(A[n - 1] - A[n - 2]) / scale;
      PetscReal A0;
      if (ConvergenceRichardson(A[n - 3], A[n - 2], A[n - 1], cfg.seq.divisor, p, &A0)) return std::abs(A[n - 1] - A0) / scale;
      return std::abs(A[n - 1] - A[n - 2]) / scale; // not asymptotic: the last difference
    };
    PetscReal p_tc, p_pf;
    ref->acor_error         = est(acor, false, &ref->observed_order);
    ref->contact_time_error = est(tc, true, &p_tc);
    ref->peak_force_error   = est(pf, true, &p_pf);
  }
  ref->wall_time = MPI_Wtime() - wall;
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceRunConfigs(MPI_Comm comm, const ConvergencePlan &plan, const std::vector<ConvergenceConfig> &cfgs, const Scenario &sc, const ConvergenceReference &ref,
                                     std::vector<std::vector<ConvergenceRun>> *all)
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
      MeasureAgainst(ref, &run);
      if (!plan.quiet) PetscCall(PrintRun(comm, cfgs[c], run));
    }
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceRunConfig(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceConfig &cfg, const Scenario &sc, const ConvergenceReference &ref, std::vector<ConvergenceRun> *runs)
{
  std::vector<std::vector<ConvergenceRun>> all;

  PetscFunctionBeginUser;
  PetscCall(ConvergenceRunConfigs(comm, plan, {cfg}, sc, ref, &all));
  *runs = all[0];
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceSpatialStudy(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &base, ConvergenceSpatial *sp)
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
    if (!plan.quiet)
      PetscCall(PetscPrintf(comm, "  N %5" PetscInt_FMT "  h %.4e m  acor %.12f  contact_time %.10e s  peak_force %.8e N  (%s, %.2f s)\n", N, (double)sp->h.back(), (double)ref.result.acor, (double)ref.result.contact_time,
                            (double)ref.result.peak_force, ref.method.c_str(), (double)ref.wall_time));
  }
  const size_t n = sp->nodes.size();
  auto         triples = [&](const std::vector<PetscReal> &A, std::vector<PetscReal> *order, PetscReal *limit, PetscReal *lsq) {
    order->assign(n, NaN);
    *limit = n ? A[n - 1] : NaN;
    for (size_t k = 2; k < n; ++k) {
      const PetscReal r1 = sp->h[k - 2] / sp->h[k - 1], r2 = sp->h[k - 1] / sp->h[k];
      PetscReal       p, A0;
      if (std::abs(r1 - r2) > 1e-9 * r2) continue; // Richardson needs a constant ratio
      if (ConvergenceRichardson(A[k - 2], A[k - 1], A[k], r2, &p, &A0)) {
        (*order)[k] = p;
        if (k == n - 1) *limit = A0;
      }
    }
    std::vector<PetscReal> e(n);
    for (size_t k = 0; k < n; ++k) e[k] = std::abs(A[k] - *limit);
    std::vector<PetscReal> h = sp->h;
    if (n) h.pop_back(), e.pop_back(); // the last level defines the limit with the extrapolation
    *lsq = ConvergenceObservedOrder(h, e, 0).lsq;
  };
  triples(sp->acor, &sp->acor_order, &sp->acor_limit, &sp->acor_order_lsq);
  triples(sp->contact_time, &sp->contact_time_order, &sp->contact_time_limit, &sp->contact_time_order_lsq);
  triples(sp->peak_force, &sp->peak_force_order, &sp->peak_force_limit, &sp->peak_force_order_lsq);
  PetscFunctionReturn(0);
}

namespace {

// ---------------------------------------------------------------------------
// The HDF5 file
// ---------------------------------------------------------------------------

// /reference: the reference's outcome and its estimated error (attributes).
PetscErrorCode WriteReference(hid_t file, const ConvergenceReference &ref)
{
  RunRecord           r;
  const ImpactResult &R = ref.result;

  PetscFunctionBeginUser;
  r.add("method", ref.method);
  for (const char *name : {"acor", "acor_corrected", "contact_time", "peak_force", "max_compression", "contacts", "final_time", "energy_error"})
    for (const ResultColumn &c : ImpactResultColumns()) // the outcome as the result table has it
      if (std::strcmp(c.name, name) == 0) r.add(name, c.get(R));
  r.add("acor_error_estimate", ref.acor_error);
  r.add("contact_time_error_estimate", ref.contact_time_error);
  r.add("peak_force_error_estimate", ref.peak_force_error);
  r.add("observed_order", ref.observed_order);
  r.add("wall_time", ref.wall_time);
  hid_t g = H5Gcreate2(file, "reference", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCall(H5WriteAttributes(g, r));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// One column per quantity of a configuration's runs, one row per level.
PetscErrorCode WriteConfigRuns(hid_t g, const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs)
{
  auto col = [&](const char *name, const char *unit, auto get) -> PetscErrorCode {
    std::vector<double> v;
    PetscFunctionBeginUser;
    for (auto &r : runs) v.push_back((double)get(r));
    PetscCall(H5WriteDataset1D(g, name, v, unit));
    PetscFunctionReturn(0);
  };
  auto icol = [&](const char *name, const char *unit, auto get) -> PetscErrorCode { // a count: an integer dataset
    std::vector<long long> v;
    PetscFunctionBeginUser;
    for (auto &r : runs) v.push_back((long long)get(r));
    PetscCall(H5WriteDatasetInt1D(g, name, v, unit));
    PetscFunctionReturn(0);
  };

  PetscFunctionBeginUser;
  PetscCall(icol("level", "", [](const ConvergenceRun &r) { return (double)r.level; }));
  PetscCall(col("dt", "s (tol runs: initial step)", [](const ConvergenceRun &r) { return r.dt; }));
  PetscCall(col("rtol", "", [](const ConvergenceRun &r) { return r.rtol; }));
  PetscCall(col("atol", "", [](const ConvergenceRun &r) { return r.atol; }));
  PetscCall(col("mean_step", "s", [](const ConvergenceRun &r) { return r.mean_step; }));
  PetscCall(col("step", "s (dt, or mean_step for tol runs)", [&](const ConvergenceRun &r) { return r.failed ? NaN : ConvergenceStepOf(cfg, r); }));
  PetscCall(icol("failed", "", [](const ConvergenceRun &r) { return r.failed ? 1 : 0; }));
  PetscCall(col("acor", "", [](const ConvergenceRun &r) { return r.failed ? NaN : r.result.acor; }));
  PetscCall(col("acor_error", "absolute", [](const ConvergenceRun &r) { return r.acor_error; }));
  PetscCall(col("contact_time_error", "relative", [](const ConvergenceRun &r) { return r.contact_time_error; }));
  PetscCall(col("peak_force_error", "relative", [](const ConvergenceRun &r) { return r.peak_force_error; }));
  PetscCall(col("max_compression_error", "relative", [](const ConvergenceRun &r) { return r.max_compression_error; }));
  PetscCall(col("energy_error", "|E_end - E_0| / E_0", [](const ConvergenceRun &r) { return r.energy_error; }));
  PetscCall(icol("contacts", "", [](const ConvergenceRun &r) { return (double)r.result.contacts; }));
  PetscCall(col("wall_time", "s, minimum of the repeats", [](const ConvergenceRun &r) { return r.failed ? NaN : r.result.wall_time; }));
  PetscCall(col("wall_time_max", "s, maximum of the repeats", [](const ConvergenceRun &r) { return r.failed ? NaN : r.wall_time_max; }));
  PetscCall(icol("steps", "", [](const ConvergenceRun &r) { return (double)r.result.steps; }));
  PetscCall(icol("rejected_steps", "", [](const ConvergenceRun &r) { return (double)r.result.rejected_steps; }));
  PetscCall(icol("event_steps", "", [](const ConvergenceRun &r) { return (double)r.result.event_steps; }));
  PetscCall(icol("function_evals", "", [](const ConvergenceRun &r) { return (double)r.result.function_evals; }));
  PetscCall(icol("jacobian_evals", "", [](const ConvergenceRun &r) { return (double)r.result.jacobian_evals; }));
  PetscCall(icol("jacobian_assemblies", "", [](const ConvergenceRun &r) { return (double)r.result.jacobian_assemblies; }));
  PetscCall(icol("nonlinear_its", "", [](const ConvergenceRun &r) { return (double)r.result.nonlinear_its; }));
  PetscCall(icol("linear_its", "linear solves (preonly LU: one per solve)", [](const ConvergenceRun &r) { return (double)r.result.linear_its; }));
  PetscFunctionReturn(0);
}

// /configs/<name>: the configuration (attributes), its runs and its observed orders.
PetscErrorCode WriteConfig(hid_t gc, size_t index, const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs, PetscReal error_floor)
{
  RunRecord a;

  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(gc, cfg.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create group /configs/%s", cfg.name.c_str());
  a.add("index", index);
  a.add("file", cfg.file);
  a.add("description", cfg.description);
  a.add("method", cfg.method);
  a.add("options", cfg.options);
  a.add("sequence", ConvergenceSequenceName(cfg.seq.kind));
  a.add("sequence_first", cfg.seq.first);
  a.add("sequence_divisor", cfg.seq.divisor);
  a.add("sequence_count", cfg.seq.count);
  a.add("expected_order", cfg.expected_order);
  a.add("atol_factor", cfg.atol_factor);
  const ConvergenceOrder oa = ConvergenceOrderOf(cfg, runs, error_floor, &ConvergenceRun::acor_error);
  const ConvergenceOrder ot = ConvergenceOrderOf(cfg, runs, error_floor, &ConvergenceRun::contact_time_error);
  const ConvergenceOrder op = ConvergenceOrderOf(cfg, runs, error_floor, &ConvergenceRun::peak_force_error);
  a.add("order_acor_lsq", oa.lsq);
  a.add("order_contact_time_lsq", ot.lsq);
  a.add("order_peak_force_lsq", op.lsq);
  PetscCall(H5WriteAttributes(g, a));
  PetscCall(WriteConfigRuns(g, cfg, runs));
  PetscCall(H5WriteDataset1D(g, "order_acor_pairwise", oa.pairwise, "between level k-1 and k"));
  PetscCall(H5WriteDataset1D(g, "order_contact_time_pairwise", ot.pairwise, "between level k-1 and k"));
  PetscCall(H5WriteDataset1D(g, "order_peak_force_pairwise", op.pairwise, "between level k-1 and k"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// /spatial: the reference at each N, the Richardson orders and the continuum limit.
PetscErrorCode WriteSpatial(hid_t file, const ConvergencePlan &plan, const ConvergenceSpatial &sp)
{
  RunRecord a;

  PetscFunctionBeginUser;
  hid_t                  g = H5Gcreate2(file, "spatial", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<long long> nodes(sp.nodes.begin(), sp.nodes.end());
  PetscCall(H5WriteDatasetInt1D(g, "nodes", nodes, ""));
  PetscCall(H5WriteDataset1D(g, "h", sp.h, "m"));
  PetscCall(H5WriteDataset1D(g, "acor", sp.acor, ""));
  PetscCall(H5WriteDataset1D(g, "contact_time", sp.contact_time, "s"));
  PetscCall(H5WriteDataset1D(g, "peak_force", sp.peak_force, "N"));
  PetscCall(H5WriteDataset1D(g, "acor_order", sp.acor_order, "Richardson, from the three levels ending here"));
  PetscCall(H5WriteDataset1D(g, "contact_time_order", sp.contact_time_order, "Richardson, from the three levels ending here"));
  PetscCall(H5WriteDataset1D(g, "peak_force_order", sp.peak_force_order, "Richardson, from the three levels ending here"));
  a.add("acor_limit", sp.acor_limit);
  a.add("contact_time_limit", sp.contact_time_limit);
  a.add("peak_force_limit", sp.peak_force_limit);
  a.add("acor_order_lsq", sp.acor_order_lsq);
  a.add("contact_time_order_lsq", sp.contact_time_order_lsq);
  a.add("peak_force_order_lsq", sp.peak_force_order_lsq);
  a.add("reference", plan.reference == ConvergenceReferenceKind::Modal ? std::string("modal") : plan.reference_file);
  PetscCall(H5WriteAttributes(g, a));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode WriteConvergenceFile(MPI_Comm comm, const std::string &path, const RunRecord &record, const ConvergencePlan &plan, const ConvergenceReference *ref, const std::vector<std::vector<ConvergenceRun>> &all,
                                    const RunRecord &summary, const ConvergenceSpatial *sp)
{
  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileWrite(comm, path, record, [&](long long file) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (ref) PetscCall(WriteReference(file, *ref));
    if (!plan.configs.empty()) {
      hid_t gc = H5Gcreate2(file, "configs", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      for (size_t c = 0; c < plan.configs.size(); ++c) PetscCall(WriteConfig(gc, c, plan.configs[c], all[c], plan.error_floor));
      H5Gclose(gc);
      hid_t gs = H5Gcreate2(file, "summary", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      PetscCall(H5WriteAttributes(gs, summary));
      H5Gclose(gs);
    }
    if (sp && !sp->nodes.empty()) PetscCall(WriteSpatial(file, plan, *sp));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// The task
// ---------------------------------------------------------------------------

// The scenario and the plan. The integrators come from the configuration files only.
PetscErrorCode ConvergenceReadOptions(MPI_Comm comm, Scenario *sc, ConvergencePlan *plan)
{
  ScenarioReading how;
  PetscBool       has;

  PetscFunctionBeginUser;
  how.monitors = false; // the runs record no time series: -monitor_* is reported unused
  PetscCall(ScenarioFromOptions(comm, how, sc));
  PetscCall(ConvergencePlanFromOptions(comm, sc->ball, plan));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_type", &has));
  PetscCheck(!has, comm, PETSC_ERR_ARG_WRONG,
             "-ts_type is not used by -task convergence: the integrators come from the -convergence_configs files; options common to every run go in a file given with -convergence_common_options FILE "
             "(a scene file that sets an integrator, such as options/base/default-scene.opts, cannot be used here)");
  PetscCall(OptionsCheckUnused(comm));
  PetscFunctionReturn(0);
}

// The file's root attributes: the scenario, its effective times and the plan.
PetscErrorCode ConvergenceRecordBuild(const Scenario &sc, const ConvergencePlan &plan, RunRecord *record)
{
  std::string names;

  PetscFunctionBeginUser;
  PetscCall(RunRecordBuild(sc, nullptr, record));
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);
  record->add("task", "convergence");
  record->add("impact_window_effective", times.window); // = impact_window (kept for older readers)
  record->add("impact_max_time_effective", times.max_time);
  record->add("convergence_reference", plan.reference == ConvergenceReferenceKind::Modal ? std::string("modal") : plan.reference_file);
  record->add("convergence_repeats", plan.repeats);
  record->add("convergence_repeat_budget", plan.repeat_budget);
  record->add("convergence_target", plan.target);
  record->add("convergence_error_floor", plan.error_floor);
  record->add("convergence_common_options", plan.common_file);
  for (auto &c : plan.configs) names += (names.empty() ? "" : ",") + c.name;
  record->add("configs", names);
  PetscFunctionReturn(0);
}

PetscErrorCode PrintReference(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceReference &ref)
{
  const ImpactResult &R = ref.result;

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "reference (%s, %.3f s): acor %.14f  contact_time %.12e s  peak_force %.10e N  contacts %" PetscInt_FMT "  final_time %.6e s  energy_error %.1e\n", ref.method.c_str(), (double)ref.wall_time,
                        (double)R.acor, (double)R.contact_time, (double)R.peak_force, R.contacts, (double)R.final_time, (double)R.energy_error));
  if (plan.reference == ConvergenceReferenceKind::Run)
    PetscCall(PetscPrintf(comm, "  its own error (Richardson over its last three levels, observed order %.2f): acor %.1e, contact_time %.1e (rel), peak_force %.1e (rel)\n", (double)ref.observed_order, (double)ref.acor_error,
                          (double)ref.contact_time_error, (double)ref.peak_force_error));
  PetscFunctionReturn(0);
}

PetscErrorCode PrintOrders(MPI_Comm comm, const ConvergencePlan &plan, const std::vector<std::vector<ConvergenceRun>> &all)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "\nobserved orders (against the step; tol runs: the mean step), errors > %g:\n  %-14s %-8s %-26s %-10s %-10s %-10s\n", (double)plan.error_floor, "config", "expected", "acor pairwise", "acor lsq",
                        "t_c lsq", "F_max lsq"));
  for (size_t c = 0; c < plan.configs.size(); ++c) {
    const auto &cfg = plan.configs[c];
    const auto  oa  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::acor_error);
    const auto  ot  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::contact_time_error);
    const auto  op  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::peak_force_error);
    PetscCall(PetscPrintf(comm, "  %-14s %-8s %-26s %-10.2f %-10.2f %-10.2f\n", cfg.name.c_str(), cfg.expected_order > 0 ? Format("%g", cfg.expected_order).c_str() : "-", OrderText(oa).c_str(), (double)oa.lsq,
                          (double)ot.lsq, (double)op.lsq));
  }
  PetscFunctionReturn(0);
}

// The fastest level of one configuration that reaches the target (-1: none).
PetscInt FastestAtTarget(const std::vector<ConvergenceRun> &runs, PetscReal target, PetscReal *t)
{
  PetscInt lv = -1;
  *t          = 0;
  for (auto &r : runs)
    if (!r.failed && r.acor_error <= target && (lv < 0 || r.result.wall_time < *t)) {
      lv = r.level;
      *t = r.result.wall_time;
    }
  return lv;
}

// The smallest ACOR error of a configuration's runs (NaN when all failed).
PetscReal SmallestError(const std::vector<ConvergenceRun> &runs)
{
  PetscReal m = NaN;
  for (auto &r : runs)
    if (!r.failed && !(r.acor_error >= m)) m = r.acor_error;
  return m;
}

// The cost of each configuration at -convergence_target, the best PETSc configuration
// against the leapfrog baseline; the same numbers go to *summary for the file.
PetscErrorCode PrintCostAtTarget(MPI_Comm comm, const ConvergencePlan &plan, const std::vector<std::vector<ConvergenceRun>> &all, RunRecord *summary)
{
  PetscInt  best = -1, base = -1;
  PetscReal best_t = 0, base_t = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "\ncost at ACOR error <= %g (fastest level that reaches it; wall time = minimum of up to %" PetscInt_FMT " runs, time stepping only):\n", (double)plan.target, plan.repeats));
  for (size_t c = 0; c < plan.configs.size(); ++c) {
    const auto &cfg = plan.configs[c];
    PetscReal   t;
    PetscInt    lv = FastestAtTarget(all[c], plan.target, &t);
    if (lv < 0) {
      PetscCall(PetscPrintf(comm, "  %-14s does not reach it (smallest error %.2e)\n", cfg.name.c_str(), (double)SmallestError(all[c])));
      continue;
    }
    const auto &r = all[c][lv];
    PetscCall(PetscPrintf(comm, "  %-14s %.3e s  level %" PetscInt_FMT "  %s  acor_err %.2e  steps %" PetscInt_FMT "\n", cfg.name.c_str(), (double)t, lv,
                          cfg.seq.kind == ConvergenceSequenceKind::Tolerance ? Format("rtol %.2e", r.rtol).c_str() : Format("dt %.3e", r.dt).c_str(), (double)r.acor_error, r.result.steps));
    summary->add("time_at_target_" + cfg.name, t);
    if (cfg.method == "leapfrog") {
      if (base < 0 || t < base_t) base = (PetscInt)c, base_t = t;
    } else if (best < 0 || t < best_t) best = (PetscInt)c, best_t = t;
  }
  summary->add("target", plan.target);
  if (best >= 0) {
    summary->add("best_config", plan.configs[best].name);
    summary->add("best_time", best_t);
  }
  if (base >= 0) {
    summary->add("baseline_config", plan.configs[base].name);
    summary->add("baseline_time", base_t);
  }
  if (best >= 0 && base >= 0) {
    summary->add("baseline_over_best", base_t / best_t);
    PetscCall(PetscPrintf(comm, "best PETSc configuration at ACOR error <= %g: %s, %.3e s; baseline %s: %.3e s; baseline/best = %.2f (best/baseline = %.2f)\n", (double)plan.target, plan.configs[best].name.c_str(), (double)best_t,
                          plan.configs[base].name.c_str(), (double)base_t, (double)(base_t / best_t), (double)(best_t / base_t)));
  }
  PetscFunctionReturn(0);
}

// The temporal study: reference, every configuration's runs, orders, cost at the target.
PetscErrorCode TemporalStudy(MPI_Comm comm, const Scenario &sc, const ConvergencePlan &plan, ConvergenceReference *ref, std::vector<std::vector<ConvergenceRun>> *all, RunRecord *summary)
{
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "convergence study: N = %" PetscInt_FMT ", x = %g m, %s law, window %g s after separation, %" PetscInt_FMT " repeat(s) per level (fewer once a level took -convergence_repeat_budget)\n", sc.beam.nodes,
                        (double)sc.impact.x, ContactLawName(sc.ball.law), (double)times.window, plan.repeats));
  PetscCall(ConvergenceReferenceCompute(comm, plan, sc, ref));
  PetscCall(PrintReference(comm, plan, *ref));
  PetscCall(ConvergenceRunConfigs(comm, plan, plan.configs, sc, *ref, all));
  PetscCall(PrintOrders(comm, plan, *all));
  PetscCall(PrintCostAtTarget(comm, plan, *all, summary));
  PetscFunctionReturn(0);
}

// The spatial study, with its continuum limit and observed orders.
PetscErrorCode SpatialStudy(MPI_Comm comm, const Scenario &sc, const ConvergencePlan &plan, ConvergenceSpatial *sp)
{
  std::string o;

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "\nspatial study (reference %s at each N):\n", plan.reference == ConvergenceReferenceKind::Modal ? "modal" : plan.reference_file.c_str()));
  PetscCall(ConvergenceSpatialStudy(comm, plan, sc, sp));
  PetscCall(PetscPrintf(comm, "  continuum limit (Richardson, last three N): acor %.10f  contact_time %.8e s  peak_force %.6e N\n", (double)sp->acor_limit, (double)sp->contact_time_limit, (double)sp->peak_force_limit));
  for (size_t k = 2; k < sp->acor_order.size(); ++k) o += Format(" %.3f", sp->acor_order[k]);
  PetscCall(PetscPrintf(comm, "  observed spatial order: acor (triples)%s; least squares: acor %.3f, contact_time %.3f, peak_force %.3f\n", o.c_str(), (double)sp->acor_order_lsq, (double)sp->contact_time_order_lsq,
                        (double)sp->peak_force_order_lsq));
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
    PetscCall(WriteConvergenceFile(comm, output, record, plan, plan.configs.empty() ? nullptr : &ref, all, summary, &sp));
    PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

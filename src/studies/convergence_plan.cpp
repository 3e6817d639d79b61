// -task convergence, the plan: options, configurations, sequences. See convergence_plan.hpp.
#include "studies/convergence_plan.hpp"

#include "io/options_files.hpp"
#include "io/text.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace beamimpact {

namespace {

const char *const SequenceNames[] = {"dt", "dt_stable", "tol"};

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
  std::ifstream            in(file);
  std::vector<std::string> lines;
  std::string              text, why;
  if (!TextLines(in, &lines, &why)) return text; // its options' reading says why
  for (const std::string &line : lines) {
    const size_t a = line.find_first_not_of(" \t");
    if (a == std::string::npos) continue;
    if (line[a] != '#') break;
    const std::string t = CommentText(line);
    if (!t.empty()) text += (text.empty() ? "" : " ") + t;
  }
  return text;
}

PetscErrorCode ReadSequence(MPI_Comm comm, PetscOptions o, const ConvergenceConfig &cfg, const char *key,
                            ConvergenceSequenceKind kind, ConvergenceSequence *seq, PetscBool *set)
{
  PetscReal v[3] = {0, 0, 0};
  PetscInt  n    = 3;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetRealArray(o, NULL, key, v, &n, set));
  if (!*set) PetscFunctionReturn(0);
  const char *where = cfg.file.empty() ? cfg.name.c_str() : cfg.file.c_str();
  PetscCheck(n == 3, comm, PETSC_ERR_ARG_WRONG,
             "%s %s: %s takes three numbers first,divisor,count (got %" PetscInt_FMT ")", where, key, key, n);
  PetscCheck(v[0] > 0 && std::isfinite(v[0]), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s %g,%g,%g is not allowed: the first value must be > 0", where, key, (double)v[0], (double)v[1],
             (double)v[2]);
  PetscCheck(kind != ConvergenceSequenceKind::StableFraction || v[0] <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s %g,...: the first step is a fraction of the stability limit, 0 < fraction <= 1", where, key,
             (double)v[0]);
  PetscCheck(v[1] > 1 && std::isfinite(v[1]), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s %g,%g,%g is not allowed: the divisor must be > 1", where, key, (double)v[0], (double)v[1],
             (double)v[2]);
  PetscCheck(v[2] >= 1 && v[2] <= 40 && v[2] == std::floor(v[2]), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %s %g,%g,%g is not allowed: the count must be a whole number in [1, 40]", where, key, (double)v[0],
             (double)v[1], (double)v[2]);
  seq->kind    = kind;
  seq->first   = v[0];
  seq->divisor = v[1];
  seq->count   = (PetscInt)v[2];
  PetscFunctionReturn(0);
}

} // namespace

const char *ConvergenceSequenceName(ConvergenceSequenceKind k) { return SequenceNames[static_cast<int>(k)]; }

PetscReal ConvergenceSequence::value(PetscInt level) const { return first / std::pow(divisor, (PetscReal)level); }

const std::vector<const char *> &ConvergenceConfigKeys()
{
  static const std::vector<const char *> keys = {"-convergence_dt",    "-convergence_dt_stable",   "-convergence_tol",
                                                 "-convergence_order", "-convergence_atol_factor", "-convergence_name",
                                                 "-convergence_method"};
  return keys;
}

std::string ConvergenceFormat(const char *fmt, double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), fmt, v);
  return buf;
}

PetscErrorCode ConvergenceConfigOptionsCreate(MPI_Comm comm, const ConvergenceConfig &cfg,
                                              const std::string &common_file, PetscOptions *o)
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

PetscErrorCode ConvergenceConfigLoad(MPI_Comm comm, const std::string &file, const std::string &text,
                                     ConvergenceConfig *cfg)
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
    PetscCheck(in.good(), comm, PETSC_ERR_FILE_OPEN,
               "cannot read the configuration file %s (a path on the command line is relative to the working "
               "directory, one in an options file to that file's directory)",
               file.c_str());
    cfg->description = FileDescription(file);
  }
  PetscCall(ConvergenceConfigOptionsCreate(comm, *cfg, "", &o));
  const char *where = file.empty() ? "configuration" : file.c_str();
  PetscCall(PetscOptionsGetString(o, NULL, "-convergence_name", buf, sizeof(buf), &set));
  if (set) cfg->name = buf;
  PetscCall(PetscOptionsGetString(o, NULL, "-convergence_method", buf, sizeof(buf), &set));
  if (set) cfg->method = buf;
  PetscCheck(cfg->method == "ts" || cfg->method == "leapfrog", comm, PETSC_ERR_ARG_WRONG,
             "%s: -convergence_method %s is not allowed: use ts (a PETSc TS configuration) or leapfrog (the "
             "Stormer-Verlet baseline)",
             where, cfg->method.c_str());
  PetscCall(PetscOptionsGetReal(o, NULL, "-convergence_order", &cfg->expected_order, NULL));
  PetscCall(PetscOptionsGetReal(o, NULL, "-convergence_atol_factor", &cfg->atol_factor, NULL));
  PetscCheck(cfg->atol_factor > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s: -convergence_atol_factor %g is not allowed: it must be > 0", where, (double)cfg->atol_factor);
  PetscBool s_dt, s_st, s_tol;
  PetscCall(ReadSequence(comm, o, *cfg, "-convergence_dt", ConvergenceSequenceKind::Step, &cfg->seq, &s_dt));
  PetscCall(
    ReadSequence(comm, o, *cfg, "-convergence_dt_stable", ConvergenceSequenceKind::StableFraction, &cfg->seq, &s_st));
  PetscCall(ReadSequence(comm, o, *cfg, "-convergence_tol", ConvergenceSequenceKind::Tolerance, &cfg->seq, &s_tol));
  PetscCheck((int)s_dt + (int)s_st + (int)s_tol == 1, comm, PETSC_ERR_ARG_WRONG,
             "%s: a configuration needs exactly one sequence: -convergence_dt first,divisor,count (fixed steps, s), "
             "-convergence_dt_stable first,divisor,count (fractions of the explicit stability limit) or "
             "-convergence_tol first,divisor,count (adaptive rtol); it has %d",
             where, (int)s_dt + (int)s_st + (int)s_tol);
  PetscCheck(!(cfg->method == "leapfrog" && s_tol), comm, PETSC_ERR_ARG_WRONG,
             "%s: the leapfrog baseline has a fixed step: use -convergence_dt or -convergence_dt_stable, not "
             "-convergence_tol",
             where);
  {
    PetscBool has_ts_dt, has_tol;
    PetscCall(PetscOptionsHasName(o, NULL, "-ts_dt", &has_ts_dt));
    PetscCall(PetscOptionsHasName(o, NULL, "-ts_rtol", &has_tol));
    PetscCheck(!has_ts_dt || s_tol, comm, PETSC_ERR_ARG_WRONG,
               "%s: -ts_dt is set by the sequence (-convergence_dt); do not give it in the file", where);
    PetscCheck(!has_tol, comm, PETSC_ERR_ARG_WRONG,
               "%s: -ts_rtol and -ts_atol are set by the sequence (-convergence_tol); do not give them in the file",
               where);
  }
  for (const char *k : ConvergenceConfigKeys()) PetscCall(PetscOptionsClearValue(o, k));
  {
    char *all;
    PetscCall(PetscOptionsGetAll(o, &all));
    cfg->options = Trim(all);
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscOptionsDestroy(&o));
  PetscFunctionReturn(0);
}

const OptionModule &ConvergenceOptionModule()
{
  static const OptionModule m = [] {
    OptionModule r{"convergence", "Convergence study: integrators against the exact reference (-task convergence)", {}};
    auto        &o = r.options;
    o.push_back(OptionText("-convergence_configs", "Integrator configurations: options files a.opts,b.opts,... (each "
                                                   "with its sequence, see docs/convergence.md)"));
    o.push_back(OptionInt("-convergence_repeats", "Runs per level; the wall time is the minimum", "3", AtLeast(1)));
    o.push_back(OptionReal("-convergence_repeat_budget", "s",
                           "A level is not repeated once its runs took this long (long runs time well once)", "2",
                           NonNegative()));
    o.push_back(OptionChoice("-convergence_reference",
                             ("The reference the runs are measured against: " + ReferenceMethodHelp(true) +
                              "; default: the first that applies (modal for the linear law, run otherwise)")
                               .c_str(),
                             ReferenceMethodNames(true), "")); // no fixed default: the scenario's
    OptionSpec reference_config = OptionFile("-convergence_reference_config",
                                             "Configuration of the reference run (finest level = reference; error from "
                                             "the last three)");
    reference_config.def        = "options/convergence/reference.opts";
    o.push_back(reference_config);
    o.push_back(OptionList("-convergence_spatial_nodes", "1", "Spatial study: N1,N2,... (h halving: 41,81,161,321,641)",
                           1, 0, Between(5, 100000)));
    o.push_back(OptionReal("-convergence_target", "1",
                           "ACOR error at which the cost of each configuration is compared (the targets)", "1e-6",
                           Positive()));
    o.push_back(OptionReal("-convergence_error_floor", "1",
                           "Errors at or below this are round-off and left out of order fits", "1e-12", NonNegative()));
    o.push_back(OptionFile("-convergence_common_options", "Options file inserted into every run before the "
                                                          "configuration's own (not checked for use)"));
    o.push_back(OptionFlag("-convergence_quiet", "Print only the tables, not every run"));
    return r;
  }();
  return m;
}

ReferenceSettings ConvergenceReferenceSettings(const ConvergencePlan &plan)
{
  ReferenceSettings s;
  s.config_file = plan.reference_file;
  s.common_file = plan.common_file;
  return s;
}

std::string ConvergenceReferenceLabel(const ConvergencePlan &plan)
{
  const ReferenceMethod *m = ReferenceMethodFind(plan.reference);
  return m ? m->label(ConvergenceReferenceSettings(plan)) : plan.reference;
}

namespace {

// The index of the study's default reference for sc among the study methods (the first that applies).
PetscInt DefaultReferenceIndex(const std::vector<std::string> &names, const Scenario &sc)
{
  const ReferenceMethod *def = ReferenceMethodDefault(sc);
  for (size_t k = 0; k < names.size(); ++k)
    if (def && names[k] == def->name) return (PetscInt)k;
  return 0;
}

} // namespace

PetscErrorCode ConvergencePlanFromOptions(MPI_Comm comm, const Scenario &sc, ConvergencePlan *plan)
{
  const OptionModule    &m = ConvergenceOptionModule();
  std::string            configs, common;
  std::vector<PetscReal> spatial;
  PetscBool              set_configs = PETSC_FALSE, set_common = PETSC_FALSE;
  const auto             references = ReferenceMethodNames(true);
  PetscInt               reference  = DefaultReferenceIndex(references, sc);
  std::string            why;

  PetscFunctionBeginUser;
  PetscCheck(!references.empty(), comm, PETSC_ERR_PLIB, "no reference method is registered (app/registry.cpp)");
  PetscOptionsBegin(comm, NULL, m.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_configs", &configs, &set_configs));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_repeats", &plan->repeats, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_repeat_budget", &plan->repeat_budget, NULL));
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-convergence_reference", &reference, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_reference_config", &plan->reference_file, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_spatial_nodes", &spatial, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_target", &plan->target, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_error_floor", &plan->error_floor, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_common_options", &common, &set_common));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-convergence_quiet", &plan->quiet, NULL));
  PetscOptionsEnd();
  plan->reference               = references[reference];
  const ReferenceMethod *method = ReferenceMethodFind(plan->reference);
  PetscCheck(method->applies(sc, &why), comm, PETSC_ERR_ARG_INCOMP,
             "-convergence_reference %s %s; -convergence_reference takes %s", method->name, why.c_str(),
             ReferenceMethodHelp(true).c_str());
  if (set_common) {
    plan->common_file = common;
    std::ifstream in(plan->common_file);
    PetscCheck(in.good(), comm, PETSC_ERR_FILE_OPEN, "-convergence_common_options %s: cannot read this options file",
               common.c_str());
  }
  plan->configs.clear();
  if (set_configs)
    for (const std::string &f : SplitList(configs)) {
      ConvergenceConfig cfg;
      PetscCall(ConvergenceConfigLoad(comm, f, "", &cfg));
      for (auto &c : plan->configs)
        PetscCheck(c.name != cfg.name, comm, PETSC_ERR_ARG_WRONG,
                   "-convergence_configs: two configurations are named %s: give one a -convergence_name",
                   cfg.name.c_str());
      plan->configs.push_back(cfg);
    }
  plan->spatial_nodes.clear();
  for (PetscReal n : spatial) {
    PetscCheck(n == std::floor(n), comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-convergence_spatial_nodes: '%g' is not allowed: node counts are whole numbers >= 5", (double)n);
    PetscCheck(plan->spatial_nodes.empty() || n > plan->spatial_nodes.back(), comm, PETSC_ERR_ARG_WRONG,
               "-convergence_spatial_nodes must increase (got %g after %" PetscInt_FMT ")", (double)n,
               plan->spatial_nodes.back());
    plan->spatial_nodes.push_back((PetscInt)n);
  }
  PetscCheck(!plan->configs.empty() || !plan->spatial_nodes.empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task convergence needs -convergence_configs a.opts,b.opts,... (integrator configurations, e.g. "
             "options/convergence/*.opts) and/or -convergence_spatial_nodes N1,N2,...");
  PetscFunctionReturn(0);
}

} // namespace beamimpact

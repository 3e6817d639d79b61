// The plan of a sweep: axes, point lists, the -sweep* options and the scenario of each
// case. See sweep_plan.hpp.
#include "studies/sweep_plan.hpp"

#include "base/option_table.hpp"
#include "io/scenario_options.hpp"
#include "io/text.hpp"
#include "run/impact_point.hpp"
#include "solvers/ts_galpha2.hpp"
#include "solvers/ts_modal.hpp"

#include <petscts.h>
#include <strings.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace beamimpact {

// ---------------------------------------------------------------------------
// Cases and points
// ---------------------------------------------------------------------------

PetscInt SweepPlan::cases() const
{
  if (axes.empty()) return 0;
  PetscInt n = sampled.empty() ? 1 : SampleRows();
  for (auto &a : axes)
    if (!a.sampled) n *= (PetscInt)a.values.size();
  return n;
}

std::vector<PetscReal> SweepPlan::CaseValues(PetscInt index) const
{
  std::vector<PetscReal> v(axes.size());
  if (!sampled.empty()) { // the sample's row varies fastest
    const PetscInt rows = SampleRows(), s = index % rows;
    for (size_t k = 0; k < sampled.size(); ++k) v[sampled[k]] = sample_rows[(size_t)s * sampled.size() + k];
    index /= rows;
  }
  for (size_t k = axes.size(); k-- > 0;) {
    if (axes[k].sampled) continue;
    const PetscInt n = (PetscInt)axes[k].values.size();
    v[k]             = axes[k].values[index % n];
    index /= n;
  }
  return v;
}

bool SweepPlanSample(SweepPlan *plan, std::string *why)
{
  plan->sampled.clear();
  plan->sample_rows.clear();
  for (size_t k = 0; k < plan->axes.size(); ++k)
    if (plan->axes[k].sampled) plan->sampled.push_back(k);
  if (plan->sampled.empty()) return true;
  const int           d = (int)plan->sampled.size();
  const PetscInt      n = plan->samples;
  std::vector<double> u, rows;
  if (!SampleUnitDesign(plan->design, (uint64_t)plan->seed, n, plan->sobol ? 2 * d : d, &u, why)) return false;
  rows = plan->sobol ? SampleSaltelliRows(u, n, d) : u;
  plan->sample_rows.resize(rows.size());
  for (size_t r = 0; r < rows.size(); ++r)
    plan->sample_rows[r] = plan->axes[plan->sampled[r % d]].dist.Quantile(rows[r]);
  for (int k = 0; k < d; ++k) {
    SweepAxis &a = plan->axes[plan->sampled[k]];
    a.values.clear();
    for (size_t r = (size_t)k; r < plan->sample_rows.size(); r += (size_t)d) a.values.push_back(plan->sample_rows[r]);
  }
  return true;
}

static bool ParseReal(const std::string &text, PetscReal *v) { return TextFiniteNumber(text, v); }

static std::string Round15(double raw)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.15g", raw);
  return text;
}

static const double kMaxAxisPoints = 1e8; // points of one axis

// "start:stop:count[:log]", both ends included.
static bool ParseRange(const std::string &spec, std::vector<PetscReal> *values, std::string *why,
                       const std::string &unit)
{
  std::vector<std::string> parts;
  std::stringstream        ss(spec);
  std::string              p;
  const std::string        u = unit.empty() ? "" : " (" + unit + ")";
  while (std::getline(ss, p, ':')) parts.push_back(Trim(p));
  if (!spec.empty() && spec.back() == ':') parts.push_back("");
  const bool log = parts.size() == 4 && parts[3] == "log";
  if (parts.size() != 3 && !log) {
    *why = parts.size() == 4 ? "the fourth field of start:stop:count:log must be 'log', not '" + parts[3] + "'"
                             : "a range is start:stop:count or start:stop:count:log (numbers separated by ':')";
    return false;
  }
  PetscReal a, b;
  if (!ParseReal(parts[0], &a) || !ParseReal(parts[1], &b)) {
    *why = "start and stop of start:stop:count must be numbers" + u;
    return false;
  }
  const std::string c = parts[2];
  PetscReal         count;
  if (!ParseReal(c, &count) || !(count >= 0) || count != std::floor(count)) {
    *why = "count of start:stop:count must be a whole number >= 1, not '" + c + "'";
    return false;
  }
  if (count > kMaxAxisPoints) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "count %s of start:stop:count is too large: an axis has at most %.0e points (each point is an impact "
                  "of milliseconds to seconds)",
                  c.c_str(), kMaxAxisPoints);
    *why = text;
    return false;
  }
  const long n = (long)count;
  if (log && !((a > 0 && b > 0) || (a < 0 && b < 0))) {
    *why = "start and stop of start:stop:count:log must be of one sign and not 0 (equal ratios between points)";
    return false;
  }
  // Rounded to 15 significant digits, so that 0:1.1:111 gives exactly the
  // doubles of 0, 0.01, ..., 1.1 (what -impact_x 0.55 gives), not 1 ulp off.
  for (long k = 0; k < n; ++k) {
    const double s   = (double)k / (double)std::max(1L, n - 1);
    const double raw = k == n - 1 && n > 1 ? b
                     : log                 ? a * std::pow(b / a, s)
                                           : a + (double)k * ((b - a) / (double)std::max(1L, n - 1));
    values->push_back(std::strtod(Round15(raw).c_str(), nullptr));
  }
  return true;
}

bool SweepParsePoints(const std::string &spec_in, std::vector<PetscReal> *values, std::string *why,
                      const std::string &unit, const std::string &separators)
{
  const std::string spec = Trim(spec_in);
  const std::string u    = unit.empty() ? "" : " (" + unit + ")";
  values->clear();
  if (spec.find(':') != std::string::npos) return ParseRange(spec, values, why, unit);
  std::string one;
  const char  sep = separators.empty() ? ',' : separators[0];
  for (size_t i = 0; i <= spec.size(); ++i) {
    if (i < spec.size() && separators.find(spec[i]) == std::string::npos) {
      one += spec[i];
      continue;
    }
    PetscReal v;
    if (Trim(one).empty()) {
      *why = std::string("empty entry in the list (values separated by '") + sep + "')";
      return false;
    }
    if (!ParseReal(one, &v)) {
      *why = "'" + Trim(one) + "' is not a number; a list is v1" + sep + "v2" + sep + "..." + u;
      return false;
    }
    values->push_back(v);
    one.clear();
  }
  return true;
}

std::string SweepOptionUnit(const std::string &name)
{
  return OptionUnit(name); // the option's row (base/option_table.hpp); "" if none
}

// Options that belong to the task or the sweep itself, not to an impact.
static bool ReservedAxis(const std::string &name)
{
  static const std::set<std::string> exact = {"task",           "output",
                                              "options_file",   "help",
                                              "version",        "rigid_loss_fraction",
                                              "reference",      "allow_unused_options",
                                              "error_traceback"};
  return exact.count(name) || name.compare(0, 5, "sweep") == 0;
}

static bool NameOk(const std::string &n)
{
  if (n.empty() || !(std::isalpha((unsigned char)n[0]))) return false;
  for (char c : n)
    if (!(std::isalnum((unsigned char)c) || c == '_')) return false;
  return true;
}

static bool IsQuote(char c) { return c == '\'' || c == '"'; }

// text split at `sep` outside quotes ('...' or "..."), each part trimmed; *open is set when a
// quote is not closed.
static std::vector<std::string> SplitOutsideQuotes(const std::string &text, char sep, bool *open)
{
  std::vector<std::string> parts;
  std::string              one;
  char                     quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) quote = 0;
      one += c;
    } else if (IsQuote(c)) {
      quote = c;
      one += c;
    } else if (c == sep) {
      parts.push_back(Trim(one));
      one.clear();
    } else one += c;
  }
  parts.push_back(Trim(one));
  if (open) *open = quote != 0;
  return parts;
}

// The kinds of value an option takes, from its row in its module's table (none: not known).
enum class AxisKind {
  Unknown,
  Number,
  Text
};
static AxisKind KindOfOption(const std::string &name)
{
  const OptionSpec *s = OptionSpecFind(name);
  if (s)
    return s->kind == OptionKind::Choice || s->kind == OptionKind::Text || s->kind == OptionKind::File
           ? AxisKind::Text
           : AxisKind::Number;
  return SweepOptionUnit(name).empty() ? AxisKind::Unknown : AxisKind::Number;
}

// The values of a text axis: v1;v2;... (quotes removed: 'v' is text as written), each one
// neither empty nor given twice.
static bool ParseLabels(const std::string &spec, std::vector<std::string> *labels, std::string *why)
{
  bool open = false;
  labels->clear();
  for (const std::string &item : SplitOutsideQuotes(spec, ';', &open)) {
    std::string v = item;
    if (v.size() >= 2 && IsQuote(v.front()) && v.back() == v.front()) v = v.substr(1, v.size() - 2);
    else if (v.find('\'') != std::string::npos || v.find('"') != std::string::npos) {
      *why = open ? "a quote is not closed (a text value is 'v' or \"v\")"
                  : "'" + item + "' has a quote inside: a quoted value is the whole entry, 'v' or \"v\"";
      return false;
    }
    if (Trim(v).empty()) {
      *why = "empty entry in the list (values separated by ';')";
      return false;
    }
    if (std::find(labels->begin(), labels->end(), v) != labels->end()) {
      *why = "'" + v + "' is given twice";
      return false;
    }
    labels->push_back(v);
  }
  return true;
}

// Whether the values of a list v1;v2;... are all numbers (then a numeric axis, unless the
// option is text).
static bool AllNumbers(const std::string &spec)
{
  for (const std::string &item : SplitOutsideQuotes(spec, ';', nullptr)) {
    PetscReal v;
    if (!ParseReal(item, &v)) return false;
  }
  return true;
}

// One axis NAME=SPEC: its name, whether it is text or numbers, and its values.
static bool ParseAxis(const std::string &item, SweepAxis *a, std::string *why)
{
  const size_t eq = item.find('=');
  if (item.empty() || eq == std::string::npos) {
    *why = item.empty()
           ? "an empty axis (axes are NAME=SPEC separated by ',')"
           : "'" + item + "' is not NAME=SPEC (e.g. impact_x=0:1.1:111, ball_speed=10;20;30 or ts_type=rk;cn)";
    return false;
  }
  a->name = Trim(item.substr(0, eq));
  if (!a->name.empty() && a->name[0] == '-') a->name = a->name.substr(1);
  a->spec = Trim(item.substr(eq + 1));
  a->unit = SweepOptionUnit(a->name);
  if (!NameOk(a->name)) {
    *why = "'" + a->name + "' is not an option name (letters, digits and '_', without the dash)";
    return false;
  }
  if (ReservedAxis(a->name)) {
    *why = "-" + a->name + " belongs to the task or the sweep itself, not to an impact: it cannot be an axis";
    return false;
  }
  if (a->spec.empty()) {
    *why = a->name + " has no values: " + a->name +
           "=start:stop:count, start:stop:count:log, v1;v2;... or a distribution (normal:MEAN:STD, uniform:LO:HI, ...)";
    return false;
  }
  const AxisKind kind = KindOfOption(a->name);
  std::string    w;
  if (SampleSpecIsDistribution(a->spec)) { // a sampled axis: its values are drawn later (SweepPlanSample)
    const OptionSpec *s = OptionSpecFind(a->name);
    if (kind == AxisKind::Text) {
      *why = a->name + "=" + a->spec + ": -" + a->name + " takes text; only a numeric option can follow a distribution";
      return false;
    }
    a->sampled = SampleDistributionParse(a->spec, a->unit, s && s->kind == OptionKind::Int, &a->dist, &w);
    if (!a->sampled) *why = a->name + "=" + a->spec + ": " + w;
    return a->sampled;
  }
  const bool quoted = a->spec.find('\'') != std::string::npos || a->spec.find('"') != std::string::npos;
  const bool text   = kind == AxisKind::Text || quoted ||
                    (kind == AxisKind::Unknown && a->spec.find(':') == std::string::npos && !AllNumbers(a->spec));
  if (text) {
    a->unit.clear();
    if (!ParseLabels(a->spec, &a->labels, &w)) {
      *why = a->name + "=" + a->spec + ": " + w;
      return false;
    }
    a->values.clear();
    for (size_t k = 0; k < a->labels.size(); ++k) a->values.push_back((PetscReal)k);
    return true;
  }
  if (!SweepParsePoints(a->spec, &a->values, &w, a->unit, ";")) {
    *why = a->name + "=" + a->spec + ": " + w;
    return false;
  }
  if (a->values.empty()) {
    *why = a->name + "=" + a->spec + " gives no values: a sweep needs at least one (count >= 1 in start:stop:count)";
    return false;
  }
  return true;
}

bool SweepParseAxes(const std::string &text, std::vector<SweepAxis> *axes, std::string *why)
{
  bool open = false;
  for (const std::string &item : SplitOutsideQuotes(text, ',', &open)) {
    SweepAxis a;
    if (open) {
      *why = "a quote is not closed (a text value is 'v' or \"v\")";
      return false;
    }
    if (!ParseAxis(item, &a, why)) return false;
    for (const SweepAxis &b : *axes)
      if (b.name == a.name) {
        *why = a.name + " is given twice";
        return false;
      }
    axes->push_back(a);
  }
  return true;
}

std::string SweepAxis::OptionValue(PetscReal v) const
{
  if (Text()) return labels[(size_t)v];
  return ShortestText((double)v); // exact, as a user writes it (-0.06, not -0.059999999999999998)
}

std::string SweepAxis::Display(PetscReal v) const
{
  if (Text()) return labels[(size_t)v];
  char text[64];
  std::snprintf(text, sizeof(text), "%g%s", (double)v, unit.empty() || unit == "1" ? "" : (" " + unit).c_str());
  return text;
}

// The names of PETSc's registry of TS types (with this program's alpha2 and modal), sorted.
static PetscErrorCode TSTypeNames(std::vector<std::string> *names)
{
  const char **list = nullptr;
  int          n    = 0;

  PetscFunctionBeginUser;
  PetscCall(TSGAlpha2Register());
  PetscCall(TSModalRegister());
  PetscCall(PetscFunctionListGet(TSList, &list, &n));
  names->clear();
  for (int k = 0; k < n; ++k) // the array ends with NULL (counted in n)
    if (list[k]) names->push_back(list[k]);
  PetscCall(PetscFree(list));
  std::sort(names->begin(), names->end());
  PetscFunctionReturn(0);
}

PetscErrorCode SweepCheckTextAxis(const SweepAxis &a, std::string *why)
{
  std::vector<std::string> allowed;
  bool                     nocase = false; // the options readers compare choices without case

  PetscFunctionBeginUser;
  why->clear();
  const OptionSpec *s = OptionSpecFind(a.name);
  if (s && s->kind == OptionKind::Choice) {
    allowed = s->choices;
    nocase  = true;
  } else if (a.name == "ts_type") PetscCall(TSTypeNames(&allowed));
  if (allowed.empty()) PetscFunctionReturn(0);
  for (const std::string &v : a.labels) {
    bool known = false;
    for (const std::string &c : allowed) known = known || (nocase ? strcasecmp(c.c_str(), v.c_str()) == 0 : c == v);
    if (known) continue;
    std::string list;
    for (const std::string &c : allowed) list += (list.empty() ? "" : ", ") + c;
    *why = a.name + "=" + a.spec + ": '" + v + "' is not " +
           (a.name == "ts_type" ? "a TS type of this program" : "a choice of -" + a.name) + ": use one of " + list;
    break;
  }
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------

static OptionSpec WithRangeText(OptionSpec s, const char *text)
{
  s.range_text = text;
  return s;
}

const OptionModule kSweepOptions = {
  "sweep",
  "Sweep: many impacts farmed out over MPI ranks (-task sweep)",
  {
    OptionText("-sweep", "Axes NAME=SPEC[,NAME=SPEC...]: NAME any option without its dash, numeric (impact_x, "
                         "ball_speed, beam_thickness, beam_nodes, ts_dt, ...) or text (ts_type, beam_theory, "
                         "beam_left, ball_law, ts_rk_type, ...), SPEC start:stop:count, start:stop:count:log or "
                         "v1;v2;... (a text value quoted, 'v', stays text: ts_rk_type='4';'3'); the cases are "
                         "their product, the last axis varying fastest. A numeric axis may be sampled from a "
                         "distribution instead (with -sweep_samples): normal:MEAN:STD, "
                         "truncnormal:MEAN:STD:LO:HI, uniform:LO:HI, lognormal:MEAN:STD, triangular:LO:MODE:HI, a "
                         "table V1@W1;V2@W2;... (relative weights) or csv:FILE[:COLUMN] "
                         "(measured values, drawn with equal probability); the grid axes' points times the sample's "
                         "rows (docs/uncertainty.md)"),
    OptionText("-sweep_x", "Impact points (m), shorthand for -sweep impact_x=SPEC: start:stop:count (both ends "
                           "included) or x1,x2,..."),
    OptionInt("-sweep_ranks_per_case",
              "Ranks that solve one impact together (the beam's DMDA is distributed over them)", "1", AtLeast(1)),
    WithRangeText(OptionReal("-rigid_loss_fraction", "1",
                             "Loss fraction f of the rigid-body model, Eq. (11), for the rigid_acor column", "0",
                             Between(0, 1, false, true)),
                  "a fraction of the incident energy, 0 <= f < 1"),
    OptionFlag("-sweep_quiet", "No progress or summary lines (errors, the count of failed points and of points "
                               "compressed beyond -ball_radius are still reported)"),
    OptionFlag("-sweep_restart", "Discard an existing -output file and its journal and start the sweep over"),
    OptionFlag("-sweep_retry_failed",
               "On resuming, compute again the points that failed (status != 0) instead of keeping their rows"),
    OptionReal("-sweep_progress_interval", "s", "Seconds between progress lines on rank 0", "2", Positive()),
    OptionReal("-sweep_write_interval", "s",
               "Minimum seconds between rewrites of -output while the sweep runs (0: as often as a 5% cost cap on rank "
               "0 allows)",
               "5", NonNegative()),
    OptionInt("-sweep_samples",
              "Points N of the sample of the sampled axes (-sweep NAME=normal:..., uniform:..., ...); with "
              "-sweep_sobol N (d + 2) runs for d sampled axes",
              "", Between(1, 1e8)),
    OptionChoice("-sweep_sampling",
                 "How the sample covers the unit cube before the inverse CDFs: random (independent draws), lhs (Latin "
                 "hypercube), sobol (GSL's Sobol' sequence, "
                 "at most 40 dimensions, digitally shifted from -sweep_seed) or halton (GSL's, shifted modulo 1)",
                 {"random", "lhs", "sobol", "halton"}, "random"),
    OptionInt("-sweep_seed",
              "Seed of the sample (and of the bootstrap): every point is a pure function of the seed and its index",
              "0", Between(0, 2147483647)),
    OptionFlag("-sweep_sobol", "First and total Sobol' indices of every results column for each sampled axis: "
                               "Saltelli's design (A, B and A_B^(i): N (d + 2) runs), Saltelli 2010 and Jansen "
                               "estimators with bootstrap intervals, in /sobol"),
    OptionText("-sweep_exceedance", "Probabilities of exceedance of a sampled sweep, COLUMN>VALUE[,COLUMN<=VALUE,...] "
                                    "(>, >=, <, <=; a /results column), with Wilson's 95% interval, in /exceedance"),
    OptionInt("-sweep_bootstrap",
              "Bootstrap resamples of the quantiles' standard errors and the Sobol' indices' intervals", "200",
              Between(10, 1e5)),
  },
};

// The -sweep* options and -rigid_loss_fraction, each checked against its row of kSweepOptions.
static PetscErrorCode SweepOptionsRead(MPI_Comm comm, SweepPlan *plan, PetscBool *set_sweep, PetscBool *set_x)
{
  const OptionModule &m = kSweepOptions;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, m.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep", &plan->sweep, set_sweep));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_x", &plan->sweep_x, set_x));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_ranks_per_case", &plan->ranks_per_case, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-rigid_loss_fraction", &plan->rigid_loss_fraction, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_quiet", &plan->quiet, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_restart", &plan->restart, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_retry_failed", &plan->retry_failed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_progress_interval", &plan->progress_interval, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_write_interval", &plan->write_interval, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_samples", &plan->samples, NULL));
  PetscInt design = 0;
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-sweep_sampling", &design, NULL));
  plan->design = (SampleDesign)design; // the row's choices in the enum's order
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_seed", &plan->seed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_sobol", &plan->sobol, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_exceedance", &plan->exceedance, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-sweep_bootstrap", &plan->bootstrap, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

// The sample of the sampled axes, and its options checked: -sweep_samples needed with a sampled
// axis; the sampling options without one are notes.
static PetscErrorCode SweepPlanSampleFromOptions(MPI_Comm comm, SweepPlan *plan)
{
  std::string why;
  bool        any = false;

  PetscFunctionBeginUser;
  for (const SweepAxis &a : plan->axes) any = any || a.sampled;
  if (!any) {
    for (const char *o : {"-sweep_samples", "-sweep_sampling", "-sweep_seed", "-sweep_sobol", "-sweep_exceedance",
                          "-sweep_bootstrap"}) {
      PetscBool given = PETSC_FALSE;
      PetscCall(PetscOptionsHasName(NULL, NULL, o, &given));
      if (given)
        PetscCall(PetscPrintf(comm,
                              "note: %s has no effect: no axis of the sweep is sampled (a distribution: -sweep "
                              "\"impact_x=normal:0.7:0.02\", ...)\n",
                              o));
    }
    PetscFunctionReturn(0);
  }
  PetscCheck(plan->samples > 0, comm, PETSC_ERR_ARG_WRONG,
             "-sweep \"%s\" samples its axes from distributions: give the sample's size, -sweep_samples N (e.g. 1000)",
             plan->sweep.c_str());
  PetscCheck(SweepPlanSample(plan, &why), comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_sampling %s is not allowed here: %s",
             SampleDesignName(plan->design), why.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode SweepPlanFromOptions(MPI_Comm comm, SweepPlan *plan)
{
  PetscBool   set_sweep = PETSC_FALSE, set_x = PETSC_FALSE;
  std::string why;

  PetscFunctionBeginUser;
  PetscCall(SweepOptionsRead(comm, plan, &set_sweep, &set_x));
  plan->axes.clear();
  plan->sweep   = set_sweep ? Trim(plan->sweep) : "";
  plan->sweep_x = set_x ? Trim(plan->sweep_x) : "";
  PetscCheck(set_sweep || set_x, comm, PETSC_ERR_ARG_WRONG,
             "-task sweep needs its axes: -sweep \"NAME=SPEC[,NAME=SPEC...]\" (e.g. -sweep "
             "\"impact_x=0:1.1:23,ball_speed=10;20;30\"), or the impact points alone: -sweep_x start:stop:count or "
             "-sweep_x x1,x2,... (m)");
  if (set_x) {
    SweepAxis a;
    a.name = "impact_x";
    a.unit = "m";
    a.spec = plan->sweep_x;
    PetscCheck(!a.spec.empty(), comm, PETSC_ERR_ARG_WRONG,
               "-sweep_x needs a value: start:stop:count (both ends included) or x1,x2,... (m), e.g. -sweep_x "
               "0:1.1:111");
    PetscCheck(SweepParsePoints(a.spec, &a.values, &why, "m"), comm, PETSC_ERR_ARG_WRONG,
               "-sweep_x %s is not allowed: %s", a.spec.c_str(), why.c_str());
    PetscCheck(!a.values.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-sweep_x %s gives no impact points: a sweep needs at least one (count >= 1 in start:stop:count)",
               a.spec.c_str());
    plan->axes.push_back(a);
  }
  if (set_sweep) {
    std::vector<SweepAxis> more;
    PetscCheck(!plan->sweep.empty(), comm, PETSC_ERR_ARG_WRONG,
               "-sweep needs a value: \"NAME=SPEC[,NAME=SPEC...]\", e.g. -sweep "
               "\"impact_x=0:1.1:23,ball_speed=10;20;30\"");
    PetscCheck(SweepParseAxes(plan->sweep, &more, &why), comm, PETSC_ERR_ARG_WRONG, "-sweep \"%s\" is not allowed: %s",
               plan->sweep.c_str(), why.c_str());
    for (const SweepAxis &a : more) {
      PetscCheck(!(set_x && a.name == "impact_x"), comm, PETSC_ERR_ARG_INCOMP,
                 "-sweep \"%s\" and -sweep_x %s both vary impact_x: give the impact points once", plan->sweep.c_str(),
                 plan->sweep_x.c_str());
      PetscCall(SweepCheckTextAxis(a, &why)); // the values the program knows are checked here, before any work
      PetscCheck(why.empty(), comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-sweep \"%s\" is not allowed: %s", plan->sweep.c_str(),
                 why.c_str());
    }
    plan->axes.insert(plan->axes.end(), more.begin(), more.end());
  }
  PetscCall(SweepPlanSampleFromOptions(comm, plan));
  double n = plan->sampled.empty() ? 1 : (double)plan->SampleRows();
  for (const SweepAxis &a : plan->axes) n *= a.sampled ? 1.0 : (double)a.values.size();
  PetscCheck(n <= 1e9, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "the sweep has %.3g points (the product of its axes): at most 1e9 are allowed", n);
  // An axis's own option given too (a scene's options file sets -beam_thickness, say): the
  // axis overrides it at every case (the announcement says so), and it is put back after.
  for (SweepAxis &a : plan->axes) {
    std::vector<char> given(1 << 16, 0);
    PetscBool         has;
    PetscCall(PetscOptionsGetString(NULL, NULL, ("-" + a.name).c_str(), given.data(), given.size(), &has));
    a.overrides = has == PETSC_TRUE;
    a.given     = has ? given.data() : "";
  }
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-impact_cost_warn", &plan->cost_warn,
                                NULL)); // its help and check: the impact's options
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// The scenario of a case
// ---------------------------------------------------------------------------

PetscErrorCode SweepCaseOptionsSet(const SweepPlan &plan, PetscInt index)
{
  const std::vector<PetscReal> v = plan.CaseValues(index);

  PetscFunctionBeginUser;
  for (size_t k = 0; k < plan.axes.size(); ++k) {
    const std::string opt = "-" + plan.axes[k].name;
    // Cleared first: a new entry, so that "used" says whether this case's reading used it.
    PetscCall(PetscOptionsClearValue(NULL, opt.c_str()));
    PetscCall(PetscOptionsSetValue(NULL, opt.c_str(), plan.axes[k].OptionValue(v[k]).c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SweepCaseOptionsClear(const SweepPlan &plan)
{
  PetscFunctionBeginUser;
  for (const SweepAxis &a : plan.axes) {
    PetscCall(PetscOptionsClearValue(NULL, ("-" + a.name).c_str()));
    if (a.overrides)
      PetscCall(PetscOptionsSetValue(NULL, ("-" + a.name).c_str(), a.given.empty() ? NULL : a.given.c_str()));
  }
  PetscFunctionReturn(0);
}

std::string SweepErrorReason(PetscErrorCode ierr)
{
  std::string  msg = LastErrorMessage(ierr);
  const size_t nl  = msg.find('\n');
  if (nl != std::string::npos) msg = msg.substr(0, nl);
  msg = Trim(msg);
  if (msg.size() > 400) msg = msg.substr(0, 397) + "...";
  return msg;
}

namespace {

// The reading of case `index` with the cache: the structure's scenario reused when the case is
// on it (how->reuse, how->read: the point's parts), else a whole reading that replaces it.
void SweepCacheReading(const SweepPlan &plan, PetscInt index, bool monitors, SweepScenarioCache *cache,
                       std::vector<PetscReal> *key, ScenarioReading *how)
{
  if (cache->axis_part.size() != plan.axes.size()) {
    cache->axis_part.clear();
    for (const SweepAxis &a : plan.axes) cache->axis_part.push_back(ScenarioPartOf(a.name));
  }
  const std::vector<PetscReal> v    = plan.CaseValues(index);
  unsigned                     read = 0;
  key->clear();
  for (size_t k = 0; k < v.size(); ++k) {
    if (cache->axis_part[k] == ScenarioAll) key->push_back(v[k]);
    else read |= cache->axis_part[k];
  }
  if (!cache->valid || cache->monitors != monitors || *key != cache->key) return; // a whole reading
  how->reuse = &cache->base;
  how->read  = read;
}

} // namespace

PetscErrorCode SweepCaseScenario(MPI_Comm comm, const SweepPlan &plan, PetscInt index, bool monitors, Scenario *sc,
                                 int *status, std::string *reason, SweepScenarioCache *cache)
{
  ScenarioReading        how;
  bool                   bodies_read = false;
  BeamParams             beam;
  std::vector<PetscReal> key;
  Scenario               read_as;

  PetscFunctionBeginUser;
  *status = SweepOk;
  reason->clear();
  if (cache) cache->last_partial = false;
  PetscCall(SweepCaseOptionsSet(plan, index));
  how.monitors      = monitors;
  how.flight_series = false; // a sweep writes no trajectory
  how.after_bodies  = [&](const Scenario &bodies) -> PetscErrorCode {
    bodies_read = true;
    beam        = bodies.beam;
    return 0;
  };
  if (cache) {
    SweepCacheReading(plan, index, monitors, cache, &key, &how);
    how.read_as = how.reuse ? nullptr : &read_as; // the structure's reading, kept once it succeeded
  }
  *sc                 = Scenario();
  PetscErrorCode ierr = ScenarioFromOptions(comm, how, sc);
  if (ierr) {
    // The impact point of this case may be off the beam or held fixed (e.g. across a
    // clamped region): a failed case, not a bad option.
    PetscReal x = ImpactParams().x, z = 0;
    PetscBool set;
    if (bodies_read && !PetscOptionsGetReal(NULL, NULL, "-impact_x", &x, &set) &&
        !PetscOptionsGetReal(NULL, NULL, "-impact_z", &z, &set)) {
      const ImpactPointWhere where = ImpactPointLocate(beam, x, z);
      if (where != ImpactPointWhere::Movable) {
        *status = where == ImpactPointWhere::OffBeam ? SweepOffBeam
                : where == ImpactPointWhere::OffFace ? SweepOffFace
                                                     : SweepHeldPoint;
        *reason = SweepErrorReason(ierr);
        PetscFunctionReturn(0);
      }
    }
    return ierr;
  }
  if (cache) cache->last_partial = how.reuse != nullptr;
  if (cache && how.reuse) ++cache->partial;
  else if (cache) {
    ++cache->full;
    cache->valid    = true;
    cache->monitors = monitors;
    cache->key      = key;
    cache->base     = std::move(read_as);
  }
  PetscFunctionReturn(0);
}

std::string SweepCaseText(const SweepPlan &plan, PetscInt index, bool petsc_format)
{
  const std::vector<PetscReal> v = plan.CaseValues(index);
  std::string                  text;
  for (size_t k = 0; k < plan.axes.size(); ++k) {
    const SweepAxis &a = plan.axes[k];
    std::string      one;
    if (petsc_format && !a.Text()) { // as PETSc's messages print it (1 reads "1.")
      const std::string unit = a.unit.empty() || a.unit == "1" ? "" : " " + a.unit;
      char              buf[256];
      if (PetscSNPrintf(buf, sizeof(buf), "%s = %g%s", a.name.c_str(), (double)v[k], unit.c_str())) buf[0] = '\0';
      one = buf;
    } else one = a.name + " = " + a.Display(v[k]);
    text += (k ? ", " : "") + one;
  }
  return text;
}

const char *SweepStatusName(int status)
{
  switch (status) {
  case SweepOk:
    return "ok";
  case SweepOffBeam:
    return "impact point off the beam";
  case SweepHeldPoint:
    return "impact point held fixed";
  case SweepRefused:
    return "refused by the run's set-up";
  case SweepNotConverged:
    return "run stopped (not converged)";
  case SweepNotFinite:
    return "solution not finite";
  case SweepCutInContact:
    return "cut off in contact by -impact_max_time";
  case SweepOffFace:
    return "off the racket's face: no impact";
  default:
    return "run failed";
  }
}

} // namespace beamimpact

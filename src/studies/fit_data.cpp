// -task fit's options, parameters and table of measurements. See fit_data.hpp.
#include "studies/fit_data.hpp"

#include "io/sha256.hpp"
#include "io/text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace beamimpact {

const OptionModule &FitOptionTable()
{
  static const OptionModule m = [] {
    std::vector<std::string> tasks;
    for (const CaseTask *t : CaseTasks()) tasks.push_back(t->name);
    return OptionModule{
      "fit",
      "beamimpact: -task fit (least-squares calibration of options against measurements; TAO's -tao_* options choose "
      "and tune the solver)",
      {
        OptionFile("-fit_data", "The measurements: a CSV file, a header of names, one row per run; a column named as "
                                "an option sets it for the row's run, a column named as a column of "
                                "-fit_task is measured (empty: not measured), <column>_sigma its standard deviation; "
                                "'#' comment lines"),
        OptionText("-fit_parameters", "The options fitted: NAME=LO:HI[:START][,...] (start: the option's given value, "
                                      "or the middle; log-scaled where HI/LO >= 10)"),
        OptionChoice("-fit_task",
                     "What each row runs: an impact (its results table's columns), the modes (frequency_K, mass, "
                     "centre_of_mass, ...) or the flight (distance, apex, ...)",
                     tasks, "impact"),
        OptionText("-fit_sigma", "Standard deviations of whole columns, COLUMN=SIGMA[,...] (the column's unit), where "
                                 "the data has no <column>_sigma; default: relative weights, each column's RMS"),
        OptionChoice("-fit_differences", "The differences of TAO's Jacobian: forward (n runs a row) or central (2n)",
                     {"forward", "central"}, "forward"),
        OptionReal("-fit_difference_step", "1",
                   "Relative step of the parameters for TAO's Jacobian (about the square root of a run's relative "
                   "precision)",
                   "1e-6", Between(0, 0.1, true, false)),
        OptionReal("-fit_covariance_step", "1",
                   "Relative step of the central differences of the Jacobian at the optimum (standard errors, "
                   "identifiability)",
                   "1e-4", Between(0, 0.1, true, false)),
        OptionReal("-fit_xtol", "1",
                   "brgn stops when no parameter moves by more than this in its scaled range [0, 1] (TAO's -tao_gatol, "
                   "-tao_grtol also stop it)",
                   "1e-8", Positive()),
        OptionReal("-fit_ftol", "1",
                   "brgn stops when chi^2 changes by less than this times itself from one iteration to the next",
                   "1e-10", NonNegative()),
        OptionReal("-fit_identifiability_tol", "1",
                   "A singular value of the parameter-scaled Jacobian below this times the largest: that combination "
                   "is not determined by the data",
                   "1e-8", Between(0, 1, true, true)),
        OptionText("-fit_options_output", "The fitted values as an options file to include (default: -output with "
                                          ".opts; none with -output none)"),
        OptionFlag("-fit_quiet", "No line per iteration"),
        OptionFlag("-fit_restart",
                   "Compute every run again: forget the runs an earlier fit into the same -output kept"),
        OptionInt("-fit_stop_after", "Stop with an error after this many runs (a test of the resume; 0: never)", "0",
                  NonNegative()),
      },
    };
  }();
  return m;
}

const OptionModule &TaoOptionTable()
{
  static const OptionModule m = {
    "tao",
    "TAO options of -task fit beamimpact advertises (read by PETSc's TaoSetFromOptions, after the program's defaults)",
    {
      OptionText("-tao_type", "Least-squares solver: brgn (Gauss-Newton with bounds) or pounders (derivative-free)",
                 "brgn"),
      OptionReal("-tao_brgn_regularizer_weight", "1",
                 "brgn's regularizer weight lambda (the program's default 0: plain Gauss-Newton; PETSc's 1e-4)", "0",
                 NonNegative()),
      OptionInt("-tao_max_it", "Iterations allowed", "50", AtLeast(0)),
      OptionInt("-tao_max_funcs", "Residual evaluations allowed (-1: no limit)", "-1"),
      OptionReal("-tao_gatol", "1",
                 "Stop when ||J^T r|| (in the scaled parameters) is below this (the program's default 0: off)", "0",
                 NonNegative()),
      OptionReal("-tao_grtol", "1", "Stop when ||J^T r|| / (chi^2/2) is below this (the program's default 0: off)", "0",
                 NonNegative()),
      OptionReal("-tao_gttol", "1", "Stop when ||J^T r|| falls below this times its start (default 0: off)", "0",
                 NonNegative()),
      OptionFlag("-tao_monitor", "Print each iteration (TAO's line)"),
      OptionFlag("-tao_view", "Print the solver's set-up at the end"),
      OptionFlag("-tao_converged_reason", "Print why the solver stopped"),
    },
    true,
    {"-tao_"},
  };
  return m;
}

PetscErrorCode FitSettingsFromOptions(MPI_Comm comm, const std::string &output, FitSettings *s)
{
  const OptionModule &m    = FitOptionTable();
  PetscInt            task = 0, differences = 0;
  PetscBool           set_data = PETSC_FALSE, set_params = PETSC_FALSE, set_opts = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, m.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_data", &s->data, &set_data));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_parameters", &s->parameters, &set_params));
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-fit_task", &task, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_sigma", &s->sigma, NULL));
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-fit_differences", &differences, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_difference_step", &s->step, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_covariance_step", &s->covariance_step, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_xtol", &s->xtol, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_ftol", &s->ftol, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_identifiability_tol", &s->identifiability, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_options_output", &s->options_output, &set_opts));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_quiet", &s->quiet, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_restart", &s->restart, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-fit_stop_after", &s->stop_after, NULL));
  PetscOptionsEnd();
  s->task    = CaseTasks()[task];
  s->central = differences == 1;
  PetscCheck(set_data && !Trim(s->data).empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task fit needs its measurements: -fit_data FILE.csv (a header of names, one row per run; docs/fit.md)");
  PetscCheck(set_params && !Trim(s->parameters).empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task fit needs the options to fit: -fit_parameters NAME=LO:HI[:START][,...], e.g. -fit_parameters "
             "\"ball_k=1e4:5e4,beam_youngs_modulus=5e10:9e10\"");
  PetscCheck(!set_opts || !Trim(s->options_output).empty(), comm, PETSC_ERR_ARG_WRONG,
             "-fit_options_output needs a file name");
  if (!set_opts) {
    const size_t dot = output.rfind('.'), slash = output.rfind('/');
    s->options_output = output.empty() ? ""
                                       : (dot != std::string::npos && (slash == std::string::npos || dot > slash)
                                            ? output.substr(0, dot)
                                            : output) +
                                           ".opts";
  }
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// Parameters
// ---------------------------------------------------------------------------

namespace {

bool ParseNumber(const std::string &text, PetscReal *v)
{
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char *end      = nullptr;
  errno          = 0;
  const double d = std::strtod(t.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(d)) return false;
  *v = d;
  return true;
}

std::vector<std::string> SplitOn(const std::string &s, char sep)
{
  std::vector<std::string> out;
  std::string              cur;
  for (char c : s) {
    if (c == sep) out.push_back(cur), cur.clear();
    else cur += c;
  }
  out.push_back(cur);
  return out;
}

std::string Num(double v)
{
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The start of p: the option's value in the database when given, else the middle.
bool ParameterStart(FitParameter *p, std::string *why)
{
  PetscReal given = 0;
  PetscBool set   = PETSC_FALSE;
  if (PetscOptionsGetReal(NULL, NULL, ("-" + p->name).c_str(), &given, &set) || !set) {
    p->start      = p->log ? std::sqrt(p->lo * p->hi) : 0.5 * (p->lo + p->hi);
    p->start_from = "the middle of the bounds";
    return true;
  }
  if (!(given >= p->lo && given <= p->hi)) {
    *why = "its start, the value -" + p->name + " " + Num(given) + " given in the options, is outside its bounds " +
           Num(p->lo) + ":" + Num(p->hi) + ": widen the bounds or give the start as NAME=LO:HI:START";
    return false;
  }
  p->start      = given;
  p->start_from = "the option's value";
  return true;
}

} // namespace

PetscReal FitParameter::ToInternal(PetscReal p) const
{
  return log ? std::log(p / lo) / std::log(hi / lo) : (p - lo) / (hi - lo);
}
PetscReal FitParameter::FromInternal(PetscReal u) const { return log ? lo * std::pow(hi / lo, u) : lo + u * (hi - lo); }

bool FitParseParameters(const std::string &text, std::vector<FitParameter> *params, std::string *why)
{
  params->clear();
  for (const std::string &item : SplitOn(text, ',')) {
    FitParameter p;
    const size_t eq                  = item.find('=');
    p.name                           = Trim(item.substr(0, eq));
    const std::vector<std::string> r = SplitOn(eq == std::string::npos ? "" : item.substr(eq + 1), ':');
    if (eq == std::string::npos || p.name.empty() || (r.size() != 2 && r.size() != 3)) {
      *why = "'" + Trim(item) + "' is not NAME=LO:HI or NAME=LO:HI:START";
      return false;
    }
    if (!p.name.empty() && p.name[0] == '-') p.name = p.name.substr(1);
    const OptionSpec *spec = OptionSpecFind("-" + p.name);
    if (!spec || spec->kind != OptionKind::Real) {
      *why = "-" + p.name + " is not a real-valued option of the program (" +
             (spec ? "it is not a number" : "no module reads it") +
             "): a parameter is an option without its dash, e.g. ball_k1, beam_youngs_modulus";
      return false;
    }
    if (!ParseNumber(r[0], &p.lo) || !ParseNumber(r[1], &p.hi) || !(p.lo < p.hi)) {
      *why = p.name + "'s bounds '" + Trim(r[0]) + ":" + Trim(r[1]) + "' are not two finite numbers LO < HI";
      return false;
    }
    for (const FitParameter &q : *params)
      if (q.name == p.name) {
        *why = p.name + " is given twice";
        return false;
      }
    p.unit = spec->unit;
    p.log  = p.lo > 0 && p.hi / p.lo >= 10;
    if (r.size() == 3) {
      if (!ParseNumber(r[2], &p.start) || !(p.start >= p.lo && p.start <= p.hi)) {
        *why = p.name + "'s start '" + Trim(r[2]) + "' is not a number within its bounds " + Trim(r[0]) + ":" +
               Trim(r[1]);
        return false;
      }
      p.start_from = "given as NAME=LO:HI:START";
    } else if (!ParameterStart(&p, why)) {
      *why = p.name + ": " + *why;
      return false;
    }
    params->push_back(p);
  }
  return true;
}

// ---------------------------------------------------------------------------
// The table of measurements
// ---------------------------------------------------------------------------

namespace {

// What a column of the table is.
enum class ColumnKind {
  Option,
  Measured,
  Sigma
};

struct TableReader {
  const std::string       &file;
  const CaseTask          &task;
  std::vector<std::string> header;
  std::vector<ColumnKind>  kind;
  std::vector<int> target;   // a sigma column's measured column (index into d->measured), a measured column's index
  std::vector<int> sigma_of; // a measured column's sigma column (index into header), -1 none
  std::string      where(int line, size_t col) const
  {
    return "-fit_data " + file + " line " + std::to_string(line) + ", column '" + header[col] + "'";
  }
};

bool ClassifyColumns(TableReader &t, const std::vector<FitParameter> &params, FitData *d, std::string *why)
{
  const size_t n = t.header.size();
  t.kind.assign(n, ColumnKind::Option);
  t.target.assign(n, -1);
  std::set<std::string> seen;
  for (size_t c = 0; c < n; ++c) {
    const std::string &h = t.header[c];
    std::string        unit, task_why;
    if (h.empty() || !seen.insert(h).second) {
      *why = "-fit_data " + t.file + ": the header's column " + std::to_string(c + 1) +
             (h.empty() ? " has no name" : " ('" + h + "') appears twice");
      return false;
    }
    for (const FitParameter &p : params)
      if (p.name == h) {
        *why = "-fit_data " + t.file + ": the column '" + h +
               "' is also a fitted parameter (-fit_parameters): a parameter takes one value in every row";
        return false;
      }
    if (t.task.column(h, &unit, &task_why)) {
      t.kind[c]   = ColumnKind::Measured;
      t.target[c] = (int)d->measured.size();
      d->measured.push_back(h);
      d->units.push_back(unit);
    } else if (h.size() > 6 && h.compare(h.size() - 6, 6, "_sigma") == 0 &&
               t.task.column(h.substr(0, h.size() - 6), &unit, &task_why)) {
      t.kind[c] = ColumnKind::Sigma;
    } else if (OptionSpecFind("-" + h) || OptionIsPetsc("-" + h)) {
      d->option_columns.push_back(h);
    } else {
      *why = "-fit_data " + t.file + ": the column '" + h +
             "' is neither an option of the program (without its dash), nor a column of -fit_task " + t.task.name +
             " (" + task_why + "), nor <column>_sigma";
      return false;
    }
  }
  t.sigma_of.assign(d->measured.size(), -1);
  for (size_t c = 0; c < n; ++c) {
    if (t.kind[c] != ColumnKind::Sigma) continue;
    const std::string base = t.header[c].substr(0, t.header[c].size() - 6);
    const auto        it   = std::find(d->measured.begin(), d->measured.end(), base);
    if (it == d->measured.end()) {
      *why = "-fit_data " + t.file + ": the column '" + t.header[c] + "' is the standard deviation of '" + base +
             "', which is not a column of the table";
      return false;
    }
    t.sigma_of[it - d->measured.begin()] = (int)c;
  }
  if (d->measured.empty())
    *why = "-fit_data " + t.file + ": no column is a measured column of -fit_task " + t.task.name + " (its columns: " +
           [&] {
             std::string unit, w;
             t.task.column("", &unit, &w);
             return w;
           }() +
           ")";
  return !d->measured.empty();
}

// One row's cells: the settings and the measured values (their sigma, or 0 when the table has none).
bool ReadRow(TableReader &t, const std::vector<std::string> &cells, int line, FitData *d, std::string *why)
{
  CaseOptions                                    settings;
  std::vector<std::pair<size_t, FitMeasurement>> row; // (header column, value)
  for (size_t c = 0; c < cells.size(); ++c) {
    const std::string cell = Trim(cells[c]);
    PetscReal         v    = 0;
    if (cell.empty()) continue; // not set, not measured
    const bool number = ParseNumber(cell, &v);
    if (t.kind[c] == ColumnKind::Option) {
      const OptionSpec *spec = OptionSpecFind("-" + t.header[c]);
      const bool        text = spec && (spec->kind == OptionKind::Text || spec->kind == OptionKind::Choice ||
                                 spec->kind == OptionKind::File);
      if (!number && !text && spec) {
        *why = t.where(line, c) + ": '" + cell + "' is not a number (-" + t.header[c] + " takes a number" +
               (spec->unit.empty() ? "" : ", in " + spec->unit) + ")";
        return false;
      }
      settings.push_back(text || !number ? CaseSetting{t.header[c], 0, cell} : CaseSetting{t.header[c], v});
      continue;
    }
    if (!number) {
      *why = t.where(line, c) + ": '" + cell + "' is not a number";
      return false;
    }
    if (t.kind[c] == ColumnKind::Sigma && !(v > 0)) {
      *why = t.where(line, c) + ": a standard deviation must be > 0; it is " + cell;
      return false;
    }
    if (t.kind[c] == ColumnKind::Measured) {
      FitMeasurement m;
      m.row        = d->rows.size();
      m.column     = (size_t)t.target[c];
      m.y          = v;
      m.sigma      = 0;
      const int sc = t.sigma_of[m.column];
      if (sc >= 0) {
        PetscReal s = 0;
        if (!ParseNumber(cells[(size_t)sc], &s)) {
          *why = t.where(line, (size_t)sc) + ": the value of '" + t.header[c] +
                 "' in this row needs its standard deviation here";
          return false;
        }
        m.sigma = s;
      }
      row.emplace_back(c, m);
    }
  }
  for (auto &cm : row) d->values.push_back(cm.second);
  d->rows.push_back(settings);
  d->line.push_back(line);
  return true;
}

// The weights: a _sigma column, else -fit_sigma's value, else the column's RMS (relative weights).
bool ChooseSigma(const std::string &file, const std::string &sigma_text, FitData *d, std::string *why)
{
  std::map<std::string, PetscReal> given;
  if (!Trim(sigma_text).empty())
    for (const std::string &item : SplitOn(sigma_text, ',')) {
      const size_t      eq   = item.find('=');
      PetscReal         s    = 0;
      const std::string name = Trim(item.substr(0, eq));
      if (eq == std::string::npos || !ParseNumber(item.substr(eq + 1), &s) || !(s > 0)) {
        *why = "-fit_sigma '" + Trim(item) + "' is not COLUMN=SIGMA with SIGMA > 0";
        return false;
      }
      if (std::find(d->measured.begin(), d->measured.end(), name) == d->measured.end()) {
        *why = "-fit_sigma " + name + ": no measured column of -fit_data " + file + " has this name";
        return false;
      }
      given[name] = s;
    }
  bool all_absolute = true;
  d->sigma_text.clear();
  for (size_t c = 0; c < d->measured.size(); ++c) {
    const std::string &name = d->measured[c];
    double             sum = 0, count = 0;
    bool               table = false;
    for (const FitMeasurement &m : d->values)
      if (m.column == c) sum += m.y * m.y, count += 1, table = table || m.sigma > 0;
    std::string how;
    if (table) how = "its " + name + "_sigma column";
    else if (given.count(name)) how = "-fit_sigma " + Num(given[name]);
    else {
      if (count == 0 || sum == 0) {
        *why = "-fit_data " + file + ": the column '" + name + "' has " + (count == 0 ? "no value" : "only zeros") +
               (count == 0
                  ? ""
                  : ": give its standard deviation (a column " + name + "_sigma or -fit_sigma " + name + "=SIGMA)");
        return false;
      }
      how          = "relative, its RMS " + Num(std::sqrt(sum / count));
      all_absolute = false;
    }
    for (FitMeasurement &m : d->values)
      if (m.column == c && !table) m.sigma = given.count(name) ? given[name] : std::sqrt(sum / count);
    d->sigma_text += (d->sigma_text.empty() ? "" : "; ") + name + ": " + how;
  }
  d->absolute = all_absolute;
  return true;
}

} // namespace

bool FitParseData(const std::string &file, const std::string &text, const CaseTask &task, const std::string &sigma,
                  const std::vector<FitParameter> &params, FitData *d, std::string *why)
{
  TableReader              t{file, task, {}, {}, {}, {}};
  std::istringstream       in(text);
  std::vector<std::string> lines;
  int                      lineno = 0;
  *d                              = FitData();
  d->file                         = file;
  d->sha256                       = Sha256Hex(text);
  if (!TextLines(in, &lines, why)) { // a UTF-8 byte order mark skipped (a spreadsheet's CSV), CR line ends read
    *why = "-fit_data " + file + ": " + *why;
    return false;
  }
  for (const std::string &line : lines) {
    ++lineno;
    const std::string s = Trim(line);
    if (s.empty() || s[0] == '#') continue;
    std::vector<std::string> cells = SplitOn(s, ',');
    if (t.header.empty()) {
      for (std::string &c : cells) t.header.push_back(Trim(c));
      if (!ClassifyColumns(t, params, d, why)) return false;
      continue;
    }
    if (cells.size() != t.header.size()) {
      *why = "-fit_data " + file + " line " + std::to_string(lineno) + ": " + std::to_string(cells.size()) +
             " cells, the header has " + std::to_string(t.header.size());
      return false;
    }
    if (!ReadRow(t, cells, lineno, d, why)) return false;
  }
  if (t.header.empty() || d->rows.empty()) {
    *why = "-fit_data " + file + ": " +
           (t.header.empty() ? "no header (a line of column names)" : "no rows after the header");
    return false;
  }
  if (!ChooseSigma(file, sigma, d, why)) return false;
  if (d->values.size() < params.size()) {
    *why = "-fit_data " + file + " has " + std::to_string(d->values.size()) + " measured values for " +
           std::to_string(params.size()) + " parameters: a fit needs at least as many values as parameters";
    return false;
  }
  return true;
}

std::string FitRowText(const FitData &d, size_t row)
{
  std::string text = CaseOptionsText(d.rows[row], false);
  return "row " + std::to_string(row + 1) + " (line " + std::to_string(d.line[row]) +
         (text.empty() ? "" : ": " + text) + ")";
}

} // namespace beamimpact

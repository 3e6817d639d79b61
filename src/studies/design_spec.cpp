// -task design's options and the text of its studies, objective and constraints. See
// design_problem.hpp; docs/design-studies.md describes the syntax.
//
//   -design_studies "rig{beam_pivot=0.1524, ball_speed=60.8, impact_x=0.55:0.75:5} game{...}"
//   -design_objective "max(bbs@game)"        (max, min, mean over the study's points; a study of
//                                             one point: bbs@game)
//   -design_constraints "max(bbcor@rig)<=0.5, drop<=3, diameter<=0.066675"
#include "studies/design.hpp"
#include "studies/design_problem.hpp"

#include "io/text.hpp"
#include "run/results_table.hpp"
#include "studies/sweep_plan.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace beamimpact {

const OptionModule &DesignOptionTable()
{
  static const OptionModule m = {
    "design",
    "beamimpact: -task design (the best design under constraints: TAO over options of the program; "
    "docs/design-studies.md)",
    {
      OptionText("-design_variables", "The design variables: options of the program, NAME=LO:HI[:START][,...] (start: "
                                      "the option's given value, or the middle; log-scaled where HI/LO >= 10)"),
      OptionText("-design_studies",
                 "The studies of each design: NAME{SETTING,...} ..., a setting OPTION=VALUE or an axis "
                 "OPTION=START:STOP:COUNT or a list A;B (the study's points: their product), each point an impact"),
      OptionText("-design_objective",
                 "What the design optimises: REDUCTION(COLUMN@STUDY) (max, min or mean of an impact's results column "
                 "over the study's points; COLUMN@STUDY for a study of one point) or a number of the bat: mass, drop, "
                 "balance, inertia_knob, inertia_pivot, inertia_cm, length, diameter"),
      OptionChoice("-design_goal", "Maximise or minimise -design_objective", {"maximize", "minimize"}, "maximize"),
      OptionText("-design_constraints",
                 "Inequalities the design must satisfy: QUANTITY<=BOUND or QUANTITY>=BOUND, separated by ',' (a "
                 "quantity as in -design_objective; the bound in its unit); a design is feasible when each holds "
                 "within "
                 "-tao_catol of its bound (relative; default 1e-4); an optimum beyond it: INFEASIBLE, exit status 3"),
      OptionChoice("-design_differences",
                   "The differences of the gradients: forward (n + 1 designs) or central (2n + 1)",
                   {"forward", "central"}, "forward"),
      OptionReal("-design_difference_step", "1",
                 "Relative step of a variable for the differences (of its bounds' range at least 1e-3; a log-scaled "
                 "one: a factor 1 + step)",
                 "1e-4", Between(0, 0.1, true, false)),
      OptionReal("-design_pivot", "m",
                 "The rig's pivot from x = 0 for the bat's inertia_pivot (NCAA/NFHS BBCOR: 6 in = 0.1524 m from the "
                 "knob)",
                 "0.1524", NonNegative()),
      OptionReal("-design_xtol", "1",
                 "bqnls, blmvm or almm (at a feasible design) stop when no variable moves by more than this in its "
                 "scaled range [0, 1] from one iteration to the next",
                 "1e-4", Positive()),
      OptionText("-design_options_output",
                 "The optimum as an options file to include (default: -output with .opts; none with -output none)"),
      OptionFlag("-design_quiet", "No line per iteration"),
      OptionFlag("-design_restart",
                 "Compute every run again: forget the runs an earlier design into the same -output kept"),
      OptionInt("-design_stop_after", "Stop with an error after this many runs (a test of the resume; 0: never)", "0",
                NonNegative()),
    },
  };
  return m;
}

PetscErrorCode DesignSettingsFromOptions(MPI_Comm comm, const std::string &output, DesignSettings *s)
{
  const OptionModule &m    = DesignOptionTable();
  PetscInt            goal = 0, diff = 0;
  PetscBool           set_v = PETSC_FALSE, set_s = PETSC_FALSE, set_o = PETSC_FALSE, set_opts = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, m.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_variables", &s->variables, &set_v));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_studies", &s->studies, &set_s));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_objective", &s->objective, &set_o));
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-design_goal", &goal, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_constraints", &s->constraints, NULL));
  PetscCall(OptionsReadChoice(PetscOptionsObject, m, "-design_differences", &diff, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_difference_step", &s->step, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_pivot", &s->pivot, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_xtol", &s->xtol, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_options_output", &s->options_output, &set_opts));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_quiet", &s->quiet, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_restart", &s->restart, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, m, "-design_stop_after", &s->stop_after, NULL));
  PetscOptionsEnd();
  s->maximize = goal == 0;
  s->central  = diff == 1;
  PetscCheck(set_v && !Trim(s->variables).empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task design needs its variables: -design_variables NAME=LO:HI[:START][,...], e.g. -design_variables "
             "\"barrel_wall_thickness=1.5e-3:4e-3\"");
  PetscCheck(set_o && !Trim(s->objective).empty(), comm, PETSC_ERR_ARG_WRONG,
             "-task design needs its objective: -design_objective, e.g. \"max(bbs@game)\" with -design_studies "
             "\"game{impact_x=0.6:0.75:4}\", or a number of the bat (mass)");
  (void)set_s;
  PetscCheck(!set_opts || !Trim(s->options_output).empty(), comm, PETSC_ERR_ARG_WRONG,
             "-design_options_output needs a file name");
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

const std::vector<std::pair<std::string, std::string>> &DesignBatNumbers()
{
  static const std::vector<std::pair<std::string, std::string>> v = {{"mass", "kg"},
                                                                     {"drop", "1"},
                                                                     {"balance", "m"},
                                                                     {"inertia_knob", "kg m^2"},
                                                                     {"inertia_pivot", "kg m^2"},
                                                                     {"inertia_cm", "kg m^2"},
                                                                     {"length", "m"},
                                                                     {"diameter", "m"}};
  return v;
}

namespace {

// The cases of a study: the product of its axes (the first slowest), each a setting.
void StudyCases(const std::vector<SweepAxis> &axes, std::vector<CaseOptions> *cases)
{
  cases->assign(1, CaseOptions());
  for (const SweepAxis &a : axes) {
    std::vector<CaseOptions> next;
    for (const CaseOptions &c : *cases)
      for (size_t k = 0; k < a.values.size(); ++k) {
        CaseOptions e = c;
        e.push_back(a.Text() ? CaseSetting{a.name, 0, a.labels[k]} : CaseSetting{a.name, (double)a.values[k]});
        next.push_back(e);
      }
    *cases = next;
  }
}

} // namespace

bool DesignParseStudies(const std::string &text, std::vector<DesignStudy> *studies, std::string *why)
{
  studies->clear();
  size_t at = 0;
  while (true) {
    const size_t open = text.find('{', at);
    if (open == std::string::npos) {
      if (!Trim(text.substr(at)).empty())
        return *why = "-design_studies: '" + Trim(text.substr(at)) + "' is not NAME{SETTING,...}", false;
      return true;
    }
    const size_t close = text.find('}', open);
    DesignStudy  s;
    s.name = Trim(text.substr(at, open - at));
    if (close == std::string::npos || s.name.empty() ||
        s.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
          std::string::npos)
      return *why = "-design_studies: '" +
                    Trim(text.substr(at, close == std::string::npos ? std::string::npos : close + 1 - at)) +
                    "' is not NAME{SETTING,...} (a name of letters, digits and _)",
             false;
    for (const DesignStudy &o : *studies)
      if (o.name == s.name) return *why = "-design_studies: the study " + s.name + " is given twice", false;
    s.spec = Trim(text.substr(open + 1, close - open - 1));
    std::vector<SweepAxis> axes;
    std::string            w;
    if (!s.spec.empty() && !SweepParseAxes(s.spec, &axes, &w))
      return *why = "-design_studies: the study " + s.name + "{" + s.spec + "}: " + w, false;
    StudyCases(axes, &s.cases);
    studies->push_back(s);
    at = close + 1;
  }
}

bool DesignParseQuantity(const std::string &text, const std::vector<DesignStudy> &studies,
                         std::vector<std::string> *columns, DesignQuantity *q, std::string *why)
{
  q->text            = Trim(text);
  std::string  in    = q->text;
  const size_t paren = in.find('(');
  if (paren != std::string::npos) {
    const std::string r = Trim(in.substr(0, paren));
    if (in.back() != ')') return *why = "'" + q->text + "' is not REDUCTION(COLUMN@STUDY)", false;
    q->reduce = r == "max"  ? DesignReduce::Max
              : r == "min"  ? DesignReduce::Min
              : r == "mean" ? DesignReduce::Mean
                            : DesignReduce::Value;
    if (q->reduce == DesignReduce::Value)
      return *why = "'" + q->text + "': the reduction '" + r + "' is not max, min or mean", false;
    in = Trim(in.substr(paren + 1, in.size() - paren - 2));
  }
  const size_t at = in.find('@');
  if (at == std::string::npos) {
    for (const auto &b : DesignBatNumbers())
      if (in == b.first && q->reduce == DesignReduce::Value) {
        q->bat = b.first, q->unit = b.second, q->study = -1;
        return true;
      }
    std::string names;
    for (const auto &b : DesignBatNumbers()) names += (names.empty() ? "" : ", ") + b.first;
    return *why = "'" + q->text + "' is neither REDUCTION(COLUMN@STUDY) nor COLUMN@STUDY nor a number of the bat (" +
                  names + ")",
           false;
  }
  const std::string col = Trim(in.substr(0, at)), study = Trim(in.substr(at + 1));
  q->study = -1;
  for (size_t k = 0; k < studies.size(); ++k)
    if (studies[k].name == study) q->study = (int)k;
  if (q->study < 0) return *why = "'" + q->text + "': no study " + study + " in -design_studies", false;
  if (q->reduce == DesignReduce::Value && studies[q->study].cases.size() != 1)
    return *why = "'" + q->text + "': the study " + study + " has " + std::to_string(studies[q->study].cases.size()) +
                  " points: say max(...), min(...) or mean(...)",
           false;
  const ResultColumn *c = ImpactResultColumn(col);
  if (!c)
    return *why = "'" + q->text + "': " + col + " is not a column of an impact's results: " + ImpactResultColumnNames(),
           false;
  q->unit   = c->unit;
  auto it   = std::find(columns->begin(), columns->end(), col);
  q->column = (size_t)(it - columns->begin());
  if (it == columns->end()) columns->push_back(col);
  return true;
}

bool DesignParseConstraints(const std::string &text, const std::vector<DesignStudy> &studies,
                            std::vector<std::string> *columns, std::vector<DesignConstraint> *cs, std::string *why)
{
  cs->clear();
  if (Trim(text).empty()) return true;
  size_t at = 0;
  while (at <= text.size()) {
    size_t comma = at, depth = 0; // the next ',' outside parentheses
    while (comma < text.size() && !(text[comma] == ',' && depth == 0))
      depth += text[comma] == '(' ? 1 : text[comma] == ')' ? -1 : 0, ++comma;
    const std::string item = Trim(text.substr(at, comma - at));
    DesignConstraint  c;
    size_t            op = item.find("<=");
    c.upper              = op != std::string::npos;
    if (!c.upper) op = item.find(">=");
    char *end = nullptr;
    errno     = 0;
    if (op != std::string::npos) c.bound = std::strtod(item.c_str() + op + 2, &end);
    if (op == std::string::npos || !end || end == item.c_str() + op + 2 || !Trim(end).empty() || errno ||
        !std::isfinite(c.bound))
      return *why = "-design_constraints: '" + item + "' is not QUANTITY<=BOUND or QUANTITY>=BOUND", false;
    if (!DesignParseQuantity(item.substr(0, op), studies, columns, &c.q, why))
      return *why = "-design_constraints: " + *why, false;
    c.scale = c.bound != 0 ? std::fabs(c.bound) : 1.0;
    cs->push_back(c);
    at = comma + 1;
  }
  return true;
}

std::string DesignConstraint::Name() const
{
  std::string s;
  for (char ch : q.text) s += std::isalnum((unsigned char)ch) ? ch : '_';
  while (!s.empty() && s.back() == '_') s.pop_back();
  std::string t; // no doubled '_'
  for (char ch : s)
    if (!(ch == '_' && !t.empty() && t.back() == '_')) t += ch;
  return t;
}

} // namespace beamimpact

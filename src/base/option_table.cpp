// The option tables, their registry and the checked readers. See option_table.hpp.
#include "base/option_table.hpp"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <strings.h>

namespace beamimpact {

const char *OptionKindName(OptionKind k)
{
  static const char *names[] = {"real", "int", "bool", "text", "choice", "real list", "file"};
  return names[static_cast<int>(k)];
}

static std::string Number(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool OptionRange::Contains(double v) const
{
  if (!std::isfinite(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string OptionRange::Text() const
{
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (!has_lo && !has_hi) return "a finite number";
  if (has_lo && !has_hi) return std::string(lo_open ? "> " : ">= ") + Number(lo);
  if (!has_lo && has_hi) return std::string(hi_open ? "< " : "<= ") + Number(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + Number(lo) + ", " + Number(hi) + (hi_open ? ")" : "]");
}

OptionRange AnyNumber() { return OptionRange(); }
OptionRange Positive() { return Between(0, std::numeric_limits<double>::infinity(), true, false); }
OptionRange NonNegative() { return Between(0, std::numeric_limits<double>::infinity()); }
OptionRange AtLeast(double lo) { return Between(lo, std::numeric_limits<double>::infinity()); }
OptionRange Between(double lo, double hi, bool lo_open, bool hi_open)
{
  OptionRange r;
  r.lo = lo, r.hi = hi, r.lo_open = lo_open, r.hi_open = hi_open;
  return r;
}

std::string OptionSpec::CountText() const
{
  if (count_min > 0 && count_min == count_max)
    return std::to_string(count_min) + (count_min == 1 ? " value" : " values");
  if (count_min > 0 && count_max > 0) return std::to_string(count_min) + " to " + std::to_string(count_max) + " values";
  if (count_min > 1) return "at least " + std::to_string(count_min) + " values";
  if (count_max > 0) return "at most " + std::to_string(count_max) + " values";
  return "one or more values";
}

std::string OptionSpec::Allowed() const
{
  const std::string u = unit.empty() || unit == "1" ? "" : " (" + unit + ")";
  switch (kind) {
  case OptionKind::Real:
    return "it must be " + (range_text.empty() ? range.Text() : range_text) + u;
  case OptionKind::Int:
    return "it must be a whole number " + (range_text.empty() ? range.Text() : range_text);
  case OptionKind::RealList:
    return "it takes " + CountText() + " separated by commas, each " +
           (range_text.empty() ? range.Text() : range_text) + u;
  case OptionKind::Choice: {
    std::string s;
    for (const std::string &c : choices) s += (s.empty() ? "" : ", ") + c;
    return "use one of " + s + (range_text.empty() ? "" : " (" + range_text + ")");
  }
  default:
    return range_text.empty() ? "see -help" : range_text;
  }
}

OptionSpec OptionReal(const char *name, const char *unit, const char *help, const char *def, OptionRange range)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::Real, s.unit = unit, s.help = help, s.def = def, s.range = range;
  return s;
}

OptionSpec OptionInt(const char *name, const char *help, const char *def, OptionRange range)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::Int, s.unit = "1", s.help = help, s.def = def, s.range = range;
  return s;
}

OptionSpec OptionFlag(const char *name, const char *help)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::Bool, s.help = help, s.def = "false";
  return s;
}

OptionSpec OptionText(const char *name, const char *help, const char *def)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::Text, s.help = help, s.def = def;
  return s;
}

OptionSpec OptionFile(const char *name, const char *help)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::File, s.help = help;
  return s;
}

OptionSpec OptionChoice(const char *name, const char *help, std::vector<std::string> choices, const char *def)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::Choice, s.help = help, s.choices = std::move(choices), s.def = def;
  return s;
}

OptionSpec OptionNeeds(OptionSpec s, std::vector<std::string> needs)
{
  s.needs = std::move(needs);
  return s;
}

OptionSpec OptionList(const char *name, const char *unit, const char *help, PetscInt count_min, PetscInt count_max,
                      OptionRange range)
{
  OptionSpec s;
  s.name = name, s.kind = OptionKind::RealList, s.unit = unit, s.help = help, s.count_min = count_min,
  s.count_max = count_max, s.range = range;
  return s;
}

const OptionSpec *OptionModule::Find(const std::string &option) const
{
  for (const OptionSpec &s : options)
    if (s.name == option) return &s;
  return nullptr;
}

namespace {

std::vector<const OptionModule *> &Registry()
{
  static std::vector<const OptionModule *> modules;
  return modules;
}

std::map<std::string, OptionUsed> &UsedLog()
{
  static std::map<std::string, OptionUsed> used;
  return used;
}

} // namespace

void OptionModuleRegister(const OptionModule *m)
{
  auto &r = Registry();
  for (const OptionModule *q : r)
    if (q == m || q->name == m->name) return;
  r.push_back(m);
}

const std::vector<const OptionModule *> &OptionModules() { return Registry(); }

const OptionSpec *OptionSpecFind(const std::string &name)
{
  const std::string n = !name.empty() && name[0] == '-' ? name : "-" + name;
  for (const OptionModule *m : Registry())
    if (const OptionSpec *s = m->Find(n)) return s;
  return nullptr;
}

const OptionModule *OptionModuleOf(const std::string &name)
{
  const std::string n = !name.empty() && name[0] == '-' ? name : "-" + name;
  for (const OptionModule *m : Registry())
    if (m->Find(n)) return m;
  return nullptr;
}

std::string Fmt(const char *format, ...)
{
  char    buf[1024];
  va_list ap;
  va_start(ap, format);
  std::vsnprintf(buf, sizeof buf, format, ap);
  va_end(ap);
  return buf;
}

double Shown(double v, int decimals) { return std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v; }

std::string ShortestText(double v)
{
  char buf[64], whole[400];
  int  first = 1; // no fewer digits than the shortest decimal that reads back (to_chars'): ~10x fewer tries
  if (std::isfinite(v)) {
    char       s[64];
    const auto r = std::to_chars(s, s + sizeof s, v, std::chars_format::scientific);
    first        = 0;
    for (const char *c = s; c < r.ptr && *c != 'e'; ++c) first += *c >= '0' && *c <= '9';
  }
  for (int digits = std::max(first, 1); digits <= 17; ++digits) { // %.17g always reads back (IEEE double)
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v || std::isnan(v)) break;
  }
  // a whole number %g puts in exponent form (1.17640458049676e+16): its digits when shorter
  if (std::isfinite(v) && v == std::floor(v) && std::snprintf(whole, sizeof whole, "%.0f", v) < (int)std::strlen(buf))
    return whole;
  return buf;
}

std::vector<std::string> OptionNames()
{
  std::vector<std::string> names;
  for (const OptionModule *m : Registry())
    for (const OptionSpec &s : m->options) names.push_back(s.name);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::string OptionUnit(const std::string &name)
{
  const OptionSpec *s = OptionSpecFind(name);
  if (!s) return "";
  return s->kind == OptionKind::Real || s->kind == OptionKind::Int || s->kind == OptionKind::RealList ? s->unit : "";
}

const std::map<std::string, OptionUsed> &OptionsUsed() { return UsedLog(); }
void                                     OptionsUsedClear() { UsedLog().clear(); }

std::string OptionWritten(const char *name)
{
  const char *value = nullptr;
  PetscBool   set   = PETSC_FALSE;
  if (PetscOptionsFindPair(NULL, NULL, name, &value, &set) || !set || !value) return "";
  return value;
}

namespace {

// PETSc's -help prints each option's manual page in parentheses after its help: ours is the
// generated reference of every option (its units, defaults and what each needs).
constexpr const char *kHelpWhere = "docs/options.md";

// One condition of a row's `needs`: "-other" (that option given), "-other=value" or
// "-other!=value" (its value as used; a number compared as a number: "-impact_offset!=0").
struct NeedCondition {
  std::string other, value;
  bool        has_value = false, negated = false;
};

NeedCondition NeedParse(const std::string &c)
{
  NeedCondition n;
  const size_t  eq = c.find('=');
  n.has_value      = eq != std::string::npos;
  n.negated        = n.has_value && eq > 0 && c[eq - 1] == '!';
  n.other          = c.substr(0, n.has_value ? eq - (n.negated ? 1 : 0) : std::string::npos);
  if (n.has_value) n.value = c.substr(eq + 1);
  return n;
}

bool NeedMet(const NeedCondition &n, const OptionUsed &o)
{
  if (!n.has_value) return o.given;
  bool equal = o.text == n.value;
  if (o.kind == OptionKind::Real || o.kind == OptionKind::Int) {
    char        *end = nullptr;
    const double v   = std::strtod(n.value.c_str(), &end);
    if (end && *end == '\0') equal = o.number == v;
  }
  return equal != n.negated;
}

// "-beam_theory timoshenko", "-impact_offset not 0", "-grip"
std::string NeedText(const NeedCondition &n)
{
  return n.other + (n.has_value ? (n.negated ? " not " : " ") + n.value : "");
}

// The options given that a run found without effect for reasons no row states (OptionWithoutEffectSet).
std::map<std::string, OptionWithoutEffect> &NotedLog()
{
  static std::map<std::string, OptionWithoutEffect> noted;
  return noted;
}

} // namespace

void OptionWithoutEffectSet(const std::string &name, const std::string &why, const std::vector<std::string> &needs)
{
  if (why.empty()) NotedLog().erase(name);
  else NotedLog()[name] = {name, "", why, needs};
}

std::vector<OptionWithoutEffect> OptionsWithoutEffect()
{
  const std::map<std::string, OptionUsed> &used = UsedLog();
  std::vector<OptionWithoutEffect>         out;
  for (const auto &[name, u] : used) {
    const OptionSpec *s = OptionSpecFind(name);
    if (!s || !u.given || s->needs.empty() || (u.kind == OptionKind::Bool && u.number == 0)) continue;
    for (const std::string &need : s->needs) { // alternatives 'A|B': met when one is
      std::string              why = "it acts only with ", last;
      std::vector<std::string> others;
      bool                     met = false, known = false;
      for (size_t a = 0, b; a <= need.size(); a = b + 1) {
        b                      = std::min(need.find('|', a), need.size());
        const NeedCondition n  = NeedParse(need.substr(a, b - a));
        const auto          it = used.find(n.other);
        why += (a ? " or " : "") + NeedText(n);
        others.push_back(n.other);
        if (it == used.end()) continue; // not read in this run: nothing known
        known = true;
        met   = met || NeedMet(n, it->second);
        if (others.size() == 1 && n.has_value) last = "; " + n.other + " is " + it->second.text;
      }
      if (!known || met) continue;
      out.push_back({name, OptionWritten(name.c_str()), why + (others.size() == 1 ? last : ""), others});
      break;
    }
  }
  for (const auto &[name, o] : NotedLog()) { // given now, and not said above
    PetscBool given = PETSC_FALSE;
    if (PetscOptionsHasName(NULL, NULL, name.c_str(), &given) || !given) continue;
    if (std::none_of(out.begin(), out.end(), [&](const OptionWithoutEffect &e) { return e.name == name; }))
      out.push_back({name, OptionWritten(name.c_str()), o.why, o.needs});
  }
  return out;
}

namespace {

// The row `name` of m, or an internal error (a reader asked for an option its table lacks).
PetscErrorCode Row(const OptionModule &m, const char *name, OptionKind kind, const OptionSpec **s)
{
  PetscFunctionBeginUser;
  *s = m.Find(name);
  PetscCheck(*s, PETSC_COMM_SELF, PETSC_ERR_PLIB, "option %s is not in the option table of module '%s'", name,
             m.name.c_str());
  const bool text_like = kind == OptionKind::Text &&
                         ((*s)->kind == OptionKind::File || (*s)->kind == OptionKind::Choice);
  PetscCheck((*s)->kind == kind || text_like, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "option %s is a %s in the table of module '%s', read as a %s", name, OptionKindName((*s)->kind),
             m.name.c_str(), OptionKindName(kind));
  PetscFunctionReturn(0);
}

std::string HelpWithUnit(const OptionSpec &s)
{
  return s.unit.empty() || s.unit == "1" ? s.help : s.help + " (" + s.unit + ")";
}

void Log(const OptionSpec &s, const std::string &text, double number, const std::vector<double> &list, PetscBool given)
{
  OptionUsed &u = UsedLog()[s.name];
  u.kind        = s.kind;
  u.unit        = s.unit;
  u.text        = text;
  u.number      = number;
  u.list        = list;
  u.given       = given ? true : false;
}

// A number logged with its text, unless its entry already holds this value, given or not (a
// sweep's point reading its module again): the text would be the same.
void LogNumber(const OptionSpec &s, double v, PetscBool given)
{
  const auto &log = UsedLog();
  const auto  it  = log.find(s.name);
  if (it != log.end() && it->second.kind == s.kind && it->second.list.empty() &&
      !std::memcmp(&it->second.number, &v, sizeof v) && it->second.given == (given ? true : false))
    return;
  Log(s, ShortestText(v), v, {}, given);
}

// A whole word parsed as a number (strtod: also inf, nan, 1e3); false if it is not one.
bool ParseReal(const std::string &w, double *v)
{
  if (w.empty()) return false;
  char *end = nullptr;
  errno     = 0;
  *v        = std::strtod(w.c_str(), &end);
  return end && *end == '\0';
}

// What is allowed, said to a value that is no finite number: "it must be a finite number > 0 (m)".
std::string FiniteAllowed(const OptionSpec &s)
{
  const std::string u = s.unit.empty() || s.unit == "1" ? "" : " (" + s.unit + ")";
  if (!s.range_text.empty()) return "it must be a finite number, " + s.range_text + u;
  const bool bounded = std::isfinite(s.range.lo) || std::isfinite(s.range.hi);
  return "it must be a finite number" + (bounded ? " " + s.range.Text() : std::string()) + u;
}

PetscErrorCode CheckReal(const OptionSpec &s, const std::string &written, double v)
{
  PetscFunctionBeginUser;
  // nan and inf parse as numbers but are none here: said so, before the range
  PetscCheck(std::isfinite(v), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %s is not allowed: %s", s.name.c_str(),
             written.c_str(), FiniteAllowed(s).c_str());
  PetscCheck(s.range.Contains(v), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %s is not allowed: %s", s.name.c_str(),
             written.c_str(), s.Allowed().c_str());
  PetscFunctionReturn(0);
}

// The option is in the database without a value ("-impact_x" alone): refused, naming it.
PetscErrorCode CheckHasValue(PetscOptionItems *PetscOptionsObject, const OptionSpec &s, const std::string &written)
{
  PetscBool present = PETSC_FALSE;
  PetscFunctionBeginUser;
  if (!written.empty()) PetscFunctionReturn(0);
  PetscCall(PetscOptionsHasName(PetscOptionsObject->options, PetscOptionsObject->prefix, s.name.c_str(), &present));
  PetscCheck(!present, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s is given without a value: %s", s.name.c_str(),
             s.Allowed().c_str());
  PetscFunctionReturn(0);
}

// Whether PETSc prints this block's help now (PetscOptionsBegin under -help, first time).
bool PrintsHelp(PetscOptionItems *PetscOptionsObject)
{
  return PetscOptionsObject->printhelp && PetscOptionsObject->count == 1 && !PetscOptionsObject->alreadyprinted;
}

// The help text handed to PETSc with a value: with its unit where PETSc prints it (-help) or
// keeps it (a published block's first pass), else none (PETSc does not read it then: a sweep's
// point reads its modules again without building every option's text).
std::string HelpForPetsc(PetscOptionItems *PetscOptionsObject, const OptionSpec &s)
{
  return PrintsHelp(PetscOptionsObject) || PetscOptionsObject->count < 1 ? HelpWithUnit(s) : std::string();
}

} // namespace

PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           PetscReal *value, PetscBool *set)
{
  const OptionSpec *s;
  PetscBool         given = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(Row(m, name, OptionKind::Real, &s));
  const std::string written = OptionWritten(name);
  double            v       = 0;
  PetscCall(CheckHasValue(PetscOptionsObject, *s, written));
  if (!written.empty()) {
    PetscCheck(ParseReal(written, &v), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "%s %s is not allowed: it must be a number; %s", name, written.c_str(), s->Allowed().c_str());
    PetscCall(CheckReal(*s, written, v));
  }
  PetscCall(PetscOptionsReal(name, HelpForPetsc(PetscOptionsObject, *s).c_str(), kHelpWhere, *value, value, &given));
  if (given) *value = v; // PETSc's parse agrees; the checked value is the one kept
  LogNumber(*s, *value, given);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           PetscInt *value, PetscBool *set)
{
  const OptionSpec *s;
  PetscBool         given = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(Row(m, name, OptionKind::Int, &s));
  const std::string written = OptionWritten(name);
  PetscCall(CheckHasValue(PetscOptionsObject, *s, written));
  if (!written.empty()) {
    double v = 0;
    PetscCheck(ParseReal(written, &v) && std::isfinite(v) && v == std::floor(v), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "%s %s is not allowed: %s", name, written.c_str(), s->Allowed().c_str());
    PetscCheck(std::abs(v) <= (double)PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
               "%s %s is not allowed: it is beyond the largest whole number this build of PETSc holds (%" PetscInt_FMT
               "); %s",
               name, written.c_str(), (PetscInt)PETSC_MAX_INT, s->Allowed().c_str());
    PetscCall(CheckReal(*s, written, v));
    // PETSc parses "1e3" as an integer only in some versions: set the plain digits it reads.
    char digits[64];
    std::snprintf(digits, sizeof digits, "%lld", (long long)v);
    if (written != digits) PetscCall(PetscOptionsSetValue(NULL, name, digits));
  }
  PetscCall(PetscOptionsInt(name, HelpForPetsc(PetscOptionsObject, *s).c_str(), kHelpWhere, *value, value, &given));
  Log(*s, std::to_string((long long)*value), (double)*value, {}, given);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           PetscBool *value, PetscBool *set)
{
  const OptionSpec *s;
  PetscBool         given = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(Row(m, name, OptionKind::Bool, &s));
  PetscCall(PetscOptionsBool(name, s->help.c_str(), kHelpWhere, *value, value, &given));
  Log(*s, *value ? "true" : "false", *value ? 1.0 : 0.0, {}, given);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsReadChoice(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                                 PetscInt *index, PetscBool *set)
{
  const OptionSpec *s;
  PetscBool         given = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(Row(m, name, OptionKind::Choice, &s));
  const std::string written = OptionWritten(name);
  if (!written.empty()) {
    bool known = false;
    for (const std::string &c : s->choices) known = known || strcasecmp(c.c_str(), written.c_str()) == 0;
    PetscCheck(known, PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "%s %s is not known: %s", name, written.c_str(),
               s->Allowed().c_str());
  }
  std::vector<const char *> list;
  for (const std::string &c : s->choices) list.push_back(c.c_str());
  PetscCall(PetscOptionsEList(name, s->help.c_str(), kHelpWhere, list.data(), (PetscInt)list.size(), list[*index],
                              index, &given));
  Log(*s, s->choices[*index], (double)*index, {}, given);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           std::string *value, PetscBool *set)
{
  const OptionSpec *s;

  PetscFunctionBeginUser;
  PetscCall(Row(m, name, OptionKind::Text, &s));
  if (s->kind == OptionKind::Choice) {
    PetscInt index = 0;
    for (size_t k = 0; k < s->choices.size(); ++k)
      if (strcasecmp(s->choices[k].c_str(), value->c_str()) == 0) index = (PetscInt)k;
    PetscCall(OptionsReadChoice(PetscOptionsObject, m, name, &index, set));
    *value = s->choices[index];
    PetscFunctionReturn(0);
  }
  PetscBool         given = PETSC_FALSE;
  std::vector<char> buf(std::max<size_t>(PETSC_MAX_PATH_LEN, OptionWritten(name).size() + 1) + 1,
                        0); // a long text (a sweep's axes) is read whole
  std::snprintf(buf.data(), buf.size(), "%s", value->c_str());
  PetscCall(PetscOptionsString(name, s->help.c_str(), kHelpWhere, buf.data(), buf.data(), buf.size(), &given));
  if (given) {
    const std::string written = OptionWritten(name);
    PetscCheck(written.size() < buf.size() - 1, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "%s: the value is longer than %d characters", name, (int)buf.size() - 2);
    PetscCheck(!(s->kind == OptionKind::File && buf[0] == '\0'), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "%s needs a file name", name);
  }
  *value = buf.data();
  Log(*s, *value, 0, {}, given);
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           std::vector<PetscReal> *value, PetscBool *set)
{
  const OptionSpec *s;
  PetscBool         present = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(Row(m, name, OptionKind::RealList, &s));
  // Parsed here, not by PetscOptionsRealArray (a fixed buffer; it reads "0.5,,0.6" as two values
  // and prints an empty default as 0): finding the option marks it used.
  const std::string written = OptionWritten(name);
  PetscCall(PetscOptionsHasName(PetscOptionsObject->options, PetscOptionsObject->prefix, name, &present));
  if (PrintsHelp(PetscOptionsObject)) {
    std::string def;
    for (PetscReal v : *value) def += (def.empty() ? "" : ",") + Number(v);
    PetscCall((*PetscHelpPrintf)(PetscOptionsObject->comm, "  %s <%s>: %s ()\n", name,
                                 def.empty() ? "none" : def.c_str(), HelpWithUnit(*s).c_str()));
  }
  if (present) {
    std::vector<double> parsed;
    PetscCheck(!written.empty(), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s is given without values: %s", name,
               s->Allowed().c_str());
    size_t a = 0;
    for (;;) {
      const size_t      b    = written.find(',', a);
      const std::string item = written.substr(a, b == std::string::npos ? std::string::npos : b - a);
      double            v    = 0;
      PetscCheck(!item.empty(), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
                 "%s %s is not allowed: an empty value between commas; %s", name, written.c_str(),
                 s->Allowed().c_str());
      PetscCheck(ParseReal(item, &v), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
                 "%s %s is not allowed: '%s' is not a number; %s", name, written.c_str(), item.c_str(),
                 s->Allowed().c_str());
      PetscCheck(std::isfinite(v), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
                 "%s %s is not allowed: %s is not a finite number; %s", name, written.c_str(), item.c_str(),
                 s->Allowed().c_str());
      PetscCheck(s->range.Contains(v), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %s is not allowed: %s; %s", name,
                 written.c_str(), item.c_str(), s->Allowed().c_str());
      parsed.push_back(v);
      if (b == std::string::npos) break;
      a = b + 1;
    }
    const PetscInt n = (PetscInt)parsed.size();
    PetscCheck(!(s->count_min > 0 && n < s->count_min) && !(s->count_max > 0 && n > s->count_max), PETSC_COMM_SELF,
               PETSC_ERR_ARG_WRONG, "%s %s is not allowed (%" PetscInt_FMT " value%s): %s", name, written.c_str(), n,
               n == 1 ? "" : "s", s->Allowed().c_str());
    *value = std::vector<PetscReal>(parsed.begin(), parsed.end());
  }
  std::string text;
  for (PetscReal v : *value) text += (text.empty() ? "" : ",") + ShortestText(v);
  Log(*s, text, 0, std::vector<double>(value->begin(), value->end()), present);
  if (set) *set = present;
  PetscFunctionReturn(0);
}

bool OptionIsPetsc(const std::string &name)
{
  for (const OptionModule *m : Registry())
    if (m->petsc)
      for (const std::string &p : m->prefixes)
        if (name.compare(0, p.size(), p) == 0) return true;
  return false;
}

PetscErrorCode OptionsCheckGiven(const OptionModule &m)
{
  PetscFunctionBeginUser;
  for (const OptionSpec &s : m.options) {
    const std::string written = OptionWritten(s.name.c_str());
    if (written.empty()) continue; // not given, or a flag
    if (s.kind == OptionKind::Real) {
      double v;
      PetscCheck(ParseReal(written, &v), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
                 "%s %s is not allowed: it must be a number; %s", s.name.c_str(), written.c_str(), s.Allowed().c_str());
      PetscCall(CheckReal(s, written, v));
    } else if (s.kind == OptionKind::Choice)
      PetscCheck(std::find(s.choices.begin(), s.choices.end(), written) != s.choices.end(), PETSC_COMM_SELF,
                 PETSC_ERR_ARG_WRONG, "%s %s is not allowed: %s", s.name.c_str(), written.c_str(), s.Allowed().c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OptionModulePrintHelp(MPI_Comm comm, const OptionModule &m)
{
  PetscBool help = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (!help) PetscFunctionReturn(0);
  PetscCall((*PetscHelpPrintf)(comm, "----------------------------------------\n%s:\n", m.title.c_str()));
  for (const OptionSpec &s : m.options) {
    std::string line = "  " + s.name + " <" + (s.def.empty() ? "none" : s.def) + ">: " + HelpWithUnit(s);
    if (s.kind == OptionKind::Choice) {
      line += " (choose one of)";
      for (const std::string &c : s.choices) line += " " + c;
    }
    PetscCall((*PetscHelpPrintf)(comm, "%s ()\n", line.c_str()));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

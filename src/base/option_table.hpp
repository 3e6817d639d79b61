// One option table per module: every option the program reads is one row of its module's table
// (name, kind, unit, help, default, allowed values), and that row is the only description of it.
// It feeds
//   * -help: a module's reader reads each option through OptionRead*, which hands PETSc the
//     row's help text with its unit, inside the module's PetscOptionsBegin block;
//   * the check of unknown options (base/options_util.hpp): the known names are the rows of the
//     registered tables, nothing is captured and nothing calls up into the application;
//   * a sweep's axes: the unit of a numeric axis, the choices of a categorical one;
//   * the run record: every value a reader read, as used, with its unit (OptionsUsed);
//   * the options reference docs/options.md (app/docs_markdown.hpp: -help_markdown options).
// A read checks the value against the row (finite, in range, a known choice, a list of the
// right length without empty items; NaN and inf are never numbers here) and an error names the
// option, the value as written and what is allowed: "-impact_window nan is not allowed: it must
// be a finite number (s)". Tables are plain data; a module registers its table once
// (OptionModuleRegister, from app/registry.cpp; the tests register the same list).
#pragma once

#include <petscsys.h>

#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace beamimpact {

enum class OptionKind {
  Real,
  Int,
  Bool,
  Text,
  Choice,
  RealList,
  File
};
const char *OptionKindName(OptionKind k);

// The values a number may take: [lo, hi], each end open or closed (NaN is never allowed; an
// infinite end means no bound and excludes inf itself).
struct OptionRange {
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool   lo_open = false, hi_open = false;
  bool   Contains(double v) const;
  // "> 0", ">= 1", "in (0, 1]", "any finite number"
  std::string Text() const;
};
OptionRange AnyNumber();
OptionRange Positive();         // > 0
OptionRange NonNegative();      // >= 0
OptionRange AtLeast(double lo); // >= lo
OptionRange Between(double lo, double hi, bool lo_open = false, bool hi_open = false);

struct OptionSpec {
  std::string name; // with the dash: "-ball_k"
  OptionKind  kind = OptionKind::Real;
  std::string unit;  // of a number ("N/m"; "1": dimensionless); "" for text, files, flags
  std::string help;  // one sentence; -help prints it with the unit
  std::string def;   // the default as -help prints it ("2e4", "linear"); "" when none (not given: the feature is off)
  OptionRange range; // Real, Int, RealList values
  std::vector<std::string> choices;                      // Choice: the allowed names (index 0 first)
  PetscInt                 count_min = 0, count_max = 0; // RealList: the number of values allowed (0: any)
  std::string range_text; // what is allowed, in words, when range.Text() is not enough (a Choice: why these)
  // When the option acts at all: every condition must hold, each "-other" (that option given),
  // "-other=value" or "-other!=value" (that option's value as used, e.g.
  // "-beam_theory=timoshenko", "-ball_friction!=0": a number compared as a number), or
  // alternatives "A|B" (one of them holds). Empty: always. An option given where a condition
  // fails has no effect: a note (OptionsWithoutEffect).
  std::vector<std::string> needs;
  std::string              Allowed() const;   // the words of an error message: "it must be > 0 (N/m)"
  std::string              CountText() const; // a RealList's number of values: "2 values", "one or more values"
};

// Rows, built readably (the row's fields in order: name, unit, help, default, range).
OptionSpec OptionReal(const char *name, const char *unit, const char *help, const char *def,
                      OptionRange range = AnyNumber());
OptionSpec OptionInt(const char *name, const char *help, const char *def, OptionRange range = AnyNumber());
OptionSpec OptionFlag(const char *name, const char *help);
OptionSpec OptionText(const char *name, const char *help, const char *def = "");
OptionSpec OptionFile(const char *name, const char *help);
OptionSpec OptionChoice(const char *name, const char *help, std::vector<std::string> choices, const char *def);
OptionSpec OptionList(const char *name, const char *unit, const char *help, PetscInt count_min, PetscInt count_max,
                      OptionRange range = AnyNumber());
// The row with its conditions (OptionSpec::needs): OptionNeeds(OptionReal(...), {"-grip"}).
OptionSpec OptionNeeds(OptionSpec s, std::vector<std::string> needs);

struct OptionModule {
  OptionModule() = default;
  OptionModule(std::string name_, std::string title_, std::vector<OptionSpec> options_, bool petsc_ = false,
               std::vector<std::string> prefixes_ = {}) :
    name(std::move(name_)),
    title(std::move(title_)),
    options(std::move(options_)),
    petsc(petsc_),
    prefixes(std::move(prefixes_))
  {
  }
  std::string             name;  // "ball"
  std::string             title; // the -help block's title
  std::vector<OptionSpec> options;
  // A table of options PETSc's own objects read (TSSetFromOptions, SNESSetFromOptions, ...),
  // listed so that -help, the unknown-option check and the sweep know them; no OptionsRead of
  // the program reads them. `prefixes` ("-ts_", ...) are the names such a table speaks for: an
  // unread option under one of them is PETSc's (a note when left over, an error only when it is
  // close to a known name: a typo).
  bool                     petsc = false;
  std::vector<std::string> prefixes;
  const OptionSpec        *Find(const std::string &option) const; // nullptr if not a row
};

// The registry of every module's table (app/registry.cpp registers them, once per process; a
// second registration of the same module is ignored).
void                                     OptionModuleRegister(const OptionModule *m);
const std::vector<const OptionModule *> &OptionModules();
const OptionSpec                        *OptionSpecFind(const std::string &name); // any module; nullptr if none
const OptionModule *OptionModuleOf(const std::string &name); // the module whose table has it; nullptr if none
// v as the shortest text that reads back (strtod) as exactly v: "0.06", not %.17g's
// "0.059999999999999998"; what a user would write, and the same double.
std::string ShortestText(double v);
// printf into a std::string (a message, a summary line, an options file's header; at most 1023
// characters).
std::string Fmt(const char *format, ...) __attribute__((format(printf, 1, 2)));
// v for printing with %.<decimals>f: +0 where it rounds to 0 there (-1e-17 prints "0.0000", not
// "-0.0000"), else v.
double                   Shown(double v, int decimals);
std::vector<std::string> OptionNames();          // every registered name (with the dash), sorted
std::string OptionUnit(const std::string &name); // "" when unknown or not a number; name with or without dash
// Whether `name` (with the dash) falls under a prefix of a registered PETSc table (-ts_, -snes_, ...).
bool OptionIsPetsc(const std::string &name);

// A table no reader reads (PETSc's: `petsc`): each of its number and choice rows given in the
// options database is checked as a reader checks it (a number, finite, in the row's range; one
// of its choices), so that a bad value is refused naming the option, the value as written and
// what is allowed, before PETSc reads it in its own words ("Unknown TS type").
PetscErrorCode OptionsCheckGiven(const OptionModule &m);

// Under -help, prints a table no reader reads (PETSc's: `petsc`) as a block of PETSc's -help
// format ("  -name <default>: help (unit)"), so that -help lists it; nothing otherwise.
PetscErrorCode OptionModulePrintHelp(MPI_Comm comm, const OptionModule &m);

// The values the readers read in this process, as used (default or given), by option name:
// the run record writes them. A later read of the same option replaces its entry.
struct OptionUsed {
  OptionKind          kind = OptionKind::Real;
  std::string         unit, text;    // text: the value as a string (numbers %.17g; lists comma-separated)
  double              number = 0;    // Real, Int, Bool (0/1), Choice (the index)
  std::vector<double> list;          // RealList
  bool                given = false; // set in the options database (not the default)
};
const std::map<std::string, OptionUsed> &OptionsUsed();
void                                     OptionsUsedClear();

// The options given in this process that have no effect: a row whose `needs` fail against the
// values read (a condition on an option no reader read is taken as met: nothing is known), and
// those a run said so of (OptionWithoutEffectSet). Each entry: the option (with the dash), its
// value as written, and why ("it acts only with -grip", "it acts only with -beam_theory
// timoshenko; -beam_theory is euler").
struct OptionWithoutEffect {
  std::string              name, written, why;
  std::vector<std::string> needs; // the options of the condition that fails ("-grip"; each of "A|B")
};
std::vector<OptionWithoutEffect> OptionsWithoutEffect();
// A run's own finding that option `name` (with the dash), when given, has no effect, for a reason
// no row's `needs` can state (the impact's -ts_rtol under a fixed step: why "the step is fixed:
// -ts_type modal", needs {"-ts_type", "-ts_adapt_type"}, the options that would give it one). It
// stays until the run says otherwise: an empty why withdraws it.
void OptionWithoutEffectSet(const std::string &name, const std::string &why,
                            const std::vector<std::string> &needs = {});

// Readers, inside a module's PetscOptionsBegin/End block (PetscOptionsObject is the block's).
// Each finds `name` in the module's table (an internal error if it is not a row), hands PETSc
// the help with the unit and *value as the default shown, checks a given value against the row,
// and logs the value used. *set (may be NULL) says whether the option was given.
PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           PetscReal *value, PetscBool *set);
PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           PetscInt *value, PetscBool *set);
PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           PetscBool *value, PetscBool *set);
// Text, File and Choice rows: a Choice is checked against the row's choices (the error lists them).
PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           std::string *value, PetscBool *set);
// A Choice row as the index of the choice.
PetscErrorCode OptionsReadChoice(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                                 PetscInt *index, PetscBool *set);
// A RealList row: any length (no fixed limit), each value checked, the count checked against
// the row, an empty item ("0.5,,0.6") refused. Under -help its line shows *value ("<none>" when
// empty) as the default.
PetscErrorCode OptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &m, const char *name,
                           std::vector<PetscReal> *value, PetscBool *set);

// The value of option `name` as written in the options database ("" when not set), for messages.
std::string OptionWritten(const char *name);

} // namespace beamimpact

// Options files (includes and file paths relative to the including file, comments, quotes,
// cycles), the closest-option suggestion for a misspelt name, and the option tables: every row
// in -help with the default it states, every option -help prints a row, the checks a row makes
// (list counts, empty items, NaN), the unknown-option check, the run record of the values read.
#include "app/tasks.hpp"
#include "base/option_table.hpp"
#include "base/options_util.hpp"
#include "io/options_files.hpp"
#include "io/run_record.hpp"
#include "io/scenario_options.hpp"
#include "io/text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <strings.h>
#include <unistd.h>
#include <vector>

using namespace beamimpact;

namespace {

std::string Scratch()
{
  char tmpl[] = "/tmp/beamimpact-options-XXXXXX";
  EXPECT_NE(nullptr, mkdtemp(tmpl));
  return tmpl;
}

void Write(const std::string &path, const std::string &text)
{
  std::ofstream(path) << text;
}

} // namespace

TEST(OptionsFiles, IncludesAndPathsRelativeToTheirFile)
{
  const std::string d = Scratch();
  ASSERT_EQ(0, system(("mkdir -p " + d + "/scenes " + d + "/bats").c_str()));
  Write(d + "/scenes/s.opts", "# a scene\n-options_file ../bats/b.opts   # the bat\n-sweep \"ball_speed=1:2:3, impact_x=0.5\"\n-impact_x 0.25\r\n-ts_dt -1e-3\n");
  Write(d + "/bats/b.opts", "-beam_profile b.profile\n-convergence_configs x.opts,/abs/y.opts,../z.opts\n");
  std::vector<std::string> t;
  std::string              err;
  ASSERT_TRUE(OptionsFileExpand(d + "/scenes/s.opts", &t, &err)) << err;
  const std::vector<std::string> want = {"-beam_profile", d + "/bats/b.profile", "-convergence_configs", d + "/bats/x.opts,/abs/y.opts," + d + "/z.opts", "-sweep", "ball_speed=1:2:3, impact_x=0.5", "-impact_x", "0.25", "-ts_dt", "-1e-3"};
  EXPECT_EQ(want, t);

  // On the command line a path stays relative to the working directory; other arguments are kept.
  std::vector<std::string> args;
  ASSERT_TRUE(OptionsArgsExpand({"-task", "impact", "-options_file", d + "/bats/b.opts", "-beam_profile", "here.profile"}, &args, &err)) << err;
  EXPECT_EQ(8u, args.size());
  EXPECT_EQ("here.profile", args.back());
}

TEST(OptionsFiles, MissingIncludeAndCycleNameTheFiles)
{
  const std::string d = Scratch();
  Write(d + "/a.opts", "-options_file missing.opts\n");
  std::vector<std::string> t;
  std::string              err;
  EXPECT_FALSE(OptionsFileExpand(d + "/a.opts", &t, &err));
  EXPECT_NE(std::string::npos, err.find("-options_file " + d + "/missing.opts (included by " + d + "/a.opts:1): cannot open the file")) << err;
  Write(d + "/loop.opts", "-beam_nodes 5\n-options_file loop.opts\n");
  err.clear();
  EXPECT_FALSE(OptionsFileExpand(d + "/loop.opts", &t, &err));
  EXPECT_NE(std::string::npos, err.find("includes nested deeper than")) << err;
}

// PETSc reads one option per line: a stray word or a second value is refused with file:line,
// not dropped (the command-line parser would skip it without a word).
TEST(OptionsFiles, StrayWordsAreRefused)
{
  const std::string d = Scratch();
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"-beam_nodes 21\n-impact_x 0.3 0.4\n", ":2: -impact_x has more than one value ('0.3', '0.4')"},
    {"# x\nimpact_x 0.3\n", ":2: 'impact_x' is not an option (an option starts with '-': -impact_x?)"},
    {"-options_file\n", ":1: -options_file needs a file name"},
  };
  for (auto &c : cases) {
    Write(d + "/bad.opts", c.first);
    std::vector<std::string> t;
    std::string              err;
    EXPECT_FALSE(OptionsFileExpand(d + "/bad.opts", &t, &err)) << c.first;
    EXPECT_NE(std::string::npos, err.find(d + "/bad.opts" + c.second)) << err;
  }
  std::vector<std::string> args;
  std::string              err;
  EXPECT_FALSE(OptionsArgsExpand({"-task", "impact", "-options_file"}, &args, &err));
  EXPECT_EQ("-options_file needs a file name", err);
  EXPECT_FALSE(OptionsArgsExpand({"-options_file", "-output", "x.h5"}, &args, &err));
}

TEST(OptionsClosest, SuggestsOnlyNearNames)
{
  const std::vector<std::string> known = {"-beam_length", "-beam_nodes", "-ball_speed", "-ball_k", "-impact_x", "-sweep_x"};
  EXPECT_EQ("-beam_length", OptionsClosest("-beam_lenght", known)); // a swap
  EXPECT_EQ("-beam_nodes", OptionsClosest("-beam_node", known));    // a deletion
  EXPECT_EQ("-impact_x", OptionsClosest("-impactx", known));        // an insertion
  EXPECT_EQ("-ball_speed", OptionsClosest("-ball_spede", known));
  EXPECT_EQ("", OptionsClosest("-no_such_thing", known));
  EXPECT_EQ("", OptionsClosest("-beam_width", known)); // 4+ edits from anything
}

// ---------------------------------------------------------------------------------------------
// The option tables
// ---------------------------------------------------------------------------------------------

namespace {

std::string *g_capture = nullptr;

PetscErrorCode CaptureHelp(MPI_Comm, const char format[], ...)
{
  va_list args;
  va_start(args, format);
  char buf[8192];
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  if (g_capture) *g_capture += buf;
  return 0;
}

PetscErrorCode CaptureVF(FILE *, const char format[], va_list args)
{
  char buf[8192];
  std::vsnprintf(buf, sizeof buf, format, args);
  if (g_capture) *g_capture += buf;
  return 0;
}

// What f() prints through PETSc (help lines and PetscPrintf), instead of printing it.
template <class F>
std::string Captured(F f)
{
  std::string text;
  auto        help = PetscHelpPrintf;
  auto        vf   = PetscVFPrintf;
  g_capture        = &text;
  PetscHelpPrintf  = CaptureHelp;
  PetscVFPrintf    = CaptureVF;
  f();
  PetscHelpPrintf = help;
  PetscVFPrintf   = vf;
  g_capture       = nullptr;
  return text;
}

// The -help listing of the program, parsed: option name -> the defaults it shows, in the order
// listed (PETSc's formats: "<1.1 : 1.1>", "<now 41 : formerly 41>", ": <FALSE : FALSE>", the
// tables' "<none>"; PETSc's options are listed by PETSc's objects, then by the PETSc table).
std::map<std::string, std::vector<std::string>> HelpListing(std::string *text)
{
  PetscOptionsHelpPrinted printed = PetscOptionsHelpPrintedSingleton; // print every block again
  PetscOptionsHelpPrintedSingleton = NULL;
  EXPECT_EQ(0, PetscOptionsSetValue(NULL, "-help", NULL));
  *text = Captured([] { EXPECT_EQ(0, PrintAllOptions(PETSC_COMM_WORLD)); });
  EXPECT_EQ(0, PetscOptionsClearValue(NULL, "-help"));
  PetscOptionsHelpPrintedDestroy(&PetscOptionsHelpPrintedSingleton);
  PetscOptionsHelpPrintedSingleton = printed;
  std::map<std::string, std::vector<std::string>> shown;
  std::istringstream                              lines(*text);
  for (std::string line; std::getline(lines, line);) {
    if (line.compare(0, 3, "  -") != 0) continue;
    const size_t end = line.find_first_of(" :<", 2);
    const std::string name = line.substr(2, end - 2);
    const size_t      a = line.find('<', end), b = a == std::string::npos ? a : line.find('>', a);
    if (b == std::string::npos) continue;
    std::string d = line.substr(a + 1, b - a - 1);
    if (d.compare(0, 4, "now ") == 0) d = d.substr(4);
    shown[name].push_back(d.substr(0, d.find(" : ")));
  }
  return shown;
}

bool SameDefault(const OptionSpec &s, const std::string &shown)
{
  switch (s.kind) {
  case OptionKind::Real:
  case OptionKind::Int: {
    const double a = std::strtod(s.def.c_str(), nullptr), b = std::strtod(shown.c_str(), nullptr);
    return std::abs(a - b) <= 1e-5 * std::abs(a); // -help prints %g
  }
  case OptionKind::RealList: return shown == (s.def.empty() ? "none" : s.def);
  default: return strcasecmp(s.def.c_str(), shown.c_str()) == 0;
  }
}

} // namespace

// Every row of every registered table is in -help, and the default -help shows (the value the
// code starts from) is the one the row states: the table and the code's defaults agree.
TEST(OptionTables, EveryRowIsInHelpWithTheDefaultItStates)
{
  std::string text;
  const auto  shown = HelpListing(&text);
  ASSERT_GT(shown.size(), 100u) << text.substr(0, 2000);
  int checked = 0;
  for (const OptionModule *m : OptionModules())
    for (const OptionSpec &s : m->options) {
      const auto it = shown.find(s.name);
      ASSERT_NE(shown.end(), it) << s.name << " (module " << m->name << ") is not in -help";
      if (s.def.empty() && s.kind != OptionKind::Text && s.kind != OptionKind::File && s.kind != OptionKind::RealList) continue; // no default: the feature is off
      // the program's readers list an option once, with the value the code starts from; the
      // PETSc table's block (last) lists PETSc's options with the program's defaults
      const std::string &d = m->petsc ? it->second.back() : it->second.front();
      EXPECT_TRUE(SameDefault(s, d)) << s.name << ": the row says '" << s.def << "', -help shows '" << d << "'";
      checked++;
    }
  EXPECT_GT(checked, 60);
  EXPECT_NE(std::string::npos, text.find("  -ts_modal_order <4>")) << "-ts_modal_order is read only under -ts_type modal, and -help lists it";
}

// Every option the program's own blocks print is a row of some table: nothing is described
// outside the tables (PETSc's blocks, under its prefixes, are PETSc's).
TEST(OptionTables, EveryOptionInHelpIsARow)
{
  std::string text;
  const auto  shown = HelpListing(&text);
  const size_t from = text.find(TaskOptionTable().title + ":");
  ASSERT_NE(std::string::npos, from);
  std::string strays;
  for (const auto &kv : shown)
    if (text.find("  " + kv.first, from) != std::string::npos && !OptionIsPetsc(kv.first) && !OptionSpecFind(kv.first)) strays += " " + kv.first;
  EXPECT_EQ("", strays) << "options -help lists that no table describes";
}

TEST(OptionTables, NamesAreUniqueAndUnitsKnown)
{
  std::map<std::string, std::string> seen;
  for (const OptionModule *m : OptionModules()) {
    for (const OptionSpec &s : m->options) {
      EXPECT_EQ(0u, seen.count(s.name)) << s.name << " is in the tables of " << seen[s.name] << " and " << m->name;
      seen[s.name] = m->name;
      EXPECT_EQ('-', s.name[0]) << s.name;
      EXPECT_FALSE(s.help.empty()) << s.name;
      if (s.kind == OptionKind::Real || s.kind == OptionKind::RealList) {
        EXPECT_FALSE(s.unit.empty()) << s.name << " has no unit";
      }
      if (s.kind == OptionKind::Choice) {
        EXPECT_FALSE(s.choices.empty()) << s.name;
      }
    }
  }
  EXPECT_EQ("m", OptionUnit("impact_x"));
  EXPECT_EQ("m/s", OptionUnit("-bat_speed"));
  EXPECT_EQ("rad/s", OptionUnit("bat_angular_velocity"));
  EXPECT_EQ("m", OptionUnit("grip"));
  EXPECT_EQ("m", OptionUnit("beam_pivot"));
  EXPECT_EQ("s", OptionUnit("ts_dt"));
  EXPECT_EQ("1", OptionUnit("beam_nodes"));
  EXPECT_EQ("", OptionUnit("beam_left")); // a choice
  EXPECT_EQ("", OptionUnit("no_such_option"));
}

namespace {

// A table of the test's own, to test the readers on it.
const OptionModule &TestTable()
{
  static const OptionModule m = {
    "test",
    "Test options",
    {
      OptionReal("-test_length", "m", "A length", "1", Positive()),
      OptionReal("-test_any", "s", "Any time", "-1"),
      OptionInt("-test_count", "A count", "3", AtLeast(1)),
      OptionChoice("-test_kind", "A choice", {"one", "two"}, "one"),
      OptionList("-test_pair", "m", "Two points", 2, 2, NonNegative()),
      OptionList("-test_points", "m", "Points", 1, 0, AnyNumber()),
    },
  };
  return m;
}

struct TestValues {
  PetscReal              length = 1, any = -1;
  PetscInt               count = 3, kind = 0;
  std::vector<PetscReal> pair, points;
};

// Reads the test table with `option value` set; returns the error code and, in *msg, its message.
PetscErrorCode ReadWith(const char *option, const char *value, TestValues *v, std::string *msg)
{
  PetscOptionsSetValue(NULL, option, value);
  PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
  const OptionModule &T    = TestTable();
  PetscErrorCode      ierr = 0;
  [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "test", "");
    ierr = OptionsRead(PetscOptionsObject, T, "-test_length", &v->length, NULL);
    if (!ierr) ierr = OptionsRead(PetscOptionsObject, T, "-test_any", &v->any, NULL);
    if (!ierr) ierr = OptionsRead(PetscOptionsObject, T, "-test_count", &v->count, NULL);
    if (!ierr) ierr = OptionsReadChoice(PetscOptionsObject, T, "-test_kind", &v->kind, NULL);
    if (!ierr) ierr = OptionsRead(PetscOptionsObject, T, "-test_pair", &v->pair, NULL);
    if (!ierr) ierr = OptionsRead(PetscOptionsObject, T, "-test_points", &v->points, NULL);
    PetscOptionsEnd();
    PetscFunctionReturn(0);
  }();
  PetscPopErrorHandler();
  *msg = ierr ? LastErrorMessage(ierr) : "";
  PetscOptionsClearValue(NULL, option);
  return ierr;
}

} // namespace

// What a row refuses, and how it says it: the option, the value as written, what is allowed.
TEST(OptionTables, ARowChecksItsValue)
{
  struct Case {
    const char *option, *value, *message;
  };
  const Case bad[] = {
    {"-test_length", "-1", "-test_length -1 is not allowed: it must be > 0 (m)"},
    {"-test_length", "inf", "-test_length inf is not allowed: it must be a finite number > 0 (m)"},
    {"-test_any", "nan", "-test_any nan is not allowed: it must be a finite number (s)"},
    {"-test_any", "abc", "-test_any abc is not allowed: it must be a number"},
    {"-test_count", "0", "-test_count 0 is not allowed: it must be a whole number >= 1"},
    {"-test_count", "2.5", "-test_count 2.5 is not allowed: it must be a whole number >= 1"},
    {"-test_kind", "three", "-test_kind three is not known: use one of one, two"},
    {"-test_pair", "0.5", "-test_pair 0.5 is not allowed (1 value): it takes 2 values separated by commas, each >= 0 (m)"},
    {"-test_pair", "0,0.1,0.5", "-test_pair 0,0.1,0.5 is not allowed (3 values): it takes 2 values"},
    {"-test_pair", "0.1,-0.2", "-test_pair 0.1,-0.2 is not allowed: -0.2; it takes 2 values"},
    {"-test_points", "0.5,,0.6", "-test_points 0.5,,0.6 is not allowed: an empty value between commas"},
    {"-test_points", "0.5,nan", "-test_points 0.5,nan is not allowed: nan is not a finite number"},
    {"-test_points", "0.5,x", "-test_points 0.5,x is not allowed: 'x' is not a number"},
    {"-test_points", nullptr, "-test_points is given without values"},
    {"-test_any", nullptr, "-test_any is given without a value"},
  };
  for (const Case &c : bad) {
    TestValues  v;
    std::string msg;
    EXPECT_NE(0, ReadWith(c.option, c.value, &v, &msg)) << c.option << " " << (c.value ? c.value : "");
    EXPECT_NE(std::string::npos, msg.find(c.message)) << "got: " << msg;
  }
  TestValues  v;
  std::string msg;
  ASSERT_EQ(0, ReadWith("-test_points", "0.5,-1,1e3", &v, &msg)) << msg;
  EXPECT_EQ((std::vector<PetscReal>{0.5, -1, 1000}), v.points);
  ASSERT_EQ(0, ReadWith("-test_count", "1e3", &v, &msg)) << msg;
  EXPECT_EQ(1000, v.count);
  ASSERT_EQ(0, ReadWith("-test_kind", "TWO", &v, &msg)) << msg;
  EXPECT_EQ(1, v.kind);
  const OptionUsed &u = OptionsUsed().at("-test_kind");
  EXPECT_EQ("two", u.text);
  EXPECT_TRUE(u.given);
  EXPECT_FALSE(OptionsUsed().at("-test_length").given);
  EXPECT_EQ("m", OptionsUsed().at("-test_length").unit);
}

namespace {

// OptionsCheckUnused with these options set (and nothing else unread): its code, its message
// and what it printed.
PetscErrorCode CheckWith(const std::vector<std::pair<const char *, const char *>> &set, std::string *msg, std::string *printed)
{
  for (auto &o : set) PetscOptionsSetValue(NULL, o.first, o.second);
  PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
  PetscErrorCode ierr = 0;
  *printed            = Captured([&] { ierr = OptionsCheckUnused(PETSC_COMM_WORLD); });
  PetscPopErrorHandler();
  *msg = ierr ? LastErrorMessage(ierr) : "";
  for (auto &o : set) PetscOptionsClearValue(NULL, o.first);
  return ierr;
}

} // namespace

TEST(UnusedOptions, AnUnknownOptionIsAnErrorWithTheSuggestion)
{
  std::string msg, printed;
  EXPECT_EQ(PETSC_ERR_ARG_WRONG, CheckWith({{"-beam_thicknes", "0.01"}, {"-no_such_thing", "1"}}, &msg, &printed));
  EXPECT_NE(std::string::npos, msg.find("2 option(s) unknown (set but read by no task): -beam_thicknes 0.01 (did you mean -beam_thickness?) -no_such_thing 1\n")) << msg;
}

TEST(UnusedOptions, AMisspeltPetscOptionIsAnErrorALeftOverOneANote)
{
  std::string msg, printed;
  for (auto typo : {std::make_pair("-ts_dtt", "-ts_dt"), std::make_pair("-ts_rk_tpye", "-ts_rk_type"), std::make_pair("-snes_rtoll", "-snes_rtol"), std::make_pair("-modes_eps_tool", "-modes_eps_tol")}) {
    EXPECT_EQ(PETSC_ERR_ARG_WRONG, CheckWith({{typo.first, "1"}}, &msg, &printed)) << typo.first;
    EXPECT_NE(std::string::npos, msg.find(std::string(typo.first) + " 1 (did you mean " + typo.second + "?)")) << msg;
  }
  // a row of the PETSc table another integrator reads, and a PETSc name close to no row: notes
  EXPECT_EQ(0, CheckWith({{"-ts_rk_type", "4"}, {"-ts_arkimex_fully_implicit", NULL}, {"-ts_sundials_type", "bdf"}}, &msg, &printed)) << msg;
  EXPECT_NE(std::string::npos, printed.find("note: 3 PETSc solver option(s) set but not used by this integrator: -ts_arkimex_fully_implicit -ts_rk_type 4 -ts_sundials_type bdf")) << printed;
  // a known option of the program another task reads: a note
  EXPECT_EQ(0, CheckWith({{"-modes_count", "3"}}, &msg, &printed)) << msg;
  EXPECT_NE(std::string::npos, printed.find("note: 1 option(s) set but not used by this task: -modes_count 3")) << printed;
  // -allow_unused_options: the errors become a warning
  EXPECT_EQ(0, CheckWith({{"-ts_dtt", "1"}, {"-allow_unused_options", NULL}}, &msg, &printed)) << msg;
  EXPECT_NE(std::string::npos, printed.find("WARNING: 1 option(s) unknown (set but read by no task): -ts_dtt 1 (did you mean -ts_dt?)")) << printed;
}

// A summary's number that rounds to 0 prints without a sign: "0.0000", never "-0.0000" (the
// frame's roll of -1e-17 rad/s, a spin of -0), and every other number as it is.
TEST(Shown, NoSignOnARoundedZero)
{
  const auto text = [](double v, int d) { return Fmt("%.*f", d, Shown(v, d)); };
  EXPECT_EQ("0.0000", text(-1e-17, 4));
  EXPECT_EQ("0.0000", text(-0.0, 4));
  EXPECT_EQ("0.0000", text(-4.9e-5, 4));
  EXPECT_EQ("-0.0001", text(-5.1e-5, 4));
  EXPECT_EQ("0", text(-0.4, 0));
  EXPECT_EQ("-1", text(-0.6, 0));
  EXPECT_EQ("0.00", text(-0.0, 2));
  EXPECT_EQ(-3.25, Shown(-3.25, 2));
}

// A number as a user writes it: the shortest text that strtod reads back as the same double
// (the sweep's axis values, /options_used): never longer than %.17g's, and exactly the digits
// a person wrote for decimal inputs (0.06, not 0.059999999999999998).
TEST(ShortestText, ReadsBackExactlyAndIsShortest)
{
  EXPECT_EQ("-0.06", ShortestText(-0.06));
  EXPECT_EQ("0.1", ShortestText(0.1));
  EXPECT_EQ("1", ShortestText(1.0));
  EXPECT_EQ("0", ShortestText(0.0));
  EXPECT_EQ("1e+300", ShortestText(1e300));
  EXPECT_EQ("0.30000000000000004", ShortestText(0.1 + 0.2)); // not 0.3: another double
  std::srand(7);
  for (int k = 0; k < 20000; ++k) {
    const double v = std::ldexp((double)std::rand() / RAND_MAX - 0.5, std::rand() % 200 - 100);
    const std::string t = ShortestText(v);
    char              full[64];
    std::snprintf(full, sizeof full, "%.17g", v);
    ASSERT_EQ(v, std::strtod(t.c_str(), nullptr)) << t;
    ASSERT_LE(t.size(), std::string(full).size()) << t << " against " << full;
  }
  // The definition, digit by digit: the first %.{d}g that reads back (not a whole number here).
  // Powers of two too: their lower rounding gap is half the upper one.
  for (int k = 0; k < 40000; ++k) {
    const double v = k % 2 ? std::ldexp((double)std::rand() / RAND_MAX + 0.5, std::rand() % 600 - 300)
                           : std::ldexp(1.0, std::rand() % 2000 - 1000);
    if (v == std::floor(v)) continue;
    char shortest[64];
    for (int d = 1; d <= 17; ++d) {
      std::snprintf(shortest, sizeof shortest, "%.*g", d, v);
      if (std::strtod(shortest, nullptr) == v) break;
    }
    ASSERT_EQ(std::string(shortest), ShortestText(v));
  }
}

// The run record holds every option the readers read, as used, with its unit: the hands, the
// swing and the damping among them (they had no attribute before).
TEST(RunRecord, CarriesTheOptionsReadWithUnits)
{
  const std::vector<std::pair<const char *, const char *>> set = {
    {"-grip", "0.05,0.2"}, {"-grip_stiffness", "1e5"}, {"-bat_speed", "20"}, {"-beam_damping_mass", "2"}};
  for (auto &o : set) PetscOptionsSetValue(NULL, o.first, o.second);
  Scenario sc;
  ASSERT_EQ(0, ScenarioFromOptions(PETSC_COMM_WORLD, &sc));
  RunRecord rec;
  ASSERT_EQ(0, RunRecordBuild(sc, nullptr, &rec));
  for (auto &o : set) PetscOptionsClearValue(NULL, o.first);
  const auto &u = rec.options_used;
  ASSERT_TRUE(u.count("-grip") && u.count("-grip_stiffness") && u.count("-grip_damping") && u.count("-bat_speed") && u.count("-bat_angular_velocity") && u.count("-beam_damping_mass") &&
              u.count("-beam_pivot"));
  EXPECT_EQ((std::vector<double>{0.05, 0.2}), u.at("-grip").list);
  EXPECT_EQ("m", u.at("-grip").unit);
  EXPECT_TRUE(u.at("-grip").given);
  EXPECT_EQ(1e5, u.at("-grip_stiffness").number);
  EXPECT_EQ("N/m^2", u.at("-grip_stiffness").unit);
  EXPECT_EQ(0, u.at("-grip_damping").number); // its default, as used
  EXPECT_FALSE(u.at("-grip_damping").given);
  EXPECT_EQ(20, u.at("-bat_speed").number);
  EXPECT_EQ("m/s", u.at("-bat_speed").unit);
  EXPECT_EQ("rad/s", u.at("-bat_angular_velocity").unit);
  EXPECT_EQ(2, u.at("-beam_damping_mass").number);
  EXPECT_EQ("1/s", u.at("-beam_damping_mass").unit);
  EXPECT_EQ("m", u.at("-beam_pivot").unit);
  EXPECT_EQ("free", u.at("-beam_left").text);
}

namespace {

// A table whose rows need another option (OptionSpec::needs), registered for the test.
const OptionModule &NeedsTable()
{
  static const OptionModule m = {
    "needs",
    "Test options with conditions",
    {
      OptionList("-needs_grip", "m", "A pair", 2, 2, NonNegative()),
      OptionNeeds(OptionReal("-needs_k", "N/m", "Acts only with -needs_grip", "0", NonNegative()), {"-needs_grip"}),
      OptionChoice("-needs_theory", "A theory", {"euler", "timoshenko"}, "euler"),
      OptionNeeds(OptionReal("-needs_G", "Pa", "Acts only under -needs_theory timoshenko", "", Positive()), {"-needs_theory=timoshenko"}),
      OptionNeeds(OptionReal("-needs_e", "1", "Acts only where -needs_k is not 0", "", Positive()), {"-needs_k!=0"}),
      OptionNeeds(OptionReal("-needs_mu", "1", "Acts only where -needs_k is not 0 or under timoshenko", "0.5", NonNegative()), {"-needs_k!=0|-needs_theory=timoshenko"}),
    },
  };
  return m;
}

// The options without effect after reading the table with `set`.
std::vector<OptionWithoutEffect> NoEffectWith(const std::vector<std::pair<const char *, const char *>> &set)
{
  const OptionModule &T = NeedsTable();
  OptionModuleRegister(&T);
  OptionsUsedClear();
  for (auto &o : set) PetscOptionsSetValue(NULL, o.first, o.second);
  std::vector<PetscReal> grip;
  PetscReal              k = 0, G = 0, e = 1, mu = 0.5;
  PetscInt               theory = 0;
  EXPECT_EQ(0, [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "needs", "");
    PetscCall(OptionsRead(PetscOptionsObject, T, "-needs_grip", &grip, NULL));
    PetscCall(OptionsRead(PetscOptionsObject, T, "-needs_k", &k, NULL));
    PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-needs_theory", &theory, NULL));
    PetscCall(OptionsRead(PetscOptionsObject, T, "-needs_G", &G, NULL));
    PetscCall(OptionsRead(PetscOptionsObject, T, "-needs_e", &e, NULL));
    PetscCall(OptionsRead(PetscOptionsObject, T, "-needs_mu", &mu, NULL));
    PetscOptionsEnd();
    PetscFunctionReturn(0);
  }());
  std::vector<OptionWithoutEffect> out = OptionsWithoutEffect();
  for (auto &o : set) PetscOptionsClearValue(NULL, o.first);
  return out;
}

} // namespace

// An option given where its row's condition fails is named, with the value as written and why;
// where the condition holds, or the option is not given, nothing is said.
TEST(OptionTables, AnOptionWithoutEffectIsNamedWithWhy)
{
  std::vector<OptionWithoutEffect> r = NoEffectWith({{"-needs_k", "1e4"}});
  ASSERT_EQ(1u, r.size());
  EXPECT_EQ("-needs_k", r[0].name);
  EXPECT_EQ("1e4", r[0].written);
  EXPECT_EQ("it acts only with -needs_grip", r[0].why);
  EXPECT_TRUE(NoEffectWith({{"-needs_k", "1e4"}, {"-needs_grip", "0.1,0.2"}}).empty());
  r = NoEffectWith({{"-needs_G", "1e9"}});
  ASSERT_EQ(1u, r.size());
  EXPECT_EQ("-needs_G", r[0].name);
  EXPECT_EQ("it acts only with -needs_theory timoshenko; -needs_theory is euler", r[0].why);
  EXPECT_TRUE(NoEffectWith({{"-needs_G", "1e9"}, {"-needs_theory", "timoshenko"}}).empty());
  EXPECT_TRUE(NoEffectWith({}).empty());
  OptionsUsedClear();
}

// The oblique impact's tangential options (issue 34): head-on (-impact_offset and -ball_spin 0,
// -flight or not) nothing slides along the tangent, so friction, the tangential compliance, the
// ball's inertia and the bat's second plane change nothing: each a note; with an offset they
// act, and without friction (-ball_friction 0) only the friction itself does.
TEST(OptionTables, TheTangentialOptionsOfAHeadOnHitAreNotes)
{
  const std::vector<std::pair<const char *, const char *>> tangential = {
    {"-ball_radius", "0.0366"}, {"-ball_friction", "0.3"}, {"-ball_tangential_cor", "0.3"}, {"-ball_inertia_factor", "0.5"}, {"-impact_tangential_plane", "rigid"}};
  auto noted = [&](const std::vector<std::pair<const char *, const char *>> &more) {
    std::vector<std::pair<const char *, const char *>> set = tangential;
    set.insert(set.end(), more.begin(), more.end());
    OptionsUsedClear();
    for (auto &o : set) PetscOptionsSetValue(NULL, o.first, o.second);
    Scenario sc;
    EXPECT_EQ(0, ScenarioFromOptions(PETSC_COMM_WORLD, &sc));
    std::map<std::string, std::string> why;
    for (const OptionWithoutEffect &o : OptionsWithoutEffect()) why[o.name] = o.why;
    for (auto &o : set) PetscOptionsClearValue(NULL, o.first);
    OptionsUsedClear();
    return why;
  };
  const std::string head_on = "it acts only with -impact_offset not 0 or -ball_spin not 0 or -impact_angle not 0 or -bat_speed_face not 0";
  for (auto more : std::vector<std::vector<std::pair<const char *, const char *>>>{{}, {{"-flight", NULL}}, {{"-impact_offset", "0.0"}, {"-ball_spin", "-0"}}}) {
    std::map<std::string, std::string> why = noted(more);
    EXPECT_EQ(4u, why.size()) << (more.empty() ? "" : more[0].first);
    for (const char *o : {"-ball_friction", "-ball_tangential_cor", "-ball_inertia_factor", "-impact_tangential_plane"}) EXPECT_EQ(head_on, why[o]) << o;
  }
  EXPECT_TRUE(noted({{"-impact_offset", "0.01"}}).empty());
  EXPECT_TRUE(noted({{"-ball_spin", "200"}}).empty());
  std::map<std::string, std::string> why = noted({{"-impact_offset", "0.01"}, {"-ball_friction", "0"}});
  EXPECT_EQ(3u, why.size());
  for (const char *o : {"-ball_tangential_cor", "-ball_inertia_factor", "-impact_tangential_plane"}) EXPECT_EQ("it acts only with -ball_friction not 0; -ball_friction is 0", why[o]) << o;
}

// A condition "-other!=value" on a number compares numbers (issue 34: -ball_tangential_cor with
// -ball_friction 0; head-on hits, -impact_offset and -ball_spin 0): "-0" and "0.0" are 0, the
// note names the value as used; alternatives of "!=" and "=" are met when one is.
TEST(OptionTables, ANotEqualConditionComparesNumbers)
{
  std::vector<OptionWithoutEffect> r = NoEffectWith({{"-needs_e", "0.3"}});
  ASSERT_EQ(1u, r.size());
  EXPECT_EQ("-needs_e", r[0].name);
  EXPECT_EQ("it acts only with -needs_k not 0; -needs_k is 0", r[0].why);
  EXPECT_EQ(std::vector<std::string>{"-needs_k"}, r[0].needs);
  // -needs_k given is itself a note (it needs -needs_grip): only -needs_e and -needs_mu are counted
  auto noted = [](const std::vector<OptionWithoutEffect> &v, const char *name) {
    for (const OptionWithoutEffect &o : v)
      if (o.name == name) return true;
    return false;
  };
  for (const char *zero : {"0.0", "-0", "0e3"}) EXPECT_TRUE(noted(NoEffectWith({{"-needs_e", "0.3"}, {"-needs_k", zero}}), "-needs_e")) << zero;
  EXPECT_FALSE(noted(NoEffectWith({{"-needs_e", "0.3"}, {"-needs_k", "1e-300"}}), "-needs_e"));
  r = NoEffectWith({{"-needs_mu", "0.7"}});
  ASSERT_EQ(1u, r.size());
  EXPECT_EQ("it acts only with -needs_k not 0 or -needs_theory timoshenko", r[0].why);
  EXPECT_EQ((std::vector<std::string>{"-needs_k", "-needs_theory"}), r[0].needs);
  EXPECT_FALSE(noted(NoEffectWith({{"-needs_mu", "0.7"}, {"-needs_k", "5"}}), "-needs_mu"));
  EXPECT_TRUE(NoEffectWith({{"-needs_mu", "0.7"}, {"-needs_theory", "timoshenko"}}).empty());
  OptionsUsedClear();
}

// A run's own finding (OptionWithoutEffectSet) is listed while the option is given, with the
// rows' notes, and withdrawn by an empty reason.
TEST(OptionTables, ARunsOwnNoteOfNoEffect)
{
  OptionsUsedClear();
  OptionWithoutEffectSet("-needs_G", "the step is fixed", {"-needs_theory"});
  EXPECT_TRUE(OptionsWithoutEffect().empty()); // not given
  PetscOptionsSetValue(NULL, "-needs_G", "2e9");
  std::vector<OptionWithoutEffect> r = OptionsWithoutEffect();
  ASSERT_EQ(1u, r.size());
  EXPECT_EQ("-needs_G", r[0].name);
  EXPECT_EQ("2e9", r[0].written);
  EXPECT_EQ("the step is fixed", r[0].why);
  OptionWithoutEffectSet("-needs_G", "");
  EXPECT_TRUE(OptionsWithoutEffect().empty());
  PetscOptionsClearValue(NULL, "-needs_G");
}

// A PETSc table's rows as given are checked before PETSc reads them: a number in its range, a
// choice among the row's (with why these), each error naming the option and the value.
TEST(OptionTables, APetscTablesValuesAreCheckedAsGiven)
{
  static const OptionModule m = {
    "given",
    "Test: a table no reader reads",
    {
      OptionReal("-given_dt", "s", "A step", "0.001", Positive()),
      [] {
        OptionSpec s = OptionChoice("-given_type", "A type", {"rk", "cn"}, "rk");
        s.range_text = "the types that roll back";
        return s;
      }(),
    },
    true,
    {"-given_"},
  };
  PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
  auto error = [&](const char *name, const char *value) {
    PetscOptionsSetValue(NULL, name, value);
    const PetscErrorCode ierr = OptionsCheckGiven(m);
    PetscOptionsClearValue(NULL, name);
    return ierr ? LastErrorMessage(ierr) : std::string("no error");
  };
  EXPECT_NE(std::string::npos, error("-given_dt", "-1").find("-given_dt -1 is not allowed: it must be > 0 (s)"));
  EXPECT_NE(std::string::npos, error("-given_dt", "abc").find("-given_dt abc is not allowed: it must be a number"));
  EXPECT_NE(std::string::npos, error("-given_type", "euler").find("-given_type euler is not allowed: use one of rk, cn (the types that roll back)"));
  EXPECT_EQ("no error", error("-given_dt", "0.5"));
  EXPECT_EQ("no error", error("-given_type", "cn"));
  PetscPopErrorHandler();
}

// The program's own rows: the hands' settings without hands, shear settings of an
// Euler-Bernoulli beam, the segment's time limit without a segment (issue 22).
TEST(OptionTables, TheProgramsRowsSayWhenTheyHaveNoEffect)
{
  const std::vector<std::pair<const char *, const char *>> set = {
    {"-grip_stiffness", "1e4"}, {"-grip_damping", "10"}, {"-grip_mass", "0.5"}, {"-monitor_grip", NULL}, {"-beam_shear_modulus", "1e9"}, {"-beam_poisson", "0.25"}, {"-monitor_segment_until", "1e-3"},
    {"-impact_energy_growth_tol", "1e-2"}};
  OptionsUsedClear();
  for (auto &o : set) PetscOptionsSetValue(NULL, o.first, o.second);
  Scenario sc;
  ASSERT_EQ(0, ScenarioFromOptions(PETSC_COMM_WORLD, &sc));
  std::map<std::string, std::string> why;
  for (const OptionWithoutEffect &o : OptionsWithoutEffect()) why[o.name] = o.why;
  for (auto &o : set) PetscOptionsClearValue(NULL, o.first);
  EXPECT_EQ(set.size(), why.size());
  EXPECT_EQ("it acts only with -grip", why["-grip_stiffness"]);
  EXPECT_EQ("it acts only with -grip", why["-grip_mass"]);
  EXPECT_EQ("it acts only with -grip", why["-monitor_grip"]);
  EXPECT_EQ("it acts only with -beam_theory timoshenko; -beam_theory is euler", why["-beam_shear_modulus"]);
  EXPECT_EQ("it acts only with -monitor_segment", why["-monitor_segment_until"]);
  EXPECT_EQ("it acts only with -impact_energy_check true; -impact_energy_check is false", why["-impact_energy_growth_tol"]);
  // with what they need, nothing is said
  const std::vector<std::pair<const char *, const char *>> with = {{"-grip", "0.05,0.2"}, {"-grip_stiffness", "1e4"}, {"-monitor_grip", NULL}, {"-monitor_segment", "0.1,0.3"}, {"-monitor_segment_until", "1e-3"},
                                                                     {"-impact_energy_check", NULL}, {"-impact_energy_growth_tol", "1e-2"}};
  OptionsUsedClear();
  for (auto &o : with) PetscOptionsSetValue(NULL, o.first, o.second);
  ASSERT_EQ(0, ScenarioFromOptions(PETSC_COMM_WORLD, &sc));
  const size_t none = OptionsWithoutEffect().size();
  for (auto &o : with) PetscOptionsClearValue(NULL, o.first);
  EXPECT_EQ(0u, none);
  OptionsUsedClear();
}

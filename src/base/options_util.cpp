// Options database helpers. See options_util.hpp.
#include "base/options_util.hpp"

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace beamimpact {

PetscErrorCode OptionsAsString(std::string *all)
{
  char *s;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &s));
  *all = s;
  PetscCall(PetscFree(s));
  PetscFunctionReturn(0);
}

namespace {

OptionsCatalog g_catalog;
std::string   *g_help_capture = nullptr;

PetscErrorCode CaptureHelpPrintf(MPI_Comm, const char format[], ...)
{
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (n > 0 && g_help_capture) {
    std::vector<char> buf((size_t)n + 1);
    std::vsnprintf(buf.data(), buf.size(), format, again);
    *g_help_capture += buf.data();
  }
  va_end(again);
  return 0;
}

// PETSc prints the lists of types (-ts_type <now rk>: ... (one of) ...) with PetscFPrintf to
// stdout, which ends in PetscVFPrintf: captured too.
PetscErrorCode CaptureVFPrintf(FILE *, const char format[], va_list args)
{
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  if (n > 0 && g_help_capture) {
    std::vector<char> buf((size_t)n + 1);
    std::vsnprintf(buf.data(), buf.size(), format, again);
    *g_help_capture += buf.data();
  }
  va_end(again);
  return 0;
}

bool StartsWithAny(const std::string &name, const std::vector<std::string> &prefixes)
{
  for (const std::string &p : prefixes)
    if (name.rfind(p, 0) == 0) return true;
  return false;
}

} // namespace

void OptionsSetCatalog(OptionsCatalog catalog)
{
  g_catalog = std::move(catalog);
}

PetscErrorCode OptionsHelpNames(const std::function<PetscErrorCode()> &readers, std::vector<std::string> *names)
{
  std::string text;
  PetscBool   had_help;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &had_help));
  PetscOptionsHelpPrinted printed = PetscOptionsHelpPrintedSingleton; // blocks already printed (or read)
  PetscOptionsHelpPrintedSingleton = NULL;
  auto print                       = PetscHelpPrintf;
  auto vfprint                     = PetscVFPrintf;
  PetscHelpPrintf                  = CaptureHelpPrintf;
  PetscVFPrintf                    = CaptureVFPrintf;
  g_help_capture                   = &text;
  if (!had_help) PetscCall(PetscOptionsSetValue(NULL, "-help", NULL));
  const PetscErrorCode ierr = readers();
  if (!had_help) PetscCall(PetscOptionsClearValue(NULL, "-help"));
  g_help_capture  = nullptr;
  PetscHelpPrintf = print;
  PetscVFPrintf   = vfprint;
  PetscCall(PetscOptionsHelpPrintedDestroy(&PetscOptionsHelpPrintedSingleton));
  PetscOptionsHelpPrintedSingleton = printed;
  (void)ierr;
  std::istringstream lines(text);
  std::string        line;
  while (std::getline(lines, line)) {
    const size_t a = line.find_first_not_of(' ');
    if (a == std::string::npos || a == 0 || line[a] != '-' || a + 1 >= line.size() || !std::isalpha((unsigned char)line[a + 1])) continue;
    const size_t b = line.find_first_of(" <:", a);
    names->push_back(line.substr(a, b == std::string::npos ? std::string::npos : b - a));
  }
  std::sort(names->begin(), names->end());
  names->erase(std::unique(names->begin(), names->end()), names->end());
  PetscFunctionReturn(0);
}

std::string OptionsClosest(const std::string &name, const std::vector<std::string> &known)
{
  std::string best;
  size_t      best_d = std::max<size_t>(2, name.size() / 5) + 1;
  for (const std::string &k : known) {
    // optimal string alignment distance, rows i-2, i-1, i
    const size_t       m = name.size(), n = k.size();
    std::vector<size_t> d2(n + 1), d1(n + 1), d0(n + 1);
    for (size_t j = 0; j <= n; ++j) d1[j] = j;
    for (size_t i = 1; i <= m; ++i) {
      d0[0] = i;
      for (size_t j = 1; j <= n; ++j) {
        const size_t cost = name[i - 1] == k[j - 1] ? 0 : 1;
        d0[j]             = std::min({d1[j] + 1, d0[j - 1] + 1, d1[j - 1] + cost});
        if (i > 1 && j > 1 && name[i - 1] == k[j - 2] && name[i - 2] == k[j - 1]) d0[j] = std::min(d0[j], d2[j - 2] + 1);
      }
      std::swap(d2, d1);
      std::swap(d1, d0);
    }
    if (d1[n] < best_d) {
      best_d = d1[n];
      best   = k;
    }
  }
  return best;
}

PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes, bool strict_solver_options)
{
  PetscInt    n;
  char      **names, **values;
  PetscBool   allow = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-allow_unused_options", &allow, NULL));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  // PETSc's own solver options left over (a scene's -ts_rk_type under a later -ts_type cn) are
  // a note, as -options_left would print; the program's own are an error (a typo costs a run).
  static const std::vector<std::string> petsc_prefixes = {"ts_", "snes_", "ksp_", "pc_", "mat_", "vec_", "dm_", "eps_", "st_", "bv_", "ds_", "rg_", "fn_",
                                                          "flight_ts_", "flight_snes_", "flight_ksp_", "flight_pc_"}; // the flight's TS (-task flight)
  // PETSc's own options read at finalize (-options_left, -malloc_dump, ...): never "unused" here.
  static const std::vector<std::string> at_finalize = {"options_left", "options_view", "malloc", "memory_view", "objects_dump", "log_"};
  std::vector<std::pair<std::string, std::string>> solver, own; // (-name, " -name value")
  for (PetscInt i = 0; i < n; ++i) {
    if (StartsWithAny(names[i], ignore_prefixes) || StartsWithAny(names[i], at_finalize)) continue;
    const std::string item = std::string(" -") + names[i] + (values[i] ? std::string(" ") + values[i] : std::string());
    (StartsWithAny(names[i], petsc_prefixes) && !strict_solver_options ? solver : own).push_back({std::string("-") + names[i], item});
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  std::vector<std::string> known;
  if (!own.empty() && g_catalog) PetscCall(g_catalog(comm, &known));
  std::string notes, unused, unknown, strict;
  PetscInt    n_notes = 0, n_unused = 0, n_unknown = 0, n_strict = 0;
  for (auto &o : solver) notes += o.second, n_notes++;
  for (auto &o : own) {
    const bool is_known = std::binary_search(known.begin(), known.end(), o.first), solver_option = StartsWithAny(o.first.substr(1), petsc_prefixes);
    if (is_known && !solver_option) {
      unused += o.second, n_unused++;
      continue;
    }
    if (solver_option) { // strict: a PETSc solver option this configuration's integrator does not read (the catalog
                         // holds only the default rk's, so it is not called unknown; a near name is suggested)
      const std::string close = is_known ? std::string() : OptionsClosest(o.first, known);
      strict += o.second + (close.empty() ? std::string() : " (did you mean " + close + "?)");
      n_strict++;
      continue;
    }
    const std::string close = OptionsClosest(o.first, known);
    unknown += o.second + (close.empty() ? std::string() : " (did you mean " + close + "?)");
    n_unknown++;
  }
  if (n_notes > 0) PetscCall(PetscPrintf(comm, "note: %" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n", n_notes, notes.c_str()));
  if (n_unused > 0) PetscCall(PetscPrintf(comm, "note: %" PetscInt_FMT " option(s) set but not used by this task:%s\n", n_unused, unused.c_str()));
  if (n_strict > 0) {
    if (allow) PetscCall(PetscPrintf(comm, "WARNING: %" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n", n_strict, strict.c_str()));
    else
      SETERRQ(comm, PETSC_ERR_ARG_WRONG, "%" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n(a configuration must run as written; -allow_unused_options makes this a warning)",
              n_strict, strict.c_str());
  }
  if (n_unknown > 0) {
    const char *what = known.empty() ? "set but not used by this task and integrator" : "unknown (set but read by no task)";
    if (allow) PetscCall(PetscPrintf(comm, "WARNING: %" PetscInt_FMT " option(s) %s:%s\n", n_unknown, what, unknown.c_str()));
    else
      SETERRQ(comm, PETSC_ERR_ARG_WRONG,
              "%" PetscInt_FMT " option(s) %s:%s\n"
              "(a typo? -help lists every option; -allow_unused_options makes this a warning)",
              n_unknown, what, unknown.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsListLength(const char *name, PetscInt *n)
{
  const char *value = nullptr;
  PetscBool   set   = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(NULL, NULL, name, &value, &set));
  *n = 0;
  if (set && value && *value) {
    *n = 1;
    for (const char *c = value; *c; ++c) *n += *c == ',';
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

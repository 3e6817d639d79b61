// Options database helpers. See options_util.hpp.
#include "base/options_util.hpp"

#include "base/option_table.hpp"

#include <algorithm>
#include <cstdio>

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

bool StartsWithAny(const std::string &name, const std::vector<std::string> &prefixes)
{
  for (const std::string &p : prefixes)
    if (name.rfind(p, 0) == 0) return true;
  return false;
}

} // namespace

std::string OptionsClosest(const std::string &name, const std::vector<std::string> &known)
{
  std::string best;
  size_t      best_d = std::max<size_t>(2, name.size() / 5) + 1;
  for (const std::string &k : known) {
    // optimal string alignment distance, rows i-2, i-1, i
    const size_t        m = name.size(), n = k.size();
    std::vector<size_t> d2(n + 1), d1(n + 1), d0(n + 1);
    for (size_t j = 0; j <= n; ++j) d1[j] = j;
    for (size_t i = 1; i <= m; ++i) {
      d0[0] = i;
      for (size_t j = 1; j <= n; ++j) {
        const size_t cost = name[i - 1] == k[j - 1] ? 0 : 1;
        d0[j]             = std::min({d1[j] + 1, d0[j - 1] + 1, d1[j - 1] + cost});
        if (i > 1 && j > 1 && name[i - 1] == k[j - 2] && name[i - 2] == k[j - 1])
          d0[j] = std::min(d0[j], d2[j - 2] + 1);
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

PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes,
                                  bool strict_solver_options, const std::vector<std::string> &varied)
{
  PetscInt  n;
  char    **names, **values;
  PetscBool allow = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-allow_unused_options", &allow, NULL));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  // PETSc's own options read at finalize (-options_left, -malloc_dump, ...) or by
  // PetscInitialize (-help, -options_file): never "unused" here.
  static const std::vector<std::string> petsc_own = {"options_", "malloc", "memory_view", "objects_dump",
                                                     "log_",     "help",   "version"};
  const std::vector<std::string>        known     = OptionNames();
  std::string                           notes, unused, unknown, strict;
  PetscInt                              n_notes = 0, n_unused = 0, n_unknown = 0, n_strict = 0;
  for (PetscInt i = 0; i < n; ++i) {
    if (StartsWithAny(names[i], ignore_prefixes) || StartsWithAny(names[i], petsc_own)) continue;
    const std::string name     = std::string("-") + names[i];
    const std::string item     = " " + name + (values[i] ? std::string(" ") + values[i] : std::string());
    const bool        is_known = OptionSpecFind(name) != nullptr;
    const std::string close    = is_known ? std::string() : OptionsClosest(name, known);
    const std::string hint     = close.empty() ? std::string() : " (did you mean " + close + "?)";
    if (OptionIsPetsc(name)) {
      if (strict_solver_options) strict += item + hint, n_strict++; // a configuration runs as written
      else if (is_known || close.empty())
        notes += item, n_notes++;               // left over by another integrator, or PETSc's beyond the table
      else unknown += item + hint, n_unknown++; // a typo of a known name
    } else if (is_known) unused += item, n_unused++;
    else unknown += item + hint, n_unknown++;
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  std::string no_effect; // read, but a condition of its row fails (OptionSpec::needs)
  for (const OptionWithoutEffect &o : OptionsWithoutEffect()) {
    const bool depends = std::any_of(o.needs.begin(), o.needs.end(), [&](const std::string &n) {
      return std::find(varied.begin(), varied.end(), n) != varied.end();
    });
    if (!depends && !StartsWithAny(o.name.substr(1), ignore_prefixes))
      no_effect += (no_effect.empty() ? " " : "; ") + o.name + (o.written.empty() ? "" : " " + o.written) + " (" +
                   o.why + ")";
  }
  if (!no_effect.empty())
    PetscCall(PetscPrintf(comm, "note: option(s) with no effect in this run:%s\n", no_effect.c_str()));
  if (n_notes > 0)
    PetscCall(PetscPrintf(comm,
                          "note: %" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n",
                          n_notes, notes.c_str()));
  if (n_unused > 0)
    PetscCall(PetscPrintf(comm, "note: %" PetscInt_FMT " option(s) set but not used by this task:%s\n", n_unused,
                          unused.c_str()));
  if (n_strict > 0) {
    if (allow)
      PetscCall(
        PetscPrintf(comm, "WARNING: %" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n",
                    n_strict, strict.c_str()));
    else
      SETERRQ(comm, PETSC_ERR_ARG_WRONG,
              "%" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n(a configuration must "
              "run as written; -allow_unused_options makes this a warning)",
              n_strict, strict.c_str());
  }
  if (n_unknown > 0) {
    if (allow)
      PetscCall(PetscPrintf(comm, "WARNING: %" PetscInt_FMT " option(s) unknown (set but read by no task):%s\n",
                            n_unknown, unknown.c_str()));
    else
      SETERRQ(comm, PETSC_ERR_ARG_WRONG,
              "%" PetscInt_FMT " option(s) unknown (set but read by no task):%s\n"
              "(a typo? -help lists every option; -allow_unused_options makes this a warning)",
              n_unknown, unknown.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

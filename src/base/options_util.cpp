// Options database helpers. See options_util.hpp.
#include "base/options_util.hpp"

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

PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes, bool strict_solver_options)
{
  PetscInt    n;
  char      **names, **values;
  PetscBool   allow = PETSC_FALSE;
  std::string list;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-allow_unused_options", &allow, NULL));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  PetscInt    counted = 0, noted = 0;
  std::string notes;
  // PETSc's own solver options left over (a scene's -ts_rk_type under a later -ts_type cn) are
  // a note, as -options_left would print; the program's own are an error (a typo costs a run).
  static const char *const petsc_prefixes[] = {"ts_", "snes_", "ksp_", "pc_", "mat_", "vec_", "dm_", "eps_", "st_", "bv_", "ds_", "rg_", "fn_"};
  for (PetscInt i = 0; i < n; ++i) {
    bool ignored = false;
    for (auto &p : ignore_prefixes) ignored = ignored || std::string(names[i]).rfind(p, 0) == 0;
    if (ignored) continue;
    std::string item = std::string(" -") + names[i] + (values[i] ? std::string(" ") + values[i] : std::string());
    bool        petsc = false;
    for (const char *p : petsc_prefixes) petsc = petsc || std::string(names[i]).rfind(p, 0) == 0;
    if (petsc && !strict_solver_options) {
      noted++;
      notes += item;
      continue;
    }
    counted++;
    list += item;
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  n = counted; // (Restore zeroes n)
  if (noted > 0) PetscCall(PetscPrintf(comm, "note: %" PetscInt_FMT " PETSc solver option(s) set but not used by this integrator:%s\n", noted, notes.c_str()));
  if (n > 0) {
    if (allow) PetscCall(PetscPrintf(comm, "WARNING: %" PetscInt_FMT " option(s) set but not used:%s\n", n, list.c_str()));
    else
      SETERRQ(comm, PETSC_ERR_ARG_WRONG,
              "%" PetscInt_FMT " option(s) set but not used by this task and integrator:%s\n"
              "(a typo, or an option for another task/integrator? see -help; -allow_unused_options makes this a warning)",
              n, list.c_str());
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

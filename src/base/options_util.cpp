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

PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes)
{
  PetscInt    n;
  char      **names, **values;
  PetscBool   allow = PETSC_FALSE;
  std::string list;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-allow_unused_options", &allow, NULL));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  PetscInt counted = 0;
  for (PetscInt i = 0; i < n; ++i) {
    bool ignored = false;
    for (auto &p : ignore_prefixes) ignored = ignored || std::string(names[i]).rfind(p, 0) == 0;
    if (ignored) continue;
    counted++;
    list += std::string(" -") + names[i];
    if (values[i]) list += std::string(" ") + values[i];
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  n = counted; // (Restore zeroes n)
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

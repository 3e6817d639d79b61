// Options database helpers. See options_util.hpp.
#include "options_util.hpp"

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

PetscErrorCode OptionsCheckUnused(MPI_Comm comm)
{
  PetscInt    n;
  char      **names, **values;
  PetscBool   allow = PETSC_FALSE;
  std::string list;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-allow_unused_options", &allow, NULL));
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; ++i) {
    list += std::string(" -") + names[i];
    if (values[i]) list += std::string(" ") + values[i];
  }
  const PetscInt nleft = n; // Restore zeroes n
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  n = nleft;
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

} // namespace beamimpact

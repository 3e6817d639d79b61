// The memory a run may take. See memory.hpp.
#include "base/memory.hpp"

#include <unistd.h>

namespace beamimpact {

double MemoryPhysical()
{
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? (double)pages * (double)page : 0;
}

double MemoryLimit()
{
  PetscReal gb  = 0;
  PetscBool set = PETSC_FALSE;
  if (!PetscOptionsGetReal(NULL, NULL, "-max_memory", &gb, &set) && set && gb > 0) return gb * 1e9;
  const double physical = MemoryPhysical();
  return physical > 0 ? 0.5 * physical : 8e9;
}

PetscErrorCode MemoryCheck(MPI_Comm comm, double need, const std::string &what, const std::string &remedy)
{
  const double limit = MemoryLimit();
  PetscFunctionBeginUser;
  PetscCheck(need <= limit, comm, PETSC_ERR_MEM,
             "%s would need about %.3g GB, above the limit of %.3g GB (-max_memory, default half of the physical "
             "memory): %s, or raise -max_memory",
             what.c_str(), need / 1e9, limit / 1e9, remedy.c_str());
  PetscFunctionReturn(0);
}

} // namespace beamimpact

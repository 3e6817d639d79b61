// The registrations of the program. See registry.hpp. A new module's option table is one line
// here.
#include "app/registry.hpp"

#include "base/option_table.hpp"
#include "studies/sweep_plan.hpp"

namespace beamimpact {

PetscErrorCode RegisterAll()
{
  PetscFunctionBeginUser;
  // One line per module: OptionModuleRegister(&kModuleOptions);
  OptionModuleRegister(&kSweepOptions);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

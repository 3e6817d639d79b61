// The registrations of the program. See registry.hpp. A new module's option table is one line
// here.
#include "app/registry.hpp"

#include "base/option_table.hpp"
#include "run/reference.hpp"
#include "studies/convergence_plan.hpp"
#include "studies/convergence_runs.hpp"

namespace beamimpact {

PetscErrorCode RegisterAll()
{
  PetscFunctionBeginUser;
  // The methods that solve one impact (run/reference.hpp), in the order -help lists them: the
  // first impact method is -reference's default, a study's default the first that applies.
  ReferenceMethodRegister(&kReferenceTimeStepping);
  ReferenceMethodRegister(&kReferenceModal);
  ReferenceMethodRegister(&kReferenceRun);
  // One line per module: OptionModuleRegister(&kModuleOptions); (after the methods: the
  // reference choices come from the registry)
  OptionModuleRegister(&ReferenceOptionModule());
  OptionModuleRegister(&ConvergenceOptionModule());
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The registrations of the program. See registry.hpp. A new module's option table is one line
// here.
#include "app/registry.hpp"

#include "base/option_table.hpp"
#include "io/flight_options.hpp"

namespace beamimpact {

PetscErrorCode RegisterAll()
{
  PetscFunctionBeginUser;
  // One line per module: OptionModuleRegister(&kModuleOptions);
  OptionModuleRegister(&FlightOptionTable());
  OptionModuleRegister(&AirOptionTable());
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The registrations of the program. See registry.hpp. A new module's option table is one line
// here.
#include "app/registry.hpp"

#include "app/tasks.hpp"
#include "base/option_table.hpp"
#include "io/ball_options.hpp"
#include "io/beam_options.hpp"
#include "io/scenario_options.hpp"
#include "run/impact_params.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/modes.hpp"
#include "solvers/petsc_options.hpp"
#include "studies/sweep_plan.hpp"

namespace beamimpact {

namespace {

// INTERIM, until their modules register tables of their own (the
// convergence study and -reference: studies/convergence.cpp,
// app/tasks.cpp): the names their readers read, with the units a sweep gives its columns, so
// that the unknown-option check and the sweeps know them. Their help and defaults are still
// their readers' (-help prints them). Each module's own table replaces its rows here.
const OptionModule &InterimOptionTable()
{
  static const OptionModule m = {
    "interim",
    "Options of modules not yet on a table",
    {
      OptionText("-reference", "ts or modal"),
      OptionReal("-reference_max_memory", "GB", "Memory limit of -reference modal", ""),
      OptionText("-convergence_configs", "Integrator configurations"),
      OptionInt("-convergence_repeats", "Runs per level", ""),
      OptionReal("-convergence_repeat_budget", "s", "Repeat budget", ""),
      OptionText("-convergence_reference", "modal or run"),
      OptionFile("-convergence_reference_config", "Configuration of the reference run"),
      OptionText("-convergence_spatial_nodes", "Spatial study: N1,N2,..."),
      OptionReal("-convergence_target", "1", "ACOR error of the cost comparison", ""),
      OptionReal("-convergence_error_floor", "1", "Errors at or below this are round-off", ""),
      OptionFile("-convergence_common_options", "Options file inserted into every run"),
      OptionFlag("-convergence_quiet", "Print only the tables"),
    },
  };
  return m;
}

} // namespace

PetscErrorCode RegisterAll()
{
  PetscFunctionBeginUser;
  OptionModuleRegister(&TaskOptionTable());
  OptionModuleRegister(&BeamOptionTable());
  OptionModuleRegister(&BallOptionModule());
  OptionModuleRegister(&SwingOptionTable());
  OptionModuleRegister(&ImpactOptionTable());
  OptionModuleRegister(&MonitorOptionTable());
  OptionModuleRegister(&ModesOptionTable());
  OptionModuleRegister(&ModalOptionTable());
  OptionModuleRegister(&LeapfrogOptionTable());
  OptionModuleRegister(&PetscSolverOptionTable());
  OptionModuleRegister(&kSweepOptions);
  OptionModuleRegister(&InterimOptionTable()); // last: a module's own table wins
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The registrations of the program. See registry.hpp. A new module's option table is one line
// here.
#include "app/registry.hpp"

#include "app/tasks.hpp"
#include "base/option_table.hpp"
#include "io/beam_options.hpp"
#include "io/scenario_options.hpp"
#include "run/impact_params.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/modes.hpp"
#include "solvers/petsc_options.hpp"
#include "studies/sweep_plan.hpp"

namespace beamimpact {

namespace {

// INTERIM, until their modules register tables of their own (the ball: io/ball_options.cpp; the
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
      OptionReal("-ball_mass", "kg", "Ball mass m_b", ""),
      OptionReal("-ball_speed", "m/s", "Incident speed v_i", ""),
      OptionText("-ball_law", "Contact law"),
      OptionReal("-ball_k", "N/m", "Linear spring stiffness k", ""),
      OptionReal("-ball_k1", "N/m^m", "Hysteresis loading coefficient k1", ""),
      OptionReal("-ball_m", "1", "Hysteresis loading exponent m", ""),
      OptionReal("-ball_n", "1", "Hysteresis unloading exponent n", ""),
      OptionReal("-ball_cor", "1", "Rigid-wall coefficient of restitution e", ""),
      OptionReal("-ball_contact_time", "s", "Rigid-wall contact time tau", ""),
      OptionReal("-ball_test_speed", "m/s", "Speed of the wall test", ""),
      OptionFile("-ball_cor_table", "File of rows 'v e'"),
      OptionReal("-ball_radius", "m", "Ball radius", ""),
      OptionReal("-ball_loss_factor", "1", "Factor applied to the ACOR for ball losses", ""),
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
  OptionModuleRegister(&SwingOptionTable());
  OptionModuleRegister(&ImpactOptionTable());
  OptionModuleRegister(&MonitorOptionTable());
  OptionModuleRegister(&ModesOptionTable());
  OptionModuleRegister(&LeapfrogOptionTable());
  OptionModuleRegister(&PetscSolverOptionTable());
  OptionModuleRegister(&kSweepOptions);
  OptionModuleRegister(&InterimOptionTable()); // last: a module's own table wins
  PetscFunctionReturn(0);
}

} // namespace beamimpact

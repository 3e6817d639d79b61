// The registrations of the program. See registry.hpp. A new module's option table is one line
// here.
#include "app/registry.hpp"

#include "app/tasks.hpp"
#include "base/option_table.hpp"
#include "io/ball_options.hpp"
#include "io/bat_maker_options.hpp"
#include "io/racket_maker_options.hpp"
#include "io/beam_options.hpp"
#include "io/flight_options.hpp"
#include "io/scenario_options.hpp"
#include "io/string_bed_options.hpp"
#include "run/impact_params.hpp"
#include "run/reference.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/flight_ts.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/modes.hpp"
#include "solvers/petsc_options.hpp"
#include "studies/convergence_plan.hpp"
#include "studies/convergence_runs.hpp"
#include "studies/design.hpp"
#include "studies/fit_data.hpp"
#include "studies/sweep_plan.hpp"
#include "system/structure_part.hpp"

namespace beamimpact {

PetscErrorCode RegisterAll()
{
  PetscFunctionBeginUser;
  // The methods that solve one impact (run/reference.hpp), in the order -help lists them: the
  // first impact method is -reference's default, a study's default the first that applies.
  ReferenceMethodRegister(&kReferenceTimeStepping);
  ReferenceMethodRegister(&kReferenceModal);
  ReferenceMethodRegister(&kReferenceRun);
  // One line per module (after the methods: the reference choices come from the registry).
  OptionModuleRegister(&TaskOptionTable());
  OptionModuleRegister(&BeamOptionTable());
  OptionModuleRegister(&BatMakerOptionTable());
  OptionModuleRegister(&RacketMakerOptionTable());
  OptionModuleRegister(&BallOptionModule());
  OptionModuleRegister(&SwingOptionTable());
  OptionModuleRegister(&ImpactOptionTable());
  OptionModuleRegister(&MonitorOptionTable());
  OptionModuleRegister(&ModesOptionTable());
  OptionModuleRegister(&ModalOptionTable());
  OptionModuleRegister(&LeapfrogOptionTable());
  OptionModuleRegister(&PetscSolverOptionTable());
  OptionModuleRegister(&kSweepOptions);
  OptionModuleRegister(&ReferenceOptionModule());
  OptionModuleRegister(&ConvergenceOptionModule());
  OptionModuleRegister(&FlightOptionTable());
  OptionModuleRegister(&AirOptionTable());
  OptionModuleRegister(&FlightTSOptionTable());
  OptionModuleRegister(&StringBedOptionTable());
  OptionModuleRegister(&FitOptionTable());
  OptionModuleRegister(&TaoOptionTable());
  OptionModuleRegister(&DesignOptionTable());
  for (const StructurePart *part : StructureParts()) OptionModuleRegister(&part->Options()); // each part's own
  PetscFunctionReturn(0);
}

} // namespace beamimpact

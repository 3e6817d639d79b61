// The scenario from the options. See scenario_options.hpp.
#include "io/scenario_options.hpp"

namespace beamimpact {

PetscErrorCode ScenarioFromOptions(MPI_Comm comm, const ScenarioReading &how, Scenario *sc)
{
  PetscFunctionBeginUser;
  PetscCall(BeamParamsFromOptions(comm, &sc->beam));
  PetscCall(BallParamsFromOptions(comm, &sc->ball));
  if (how.after_bodies) PetscCall(how.after_bodies(*sc));
  PetscCall(ImpactParamsFromOptions(comm, sc->beam, &sc->impact));
  if (how.monitors) PetscCall(MonitorRequestFromOptions(comm, sc->beam, &sc->monitor));
  PetscFunctionReturn(0);
}

PetscErrorCode ScenarioFromOptions(MPI_Comm comm, Scenario *sc)
{
  PetscFunctionBeginUser;
  PetscCall(ScenarioFromOptions(comm, ScenarioReading(), sc));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

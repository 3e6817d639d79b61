// The scenario from the options. See scenario_options.hpp.
#include "io/scenario_options.hpp"

#include <cmath>

namespace beamimpact {

namespace {

// -bat_speed, -bat_angular_velocity: a swinging bat, free at both ends.
PetscErrorCode SwingFromOptions(MPI_Comm comm, const BeamParams &beam, SwingParams *s)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Swinging bat: its rigid motion toward the ball before the impact", "beamimpact");
  PetscCall(PetscOptionsReal("-bat_speed", "Centre-of-mass speed V_cm of the bat toward the ball (m/s)", "", s->bat_speed, &s->bat_speed, NULL));
  PetscCall(PetscOptionsReal("-bat_angular_velocity", "Angular velocity Omega about the centre of mass (rad/s; > 0: the x = L end moves faster toward the ball)", "", s->bat_angular_velocity,
                             &s->bat_angular_velocity, NULL));
  PetscOptionsEnd();
  PetscCheck(std::isfinite(s->bat_speed), comm, PETSC_ERR_ARG_OUTOFRANGE, "-bat_speed %g is not allowed: give a finite speed (m/s)", (double)s->bat_speed);
  PetscCheck(std::isfinite(s->bat_angular_velocity), comm, PETSC_ERR_ARG_OUTOFRANGE, "-bat_angular_velocity %g is not allowed: give a finite angular velocity (rad/s)", (double)s->bat_angular_velocity);
  if (s->Swings()) {
    const char *held = beam.left != Support::Free ? "-beam_left" : beam.right != Support::Free ? "-beam_right" : beam.has_clamp ? "-beam_clamp" : beam.has_pivot ? "-beam_pivot" : nullptr;
    PetscCheck(!held, comm, PETSC_ERR_ARG_INCOMP, "-bat_speed/-bat_angular_velocity swing a free bat: %s holds it (remove it, or do not swing)", held);
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ScenarioFromOptions(MPI_Comm comm, const ScenarioReading &how, Scenario *sc)
{
  PetscFunctionBeginUser;
  PetscCall(BeamParamsFromOptions(comm, &sc->beam));
  PetscCall(BallParamsFromOptions(comm, &sc->ball));
  PetscCall(SwingFromOptions(comm, sc->beam, &sc->swing));
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

// The scenario from the options. See scenario_options.hpp.
#include "io/scenario_options.hpp"

#include <cmath>

namespace beamimpact {

const OptionModule &SwingOptionTable()
{
  static const OptionModule m = {
    "bat",
    "Swinging bat: its rigid motion toward the ball before the impact",
    {
      OptionReal("-bat_speed", "m/s", "Centre-of-mass speed V_cm of the bat toward the ball", "0"),
      OptionReal("-bat_angular_velocity", "rad/s", "Angular velocity Omega about the centre of mass (> 0: the x = L end moves faster toward the ball)", "0"),
    },
  };
  return m;
}

namespace {

// -bat_speed, -bat_angular_velocity: a swinging bat, free at both ends.
PetscErrorCode SwingFromOptions(MPI_Comm comm, const BeamParams &beam, SwingParams *s)
{
  const OptionModule &T = SwingOptionTable();
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_speed", &s->bat_speed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_angular_velocity", &s->bat_angular_velocity, NULL));
  PetscOptionsEnd();
  if (s->Swings()) {
    const char *held = beam.left.Holds() != NodeHold::None ? "-beam_left" : beam.right.Holds() != NodeHold::None ? "-beam_right" : beam.has_clamp ? "-beam_clamp" : beam.has_pivot ? "-beam_pivot" : nullptr;
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
  // A ball at rest is struck only by a swinging bat (the approach speed v_i + V(x) > 0 is then
  // checked at the impact point, naming both options).
  PetscCheck(sc->ball.speed > 0 || sc->swing.Swings(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-ball_speed 0 is not allowed for a bat at rest: ball and beam would never meet; give -ball_speed > 0 (m/s), or swing the bat (-bat_speed, -bat_angular_velocity)");
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

// The scenario of a task from the options database: -beam_*, -ball_*, -impact_* and the
// monitors, read once, in that order (the order of -help and of the checks).
#pragma once

#include "io/beam_options.hpp"
#include "io/ball_options.hpp"
#include "io/flight_options.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <functional>

namespace beamimpact {

// The -bat_* options (a swinging bat): the swing module's table (registered by app/registry.cpp).
const OptionModule &SwingOptionTable();

// Reads the beam, the ball, the swing, the impact rules and the monitors, each checked as it is
// read.
PetscErrorCode ScenarioFromOptions(MPI_Comm comm, Scenario *sc);

// How a task departs from the plain reading.
struct ScenarioReading {
  // Called once the beam and ball are read, before the impact rules: a study reads its own
  // options there (checked against the beam) and may stand in values for the options it varies.
  std::function<PetscErrorCode(const Scenario &)> after_bodies;
  // false: the monitors stay unread, so a task that records none reports them as unused options.
  bool monitors = true;
};
PetscErrorCode ScenarioFromOptions(MPI_Comm comm, const ScenarioReading &how, Scenario *sc);

} // namespace beamimpact

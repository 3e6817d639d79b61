// The scenario of a task from the options database: -beam_*, -ball_*, -impact_* and the
// monitors, read once, in that order (the order of -help and of the checks).
#pragma once

#include "io/beam_options.hpp"
#include "io/ball_options.hpp"
#include "io/flight_options.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <functional>
#include <string>

namespace beamimpact {

// The -bat_* options (a swinging bat): the swing module's table (registered by app/registry.cpp).
const OptionModule &SwingOptionTable();

// Reads the beam, the ball, the swing, the impact rules and the monitors, each checked as it is
// read.
PetscErrorCode ScenarioFromOptions(MPI_Comm comm, Scenario *sc);

// The parts of a scenario, each read from its own modules' options: the beam (-beam_* and
// every module a structure reads), the ball (-ball_*), the swing (-bat_*), the impact rules
// (-impact_*), the monitors (-monitor_*, -snapshot_times) and the flight (-flight*, -air_*).
enum ScenarioPart : unsigned {
  ScenarioBeam     = 1u << 0,
  ScenarioBall     = 1u << 1,
  ScenarioSwing    = 1u << 2,
  ScenarioImpact   = 1u << 3,
  ScenarioMonitors = 1u << 4,
  ScenarioFlight   = 1u << 5,
  ScenarioAll      = (1u << 6) - 1,
};
// The one part option `name` (with or without the dash) feeds, by its module's table (ball,
// bat, impact, monitor, flight, air); ScenarioAll for any other option (the beam's modules, and
// an option the scenario does not read: the safe answer, everything read again).
unsigned ScenarioPartOf(const std::string &name);

// How a task departs from the plain reading.
struct ScenarioReading {
  // Called once the beam and ball are read, before the impact rules: a study reads its own
  // options there (checked against the beam) and may stand in values for the options it varies.
  std::function<PetscErrorCode(const Scenario &)> after_bodies;
  // false: the monitors stay unread, so a task that records none reports them as unused options.
  bool monitors = true;
  // false (and without monitors): the flight after the impact keeps no series and leaves
  // -flight_series_dt unread (a task that writes no trajectory: a sweep, a study).
  bool flight_series = true;
  // A sweep's points on one structure: the parts not in `read` are copied from *reuse instead of
  // read again; *reuse must be a scenario as read (`read_as` of an earlier reading) from the same
  // values of every option of those parts. The checks that join parts (a ball at rest needs a
  // swing, the swing a free bat, the impact point on the beam, the shell's contact radius) are
  // made again; the parts read are checked as always.
  const Scenario *reuse = nullptr;
  unsigned        read  = ScenarioAll;
  // When given, the scenario as read, before the values resolved from several parts (the shell's
  // default contact radius, from the ball and the impact point): what a later reading may reuse.
  Scenario *read_as = nullptr;
};
PetscErrorCode ScenarioFromOptions(MPI_Comm comm, const ScenarioReading &how, Scenario *sc);

} // namespace beamimpact

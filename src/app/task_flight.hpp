// -task flight: the batted ball's flight on its own (docs/flight.md), from a launch given by
// options, under A. M. Nathan's trajectory model, so that it can be checked against his
// calculator's published trajectories.
//
//   beamimpact -task flight -flight_speed 45 -flight_angle 28 -flight_spin 260
//   beamimpact -options_file options/scenes/flight-nathan.opts
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// Reads -flight_*, -air_* and -flight_ts_*, flies the ball, prints one summary and writes
// the results file (unless output is empty).
PetscErrorCode TaskFlight(MPI_Comm comm, const std::string &output);

// Under -help: the flight's blocks (-flight_*, -air_*, the flight TS's -flight_ts_*).
PetscErrorCode FlightHelpOptions(MPI_Comm comm);

} // namespace beamimpact

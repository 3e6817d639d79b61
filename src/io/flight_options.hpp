// The options of -task flight (docs/flight.md): the launch, the ball and its aerodynamics
// (-flight_*, one table) and the air (-air_*, another), read by the checked readers of
// base/option_table.hpp; both tables are registered in app/registry.cpp. SI throughout:
// speeds in m/s, spins in rad/s (2500 rpm = 261.8 rad/s), temperature in degC, pressure in
// Pa, relative humidity in %, angles in degrees. The flight's integrator takes PETSc's TS
// options with the prefix -flight_ (-flight_ts_type, -flight_ts_rtol, ...).
#pragma once

#include "base/option_table.hpp"
#include "model/flight.hpp"
#include "solvers/flight_ts.hpp"

#include <petscsys.h>

namespace beamimpact {

const OptionModule &FlightOptionTable();
const OptionModule &AirOptionTable();

// -air_*: the air; a density <= 0 from the formula is refused, naming the options.
PetscErrorCode AirParamsFromOptions(MPI_Comm comm, AirParams *air);

// -flight_* and -air_*: everything -task flight reads but the TS's own options.
PetscErrorCode FlightParamsFromOptions(MPI_Comm comm, FlightParams *p, FlightSolveParams *s);

} // namespace beamimpact

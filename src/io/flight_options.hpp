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

// -flight_* and -air_*: everything -task flight reads but the TS's own options; a spin beyond
// FlightSpinMax is refused, naming -flight_spin and -flight_sidespin. Without `series` (a
// task that writes none) -flight_series_dt is not read (a note if given) and s->series is false.
PetscErrorCode FlightParamsFromOptions(MPI_Comm comm, FlightParams *p, FlightSolveParams *s, bool series = true);
// -flight (-task impact): whether to fly the batted ball after the impact, and then the flight's
// ball, air and aerodynamics (the launch options are refused: the impact gives the launch), and
// the flight's integrator options checked (FlightTSCheckOptions) before the impact runs.
PetscErrorCode FlightAfterImpactFromOptions(MPI_Comm comm, PetscBool *on, FlightParams *p, FlightSolveParams *s,
                                            bool series = true);

} // namespace beamimpact

// The flight of a ball (model/flight.hpp) integrated by a PETSc TS of its own, options prefix
// "flight_" (-flight_ts_type, -flight_ts_rtol, -flight_ts_max_time, ...: PETSc's TS options
// with that prefix, apart from the impact's -ts_*). Default: adaptive Dormand-Prince 5(4)
// (rk 5dp) with rtol = atol = 1e-10, first step 1e-3 s, at most 60 s of flight.
//
// The landing (height 0) is located, not taken from the last step: the step that ends below
// the ground is rolled back and re-stepped onto the root of the quintic Hermite interpolant
// (position, velocity, acceleration at both ends), then onto Newton corrections
// dt <- dt - z/vz until |z| <= 1e-12 m, so the landing state is the integrator's own state
// there, of its full order. The apex is the top of the interpolant. A series is sampled from
// the interpolant every series_dt. One serial TS on PETSC_COMM_SELF: under MPI every rank
// computes the same flight.
#pragma once

#include "base/option_table.hpp"
#include "model/flight.hpp"

#include <petscts.h>

#include <string>
#include <vector>

namespace beamimpact {

struct FlightSolveParams {
  PetscReal series_dt = 0.01; // s between series samples (0: only the launch and the landing)
  bool      series    = true; // false: no series at all (nobody writes one: a sweep's points)
};

// The trajectory as sampled: time, position, velocity and the spin in effect.
struct FlightSeries {
  std::vector<PetscReal> t, x, y, z, vx, vy, vz, spin; // s, m, m, m, m/s, m/s, m/s, rad/s
};

struct FlightResult {
  FlightLanding landing;
  PetscReal     apex = 0, apex_time = 0; // m, s: the highest point (the launch height when launched downward)
  PetscReal     landing_residual = 0;    // m, |z| of the located landing state
  PetscInt      steps = 0, rejected_steps = 0, locate_steps = 0, function_evals = 0;
  PetscReal     wall_time = 0;      // s
  std::string   ts_type;            // "rk 5dp", "cn", ...
  PetscReal     rtol = 0, atol = 0; // 1; m, m/s: the tolerances of an adaptive step
  bool          fixed_step = false; // the step is fixed at dt (no error control: rtol, atol unused)
  PetscReal     dt         = 0;     // s, the fixed step (the first step when adaptive)
  FlightSeries  series;
};

// Flies the ball from state u0 (x, y, z, vx, vy, vz; z >= 0) until it lands. The step is adaptive
// (rtol, atol held) wherever the type estimates its error: theta, beuler, cn and alpha get the
// basic adaptor, which PETSc leaves them without, unless -flight_ts_adapt_type is given; an rk
// tableau without an embedded pair (1fe, 3, 4) steps at the fixed -flight_ts_dt, as does
// -flight_ts_adapt_type none: r->fixed_step says so, and a given -flight_ts_rtol/atol is noted
// as without effect. Errors: a state that starts below the ground or on it going down, a spin
// beyond FlightSpinMax, a -flight_ts_* value outside its row (a type that cannot roll back a
// step, a step <= 0, ...), a series beyond the memory limit (-max_memory), a state that stops
// being finite (a fixed step far too long), no landing within -flight_ts_max_time.
PetscErrorCode FlightSolve(const FlightModel &m, const PetscReal u0[6], const FlightSolveParams &p, FlightResult *r);
// The checks FlightSolve makes of the options before it flies (the TS's, the series' memory),
// made without flying: -task impact -flight runs them before the impact, whose launch the flight
// takes after it; this also reads the -flight_ts_* options, which the impact's check of unused
// options then counts as used.
PetscErrorCode FlightTSCheckOptions(const FlightSolveParams &p);

// The flight TS's PETSc options the program advertises, with its defaults (a PETSc table:
// prefixes -flight_ts_, -flight_snes_, -flight_ksp_, -flight_pc_; PETSc's TS reads them).
const OptionModule &FlightTSOptionTable();

// Under -help: the flight TS's options (-flight_ts_*) as PETSc lists them for its default
// type, then its table.
PetscErrorCode FlightTSOptionsHelp(MPI_Comm comm);

} // namespace beamimpact

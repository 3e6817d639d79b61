// -task flight. See task_flight.hpp.
#include "app/task_flight.hpp"

#include "base/options_util.hpp"
#include "io/flight_h5.hpp"
#include "io/flight_options.hpp"
#include "solvers/flight_ts.hpp"

#include <cmath>
#include <cstdio>

namespace beamimpact {

namespace {

PetscErrorCode FlightPrintSummary(MPI_Comm comm, const FlightParams &p, const FlightModel &m, const FlightResult &r)
{
  const FlightLanding &l = r.landing;
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "flight: distance %.4f m  apex %.4f m at %.4f s  hang_time %.4f s  landing_speed %.4f m/s  "
                        "landing_angle %.3f deg  bearing %.3f deg\n",
                        (double)l.distance, (double)r.apex, (double)r.apex_time, (double)l.hang_time,
                        (double)l.landing_speed, (double)l.landing_angle, (double)l.bearing));
  char line[512]; // std::snprintf: PETSc's %g would write 45 as "45."
  std::snprintf(line, sizeof line,
                "launch %g m/s at %g deg from %g m, spin %g rad/s (%.0f rpm); air %.5f kg/m^3, K %.6e 1/m (%s "
                "constants)",
                (double)p.launch.speed, (double)p.launch.angle, (double)p.launch.height, (double)m.spin,
                (double)(m.spin * 30 / M_PI), (double)m.rho, (double)m.K,
                p.aero.constants == FlightConstants::Calculator ? "calculator" : "exact");
  PetscCall(PetscPrintf(comm, "%s\n", line));
  char control[96]; // the error control, or the truth: a fixed step without one
  if (r.fixed_step) std::snprintf(control, sizeof control, "fixed step %g s (no error control)", (double)r.dt);
  else std::snprintf(control, sizeof control, "rtol %g  atol %g", (double)r.rtol, (double)r.atol);
  std::snprintf(line, sizeof line,
                "ts %s  %s  steps %lld  rejected %lld  landing re-steps %lld  fevals %lld  wall %.3e s",
                r.ts_type.c_str(), control, (long long)r.steps, (long long)r.rejected_steps, (long long)r.locate_steps,
                (long long)r.function_evals, (double)r.wall_time);
  PetscCall(PetscPrintf(comm, "%s\n", line));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TaskFlight(MPI_Comm comm, const std::string &output)
{
  FlightParams      p;
  FlightSolveParams s;
  FlightResult      r;
  PetscReal         u0[6];

  PetscFunctionBeginUser;
  PetscCall(FlightParamsFromOptions(comm, &p, &s));
  const FlightModel m = FlightModelOf(p);
  FlightInitialState(p.launch, u0);
  PetscCall(FlightSolve(m, u0, s, &r));
  PetscCall(OptionsCheckUnused(comm)); // after the TS read its -flight_ts_* options
  PetscCall(FlightPrintSummary(comm, p, m, r));
  if (output.empty()) PetscFunctionReturn(0);
  RunRecord rec;
  PetscCall(FlightRunRecordBuild(p, m, s, r, &rec));
  PetscCall(ResultsWriteFlightFile(comm, output, rec, r));
  PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode FlightHelpOptions(MPI_Comm comm)
{
  FlightParams      p;
  FlightSolveParams s;
  PetscFunctionBeginUser;
  (void)FlightParamsFromOptions(comm, &p, &s); // its checks' errors are not what -help asks
  PetscCall(FlightTSOptionsHelp(comm));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

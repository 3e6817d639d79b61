// The oblique impact in a run (docs/model.md "Oblique impacts", MODEL section 10): an impact
// with -impact_offset D or -ball_spin not 0 (or -flight) is split along the contact's fixed
// normal n and tangent t (model/oblique.hpp):
//
//   * along n, the existing impact on the flexible bat, any law, any integrator: the run's
//     scenario with the ball's and the swing's speeds projected on n (times cos theta; exactly
//     today's run head-on, cos theta = 1);
//   * along t, the friction force, driven by that run's normal force F_n(t) (the run records the
//     ball's series for it), on the ball (translation and spin) and on the bat as a rigid body in
//     its second plane: its effective mass at the impact point (free bat: Eq. 11's M_e; a rig
//     free about its pivot: I_p / (x - x_p)^2; otherwise held) and its roll about its axis
//     (free bat: the profile's polar inertia 2 int rho I dx; otherwise held).
//
// The second plane is rigid here, not a second flexible field: for a round, straight bat the
// planes decouple, so the bat's bending along t is driven by F_t only, which is at most mu F_n
// and, for the undercuts of play, much smaller (docs/model.md says what this leaves out).
// Then, with -flight, the batted ball's flight (solvers/flight_ts.hpp) from the exit speed,
// launch angle and spin.
#pragma once

#include "model/flight.hpp"
#include "model/oblique.hpp"
#include "model/swing.hpp"
#include "solvers/flight_ts.hpp"

#include <petscsys.h>

namespace beamimpact {

struct Scenario;
struct ImpactSeries;

// -flight after an impact: the flight's ball, air and aerodynamics (-flight_*, -air_*; the
// launch comes from the impact).
struct FlightAfterImpact {
  PetscBool         on = PETSC_FALSE;
  FlightParams      params;
  FlightSolveParams solve;
};

// The incoming impact of a run whose scenario was projected on the normal (on: projected).
struct ObliqueIncoming {
  bool            on = false;
  PetscReal       ball_speed = 0; // m/s, as given
  SwingParams     swing;          // as given
  ObliqueGeometry geometry;
  PetscReal       bat_radius = 0; // m, at the impact point
  bool            ball_series_asked = false, series_asked = false; // -monitor_ball; any monitor (the run records the ball's series for F_n)
};

// What the tangential contact and the flight hand the outcome.
struct ObliqueRecord {
  bool             on = false;
  ObliqueGeometry  geometry;
  TangentialModel  model;
  TangentialBodies before, after;
  TangentialState  contact;
  ObliqueExit      exit;
  bool             flew = false;
  FlightResult     flight;
};

// Whether the impact is oblique: -impact_offset or -ball_spin not 0, or -flight.
bool ObliqueImpact(const Scenario &sc);

// The scenario of the run along the normal: checks the geometry (a round section at the impact
// point, -ball_radius, |D| < R_b + R_bat) and projects the ball's and the swing's speeds.
PetscErrorCode ObliqueNormalScenario(MPI_Comm comm, const Scenario &sc, Scenario *normal);

// After the run along the normal (sc: its projected scenario; series: its ball series, F_n at
// every step): the tangential contact, the exit, and with -flight the flight.
PetscErrorCode ObliqueFinish(const Scenario &sc, const ImpactSeries &series, PetscReal ball_normal_speed_end, ObliqueRecord *rec);

} // namespace beamimpact

// The batted ball's flight under A. M. Nathan's trajectory model (docs/flight.md), as his
// trajectory calculator computes it (TrajectoryCalculator-new-3D.xlsx,
// baseball.physics.illinois.edu): a ball of mass m and radius R in still air,
//
//   dv/dt = -K C_D |v| v + K (C_L / |w|) |v| (w x v) - g z^,   K = 1/2 rho A / m,  A = pi R^2,
//
//   C_D = cd0 + cd_spin (spin / 1000 rpm) d(t),     C_L = cl2 S / (cl0 + cl1 S),
//   S   = R |w| d(t) / |v|,                         d(t) = exp(-t |v| / (tau v_ref)),
//
// with the spin w (rad/s) fixed in direction from the launch (backspin about the horizontal
// axis across the launch direction, sidespin about the axis in the vertical plane of the launch
// perpendicular to it), its effect decaying by d(t) (tau at v_ref = 100 mph, faster in
// proportion to the speed), and the air density rho from temperature, barometric pressure
// (reduced to sea level), relative humidity and elevation by the calculator's formula.
//
// Frame (the calculator's): x horizontal to the right seen from the launch point looking down
// the field, y horizontal down the field (the launch direction at -flight_direction 0), z up;
// the ground is z = 0. Units SI: m, s, kg, rad/s; angles in degrees where the options give them.
// Plain numbers: the options are read in io/flight_options.cpp, the TS lives in
// solvers/flight_ts.cpp.
#pragma once

#include <petscsys.h>

namespace beamimpact {

// The air (the calculator's inputs, in SI).
struct AirParams {
  PetscReal temperature = 20;     // degC
  PetscReal pressure    = 101325; // Pa, barometric pressure reduced to sea level (as weather reports give it)
  PetscReal humidity    = 50;     // %, relative
  PetscReal elevation   = 0;      // m above sea level
  PetscReal density     = -1;     // kg/m^3: >= 0 replaces the formula (0: vacuum); < 0: from the four above
};

// Saturation vapour pressure over water (Pa) at temperature T (degC), the calculator's
// 4.5841 mmHg exp((18.687 - T/234.5) T / (257.14 + T)) (Buck's equation).
PetscReal AirSaturationVaporPressure(PetscReal T);
// The air density (kg/m^3) as the calculator computes it:
//   rho = 1.2929 (273 / (T + 273)) (p exp(-beta h) - 0.3783 (RH/100) p_sat(T)) / 760 mmHg,
// beta = 1.217e-4 1/m; or air.density when it is given (>= 0).
PetscReal AirDensity(const AirParams &air);

// The ball and its aerodynamic coefficients (the calculator's values by default).
struct FlightBall {
  PetscReal mass   = 5.125 * 0.028349523125;      // kg (5.125 oz: the calculator's baseball)
  PetscReal radius = 9.125 * 0.0254 / (2 * M_PI); // m (circumference 9.125 in)
};

// How K = 1/2 rho A / m is evaluated. Calculator: as the spreadsheet does, with its constants
// 0.07182 ft^2/lb (1/2 A/m of the 5.125 oz, 9.125 in ball, rounded) and 0.06261 (lb/ft^3 per
// kg/m^3; exactly 0.0624280), which make K FlightCalculatorFactor() = 1.00281 times the exact
// value; exact: 1/2 rho pi R^2 / m.
enum class FlightConstants {
  Calculator,
  Exact
};

struct FlightAero {
  PetscReal       cd0             = 0.3008; // 1, drag without spin
  PetscReal       cd_spin         = 0.0292; // 1 per 1000 rpm of spin (the calculator's unit)
  PetscReal       cl0             = 0.583;  // 1, lift C_L = cl2 S / (cl0 + cl1 S)
  PetscReal       cl1             = 2.333;  // 1
  PetscReal       cl2             = 1.120;  // 1
  PetscReal       spin_decay_time = 30;     // s, tau at v_ref = 100 mph (0: no decay)
  FlightConstants constants       = FlightConstants::Calculator;
};

// The launch: speed, direction and spin of the ball as it leaves the bat, and where.
struct FlightLaunch {
  PetscReal speed     = 45;  // m/s
  PetscReal angle     = 30;  // deg above the horizontal
  PetscReal direction = 0;   // deg, horizontal, from the y axis toward +x (the calculator's phi)
  PetscReal backspin  = 250; // rad/s (< 0: topspin), about the horizontal axis across the launch
  PetscReal sidespin  = 0;   // rad/s, the calculator's sign: > 0 curves the ball toward -x
  PetscReal height    = 1;   // m above the ground
};

struct FlightParams {
  FlightBall   ball;
  FlightAero   aero;
  FlightLaunch launch;
  AirParams    air;
  PetscReal    gravity = 9.80665; // m/s^2
};

// The bound on a ball's spin: its surface speed |w| R below the speed of sound in air, 343 m/s
// (dry air at 20 degC). Beyond it the flow over the ball is supersonic and no drag or lift model
// applies; the lift here is fitted to spins of 1500-4500 rpm, spin factors S = R |w| / |v| of
// 0.09-0.6 (A. M. Nathan, Am. J. Phys. 76, 119 (2008)), so even below the bound a large S is an
// extrapolation. For a baseball (R = 36.9 mm) the bound is 9300 rad/s, 89,000 rpm, 35 times the
// 2500 rpm of a well-hit fly ball: it refuses only what no bat or pitcher gives (issue 34: a spin
// of 1e9 rad/s flew 1.6e-27 m).
constexpr PetscReal kSpeedOfSound = 343; // m/s
// The largest spin (rad/s) a ball of radius R (m) may have: kSpeedOfSound / R.
PetscReal FlightSpinMax(PetscReal radius);

// The speed (m/s) the calculator's spin decay refers to: 100 mph as it converts it, 146.7 ft/s.
extern const PetscReal kFlightDecaySpeed;
// K(calculator) / K(exact): 0.07182 / (1/2 A/m of its reference ball in ft^2/lb) times
// 0.06261 / 0.0624280 (lb/ft^3 per kg/m^3).
PetscReal FlightCalculatorFactor();

// What one flight needs, derived once from FlightParams.
struct FlightModel {
  PetscReal K      = 0;           // 1/m, 1/2 rho A / m (times FlightCalculatorFactor() for the calculator)
  PetscReal rho    = 0;           // kg/m^3, the air density used
  PetscReal w[3]   = {0, 0, 0};   // rad/s, the spin vector (fixed in direction)
  PetscReal spin   = 0;           // rad/s, |w|
  PetscReal radius = 0;           // m
  PetscReal cd0 = 0, cd_spin = 0; // 1; 1 per rad/s
  PetscReal cl0 = 0, cl1 = 0, cl2 = 0;
  PetscReal tau     = 0; // s (0: no decay)
  PetscReal gravity = 0; // m/s^2
};
FlightModel FlightModelOf(const FlightParams &p);

// The launch state u = (x, y, z, vx, vy, vz) at (0, 0, height).
void FlightInitialState(const FlightLaunch &launch, PetscReal u[6]);

// The decay factor d(t) of the spin's effect at speed |v| (1 without decay).
PetscReal FlightSpinDecay(const FlightModel &m, PetscReal t, PetscReal speed);
// The spin in effect, |w| d(t) (rad/s).
PetscReal FlightSpinAt(const FlightModel &m, PetscReal t, PetscReal speed);
// The spin factor S = R |w| d(t) / |v| (1; speed > 0).
PetscReal FlightSpinFactor(const FlightModel &m, PetscReal t, PetscReal speed);
PetscReal FlightDragCoefficient(const FlightModel &m, PetscReal t, PetscReal speed);
PetscReal FlightLiftCoefficient(const FlightModel &m, PetscReal S);

// The acceleration (m/s^2) at time t and velocity v; the right-hand side du/dt of the state.
void FlightAcceleration(const FlightModel &m, PetscReal t, const PetscReal v[3], PetscReal a[3]);
void FlightRHS(const FlightModel &m, PetscReal t, const PetscReal u[6], PetscReal du[6]);

// One step of a flight: the states at both ends with their accelerations. Between them the
// quintic Hermite interpolant through position, velocity and acceleration (error O(h^6) in
// position, O(h^5) in velocity) gives the series samples, the apex and the landing's first guess.
struct FlightStep {
  PetscReal t0 = 0, t1 = 0;
  PetscReal u0[6] = {0}, u1[6] = {0};
  PetscReal a0[3] = {0}, a1[3] = {0};
};
void FlightStepInterpolate(const FlightStep &s, PetscReal t, PetscReal u[6]);
// The time in [t0, t1] where the interpolant's height comes down to zero (needs z0 >= 0 > z1 or
// z0 > 0 >= z1; from z0 = 0 going up, the root after the interpolant's top).
PetscReal FlightStepGroundTime(const FlightStep &s);
// The top of the interpolant in [t0, t1] (needs vz0 > 0 >= vz1): its time and height.
void FlightStepApex(const FlightStep &s, PetscReal *t, PetscReal *z);

// Where and how the ball lands, from the launch state and the landing state at time t.
struct FlightLanding {
  PetscReal distance      = 0; // m, horizontal, launch point to landing point
  PetscReal hang_time     = 0; // s
  PetscReal landing_speed = 0; // m/s
  PetscReal landing_angle = 0; // deg below the horizontal
  PetscReal landing_x     = 0; // m (frame above)
  PetscReal landing_y     = 0; // m
  PetscReal bearing       = 0; // deg, from the y axis toward +x, seen from the launch point
};
FlightLanding FlightLandingOf(const PetscReal u0[6], PetscReal t, const PetscReal u[6]);

} // namespace beamimpact

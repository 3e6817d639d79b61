// The batted ball's flight under Nathan's trajectory model. See flight.hpp; the formulas and
// constants are those of A. M. Nathan's TrajectoryCalculator-new-3D.xlsx (docs/flight.md cites
// the cells), converted to SI exactly.
#include "model/flight.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

namespace {

// Exact unit conversions.
constexpr PetscReal kFoot         = 0.3048;        // m
constexpr PetscReal kPound        = 0.45359237;    // kg
constexpr PetscReal kMillimetreHg = 133.322387415; // Pa

// The calculator's constants (cells D1, D2, D4, D5, D20 of its sheets).
constexpr PetscReal kRho0         = 1.2929;   // kg/m^3, dry air at 273 K and 760 mmHg
constexpr PetscReal kT0           = 273;      // K, as the sheet writes it
constexpr PetscReal kP0           = 760;      // mmHg
constexpr PetscReal kBeta         = 1.217e-4; // 1/m, pressure falls as exp(-beta h)
constexpr PetscReal kVapour       = 0.3783;   // 1 - M_water/M_air: humid air is lighter
constexpr PetscReal kHalfAOverM   = 0.07182;  // ft^2/lb, 1/2 A/m of the 5.125 oz, 9.125 in ball (rounded)
constexpr PetscReal kLbFt3PerKgM3 = 0.06261;  // the sheet's conversion of rho to lb/ft^3

} // namespace

const PetscReal kFlightDecaySpeed = 146.7 * kFoot; // m/s: 100 mph as the sheet converts it (1.467 ft/s per mph)

PetscReal FlightSpinMax(PetscReal radius) { return kSpeedOfSound / radius; }

PetscReal FlightCalculatorFactor()
{
  const PetscReal circ = 9.125 / 12, mass = 5.125 / 16;          // ft, lb: the reference ball
  const PetscReal half  = 0.5 * circ * circ / (4 * M_PI) / mass; // ft^2/lb, exact 1/2 A/m
  const PetscReal lbft3 = kFoot * kFoot * kFoot / kPound;        // lb/ft^3 per kg/m^3, exact
  return (kHalfAOverM / half) * (kLbFt3PerKgM3 / lbft3);
}

PetscReal AirSaturationVaporPressure(PetscReal T)
{
  return 4.5841 * std::exp((18.687 - T / 234.5) * T / (257.14 + T)) * kMillimetreHg;
}

PetscReal AirDensity(const AirParams &air)
{
  if (air.density >= 0) return air.density;
  const PetscReal p = air.pressure / kMillimetreHg * std::exp(-kBeta * air.elevation); // mmHg at the field
  const PetscReal e = kVapour * (air.humidity / 100) * AirSaturationVaporPressure(air.temperature) / kMillimetreHg;
  return kRho0 * (kT0 / (air.temperature + kT0)) * (p - e) / kP0;
}

FlightModel FlightModelOf(const FlightParams &p)
{
  FlightModel     m;
  const PetscReal d2r = M_PI / 180, th = p.launch.angle * d2r, ph = p.launch.direction * d2r;
  const PetscReal wb = p.launch.backspin, ws = p.launch.sidespin;
  m.rho = AirDensity(p.air);
  m.K   = 0.5 * m.rho * M_PI * p.ball.radius * p.ball.radius / p.ball.mass;
  if (p.aero.constants == FlightConstants::Calculator) m.K *= FlightCalculatorFactor();
  // Backspin about (cos phi, -sin phi, 0); sidespin about (-sin th sin phi, -sin th cos phi, cos th).
  m.w[0]    = wb * std::cos(ph) - ws * std::sin(th) * std::sin(ph);
  m.w[1]    = -wb * std::sin(ph) - ws * std::sin(th) * std::cos(ph);
  m.w[2]    = ws * std::cos(th);
  m.spin    = std::sqrt(wb * wb + ws * ws);
  m.radius  = p.ball.radius;
  m.cd0     = p.aero.cd0;
  m.cd_spin = p.aero.cd_spin * (30 / M_PI) / 1000; // per 1000 rpm -> per rad/s
  m.cl0     = p.aero.cl0;
  m.cl1     = p.aero.cl1;
  m.cl2     = p.aero.cl2;
  m.tau     = p.aero.spin_decay_time;
  m.gravity = p.gravity;
  return m;
}

void FlightInitialState(const FlightLaunch &l, PetscReal u[6])
{
  const PetscReal d2r = M_PI / 180, th = l.angle * d2r, ph = l.direction * d2r;
  u[0] = 0, u[1] = 0, u[2] = l.height;
  u[3] = l.speed * std::cos(th) * std::sin(ph);
  u[4] = l.speed * std::cos(th) * std::cos(ph);
  u[5] = l.speed * std::sin(th);
}

PetscReal FlightSpinDecay(const FlightModel &m, PetscReal t, PetscReal speed)
{
  return m.tau > 0 ? std::exp(-t * speed / (m.tau * kFlightDecaySpeed)) : 1.0;
}

PetscReal FlightSpinAt(const FlightModel &m, PetscReal t, PetscReal speed)
{
  return m.spin * FlightSpinDecay(m, t, speed);
}

PetscReal FlightSpinFactor(const FlightModel &m, PetscReal t, PetscReal speed)
{
  return m.radius * FlightSpinAt(m, t, speed) / speed;
}

PetscReal FlightDragCoefficient(const FlightModel &m, PetscReal t, PetscReal speed)
{
  return m.cd0 + m.cd_spin * FlightSpinAt(m, t, speed);
}

PetscReal FlightLiftCoefficient(const FlightModel &m, PetscReal S) { return m.cl2 * S / (m.cl0 + m.cl1 * S); }

void FlightAcceleration(const FlightModel &m, PetscReal t, const PetscReal v[3], PetscReal a[3])
{
  const PetscReal speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  a[0] = a[1] = 0;
  a[2]        = -m.gravity;
  if (speed == 0 || m.K == 0) return; // no air force at rest or in vacuum
  const PetscReal drag = m.K * FlightDragCoefficient(m, t, speed) * speed;
  for (int i = 0; i < 3; ++i) a[i] -= drag * v[i];
  if (m.spin == 0) return;
  const PetscReal lift = m.K * FlightLiftCoefficient(m, FlightSpinFactor(m, t, speed)) / m.spin * speed; // times w x v
  a[0] += lift * (m.w[1] * v[2] - m.w[2] * v[1]);
  a[1] += lift * (m.w[2] * v[0] - m.w[0] * v[2]);
  a[2] += lift * (m.w[0] * v[1] - m.w[1] * v[0]);
}

void FlightRHS(const FlightModel &m, PetscReal t, const PetscReal u[6], PetscReal du[6])
{
  du[0] = u[3], du[1] = u[4], du[2] = u[5];
  FlightAcceleration(m, t, u + 3, du + 3);
}

void FlightStepInterpolate(const FlightStep &s, PetscReal t, PetscReal u[6])
{
  const PetscReal h = s.t1 - s.t0, x = h > 0 ? (t - s.t0) / h : 1, x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
  // Quintic Hermite basis on [0, 1] (value, h * slope, h^2 * curvature at each end) and its derivative.
  const PetscReal H[6]  = {1 - 10 * x3 + 15 * x4 - 6 * x5,    x - 6 * x3 + 8 * x4 - 3 * x5,
                           0.5 * (x2 - 3 * x3 + 3 * x4 - x5), 10 * x3 - 15 * x4 + 6 * x5,
                           -4 * x3 + 7 * x4 - 3 * x5,         0.5 * (x3 - 2 * x4 + x5)};
  const PetscReal dH[6] = {-30 * x2 + 60 * x3 - 30 * x4,
                           1 - 18 * x2 + 32 * x3 - 15 * x4,
                           0.5 * (2 * x - 9 * x2 + 12 * x3 - 5 * x4),
                           30 * x2 - 60 * x3 + 30 * x4,
                           -12 * x2 + 28 * x3 - 15 * x4,
                           0.5 * (3 * x2 - 8 * x3 + 5 * x4)};
  for (int i = 0; i < 3; ++i) {
    const PetscReal c[6] = {s.u0[i], h * s.u0[3 + i], h * h * s.a0[i], s.u1[i], h * s.u1[3 + i], h * h * s.a1[i]};
    PetscReal       p = 0, dp = 0;
    for (int k = 0; k < 6; ++k) p += c[k] * H[k], dp += c[k] * dH[k];
    u[i]     = p;
    u[3 + i] = h > 0 ? dp / h : s.u1[3 + i];
  }
}

namespace {

// A root of f on [a, b] with f(a), f(b) of opposite signs (or one zero): Illinois false position,
// to the resolution of the interval.
template <class F>
PetscReal BracketedRoot(F f, PetscReal a, PetscReal b)
{
  PetscReal fa = f(a), fb = f(b);
  if (fa == 0) return a;
  if (fb == 0) return b;
  int side = 0;
  for (int it = 0; it < 200 && b - a > 4 * PETSC_MACHINE_EPSILON * std::max(std::abs(a), std::abs(b)); ++it) {
    PetscReal c = (a * fb - b * fa) / (fb - fa);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const PetscReal fc = f(c);
    if (fc == 0) return c;
    if ((fc > 0) == (fb > 0)) {
      b = c, fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = c, fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
  return std::abs(fa) < std::abs(fb) ? a : b;
}

} // namespace

PetscReal FlightStepGroundTime(const FlightStep &s)
{
  PetscReal a = s.t0, z_top;
  if (s.u0[2] <= 0 && s.u0[5] > 0)
    FlightStepApex(s, &a, &z_top); // a step from the ground over the whole flight: the root after the top
  return BracketedRoot(
    [&](PetscReal t) {
      PetscReal u[6];
      FlightStepInterpolate(s, t, u);
      return u[2];
    },
    a, s.t1);
}

void FlightStepApex(const FlightStep &s, PetscReal *t, PetscReal *z)
{
  PetscReal u[6];
  *t = BracketedRoot(
    [&](PetscReal r) {
      FlightStepInterpolate(s, r, u);
      return u[5];
    },
    s.t0, s.t1);
  FlightStepInterpolate(s, *t, u);
  *z = u[2];
}

FlightLanding FlightLandingOf(const PetscReal u0[6], PetscReal t, const PetscReal u[6])
{
  FlightLanding   l;
  const PetscReal dx = u[0] - u0[0], dy = u[1] - u0[1], horizontal = std::sqrt(u[3] * u[3] + u[4] * u[4]);
  l.distance      = std::sqrt(dx * dx + dy * dy);
  l.hang_time     = t;
  l.landing_speed = std::sqrt(horizontal * horizontal + u[5] * u[5]);
  l.landing_angle = std::atan2(-u[5], horizontal) * 180 / M_PI;
  l.landing_x     = u[0];
  l.landing_y     = u[1];
  l.bearing       = std::atan2(dx, dy) * 180 / M_PI;
  return l;
}

} // namespace beamimpact

// The -flight_* and -air_* options. See flight_options.hpp.
#include "io/flight_options.hpp"

#include <cmath>

namespace beamimpact {

const OptionModule &FlightOptionTable()
{
  static const OptionModule m = {
    "flight",
    "Flight of the batted ball, -task flight (A. M. Nathan's trajectory model; docs/flight.md)",
    {
      OptionReal("-flight_speed", "m/s", "Launch speed of the ball", "45", Positive()),
      OptionReal("-flight_angle", "deg", "Launch angle above the horizontal", "30", Between(-90, 90)),
      OptionReal("-flight_direction", "deg",
                 "Horizontal launch direction, from the y axis (down the field) toward +x (to the right)", "0",
                 Between(-180, 180)),
      OptionReal("-flight_spin", "rad/s",
                 "Backspin about the horizontal axis across the launch direction (< 0: topspin; 2500 rpm = 261.8 "
                 "rad/s); the whole spin's surface speed below the speed of sound, |spin| R < 343 m/s",
                 "250"),
      OptionReal("-flight_sidespin", "rad/s",
                 "Sidespin about the axis across the launch in its vertical plane (> 0 curves the ball toward -x, the "
                 "calculator's sign); bounded with -flight_spin",
                 "0"),
      OptionReal("-flight_height", "m", "Launch height above the ground (the ground is z = 0)", "1", NonNegative()),
      OptionReal("-flight_ball_mass", "kg",
                 "Mass of the ball, -task flight (default: the calculator's baseball, 5.125 oz; after an impact, "
                 "-flight, the impact's ball: -ball_mass)",
                 "0.145291", Positive()),
      OptionReal("-flight_ball_radius", "m",
                 "Radius of the ball, -task flight (default: circumference 9.125 in; after an impact the impact's "
                 "ball: -ball_radius)",
                 "0.0368881", Positive()),
      OptionReal("-flight_cd0", "1", "Drag coefficient without spin, C_D = cd0 + cd_spin (spin / 1000 rpm)", "0.3008",
                 NonNegative()),
      OptionReal("-flight_cd_spin", "1 per 1000 rpm", "Increase of C_D with the spin, in the calculator's unit",
                 "0.0292"),
      OptionReal("-flight_cl0", "1", "Lift C_L = cl2 S / (cl0 + cl1 S), S = R spin / speed", "0.583", Positive()),
      OptionReal("-flight_cl1", "1", "Lift coefficient cl1 (see -flight_cl0)", "2.333", NonNegative()),
      OptionReal("-flight_cl2", "1", "Lift coefficient cl2 (see -flight_cl0)", "1.120", NonNegative()),
      OptionReal("-flight_spin_decay_time", "s",
                 "Decay time of the spin's effect at 100 mph, shorter in proportion to the speed (0: no decay)", "30",
                 NonNegative()),
      OptionChoice("-flight_constants",
                   "K = 1/2 rho A / m as the calculator evaluates it (calculator: its rounded constants 0.07182 and "
                   "0.06261, K 0.28% above) or exactly (exact)",
                   {"calculator", "exact"}, "calculator"),
      OptionReal("-flight_gravity", "m/s^2", "Acceleration of gravity (the calculator: 32.174 ft/s^2 = 9.8066352)",
                 "9.80665", NonNegative()),
      OptionReal("-flight_series_dt", "s",
                 "Interval of the trajectory's samples in /series (0: only launch and landing; a sweep writes none); "
                 "at most -max_memory of samples up to -flight_ts_max_time",
                 "0.01", NonNegative()),
      OptionFlag("-flight", "-task impact: fly the batted ball after the impact from its exit speed, launch angle and "
                            "spin (distance, apex, hang_time in /results, the trajectory in /series); the launch "
                            "options -flight_speed, -flight_angle, -flight_spin then come from the impact, the ball "
                            "(its mass and size) is the impact's (-ball_mass, -ball_radius), the aerodynamics Nathan's "
                            "baseball's unless -flight_cd*/-flight_cl* are given"),
    },
  };
  return m;
}

const OptionModule &AirOptionTable()
{
  static const OptionModule m = {
    "air",
    "Air of the flight (its density as Nathan's trajectory calculator computes it)",
    {
      OptionReal("-air_temperature", "degC", "Air temperature", "20", Between(-60, 60)),
      OptionReal("-air_pressure", "Pa",
                 "Barometric pressure reduced to sea level, as weather reports give it (29.92 inHg = 101321 Pa)",
                 "101325", Positive()),
      OptionReal("-air_humidity", "%", "Relative humidity", "50", Between(0, 100)),
      OptionReal("-air_elevation", "m",
                 "Elevation of the field above sea level (the pressure there is the reduced one times exp(-1.217e-4 "
                 "h))",
                 "0", Between(-500, 9000)),
      OptionReal("-air_density", "kg/m^3",
                 "Air density: given, it replaces the one computed from the four options above, which -help shows (0: "
                 "vacuum)",
                 "", NonNegative()),
    },
  };
  return m;
}

namespace {

// The launch's spin (backspin and sidespin) within its bound, FlightSpinMax (model/flight.hpp).
PetscErrorCode FlightSpinCheck(MPI_Comm comm, const FlightParams &p)
{
  const PetscReal spin = std::hypot(p.launch.backspin, p.launch.sidespin), max = FlightSpinMax(p.ball.radius);
  PetscFunctionBeginUser;
  if (spin < max) PetscFunctionReturn(0);
  std::string given;
  for (const char *o : {"-flight_spin", "-flight_sidespin"})
    if (!OptionWritten(o).empty()) given += (given.empty() ? "" : " with ") + std::string(o) + " " + OptionWritten(o);
  SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE,
          "%s is not allowed: a spin of %g rad/s moves the ball's surface at %g m/s (-flight_ball_radius %g m), beyond "
          "the speed of sound in air (%g m/s), where no drag or lift model holds (the "
          "lift is fitted to 1500-4500 rpm, Nathan 2008); the spin must be below %g rad/s",
          given.c_str(), (double)spin, (double)(spin * p.ball.radius), (double)p.ball.radius, (double)kSpeedOfSound,
          (double)max);
}

} // namespace

PetscErrorCode AirParamsFromOptions(MPI_Comm comm, AirParams *air)
{
  const OptionModule &t = AirOptionTable();
  PetscBool           set_density;
  PetscReal           density;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, t.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, t, "-air_temperature", &air->temperature, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-air_pressure", &air->pressure, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-air_humidity", &air->humidity, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-air_elevation", &air->elevation, NULL));
  density = AirDensity(*air); // -help shows the computed value as the default
  PetscCall(OptionsRead(PetscOptionsObject, t, "-air_density", &density, &set_density));
  PetscOptionsEnd();
  if (set_density) air->density = density;
  else
    PetscCheck(std::isfinite(density) && density > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-air_temperature %g, -air_pressure %g, -air_humidity %g and -air_elevation %g give an air density of "
               "%g kg/m^3: it must be > 0 (is the pressure far below the vapour's?)",
               (double)air->temperature, (double)air->pressure, (double)air->humidity, (double)air->elevation,
               (double)density);
  PetscFunctionReturn(0);
}

PetscErrorCode FlightAfterImpactFromOptions(MPI_Comm comm, PetscBool *on, FlightParams *p, FlightSolveParams *s,
                                            bool series)
{
  const OptionModule &t    = FlightOptionTable();
  PetscBool           help = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help)
    PetscFunctionReturn(
      0); // -help lists -flight in the flight's block (FlightParamsFromOptions): PETSc prints a block's title once
  PetscOptionsBegin(comm, NULL, t.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight", on, NULL));
  PetscOptionsEnd();
  if (!*on) PetscFunctionReturn(0);
  for (const char *launch :
       {"-flight_speed", "-flight_angle", "-flight_spin", "-flight_sidespin", "-flight_direction"}) {
    PetscBool given;
    PetscCall(PetscOptionsHasName(NULL, NULL, launch, &given));
    PetscCheck(!given, comm, PETSC_ERR_ARG_INCOMP,
               "%s %s with -flight: after an impact the launch (speed, angle, spin) is the batted ball's; remove %s, "
               "or fly a given launch with -task flight",
               launch, OptionWritten(launch).c_str(), launch);
  }
  for (const char *ball : {"-flight_ball_mass", "-flight_ball_radius"}) {
    PetscBool given;
    PetscCall(PetscOptionsHasName(NULL, NULL, ball, &given));
    PetscCheck(!given, comm, PETSC_ERR_ARG_INCOMP,
               "%s %s with -flight: after an impact the flight flies the impact's own ball (-ball_mass, -ball_radius); "
               "remove %s, or fly a ball of your own with -task flight",
               ball, OptionWritten(ball).c_str(), ball);
  }
  PetscCall(FlightParamsFromOptions(comm, p, s, series));
  PetscCall(FlightTSCheckOptions(*s)); // the flight's integrator before the impact, whose ball it flies after
  PetscFunctionReturn(0);
}

PetscErrorCode FlightParamsFromOptions(MPI_Comm comm, FlightParams *p, FlightSolveParams *s, bool series)
{
  const OptionModule &t         = FlightOptionTable();
  PetscInt            constants = p->aero.constants == FlightConstants::Calculator ? 0 : 1;
  PetscBool           help      = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  PetscOptionsBegin(comm, NULL, t.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_speed", &p->launch.speed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_angle", &p->launch.angle, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_direction", &p->launch.direction, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_spin", &p->launch.backspin, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_sidespin", &p->launch.sidespin, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_height", &p->launch.height, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_ball_mass", &p->ball.mass, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_ball_radius", &p->ball.radius, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_cd0", &p->aero.cd0, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_cd_spin", &p->aero.cd_spin, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_cl0", &p->aero.cl0, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_cl1", &p->aero.cl1, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_cl2", &p->aero.cl2, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_spin_decay_time", &p->aero.spin_decay_time, NULL));
  PetscCall(OptionsReadChoice(PetscOptionsObject, t, "-flight_constants", &constants, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_gravity", &p->gravity, NULL));
  if (series || help)
    PetscCall(OptionsRead(PetscOptionsObject, t, "-flight_series_dt", &s->series_dt, NULL)); // else unread: a note
  s->series = series;
  if (help) {
    PetscBool after = PETSC_FALSE; // -help lists -flight (of -task impact) in this block
    PetscCall(OptionsRead(PetscOptionsObject, t, "-flight", &after, NULL));
  }
  PetscOptionsEnd();
  p->aero.constants = constants == 0 ? FlightConstants::Calculator : FlightConstants::Exact;
  PetscCall(FlightSpinCheck(comm, *p));
  PetscCheck(p->launch.height > 0 || p->launch.angle > 0, comm, PETSC_ERR_ARG_INCOMP,
             "-flight_height 0 with -flight_angle %g: the ball would start on the ground going down; give a launch "
             "angle > 0 or a height > 0",
             (double)p->launch.angle);
  PetscCall(AirParamsFromOptions(comm, &p->air));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The scenario from the options. See scenario_options.hpp.
#include "io/scenario_options.hpp"

#include "base/option_table.hpp"
#include "io/text.hpp"
#include "system/beam_system.hpp"

#include <cmath>
#include <cstdio>

namespace beamimpact {

const OptionModule &SwingOptionTable()
{
  static const OptionModule m = {
    "bat",
    "Swinging bat: its rigid motion toward the ball before the impact (given, or the batter's swing law of the bat's "
    "moment of inertia)",
    {
      OptionReal("-bat_speed", "m/s", "Centre-of-mass speed V_cm of the bat toward the ball", "0"),
      OptionReal("-bat_angular_velocity", "rad/s",
                 "Angular velocity Omega about the centre of mass (> 0: the x = L end moves faster toward the ball)",
                 "0"),
      OptionNeeds(OptionReal("-bat_speed_face", "m/s",
                             "A racket's speed along its face at the impact point, toward +z (across the mains; > 0: "
                             "brushing up the back of a ball on a face whose +z is up, a topspin forehand), beside "
                             "its swing toward the ball; for an impact on a string bed (docs/model.md section 13, "
                             "\"On the string bed\")",
                             "0"),
                  {"-strings_frame=held|-strings_frame=beam", "-ball_radius"}),
      OptionReal("-bat_swing_angular_velocity", "rad/s",
                 "The batter's swing as a law instead of -bat_speed/-bat_angular_velocity: the bat turns at omega_0 "
                 "about -bat_swing_pivot, both scaled by (I_s/I_0)^(-n) (Cross & Bower 2006)",
                 ""),
      OptionNeeds(OptionReal("-bat_swing_pivot", "m",
                             "The point x_s the swing turns about (the hands), from x = 0; I_s is the bat's moment of "
                             "inertia about it",
                             "0", NonNegative()),
                  {"-bat_swing_angular_velocity"}),
      OptionNeeds(OptionReal("-bat_swing_pivot_speed", "m/s", "The speed v_s of the point x_s toward the ball (at I_0)",
                             "0"),
                  {"-bat_swing_angular_velocity"}),
      OptionNeeds(OptionReal("-bat_swing_exponent", "1",
                             "n of the swing speed's law V = V_0 (I_s/I_0)^(-n) (Cross & Bower 2006: 0.25 softball "
                             "bats, 0.26 golf clubs, 0.27 rods and rackets)",
                             "0.26", Between(0, 2)),
                  {"-bat_swing_reference_inertia"}),
      OptionNeeds(OptionReal("-bat_swing_reference_inertia", "kg m^2",
                             "I_0: the moment of inertia about x_s at which the batter swings at omega_0 (default: "
                             "none, the swing does not depend on the bat)",
                             "", Positive()),
                  {"-bat_swing_angular_velocity"}),
    },
  };
  return m;
}

namespace {

// -bat_speed, -bat_angular_velocity (or the swing's law, -bat_swing_*: the rigid motion from the
// bat's moment of inertia, model/swing.hpp): a swinging bat, free at both ends.
PetscErrorCode SwingFromOptions(MPI_Comm comm, const BeamParams &beam, SwingParams *s)
{
  const OptionModule &T = SwingOptionTable();
  SwingLaw            law;
  PetscBool           setlaw = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_speed", &s->bat_speed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_angular_velocity", &s->bat_angular_velocity, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_speed_face", &s->face_speed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_swing_angular_velocity", &law.angular_velocity, &setlaw));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_swing_pivot", &law.pivot, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_swing_pivot_speed", &law.pivot_speed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_swing_exponent", &law.exponent, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_swing_reference_inertia", &law.reference_inertia, NULL));
  PetscOptionsEnd();
  if (setlaw) {
    PetscCheck(!s->Swings(), comm, PETSC_ERR_ARG_INCOMP,
               "-bat_swing_angular_velocity with %s is not allowed: the swing is either the law's or the bat's own "
               "rigid motion",
               s->bat_speed != 0 ? "-bat_speed" : "-bat_angular_velocity");
    PetscCheck(law.pivot < beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-bat_swing_pivot %g is not allowed: the swing turns about a point of the bat, 0 <= x_s < L = %g (m)",
               (double)law.pivot, (double)beam.length);
    law.on = true;
    *s     = SwingFromLaw(law, BeamRigidBodyOf(beam));
  }
  if (s->Swings()) {
    const char *held = beam.left.Holds() != NodeHold::None  ? "-beam_left"
                     : beam.right.Holds() != NodeHold::None ? "-beam_right"
                     : beam.has_clamp                       ? "-beam_clamp"
                     : beam.has_pivot                       ? "-beam_pivot"
                                                            : nullptr;
    PetscCheck(!held, comm, PETSC_ERR_ARG_INCOMP,
               "-bat_speed/-bat_angular_velocity swing a free bat: %s holds it (remove it, or do not swing)", held);
  }
  PetscFunctionReturn(0);
}

// Each registered part present at the impact point (StructurePart::Resolve: the shell's patch
// radius from the ball at the approach speed, its entries within the coupling's room).
PetscErrorCode StructurePartsResolve(MPI_Comm comm, Scenario *sc)
{
  PetscFunctionBeginUser;
  if (sc->beam.parts.present.empty()) PetscFunctionReturn(0);
  PartPoint at;
  at.ball     = &sc->ball;
  at.x        = sc->impact.x;
  at.z        = sc->impact.z;
  at.approach = ImpactApproachSpeed(*sc);
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = sc->beam.parts.Find(part->Name())) {
      std::shared_ptr<const PartParams> out;
      std::string                       why;
      PetscCheck(part->Resolve(*q, sc->beam, at, &out, &why), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", why.c_str());
      if (out) sc->beam.parts.Set(part->Name(), out);
    }
  PetscFunctionReturn(0);
}

// -flight: the flight flies the impact's own ball (its mass and size: run/oblique.cpp), which
// needs its radius; with Nathan's baseball coefficients unless the run gives its own, a note
// when the ball is not a baseball (its mass or radius 10 % or more from the calculator's).
PetscErrorCode FlightBallResolve(MPI_Comm comm, const Scenario &sc)
{
  PetscFunctionBeginUser;
  PetscCheck(sc.ball.radius > 0, comm, PETSC_ERR_ARG_WRONG,
             "-flight needs the ball's size for its drag and lift in the air: give -ball_radius (m)");
  const FlightBall baseball;
  const bool       other = std::abs(sc.ball.mass / baseball.mass - 1) >= 0.1 ||
                     std::abs(sc.ball.radius / baseball.radius - 1) >= 0.1;
  bool aero = false;
  for (const char *c : {"-flight_cd0", "-flight_cd_spin", "-flight_cl0", "-flight_cl1", "-flight_cl2"}) {
    PetscBool given;
    PetscCall(PetscOptionsHasName(NULL, NULL, c, &given));
    aero = aero || given;
  }
  if (!other || aero) PetscFunctionReturn(0);
  const FlightAero &a = sc.flight.params.aero;
  char              text[600];
  std::snprintf(text, sizeof text,
                "note: -flight flies the impact's ball (%g kg, radius %g m) with Nathan's baseball aerodynamics (C_D = "
                "%g + %g per 1000 rpm, C_L = %g S/(%g + %g S)): another ball has its own (a tennis ball's C_D is "
                "about 0.55); give -flight_cd0, -flight_cd_spin, -flight_cl0, -flight_cl1, -flight_cl2 "
                "(docs/flight.md)\n",
                (double)sc.ball.mass, (double)sc.ball.radius, (double)a.cd0, (double)a.cd_spin, (double)a.cl2,
                (double)a.cl0, (double)a.cl1);
  PetscCall(PrintOnce(comm, text));
  PetscFunctionReturn(0);
}

} // namespace

unsigned ScenarioPartOf(const std::string &name)
{
  const std::string option = name.empty() || name[0] == '-' ? name : "-" + name;
  for (const OptionModule *m : OptionModules()) {
    if (!m->Find(option)) continue;
    if (m->name == "ball") return ScenarioBall;
    if (m->name == "bat") return ScenarioSwing;
    if (m->name == "impact") return ScenarioImpact;
    if (m->name == "monitor") return ScenarioMonitors;
    if (m->name == "flight" || m->name == "air") return ScenarioFlight;
    return ScenarioAll;
  }
  return ScenarioAll;
}

PetscErrorCode ScenarioFromOptions(MPI_Comm comm, const ScenarioReading &how, Scenario *sc)
{
  const unsigned read = how.reuse && !(how.read & ScenarioBeam) ? how.read
                                                                : ScenarioAll; // a beam read again: everything
  auto           part = [&](ScenarioPart p) { return (read & p) != 0; };

  PetscFunctionBeginUser;
  if (how.reuse) { // the parts not read again, as read before
    const Scenario &r = *how.reuse;
    if (!part(ScenarioBeam)) sc->beam = r.beam;
    if (!part(ScenarioBall)) sc->ball = r.ball;
    if (!part(ScenarioSwing)) sc->swing = r.swing;
    if (!part(ScenarioImpact)) sc->impact = r.impact;
    if (!part(ScenarioMonitors)) sc->monitor = r.monitor;
    if (!part(ScenarioFlight)) sc->flight = r.flight;
  }
  if (part(ScenarioBeam)) PetscCall(BeamParamsFromOptions(comm, &sc->beam));
  if (part(ScenarioBall)) PetscCall(BallParamsFromOptions(comm, &sc->ball));
  if (part(ScenarioSwing)) PetscCall(SwingFromOptions(comm, sc->beam, &sc->swing));
  // A ball at rest is struck only by a swinging bat (the approach speed v_i + V(x) > 0 is then
  // checked at the impact point, naming both options).
  PetscCheck(sc->ball.speed > 0 || sc->swing.Swings(), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-ball_speed 0 is not allowed for a bat at rest: ball and beam would never meet; give -ball_speed > 0 "
             "(m/s), or swing the bat (-bat_speed, -bat_angular_velocity)");
  if (how.after_bodies) PetscCall(how.after_bodies(*sc));
  if (part(ScenarioImpact)) PetscCall(ImpactParamsFromOptions(comm, sc->beam, &sc->impact));
  const PartParamSet parts_as_read = sc->beam.parts;
  PetscCall(StructurePartsResolve(comm, sc));
  if (how.monitors && part(ScenarioMonitors)) PetscCall(MonitorRequestFromOptions(comm, sc->beam, &sc->monitor));
  if (part(ScenarioFlight))
    PetscCall(FlightAfterImpactFromOptions(comm, &sc->flight.on, &sc->flight.params, &sc->flight.solve,
                                           how.monitors && how.flight_series));
  if (sc->flight.on && (part(ScenarioFlight) || part(ScenarioBall))) PetscCall(FlightBallResolve(comm, *sc));
  if (how.read_as) {
    *how.read_as            = *sc;
    how.read_as->beam.parts = parts_as_read;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ScenarioFromOptions(MPI_Comm comm, Scenario *sc)
{
  PetscFunctionBeginUser;
  PetscCall(ScenarioFromOptions(comm, ScenarioReading(), sc));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

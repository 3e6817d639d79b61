// The impact's rules and monitors from the options (-impact_*, -monitor_*, -snapshot_times)
// and the run's time rules. See impact.hpp.
#include "run/impact.hpp"

#include "run/impact_params.hpp"
#include "run/impact_point.hpp"
#include "run/scenario.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

const char *ImpactAfterName(ImpactAfter a) { return a == ImpactAfter::Time ? "time" : "modal"; }

ImpactTimes ImpactTimesOf(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip)
{
  ImpactTimes     t;
  const PetscReal omega1 = BeamFundamentalFrequencyEstimate(beam);
  t.window               = ip.window >= 0 ? ip.window : 2 * (2 * M_PI / omega1);
  // A ball at rest (struck by a swinging bat): a speed-dependent law's time scale at v_i = 0 is
  // infinite; the cap takes it at 1 m/s (as long or longer than at a faster approach for every law
  // that stiffens with compression).
  BallParams at = ball;
  if (!(at.speed > 0)) at.speed = 1;
  t.max_time = ip.max_time > 0 ? ip.max_time : 4 * t.window + 100 * ContactTimeScale(at);
  return t;
}

PetscReal ImpactApproachSpeed(const Scenario &sc)
{
  if (!sc.swing.Swings()) return sc.ball.speed;
  return sc.ball.speed + SwingSpeedAt(sc.swing, BeamRigidBodyOf(sc.beam), sc.impact.x);
}

const OptionModule &ImpactOptionTable()
{
  static const OptionModule m = {
    "impact",
    "Impact: where the ball strikes and how long to follow it",
    {
      OptionReal("-impact_x", "m", "Impact point, metres from the x = 0 end", "0.55"),
      OptionNeeds(OptionReal("-impact_z", "m",
                             "Impact point across the face, metres from the frame's axis (a racket's off-centre hit: "
                             "it rolls the head; > 0 toward +z of the string bed's grid); needs -beam_torsion or a "
                             "string bed; inside the head's outline, or without a bed within the section's half-width "
                             "(half -beam_width, a profile's radius; else half the frame's length)",
                             "0"),
                  {"-beam_torsion|-strings_frame"}),
      OptionNeeds(OptionReal("-impact_offset", "m",
                             "Offset D of the ball's line of flight from the bat's axis (> 0: the ball's centre passes "
                             "above it, the bat strikes below its centre: launched up with backspin); needs a round "
                             "bat (-beam_profile) and -ball_radius; 0: head-on",
                             "0"),
                  {"-ball_radius"}),
      OptionNeeds(OptionReal("-impact_angle", "deg",
                             "An oblique impact on a racket's string bed: the ball's path at this angle from the "
                             "face's normal, in the plane of the normal and the face's z (across the mains: > 0 the "
                             "ball moving toward +z, leaving with backspin about x; < 0 toward -z, as a racket "
                             "brushing up the back of the ball: topspin); needs a string bed struck inside its "
                             "outline (-strings_frame), -ball_radius, and no -impact_offset (a bat's); 0: along the "
                             "normal",
                             "0", Between(-90, 90, true, true)),
                  {"-ball_radius", "-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionChoice("-impact_tangential_plane",
                               "An oblique impact: the bat in its second bending plane (across the line of centres), "
                               "flexible (the same beam in its modes, driven by the friction force) or rigid (its "
                               "effective mass at the impact point); on a string bed, flexible: the mains under the "
                               "ball slide and snap back on the frame (-strings_inplane_*), rigid: they are locked, "
                               "the rigid-surface model on the frame's effective mass",
                               {"flexible", "rigid"}, "flexible"),
                  {"-impact_offset!=0|-ball_spin!=0|-impact_angle!=0|-bat_speed_face!=0", "-ball_friction!=0"}),
      OptionReal("-impact_window", "s",
                 "Time followed after each separation, >= 0 (0: nothing followed); default two fundamental periods of "
                 "the beam (the file records the value used)",
                 "", NonNegative()),
      OptionChoice("-impact_after",
                   "After a separation: integrate in time, or the exact free vibration in the beam's modes (modal: the "
                   "default wherever the beam allows it)",
                   {"time", "modal"}, "modal"),
      OptionReal("-impact_max_time", "s",
                 "Cap on the simulated time; <= 0: 4 windows + 100 contact times (the file records the value used); a "
                 "run it cuts off in contact is an error, a failed point",
                 "-1"),
      OptionReal("-impact_event_tol", "1",
                 "Events are located until |indicator| (c/c_scale or dc/dt/v_i) is below this", "1e-10",
                 Between(0, 1e-2, true, true)),
      OptionInt("-impact_max_contacts", "Stop with an error after this many separate contacts", "50", AtLeast(1)),
      OptionFlag("-impact_energy_check", "Stop when the total energy grows beyond -impact_energy_growth_tol"),
      OptionReal("-impact_cost_warn", "s",
                 "-task impact: print the expected cost before a run expected to take more than this (wall time)", "30",
                 NonNegative()),
      OptionReal("-impact_progress", "s",
                 "-task impact: a progress line every this many seconds of wall time (0: none)", "10", NonNegative()),
      OptionNeeds(OptionReal("-impact_energy_growth_tol", "1",
                             "Allowed energy growth, relative to the incident kinetic energy", "1e-3", Positive()),
                  {"-impact_energy_check=true"}),
    },
  };
  return m;
}

const OptionModule &MonitorOptionTable()
{
  static const OptionModule m = {
    "monitor",
    "Monitors: time series and snapshots, written only when asked",
    {
      OptionFlag("-monitor_ball", "Record ball position, velocity, compression and force at every step"),
      OptionFlag("-monitor_energy",
                 "Record ball kinetic, stored and dissipated energy and beam kinetic and strain energy at every step"),
      OptionList("-monitor_velocity_at", "m",
                 "Record the beam velocity at these points x1,x2,... at every step (any number; none by default)", 1, 0,
                 NonNegative()),
      OptionList("-snapshot_times", "s",
                 "Record the beam displacement y(x) at these times t1,t2,... (any number, in any order; none by "
                 "default; times after the run's end are named in a note)",
                 1, 0, NonNegative()),
      OptionList("-monitor_segment", "m",
                 "Record the kinetic energy of the beam segment x0,x1 at every step, and its peak", 2, 2,
                 NonNegative()),
      OptionNeeds(OptionReal("-monitor_segment_until", "s",
                             "Take the segment's peak over t <= this; < 0: the whole run", "-1"),
                  {"-monitor_segment"}),
    },
  };
  return m;
}

PetscErrorCode ImpactParamsFromOptions(MPI_Comm comm, const BeamParams &beam, ImpactParams *p)
{
  const OptionModule &T     = ImpactOptionTable();
  PetscInt            after = (PetscInt)p->after; // the row's choices in the order of ImpactAfter
  PetscBool           x_set;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_x", &p->x, &x_set));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_z", &p->z, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_offset", &p->offset, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_angle", &p->angle, NULL));
  {
    PetscInt plane = p->tangential_rigid ? 1 : 0; // the row's choices: flexible, rigid
    PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-impact_tangential_plane", &plane, NULL));
    p->tangential_rigid = plane == 1 ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_window", &p->window, NULL));
  PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-impact_after", &after, &p->after_set));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_max_time", &p->max_time, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_event_tol", &p->event_tol, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_max_contacts", &p->max_contacts, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_energy_check", &p->energy_check, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_cost_warn", &p->cost_warn, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_progress", &p->progress, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-impact_energy_growth_tol", &p->energy_growth_tol, NULL));
  PetscOptionsEnd();
  p->after = (ImpactAfter)after;
  // The default point is in metres, not relative: on a beam shorter than 0.55 m it is off the
  // beam, and the message says so instead of naming an option the user never gave.
  PetscCheck(x_set || ImpactPointLocate(beam, p->x) != ImpactPointWhere::OffBeam, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "the default impact point -impact_x %g m is beyond the end of this %.12g m beam: give -impact_x, 0 <= x "
             "<= %.12g (m)",
             (double)p->x, (double)beam.length, (double)beam.length);
  {
    char what[64];
    PetscCall(PetscSNPrintf(what, sizeof(what), "-impact_x %.12g", (double)p->x));
    PetscCall(ImpactAcrossCheck(comm, beam, p->z));
    PetscCall(ImpactPointCheck(comm, beam, p->x, what, p->z));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode MonitorRequestFromOptions(MPI_Comm comm, const BeamParams &beam, MonitorRequest *m)
{
  const OptionModule    &T = MonitorOptionTable();
  std::vector<PetscReal> seg;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-monitor_ball", &m->ball, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-monitor_energy", &m->energy, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-monitor_velocity_at", &m->velocity_at, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-snapshot_times", &m->snapshot_times, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-monitor_segment", &seg, &m->segment));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-monitor_segment_until", &m->segment_until, NULL));
  PetscOptionsEnd();
  // a part's own monitor row (the hands'), read with its options
  m->parts = StructurePartsMonitor(beam);
  if (m->segment) { // two values >= 0: the row's; on the beam and in order: here
    PetscCheck(seg[0] < seg[1] && seg[1] <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-monitor_segment %g,%g is not allowed: it needs two points 0 <= x0 < x1 <= L = %g (m)", (double)seg[0],
               (double)seg[1], (double)beam.length);
    m->segment_x0 = seg[0];
    m->segment_x1 = seg[1];
  }
  for (PetscReal x : m->velocity_at)
    PetscCheck(x <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-monitor_velocity_at %g is not allowed: points must lie on the beam, 0 <= x <= %g (m)", (double)x,
               (double)beam.length);
  std::sort(m->snapshot_times.begin(), m->snapshot_times.end());
  PetscFunctionReturn(0);
}

} // namespace beamimpact

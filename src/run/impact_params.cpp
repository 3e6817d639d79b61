// The impact's rules and monitors from the options (-impact_*, -monitor_*, -snapshot_times)
// and the run's time rules. See impact.hpp.
#include "run/impact.hpp"

#include "base/options_util.hpp"
#include "run/impact_point.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

const char *ImpactAfterName(ImpactAfter a) { return a == ImpactAfter::Time ? "time" : "modal"; }

ImpactTimes ImpactTimesOf(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip)
{
  ImpactTimes     t;
  const PetscReal omega1 = BeamFundamentalFrequencyEstimate(beam);
  t.window               = ip.window >= 0 ? ip.window : 2 * (2 * M_PI / omega1);
  t.max_time             = ip.max_time > 0 ? ip.max_time : 4 * t.window + 100 * ContactTimeScale(ball);
  return t;
}

PetscErrorCode ImpactParamsFromOptions(MPI_Comm comm, const BeamParams &beam, ImpactParams *p)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Impact: where the ball strikes and how long to follow it", "beamimpact");
  PetscCall(PetscOptionsReal("-impact_x", "Impact point, metres from the x = 0 end", "", p->x, &p->x, NULL));
  PetscCall(PetscOptionsReal("-impact_window", "Time followed after each separation (s); < 0: two fundamental periods of the beam (the file records the value used)", "", p->window, &p->window, NULL));
  {
    const char *const names[] = {"time", "modal", "ImpactAfter", "IMPACT_AFTER_", nullptr};
    PetscEnum         e       = (PetscEnum)p->after;
    PetscCall(PetscOptionsEnum("-impact_after", "After a separation: integrate in time, or the exact free vibration in the beam's modes (modal: the default wherever the beam allows it)", "", names, e, &e,
                               &p->after_set));
    p->after = (ImpactAfter)e;
  }
  PetscCall(PetscOptionsReal("-impact_max_time", "Cap on the simulated time (s); < 0: 4 windows + 100 contact times (the file records the value used); a run it cuts off in contact is an error, a failed point", "", p->max_time, &p->max_time, NULL));
  PetscCall(PetscOptionsReal("-impact_event_tol", "Events are located until |indicator| (c/c_scale or dc/dt/v_i) is below this", "", p->event_tol, &p->event_tol, NULL));
  PetscCall(PetscOptionsInt("-impact_max_contacts", "Stop with an error after this many separate contacts", "", p->max_contacts, &p->max_contacts, NULL));
  PetscCall(PetscOptionsBool("-impact_energy_check", "Stop when the total energy grows beyond -impact_energy_growth_tol", "", p->energy_check, &p->energy_check, NULL));
  PetscCall(PetscOptionsReal("-impact_cost_warn", "-task impact: print the expected cost before a run expected to take more than this (s of wall time)", "", p->cost_warn, &p->cost_warn, NULL));
  PetscCall(PetscOptionsReal("-impact_progress", "-task impact: a progress line every this many seconds of wall time (0: none)", "", p->progress, &p->progress, NULL));
  PetscCall(PetscOptionsReal("-impact_energy_growth_tol", "Allowed energy growth, relative to the incident kinetic energy", "", p->energy_growth_tol, &p->energy_growth_tol, NULL));
  PetscOptionsEnd();
  {
    char what[64];
    PetscCall(PetscSNPrintf(what, sizeof(what), "-impact_x %.12g", (double)p->x));
    PetscCall(ImpactPointCheck(comm, beam, p->x, what));
  }
  PetscCheck(p->event_tol > 0 && p->event_tol < 1e-2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_event_tol %g is not allowed: use a value in (0, 1e-2)", (double)p->event_tol);
  PetscCheck(p->max_contacts >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_max_contacts %" PetscInt_FMT " is not allowed: at least 1", p->max_contacts);
  PetscCheck(p->cost_warn >= 0 && p->progress >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_cost_warn %g, -impact_progress %g are not allowed: they must be >= 0 (s)", (double)p->cost_warn, (double)p->progress);
  PetscCheck(p->energy_growth_tol > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_energy_growth_tol %g is not allowed: it must be > 0", (double)p->energy_growth_tol);
  PetscFunctionReturn(0);
}

PetscErrorCode MonitorRequestFromOptions(MPI_Comm comm, const BeamParams &beam, MonitorRequest *m)
{
  PetscInt  npts = 0, ntimes = 0; // lists of any length: sized from the options first
  PetscBool setpts = PETSC_FALSE, settimes = PETSC_FALSE;
  PetscReal seg[2] = {0, 0};
  PetscInt  nseg   = 2;

  PetscFunctionBeginUser;
  PetscCall(OptionsListLength("-monitor_velocity_at", &npts));
  PetscCall(OptionsListLength("-snapshot_times", &ntimes));
  std::vector<PetscReal> pts(std::max<PetscInt>(npts, 1), 0.0), times(std::max<PetscInt>(ntimes, 1), 0.0);
  PetscOptionsBegin(comm, NULL, "Monitors: time series and snapshots, written only when asked", "beamimpact");
  PetscCall(PetscOptionsBool("-monitor_ball", "Record ball position, velocity, compression and force at every step", "", m->ball, &m->ball, NULL));
  PetscCall(PetscOptionsBool("-monitor_energy", "Record ball kinetic, stored and dissipated energy and beam kinetic and strain energy at every step", "", m->energy, &m->energy, NULL));
  PetscCall(PetscOptionsRealArray("-monitor_velocity_at", "Record the beam velocity at these points x1,x2,... (m) at every step (any number; none by default)", "", pts.data(), &npts, &setpts));
  PetscCall(PetscOptionsRealArray("-snapshot_times", "Record the beam displacement y(x) at these times t1,t2,... (s) (any number, in any order; none by default; times after the run's end are named in a note)", "", times.data(), &ntimes, &settimes));
  PetscCall(PetscOptionsRealArray("-monitor_segment", "Record the kinetic energy of the beam segment x0,x1 (m) at every step, and its peak", "", seg, &nseg, &m->segment));
  PetscCall(PetscOptionsBool("-monitor_grip", "With -grip: record the force of the bat on the hands (total, and its moment about x = 0), the grip's stored energy and the hands' work at every step", "", m->grip, &m->grip, NULL));
  PetscCall(PetscOptionsReal("-monitor_segment_until", "Take the segment's peak over t <= this (s); < 0: the whole run", "", m->segment_until, &m->segment_until, NULL));
  PetscOptionsEnd();
  if (m->segment) {
    PetscCheck(nseg == 2 && seg[0] >= 0 && seg[0] < seg[1] && seg[1] <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-monitor_segment needs two points 0 <= x0 < x1 <= L = %g (m); got %" PetscInt_FMT " value(s) %g,%g", (double)beam.length, nseg, (double)seg[0], (double)(nseg > 1 ? seg[1] : 0));
    m->segment_x0 = seg[0];
    m->segment_x1 = seg[1];
  }
  if (setpts) {
    for (PetscInt q = 0; q < npts; ++q)
      PetscCheck(pts[q] >= 0 && pts[q] <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE, "-monitor_velocity_at %g is not allowed: points must lie on the beam, 0 <= x <= %g (m)", (double)pts[q], (double)beam.length);
    m->velocity_at.assign(pts.begin(), pts.begin() + npts);
  }
  if (settimes) {
    for (PetscInt q = 0; q < ntimes; ++q) PetscCheck(times[q] >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-snapshot_times %g is not allowed: times must be >= 0 (s)", (double)times[q]);
    m->snapshot_times.assign(times.begin(), times.begin() + ntimes);
    std::sort(m->snapshot_times.begin(), m->snapshot_times.end());
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

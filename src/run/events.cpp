// Contact events: which one a step crossed, the indicator it is located on, the bracketed
// location on any stepper, and its application to the contact law and the outcome.
// See events.hpp.
#include "run/events.hpp"

#include "run/impact_problem.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

static const char *const EventNames[] = {"contact", "max_compression", "reload", "separation"};
const char              *ContactEventName(ContactEventKind k) { return EventNames[static_cast<int>(k)]; }

int ContactCrossedEvent(ContactPhase phase, const EventIndicators &a, const EventIndicators &b, PetscReal tol)
{
  switch (phase) {
  case ContactPhase::Loading:
    if (a.cdot > -tol && b.cdot <= 0 && !(a.cdot <= 0 && b.cdot >= a.cdot))
      return static_cast<int>(ContactEventKind::MaxCompression);
    if (a.c > -tol && b.c <= 0 && !(a.c <= 0 && b.c >= a.c))
      return static_cast<int>(ContactEventKind::Separation); // only if dc/dt was missed
    return -1;
  case ContactPhase::Unloading: {
    const bool sep = a.c > 0 && b.c <= 0, rel = a.cdot < tol && b.cdot >= 0 && !(a.cdot >= 0 && b.cdot <= a.cdot);
    if (sep && rel) { // the earlier root by linear interpolation
      const PetscReal ts = a.c / (a.c - b.c), tr = a.cdot / (a.cdot - b.cdot);
      return static_cast<int>(tr < ts ? ContactEventKind::Reload : ContactEventKind::Separation);
    }
    if (sep) return static_cast<int>(ContactEventKind::Separation);
    if (rel) return static_cast<int>(ContactEventKind::Reload);
    return -1;
  }
  case ContactPhase::Separated:
    return a.c < 0 && b.c >= 0 ? static_cast<int>(ContactEventKind::ContactStart) : -1;
  }
  return -1;
}

PetscReal ContactEventIndicator(ContactEventKind k, const EventIndicators &g)
{
  return (k == ContactEventKind::MaxCompression || k == ContactEventKind::Reload) ? g.cdot : g.c;
}

bool ContactEventFalling(ContactEventKind k)
{
  return k == ContactEventKind::MaxCompression || k == ContactEventKind::Separation;
}

ContactEvent ContactStartEvent(const BallParams &ball, const ContactState &s, PetscReal te, PetscReal c, PetscReal v)
{
  ContactEvent e{ContactEventKind::ContactStart, te, c, ContactForce(ball, s, c)};
  e.approach_speed = v;
  e.cor            = BallCorAt(ball, v);
  e.n              = ContactUnloadingExponent(ball, s);
  return e;
}

PetscErrorCode ContactEventApply(const ImpactProblem &pb, const char *method, ContactEventKind kind, const EventAt &at,
                                 ImpactRunState *run, bool *force_changed)
{
  const MPI_Comm     comm  = pb.comm;
  const BallParams  &ball  = pb.sc.ball;
  const ImpactTimes &times = pb.times;
  const PetscReal    te = at.te, c = at.c, cdot = at.cdot;
  ContactState      *state = &run->contact;
  ContactTimeline   *tl    = &run->timeline;
  ContactTally      *tally = &run->record.contact;
  PetscFunctionBeginUser;
  *force_changed = true;
  switch (kind) {
  case ContactEventKind::MaxCompression:
    *force_changed = ContactHasHysteresis(ball);
    ContactSwitch(ball, state, ContactPhase::Unloading, c);
    break;
  case ContactEventKind::Reload:
    *force_changed = ContactHasHysteresis(ball);
    ContactSwitch(ball, state, ContactPhase::Loading, c);
    break;
  case ContactEventKind::Separation:
    if (state->phase == ContactPhase::Loading && ContactHasHysteresis(ball)) {
      // The unloading branch was never applied: the ball would leave without its hysteresis loss.
      char after[96] = "";
      for (const ContactEvent &e : tally->events)
        if (e.kind == ContactEventKind::Reload)
          PetscCall(PetscSNPrintf(after, sizeof(after), " after the reload located at t = %g s", (double)e.time));
      SETERRQ(comm, PETSC_ERR_PLIB,
              "the ball separated at t = %g s while the hysteretic law was still in its loading branch: the "
              "maximum-compression event was missed%s, so the unloading (lossy) branch was skipped and "
              "the result would be wrong; none is reported (%s; a defect of the event location: a different step "
              "changes whether it is hit)",
              (double)te, after, method);
    }
    ContactSwitch(ball, state, ContactPhase::Separated, c);
    if (tally->contacts == 1) tally->contact_time = te - tl->contact_start;
    tally->contact_time_total += te - tl->contact_start;
    tl->t_stop = std::min(times.max_time, te + times.window);
    break;
  case ContactEventKind::ContactStart:
    ContactBegin(ball, state, cdot); // what the law keeps for this contact (with -ball_cor_table: n from e(v_approach))
    ContactSwitch(ball, state, ContactPhase::Loading, c);
    tally->contacts++;
    tl->contact_start = te;
    tl->t_stop        = times.max_time;
    break;
  }
  const PetscReal F = ContactForce(ball, *state, c);
  if (kind == ContactEventKind::ContactStart) tally->events.push_back(ContactStartEvent(ball, *state, te, c, cdot));
  else tally->events.push_back({kind, te, c, F});
  if (kind == ContactEventKind::MaxCompression) {
    tally->max_compression = std::max(tally->max_compression, c);
    tally->peak_force      = std::max(tally->peak_force, F);
  }
  PetscFunctionReturn(0);
}

void ContactTallyStart(const BallParams &ball, const ContactState &s, PetscReal v, ContactTally *tally)
{
  tally->contacts = 1;
  tally->events.push_back(ContactStartEvent(ball, s, 0.0, 0.0, v));
}

void ContactTallyClose(ContactPhase phase, const ContactTimeline &tl, PetscReal t, ContactTally *tally)
{
  tally->touching = phase != ContactPhase::Separated;
  if (!tally->touching) return;
  tally->contact_time_total += t - tl.contact_start;
  if (tally->contacts == 1) tally->contact_time = t - tl.contact_start;
}

PetscErrorCode EventLocate(Stepper &stepper, ContactEventKind kind, PetscReal ta, PetscReal ga, PetscReal gb,
                           PetscReal tol, const std::function<PetscErrorCode(EventIndicators *)> &indicators,
                           PetscInt *event_steps)
{
  const bool falling = ContactEventFalling(kind);
  PetscReal  tb      = stepper.Time();
  const PetscReal
       step_len = tb - ta; // a located event is within 1e-4 of this: an O(1e-8 dt^2) local error at a C^0 force switch
  bool at_post  = true;
  int  side     = 0;
  // The bracket is lost when a re-step to its post end lands on the pre side (another path to
  // the same time: the event's time moves with the path, by up to the local error): the post
  // end is then unknown, and steps of doubling length from the least one walk on until the
  // indicator is past the event, which closes a new bracket.
  bool      lost = false;
  PetscReal walk = 0;

  PetscFunctionBeginUser;
  for (int it = 0;; ++it) {
    if (at_post && std::abs(gb) <= tol) break;
    if (!at_post && std::abs(ga) <= tol) break; // on the root from the pre-event side: as good
    PetscCheck(it < 100, stepper.Comm(), PETSC_ERR_NOT_CONVERGED,
               "event %s could not be located in [%g, %g] s with %s (indicator %g -> %g)", ContactEventName(kind),
               (double)ta, (double)tb, stepper.Method().c_str(), (double)ga, (double)gb);
    const PetscReal min_step = 1e-4 * step_len;
    PetscReal       tn;
    if (lost) tn = ta + (walk = std::min(2 * walk, step_len));
    else {
      tn = tb - gb * (tb - ta) / (gb - ga);
      if (!(tn > ta && tn < tb)) tn = 0.5 * (ta + tb);
      // Never re-step by a vanishing amount (implicit second-order schemes are ill-conditioned
      // there): a bracket this narrow is located; take the post side.
      if (tn - ta < min_step) tn = std::min(tb, ta + min_step);
      if (tb - ta <= 2 * min_step) {
        if (at_post) break;
        // The step to tb landed on the pre side this time (another path to the same time: its
        // round-off; on a grid beyond double precision, N = 40961 with cn, by more than tol; at
        // a coarse implicit step, its local error): the bracket has closed, and a step to tb
        // would be of length 0 (a NaN residual in an implicit solve). Walk on past tb.
        if (tb - ta > 8 * PETSC_MACHINE_EPSILON * std::abs(tb)) tn = tb;
        else lost = true, tn = ta + (walk = min_step);
      }
    }
    if (at_post) PetscCall(stepper.RollBack());
    PetscCall(stepper.Step(tn - ta));
    (*event_steps)++;
    EventIndicators gn;
    PetscCall(indicators(&gn));
    const PetscReal gv   = ContactEventIndicator(kind, gn);
    const bool      post = falling ? gv <= 0 : gv >= 0;
    if (post) {
      tb = stepper.Time();
      gb = gv;
      if (side == 1) ga *= 0.5; // Illinois
      side    = 1;
      at_post = true;
      lost    = false; // a new bracket [ta, tb]
    } else {
      ta = stepper.Time();
      ga = gv;
      if (side == -1) gb *= 0.5;
      side    = -1;
      at_post = false;
      if (!lost && ta >= tb * (1 - 8 * PETSC_MACHINE_EPSILON))
        lost = true, walk = min_step; // at or past the old post end, still before the event
    }
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// Contact events of the run (MODEL: contact start, maximum compression, reload,
// separation): which one a step crossed, on which scaled indicator it is located, the
// location itself on any stepper (bracketing re-steps onto the root, so the stepper's own
// state is on the event and its order survives the force kink), and the event's effect on
// the contact law, the outcome and the run's stop time.
//
// Why not PETSc's TSSetEventHandler: in PETSc 3.18 its locator misses or invents events
// with some types and disagrees between serial and parallel runs (rewritten in 3.21), it
// works on TS only (the leapfrog baseline and the modal tools have no TS), and an event
// changing only the loading/unloading branch does not restart the integrator. The locator
// here is used by every stepper alike (docs/design.md).
#pragma once

#include "run/impact.hpp"
#include "solvers/stepper.hpp"

#include <functional>

namespace beamimpact {

// Scaled indicators: c / c_scale and (dc/dt) / v_i.
struct EventIndicators {
  PetscReal c = 0, cdot = 0;
};
// The event crossed between indicator values a (step start) and b (step end) in `phase`
// (-1: none). A start within tol of zero on the wrong side (an event located from its
// pre-event side) counts as before the crossing, so the next event is never missed.
int ContactCrossedEvent(ContactPhase phase, const EventIndicators &a, const EventIndicators &b, PetscReal tol);
// The indicator an event is located on, and whether it falls through zero.
PetscReal ContactEventIndicator(ContactEventKind k, const EventIndicators &g);
bool      ContactEventFalling(ContactEventKind k);
// The run's contact bookkeeping between events.
struct ContactTimeline {
  PetscReal contact_start = 0; // s, start of the current (or last) contact
  PetscReal t_stop        = 0; // s, the run ends here unless another contact starts
};
// Where a located event is: its time te (s), the compression c (m) and its rate cdot (m/s).
struct EventAt {
  PetscReal te = 0, c = 0, cdot = 0;
};
struct ImpactProblem;
struct ImpactRunState;
// Applies a located event `at` of the problem's run (run/impact_problem.hpp) to its state
// (run->contact, run->timeline, the tally run->record.contact): switches the law's phase, records the event, peak
// force, maximum compression, contacts and contact times in the tally, moves the stop time. At a contact start cdot is
// the approach speed: with -ball_cor_table the contact's unloading exponent n is set from e(cdot), and the event
// records cdot, e and n. *force_changed tells whether the force law changed (the integrator must restart). A separation
// still in the hysteretic loading branch (a missed maximum compression) is an error: the result would lack the ball's
// loss. The caller checks -impact_max_contacts. method: the stepper's, for the message of a missed maximum compression.
PetscErrorCode ContactEventApply(const ImpactProblem &pb, const char *method, ContactEventKind kind, const EventAt &at,
                                 ImpactRunState *run, bool *force_changed);
// ContactStartEvent: the record of a contact that starts with approach speed v (m/s) in state s.
ContactEvent ContactStartEvent(const BallParams &ball, const ContactState &s, PetscReal te, PetscReal c, PetscReal v);
// The first contact, at t = 0 with approach speed v (m/s), in the tally.
void ContactTallyStart(const BallParams &ball, const ContactState &s, PetscReal v, ContactTally *tally);
// The end of the run at time t (s) in `phase`: a contact still open is closed there (touching).
void ContactTallyClose(ContactPhase phase, const ContactTimeline &tl, PetscReal t, ContactTally *tally);

// Locates event `kind` crossed by the stepper's last step, from the step's start ta with
// indicator ga to its end with gb (the stepper is at tb): Illinois (regula falsi)
// re-steps from the bracket's pre-event end, until the indicator is within tol. Leaves the
// stepper on the located state; counts the re-steps in *event_steps. indicators(g) reads
// the current state's scaled indicators.
PetscErrorCode EventLocate(Stepper &stepper, ContactEventKind kind, PetscReal ta, PetscReal ga, PetscReal gb,
                           PetscReal tol, const std::function<PetscErrorCode(EventIndicators *)> &indicators,
                           PetscInt *event_steps);

} // namespace beamimpact

// One impact's problem, complete before the first step: the scenario as run (an oblique
// impact's projection on the normal, once), the system, the ball's coupling, the contact's
// scales, the swing's initial motion and frame, the run's times, -impact_after resolved
// against the system, -ts_type, and the modal truncation (-modal_modes, -modal_tolerance,
// -modal_weight, -modal_refine) read once, where a consumer of the modes runs. The driver, the
// steppers (through StepperProblem), the free flight, the oblique impact's second plane and the
// exact modal reference take it; nothing after its build reads those options again.
#pragma once

#include "run/events.hpp"
#include "run/impact.hpp"
#include "run/outcome.hpp"
#include "run/scenario.hpp"
#include "solvers/stepper_problem.hpp"

#include <memory>
#include <string>
#include <vector>

namespace beamimpact {

// Who runs the problem: the PETSc TS stepper (-ts_type), the leapfrog baseline (serial), or the
// exact modal reference (-reference modal: no stepper, no system here: it builds its own).
enum class ImpactMethod {
  Stepped,
  Leapfrog,
  ModalReference
};

struct ImpactProblem {
  MPI_Comm     comm   = MPI_COMM_NULL;
  ImpactMethod method = ImpactMethod::Stepped;
  Scenario     sc;    // as run: an oblique impact's run along the normal (run/oblique.hpp), else as given
  ImpactTimes  times; // the window after each separation and -impact_max_time (s)
  std::shared_ptr<const BeamSystem> system; // built for this run, or the structure's (ImpactStructure)
  const BeamSystem                 &sys() const { return *system; }
  ContactCoupling                   g;             // the ball's contact point on the system
  ContactScales                     scales;        // of the first contact's approach speed
  PetscReal                         V_x      = 0;  // m/s, the swinging bat's speed toward the ball at the impact point
  PetscReal                         approach = 0;  // m/s, v_ball + V_x: the first contact's approach speed
  std::vector<PetscReal>            beam_velocity; // m/s (rad/s) per dof at t = 0 (empty: at rest)
  FrameMotion frame;   // the swing's rigid frame, which a grip ties the handle to (at rest for a bat at rest)
  std::string ts_type; // Stepped: -ts_type as the TS stepper takes it (default rk)
  bool        after_modal = false; // -impact_after resolved: the free flight after a separation is modal
  bool        needs_force = false; // a stage after the contact reads F_n(t) (run/stage.hpp): the run records it
  // Whether some consumer of the modes runs (-ts_type modal, the modal free flight with a window
  // to follow, an oblique impact's second plane, the modal reference): then the truncation was
  // read, so its options are marked used before the stepper's check of unused options.
  bool            modal_used = false;
  ModalTruncation truncation; // read once; T and the force's start from `approach`, the load g, the run's
                              // cost line and progress (the modal reference: its own rule, T its default)
};

// What one run of the problem changes: the contact law's phase (the stepper's force law reads
// it: ImpactProblemStepper), the contact's start and the stop time, the record the outcome is
// made of (the tally, series, peaks, measures, mode energies), the free flight's modes (once).
struct ImpactRunState {
  ContactState                     contact;
  ContactTimeline                  timeline;
  ImpactRecord                     record;
  std::shared_ptr<const BeamModes> modes; // the free flight's basis (the problem's truncation)
};

// Builds the problem of `given` for `method` (Stepped and Leapfrog: the system from *structure
// when it holds one, else built and kept there; structure may be nullptr). Collective on comm.
PetscErrorCode ImpactProblemBuild(MPI_Comm comm, const Scenario &given, ImpactMethod method, ImpactStructure *structure,
                                  ImpactProblem *pb);

// What the steppers are created from; contact: the run's contact state (its phase).
StepperProblem ImpactProblemStepper(const ImpactProblem &pb, ContactState *contact);

// The truncation the cost note of an explicit step bound estimates -ts_type modal's modes with
// (no load: a mode's error alone): the problem's when it read one, else read now, after the
// stepper's check of unused options (-task impact), as before the problem object (a sweep's
// check, after its probe, counts it: the set of options marked used is unchanged).
PetscErrorCode ImpactProblemNoteTruncation(const ImpactProblem &pb, ModalTruncation *t);

// The truncation an oblique impact's second plane keeps its modes with (no load).
ModalTruncation ImpactProblemPlaneTruncation(const ImpactProblem &pb);

} // namespace beamimpact

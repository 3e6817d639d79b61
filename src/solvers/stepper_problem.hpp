// What every stepper of the impact is created from (the PETSc TS stepper, the leapfrog): the
// system, the ball at its contact point, the contact's scales and state, the beam's initial
// motion, the swing's frame and the modal truncation, all resolved once by the run's set-up
// (run/impact_problem.hpp, ImpactProblemStepper). Pointers: owned by the caller, alive while
// the stepper is.
#pragma once

#include "model/contact.hpp"
#include "solvers/beam_modes.hpp"
#include "system/beam_system.hpp"

#include <string>
#include <vector>

namespace beamimpact {

struct StepperProblem {
  MPI_Comm                      comm = MPI_COMM_NULL;
  const BeamSystem             *sys  = nullptr;
  ContactCoupling               g;                       // the ball's contact point on the beam
  BallParams                    ball;                    // as given (its speed m/s: the ball's own)
  ContactScales                 scales;                  // of the first contact's approach speed
  ContactState                 *contact       = nullptr; // the phase the force law reads (the run's)
  const std::vector<PetscReal> *beam_velocity = nullptr; // m/s (rad/s) per dof at t = 0 (empty: at rest)
  const FrameMotion            *frame         = nullptr; // the swing's frame, which a grip ties the handle to
  std::string                   ts_type       = "rk";    // -ts_type, read once (the formulation depends on it)
  ModalTruncation truncation; // -ts_type modal's modes: T, the load, cost line and progress set (the free flight's)
};

} // namespace beamimpact

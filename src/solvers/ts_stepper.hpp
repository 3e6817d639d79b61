// The PETSc TS stepper of the impact: any -ts_type that can roll back a step, in the
// formulation its type needs (explicit RHS, IMEX split, fully implicit, second-order form
// for alpha2; solvers/ts_problem.hpp), behind the Stepper interface (solvers/stepper.hpp).
// The TS is configured from the options database (no prefix), after the program's defaults:
// a step of T_r/200 (explicit rk: at most 0.9 of its stability limit), adaptive steps capped
// at T_r/8 so one step cannot hold two events, LU (MUMPS in parallel) for the linear solves.
#pragma once

#include "model/contact.hpp"
#include "solvers/stepper.hpp"
#include "solvers/stepper_problem.hpp"
#include "system/beam_system.hpp"

#include <memory>

namespace beamimpact {

struct TSStepperSettings {
  bool check_unused_options  = false; // an option set but not used by the TS set-up is an error
  bool report_setup          = false; // print the integrator, its step and stability limit, and resolution warnings
  bool strict_solver_options = false; // with check_unused_options: left-over PETSc solver options are errors too, not
                                      // notes
  // The key of the integrator's context (its communicator, grid, type and the -ts_, -snes_, -ksp_,
  // -pc_, -mat_ options) kept by a caller whose runs change none of these (a sweep's points on one
  // structure: ImpactStructure): used when not empty, else computed from the options database and
  // stored there. nullptr: computed for this run.
  std::string *context_key = nullptr;
};

// Creates the stepper of p.ts_type on p.comm at t = 0 with the beam undeformed, moving with
// p.beam_velocity, and the ball touching it at the impact point, moving at the ball's speed;
// fills *info. p.contact and p.frame (the swing's frame the force operator ties a grip to) are
// the contact law's state and the frame the residuals use; -ts_type modal keeps p.truncation's modes.
PetscErrorCode TSStepperCreate(const StepperProblem &p, const TSStepperSettings &settings,
                               std::unique_ptr<Stepper> *stepper, IntegratorInfo *info);

// The per-structure contexts (the layout, the configured TS, its vectors and the Jacobian's
// storage): TSStepperCreate reuses one built for the same communicator, grid, type and solver
// options (-ts_, -snes_, -ksp_, -pc_, -mat_) when no run holds it, so a sweep's points cost
// their stepping only (-ts_type modal too: its modes, gamma and static correction set per point,
// TSModalNewPoint). A run that checks its options (-task impact) or a
// TS monitor builds its own. built / reused: the contexts made and the runs that reused one,
// since the start; the cache is emptied at PetscFinalize, or by TSStepperContextCacheClear.
void TSStepperContextCounts(PetscInt *built, PetscInt *reused);
// The LU factorizations of the beam's part of the implicit types' Jacobian (one per structure
// and step size, kept with the context: ts_problem.hpp, JacobianCache) since the start.
PetscInt       TSStepperBeamFactorizations();
PetscErrorCode TSStepperContextCacheClear();

} // namespace beamimpact

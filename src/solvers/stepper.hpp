// One small interface over every time stepper of the impact (the PETSc TS stepper, the
// leapfrog baseline): the run driver (run/impact_driver.cpp) steps, rolls back, restarts
// and reads the state through it, and owns the event location, the contact phases and the
// outcome. A stepper evaluates the contact force with the ContactState the driver owns
// (given at creation) and calls Restart() when the driver switched its phase.
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

namespace beamimpact {

// Read access to the current state: beam dof d (node-major, system/beam_system.hpp) is
// y[(d / fields) * stride + d % fields] for d in the owned range widened by the ghost width,
// and v[...] likewise for owned d; the ball's values are the same on every rank.
struct StateView {
  const PetscReal *y = nullptr, *v = nullptr;
  PetscInt         y_stride = 1, v_stride = 1; // per node
  PetscInt         d0 = 0, d1 = 0;             // owned dofs
  PetscReal        ball_y = 0, ball_v = 0;     // m, m/s
};

// The whole state, the same on every rank: beam dof d (node-major, held dofs 0) at y[d], v[d];
// the ball; and the energy dissipated by the beam's damping since t = 0 (J).
struct FullState {
  std::vector<PetscReal> y, v; // m (or rad), m/s (or rad/s)
  PetscReal              ball_y = 0, ball_v = 0, dissipated = 0;
};

// The state in the modes of a basis (solvers/beam_modes.hpp, mass-normalised: the beam's free
// dofs are M^{-1/2} Phi z): the amplitudes and their rates per kept mode, the ball, and the
// energy dissipated by the beam's damping since t = 0 (J). The same on every rank.
struct ModalState {
  std::vector<PetscReal> z, zd; // m kg^{1/2}, m kg^{1/2}/s per mode
  PetscReal              ball_y = 0, ball_v = 0, dissipated = 0;
};

// A state kept to be expanded later with others (Stepper::Sample, Stepper::Expand): -ts_type
// modal's state in its modes and the force the static shape of its modes left out carries.
struct StateSample {
  PetscReal              t = 0;                  // s
  std::vector<PetscReal> z, zd;                  // m kg^{1/2}, m kg^{1/2}/s per kept mode
  PetscReal              static_force = 0;       // N: on the modes left out, quasi-statically (0: every mode kept)
  PetscReal              ball_y = 0, ball_v = 0; // m, m/s: the ball's centre (the state's own, as written)
};

// Where expanded samples lie (Stepper::Expand): this rank's owned beam dofs [d0, d1) and the
// range [e0, e1) the arrays hold (the owned ones and the neighbours' the strain terms reach).
struct SampleRange {
  PetscInt d0 = 0, d1 = 0, e0 = 0, e1 = 0;
};

// What the stepper itself counted.
struct StepperCounts {
  PetscInt rejected_steps = 0; // rejected by the error controller
  PetscInt failed_solves  = 0; // nonlinear solves that failed (the step was retried smaller)
  PetscInt function_evals = 0, jacobian_evals = 0, jacobian_assemblies = 0, nonlinear_its = 0, linear_its = 0;
};

// How the run is integrated (set when the stepper is created).
struct IntegratorInfo {
  std::string ts_type;                 // -ts_type, or "leapfrog" / "modal"
  std::string formulation;             // explicit | imex | implicit | second-order | exact
  PetscReal   dt_stable       = 0;     // s, explicit stability limit (0: not explicit)
  PetscReal   dt_nominal      = 0;     // s, the fixed step, or the initial step of an adaptive run
  PetscReal   omega_max_bound = 0;     // rad/s, Gershgorin bound used for dt_stable
  PetscInt    omega_max_dof   = -1;    // the dof whose row sets it (-1: the ball's contact spring)
  bool        fixed_step      = false; // the step is fixed (-ts_adapt_type none): dt_nominal throughout
};

struct BeamModes;

class Stepper {
public:
  // The modal engine's basis when the stepper is one (-ts_type modal), else null.
  virtual std::shared_ptr<const BeamModes> Modes() const { return nullptr; }
  virtual ~Stepper()                        = default;
  virtual MPI_Comm       Comm() const       = 0;
  virtual std::string    Method() const     = 0; // for messages: "-ts_type cn", "leapfrog"
  virtual std::string    StepOption() const = 0; // what sets its step: "-ts_dt", "-ts_rtol/-ts_atol", "-leapfrog_dt"
  virtual PetscReal      Time() const       = 0; // s
  virtual PetscErrorCode Step(
    PetscReal dt)                   = 0; // one step from the current state; a failed step is an error that says why
  virtual PetscErrorCode RollBack() = 0; // back to the start of the last step
  virtual PetscErrorCode Restart()  = 0; // the force law changed at the current state
  virtual PetscErrorCode NextStep(
    PetscReal *dt) = 0; // the step it takes next (fixed, or the adaptive suggestion within its cap)
  virtual PetscErrorCode Compression(PetscReal *c, PetscReal *cdot) = 0; // m, m/s at the current state (every rank)
  virtual PetscErrorCode ViewBegin(StateView *v)                    = 0;
  virtual PetscErrorCode ViewEnd(StateView *v)                      = 0;
  // Rank 0: fields [f0, f0 + nf) of every node's displacement, node-major (y[i nf + f - f0]; m or
  // rad): field 0 alone is the deflection per node, a string bed's fields its columns.
  virtual PetscErrorCode GatherFields(PetscInt f0, PetscInt nf, std::vector<PetscReal> *y) = 0;
  PetscErrorCode         GatherDisplacement(std::vector<PetscReal> *y)
  {
    return GatherFields(0, 1, y);
  } // rank 0: deflection per node (m)
  virtual PetscErrorCode Counts(StepperCounts *n) = 0;
  // Why the energy may have grown at the current step (the likely cause, for the error message).
  virtual std::string EnergyGrowthCause() const = 0;
  // Energy (J) dissipated by the beam's damping C since t = 0, the integral of v^T C v over the
  // steps taken (undone by RollBack); the same on every rank. 0 for an undamped beam.
  virtual PetscReal Dissipated() const { return 0; }
  // Replaces the current state by s at time t (the exact free vibration after a separation,
  // run/free_flight.hpp). Each rank takes its owned part. The caller calls Restart() before
  // stepping on from it; reading it (views, measures) needs nothing more. Not undone by RollBack.
  virtual PetscErrorCode SetState(PetscReal t, const FullState &s) = 0;
  // The same in the modes `m`, for a stepper that integrates in exactly that basis (-ts_type
  // modal, when the free flight's modes are its own): O(modes), no projection through the
  // physical state (which is written from the modes when read). *done false for any other
  // stepper or basis: then use the physical state (ViewBegin, SetState). Collective.
  virtual PetscErrorCode GetModalState(const BeamModes &m, ModalState *s, bool *done)
  {
    (void)m, (void)s;
    *done = false;
    return 0;
  }
  virtual PetscErrorCode SetModalState(PetscReal t, const BeamModes &m, const ModalState &s, bool *done)
  {
    (void)t, (void)m, (void)s;
    *done = false;
    return 0;
  }
  // The current state in the stepper's own modes (*modes, its basis) where reading the physical
  // state (ViewBegin) would first write it from them, O(n k): -ts_type modal after a step, the
  // physical state the modes' expansion alone (no static shape of the modes left out under a
  // contact force). The measures then take it in modes (run/measures.cpp). *done false otherwise
  // (the physical state is current, or the stepper has no modes): read the physical state. Collective.
  virtual PetscErrorCode ModalStateUnwritten(std::shared_ptr<const BeamModes> *modes, ModalState *s, bool *done)
  {
    (void)modes, (void)s;
    *done = false;
    return 0;
  }
  // The current state as a sample, O(modes), where writing the physical state costs O(n k) per
  // state (-ts_type modal): samples are then expanded many at once (Expand, one matrix product
  // that reads the modes once, instead of a pass over every mode per state). *done false for any
  // other stepper. The same on every rank.
  virtual PetscErrorCode Sample(StateSample *s, bool *done)
  {
    (void)s;
    *done = false;
    return 0;
  }
  // The physical states of samples taken by Sample since the last change of basis: on this rank's
  // dofs [r->e0, r->e1) (its owned ones [r->d0, r->d1) and the neighbours' the strain terms reach),
  // state s's displacement of dof d at (*y)[s (e1 - e0) + d - e0] and its velocity in *v
  // (node-major, held dofs 0). Local (no communication).
  virtual PetscErrorCode Expand(const std::vector<StateSample> &s, SampleRange *r, std::vector<PetscReal> *y,
                                std::vector<PetscReal> *v)
  {
    (void)s, (void)r, (void)y, (void)v;
    SETERRQ(Comm(), PETSC_ERR_SUP, "%s keeps no samples to expand", Method().c_str());
  }
};

} // namespace beamimpact

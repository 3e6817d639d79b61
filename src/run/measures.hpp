// Energies, momenta, point velocities and the contact of the current state of any stepper
// (identical on every rank: one reduction for all). A state the stepper holds in its modes
// (-ts_type modal after a step) is measured in them, O(modes), where no monitor asks for the
// physical state and no part's energy is kept apart: the same measures to round-off.
#pragma once

#include "run/impact.hpp"
#include "solvers/stepper.hpp"
#include "system/beam_system.hpp"

#include <vector>

namespace beamimpact {

struct StateMeasures {
  PetscReal ball_y = 0, ball_v = 0, c = 0, force = 0; // m, m/s, m, N
  PetscReal c_rate       = 0,
            force_rate   = 0; // m/s, N/s: dc/dt and dF/dt = dF/dc dc/dt on the active branch (0 when separated)
  PetscReal ball_kinetic = 0, ball_stored = 0, ball_work = 0, beam_kinetic = 0, beam_strain = 0; // J
  PetscReal momentum = 0, angular_momentum = 0; // kg m/s, kg m^2/s about x = 0 (beam and ball)
  PetscReal beam_momentum = 0, beam_moment = 0; // sum m_i v_i (kg m/s), sum m_i x_i v_i (kg m^2/s)
  PetscReal segment_kinetic = 0;                // J, the monitored segment
  // The accounts kept apart from the beam's (StructurePart::AccountApart: the barrel wall,
  // -barrel_hoop_frequency or -beam_shell): their stored and kinetic energy (J), not in
  // beam_kinetic and beam_strain; their displacement under the ball (m, into the bat). 0 without.
  PetscReal apart_energy = 0, apart_deflection = 0;
  // The largest deflection of the fields across the face from their frame (a racket's string bed),
  // max |w - y - z phi| over its nodes (m); the angular momentum about the frame's axis of the structure and the ball
  // (kg m^2/s: sum rho J phi_t + sum m z v + m_b z_b v_b). 0 without.
  PetscReal face_deflection = 0, roll_momentum = 0;
  PetscReal beam_roll = 0; // kg m^2/s, the structure's share of roll_momentum
  // Each energy account a > 0 (system/structure_part.hpp, StructureAccountOf: a part's own), for the
  // split of the energy into rigid motions and parts (run/energy_parts.hpp): its stored plus kinetic
  // energy (J; in beam_kinetic and beam_strain but for the accounts of apart_energy) and its
  // deflections' share of beam_momentum, beam_moment and beam_roll (sum m v, sum m x v, sum m z v
  // over the fields across the face, StructurePart::FieldZ: kg m/s, kg m^2/s, kg m^2/s). The beam's
  // account (0) is the rest; 0 without parts.
  PetscReal account_energy[kMaxAccounts]      = {};
  PetscReal account_momentum[kMaxAccounts][3] = {};
  PetscReal beam_dissipated = 0; // J, dissipated by the beam's damping since t = 0 (0 when undamped; with a grip its
                                 // damper's share too)
  // The force operator's frame terms (system/force_operator.hpp; the hands' part reads them as its
  // slots): the energy stored in the force terms other than the elastic one (the hands' 1/2 sum
  // k_i (y_i - v_f,i t)^2), the work the swing's frame has done on the bat since t = 0 (through
  // the hands), the force of the bat on the frame and its moment about x = 0 (0 without a term
  // tied to the frame).
  PetscReal terms_stored = 0, frame_work = 0;  // J
  PetscReal frame_force = 0, frame_moment = 0; // N, N m
  // The registered structure parts' measures (system/structure_part.hpp: part p's slots from its
  // PartInstance::slot0, in the units its Slots() declare); 0 without parts.
  PetscReal part_slot[kMaxPartSlots] = {};
  // The conserved total: with the linear spring and an undamped beam, a constant.
  PetscReal total() const
  {
    return ball_kinetic + ball_work + beam_kinetic + beam_strain + apart_energy + beam_dissipated + terms_stored -
           frame_work;
  }
};

// What a measurement needs besides the state.
struct MeasureContext {
  const BeamSystem      *sys     = nullptr;
  const ContactCoupling *g       = nullptr;
  const BallParams      *ball    = nullptr;
  const ContactState    *contact = nullptr;
  const FrameMotion     *frame   = nullptr; // the swing's frame (nullptr: at rest)
};

// The ball's measures at the current state, m->ball_y and m->ball_v set: its compression and rate
// (the stepper's, O(modes) for -ts_type modal), the contact force and its rate, the ball's kinetic
// and stored energy and the law's work. Collective.
PetscErrorCode MeasureBall(Stepper &stepper, const MeasureContext &ctx, StateMeasures *m);

// Measures the current state; with a monitor request also the point velocities (m/s, at
// mon->velocity_at) and the segment's kinetic energy.
PetscErrorCode MeasureState(Stepper &stepper, const MeasureContext &ctx, const MonitorRequest *mon, StateMeasures *m,
                            std::vector<PetscReal> *point_v);
// The structure's measures of `count` states given on this rank's dofs [r.e0, r.e1) (its owned
// ones [r.d0, r.d1) and its neighbours' the strain terms reach; state s's dof d at y[s (e1 - e0)
// + d - e0], as Stepper::Expand gives them), state s at time t[s]: what
// MeasureState computes from the structure (its energies, momenta, the wall's, the bed's and the
// parts' measures), not the ball's, the contact's or the stepper's dissipation (left 0).
// Collective: one reduction for all the states.
PetscErrorCode MeasureStructureStates(MPI_Comm comm, const MeasureContext &ctx, const SampleRange &r,
                                      const std::vector<PetscReal> &y, const std::vector<PetscReal> &v,
                                      const std::vector<PetscReal> &t, std::vector<StateMeasures> *m);

} // namespace beamimpact

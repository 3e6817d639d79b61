// The modal integrator, registered as the PETSc TS type "modal" (-ts_type modal), as
// ts_galpha2.cpp registers alpha2. The beam's linear flow is exact over every step, in its
// modes (solvers/beam_modes.hpp: K phi = w^2 M phi on the free dofs, exact rigid modes, each
// mode's exact Rayleigh-damped rotation); the ball and the contact force enter by splitting:
//
//   order 2 (Strang):  S(h) = kick(h/2) o [beam flow(h) + ball drift(h)] o kick(h/2)
//   order 4 (Yoshida): S(w1 h) S(w0 h) S(w1 h),  w1 = 1/(2 - 2^(1/3)),  w0 = 1 - 2 w1 < 0
//
// (-ts_modal_order 2|4). The kick adds tau F gamma_k to each modal velocity and -tau F/m_b to
// the ball's, F the contact law at c = y_b - sum_k gamma_k z_k, gamma_k = g^T M^{-1/2} phi_k
// (the coupling's modal row). The negative substep of order 4 is fine: the beam's flow is
// exact backwards too. Both are symmetric compositions of exact flows, so the order is 2 or 4
// for any smooth force law inside a contact phase (the driver locates the phase switches and
// restarts there). No stability limit from the beam: each mode's rotation is exact.
//
// State: the TS keeps (z, zd, y_b, v_b) in modal coordinates, the same on every rank (a serial
// modal state, computed redundantly; the physical Vec stays distributed on the DMDA). A step
// costs O(modes): 3 (order 2: 2) kicks and flows of O(n) each, the flows from cached 2x2
// propagators of the step lengths in use. The physical vector TSGetSolution returns is
// written from the modes only when it is read (TSModalSyncSolution, O(n^2 / ranks): the dense
// modes); the driver's per-step read, the compression, is answered from the modal state
// (TSModalCompression, O(n)), and so is the damped beam's dissipation rate. A write into the
// physical vector from outside (the initial state, SetState after a free flight) is detected
// (object state and an O(N) comparison with the last written copy) and projected on the
// modes at the next step (O(n^2), once).
//
// Requires the beamimpact problem in its explicit form (TSSetRHSFunction with TSRHSExplicit,
// ts_problem.hpp; FormulationOfType gives it) and a beam whose modes are available
// (BeamModesAvailable: at most BeamModesMaxDofs free dofs, proportional damping).
#pragma once

#include <petscts.h>

#define TSMODAL "modal"

namespace beamimpact {

PetscErrorCode TSModalRegister();
bool           TSModalIsType(const char *type);

// Hooks for the TS stepper; for any other TS type they do nothing (*done = false).
// The physical state of TSGetSolution's vector, written from the modal state if stale.
PetscErrorCode TSModalSyncSolution(TS ts);
// c = y_b - g^T y and its rate from the modal state (every rank).
PetscErrorCode TSModalCompression(TS ts, PetscReal *c, PetscReal *cdot, PetscBool *done);
// Damped beam: P = v^T C v = sum_k 2 sigma_k zd_k^2 and dP/dt = 2 a^T C v at the current state.
PetscErrorCode TSModalDissipationRate(TS ts, PetscReal *rate, PetscReal *rate_dot, PetscBool *done);

} // namespace beamimpact

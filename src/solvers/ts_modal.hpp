// The modal integrator, registered as the PETSc TS type "modal" (-ts_type modal), as
// ts_galpha2.cpp registers alpha2. The beam's linear flow is exact over every step, in its
// modes (solvers/beam_modes.hpp: K phi = w^2 M phi on the free dofs, exact rigid modes, each
// mode's exact Rayleigh-damped rotation); the contact force enters as a polynomial in time over
// each step, for which the beam's modes and the ball are integrated exactly (an exponential
// collocation method): order 2 (-ts_modal_order 2): F linear through F(t0) and F(t0 + h);
// order 4 (the default): F quadratic through its values at t0, t0 + h/2, t0 + h. The unknown
// force values satisfy F_i = F(c(t_i)), c(t_i) = c_free(t_i) - sum_j W_ij F_j (W from the
// modes' responses, sum_k gamma_k^2 ..., and the ball's), solved by Newton (1 or 2 unknowns);
// gamma_k = g^T M^{-1/2} phi_k is the coupling's modal row. No stability limit from the beam.
// (A Strang splitting, impulse kicks around the exact flow, was tried first and dropped: the
// kicks leave O(h F gamma_k) in every unresolved mode at each step end, so the compression
// rate depends on the path of steps and the event locator failed at maximum compression.)
//
// State: the TS keeps (z, zd, y_b, v_b) in modal coordinates, the same on every rank (a serial
// modal state, computed redundantly; the physical Vec stays distributed on the DMDA). A step
// costs O(modes) in two passes over the modes (no allocation), from weights cached per step
// length in a few reused slots (least recently used refilled; one sincos per undamped mode for
// each new length: the nominal step and the event location's steps; the coupling gamma_k
// folded into the weights). The nominal step's parts free of gamma_k are kept across the points
// on one basis, so a sweep's next point only folds its gamma_k in (O(modes), no sincos). The
// compression at the step's end comes out of the update pass and
// is kept until the state changes. The physical vector TSGetSolution returns is
// written from the modes only when it is read (TSModalSyncSolution, O(n^2 / ranks): the dense
// modes); the driver's per-step read, the compression, is answered from the modal state
// (TSModalCompression, O(1) after a step), and so are the damped beam's dissipation rate and
// the end of a run's measures (TSModalGetUnwrittenState: energies and momenta in modes). A write
// into the physical vector from outside (the initial state, SetState after a free flight) is
// detected (object state and an O(N) comparison with the last written copy) and projected on
// the modes at the next step (O(n^2), once), unless it changed the vector by round-off only
// (max |change| <= 1e-11 of each kind's largest entry: the round trip through a free flight of
// zero length when the window ends at the separation), which keeps the modal state.
//
// Requires the beamimpact problem in its explicit form (TSSetRHSFunction with TSRHSExplicit,
// ts_problem.hpp; FormulationOfType gives it) and a beam whose modes are available
// (BeamModesAvailable: proportional damping, no grip; the modes kept by -modal_modes, -modal_tolerance,
// with the static correction at the contact point: docs/model.md §12).
#pragma once

#include "solvers/beam_modes.hpp"

#include <petscts.h>

#include <memory>
#include <vector>

#define TSMODAL "modal"

namespace beamimpact {

PetscErrorCode TSModalRegister();
bool           TSModalIsType(const char *type);
// How many steps so far (this process) took their weights folded from the shapes an earlier point
// kept for the same nominal step, instead of computing them (a sweep's reuse, observable by tests).
PetscInt TSModalFoldCount();

// Hooks for the TS stepper; for any other TS type they do nothing (*done = false).
// The physical state of TSGetSolution's vector, written from the modal state if stale.
PetscErrorCode TSModalSyncSolution(TS ts);
// c = y_b - g^T y and its rate from the modal state (every rank).
PetscErrorCode TSModalCompression(TS ts, PetscReal *c, PetscReal *cdot, PetscBool *done);
// Damped beam: P = v^T C v = sum_k 2 sigma_k zd_k^2 and dP/dt = 2 a^T C v at the current state.
PetscErrorCode TSModalDissipationRate(TS ts, PetscReal *rate, PetscReal *rate_dot, PetscBool *done);
// A reused TS's next point (the per-structure context, ts_stepper.hpp: the same grid, another
// contact point, ball or beam on it): the per-point set-up again (the modes from the shared
// cache, gamma_k and the static correction at the point, the step weights and the modal state
// anew); the TS, its vectors and its gather of the physical state kept.
PetscErrorCode TSModalNewPoint(TS ts);
// The beam's modes the TS integrates in (null for any other type, or before its set-up).
std::shared_ptr<const BeamModes> TSModalModes(TS ts);
// The modal state in those modes (z, zd per kept mode; the ball), an outside write of the
// physical vector projected first. O(modes). Collective; *done false for any other type.
PetscErrorCode TSModalGetState(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb,
                               PetscReal *vb, PetscBool *done);
// Replaces the modal state by (z, zd, yb, vb) in those modes (the exact free flight's end,
// run/free_flight.hpp): O(modes); the physical vector is written from it when next read (no
// projection). The caller sets the time and restarts. Collective; *done false for any other type.
PetscErrorCode TSModalSetState(TS ts, const std::vector<PetscReal> &z, const std::vector<PetscReal> &zd, PetscReal yb,
                               PetscReal vb, PetscBool *done);
// The modal state as TSModalGetState gives it, but only where reading the physical vector would
// first write it from the modes (O(n k): after a step or TSModalSetState, before any read) and it
// would be their expansion alone (every mode kept, or no contact force on the static shape of the
// modes left out): the measures then take it in modes (run/measures.cpp). *done false otherwise
// (the vector holds the state: read it), and for any other type. Collective.
PetscErrorCode TSModalGetUnwrittenState(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb,
                                        PetscReal *vb, PetscBool *done);
// The modal state (z, zd), the ball's (ball_y, ball_v: m, m/s) and the force on the static shape of
// the modes left out (0 when every mode is kept), an outside write projected first: O(modes), the
// physical vector left as it is. Collective; *done false for any other type.
PetscErrorCode TSModalSample(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *ball_y,
                             PetscReal *ball_v, PetscReal *static_force, PetscBool *done);
// The physical states of `count` such samples on the beam dofs [e0, e1) (this rank's owned ones
// and the neighbours' a stencil reaches): y = M^{-1/2} (Phi Z + u_r F) and v = M^{-1/2} Phi Zd in
// one BLAS 3 product (Z = [Z Zd]: kept modes x 2 count, column-major, the rates after the amplitudes),
// state s's dof d at y[s (e1 - e0) + d - e0] (held dofs 0). The same values as the state written
// at each step (TSModalSyncSolution) to round-off (another order of the sums over the modes).
// Local; *done false for any other type.
PetscErrorCode TSModalExpand(TS ts, const PetscReal *Z, const PetscReal *F, PetscInt count, PetscInt e0, PetscInt e1,
                             PetscReal *y, PetscReal *v, PetscBool *done);

} // namespace beamimpact

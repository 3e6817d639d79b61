// Exact reference for the linear spring (MODEL.md section 2): between events the
// semi-discrete beam + ball system is linear, M q'' + K_p q = 0 with K_p = K + k g g^T
// in contact and K_p = K when separated (q: free beam nodes and the ball). A symmetric
// eigen-decomposition of M^{-1/2} K_p M^{-1/2} (LAPACK) gives q(t) in closed form; the
// separation and re-contact times are roots of c(t) = g^T q(t), a sum of sines, found
// by provably safe bracketing steps and bisection to round-off. No time step, no
// tolerance: only round-off. The eigenvectors are refined by inverse iteration (banded
// LU), so the reference stays exact as the h^-4 spectrum widens: measured against a
// 5(4) run at rtol 1e-12, ACOR agrees to 2e-14 / 6e-11 / 6e-9 and energy is conserved to
// 1e-14 / 4e-11 / 3e-9 at N = 41 / 161 / 641. Serial (the system is small and dense).
#pragma once

#include "run/impact.hpp"

namespace beamimpact {

// Fills the outcome fields of an ImpactResult (acor, acor_corrected, contact_time(_total),
// peak_force, max_compression, contacts, events, ball_final_velocity, final_time,
// energy_error, beam energies at the end) for the linear law; the same window and cap
// rules as ImpactRun, so both see the same contacts. ts_type is set to "modal".
// PETSC_ERR_SUP for the hysteretic law.
PetscErrorCode ModalReferenceRun(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, ImpactResult *res);
struct Scenario;
PetscErrorCode ModalReferenceRun(const Scenario &scenario, ImpactResult *res);

} // namespace beamimpact

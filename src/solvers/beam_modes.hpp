// The modes of the beam alone, as supported (any theory and profile, held dofs and clamped
// regions, Rayleigh damping): K phi = w^2 M phi on the free dofs, every mode (no truncation),
// with each mode's decay rate sigma = alpha/2 + beta w^2/2 (C = alpha M + beta K is diagonal
// in this basis, so the damped free vibration is exact mode by mode: ModalModeAt).
//
// Computed once per beam and shared: BeamModesShared keeps the last few bases in a small
// cache of this process keyed by the system's content (nodes, fields, masses, held dofs, the
// bands of K and C of the force operator, compared exactly), so every point of a sweep, every run of a
// study and every repetition of a scene that builds the same BeamSystem reuses one
// decomposition; a different beam (grid, theory, support, damping) is a new entry. The ball
// and the impact point are not in the key: the ball is free after separation and the impact
// point enters only through the coupling (gamma_k = g^T phi_k), which costs O(n) per run.
//
// Method: dense LAPACK syev of M^{-1/2} K M^{-1/2}, refined by banded inverse iteration
// (solvers/modal_basis.hpp), which is exact to round-off for every mode. The whole spectrum
// is kept: the state after a separation has content in every mode and the restart state
// must be exact, so nothing is truncated; beyond BeamModesMaxDofs free dofs the dense
// decomposition is refused (the caller then integrates in time and says why).
#pragma once

#include "solvers/modal_basis.hpp"
#include "system/beam_system.hpp"

#include <petscsys.h>

#include <memory>
#include <string>

namespace beamimpact {

struct BeamModes {
  BeamSystem  sys; // the copy the basis was built from (S.sys points here)
  ModalSystem S;   // the beam's free dofs (no ball)
  ModalBasis  B;   // omega, Phi (S.n x S.n, of M^{-1/2} K M^{-1/2}), rate; gamma unused (0)
  double      build_seconds = 0;
};

// Largest number of free beam dofs the dense decomposition accepts (time and memory ~ n^3, n^2).
constexpr PetscInt BeamModesMaxDofs = 3000;

// Whether the beam's free vibration can be propagated exactly in modes; if not, *why says so.
bool BeamModesAvailable(const BeamSystem &sys, std::string *why);

// The beam's modes, from the cache when the same system was decomposed before in this
// process, else computed and cached (the last BeamModesCacheSize systems are kept).
constexpr int  BeamModesCacheSize = 4;
PetscErrorCode BeamModesShared(const BeamSystem &sys, std::shared_ptr<const BeamModes> *modes);
// Cache statistics (for tests): decompositions computed and reused since the process started.
void BeamModesCacheCounts(PetscInt *computed, PetscInt *reused);

} // namespace beamimpact

// The beam's static flexibility in factored (mixed) form, for the modal engine on fine grids
// (issue 21; docs/model.md §12, docs/convergence.md "Scale").
//
// The stiffness is K = B^T W B (system/beam_system.hpp: U = 1/2 sum_t w_t (b_t . y)^2). For the
// Euler-Bernoulli beam B is a second difference, so K is a fourth difference whose condition
// number grows as 16 (L/h)^4 (1e18 at N = 40961): any solve with K (a Cholesky or LU of the
// band, shift-and-invert on K) loses the low modes and the flexibility to eps cond(K). Where
// the structure is statically determinate (free dofs - strains = rigid motions: a free,
// pinned-free, pinned-pinned or cantilevered Euler-Bernoulli beam, a free Timoshenko beam),
// K^+ f needs no solve with K: with the load f made self-equilibrated (its rigid-body inertia
// removed) and one temporary support per rigid motion, the stress resultants m' = W^{1/2} B u
// solve the square, banded equilibrium S m' = f (S = B^T W^{1/2} without the supports' rows:
// M'' = f for the beam, a second difference), and the deflection the compatibility
// S^T u = m' (EI w'' = M), two solves conditioned as (L/h)^2 with one LU of S. The
// flexibility is then a sum of squares, f^T K^+ f = |m'|^2 (no cancellation), and the modes
// are the largest eigenvalues 1/omega^2 of M^{1/2} K^+ M^{1/2} (BeamModesLowestFactored,
// solvers/modes.hpp), exact to eps (L/h)^2 before their Rayleigh quotients in the strain
// energy, where shift-and-invert on K is exact to eps (L/h)^4.
//
// Units: SI; f in N per dof (N m for a rotation), u in m per N of the load's scale, G in m/N.
#pragma once

#include "system/beam_system.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// The temporary supports of a flexibility solve: one dof (an index into dof, the free dofs) per
// rigid mode R[i] (over the same free dofs; BeamSystemRigidMotions), chosen so that the rigid
// modes' values there are independent (each the largest after the earlier ones are eliminated):
// statically determinate, so a self-equilibrated load has no reactions. A deflection dof where
// one moves the mode (translation, pitch), else any (a roll: the roll field).
std::vector<PetscInt> BeamTemporarySupports(const BeamSystem &sys, const std::vector<PetscInt> &dof,
                                            const std::vector<std::vector<PetscReal>> &R);

// The factored form of a statically determinate beam (BeamFactorCreate).
struct BeamFactor {
  PetscInt                            n = 0;   // free dofs, in dof order (as ModalSystemBeamOnly)
  std::vector<PetscInt>               dof;     // free index -> system dof
  std::vector<PetscReal>              mass;    // kg (or kg m^2) per free dof
  std::vector<std::vector<PetscReal>> rigid;   // the rigid modes on the free dofs, M-orthonormal (kg^-1/2)
  std::vector<PetscInt>               support; // free indices of the temporary supports, one per rigid mode
  std::vector<PetscInt>               row;     // free index -> row of S (-1 at a support)
  int                                 m = 0, kl = 0, ku = 0; // S: m x m, its sub- and super-diagonals
  std::vector<double>                 lu; // S's banded LU (LAPACK dgbtrf, leading dimension 2 kl + ku + 1)
  std::vector<int>                    ipiv;
  PetscReal rcond = 0; // the ratio of S's smallest pivot to its largest (1: a proxy of its reciprocal condition)
};

// Builds the factored form of sys. Returns false with *why (if given) where the structure is not
// statically determinate (clamped at both ends, supports in the span, a shell's negative
// weights...), S's band is wider than 64 or S is singular or its pivots spread beyond
// 1/(100 eps): the primal path (K) stays the one used there. O(n): cheap enough to ask per run.
bool BeamFactorCreate(const BeamSystem &sys, BeamFactor *F, std::string *why = nullptr);

// u = K^+ f on the free dofs for any f (per free dof, N): f less its rigid-body inertia
// (f - M R R^T f) is the load, u is M-orthogonal to the rigid modes, and *G = f^T u = |m'|^2
// the flexibility on the flexible subspace (m/N for a unit load). u or G may be null.
void BeamFactorFlexibility(const BeamFactor &F, const PetscReal *f, PetscReal *u, PetscReal *G);

} // namespace beamimpact

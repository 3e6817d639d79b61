// Exact in-contact vibration of a Rayleigh-damped beam with the linear spring. The ball and
// the spring carry no damping, so C = blockdiag(alpha M + beta K, 0) is not proportional to
// the coupled (M, K + k g g^T) and the modes of modal_basis.hpp do not decouple it. In the
// undamped coupled modes q = M^{-1/2} Phi z (z'' + Chat z' + Omega^2 z = 0, Chat = U^T C U,
// U = M^{-1/2} Phi) the energy-scaled first-order state
//   y = [Omega_f z_f ; z'],   y' = A y,   A = [[0, Omega_f E^T], [-E Omega_f, -Chat]]
// (z_f: the modes of Omega > 0; E selects them) has E = 1/2 |y|^2, A skew-symmetric plus the
// damping block: near-normal, its eigenvectors well-conditioned unless a mode is critically
// damped. The rigid modes (Omega = 0: translation and rotation of a free beam with the ball
// following, g^T z_r = 0) keep only their velocity in y; their displacement is the exact
// integral of it. A = V Lambda V^{-1} (LAPACK geev, conjugate pairs), so
//   y(s) = Re sum_j a_j v_j e^{lambda_j s}   (one term per real eigenvalue or pair),
//   c(s) = g^T q = Re sum_j Gamma_j a_j e^{lambda_j s},
// c^(p)(s) = Re sum_j Gamma_j a_j lambda_j^p e^{lambda_j s}, and with Re lambda_j <= 0 the bound
// |c^(p)| <= sum_j |Gamma_j a_j| |lambda_j|^p holds for every s >= 0: the phase has the
// interface of ModalPhase (From, State, Derivative, Bound) and the same event search.
// The dissipated energy D(s) = int_0^s v^T C v is a double sum over the exponentials, exact.
#pragma once

#include "solvers/modal_basis.hpp"

#include <petscsys.h>

#include <complex>
#include <limits>
#include <vector>

namespace beamimpact {

using ModalComplex = std::complex<PetscReal>;

struct ModalDampedBasis {
  PetscInt                  n = 0, m = 0;    // free dofs (ball last); states nf + n
  std::vector<PetscInt>     flex;            // state i < nf -> its mode (Omega > 0)
  std::vector<PetscInt>     state_of;        // mode -> its displacement state (-1: rigid)
  std::vector<PetscReal>    omega;           // rad/s per mode (exactly 0 for a rigid mode)
  std::vector<PetscReal>    U;               // n x n column-major: shape of mode k, M^{-1/2} Phi_k
  std::vector<PetscReal>    Ut;              // n x n: z = Ut q (Phi^T M^{1/2})
  std::vector<PetscReal>    gamma;           // g^T U_k
  std::vector<PetscReal>    Chat;            // n x n: U^T C U
  std::vector<ModalComplex> lambda;          // one per real eigenvalue or conjugate pair (Im > 0)
  std::vector<PetscInt>     col;             // its first column of the real eigenvector matrix
  std::vector<ModalComplex> V;               // m x r: complex eigenvector of each term
  std::vector<PetscReal>    Vinv;            // m x m: inverse of the real eigenvector matrix
  std::vector<ModalComplex> Gamma;           // contribution of each term's eigenvector to c
  std::vector<ModalComplex> G1, G2;          // r x r: w_j^T Chat w_k and w_j^T Chat conj(w_k) (w: velocity part)
  PetscReal                 cond        = 0; // 1-norm condition number of the real eigenvector matrix
  PetscReal                 rigid_gamma = 0; // max |g^T U_r| / max |gamma| over rigid modes (0 in exact arithmetic)
};

// Largest condition number of the eigenvector matrix that is accepted.
constexpr PetscReal kModalDampedMaxCondition = 1e10;

// The damped basis of a phase (contact: K + k g g^T, else K) of S, whose beam may be damped
// (the undamped modes are built on an undamped copy of the system). PETSC_ERR_NOT_CONVERGED,
// naming -beam_damping_mass and -beam_damping_stiffness, when the eigenvector matrix is
// too ill-conditioned (above kModalDampedMaxCondition) to be trusted.
PetscErrorCode ModalDampedBasisBuild(const ModalSystem &S, bool contact, ModalDampedBasis *B);

// A phase from its start: the coefficients a_j and the rigid modes' displacements at s = 0.
struct ModalDampedPhase {
  const ModalSystem        *S = nullptr;
  const ModalDampedBasis   *B = nullptr;
  std::vector<ModalComplex> a;
  std::vector<PetscReal>    z0; // modal displacements at s = 0 (the rigid ones are used)

  void From(const std::vector<PetscReal> &q, const std::vector<PetscReal> &qd);
  // Modal displacements and velocities at s.
  void At(PetscReal s, std::vector<PetscReal> &z, std::vector<PetscReal> &zd) const;
  void State(PetscReal s, std::vector<PetscReal> &q, std::vector<PetscReal> &qd) const;
  // d^p c / ds^p at s (any p >= 0) and its bound over s >= 0.
  PetscReal Derivative(PetscReal s, int p) const;
  PetscReal Bound(int p) const;
  // Energy dissipated by the beam's damping over [0, s] (J), exact.
  PetscReal Dissipated(PetscReal s) const;
};

inline bool ModalFirstCrossing(const ModalDampedPhase &ph, int p, PetscReal sign, PetscReal s_end, PetscReal s_min,
                               PetscReal *root)
{
  return ModalFirstCrossingOf(ph, p, sign, s_end, s_min, root);
}

} // namespace beamimpact

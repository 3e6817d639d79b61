// Exact free and in-contact vibration of the semi-discrete system (system/beam_system.hpp)
// with a linear spring: between events the beam + ball system is linear, M q'' + K_p q = 0
// with K_p = K + k g g^T in contact and K_p = K when separated (q: free beam dofs and the
// ball). A symmetric eigen-decomposition of M^{-1/2} K_p M^{-1/2} (LAPACK dsyevd, divide and
// conquer; syev where it fails; refined by banded inverse iteration) gives q(t) in closed form in each phase,
//   q(t0 + s) = M^{-1/2} Phi z(s),  z_k(s) = z_k cos(w_k s) + zdot_k sin(w_k s) / w_k,
// or, with Rayleigh damping in a separated phase, the exact damped solution of each mode
// (ModalModeAt),
// and events are the first sign changes of c(s) = g^T q (separation, re-contact) and of
// dc/ds (maximum compression), bracketed with steps that provably cannot skip a crossing (a
// Taylor bound with |f''| <= sum_k |gamma_k a_k| w_k^2) and bisected to round-off. Serial
// (the system is small and dense). Used by the exact reference (run/modal_reference.hpp).
#pragma once

#include "system/beam_system.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace beamimpact {

// The free degrees of freedom: beam dofs that are not held (any number of fields per node;
// the ball touches the dofs of ContactCoupling), then the ball. K, M and the damping come from
// the system and its force operator.
struct ModalSystem {
  const BeamSystem      *sys = nullptr;
  std::vector<PetscInt>  dof;  // free dof -> beam dof (the last is the ball: -1)
  std::vector<PetscReal> mass; // kg, per free dof
  std::vector<PetscReal> g;    // dc/dq per free dof
  PetscInt               n    = 0;
  PetscReal              k    = 0;    // N/m, the contact spring
  bool                   ball = true; // false: the beam alone (ModalSystemBeamOnly), no ball dof
  bool damping                = true; // false: the system's damping left out (the undamped modes of the same M and K)
  bool mirror                 = true; // the dense decomposition split by the structure's mirror z -> -z where it has
                                      // one (-modal_mirror; ModalBasisBuild)
  PetscInt BeamDofs() const { return ball ? n - 1 : n; }
  // The beam's damping C = alpha M + beta K (the force operator's, ForceOperatorModal; 0, 0
  // without damping or with `damping` false). False when the system's forces are not modal.
  bool Rayleigh(PetscReal *alpha, PetscReal *beta, std::string *why = nullptr) const;
};
ModalSystem ModalSystemBuild(const BeamSystem &sys, const ContactCoupling &g, PetscReal ball_mass, PetscReal k);
// The beam alone (free beam dofs, g = 0): its separated basis (ModalBasisBuild, contact false)
// is the beam's modes, K phi = w^2 M phi, shared by every ball and impact point (solvers/beam_modes.hpp).
ModalSystem ModalSystemBeamOnly(const BeamSystem &sys);

// phi (n entries) minus its projections on the first `count` columns of Phi (n x n, orthonormal
// columns), `passes` times (2: re-orthogonalised against round-off), then normalised.
void ModalOrthonormalize(const std::vector<PetscReal> &Phi, PetscInt n, PetscInt count, int passes, PetscReal *phi);

// One phase's eigen-decomposition of M^{-1/2} K_p M^{-1/2}.
struct ModalBasis {
  std::vector<PetscReal> omega; // rad/s, per mode (n, or the modes kept of a truncated basis)
  std::vector<PetscReal> Phi;   // n x modes, column-major: Phi[r + k n] (orthonormal eigenvectors)
  std::vector<PetscReal> gamma; // g^T M^{-1/2} Phi_k: contribution of mode k to c
  std::vector<PetscReal> rate;  // 1/s, sigma_k = zeta_k omega_k: z_k'' + 2 sigma_k z_k' + omega_k^2 z_k = 0
  PetscInt
       refined  = 0; // modes refined by inverse iteration (all of them where the band is narrow: ModalRefinesEveryMode)
  bool by_need  = false; // refined where the residual asked for it (a wide band), not every mode
  bool mirrored = false; // decomposed as its even and odd halves under the structure's mirror z -> -z
};
// The basis in contact (K + k g g^T) or separated (K). With Rayleigh damping C = alpha M +
// beta K on the beam dofs (ModalSystem::Rayleigh, from the force operator) the separated basis
// decouples it exactly (sigma = alpha/2 + beta omega^2/2 a beam mode, alpha/2 a rigid one, 0
// the ball's); in contact it does not (the ball and the spring are undamped): PETSC_ERR_SUP.
// refine_all: every mode refined whatever the band (-modal_refine all). Where the structure is
// mirrored across the face (z -> -z: a racket's string bed about the frame's axis, the frame's
// roll changing sign) and S.mirror, the even and odd halves are decomposed apart (B->mirrored).
// On a communicator of several ranks (comm) the work is shared out and the result handed to
// every rank, the same bits as on one: the mirror's two halves one rank each, the residuals and
// the refined modes mode by mode.
// The structure's mirror across the face (z -> -z) on the free dofs of S: each dof's image at the
// same node and -z (the frame's roll its own, with sign -1; every dof on the axis its own). False
// where a dof has no free image or the map is the identity. Whether K and M commute with it is
// the caller's to check.
struct ModalMirror {
  std::vector<PetscInt> to;   // free dof -> its image
  std::vector<int>      sign; // +1 or -1
};
bool ModalMirrorOf(const ModalSystem &S, ModalMirror *m);

PetscErrorCode ModalBasisBuild(const ModalSystem &S, bool contact, ModalBasis *B, bool refine_all = false,
                               MPI_Comm comm = PETSC_COMM_SELF);

// The beam alone (S from ModalSystemBeamOnly), from `count` of its modes found elsewhere (a
// partial eigen-solve): Phi (S.n x count, column-major) the columns M^{1/2} phi_k, lambda their
// omega^2 estimates (ascending). Refined as ModalBasisBuild refines the dense basis (inverse
// iteration corrected in the factored form, modified Gram-Schmidt, Rayleigh quotients and
// decay rates): omega, Phi, rate of count modes. refine false: Phi is kept as given (modes
// already exact and orthonormal, from the factored form: inverse iteration with K's band would
// spoil them where eps cond(K) > 1), only the quotients and rates are computed.
PetscErrorCode ModalBasisFromModes(const ModalSystem &S, const std::vector<PetscReal> &lambda,
                                   std::vector<PetscReal> &&Phi, ModalBasis *B, bool refine = true,
                                   bool refine_all = false);

// The refinement of a basis (ModalBasisBuild, ModalBasisFromModes): two steps of inverse
// iteration per mode with a banded LU of A - sigma I (half-bandwidth kl, ModalRefineHalfWidth),
// ModalRefineModeFlops(n, kl) flops a mode. Every mode where that costs at most 4 n^2 flops (the
// dense decomposition's share of a mode) or 2e9 flops in all (ModalRefinesEveryMode: every beam,
// shell and hoop); elsewhere (a string bed: kl ~ 2 fields per node) only the modes whose
// relative residual |A phi - rho phi| / rho in the factored form (ModalResiduals) exceeds
// ModalRefineResidual() (1e-12). ModalResiduals with (rank, size): only the modes k = rank mod
// size, the others' 0 (a basis built on several ranks shares its modes' residuals and
// refinements out, each mode on one rank: ModalBasisBuild's comm).
PetscInt               ModalRefineHalfWidth(const ModalSystem &S);
double                 ModalRefineModeFlops(PetscInt n, PetscInt kl);
bool                   ModalRefinesEveryMode(PetscInt n, PetscInt kl, PetscInt count);
PetscReal              ModalRefineResidual();
std::vector<PetscReal> ModalResiduals(const ModalSystem &S, bool contact, const std::vector<PetscReal> &Phi,
                                      PetscInt count, PetscMPIInt rank = 0, PetscMPIInt size = 1);

// Mode (omega w, rate sigma) from z, zd at s = 0: z and z' at s, exact for every damping
// (under-, critically and overdamped, rigid). Bound: sup over s >= 0 of |d^p z / ds^p|.
void ModalModeAt(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, PetscReal s, PetscReal *q, PetscReal *qd);
PetscReal ModalModeBound(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, int p);

// A phase's solution from its start: modal coordinates and velocities.
struct ModalPhase {
  const ModalSystem     *S = nullptr;
  const ModalBasis      *B = nullptr;
  std::vector<PetscReal> z, zd; // modal displacement and velocity at s = 0

  bool Damped(PetscInt k) const { return !B->rate.empty() && B->rate[k] > 0; }

  void From(const std::vector<PetscReal> &q, const std::vector<PetscReal> &qd)
  {
    const PetscInt n = S->n;
    z.assign(n, 0.0);
    zd.assign(n, 0.0);
    for (PetscInt k = 0; k < n; ++k)
      for (PetscInt d = 0; d < n; ++d) {
        const PetscReal m = std::sqrt(S->mass[d]) * B->Phi[d + k * n];
        z[k] += m * q[d];
        zd[k] += m * qd[d];
      }
  }
  // Modal displacement and velocity at s.
  void At(PetscReal s, std::vector<PetscReal> &zs, std::vector<PetscReal> &zds) const
  {
    const PetscInt n = S->n;
    zs.resize(n);
    zds.resize(n);
    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal w = B->omega[k];
      if (Damped(k)) ModalModeAt(w, B->rate[k], z[k], zd[k], s, &zs[k], &zds[k]);
      else if (w == 0.0) {
        zs[k]  = z[k] + zd[k] * s;
        zds[k] = zd[k];
      } else {
        const PetscReal cs = std::cos(w * s), sn = std::sin(w * s);
        zs[k]  = z[k] * cs + zd[k] * sn / w;
        zds[k] = -z[k] * w * sn + zd[k] * cs;
      }
    }
  }
  // d^p c / ds^p at s for p = 0..3.
  PetscReal Derivative(PetscReal s, int p) const
  {
    PetscReal v = 0;
    for (PetscInt k = 0; k < S->n; ++k) {
      const PetscReal w = B->omega[k], gk = B->gamma[k];
      if (gk == 0.0) continue;
      if (Damped(k)) { // q'' = -2 sigma q' - w^2 q, and on
        PetscReal d[4];
        ModalModeAt(w, B->rate[k], z[k], zd[k], s, &d[0], &d[1]);
        for (int i = 2; i <= p; ++i) d[i] = -2 * B->rate[k] * d[i - 1] - w * w * d[i - 2];
        v += gk * d[p];
        continue;
      }
      if (w == 0.0) {
        v += gk * (p == 0 ? z[k] + zd[k] * s : p == 1 ? zd[k] : 0.0);
        continue;
      }
      const PetscReal cs = std::cos(w * s), sn = std::sin(w * s), a = z[k], b = zd[k] / w;
      // f = a cos + b sin; derivatives rotate by 90 degrees and scale by w.
      switch (p) {
      case 0:
        v += gk * (a * cs + b * sn);
        break;
      case 1:
        v += gk * w * (-a * sn + b * cs);
        break;
      case 2:
        v += gk * w * w * (-a * cs - b * sn);
        break;
      default:
        v += gk * w * w * w * (a * sn - b * cs);
        break;
      }
    }
    return v;
  }
  // Upper bound on |d^p c / ds^p| over all s (p >= 1 for oscillating modes).
  PetscReal Bound(int p) const
  {
    PetscReal b = 0;
    for (PetscInt k = 0; k < S->n; ++k) {
      const PetscReal w = B->omega[k];
      if (Damped(k)) {
        b += std::abs(B->gamma[k]) * ModalModeBound(w, B->rate[k], z[k], zd[k], p);
        continue;
      }
      if (w == 0.0) continue;
      b += std::abs(B->gamma[k]) * std::hypot(z[k], zd[k] / w) * std::pow(w, p);
    }
    return b;
  }
  void State(PetscReal s, std::vector<PetscReal> &q, std::vector<PetscReal> &qd) const
  {
    std::vector<PetscReal> zs, zds;
    At(s, zs, zds);
    const PetscInt n = S->n;
    q.assign(n, 0.0);
    qd.assign(n, 0.0);
    for (PetscInt d = 0; d < n; ++d) {
      const PetscReal im = 1.0 / std::sqrt(S->mass[d]);
      for (PetscInt k = 0; k < n; ++k) {
        q[d] += im * B->Phi[d + k * n] * zs[k];
        qd[d] += im * B->Phi[d + k * n] * zds[k];
      }
    }
  }
};

// First s in (0, s_end] where sign * c^(p)(s) goes from > 0 to <= 0; returns false if none.
// Steps are safe: with f = sign c^(p), f' and |f''| <= bound, f cannot reach 0 within
// the step unless the step is the minimum one. For any phase with Derivative(s, p) and
// Bound(p): the undamped and Rayleigh-damped ModalPhase, and the damped first-order phase of
// modal_damped.hpp. A root we start on (the previous event) is left towards the side of the
// search first; the bracketed root is bisected to round-off (the post side is returned).
template <class Phase>
bool ModalFirstCrossingOf(const Phase &ph, int p, PetscReal sign, PetscReal s_end, PetscReal s_min, PetscReal *root)
{
  const PetscReal bound = std::max(ph.Bound(p + 2), 1e-300);
  PetscReal       s     = 0.0;
  PetscReal       f     = sign * ph.Derivative(s, p);
  int             guard = 0;
  while (f <= 0 && s < s_end && guard++ < 1000) {
    s = std::min(s_end, s + s_min * (1 << std::min(guard, 20)));
    f = sign * ph.Derivative(s, p);
  }
  if (f <= 0) return false;
  while (s < s_end) {
    const PetscReal fd   = sign * ph.Derivative(s, p + 1);
    PetscReal       step = fd >= 0 ? std::sqrt(2 * f / bound) : (fd + std::sqrt(fd * fd + 2 * bound * f)) / bound;
    step                 = std::max(step, s_min);
    const PetscReal sn   = std::min(s_end, s + step);
    const PetscReal fn   = sign * ph.Derivative(sn, p);
    if (fn <= 0) {
      PetscReal a = s, b = sn;
      for (int it = 0; it < 200 && b - a > 4 * std::numeric_limits<PetscReal>::epsilon() * b; ++it) {
        const PetscReal mid                        = 0.5 * (a + b);
        (sign * ph.Derivative(mid, p) > 0 ? a : b) = mid;
      }
      *root = b;
      return true;
    }
    s = sn;
    f = fn;
  }
  return false;
}

inline bool ModalFirstCrossing(const ModalPhase &ph, int p, PetscReal sign, PetscReal s_end, PetscReal s_min,
                               PetscReal *root)
{
  return ModalFirstCrossingOf(ph, p, sign, s_end, s_min, root);
}

} // namespace beamimpact

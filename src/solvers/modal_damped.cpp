// The exact damped in-contact phase. See modal_damped.hpp.
#include "solvers/modal_damped.hpp"

#include <petscblaslapack.h>

#include <algorithm>
#include <cmath>

namespace beamimpact {

namespace {

// (e^{mu s} - 1) / mu, and s for mu = 0: no cancellation for small |mu s|.
ModalComplex Phi1(ModalComplex mu, PetscReal s)
{
  if (mu == ModalComplex(0, 0)) return ModalComplex(s, 0);
  const PetscReal x = mu.real() * s, y = mu.imag() * s, h = std::sin(0.5 * y);
  return ModalComplex(std::expm1(x) * std::cos(y) - 2 * h * h, std::exp(x) * std::sin(y)) / mu;
}

} // namespace

namespace {

// The undamped coupled modes, mass-scaled (U, U^T M) and split into flexible and rigid.
PetscErrorCode UndampedModes(const ModalSystem &S, bool contact, ModalDampedBasis *B)
{
  const BeamSystem &sys = *S.sys;
  const PetscInt    n   = S.n;
  ModalSystem       S0  = S;
  ModalBasis        MB;

  PetscFunctionBeginUser;
  S0.damping = false; // the same M and K, without the damping
  PetscCall(ModalBasisBuild(S0, contact, &MB));
  *B   = ModalDampedBasis();
  B->n = n;
  B->U.assign(n * n, 0.0);
  B->Ut.assign(n * n, 0.0);
  B->omega.assign(n, 0.0);
  B->gamma = MB.gamma;
  B->state_of.assign(n, -1);
  const PetscReal zero = 1e-3 * sys.frequency_unit;
  PetscReal       gmax = 0, grigid = 0;
  for (PetscInt k = 0; k < n; ++k) {
    for (PetscInt d = 0; d < n; ++d) {
      B->U[d + k * n]  = MB.Phi[d + k * n] / std::sqrt(S.mass[d]);
      B->Ut[k + d * n] = MB.Phi[d + k * n] * std::sqrt(S.mass[d]);
    }
    gmax = std::max(gmax, std::abs(MB.gamma[k]));
    if (MB.omega[k] > zero) {
      B->omega[k]    = MB.omega[k];
      B->state_of[k] = (PetscInt)B->flex.size();
      B->flex.push_back(k);
    } else grigid = std::max(grigid, std::abs(MB.gamma[k]));
  }
  B->rigid_gamma = gmax > 0 ? grigid / gmax : 0;
  PetscFunctionReturn(0);
}

// Chat = U^T C U (the beam dofs; the ball carries no damping), symmetrized.
void ModalDampingMatrix(const ModalSystem &S, ModalDampedBasis *B)
{
  const BeamSystem      &sys = *S.sys;
  const PetscInt         n   = S.n;
  std::vector<PetscReal> shape(sys.ndof), f(sys.ndof);
  B->Chat.assign(n * n, 0.0);
  for (PetscInt k = 0; k < n && sys.Damped(); ++k) {
    std::fill(shape.begin(), shape.end(), 0.0);
    for (PetscInt d = 0; d + 1 < n; ++d) shape[S.dof[d]] = B->U[d + k * n];
    BeamSystemDampingApply(sys, shape.data(), sys.fields, 0, sys.ndof, f.data(), sys.fields);
    for (PetscInt j = 0; j < n; ++j) {
      PetscReal v = 0;
      for (PetscInt d = 0; d + 1 < n; ++d) v += B->U[d + j * n] * f[S.dof[d]];
      B->Chat[j + k * n] = v;
    }
  }
  for (PetscInt k = 0; k < n; ++k)
    for (PetscInt j = 0; j < k; ++j)
      B->Chat[j + k * n] = B->Chat[k + j * n] = 0.5 * (B->Chat[j + k * n] + B->Chat[k + j * n]);
}

// The state matrix on y = [Omega_f z_f ; z'] and its eigen-decomposition (LAPACK geev): one
// term per real eigenvalue or conjugate pair (consecutive, Im > 0 first). VR: the real
// eigenvector matrix.
PetscErrorCode StateEigen(ModalDampedBasis *B, std::vector<PetscReal> *VR)
{
  const PetscInt n = B->n, nf = (PetscInt)B->flex.size(), m = nf + n;
  PetscFunctionBeginUser;
  B->m = m;
  std::vector<PetscReal> A((size_t)m * m, 0.0), wr(m), wi(m);
  VR->assign((size_t)m * m, 0.0);
  for (PetscInt i = 0; i < nf; ++i) A[i + (nf + B->flex[i]) * m] = B->omega[B->flex[i]];
  for (PetscInt k = 0; k < n; ++k) {
    for (PetscInt l = 0; l < n; ++l) A[nf + k + (nf + l) * m] = -B->Chat[k + l * n];
    if (B->state_of[k] >= 0) A[nf + k + B->state_of[k] * m] = -B->omega[k];
  }
  {
    PetscBLASInt bm, lwork, info, one = 1;
    PetscCall(PetscBLASIntCast(m, &bm));
    PetscCall(PetscBLASIntCast(std::max<PetscInt>(1, 8 * m), &lwork));
    std::vector<PetscReal> work(lwork), vl(1);
    PetscCallBLAS("LAPACKgeev", LAPACKgeev_("N", "V", &bm, A.data(), &bm, wr.data(), wi.data(), vl.data(), &one,
                                            VR->data(), &bm, work.data(), &lwork, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK geev failed (info %d)", (int)info);
  }
  PetscReal lmax = 0;
  for (PetscInt j = 0; j < m; ++j) lmax = std::max(lmax, std::hypot(wr[j], wi[j]));
  for (PetscInt j = 0; j < m; ++j) {
    // Re lambda <= 0 for a damped system: a positive real part is round-off (the rigid
    // velocities without alpha, undamped modes); set to 0 so that the bounds hold.
    PetscCheck(wr[j] <= 1e-9 * lmax, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "damped modal basis: eigenvalue %g%+gi with a positive real part", (double)wr[j], (double)wi[j]);
    wr[j] = std::min<PetscReal>(wr[j], 0.0);
  }
  for (PetscInt j = 0; j < m; ++j) {
    B->lambda.push_back(ModalComplex(wr[j], wi[j]));
    B->col.push_back(j);
    for (PetscInt i = 0; i < m; ++i)
      B->V.push_back(wi[j] != 0 ? ModalComplex((*VR)[i + j * m], (*VR)[i + (j + 1) * m])
                                : ModalComplex((*VR)[i + j * m], 0));
    if (wi[j] != 0) ++j;
  }
  PetscFunctionReturn(0);
}

// The inverse of the real eigenvector matrix and its condition number (refused above the limit).
PetscErrorCode StateInverse(const BeamSystem &sys, bool contact, const std::vector<PetscReal> &VR, ModalDampedBasis *B)
{
  const PetscInt      m  = B->m;
  const DampingScales ds = ForceOperatorDampingScales(sys); // alpha, beta (for the messages)
  PetscFunctionBeginUser;
  B->Vinv = VR;
  {
    PetscBLASInt              bm, info, lwork;
    std::vector<PetscBLASInt> piv(m);
    PetscCall(PetscBLASIntCast(m, &bm));
    PetscCall(PetscBLASIntCast(std::max<PetscInt>(1, 8 * m), &lwork));
    std::vector<PetscReal> work(lwork);
    PetscCallBLAS("LAPACKgetrf", LAPACKgetrf_(&bm, &bm, B->Vinv.data(), &bm, piv.data(), &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED,
               "-beam_damping_mass %g, -beam_damping_stiffness %g: the eigenvectors of the damped %s system are "
               "linearly dependent (a defective, critically damped mode); the exact "
               "modal reference cannot represent it (use a tight TS run as the reference)",
               (double)ds.mass_rate, (double)ds.stiffness, contact ? "in-contact" : "separated");
    PetscCallBLAS("LAPACKgetri", LAPACKgetri_(&bm, B->Vinv.data(), &bm, piv.data(), work.data(), &lwork, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK getri failed (info %d)", (int)info);
  }
  PetscReal n1 = 0, n1i = 0;
  for (PetscInt j = 0; j < m; ++j) {
    PetscReal c = 0, ci = 0;
    for (PetscInt i = 0; i < m; ++i) c += std::abs(VR[i + j * m]), ci += std::abs(B->Vinv[i + j * m]);
    n1 = std::max(n1, c), n1i = std::max(n1i, ci);
  }
  B->cond = n1 * n1i;
  PetscCheck(B->cond <= kModalDampedMaxCondition, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED,
             "-beam_damping_mass %g, -beam_damping_stiffness %g: the eigenvector matrix of the damped %s system has "
             "condition number %.3g (> %.0e; a mode close to critical "
             "damping): the exact modal reference would not be trustworthy (use a tight TS run as the reference)",
             (double)ds.mass_rate, (double)ds.stiffness, contact ? "in-contact" : "separated", (double)B->cond,
             (double)kModalDampedMaxCondition);
  PetscFunctionReturn(0);
}

// Each term's share of c, and the dissipation forms of the velocity parts.
void TermForms(const BeamSystem &sys, ModalDampedBasis *B)
{
  const PetscInt n = B->n, m = B->m, nf = (PetscInt)B->flex.size(), r = (PetscInt)B->lambda.size();
  B->Gamma.assign(r, 0.0);
  for (PetscInt j = 0; j < r; ++j)
    for (PetscInt i = 0; i < nf; ++i) B->Gamma[j] += B->gamma[B->flex[i]] / B->omega[B->flex[i]] * B->V[i + j * m];
  B->G1.assign(r * r, 0.0);
  B->G2.assign(r * r, 0.0);
  if (!sys.Damped()) return;
  std::vector<ModalComplex> Cw((size_t)n * r, 0.0);
  for (PetscInt k = 0; k < r; ++k)
    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt l = 0; l < n; ++l) Cw[i + k * n] += B->Chat[i + l * n] * B->V[nf + l + k * m];
  for (PetscInt k = 0; k < r; ++k)
    for (PetscInt j = 0; j < r; ++j) {
      ModalComplex g1 = 0, g2 = 0;
      for (PetscInt i = 0; i < n; ++i) {
        g1 += B->V[nf + i + j * m] * Cw[i + k * n];
        g2 += B->V[nf + i + j * m] * std::conj(Cw[i + k * n]);
      }
      B->G1[j + k * r] = g1;
      B->G2[j + k * r] = g2;
    }
}

} // namespace

PetscErrorCode ModalDampedBasisBuild(const ModalSystem &S, bool contact, ModalDampedBasis *B)
{
  std::vector<PetscReal> VR;
  PetscFunctionBeginUser;
  PetscCall(UndampedModes(S, contact, B));
  ModalDampingMatrix(S, B);
  PetscCall(StateEigen(B, &VR));
  PetscCall(StateInverse(*S.sys, contact, VR, B));
  TermForms(*S.sys, B);
  PetscFunctionReturn(0);
}

void ModalDampedPhase::From(const std::vector<PetscReal> &q, const std::vector<PetscReal> &qd)
{
  const PetscInt         n = B->n, m = B->m, nf = (PetscInt)B->flex.size(), r = (PetscInt)B->lambda.size();
  std::vector<PetscReal> zd(n, 0.0), y(m, 0.0), b(m, 0.0);
  z0.assign(n, 0.0);
  for (PetscInt d = 0; d < n; ++d)
    for (PetscInt k = 0; k < n; ++k) {
      z0[k] += B->Ut[k + d * n] * q[d];
      zd[k] += B->Ut[k + d * n] * qd[d];
    }
  for (PetscInt i = 0; i < nf; ++i) y[i] = B->omega[B->flex[i]] * z0[B->flex[i]];
  for (PetscInt k = 0; k < n; ++k) y[nf + k] = zd[k];
  for (PetscInt j = 0; j < m; ++j)
    for (PetscInt i = 0; i < m; ++i) b[i] += B->Vinv[i + j * m] * y[j];
  a.resize(r);
  for (PetscInt j = 0; j < r; ++j)
    a[j] = B->lambda[j].imag() != 0 ? ModalComplex(b[B->col[j]], -b[B->col[j] + 1]) : ModalComplex(b[B->col[j]], 0);
}

void ModalDampedPhase::At(PetscReal s, std::vector<PetscReal> &z, std::vector<PetscReal> &zd) const
{
  const PetscInt            n = B->n, m = B->m, nf = (PetscInt)B->flex.size(), r = (PetscInt)B->lambda.size();
  std::vector<ModalComplex> e(r), f(r);
  for (PetscInt j = 0; j < r; ++j) {
    e[j] = a[j] * std::exp(B->lambda[j] * s);
    f[j] = a[j] * Phi1(B->lambda[j], s);
  }
  z.assign(n, 0.0);
  zd.assign(n, 0.0);
  for (PetscInt k = 0; k < n; ++k) {
    const PetscInt i = B->state_of[k];
    PetscReal      v = 0, u = 0;
    for (PetscInt j = 0; j < r; ++j) {
      v += (e[j] * B->V[nf + k + j * m]).real();
      if (i >= 0) u += (e[j] * B->V[i + j * m]).real();
      else u += (f[j] * B->V[nf + k + j * m]).real();
    }
    zd[k] = v;
    z[k]  = i >= 0 ? u / B->omega[k] : z0[k] + u;
  }
}

void ModalDampedPhase::State(PetscReal s, std::vector<PetscReal> &q, std::vector<PetscReal> &qd) const
{
  const PetscInt         n = B->n;
  std::vector<PetscReal> z, zd;
  At(s, z, zd);
  q.assign(n, 0.0);
  qd.assign(n, 0.0);
  for (PetscInt k = 0; k < n; ++k)
    for (PetscInt d = 0; d < n; ++d) {
      q[d] += B->U[d + k * n] * z[k];
      qd[d] += B->U[d + k * n] * zd[k];
    }
}

PetscReal ModalDampedPhase::Derivative(PetscReal s, int p) const
{
  PetscReal v = 0;
  for (size_t j = 0; j < a.size(); ++j) {
    const ModalComplex l = B->lambda[j];
    ModalComplex       t = B->Gamma[j] * a[j] * std::exp(l * s);
    for (int i = 0; i < p; ++i) t *= l;
    v += t.real();
  }
  return v;
}

PetscReal ModalDampedPhase::Bound(int p) const
{
  PetscReal b = 0;
  for (size_t j = 0; j < a.size(); ++j) b += std::abs(B->Gamma[j] * a[j]) * std::pow(std::abs(B->lambda[j]), p);
  return b;
}

PetscReal ModalDampedPhase::Dissipated(PetscReal s) const
{
  const size_t r = a.size();
  PetscReal    D = 0;
  for (size_t k = 0; k < r; ++k)
    for (size_t j = 0; j < r; ++j) {
      const ModalComplex lj = B->lambda[j], lk = B->lambda[k];
      D += (a[j] * a[k] * B->G1[j + k * r] * Phi1(lj + lk, s) +
            a[j] * std::conj(a[k]) * B->G2[j + k * r] * Phi1(lj + std::conj(lk), s))
             .real();
    }
  return 0.5 * D;
}

} // namespace beamimpact

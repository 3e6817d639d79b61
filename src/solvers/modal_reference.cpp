// Exact (modal) solution of the linear-spring impact on the semi-discrete beam.
// See modal_reference.hpp. Phases alternate between contact (K + k g g^T) and
// separation (K; the ball flies freely); in each phase
//   q(t0 + s) = M^{-1/2} Phi z(s),  z_k(s) = z_k cos(w_k s) + zdot_k sin(w_k s) / w_k,
// and events are the first sign changes of c(s) = g^T q (separation, re-contact) and
// of dc/ds (maximum compression). Roots are bracketed with steps that provably
// cannot skip a crossing (a Taylor bound with |f''| <= sum_k |gamma_k a_k| w_k^2),
// then bisected to round-off.
#include "solvers/modal_reference.hpp"
#include "run/scenario.hpp"

#include <petscblaslapack.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace beamimpact {

extern "C" void dgbsv_(const int *n, const int *kl, const int *ku, const int *nrhs, double *ab, const int *ldab, int *ipiv, double *b, const int *ldb, int *info);

namespace {

// The free degrees of freedom: beam nodes that are not held, then the ball.
struct ModalSystem {
  BeamOperator          op;
  std::vector<PetscInt> node;     // dof -> beam node (the last dof is the ball: -1)
  std::vector<PetscReal> mass;    // kg, per dof
  std::vector<PetscReal> g;       // dc/dq per dof
  PetscInt              n = 0;
  PetscReal             k = 0;    // N/m
};

// One phase's eigen-decomposition of M^{-1/2} K_p M^{-1/2}.
struct ModalBasis {
  std::vector<PetscReal> omega; // rad/s, per mode
  std::vector<PetscReal> Phi;   // n x n, column-major: Phi[r + k n] (orthonormal eigenvectors)
  std::vector<PetscReal> gamma; // g^T M^{-1/2} Phi_k: contribution of mode k to c
};

// syev's eigenvectors are accurate only to eps * lambda_max / gap: with the h^-4 spread of
// the beam's spectrum that is ~1e-6 at N = 641. Two steps of inverse iteration per mode,
// shifted by its eigenvalue, with a banded LU of A - sigma I (the ball is ordered next to
// its two nodes, so A is banded with 3 sub- and super-diagonals), then modified
// Gram-Schmidt, bring each vector to round-off relative to its own eigenvalue.
PetscErrorCode RefineBasis(const ModalSystem &S, bool contact, const std::vector<PetscReal> &lambda, ModalBasis *B)
{
  const int n = (int)S.n, kl = 3, ku = 3, ldab = 2 * kl + ku + 1, one = 1;

  PetscFunctionBeginUser;
  // Band order: beam dofs in node order with the ball right after the later of its nodes.
  std::vector<PetscInt> dof_of_node(S.op.N, -1);
  for (PetscInt d = 0; d < n - 1; ++d) dof_of_node[S.node[d]] = d;
  PetscInt after = -1;
  for (PetscInt d = 0; d < n - 1; ++d)
    if (S.g[d] != 0.0) after = d;
  std::vector<int> pos(n); // dof -> band position
  {
    int p = 0;
    if (after < 0) pos[n - 1] = p++;
    for (PetscInt d = 0; d < n - 1; ++d) {
      pos[d] = p++;
      if (d == after) pos[n - 1] = p++;
    }
  }
  // Entries of A = M^{-1/2} K_p M^{-1/2} as (row dof, col dof, value).
  struct Entry {
    PetscInt r, c;
    PetscReal v;
  };
  std::vector<Entry> entries;
  for (PetscInt d = 0; d < n - 1; ++d) {
    PetscInt  cols[5];
    PetscReal vals[5];
    const PetscInt nc = BeamStiffnessRow(S.op, S.node[d], cols, vals);
    for (PetscInt q = 0; q < nc; ++q) {
      const PetscInt c = dof_of_node[cols[q]];
      entries.push_back({d, c, vals[q] / std::sqrt(S.mass[d] * S.mass[c])});
    }
  }
  if (contact)
    for (PetscInt r = 0; r < n; ++r)
      for (PetscInt c = 0; c < n; ++c)
        if (S.g[r] != 0.0 && S.g[c] != 0.0) entries.push_back({r, c, S.k * S.g[r] * S.g[c] / std::sqrt(S.mass[r] * S.mass[c])});
  const PetscReal        scale = *std::max_element(lambda.begin(), lambda.end());
  std::vector<double>    ab((size_t)ldab * n), x(n);
  std::vector<int>       ipiv(n);
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal sigma = lambda[k] - 1e-14 * scale; // just below: never exactly singular
    PetscReal *phi  = &B->Phi[k * n];
    for (int it = 0; it < 2; ++it) {
      std::fill(ab.begin(), ab.end(), 0.0);
      for (const Entry &e : entries) {
        const int i = pos[e.r], j = pos[e.c];
        ab[(size_t)(kl + ku + i - j) + (size_t)j * ldab] += e.v;
      }
      for (int i = 0; i < n; ++i) ab[(size_t)(kl + ku) + (size_t)i * ldab] -= sigma;
      for (PetscInt d = 0; d < n; ++d) x[pos[d]] = phi[d];
      int info;
      dgbsv_(&n, &kl, &ku, &one, ab.data(), &ldab, ipiv.data(), x.data(), &n, &info);
      PetscCheck(info >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK dgbsv failed (info %d)", info);
      if (info > 0) break; // exactly singular: the vector is already exact
      PetscReal nrm = 0;
      for (int i = 0; i < n; ++i) nrm += x[i] * x[i];
      nrm = std::sqrt(nrm);
      PetscReal sgn = 0; // keep the orientation
      for (PetscInt d = 0; d < n; ++d) sgn += x[pos[d]] * phi[d];
      for (PetscInt d = 0; d < n; ++d) phi[d] = (sgn < 0 ? -1 : 1) * x[pos[d]] / nrm;
    }
  }
  // Modified Gram-Schmidt (cleans up (near-)degenerate pairs such as the rigid modes).
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal *phi = &B->Phi[k * n];
    for (PetscInt l = 0; l < k; ++l) {
      const PetscReal *psi = &B->Phi[l * n];
      PetscReal        dot = 0;
      for (PetscInt d = 0; d < n; ++d) dot += phi[d] * psi[d];
      for (PetscInt d = 0; d < n; ++d) phi[d] -= dot * psi[d];
    }
    PetscReal nrm = 0;
    for (PetscInt d = 0; d < n; ++d) nrm += phi[d] * phi[d];
    nrm = std::sqrt(nrm);
    for (PetscInt d = 0; d < n; ++d) phi[d] /= nrm;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BuildBasis(const ModalSystem &S, bool contact, ModalBasis *B)
{
  const PetscInt         n = S.n;
  std::vector<PetscReal> A(n * n, 0.0), w(n);

  PetscFunctionBeginUser;
  std::vector<PetscInt> dof_of_node(S.op.N, -1);
  for (PetscInt d = 0; d < n - 1; ++d) dof_of_node[S.node[d]] = d;
  for (PetscInt d = 0; d < n - 1; ++d) {
    PetscInt  cols[5];
    PetscReal vals[5];
    const PetscInt nc = BeamStiffnessRow(S.op, S.node[d], cols, vals);
    for (PetscInt q = 0; q < nc; ++q) A[d + dof_of_node[cols[q]] * n] += vals[q];
  }
  if (contact)
    for (PetscInt r = 0; r < n; ++r)
      for (PetscInt c = 0; c < n; ++c) A[r + c * n] += S.k * S.g[r] * S.g[c];
  for (PetscInt r = 0; r < n; ++r)
    for (PetscInt c = 0; c < n; ++c) A[r + c * n] /= std::sqrt(S.mass[r] * S.mass[c]);
  {
    PetscBLASInt bn, lwork, info;
    PetscCall(PetscBLASIntCast(n, &bn));
    PetscCall(PetscBLASIntCast(std::max<PetscInt>(1, 8 * n), &lwork));
    std::vector<PetscReal> work(lwork);
    PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "U", &bn, A.data(), &bn, w.data(), work.data(), &lwork, &info));
    PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK syev failed (info %d)", (int)info);
  }
  B->Phi = A;
  B->omega.assign(n, 0.0);
  B->gamma.assign(n, 0.0);
  PetscCall(RefineBasis(S, contact, w, B));
  // Refine each eigenvalue by its Rayleigh quotient in the energy form (a sum of squares:
  // accurate relative to the mode itself, where syev's is only relative to the largest).
  std::vector<PetscReal> shape(S.op.N);
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal *phi = &B->Phi[k * n];
    std::fill(shape.begin(), shape.end(), 0.0);
    PetscReal norm = 0, c = 0;
    for (PetscInt d = 0; d < n; ++d) {
      const PetscReal q = phi[d] / std::sqrt(S.mass[d]);
      if (d < n - 1) shape[S.node[d]] = q;
      norm += S.mass[d] * q * q;
      c += S.g[d] * q;
    }
    PetscReal twoU = 2 * BeamStrainEnergy(S.op, shape.data(), 1, 0, S.op.N);
    if (contact) twoU += S.k * c * c;
    B->omega[k] = std::sqrt(std::max<PetscReal>(0.0, twoU / norm));
    B->gamma[k] = c;
  }
  PetscFunctionReturn(0);
}

// A phase's solution from its start: modal coordinates and velocities.
struct ModalPhase {
  const ModalSystem *S = nullptr;
  const ModalBasis  *B = nullptr;
  std::vector<PetscReal> z, zd; // modal displacement and velocity at s = 0

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
      if (w == 0.0) {
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
      if (w == 0.0) {
        v += gk * (p == 0 ? z[k] + zd[k] * s : p == 1 ? zd[k] : 0.0);
        continue;
      }
      const PetscReal cs = std::cos(w * s), sn = std::sin(w * s), a = z[k], b = zd[k] / w;
      // f = a cos + b sin; derivatives rotate by 90 degrees and scale by w.
      switch (p) {
      case 0: v += gk * (a * cs + b * sn); break;
      case 1: v += gk * w * (-a * sn + b * cs); break;
      case 2: v += gk * w * w * (-a * cs - b * sn); break;
      default: v += gk * w * w * w * (a * sn - b * cs); break;
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
// the step unless the step is the minimum one.
bool FirstCrossing(const ModalPhase &ph, int p, PetscReal sign, PetscReal s_end, PetscReal s_min, PetscReal *root)
{
  const PetscReal bound = std::max(ph.Bound(p + 2), 1e-300);
  PetscReal       s     = 0.0;
  PetscReal       f     = sign * ph.Derivative(s, p);
  // Leave a root we start on (the previous event) towards the side of the search.
  int guard = 0;
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
    if (fn <= 0) { // bracketed: bisect to round-off, return the post side
      PetscReal a = s, b = sn;
      for (int it = 0; it < 200 && b - a > 4 * std::numeric_limits<PetscReal>::epsilon() * b; ++it) {
        const PetscReal m = 0.5 * (a + b);
        (sign * ph.Derivative(m, p) > 0 ? a : b) = m;
      }
      *root = b;
      return true;
    }
    s = sn;
    f = fn;
  }
  return false;
}

} // namespace

PetscErrorCode ModalReferenceRun(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, ImpactResult *res)
{
  ModalSystem S;
  ModalBasis  contact_basis, free_basis;

  PetscFunctionBeginUser;
  PetscCheck(ball.law == ContactLawKind::Linear, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "-reference modal needs -ball_law linear (the hysteretic law is nonlinear: use a tight run of a high-order integrator as the reference)");
  const double wall0 = MPI_Wtime();
  *res               = ImpactResult();
  res->x             = ip.x;
  res->ts_type       = "modal";
  res->formulation   = "exact";
  S.op               = BeamOperatorBuild(beam);
  S.k                = ball.k;
  const ImpactStencil st = BeamImpactStencil(S.op, ip.x);
  for (PetscInt i = 0; i < S.op.N; ++i) {
    if (S.op.held[i]) continue;
    S.node.push_back(i);
    S.mass.push_back(S.op.mass[i]);
    S.g.push_back(i == st.j ? -st.w : (i == st.j + 1 ? -(1 - st.w) : 0.0));
  }
  S.node.push_back(-1);
  S.mass.push_back(ball.mass);
  S.g.push_back(1.0);
  S.n = (PetscInt)S.node.size();
  PetscCall(BuildBasis(S, true, &contact_basis));
  PetscCall(BuildBasis(S, false, &free_basis));

  const ImpactTimes times  = ImpactTimesOf(beam, ball, ip);
  const PetscReal   t_cap  = times.max_time;
  const PetscReal   s_min  = 1e-13 * ContactTimeScale(ball);
  const PetscReal   E0     = 0.5 * ball.mass * ball.speed * ball.speed;
  std::vector<PetscReal> q(S.n, 0.0), qd(S.n, 0.0);
  qd[S.n - 1]         = ball.speed;
  PetscReal  t        = 0;
  bool       touching = true;
  ModalPhase ph;
  res->contacts = 1;
  res->events.push_back({ContactEventKind::ContactStart, 0.0, 0.0, 0.0});
  auto energy = [&](bool in_contact) {
    std::vector<PetscReal> shape(S.op.N, 0.0);
    PetscReal              T = 0, c = 0;
    for (PetscInt d = 0; d < S.n; ++d) {
      T += 0.5 * S.mass[d] * qd[d] * qd[d];
      c += S.g[d] * q[d];
      if (S.node[d] >= 0) shape[S.node[d]] = q[d];
    }
    return T + BeamStrainEnergy(S.op, shape.data(), 1, 0, S.op.N) + (in_contact ? 0.5 * S.k * c * c : 0.0);
  };
  for (;;) {
    ph.S = &S;
    ph.B = touching ? &contact_basis : &free_basis;
    ph.From(q, qd);
    if (touching) {
      PetscReal s_sep;
      PetscCheck(FirstCrossing(ph, 0, +1.0, t_cap - t, s_min, &s_sep), PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "modal reference: the ball is still in contact at -impact_max_time %g s", (double)t_cap);
      // Maximum compressions: dc/dt falling through 0 before the separation.
      PetscReal s = 0, s_max;
      ModalPhase rate = ph;
      while (FirstCrossing(rate, 1, +1.0, s_sep - s, s_min, &s_max)) {
        s += s_max;
        const PetscReal c = ph.Derivative(s, 0);
        res->events.push_back({ContactEventKind::MaxCompression, t + s, c, ball.k * c});
        res->max_compression = std::max(res->max_compression, c);
        // Continue after this maximum: restart the search from the state at s.
        std::vector<PetscReal> qs, qds;
        ph.State(s, qs, qds);
        rate.From(qs, qds);
        // Skip to where dc/dt rises again (a local minimum), then look for the next maximum.
        PetscReal s_min_c;
        if (!FirstCrossing(rate, 1, -1.0, s_sep - s, s_min, &s_min_c)) break;
        s += s_min_c;
        ph.State(s, qs, qds);
        rate.From(qs, qds);
      }
      ph.State(s_sep, q, qd);
      t += s_sep;
      res->events.push_back({ContactEventKind::Separation, t, 0.0, 0.0});
      touching = false;
    } else {
      const PetscReal t_stop = std::min(t_cap, t + times.window);
      PetscReal       s_con;
      if (FirstCrossing(ph, 0, -1.0, t_stop - t, s_min, &s_con)) {
        ph.State(s_con, q, qd);
        t += s_con;
        res->contacts++;
        PetscCheck(res->contacts <= ip.max_contacts, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "modal reference: more than -impact_max_contacts %" PetscInt_FMT " contacts", ip.max_contacts);
        res->events.push_back({ContactEventKind::ContactStart, t, 0.0, 0.0});
        touching = true;
      } else {
        ph.State(t_stop - t, q, qd);
        t = t_stop;
        break;
      }
    }
  }
  // Contact times from the event list.
  PetscReal start = 0;
  bool      first = true;
  for (const ContactEvent &e : res->events) {
    if (e.kind == ContactEventKind::ContactStart) start = e.time;
    if (e.kind == ContactEventKind::Separation) {
      if (first) res->contact_time = e.time - start;
      first = false;
      res->contact_time_total += e.time - start;
    }
  }
  res->peak_force          = ball.k * res->max_compression;
  res->final_time          = t;
  res->ball_final_velocity = qd[S.n - 1];
  res->acor                = -qd[S.n - 1] / ball.speed;
  res->acor_corrected      = res->acor * ball.loss_factor;
  res->energy_error        = (energy(false) - E0) / E0;
  {
    std::vector<PetscReal> shape(S.op.N, 0.0);
    PetscReal              T = 0;
    for (PetscInt d = 0; d + 1 < S.n; ++d) {
      T += 0.5 * S.mass[d] * qd[d] * qd[d];
      shape[S.node[d]] = q[d];
    }
    res->beam_kinetic_end = T;
    res->beam_strain_end  = BeamStrainEnergy(S.op, shape.data(), 1, 0, S.op.N);
  }
  res->wall_time = MPI_Wtime() - wall0;
  PetscFunctionReturn(0);
}

PetscErrorCode ModalReferenceRun(const Scenario &sc, ImpactResult *res) { return ModalReferenceRun(sc.beam, sc.ball, sc.impact, res); }

} // namespace beamimpact

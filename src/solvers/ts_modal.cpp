// The modal integrator as the PETSc TS type "modal". See ts_modal.hpp for the method, the
// state it keeps and what each step costs.
#include "solvers/ts_modal.hpp"

#include "solvers/beam_modes.hpp"
#include "solvers/ts_problem.hpp"

#include <petsc/private/tsimpl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace beamimpact {

namespace {

// Response at t of a mode z'' + 2 sigma z' + w^2 z = s^m from rest: *rz = z(t), *rv = z'(t).
// Taylor series where w t and sigma t are small (no cancellation), else a polynomial particular
// solution plus the exact homogeneous solution (ModalModeAt).
void ModeForced(PetscReal w, PetscReal sg, int m, PetscReal t, PetscReal *rz, PetscReal *rv)
{
  if (w == 0.0 || (w * t < 0.5 && sg * t < 0.5)) {
    PetscReal d[3] = {0, 0, 0}; // z^(i), z^(i+1), z^(i+2) at 0, rolling
    PetscReal fact_m = 1;
    for (int i = 2; i <= m; ++i) fact_m *= i;
    PetscReal z = 0, v = 0, ti = 1; // ti = t^i / i!
    for (int i = 0; i < 400; ++i) {
      d[2]                = -2 * sg * d[1] - w * w * d[0] + (i == m ? fact_m : 0.0);
      const PetscReal tz = d[0] * ti, tv = d[1] * ti;
      z += tz;
      v += tv;
      if (i > m + 3 && std::abs(tz) <= 1e-18 * std::abs(z) && std::abs(tv) <= 1e-18 * std::abs(v)) break;
      d[0] = d[1];
      d[1] = d[2];
      ti *= t / (i + 1);
    }
    *rz = z;
    *rv = v;
    return;
  }
  PetscReal p[5] = {0, 0, 0, 0, 0}; // P(s) = sum p_i s^i: w^2 p_i + 2 sigma (i+1) p_{i+1} + (i+2)(i+1) p_{i+2} = [i == m]
  for (int i = m; i >= 0; --i) p[i] = ((i == m ? 1.0 : 0.0) - 2 * sg * (i + 1) * p[i + 1] - (i + 2) * (i + 1) * p[i + 2]) / (w * w);
  PetscReal P = 0, Pd = 0, tp = 1;
  for (int i = 0; i <= m; ++i, tp *= t) {
    P += p[i] * tp;
    if (i < m) Pd += (i + 1) * p[i + 1] * tp;
  }
  PetscReal hz, hv;
  ModalModeAt(w, sg, -p[0], -p[1], t, &hz, &hv);
  *rz = P + hz;
  *rv = Pd + hv;
}

// An undamped mode over t, x = w t: cos x, sin x and the functions of the forced responses
// from rest, sinc = sin x / x, f2 = (1 - cos x)/x^2, f3 = (x - sin x)/x^3, g4 = (x^2 - 2(1 - cos x))/x^4,
// by their series below x = 0.5 (no cancellation; exact for a rigid mode, x = 0).
struct UndampedForced {
  PetscReal c, sn, sinc, f2, f3, g4;
  UndampedForced(PetscReal w, PetscReal t)
  {
    const PetscReal x = w * t, x2 = x * x;
    c  = std::cos(x);
    sn = std::sin(x);
    if (x < 0.5) {
      // sum_j (-1)^j x^(2j) / (2j + p)!, p = 1, 2, 3, 4; 9 terms: x^18/18! < 1e-21
      static const std::vector<PetscReal> ifact = [] {
        std::vector<PetscReal> f(24, 1.0);
        for (int i = 1; i < 24; ++i) f[i] = f[i - 1] / i;
        return f;
      }();
      PetscReal s1 = 0, s2 = 0, s3 = 0, s4 = 0, xp = 1;
      for (int j = 0; j < 9; ++j, xp *= -x2) {
        s1 += xp * ifact[2 * j + 1];
        s2 += xp * ifact[2 * j + 2];
        s3 += xp * ifact[2 * j + 3];
        s4 += xp * ifact[2 * j + 4];
      }
      sinc = s1, f2 = s2, f3 = s3, g4 = 2 * s4;
    } else {
      const PetscReal hs = std::sin(0.5 * x), omc = 2 * hs * hs; // 1 - cos x
      sinc = sn / x;
      f2   = omc / x2;
      f3   = (x - sn) / (x2 * x);
      g4   = (x2 - 2 * omc) / (x2 * x2);
    }
  }
};

// Everything a step of length h needs, per mode, cached by h. The force over the step is the
// polynomial through its values at the nodes tau_j h (order 2: 0, 1; order 4: 0, 1/2, 1),
// F(s) = sum_j F_j l_j(s/h).
struct StepWeights {
  PetscReal              h = 0;
  std::vector<PetscReal> a;      // 4 per mode: the exact free propagator over h
  std::vector<PetscReal> am;     // 2 per mode: its first row over h/2 (order 4)
  std::vector<PetscReal> rz, rv; // [j n + k]: mode k's displacement and velocity at h forced by l_j
  PetscReal              W[3][3] = {{0}}; // dc(tau_i h) / dF_j (beam and ball), i >= 1
  PetscReal              by[3] = {0}, bv[3] = {0}; // ball's displacement and velocity at h per unit F_j (times m_b)
};
constexpr size_t kWeightsCache = 8; // the nominal step and a few event steps

struct ModalTS {
  PetscInt order = 4;
  // Set up once (TSSetUp_Modal).
  TSProblem                       *P = nullptr;
  std::shared_ptr<const BeamModes> modes;
  PetscInt                         n = 0;                      // modes (= free beam dofs)
  std::vector<PetscReal>           gamma, omega, sigma;        // per mode
  std::vector<PetscReal>           isqm;                       // 1/sqrt(m) per free dof
  std::vector<PetscInt>            free_of;                    // beam dof -> free dof (-1: held)
  std::deque<StepWeights>          weights;
  // The modal state and the start of the last step (rollback).
  std::vector<PetscReal> z, zd, z0, zd0;
  PetscReal              yb = 0, vb = 0, yb0 = 0, vb0 = 0;
  bool                   have_modal = false, have_step = false;
  // The physical vector ts->vec_sol: whether it holds the modal state (phys_valid), the
  // object and state it had when last written or projected, and a copy of that content.
  bool             phys_valid = false;
  PetscObjectId    vec_id     = 0;
  PetscObjectState vec_state  = 0;
  Vec              Xc = nullptr, all = nullptr;
  VecScatter       gather = nullptr;
  PetscInt         projections = 0, syncs = 0, newton_fail = 0;
};

ModalTS *Data(TS ts) { return static_cast<ModalTS *>(ts->data); }

// Nodes tau_j and the Lagrange basis l_j(x) = sum_m L[j][m] x^m of the force polynomial.
PetscInt StageCount(PetscInt order) { return order == 2 ? 2 : 3; }
const PetscReal kTau2[2] = {0, 1}, kTau4[3] = {0, 0.5, 1};
const PetscReal kL2[2][3] = {{1, -1, 0}, {0, 1, 0}};
const PetscReal kL4[3][3] = {{1, -3, 2}, {0, 4, -4}, {0, -1, 2}};

const StepWeights &WeightsOf(ModalTS &m, PetscReal h)
{
  for (const StepWeights &w : m.weights)
    if (w.h == h) return w;
  const PetscInt   s    = StageCount(m.order), n = m.n;
  const PetscReal *tau  = m.order == 2 ? kTau2 : kTau4;
  const PetscReal(*L)[3] = m.order == 2 ? nullptr : kL4;
  auto Lc               = [&](PetscInt j, PetscInt q) { return L ? L[j][q] : kL2[j][q]; };
  StepWeights      W;
  W.h = h;
  W.a.resize(4 * (size_t)n);
  W.am.resize(2 * (size_t)n);
  W.rz.assign((size_t)s * n, 0.0);
  W.rv.assign((size_t)s * n, 0.0);
  const PetscReal mb = m.P->ball.mass;
  PetscReal       coef[3][3] = {{0}}; // l_j(s/h) = sum_q coef[j][q] s^q
  for (PetscInt j = 0; j < s; ++j)
    for (PetscInt q = 0; q < s; ++q) coef[j][q] = Lc(j, q) / std::pow(h, (PetscReal)q);
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal w = m.omega[k], sg = m.sigma[k], g2 = m.gamma[k] * m.gamma[k];
    if (sg == 0.0) { // undamped (rigid modes included): closed forms in x = w t, one sin and cos per time
      for (PetscInt i = 1; i < s; ++i) {
        const PetscReal t = tau[i] * h;
        UndampedForced  u(w, t);
        const PetscReal rz[3] = {t * t * u.f2, t * t * t * u.f3, t * t * t * t * u.g4}, rv[3] = {t * u.sinc, t * t * u.f2, 2 * t * t * t * u.f3};
        if (i == s - 1) {
          PetscReal *a = &W.a[4 * k];
          a[0] = u.c, a[1] = t * u.sinc, a[2] = -w * u.sn, a[3] = u.c;
        } else W.am[2 * k] = u.c, W.am[2 * k + 1] = t * u.sinc;
        for (PetscInt j = 0; j < s; ++j) {
          PetscReal z = 0, v = 0;
          for (PetscInt q = 0; q < s; ++q) {
            z += coef[j][q] * rz[q];
            v += coef[j][q] * rv[q];
          }
          W.W[i][j] += g2 * z;
          if (i == s - 1) {
            W.rz[j * n + k] = z;
            W.rv[j * n + k] = v;
          }
        }
      }
      continue;
    }
    ModalModeAt(w, sg, 1.0, 0.0, h, &W.a[4 * k], &W.a[4 * k + 2]);
    ModalModeAt(w, sg, 0.0, 1.0, h, &W.a[4 * k + 1], &W.a[4 * k + 3]);
    if (s == 3) {
      PetscReal dummy;
      ModalModeAt(w, sg, 1.0, 0.0, 0.5 * h, &W.am[2 * k], &dummy);
      ModalModeAt(w, sg, 0.0, 1.0, 0.5 * h, &W.am[2 * k + 1], &dummy);
    }
    for (PetscInt q = 0; q < s; ++q) { // the monomial (s/h)^q
      PetscReal rz, rv;
      const PetscReal hq = std::pow(h, (PetscReal)q);
      ModeForced(w, sg, (int)q, h, &rz, &rv);
      for (PetscInt j = 0; j < s; ++j) {
        W.rz[j * n + k] += Lc(j, q) * rz / hq;
        W.rv[j * n + k] += Lc(j, q) * rv / hq;
      }
      for (PetscInt i = 1; i < s; ++i) {
        PetscReal rzi = rz, rvi;
        if (tau[i] != 1.0) ModeForced(w, sg, (int)q, tau[i] * h, &rzi, &rvi);
        for (PetscInt j = 0; j < s; ++j) W.W[i][j] += g2 * Lc(j, q) * rzi / hq;
      }
    }
  }
  // The ball: y_b'' = -F/m_b; int_0^t (t - u) u^q du = t^(q+2)/((q+1)(q+2)), int_0^t u^q du = t^(q+1)/(q+1).
  for (PetscInt q = 0; q < s; ++q) {
    const PetscReal hq = std::pow(h, (PetscReal)q);
    for (PetscInt j = 0; j < s; ++j) {
      W.by[j] += Lc(j, q) * std::pow(h, (PetscReal)q + 2) / ((q + 1) * (q + 2)) / hq;
      W.bv[j] += Lc(j, q) * std::pow(h, (PetscReal)q + 1) / (q + 1) / hq;
      for (PetscInt i = 1; i < s; ++i) W.W[i][j] += Lc(j, q) * std::pow(tau[i] * h, (PetscReal)q + 2) / ((q + 1) * (q + 2)) / hq / mb;
    }
  }
  m.weights.push_front(std::move(W));
  while (m.weights.size() > kWeightsCache) m.weights.pop_back();
  return m.weights.front();
}

PetscReal ModalCompression(const ModalTS &m, PetscReal *cdot)
{
  PetscReal c = m.yb, cd = m.vb;
  for (PetscInt k = 0; k < m.n; ++k) {
    c -= m.gamma[k] * m.z[k];
    cd -= m.gamma[k] * m.zd[k];
  }
  if (cdot) *cdot = cd;
  return c;
}

// One step of length h (exponential collocation on the force; see ts_modal.hpp).
void StepBy(ModalTS &m, PetscReal h)
{
  TSProblem        &P  = *m.P;
  const bool        in = P.contact->phase != ContactPhase::Separated;
  const StepWeights &W = WeightsOf(m, h);
  const PetscInt    s  = StageCount(m.order), n = m.n;
  const PetscReal  *tau = m.order == 2 ? kTau2 : kTau4;
  PetscReal         F[3] = {0, 0, 0};
  if (in) {
    // Free compression at the stage times, then F_i = F(c_i) with c_i = cfree_i - sum_j W_ij F_j.
    PetscReal cfree[3] = {0, 0, 0};
    for (PetscInt i = 1; i < s; ++i) cfree[i] = m.yb + m.vb * tau[i] * h;
    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal gk = m.gamma[k], z = m.z[k], zd = m.zd[k];
      if (s == 3) cfree[1] -= gk * (W.am[2 * k] * z + W.am[2 * k + 1] * zd);
      cfree[s - 1] -= gk * (W.a[4 * k] * z + W.a[4 * k + 1] * zd);
    }
    P.count.func++;
    F[0] = ContactForce(P.ball, *P.contact, ModalCompression(m, nullptr));
    for (PetscInt i = 1; i < s; ++i) F[i] = F[0];
    const PetscInt nu = s - 1; // unknowns F_1 .. F_{s-1}
    PetscReal dprev = PETSC_MAX_REAL;
    for (int it = 0; it < 50; ++it) {
      PetscReal r[2], J[2][2], c[3];
      for (PetscInt i = 1; i < s; ++i) {
        c[i] = cfree[i];
        for (PetscInt j = 0; j < s; ++j) c[i] -= W.W[i][j] * F[j];
        const PetscReal k = ContactStiffness(P.ball, *P.contact, c[i]);
        r[i - 1]          = F[i] - ContactForce(P.ball, *P.contact, c[i]);
        for (PetscInt l = 1; l < s; ++l) J[i - 1][l - 1] = (i == l ? 1.0 : 0.0) + k * W.W[i][l];
      }
      P.count.func++;
      PetscReal d[2];
      if (nu == 1) d[0] = r[0] / J[0][0];
      else {
        const PetscReal det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        d[0]                = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
        d[1]                = (J[0][0] * r[1] - J[1][0] * r[0]) / det;
      }
      PetscReal dmax = 0, fmax = std::abs(F[0]);
      for (PetscInt i = 0; i < nu; ++i) {
        F[i + 1] -= d[i];
        dmax = std::max(dmax, std::abs(d[i]));
        fmax = std::max(fmax, std::abs(F[i + 1]));
      }
      if (!(dmax > 1e-14 * fmax) || (it > 2 && dmax >= dprev)) break; // converged, or at round-off
      dprev = dmax;
      if (it == 49) m.newton_fail++;
    }
  }
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal *a = &W.a[4 * k], z = m.z[k], zd = m.zd[k];
    PetscReal        zn = a[0] * z + a[1] * zd, zdn = a[2] * z + a[3] * zd;
    if (in)
      for (PetscInt j = 0; j < s; ++j) {
        zn += m.gamma[k] * F[j] * W.rz[j * n + k];
        zdn += m.gamma[k] * F[j] * W.rv[j * n + k];
      }
    m.z[k]  = zn;
    m.zd[k] = zdn;
  }
  m.yb += m.vb * h;
  for (PetscInt j = 0; j < s; ++j) {
    m.yb -= F[j] * W.by[j] / P.ball.mass;
    m.vb -= F[j] * W.bv[j] / P.ball.mass;
  }
}

// Collective: whether any rank says so.
PetscErrorCode AnyRank(MPI_Comm comm, bool local, bool *any)
{
  PetscMPIInt size, v = local ? 1 : 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MAX, comm));
  *any = v != 0;
  PetscFunctionReturn(0);
}

// The modal state from the physical vector (every rank gathers it): z = Phi^T M^{1/2} y.
PetscErrorCode Project(TS ts)
{
  ModalTS        &m = *Data(ts);
  const TSLayout &L = m.P->L;
  const PetscInt  nf = L.fields, n = m.n;
  Vec             X  = ts->vec_sol;

  PetscFunctionBeginUser;
  if (!m.gather) PetscCall(VecScatterCreateToAll(X, &m.gather, &m.all));
  PetscCall(VecScatterBegin(m.gather, X, m.all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.gather, X, m.all, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar     *u;
  std::vector<PetscReal> sy(n), sv(n);
  PetscCall(VecGetArrayRead(m.all, &u));
  for (PetscInt i = 0; i < n; ++i) {
    const PetscInt  d = m.modes->S.dof[i], node = d / nf, f = d % nf;
    const PetscReal sm = 1.0 / m.isqm[i];
    sy[i]              = sm * u[L.NodeIndex(node, f)];
    sv[i]              = sm * u[L.NodeIndex(node, nf + f)];
  }
  m.yb = u[L.BallIndex(0)];
  m.vb = u[L.BallIndex(1)];
  PetscCall(VecRestoreArrayRead(m.all, &u));
  m.z.assign(n, 0.0);
  m.zd.assign(n, 0.0);
  const PetscReal *Phi  = m.modes->B.Phi.data();
  bool             rest = true; // the beam at rest and undeformed (the start of an impact): z = 0, no O(n^2) work
  for (PetscInt i = 0; i < n && rest; ++i) rest = sy[i] == 0.0 && sv[i] == 0.0;
  for (PetscInt k = 0; k < n && !rest; ++k) {
    const PetscReal *phi = Phi + (size_t)k * n;
    PetscReal        a = 0, b = 0;
    for (PetscInt i = 0; i < n; ++i) {
      a += phi[i] * sy[i];
      b += phi[i] * sv[i];
    }
    m.z[k]  = a;
    m.zd[k] = b;
  }
  m.have_modal = true;
  m.projections++;
  // The vector is the truth it was projected from: keep it as the written copy.
  if (!m.Xc) PetscCall(VecDuplicate(X, &m.Xc));
  PetscCall(VecCopy(X, m.Xc));
  PetscCall(PetscObjectGetId((PetscObject)X, &m.vec_id));
  PetscCall(PetscObjectStateGet((PetscObject)X, &m.vec_state));
  m.phys_valid = true;
  PetscFunctionReturn(0);
}

// Makes the modal state authoritative: projects the physical vector if it was replaced or
// written from outside since the modal state last matched it. Collective.
PetscErrorCode Reconcile(TS ts)
{
  ModalTS         &m = *Data(ts);
  Vec              X = ts->vec_sol;
  PetscObjectId    id;
  PetscObjectState st;
  bool             stale;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetId((PetscObject)X, &id));
  PetscCall(PetscObjectStateGet((PetscObject)X, &st));
  PetscCall(AnyRank(PetscObjectComm((PetscObject)ts), !m.have_modal || id != m.vec_id || st != m.vec_state, &stale));
  if (!stale) PetscFunctionReturn(0);
  if (m.have_modal && m.phys_valid) { // touched, maybe only read: compare with what it held
    PetscBool same = PETSC_FALSE;
    PetscCall(VecEqual(X, m.Xc, &same)); // collective
    if (same) {
      m.vec_id    = id;
      m.vec_state = st;
      PetscFunctionReturn(0);
    }
  }
  PetscCall(Project(ts));
  PetscFunctionReturn(0);
}

// Writes the modal state into the physical vector (each rank its owned dofs). Collective.
PetscErrorCode Sync(TS ts)
{
  ModalTS     &m = *Data(ts);
  Vec          X = ts->vec_sol;
  TSStateWrite o;

  PetscFunctionBeginUser;
  if (!m.P || !X) PetscFunctionReturn(0); // not set up yet: nothing to write
  const TSLayout &L = m.P->L;
  const PetscInt  nf = L.fields, n = m.n;
  PetscCall(Reconcile(ts));
  if (m.phys_valid) PetscFunctionReturn(0);
  // The owned beam dofs [D0, D1) are a contiguous range [i0, i1) of free dofs.
  PetscInt i0 = n, i1 = 0;
  for (PetscInt d = L.D0(); d < L.D1(); ++d)
    if (m.free_of[d] >= 0) {
      i0 = std::min(i0, m.free_of[d]);
      i1 = std::max(i1, m.free_of[d] + 1);
    }
  std::vector<PetscReal> y(std::max<PetscInt>(i1 - i0, 0), 0.0), v(y.size(), 0.0);
  const PetscReal       *Phi = m.modes->B.Phi.data();
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal *phi = Phi + (size_t)k * n, zk = m.z[k], zdk = m.zd[k];
    for (PetscInt i = i0; i < i1; ++i) {
      y[i - i0] += phi[i] * zk;
      v[i - i0] += phi[i] * zdk;
    }
  }
  PetscCall(TSStateWriteBegin(L, X, &o));
  for (PetscInt d = L.D0(); d < L.D1(); ++d) {
    const PetscInt i = m.free_of[d], k = (d / nf) * L.dof + d % nf;
    o.beam[k]        = i < 0 ? 0.0 : m.isqm[i] * y[i - i0];
    o.beam[k + nf]   = i < 0 ? 0.0 : m.isqm[i] * v[i - i0];
  }
  if (o.ball) {
    o.ball[0] = m.yb;
    o.ball[1] = m.vb;
  }
  PetscCall(TSStateWriteEnd(L, X, &o));
  if (!m.Xc) PetscCall(VecDuplicate(X, &m.Xc));
  PetscCall(VecCopy(X, m.Xc));
  PetscCall(PetscObjectGetId((PetscObject)X, &m.vec_id));
  PetscCall(PetscObjectStateGet((PetscObject)X, &m.vec_state));
  m.phys_valid = true;
  m.syncs++;
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------- TS methods

PetscErrorCode TSStep_Modal(TS ts)
{
  ModalTS        &m = *Data(ts);
  const PetscReal h = ts->time_step;

  PetscFunctionBeginUser;
  PetscCall(Reconcile(ts));
  m.z0        = m.z;
  m.zd0       = m.zd;
  m.yb0       = m.yb;
  m.vb0       = m.vb;
  m.have_step = true;
  StepBy(m, h);
  m.phys_valid = false;
  ts->ptime += h;
  PetscFunctionReturn(0);
}

PetscErrorCode TSRollBack_Modal(TS ts)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  PetscCheck(m.have_step, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER, "TS modal: no completed step to roll back");
  m.z          = m.z0;
  m.zd         = m.zd0;
  m.yb         = m.yb0;
  m.vb         = m.vb0;
  m.have_step  = false;
  m.phys_valid = false; // the vector (if it was written after the step) holds the step's end
  PetscFunctionReturn(0);
}

PetscErrorCode TSReset_Modal(TS ts)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&m.Xc));
  PetscCall(VecDestroy(&m.all));
  PetscCall(VecScatterDestroy(&m.gather));
  const PetscInt order = m.order;
  m                    = ModalTS();
  m.order              = order;
  PetscFunctionReturn(0);
}

PetscErrorCode SyncSolution_Modal(TS ts)
{
  PetscFunctionBeginUser;
  PetscCall(Sync(ts));
  PetscFunctionReturn(0);
}

PetscErrorCode Compression_Modal(TS ts, PetscReal *c, PetscReal *cdot)
{
  PetscFunctionBeginUser;
  PetscCall(Reconcile(ts));
  *c = ModalCompression(*Data(ts), cdot);
  PetscFunctionReturn(0);
}

PetscErrorCode DissipationRate_Modal(TS ts, PetscReal *rate, PetscReal *rate_dot)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  PetscCall(Reconcile(ts));
  const TSProblem &P = *m.P;
  const PetscReal  F = ContactForce(P.ball, *P.contact, ModalCompression(m, nullptr));
  PetscReal        r = 0, rd = 0;
  for (PetscInt k = 0; k < m.n; ++k) {
    const PetscReal s2 = 2 * m.sigma[k], zdd = -m.omega[k] * m.omega[k] * m.z[k] - s2 * m.zd[k] + m.gamma[k] * F;
    r += s2 * m.zd[k] * m.zd[k];
    rd += 2 * s2 * zdd * m.zd[k];
  }
  *rate     = r;
  *rate_dot = rd;
  PetscFunctionReturn(0);
}

PetscErrorCode TSDestroy_Modal(TS ts)
{
  PetscFunctionBeginUser;
  PetscCall(TSReset_Modal(ts));
  delete Data(ts);
  ts->data = nullptr;
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalSyncSolution_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalCompression_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalDissipationRate_C", nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode TSSetUp_Modal(TS ts)
{
  ModalTS      &m = *Data(ts);
  TSRHSFunction f = nullptr;
  void         *ctx = nullptr;
  std::string   why;

  PetscFunctionBeginUser;
  PetscCall(TSGetRHSFunction(ts, nullptr, &f, &ctx));
  PetscCheck(f == TSRHSExplicit && ctx, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_WRONGSTATE,
             "TS modal integrates the beam-and-ball problem of beamimpact only (its explicit right-hand side, solvers/ts_problem.hpp)");
  m.P                  = static_cast<TSProblem *>(ctx);
  const BeamSystem &sys = *m.P->sys;
  PetscCheck(BeamModesAvailable(sys, &why), PetscObjectComm((PetscObject)ts), PETSC_ERR_SUP, "-ts_type modal needs the beam's modes: %s; use another -ts_type", why.c_str());
  PetscCall(BeamModesShared(sys, &m.modes));
  const ModalSystem &S = m.modes->S;
  const ModalBasis  &B = m.modes->B;
  const PetscInt     n = S.n;
  m.n                  = n;
  m.omega              = B.omega;
  m.sigma              = B.rate.empty() ? std::vector<PetscReal>(n, 0.0) : B.rate;
  m.isqm.resize(n);
  m.free_of.assign(sys.ndof, -1);
  // gamma_k = sum over the two coupled dofs of w_q phi_k[d_q] / sqrt(m_{d_q}).
  std::vector<PetscReal> gw(n, 0.0);
  const ContactCoupling &g = m.P->g;
  for (PetscInt i = 0; i < n; ++i) {
    m.isqm[i]          = 1.0 / std::sqrt(S.mass[i]);
    m.free_of[S.dof[i]] = i;
    for (int q = 0; q < 2; ++q)
      if (S.dof[i] == g.dof[q]) gw[i] += g.w[q] * m.isqm[i];
  }
  m.gamma.assign(n, 0.0);
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal *phi = &B.Phi[(size_t)k * n];
    PetscReal        c   = 0;
    for (PetscInt i = 0; i < n; ++i) c += phi[i] * gw[i];
    m.gamma[k] = c;
  }
  m.weights.clear();
  m.have_modal = m.have_step = m.phys_valid = false;
  PetscFunctionReturn(0);
}

PetscErrorCode TSSetFromOptions_Modal(TS ts, PetscOptionItems *PetscOptionsObject)
{
  ModalTS  &m     = *Data(ts);
  PetscInt  order = m.order;
  PetscBool flg;

  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Modal integrator (beamimpact): exact beam flow in its modes, contact force by splitting");
  PetscCall(PetscOptionsInt("-ts_modal_order", "Order: 2 (force linear over the step, trapezoidal collocation) or 4 (force quadratic, Lobatto collocation at 0, h/2, h); the beam's modes are exact for the force", "TSModal", order, &order, &flg));
  PetscOptionsHeadEnd();
  PetscCheck(order == 2 || order == 4, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_OUTOFRANGE, "-ts_modal_order %" PetscInt_FMT " is not allowed: use 2 or 4", order);
  if (order != m.order) m.weights.clear();
  m.order = order;
  PetscFunctionReturn(0);
}

PetscErrorCode TSView_Modal(TS ts, PetscViewer viewer)
{
  const ModalTS &m = *Data(ts);
  PetscBool      ascii;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii)
    PetscCall(PetscViewerASCIIPrintf(viewer, "  Modal (beamimpact): exact beam flow in %" PetscInt_FMT " modes, contact force by %s collocation (order %" PetscInt_FMT "); %" PetscInt_FMT " projections, %" PetscInt_FMT " syncs of the physical state, %" PetscInt_FMT " unconverged force solves\n",
                                     m.n, m.order == 2 ? "trapezoidal" : "3-point Lobatto", m.order, m.projections, m.syncs, m.newton_fail));
  PetscFunctionReturn(0);
}

PetscErrorCode TSCreate_Modal(TS ts)
{
  PetscFunctionBeginUser;
  ts->ops->reset          = TSReset_Modal;
  ts->ops->destroy        = TSDestroy_Modal;
  ts->ops->view           = TSView_Modal;
  ts->ops->setup          = TSSetUp_Modal;
  ts->ops->setfromoptions = TSSetFromOptions_Modal;
  ts->ops->step           = TSStep_Modal;
  ts->ops->rollback       = TSRollBack_Modal;
  ts->usessnes            = PETSC_FALSE;
  ts->default_adapt_type  = TSADAPTNONE;
  ts->data                = new ModalTS();
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalSyncSolution_C", SyncSolution_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalCompression_C", Compression_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalDissipationRate_C", DissipationRate_Modal));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TSModalRegister()
{
  PetscFunctionBeginUser;
  PetscCall(TSRegister(TSMODAL, TSCreate_Modal));
  PetscFunctionReturn(0);
}

bool TSModalIsType(const char *type) { return type && !std::strcmp(type, TSMODAL); }

PetscErrorCode TSModalSyncSolution(TS ts)
{
  PetscErrorCode (*f)(TS) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalSyncSolution_C", &f));
  if (f) PetscCall((*f)(ts));
  PetscFunctionReturn(0);
}

PetscErrorCode TSModalCompression(TS ts, PetscReal *c, PetscReal *cdot, PetscBool *done)
{
  PetscErrorCode (*f)(TS, PetscReal *, PetscReal *) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalCompression_C", &f));
  *done = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(ts, c, cdot));
  PetscFunctionReturn(0);
}

PetscErrorCode TSModalDissipationRate(TS ts, PetscReal *rate, PetscReal *rate_dot, PetscBool *done)
{
  PetscErrorCode (*f)(TS, PetscReal *, PetscReal *) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalDissipationRate_C", &f));
  *done = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(ts, rate, rate_dot));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

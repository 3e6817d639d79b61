// The modal integrator as the PETSc TS type "modal". See ts_modal.hpp for the method, the
// state it keeps and what each step costs.
#include "solvers/ts_modal.hpp"

#include "solvers/beam_modes.hpp"
#include "solvers/ts_problem.hpp"
#include "model/contact.hpp"

#include <petsc/private/tsimpl.h>
#include <petscblaslapack.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <array>
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
    PetscReal d[3]   = {0, 0, 0}; // z^(i), z^(i+1), z^(i+2) at 0, rolling
    PetscReal fact_m = 1;
    for (int i = 2; i <= m; ++i) fact_m *= i;
    PetscReal z = 0, v = 0, ti = 1; // ti = t^i / i!
    for (int i = 0; i < 400; ++i) {
      d[2]               = -2 * sg * d[1] - w * w * d[0] + (i == m ? fact_m : 0.0);
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
  PetscReal p[5] = {0, 0, 0, 0,
                    0}; // P(s) = sum p_i s^i: w^2 p_i + 2 sigma (i+1) p_{i+1} + (i+2)(i+1) p_{i+2} = [i == m]
  for (int i = m; i >= 0; --i)
    p[i] = ((i == m ? 1.0 : 0.0) - 2 * sg * (i + 1) * p[i + 1] - (i + 2) * (i + 1) * p[i + 2]) / (w * w);
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

// 1/i!, i < 24.
const std::array<PetscReal, 24> kInvFact = [] {
  std::array<PetscReal, 24> f;
  f[0] = 1.0;
  for (int i = 1; i < 24; ++i) f[i] = f[i - 1] / i;
  return f;
}();

// An undamped mode over t, x = w t: cos x, sin x and the functions of the forced responses
// from rest, sinc = sin x / x, f2 = (1 - cos x)/x^2, f3 = (x - sin x)/x^3, g4 = (x^2 - 2(1 - cos x))/x^4,
// from cos x, sin x and omc = 1 - cos x (given without cancellation), by their series below
// x = 0.5 (no cancellation; exact for a rigid mode, x = 0).
struct UndampedForced {
  PetscReal c, sn, sinc, f2, f3, g4;
  UndampedForced(PetscReal x, PetscReal cx, PetscReal sx, PetscReal omc) : c(cx), sn(sx)
  {
    const PetscReal x2 = x * x;
    if (x < 0.5) {
      // sum_j (-1)^j x^(2j) / (2j + p)!, p = 1, 2, 3, 4; 9 terms: x^18/18! < 1e-21
      // (stopped once a term is below 1e-20 of the sum's leading term: it no longer changes it)
      PetscReal s1 = 0, s2 = 0, s3 = 0, s4 = 0, xp = 1;
      for (int j = 0; j < 9; ++j, xp *= -x2) {
        s1 += xp * kInvFact[2 * j + 1];
        s2 += xp * kInvFact[2 * j + 2];
        s3 += xp * kInvFact[2 * j + 3];
        s4 += xp * kInvFact[2 * j + 4];
        if (std::abs(xp) * kInvFact[2 * j + 1] < 1e-20) break;
      }
      sinc = s1, f2 = s2, f3 = s3, g4 = 2 * s4;
    } else {
      const PetscReal ix = 1 / x, ix2 = ix * ix;
      sinc = sn * ix;
      f2   = omc * ix2;
      f3   = (x - sn) * (ix2 * ix);
      g4   = (x2 - 2 * omc) * (ix2 * ix2);
    }
  }
};

// cos, sin and 1 - cos of 2y from cos y and sin y (no cancellation: 1 - cos 2y = 2 sin^2 y).
inline void TrigDoubled(PetscReal cy, PetscReal sy, PetscReal *c, PetscReal *s, PetscReal *omc)
{
  *omc = 2 * sy * sy;
  *c   = 1 - *omc;
  *s   = 2 * sy * cy;
}
// 1 - cos y from cos y and sin y without cancellation.
inline PetscReal OneMinusCos(PetscReal cy, PetscReal sy) { return cy > 0 ? sy * sy / (1 + cy) : 1 - cy; }

// Everything a step of length h needs, per mode (arrays over the modes k), cached by h. The
// force over the step is the polynomial through its values at the nodes tau_j h (order 2: 0,
// 1; order 4: 0, 1/2, 1), F(s) = sum_j F_j l_j(s/h). The coupling gamma_k is folded in where
// the step uses it with a weight.
struct StepWeights {
  PetscReal              h    = 0;
  unsigned long          used = 0;        // last use (least recently used slot is refilled)
  std::vector<PetscReal> a0, a1, a2, a3;  // the exact free propagator over h: [z, zd] -> [a0 z + a1 zd, a2 z + a3 zd]
  std::vector<PetscReal> gm0, gm1;        // gamma times its first row over h/2 (order 4)
  std::vector<PetscReal> g0, g1;          // gamma times its first row over h
  std::vector<PetscReal> R[3], V[3];      // gamma times mode k's displacement and velocity at h forced by l_j
  PetscReal              W[3][3] = {{0}}; // dc(tau_i h) / dF_j (beam and ball), i >= 1
  PetscReal              by[3] = {0}, bv[3] = {0}; // ball's displacement and velocity at h per unit F_j (times m_b)
};
constexpr size_t kWeightsCache = 8; // the nominal step and a few event steps

// The parts of a step's weights that do not depend on the contact point (gamma_k), per mode, for
// one step length: the free propagator, the first row over h/2 (order 4), the forced responses
// at h (R, V) and the forced displacements W sums over the modes (an undamped mode: at node
// tau_i h of the basis function l_j, X[3 (i - 1) + j]; a damped one: of the monomial q,
// X[2 q + i - 1]). Kept for the nominal step across the points on one basis (WeightsOf): the
// next point folds its gamma_k in, O(modes), without a sincos per mode; the same numbers.
struct StepShapes {
  PetscReal              h     = -1; // s (-1: none kept)
  PetscInt               order = 0;
  std::vector<PetscReal> a0, a1, a2, a3, m0, m1;
  std::vector<PetscReal> R[3], V[3], X[6];
};

// The expansion of samples split by the modes' parity under the structure's mirror (ModalMirrorOf):
// where every kept mode is even or odd (phi(R r) = +-s_r phi(r) to kParityTolerance of its largest
// entry: a mirror-split basis, section 12), a dof and its image share their rows, y(r) = E + O and
// y(R r) = s_r (E - O) with E, O the even and odd modes' sums on r alone: half the products. Built
// once per basis and range of free dofs [i0, i1) (node-aligned, so a pair lies in it whole).
constexpr PetscReal kParityTolerance = 1e-12;
struct ParityPlan {
  const BeamModes       *modes = nullptr;
  PetscInt               i0 = -1, i1 = -1;
  bool                   ok = false;
  std::vector<PetscInt>  rep, image;       // free dofs r <= R r in [i0, i1), and R r
  std::vector<int>       sign;             // s_r
  std::vector<PetscInt>  even, odd, mixed; // the kept modes of each parity, and of neither (a refined pair's)
  std::vector<PetscReal> Pe, Po, Pm;       // Phi on the rows rep: the even and the odd modes; on [i0, i1): the mixed
};

void ParityPlanBuild(const BeamModes &modes, PetscInt i0, PetscInt i1, ParityPlan *p)
{
  *p       = ParityPlan();
  p->modes = &modes, p->i0 = i0, p->i1 = i1;
  ModalMirror mir;
  if (!modes.B.mirrored || !ModalMirrorOf(modes.S, &mir)) return;
  const PetscInt   n = modes.S.n, k = modes.Count();
  const PetscReal *Phi = modes.B.Phi.data();
  for (PetscInt j = 0; j < k; ++j) { // each mode's parity, over every dof
    const PetscReal *phi = Phi + (size_t)j * n;
    PetscReal        e = 0, o = 0, big = 0;
    for (PetscInt r = 0; r < n; ++r) {
      const PetscReal im = mir.sign[r] * phi[mir.to[r]];
      e = std::max(e, std::abs(phi[r] - im)), o = std::max(o, std::abs(phi[r] + im)),
      big = std::max(big, std::abs(phi[r]));
    }
    if (e <= kParityTolerance * big) p->even.push_back(j);
    else if (o <= kParityTolerance * big) p->odd.push_back(j);
    else p->mixed.push_back(j);
  }
  for (PetscInt r = i0; r < i1; ++r) {
    const PetscInt t = mir.to[r];
    if (t < i0 || t >= i1) return;
    if (r <= t) p->rep.push_back(r), p->image.push_back(t), p->sign.push_back(mir.sign[r]);
  }
  const size_t nr = p->rep.size();
  for (auto [cols, P] : {std::make_pair(&p->even, &p->Pe), std::make_pair(&p->odd, &p->Po)}) {
    P->resize(nr * cols->size());
    for (size_t c = 0; c < cols->size(); ++c)
      for (size_t q = 0; q < nr; ++q) (*P)[q + c * nr] = Phi[(size_t)(*cols)[c] * n + p->rep[q]];
  }
  const size_t ni = (size_t)(i1 - i0);
  p->Pm.resize(ni * p->mixed.size());
  for (size_t c = 0; c < p->mixed.size(); ++c)
    std::copy_n(Phi + (size_t)p->mixed[c] * n + i0, ni, p->Pm.begin() + c * ni);
  p->ok = 4 * p->mixed.size() < (size_t)k; // else the whole product is as quick
}

// The plan for the samples' rows, built when the basis or the rows change (-info says which).
PetscErrorCode ParityPlanFor(const BeamModes &modes, PetscInt i0, PetscInt i1, ParityPlan *p)
{
  PetscFunctionBeginUser;
  if (p->modes == &modes && p->i0 == i0 && p->i1 == i1) PetscFunctionReturn(0);
  ParityPlanBuild(modes, i0, i1, p);
  PetscCall(PetscInfo(NULL, "samples' expansion: %s (%zu even, %zu odd, %zu of neither parity)\n",
                      p->ok ? "by parity under the mirror" : "every mode on every row", p->even.size(), p->odd.size(),
                      p->mixed.size()));
  PetscFunctionReturn(0);
}

// YV (ni x w, column-major, rows [i0, i1)) = Phi W (W: kept modes x w) by the parity plan p.
PetscErrorCode ParityExpand(const ParityPlan &p, PetscInt k, const PetscReal *W, PetscInt w, PetscReal *YV)
{
  const PetscInt                ni = p.i1 - p.i0, nr = (PetscInt)p.rep.size();
  const PetscScalar             one = 1, zero = 0;
  std::vector<PetscReal>        part[2];
  const std::vector<PetscInt>  *cols[2] = {&p.even, &p.odd};
  const std::vector<PetscReal> *P[2]    = {&p.Pe, &p.Po};

  PetscFunctionBeginUser;
  for (int b = 0; b < 2; ++b) { // E and O on the representatives
    const PetscInt         kb = (PetscInt)cols[b]->size();
    std::vector<PetscReal> Wb((size_t)kb * w);
    for (PetscInt c = 0; c < w; ++c)
      for (PetscInt q = 0; q < kb; ++q) Wb[q + (size_t)c * kb] = W[(*cols[b])[q] + (size_t)c * k];
    part[b].assign((size_t)nr * w, 0.0);
    if (kb == 0 || nr == 0) continue;
    PetscBLASInt bn, bw, bk;
    PetscCall(PetscBLASIntCast(nr, &bn));
    PetscCall(PetscBLASIntCast(w, &bw));
    PetscCall(PetscBLASIntCast(kb, &bk));
    PetscCallBLAS("BLASgemm", BLASgemm_("N", "N", &bn, &bw, &bk, &one, P[b]->data(), &bn, Wb.data(), &bk, &zero,
                                        part[b].data(), &bn));
  }
  for (PetscInt c = 0; c < w; ++c)
    for (PetscInt q = 0; q < nr; ++q) {
      const PetscReal E = part[0][q + (size_t)c * nr], O = part[1][q + (size_t)c * nr];
      YV[p.rep[q] - p.i0 + (size_t)c * ni]   = E + O;
      YV[p.image[q] - p.i0 + (size_t)c * ni] = p.sign[q] * (E - O);
    }
  const PetscInt km = (PetscInt)p.mixed.size();
  if (km > 0 && ni > 0) { // the modes of neither parity on every row, added
    std::vector<PetscReal> Wm((size_t)km * w);
    for (PetscInt c = 0; c < w; ++c)
      for (PetscInt q = 0; q < km; ++q) Wm[q + (size_t)c * km] = W[p.mixed[q] + (size_t)c * k];
    PetscBLASInt bn, bw, bk;
    PetscCall(PetscBLASIntCast(ni, &bn));
    PetscCall(PetscBLASIntCast(w, &bw));
    PetscCall(PetscBLASIntCast(km, &bk));
    PetscCallBLAS("BLASgemm",
                  BLASgemm_("N", "N", &bn, &bw, &bk, &one, p.Pm.data(), &bn, Wm.data(), &bk, &one, YV, &bn));
  }
  PetscFunctionReturn(0);
}

struct ModalTS {
  PetscInt order = 4;
  // Set up once (TSSetUp_Modal).
  TSProblem                       *P = nullptr;
  std::shared_ptr<const BeamModes> modes;
  PetscInt                         n    = 0;            // modes kept (all: the free beam dofs)
  PetscInt                         nd   = 0;            // free beam dofs (the rows of Phi)
  const ModalCorrection           *corr = nullptr;      // the static correction at the point (Gr = 0: every mode kept)
  PetscReal                        Gr   = 0;            // m/N: its residual flexibility
  std::vector<PetscReal>           gamma, omega, sigma; // per mode
  std::vector<PetscReal>           isqm;                // 1/sqrt(m) per free dof
  std::vector<PetscInt>            free_of;             // beam dof -> free dof (-1: held)
  std::vector<StepWeights>         weights;             // at most kWeightsCache slots
  unsigned long                    uses = 0;
  StepShapes                       shapes;              // the nominal step's, across points
  bool                             keep_shapes = false; // the point's first weights computed: keep their shapes
  // The modal state and the start of the last step (rollback); the compression c = y_b -
  // gamma . z and its rate at the current state (c_valid) and at the start of the last step.
  std::vector<PetscReal> z, zd, z0, zd0;
  PetscReal              yb = 0, vb = 0, yb0 = 0, vb0 = 0;
  PetscReal              c = 0, cd = 0, c0 = 0,
            cd0   = 0; // the kept modes' part y_b - gamma . z (CompressionNow adds the static correction)
  bool c_valid    = false;
  bool have_modal = false, have_step = false;
  // The physical vector ts->vec_sol: whether it holds the modal state (phys_valid), the
  // object and state it had when last written or projected, and a copy of that content.
  bool                   phys_valid = false;
  PetscObjectId          vec_id     = 0;
  PetscObjectState       vec_state  = 0;
  Vec                    Xc = nullptr, all = nullptr;
  VecScatter             gather = nullptr;
  std::vector<PetscReal> sy, sv; // Project's scaled state
  ParityPlan             parity; // Expand's, for the current basis and range
  PetscInt               projections = 0, syncs = 0, kept = 0, newton_fail = 0, weight_sets = 0;
};

ModalTS *Data(TS ts) { return static_cast<ModalTS *>(ts->data); }

// Nodes tau_j and the Lagrange basis l_j(x) = sum_m L[j][m] x^m of the force polynomial.
PetscInt        StageCount(PetscInt order) { return order == 2 ? 2 : 3; }
const PetscReal kTau2[2] = {0, 1}, kTau4[3] = {0, 0.5, 1};
const PetscReal kL2[2][3] = {{1, -1, 0}, {0, 1, 0}};
const PetscReal kL4[3][3] = {{1, -3, 2}, {0, 4, -4}, {0, -1, 2}};

// The ball's share of a step's weights (y_b'' = -F/m_b; int_0^t (t - u) u^q du = t^(q+2)/((q+1)(q+2)),
// int_0^t u^q du = t^(q+1)/(q+1)), added to the modes' Wacc, which is then W.W.
template <PetscInt s>
void WeightsBall(const ModalTS &m, PetscReal h, const PetscReal hq[3], PetscReal Wacc[3][3], StepWeights &W)
{
  const PetscReal *tau = s == 2 ? kTau2 : kTau4;
  auto             Lc  = [](PetscInt j, PetscInt q) { return s == 2 ? kL2[j][q] : kL4[j][q]; };
  const PetscReal  mb  = m.P->ball.mass;
  for (PetscInt i = 0; i < 3; ++i) W.by[i] = W.bv[i] = 0;
  for (PetscInt q = 0; q < s; ++q) {
    for (PetscInt j = 0; j < s; ++j) {
      W.by[j] += Lc(j, q) * std::pow(h, (PetscReal)q + 2) / ((q + 1) * (q + 2)) / hq[q];
      W.bv[j] += Lc(j, q) * std::pow(h, (PetscReal)q + 1) / (q + 1) / hq[q];
      for (PetscInt i = 1; i < s; ++i)
        Wacc[i][j] += Lc(j, q) * std::pow(tau[i] * h, (PetscReal)q + 2) / ((q + 1) * (q + 2)) / hq[q] / mb;
    }
  }
  for (PetscInt i = 0; i < 3; ++i)
    for (PetscInt j = 0; j < 3; ++j) W.W[i][j] = Wacc[i][j];
}

PetscInt folds = 0; // steps whose weights were folded from an earlier point's shapes (TSModalFoldCount)

// WeightsCompute's mode k when damped (sigma_k > 0): its weights from ModalModeAt and ModeForced
// (Wacc the ball's accumulated sums; the same operations in the same order as inline).
template <PetscInt s>
inline void DampedModeWeights(PetscInt k, PetscReal w, PetscReal sg, PetscReal gk, PetscReal g2, PetscReal h,
                              const PetscReal *hq, PetscReal Wacc[3][3], StepWeights &W, StepShapes *Sh)
{
  const PetscReal *tau = s == 2 ? kTau2 : kTau4;
  auto             Lc  = [](PetscInt j, PetscInt q) { return s == 2 ? kL2[j][q] : kL4[j][q]; };
  ModalModeAt(w, sg, 1.0, 0.0, h, &W.a0[k], &W.a2[k]);
  ModalModeAt(w, sg, 0.0, 1.0, h, &W.a1[k], &W.a3[k]);
  W.g0[k] = gk * W.a0[k], W.g1[k] = gk * W.a1[k];
  if (Sh) Sh->a0[k] = W.a0[k], Sh->a1[k] = W.a1[k], Sh->a2[k] = W.a2[k], Sh->a3[k] = W.a3[k];
  if (s == 3) {
    PetscReal dummy, am0, am1;
    ModalModeAt(w, sg, 1.0, 0.0, 0.5 * h, &am0, &dummy);
    ModalModeAt(w, sg, 0.0, 1.0, 0.5 * h, &am1, &dummy);
    W.gm0[k] = gk * am0, W.gm1[k] = gk * am1;
    if (Sh) Sh->m0[k] = am0, Sh->m1[k] = am1;
  }
  PetscReal Rk[3] = {0, 0, 0}, Vk[3] = {0, 0, 0};
  for (PetscInt q = 0; q < s; ++q) { // the monomial (s/h)^q
    PetscReal rz, rv;
    ModeForced(w, sg, (int)q, h, &rz, &rv);
    for (PetscInt j = 0; j < s; ++j) {
      Rk[j] += Lc(j, q) * rz / hq[q];
      Vk[j] += Lc(j, q) * rv / hq[q];
    }
    for (PetscInt i = 1; i < s; ++i) {
      PetscReal rzi = rz, rvi;
      if (tau[i] != 1.0) ModeForced(w, sg, (int)q, tau[i] * h, &rzi, &rvi);
      for (PetscInt j = 0; j < s; ++j) Wacc[i][j] += g2 * Lc(j, q) * rzi / hq[q];
      if (Sh) Sh->X[2 * q + i - 1][k] = rzi;
    }
  }
  for (PetscInt j = 0; j < s; ++j) W.R[j][k] = gk * Rk[j], W.V[j][k] = gk * Vk[j];
  if (Sh)
    for (PetscInt j = 0; j < s; ++j) Sh->R[j][k] = Rk[j], Sh->V[j][k] = Vk[j];
}

// The weights of a step of length h into W (its arrays sized already), for s = StageCount
// nodes (a template: the small loops over nodes and powers unroll into registers); with Sh (its
// arrays sized) also their parts free of gamma_k (StepShapes, for WeightsFold).
template <PetscInt s>
void WeightsCompute(const ModalTS &m, PetscReal h, StepWeights &W, StepShapes *Sh)
{
  const PetscInt   n          = m.n;
  const PetscReal *tau        = s == 2 ? kTau2 : kTau4;
  auto             Lc         = [](PetscInt j, PetscInt q) { return s == 2 ? kL2[j][q] : kL4[j][q]; };
  PetscReal        coef[3][3] = {{0}}; // l_j(s/h) = sum_q coef[j][q] s^q
  PetscReal        hq[3]      = {1, h, h * h};
  PetscReal        Wacc[3][3] = {{0}}; // W.W, accumulated here (not through memory the stores below may alias)
  W.h                         = h;
  for (PetscInt j = 0; j < s; ++j)
    for (PetscInt q = 0; q < s; ++q) coef[j][q] = Lc(j, q) / hq[q];
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal w = m.omega[k], sg = m.sigma[k], gk = m.gamma[k], g2 = gk * gk;
    if (sg == 0.0) { // undamped (rigid modes included): closed forms in x = w t, one sincos per mode
      // The trigonometric functions at the last node (h) and, for order 4, at h/2, from one sincos.
      PetscReal cx[3], sx[3], omc[3];
      if (s == 3) {
        const PetscReal y = 0.5 * w * h, cy = std::cos(y), sy = std::sin(y);
        cx[1] = cy, sx[1] = sy, omc[1] = OneMinusCos(cy, sy);
        TrigDoubled(cy, sy, &cx[2], &sx[2], &omc[2]);
      } else {
        const PetscReal y = 0.5 * w * h, cy = std::cos(y), sy = std::sin(y);
        TrigDoubled(cy, sy, &cx[1], &sx[1], &omc[1]);
      }
      for (PetscInt i = 1; i < s; ++i) {
        const PetscReal t = tau[i] * h;
        UndampedForced  u(w * t, cx[i], sx[i], omc[i]);
        const PetscReal rz[3] = {t * t * u.f2, t * t * t * u.f3, t * t * t * t * u.g4},
                        rv[3] = {t * u.sinc, t * t * u.f2, 2 * t * t * t * u.f3};
        if (i == s - 1) {
          W.a0[k] = u.c, W.a1[k] = t * u.sinc, W.a2[k] = -w * u.sn, W.a3[k] = u.c;
          W.g0[k] = gk * W.a0[k], W.g1[k] = gk * W.a1[k];
        } else {
          W.gm0[k] = gk * u.c, W.gm1[k] = gk * (t * u.sinc);
          if (Sh) Sh->m0[k] = u.c, Sh->m1[k] = t * u.sinc;
        }
        for (PetscInt j = 0; j < s; ++j) {
          PetscReal zz = 0, v = 0;
          for (PetscInt q = 0; q < s; ++q) {
            zz += coef[j][q] * rz[q];
            v += coef[j][q] * rv[q];
          }
          Wacc[i][j] += g2 * zz;
          if (Sh) Sh->X[3 * (i - 1) + j][k] = zz;
          if (i == s - 1) {
            W.R[j][k] = gk * zz;
            W.V[j][k] = gk * v;
            if (Sh) Sh->R[j][k] = zz, Sh->V[j][k] = v;
          }
        }
      }
      if (Sh) Sh->a0[k] = W.a0[k], Sh->a1[k] = W.a1[k], Sh->a2[k] = W.a2[k], Sh->a3[k] = W.a3[k];
      continue;
    }
    DampedModeWeights<s>(k, w, sg, gk, g2, h, hq, Wacc, W, Sh);
  }
  WeightsBall<s>(m, h, hq, Wacc, W);
}

// The weights of a step of length h from the parts of it kept free of gamma_k (Sh, computed by
// WeightsCompute for the same basis, order and h): gamma_k folded in with the same operations in
// the same order, so the same numbers, O(modes) without a sincos.
template <PetscInt s>
void WeightsFold(const ModalTS &m, const StepShapes &Sh, StepWeights &W)
{
  const PetscInt  n          = m.n;
  const PetscReal h          = Sh.h;
  auto            Lc         = [](PetscInt j, PetscInt q) { return s == 2 ? kL2[j][q] : kL4[j][q]; };
  PetscReal       hq[3]      = {1, h, h * h};
  PetscReal       Wacc[3][3] = {{0}};
  W.h                        = h;
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal gk = m.gamma[k], g2 = gk * gk;
    W.a0[k] = Sh.a0[k], W.a1[k] = Sh.a1[k], W.a2[k] = Sh.a2[k], W.a3[k] = Sh.a3[k];
    W.g0[k] = gk * W.a0[k], W.g1[k] = gk * W.a1[k];
    if (s == 3) W.gm0[k] = gk * Sh.m0[k], W.gm1[k] = gk * Sh.m1[k];
    if (m.sigma[k] == 0.0) {
      for (PetscInt i = 1; i < s; ++i)
        for (PetscInt j = 0; j < s; ++j) Wacc[i][j] += g2 * Sh.X[3 * (i - 1) + j][k];
    } else {
      for (PetscInt q = 0; q < s; ++q)
        for (PetscInt i = 1; i < s; ++i)
          for (PetscInt j = 0; j < s; ++j) Wacc[i][j] += g2 * Lc(j, q) * Sh.X[2 * q + i - 1][k] / hq[q];
    }
    for (PetscInt j = 0; j < s; ++j) W.R[j][k] = gk * Sh.R[j][k], W.V[j][k] = gk * Sh.V[j][k];
  }
  WeightsBall<s>(m, h, hq, Wacc, W);
}

// The weights of a step of length h: from the cache, else computed into the least recently
// used slot (its arrays reused: no allocation once the cache is full).
const StepWeights &WeightsOf(ModalTS &m, PetscReal h)
{
  ++m.uses;
  for (StepWeights &w : m.weights)
    if (w.h == h) {
      w.used = m.uses;
      return w;
    }
  StepWeights *W;
  if (m.weights.size() < kWeightsCache) {
    m.weights.reserve(kWeightsCache); // no reallocation: references handed out stay valid until refilled
    m.weights.emplace_back();
    W              = &m.weights.back();
    const size_t n = (size_t)m.n;
    for (std::vector<PetscReal> *v : {&W->a0, &W->a1, &W->a2, &W->a3, &W->gm0, &W->gm1, &W->g0, &W->g1})
      v->assign(n, 0.0);
    for (int j = 0; j < 3; ++j) W->R[j].assign(n, 0.0), W->V[j].assign(n, 0.0);
  } else
    W = &*std::min_element(m.weights.begin(), m.weights.end(),
                           [](const StepWeights &a, const StepWeights &b) { return a.used < b.used; });
  // The point's first step (the nominal one): folded from the shapes kept by an earlier point on
  // this basis, else computed and its shapes kept for the next point. Other lengths: computed.
  if (m.shapes.h == h && m.shapes.order == m.order) {
    ++folds;
    if (m.order == 2) WeightsFold<2>(m, m.shapes, *W);
    else WeightsFold<3>(m, m.shapes, *W);
  } else {
    StepShapes *keep = m.keep_shapes ? &m.shapes : nullptr;
    if (keep) {
      keep->h     = h;
      keep->order = m.order;
      for (std::vector<PetscReal> *v : {&keep->a0, &keep->a1, &keep->a2, &keep->a3, &keep->m0, &keep->m1})
        v->assign((size_t)m.n, 0.0);
      for (int j = 0; j < 3; ++j) keep->R[j].assign((size_t)m.n, 0.0), keep->V[j].assign((size_t)m.n, 0.0);
      for (int j = 0; j < 6; ++j) keep->X[j].assign((size_t)m.n, 0.0);
    }
    if (m.order == 2) WeightsCompute<2>(m, h, *W, keep);
    else WeightsCompute<3>(m, h, *W, keep);
  }
  m.keep_shapes = false;
  W->used       = m.uses;
  m.weight_sets++;
  return *W;
}

// c = y_b - gamma . z and its rate, from the modal state.
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

// The compression c = c_m - G_r F(c) with the modes left out (c_m = y_b - gamma . z, the kept
// modes'; docs/model.md §12), by Newton on the scalar equation, and its rate c_m' / (1 + G_r k(c)).
PetscReal StaticallyCorrected(const ModalTS &m, PetscReal cm, PetscReal cmd, PetscReal *cdot)
{
  const TSProblem &P = *m.P;
  PetscReal        c = cm;
  for (int it = 0; it < 50; ++it) {
    const PetscReal r  = c - cm + m.Gr * ContactForce(P.ball, *P.contact, c),
                    dc = r / (1 + m.Gr * ContactStiffness(P.ball, *P.contact, c));
    c -= dc;
    if (!(std::abs(dc) > 1e-15 * std::abs(c))) break;
  }
  if (cdot) *cdot = cmd / (1 + m.Gr * ContactStiffness(P.ball, *P.contact, c));
  return c;
}

// The compression and its rate at the current modal state (cached until the state changes).
PetscReal CompressionNow(ModalTS &m, PetscReal *cdot)
{
  if (!m.c_valid) {
    m.c       = ModalCompression(m, &m.cd);
    m.c_valid = true;
  }
  if (m.Gr > 0) return StaticallyCorrected(m, m.c, m.cd, cdot);
  if (cdot) *cdot = m.cd;
  return m.c;
}

// One step of length h (exponential collocation on the force; see ts_modal.hpp). O(modes),
// one pass over the modes for the free compression at the nodes and one for the update (which
// also gives the compression at the step's end).
// The stage compressions the modes would give without the step's force (c_i at tau_i h).
static void FreeStageCompressions(const ModalTS &m, const StepWeights &W, PetscInt s, PetscReal h, const PetscReal *tau,
                                  PetscReal cfree[3])
{
  const PetscReal *z = m.z.data(), *zd = m.zd.data();
  const PetscInt   n = m.n;
  for (PetscInt i = 1; i < s; ++i) cfree[i] = m.yb + m.vb * tau[i] * h;
  if (s == 3) {
    const PetscReal *gm0 = W.gm0.data(), *gm1 = W.gm1.data(), *g0 = W.g0.data(), *g1 = W.g1.data();
    PetscReal        c1 = cfree[1], c2 = cfree[2];
    for (PetscInt k = 0; k < n; ++k) {
      c1 -= gm0[k] * z[k] + gm1[k] * zd[k];
      c2 -= g0[k] * z[k] + g1[k] * zd[k];
    }
    cfree[1] = c1, cfree[2] = c2;
  } else {
    const PetscReal *g0 = W.g0.data(), *g1 = W.g1.data();
    PetscReal        c1 = cfree[1];
    for (PetscInt k = 0; k < n; ++k) c1 -= g0[k] * z[k] + g1[k] * zd[k];
    cfree[1] = c1;
  }
}

// The stage forces F_i = F(c_i), c_i = cfree_i - sum_j W_ij F_j: Newton on the 1 or 2 unknowns.
static void StageForces(ModalTS &m, const StepWeights &W, PetscInt s, const PetscReal cfree[3], PetscReal F[3])
{
  TSProblem &P = *m.P;
  P.count.func++;
  F[0] = ContactForce(P.ball, *P.contact, CompressionNow(m, nullptr));
  for (PetscInt i = 1; i < s; ++i) F[i] = F[0];
  const PetscInt nu    = s - 1; // unknowns F_1 .. F_{s-1}
  PetscReal      dprev = PETSC_MAX_REAL;
  for (int it = 0; it < 50; ++it) {
    PetscReal r[2], J[2][2], c[3];
    for (PetscInt i = 1; i < s; ++i) {
      c[i] = cfree[i];
      for (PetscInt j = 0; j < s; ++j) c[i] -= W.W[i][j] * F[j];
      if (m.Gr > 0) c[i] -= m.Gr * F[i]; // the modes left out, quasi-statically
      const PetscReal k = ContactStiffness(P.ball, *P.contact, c[i]);
      r[i - 1]          = F[i] - ContactForce(P.ball, *P.contact, c[i]);
      for (PetscInt l = 1; l < s; ++l) J[i - 1][l - 1] = (i == l ? 1.0 + k * m.Gr : 0.0) + k * W.W[i][l];
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

// The modes over the step with the stage forces (none in free flight), and the compression and
// its rate at the end (the ball has moved first).
static void AdvanceModes(ModalTS &m, const StepWeights &W, PetscInt s, bool in, const PetscReal F[3])
{
  PetscReal       *z = m.z.data(), *zd = m.zd.data();
  const PetscInt   n  = m.n;
  const PetscReal *a0 = W.a0.data(), *a1 = W.a1.data(), *a2 = W.a2.data(), *a3 = W.a3.data(), *gamma = m.gamma.data();
  PetscReal        c = m.yb, cd = m.vb;
  if (!in) // free flight of the ball: the beam's modes free
    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal zk = z[k], zdk = zd[k], zn = a0[k] * zk + a1[k] * zdk, zdn = a2[k] * zk + a3[k] * zdk;
      z[k]  = zn;
      zd[k] = zdn;
      c -= gamma[k] * zn;
      cd -= gamma[k] * zdn;
    }
  else if (s == 3) {
    const PetscReal *R0 = W.R[0].data(), *R1 = W.R[1].data(), *R2 = W.R[2].data(), *V0 = W.V[0].data(),
                    *V1 = W.V[1].data(), *V2 = W.V[2].data();
    const PetscReal F0 = F[0], F1 = F[1], F2 = F[2];
    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal zk = z[k], zdk = zd[k];
      const PetscReal zn  = a0[k] * zk + a1[k] * zdk + F0 * R0[k] + F1 * R1[k] + F2 * R2[k],
                      zdn = a2[k] * zk + a3[k] * zdk + F0 * V0[k] + F1 * V1[k] + F2 * V2[k];
      z[k]                = zn;
      zd[k]               = zdn;
      c -= gamma[k] * zn;
      cd -= gamma[k] * zdn;
    }
  } else {
    const PetscReal *R0 = W.R[0].data(), *R1 = W.R[1].data(), *V0 = W.V[0].data(), *V1 = W.V[1].data();
    const PetscReal  F0 = F[0], F1 = F[1];
    for (PetscInt k = 0; k < n; ++k) {
      const PetscReal zk = z[k], zdk = zd[k];
      const PetscReal zn  = a0[k] * zk + a1[k] * zdk + F0 * R0[k] + F1 * R1[k],
                      zdn = a2[k] * zk + a3[k] * zdk + F0 * V0[k] + F1 * V1[k];
      z[k]                = zn;
      zd[k]               = zdn;
      c -= gamma[k] * zn;
      cd -= gamma[k] * zdn;
    }
  }
  m.c       = c;
  m.cd      = cd;
  m.c_valid = true;
}

void StepBy(ModalTS &m, PetscReal h)
{
  TSProblem         &P    = *m.P;
  const bool         in   = P.contact->phase != ContactPhase::Separated;
  const StepWeights &W    = WeightsOf(m, h);
  const PetscInt     s    = StageCount(m.order);
  const PetscReal   *tau  = m.order == 2 ? kTau2 : kTau4;
  PetscReal          F[3] = {0, 0, 0};
  if (in) {
    PetscReal cfree[3] = {0, 0, 0};
    FreeStageCompressions(m, W, s, h, tau, cfree);
    StageForces(m, W, s, cfree, F);
  }
  // The ball first (the compression at the end needs it).
  m.yb += m.vb * h;
  for (PetscInt j = 0; j < s; ++j) {
    m.yb -= F[j] * W.by[j] / P.ball.mass;
    m.vb -= F[j] * W.bv[j] / P.ball.mass;
  }
  AdvanceModes(m, W, s, in, F);
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
  ModalTS        &m  = *Data(ts);
  const TSLayout &L  = m.P->L;
  const PetscInt  nf = L.fields, n = m.nd, nm = m.n; // free dofs, modes
  Vec             X = ts->vec_sol;

  PetscFunctionBeginUser;
  if (!m.gather) PetscCall(VecScatterCreateToAll(X, &m.gather, &m.all));
  PetscCall(VecScatterBegin(m.gather, X, m.all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(m.gather, X, m.all, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar *u;
  m.sy.resize(n);
  m.sv.resize(n);
  PetscReal *sy = m.sy.data(), *sv = m.sv.data();
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
  m.z.assign(nm, 0.0);
  m.zd.assign(nm, 0.0);
  const PetscReal *Phi  = m.modes->B.Phi.data();
  bool             rest = true; // the beam at rest and undeformed (the start of an impact): z = 0, no O(n^2) work
  for (PetscInt i = 0; i < n && rest; ++i) rest = sy[i] == 0.0 && sv[i] == 0.0;
  if (!rest) {
    // Two dot products per mode, four modes at a time (eight independent sums, each in the
    // order of the plain loop: the same values).
    PetscInt k = 0;
    for (; k + 4 <= nm; k += 4) {
      const PetscReal *p0 = Phi + (size_t)k * n, *p1 = p0 + n, *p2 = p1 + n, *p3 = p2 + n;
      PetscReal        a0 = 0, a1 = 0, a2 = 0, a3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
      for (PetscInt i = 0; i < n; ++i) {
        const PetscReal y = sy[i], v = sv[i];
        a0 += p0[i] * y, b0 += p0[i] * v;
        a1 += p1[i] * y, b1 += p1[i] * v;
        a2 += p2[i] * y, b2 += p2[i] * v;
        a3 += p3[i] * y, b3 += p3[i] * v;
      }
      m.z[k] = a0, m.z[k + 1] = a1, m.z[k + 2] = a2, m.z[k + 3] = a3;
      m.zd[k] = b0, m.zd[k + 1] = b1, m.zd[k + 2] = b2, m.zd[k + 3] = b3;
    }
    for (; k < nm; ++k) {
      const PetscReal *phi = Phi + (size_t)k * n;
      PetscReal        a = 0, b = 0;
      for (PetscInt i = 0; i < n; ++i) {
        a += phi[i] * sy[i];
        b += phi[i] * sv[i];
      }
      m.z[k]  = a;
      m.zd[k] = b;
    }
  }
  m.have_modal = true;
  m.c_valid    = false;
  m.projections++;
  // The vector is the truth it was projected from: keep it as the written copy.
  if (!m.Xc) PetscCall(VecDuplicate(X, &m.Xc));
  PetscCall(VecCopy(X, m.Xc));
  PetscCall(PetscObjectGetId((PetscObject)X, &m.vec_id));
  PetscCall(PetscObjectStateGet((PetscObject)X, &m.vec_state));
  m.phys_valid = true;
  PetscFunctionReturn(0);
}

// Whether X differs from the written copy Xc by round-off only: per kind of entry (beam
// displacements, beam velocities, ball), max |X - Xc| <= kRoundOff max |Xc|. The O(n^2)
// round trip of the modal state through the physical one (a free flight of zero length, when
// the window ends at the separation: the driver reads the state, projects it on the modes,
// propagates it by 0 and writes it back) changes the entries by ~ n eps of their kind's
// magnitude; a real change of state is many orders above. Collective, O(N / ranks).
constexpr PetscReal kRoundOff = 1e-11;
PetscErrorCode      SameToRoundOff(const ModalTS &m, Vec X, Vec Xc, bool *same)
{
  const TSLayout    &L = m.P->L;
  const PetscScalar *x, *xc;
  PetscInt           nloc;
  PetscReal          v[6] = {0, 0, 0, 0, 0, 0}; // max |X - Xc| and max |Xc| for the three kinds

  PetscFunctionBeginUser;
  PetscInt nc;
  PetscCall(VecGetLocalSize(X, &nloc));
  PetscCall(VecGetLocalSize(Xc, &nc));
  if (nc != nloc) v[0] = PETSC_INFINITY, nloc = 0; // another layout: not the same
  PetscCall(VecGetArrayRead(X, &x));
  PetscCall(VecGetArrayRead(Xc, &xc));
  const PetscInt nbeam = (L.xe - L.xs) * L.dof; // the owned beam block, then (rank 0) the ball
  for (PetscInt i = 0; i < nloc; ++i) {
    const int kind = i >= nbeam ? 2 : ((i % L.dof) < L.fields ? 0 : 1);
    v[kind]        = std::max(v[kind], (PetscReal)std::abs(x[i] - xc[i]));
    v[3 + kind]    = std::max(v[3 + kind], (PetscReal)std::abs(xc[i]));
  }
  PetscCall(VecRestoreArrayRead(Xc, &xc));
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, v, 6, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)X)));
  *same = true;
  for (int kind = 0; kind < 3; ++kind) *same = *same && v[kind] <= kRoundOff * v[3 + kind];
  PetscFunctionReturn(0);
}

// Makes the modal state authoritative: projects the physical vector if it was replaced or
// written from outside since the modal state last matched it (unless the write changed it
// by round-off only: then the modal state is kept). Collective.
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
    bool same;
    PetscCall(SameToRoundOff(m, X, m.Xc, &same)); // collective
    if (same) {
      m.vec_id    = id;
      m.vec_state = st; // the vector keeps what was written (within round-off of the modal state)
      m.kept++;
      PetscFunctionReturn(0);
    }
  }
  PetscCall(Project(ts));
  PetscFunctionReturn(0);
}

// The owned dofs' range [i0, i1) of free dofs (contiguous: the owned beam dofs [D0, D1)).
void OwnedFree(const ModalTS &m, PetscInt *i0, PetscInt *i1)
{
  const TSLayout &L = m.P->L;
  *i0 = m.nd, *i1 = 0;
  for (PetscInt d = L.D0(); d < L.D1(); ++d)
    if (m.free_of[d] >= 0) {
      *i0 = std::min(*i0, m.free_of[d]);
      *i1 = std::max(*i1, m.free_of[d] + 1);
    }
}

// Writes the modal state into the physical vector (each rank its owned dofs). Collective.
PetscErrorCode Sync(TS ts)
{
  ModalTS     &m = *Data(ts);
  Vec          X = ts->vec_sol;
  TSStateWrite o;

  PetscFunctionBeginUser;
  if (!m.P || !X) PetscFunctionReturn(0); // not set up yet: nothing to write
  const TSLayout &L  = m.P->L;
  const PetscInt  nf = L.fields, n = m.nd, nm = m.n; // free dofs, modes
  PetscCall(Reconcile(ts));
  if (m.phys_valid) PetscFunctionReturn(0);
  PetscInt i0, i1; // the owned beam dofs [D0, D1) are a contiguous range [i0, i1) of free dofs
  OwnedFree(m, &i0, &i1);
  const PetscInt ni = std::max<PetscInt>(i1 - i0, 0);
  m.sy.assign(ni, 0.0);
  m.sv.assign(ni, 0.0);
  PetscReal       *y = m.sy.data(), *v = m.sv.data();
  const PetscReal *Phi = m.modes->B.Phi.data() + i0;
  // y += phi_k z_k over the modes, four at a time (each entry summed in the order of the
  // plain loop over k: the same values).
  PetscInt k = 0;
  for (; k + 4 <= nm; k += 4) {
    const PetscReal *p0 = Phi + (size_t)k * n, *p1 = p0 + n, *p2 = p1 + n, *p3 = p2 + n;
    const PetscReal  z0 = m.z[k], z1 = m.z[k + 1], z2 = m.z[k + 2], z3 = m.z[k + 3];
    const PetscReal  d0 = m.zd[k], d1 = m.zd[k + 1], d2 = m.zd[k + 2], d3 = m.zd[k + 3];
    for (PetscInt i = 0; i < ni; ++i) {
      y[i] = (((y[i] + p0[i] * z0) + p1[i] * z1) + p2[i] * z2) + p3[i] * z3;
      v[i] = (((v[i] + p0[i] * d0) + p1[i] * d1) + p2[i] * d2) + p3[i] * d3;
    }
  }
  for (; k < nm; ++k) {
    const PetscReal *phi = Phi + (size_t)k * n, zk = m.z[k], zdk = m.zd[k];
    for (PetscInt i = 0; i < ni; ++i) {
      y[i] += phi[i] * zk;
      v[i] += phi[i] * zdk;
    }
  }
  if (m.Gr > 0) { // the modes left out, quasi-statically: their static shape under the force (their velocity left out)
    const PetscReal F = ContactForce(m.P->ball, *m.P->contact, CompressionNow(m, nullptr));
    if (F != 0.0)
      for (PetscInt i = 0; i < ni; ++i) y[i] += m.corr->ur[i0 + i] * F / m.isqm[i0 + i];
  }
  PetscCall(TSStateWriteBegin(L, X, &o));
  for (PetscInt d = L.D0(); d < L.D1(); ++d) {
    const PetscInt i = m.free_of[d], kk = (d / nf) * L.dof + d % nf;
    o.beam[kk]      = i < 0 ? 0.0 : m.isqm[i] * y[i - i0];
    o.beam[kk + nf] = i < 0 ? 0.0 : m.isqm[i] * v[i - i0];
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

PetscErrorCode Expand_Modal(TS ts, const PetscReal *Z, const PetscReal *F, PetscInt count, PetscInt e0, PetscInt e1,
                            PetscReal *y, PetscReal *v)
{
  ModalTS &m  = *Data(ts);
  PetscInt i0 = m.nd, i1 = 0; // the free dofs of [e0, e1): contiguous

  PetscFunctionBeginUser;
  for (PetscInt d = e0; d < e1; ++d)
    if (m.free_of[d] >= 0) i0 = std::min(i0, m.free_of[d]), i1 = std::max(i1, m.free_of[d] + 1);
  const PetscInt n = m.nd, ni = std::max<PetscInt>(i1 - i0, 0), ne = e1 - e0;
  // [Y V] = Phi [Z Zd] in one product (the modes read once): Z holds the rates' columns after the amplitudes'.
  std::vector<PetscReal> YV((size_t)ni * 2 * count);
  PetscReal             *Y = YV.data(), *V = Y + (size_t)ni * count;
  if (ni > 0 && count > 0) PetscCall(ParityPlanFor(*m.modes, i0, i1, &m.parity));
  if (ni > 0 && count > 0 && m.parity.ok) PetscCall(ParityExpand(m.parity, m.n, Z, 2 * count, Y));
  else if (ni > 0 && count > 0) {
    PetscBLASInt      bi, bc, bk, bn;
    const PetscScalar one = 1, zero = 0;
    PetscCall(PetscBLASIntCast(ni, &bi));
    PetscCall(PetscBLASIntCast(2 * count, &bc));
    PetscCall(PetscBLASIntCast(m.n, &bk));
    PetscCall(PetscBLASIntCast(n, &bn));
    const PetscReal *Phi = m.modes->B.Phi.data() + i0;
    PetscCallBLAS("BLASgemm", BLASgemm_("N", "N", &bi, &bc, &bk, &one, Phi, &bn, Z, &bk, &zero, Y, &bi));
  }
  for (PetscInt s = 0; s < count; ++s) {
    PetscReal *ys = Y + (size_t)s * ni;
    if (F[s] != 0.0) // the modes left out, quasi-statically (their velocity left out), as Sync
      for (PetscInt i = 0; i < ni; ++i) ys[i] += m.corr->ur[i0 + i] * F[s] / m.isqm[i0 + i];
    for (PetscInt d = e0; d < e1; ++d) {
      const PetscInt i = m.free_of[d];
      const size_t   o = (size_t)s * ne + d - e0;
      y[o]             = i < 0 ? 0.0 : m.isqm[i] * ys[i - i0];
      v[o]             = i < 0 ? 0.0 : m.isqm[i] * V[(size_t)s * ni + i - i0];
    }
  }
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------- TS methods

PetscErrorCode TSStep_Modal(TS ts)
{
  ModalTS        &m = *Data(ts);
  const PetscReal h = ts->time_step;

  PetscFunctionBeginUser;
  PetscCall(Reconcile(ts));
  m.z0.assign(m.z.begin(), m.z.end()); // no allocation after the first step
  m.zd0.assign(m.zd.begin(), m.zd.end());
  m.yb0 = m.yb;
  m.vb0 = m.vb;
  CompressionNow(m, nullptr); // m.c, m.cd valid: the kept modes' part (rolled back as it is)
  m.c0        = m.c;
  m.cd0       = m.cd;
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
  PetscCheck(m.have_step, PetscObjectComm((PetscObject)ts), PETSC_ERR_ORDER,
             "TS modal: no completed step to roll back");
  m.z.swap(m.z0); // the step's end is not needed again
  m.zd.swap(m.zd0);
  m.yb         = m.yb0;
  m.vb         = m.vb0;
  m.c          = m.c0;
  m.cd         = m.cd0;
  m.c_valid    = true;
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
  *c = CompressionNow(*Data(ts), cdot);
  PetscFunctionReturn(0);
}

PetscErrorCode GetState_Modal(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb,
                              PetscReal *vb)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  PetscCall(Reconcile(ts));
  z->assign(m.z.begin(), m.z.end());
  zd->assign(m.zd.begin(), m.zd.end());
  *yb = m.yb;
  *vb = m.vb;
  PetscFunctionReturn(0);
}

// GetState_Modal's state and the force on the static shape of the modes left out (0: none).
PetscErrorCode Sample_Modal(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb, PetscReal *vb,
                            PetscReal *F)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  PetscCall(GetState_Modal(ts, z, zd, yb, vb));
  *F = m.Gr > 0 ? ContactForce(m.P->ball, *m.P->contact, CompressionNow(m, nullptr)) : 0.0;
  PetscFunctionReturn(0);
}

// The modal state when the physical vector does not hold it and would be its expansion alone:
// not written since the last step or modal state set (writing it is O(n k)), and no static shape
// of the modes left out in it (every mode kept, or no contact force). *done false otherwise.
PetscErrorCode UnwrittenState_Modal(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb,
                                    PetscReal *vb, PetscBool *done)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  *done = PETSC_FALSE;
  if (!m.P || !ts->vec_sol) PetscFunctionReturn(0);
  PetscCall(Reconcile(ts)); // an outside write is projected (then the vector holds the state)
  if (m.phys_valid) PetscFunctionReturn(0);
  if (m.Gr > 0 && ContactForce(m.P->ball, *m.P->contact, CompressionNow(m, nullptr)) != 0.0) PetscFunctionReturn(0);
  z->assign(m.z.begin(), m.z.end());
  zd->assign(m.zd.begin(), m.zd.end());
  *yb   = m.yb;
  *vb   = m.vb;
  *done = PETSC_TRUE;
  PetscFunctionReturn(0);
}

// The modal state replaced; the physical vector left as it is, marked stale (written from the
// modes at its next read) and its object state recorded, so that Reconcile does not take it
// for an outside write and project it back.
PetscErrorCode SetState_Modal(TS ts, const std::vector<PetscReal> &z, const std::vector<PetscReal> &zd, PetscReal yb,
                              PetscReal vb)
{
  ModalTS &m = *Data(ts);
  Vec      X = ts->vec_sol;

  PetscFunctionBeginUser;
  PetscCheck(m.P && X && (PetscInt)z.size() == m.n && (PetscInt)zd.size() == m.n, PetscObjectComm((PetscObject)ts),
             PETSC_ERR_ARG_SIZ,
             "TS modal: a modal state of %zu modes set on a TS with %" PetscInt_FMT " (not set up, or another basis)",
             z.size(), m.n);
  m.z.assign(z.begin(), z.end());
  m.zd.assign(zd.begin(), zd.end());
  m.yb         = yb;
  m.vb         = vb;
  m.have_modal = true;
  m.have_step  = false;
  m.c_valid    = false;
  m.phys_valid = false;
  PetscCall(PetscObjectGetId((PetscObject)X, &m.vec_id));
  PetscCall(PetscObjectStateGet((PetscObject)X, &m.vec_state));
  PetscFunctionReturn(0);
}

PetscErrorCode DissipationRate_Modal(TS ts, PetscReal *rate, PetscReal *rate_dot)
{
  ModalTS &m = *Data(ts);

  PetscFunctionBeginUser;
  PetscCall(Reconcile(ts));
  const TSProblem &P = *m.P;
  const PetscReal  F = ContactForce(P.ball, *P.contact, CompressionNow(m, nullptr));
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
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalNewPoint_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalGetState_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalSetState_C", nullptr));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalGetUnwrittenState_C", nullptr));
  PetscFunctionReturn(0);
}

// What depends on the point (and on the structure, from the shared cache of the modes): the
// modes of -modal_modes / -modal_tolerance for this beam and ball, gamma_k at the contact point,
// the static correction there (cached per point in the modes), the step weights (gamma and the
// ball's mass are folded in: dropped, their arrays kept when the modes kept are as many), the
// modal state (projected from the initial state at the first step). The TS's own objects (the
// gather of the physical state, the written copy) are the structure's and stay. Collective.
PetscErrorCode PointSetUp(TS ts)
{
  ModalTS          &m   = *Data(ts);
  const BeamSystem &sys = *m.P->sys;
  std::string       why;

  PetscFunctionBeginUser;
  PetscCheck(BeamModesAvailable(sys, &why), PetscObjectComm((PetscObject)ts), PETSC_ERR_SUP,
             "-ts_type modal needs the beam's modes: %s; use another -ts_type", why.c_str());
  const BeamModes *before = m.modes.get(); // alive until replaced: another basis has another address
  {
    // The run's truncation (run/impact_problem.cpp, read once): T and the force's start from the
    // approach, the load g (-modal_weight share), the run's cost line and progress (0 in a sweep).
    PetscCall(BeamModesShared(PetscObjectComm((PetscObject)ts), sys, m.P->truncation, &m.modes));
  }
  const ModalSystem &S          = m.modes->S;
  const ModalBasis  &B          = m.modes->B;
  const PetscInt     n          = S.n;
  const bool         same_count = m.n == m.modes->Count();
  m.n                           = m.modes->Count();
  m.nd                          = n;
  m.omega.assign(B.omega.begin(), B.omega.end());
  if (B.rate.empty()) m.sigma.assign(m.n, 0.0);
  else m.sigma.assign(B.rate.begin(), B.rate.end());
  m.isqm.resize(n);
  m.free_of.assign(sys.ndof, -1);
  // gamma_k = sum over the coupled dofs of w_q phi_k[d_q] / sqrt(m_{d_q}).
  std::vector<PetscReal> gw(n, 0.0);
  const ContactCoupling &g = m.P->g;
  for (PetscInt i = 0; i < n; ++i) {
    m.isqm[i]           = 1.0 / std::sqrt(S.mass[i]);
    m.free_of[S.dof[i]] = i;
    for (PetscInt q = 0; q < g.n; ++q)
      if (S.dof[i] == g.dof[q]) gw[i] += g.w[q] * m.isqm[i];
  }
  // O(n): only the coupled dofs (the coupling's few entries) have gw != 0 (the other terms of the dot product are
  // zeros).
  std::vector<PetscInt> coupled;
  for (PetscInt i = 0; i < n; ++i)
    if (gw[i] != 0.0) coupled.push_back(i);
  m.gamma.assign(m.n, 0.0);
  for (PetscInt k = 0; k < m.n; ++k) {
    const PetscReal *phi = &B.Phi[(size_t)k * n];
    PetscReal        c   = 0;
    for (PetscInt i : coupled) c += phi[i] * gw[i];
    m.gamma[k] = c;
  }
  PetscCall(m.modes->StaticCorrection(g, &m.corr));
  m.Gr = m.corr->Gr;
  PetscBool info;
  PetscCall(PetscInfoEnabled(TS_CLASSID, &info)); // the summary's text only for -info (a sweep's points: not formatted)
  if (info) PetscCall(PetscInfo(ts, "%s\n", BeamModesSummary(*m.modes, m.corr).c_str()));
  if (same_count)
    for (StepWeights &w : m.weights) w.h = -1, w.used = 0; // refilled as new (no length matches -1)
  else m.weights.clear();
  if (m.modes.get() != before) m.shapes.h = -1; // the shapes are the basis' (omega_k, sigma_k)
  m.keep_shapes = true;
  m.have_modal = m.have_step = m.phys_valid = m.c_valid = false;
  PetscFunctionReturn(0);
}

PetscErrorCode TSSetUp_Modal(TS ts)
{
  ModalTS      &m   = *Data(ts);
  TSRHSFunction f   = nullptr;
  void         *ctx = nullptr;

  PetscFunctionBeginUser;
  PetscCall(TSGetRHSFunction(ts, nullptr, &f, &ctx));
  PetscCheck(f == TSRHSExplicit && ctx, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_WRONGSTATE,
             "TS modal integrates the beam-and-ball problem of beamimpact only (its explicit right-hand side, "
             "solvers/ts_problem.hpp)");
  m.P = static_cast<TSProblem *>(ctx);
  PetscCall(PointSetUp(ts));
  PetscFunctionReturn(0);
}

PetscErrorCode NewPoint_Modal(TS ts)
{
  PetscFunctionBeginUser;
  if (Data(ts)->P) PetscCall(PointSetUp(ts)); // (not set up yet: TSSetUp will)
  PetscFunctionReturn(0);
}

PetscErrorCode TSSetFromOptions_Modal(TS ts, PetscOptionItems *PetscOptionsObject)
{
  ModalTS  &m     = *Data(ts);
  PetscInt  order = m.order;
  PetscBool flg;

  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject,
                        "Modal integrator (beamimpact): exact beam flow in its modes, contact force by splitting");
  PetscCall(PetscOptionsInt("-ts_modal_order",
                            "Order: 2 (force linear over the step, trapezoidal collocation) or 4 (force quadratic, "
                            "Lobatto collocation at 0, h/2, h); the beam's modes are exact for the force",
                            "TSModal", order, &order, &flg));
  PetscOptionsHeadEnd();
  PetscCheck(order == 2 || order == 4, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_OUTOFRANGE,
             "-ts_modal_order %" PetscInt_FMT " is not allowed: use 2 or 4", order);
  if (order != m.order) m.weights.clear(), m.shapes.h = -1;
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
    PetscCall(PetscViewerASCIIPrintf(viewer, "  %s\n",
                                     m.modes ? BeamModesSummary(*m.modes, m.corr).c_str() : "modes not built yet"));
  if (ascii)
    PetscCall(PetscViewerASCIIPrintf(viewer,
                                     "  Modal (beamimpact): exact beam flow in %" PetscInt_FMT
                                     " modes, contact force by %s collocation (order %" PetscInt_FMT "); %" PetscInt_FMT
                                     " step lengths weighted, %" PetscInt_FMT " projections, %" PetscInt_FMT
                                     " syncs of the physical state, %" PetscInt_FMT
                                     " writes kept (round-off), %" PetscInt_FMT " unconverged force solves\n",
                                     m.n, m.order == 2 ? "trapezoidal" : "3-point Lobatto", m.order, m.weight_sets,
                                     m.projections, m.syncs, m.kept, m.newton_fail));
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
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalNewPoint_C", NewPoint_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalGetState_C", GetState_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalSetState_C", SetState_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalGetUnwrittenState_C", UnwrittenState_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalSample_C", Sample_Modal));
  PetscCall(PetscObjectComposeFunction((PetscObject)ts, "TSModalExpand_C", Expand_Modal));
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

PetscInt TSModalFoldCount() { return folds; }

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

PetscErrorCode TSModalNewPoint(TS ts)
{
  PetscErrorCode (*f)(TS) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalNewPoint_C", &f));
  if (f) PetscCall((*f)(ts));
  PetscFunctionReturn(0);
}

std::shared_ptr<const BeamModes> TSModalModes(TS ts)
{
  const char *type = nullptr;
  if (!ts || TSGetType(ts, &type) || !type || !TSModalIsType(type) || !ts->data) return nullptr;
  return Data(ts)->modes;
}

PetscErrorCode TSModalGetState(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb,
                               PetscReal *vb, PetscBool *done)
{
  PetscErrorCode (*f)(TS, std::vector<PetscReal> *, std::vector<PetscReal> *, PetscReal *, PetscReal *) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalGetState_C", &f));
  *done = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(ts, z, zd, yb, vb));
  PetscFunctionReturn(0);
}

PetscErrorCode TSModalSetState(TS ts, const std::vector<PetscReal> &z, const std::vector<PetscReal> &zd, PetscReal yb,
                               PetscReal vb, PetscBool *done)
{
  PetscErrorCode (*f)(TS, const std::vector<PetscReal> &, const std::vector<PetscReal> &, PetscReal,
                      PetscReal) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalSetState_C", &f));
  *done = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(ts, z, zd, yb, vb));
  PetscFunctionReturn(0);
}

PetscErrorCode TSModalGetUnwrittenState(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *yb,
                                        PetscReal *vb, PetscBool *done)
{
  PetscErrorCode (*f)(TS, std::vector<PetscReal> *, std::vector<PetscReal> *, PetscReal *, PetscReal *,
                      PetscBool *) = nullptr;

  PetscFunctionBeginUser;
  *done = PETSC_FALSE;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalGetUnwrittenState_C", &f));
  if (f) PetscCall((*f)(ts, z, zd, yb, vb, done));
  PetscFunctionReturn(0);
}

PetscErrorCode TSModalSample(TS ts, std::vector<PetscReal> *z, std::vector<PetscReal> *zd, PetscReal *ball_y,
                             PetscReal *ball_v, PetscReal *static_force, PetscBool *done)
{
  PetscErrorCode (*f)(TS, std::vector<PetscReal> *, std::vector<PetscReal> *, PetscReal *, PetscReal *,
                      PetscReal *) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalSample_C", &f));
  *done = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(ts, z, zd, ball_y, ball_v, static_force));
  PetscFunctionReturn(0);
}

PetscErrorCode TSModalExpand(TS ts, const PetscReal *Z, const PetscReal *F, PetscInt count, PetscInt e0, PetscInt e1,
                             PetscReal *y, PetscReal *v, PetscBool *done)
{
  PetscErrorCode (*f)(TS, const PetscReal *, const PetscReal *, PetscInt, PetscInt, PetscInt, PetscReal *,
                      PetscReal *) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectQueryFunction((PetscObject)ts, "TSModalExpand_C", &f));
  *done = f ? PETSC_TRUE : PETSC_FALSE;
  if (f) PetscCall((*f)(ts, Z, F, count, e0, e1, y, v));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

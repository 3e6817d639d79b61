// Euler-Bernoulli beam operator on a uniform grid: supports, curvature terms,
// stiffness action, energies and the -beam_* options. See beam.hpp.
#include "model/beam.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

SectionProperties BeamSectionAt(const BeamParams &p, PetscReal x)
{
  if (p.section.source != SectionSource::Uniform) return SectionAt(p.section, x);
  SectionProperties s;
  s.EI   = p.EI;
  s.mu   = p.mu;
  s.kGA  = p.kGA;
  s.rhoI = p.rhoI;
  return s;
}

SectionProperties BeamSectionMean(const BeamParams &p, PetscReal a, PetscReal b)
{
  if (p.section.source == SectionSource::Uniform) return BeamSectionAt(p, a);
  SectionProperties s = SectionIntegral(p.section, a, b);
  const PetscReal   w = 1.0 / (b - a);
  s.EI *= w, s.mu *= w, s.kGA *= w, s.rhoI *= w;
  return s;
}

BeamRigidBody BeamRigidBodyOf(const BeamParams &p)
{
  SectionMoments m;
  if (p.section.source == SectionSource::Uniform) {
    const PetscReal L = p.length;
    m.m0 = p.mu * L, m.m1 = p.mu * L * L / 2, m.m2 = p.mu * L * L * L / 3, m.j = p.rhoI * L;
  } else m = SectionMomentsOf(p.section, 0, p.length);
  if (p.theory != "timoshenko") m.j = 0; // an Euler-Bernoulli beam's sections do not spin
  BeamRigidBody b;
  b.mass        = m.m0;
  b.x_cm        = m.m1 / m.m0;
  b.inertia_end = m.m2 + m.j;
  b.inertia_cm  = m.m2 - m.m1 * m.m1 / m.m0 + m.j;
  return b;
}

PetscInt BeamPivotNode(const BeamParams &p)
{
  const PetscReal h = p.length / (p.nodes - 1);
  return std::min<PetscInt>(p.nodes - 1, std::max<PetscInt>(0, (PetscInt)std::lround(p.pivot_x / h)));
}

std::vector<NodeHold> BeamNodeHolds(const BeamParams &p)
{
  const PetscInt        N = p.nodes;
  const PetscReal       h = p.length / (N - 1);
  std::vector<NodeHold> hold(N, NodeHold::None);
  hold[0]     = p.left.Holds();
  hold[N - 1] = hold[N - 1] | p.right.Holds();
  if (p.has_pivot) hold[BeamPivotNode(p)] = hold[BeamPivotNode(p)] | NodeHold::Pin; // y = 0, free rotation
  if (p.has_clamp) {
    const PetscReal tol = 1e-9 * h;
    for (PetscInt i = 0; i < N; ++i) {
      const PetscReal x = i * h;
      if (x >= p.clamp_x0 - tol && x <= p.clamp_x1 + tol) hold[i] = NodeHold::Clamp;
    }
  }
  return hold;
}

BeamOperator BeamOperatorBuild(const BeamParams &p)
{
  BeamOperator op;
  op.N  = p.nodes;
  op.L  = p.length;
  op.h  = p.length / (p.nodes - 1);
  op.EI = p.EI;
  op.mu = p.mu;
  const PetscInt N = op.N;
  op.mass.resize(N);
  op.EI_node.resize(N);
  for (PetscInt i = 0; i < N; ++i) { // cell [x_i - h/2, x_i + h/2] within the beam
    const PetscReal         a = std::max<PetscReal>(0, (i - 0.5) * op.h), b = std::min(op.L, (i + 0.5) * op.h);
    const SectionProperties s = BeamSectionMean(p, a, b);
    op.mass[i]                = s.mu * op.h;
    op.EI_node[i]             = s.EI;
  }
  op.mass[0] *= 0.5; // = mean mu over the half cell x (h/2)
  op.mass[N - 1] *= 0.5;

  const std::vector<NodeHold> hold = BeamNodeHolds(p);
  std::vector<char>           clamp_held(N, 0);
  op.held.assign(N, 0);
  for (PetscInt i = 0; i < N; ++i) {
    clamp_held[i] = hold[i] == NodeHold::Clamp;
    op.held[i]    = HoldsDeflection(hold[i]);
  }

  op.curvature.assign(N, Curvature::None);
  for (PetscInt k = 0; k < N; ++k) {
    const bool left_free  = k > 0 && !op.held[k - 1];
    const bool right_free = k < N - 1 && !op.held[k + 1];
    if (clamp_held[k]) {
      if (left_free && right_free) op.curvature[k] = Curvature::Standard; // a one-node "region" acts as a pin
      else if (right_free) op.curvature[k] = Curvature::MirrorRight;
      else if (left_free) op.curvature[k] = Curvature::MirrorLeft;
    } else if (k > 0 && k < N - 1) {
      op.curvature[k] = Curvature::Standard; // interior node (also next to a pinned one)
    } // free or pinned end node: no curvature term
  }
  return op;
}

static inline PetscReal CurvatureWeight(Curvature c)
{
  switch (c) {
  case Curvature::Standard: return 1.0;
  case Curvature::MirrorRight:
  case Curvature::MirrorLeft: return 0.5;
  default: return 0.0;
  }
}

PetscReal BeamCurvature(const BeamOperator &op, const PetscReal *y, PetscInt stride, PetscInt k)
{
  const PetscReal ih2 = 1.0 / (op.h * op.h);
  switch (op.curvature[k]) {
  case Curvature::Standard: return (y[(k - 1) * stride] - 2.0 * y[k * stride] + y[(k + 1) * stride]) * ih2;
  case Curvature::MirrorRight: return 2.0 * y[(k + 1) * stride] * ih2;
  case Curvature::MirrorLeft: return 2.0 * y[(k - 1) * stride] * ih2;
  default: return 0.0;
  }
}

PetscReal BeamCurvatureDerivative(const BeamOperator &op, PetscInt k, PetscInt i)
{
  const PetscReal ih2 = 1.0 / (op.h * op.h);
  switch (op.curvature[k]) {
  case Curvature::Standard: return i == k ? -2.0 * ih2 : (std::abs(i - k) == 1 ? ih2 : 0.0);
  case Curvature::MirrorRight: return i == k + 1 ? 2.0 * ih2 : 0.0;
  case Curvature::MirrorLeft: return i == k - 1 ? 2.0 * ih2 : 0.0;
  default: return 0.0;
  }
}

void BeamStiffnessApply(const BeamOperator &op, const PetscReal *y, PetscInt stride, PetscInt i0, PetscInt i1, PetscReal *f, PetscInt fstride)
{
  const PetscInt  N = op.N;
  const PetscReal c = op.h;
  // Weighted curvatures EI_k w_k kappa_k for k in [i0-1, i1], kept in a 3-entry window.
  auto wk = [&](PetscInt k) -> PetscReal {
    if (k < 0 || k >= N) return 0.0;
    const Curvature kind = op.curvature[k];
    return kind == Curvature::None ? 0.0 : op.EI_node[k] * CurvatureWeight(kind) * BeamCurvature(op, y, stride, k);
  };
  PetscReal wprev = wk(i0 - 1), wcur = wk(i0);
  for (PetscInt i = i0; i < i1; ++i) {
    const PetscReal wnext = wk(i + 1);
    PetscReal       s     = 0.0;
    if (!op.held[i]) {
      if (i > 0) s += wprev * BeamCurvatureDerivative(op, i - 1, i);
      s += wcur * BeamCurvatureDerivative(op, i, i);
      if (i < N - 1) s += wnext * BeamCurvatureDerivative(op, i + 1, i);
    }
    f[i * fstride] = c * s;
    wprev          = wcur;
    wcur           = wnext;
  }
}

PetscInt BeamStiffnessRow(const BeamOperator &op, PetscInt i, PetscInt cols[5], PetscReal vals[5])
{
  if (op.held[i]) return 0;
  PetscReal row[5] = {0, 0, 0, 0, 0}; // columns i-2 .. i+2
  for (PetscInt k = std::max<PetscInt>(0, i - 1); k <= std::min<PetscInt>(op.N - 1, i + 1); ++k) {
    const PetscReal w = op.EI_node[k] * CurvatureWeight(op.curvature[k]);
    if (w == 0.0) continue;
    const PetscReal di = BeamCurvatureDerivative(op, k, i);
    if (di == 0.0) continue;
    for (PetscInt l = k - 1; l <= k + 1; ++l) {
      if (l < 0 || l >= op.N) continue;
      row[l - i + 2] += w * di * BeamCurvatureDerivative(op, k, l);
    }
  }
  PetscInt n = 0;
  for (PetscInt d = 0; d < 5; ++d) {
    const PetscInt l = i + d - 2;
    if (l < 0 || l >= op.N || op.held[l] || row[d] == 0.0) continue;
    cols[n]   = l;
    vals[n++] = op.h * row[d];
  }
  return n;
}

PetscReal BeamStrainEnergy(const BeamOperator &op, const PetscReal *y, PetscInt stride, PetscInt k0, PetscInt k1)
{
  PetscReal U = 0.0;
  for (PetscInt k = k0; k < k1; ++k) {
    const PetscReal w = CurvatureWeight(op.curvature[k]);
    if (w == 0.0) continue;
    const PetscReal kap = BeamCurvature(op, y, stride, k);
    U += op.EI_node[k] * w * kap * kap;
  }
  return 0.5 * op.h * U;
}

PetscReal BeamKineticEnergy(const BeamOperator &op, const PetscReal *v, PetscInt stride, PetscInt i0, PetscInt i1)
{
  PetscReal T = 0.0;
  for (PetscInt i = i0; i < i1; ++i) T += op.mass[i] * v[i * stride] * v[i * stride];
  return 0.5 * T;
}

ImpactStencil BeamImpactStencil(const BeamOperator &op, PetscReal x_imp) { return GridImpactStencil(op.N, op.L, x_imp); }

ImpactStencil GridImpactStencil(PetscInt N, PetscReal L, PetscReal x_imp)
{
  ImpactStencil   st;
  const PetscReal h  = L / (N - 1);
  const PetscReal s  = std::min(std::max(x_imp, (PetscReal)0), L) / h;
  const PetscReal sr = std::round(s);
  PetscInt        j  = std::abs(s - sr) < 1e-9 ? static_cast<PetscInt>(sr) : static_cast<PetscInt>(std::floor(s));
  PetscReal       frac = std::abs(s - sr) < 1e-9 ? 0.0 : s - j;
  j                    = std::max<PetscInt>(0, j);
  if (j >= N - 1) { // at (or past) the x = L end: all weight on the last node
    j    = N - 2;
    frac = 1.0;
  }
  st.j = j;
  st.w = 1.0 - frac;
  return st;
}

PetscReal BeamMaxFrequencyBound(const BeamOperator &op, const ImpactStencil &s, PetscReal k_extra, PetscReal m_extra)
{
  PetscReal lam = 0.0;
  for (PetscInt i = 0; i < op.N; ++i) {
    if (op.held[i]) continue;
    PetscInt  cols[5];
    PetscReal vals[5];
    const PetscInt n   = BeamStiffnessRow(op, i, cols, vals);
    PetscReal      sum = 0.0;
    for (PetscInt q = 0; q < n; ++q) sum += std::abs(vals[q]);
    PetscReal g = i == s.j ? s.w : (i == s.j + 1 ? 1.0 - s.w : 0.0);
    if (g != 0.0) sum += k_extra * g * (1.0 + 1.0); // |g_i| (|w| + |1-w| + 1)
    lam = std::max(lam, sum / op.mass[i]);
  }
  if (m_extra > 0) lam = std::max(lam, 2.0 * k_extra / m_extra);
  return std::sqrt(lam);
}

PetscReal BeamFundamentalFrequencyEstimate(const BeamParams &p)
{
  // beta L of the lowest flexural mode of a uniform beam, by what each end holds (none, the
  // deflection, the rotation, both): free-free 4.73004, free-pinned 3.92660, free-guided
  // 2.36502, free-clamped 1.87510, pinned-pinned pi, pinned-guided pi/2, pinned-clamped
  // 3.92660, guided-guided pi, guided-clamped 2.36502, clamped-clamped 4.73004.
  static const PetscReal table[4][4] = {
    {4.73004, 3.92660, 2.36502, 1.87510},
    {3.92660, M_PI, M_PI / 2, 3.92660},
    {2.36502, M_PI / 2, M_PI, 2.36502},
    {1.87510, 3.92660, 2.36502, 4.73004},
  };
  auto betaL = [](NodeHold a, NodeHold b) { return table[static_cast<int>(a)][static_cast<int>(b)]; };
  PetscReal span = p.length, bl = betaL(p.left.Holds(), p.right.Holds());
  if (p.has_clamp) {
    const PetscReal left_span = p.clamp_x0, right_span = p.length - p.clamp_x1;
    if (left_span >= right_span) {
      span = left_span;
      bl   = betaL(p.left.Holds(), NodeHold::Clamp);
    } else {
      span = right_span;
      bl   = betaL(NodeHold::Clamp, p.right.Holds());
    }
    span = std::max(span, p.length / (p.nodes - 1));
  }
  return bl * bl * std::sqrt(p.EI / p.mu) / (span * span);
}

} // namespace beamimpact

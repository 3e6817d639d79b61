// The beam's parameters on a uniform grid: sections, supports and holds, curvature kinds,
// the impact stencil, the rigid body. See beam.hpp.
#include "model/beam.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

const char *const SupportNames[] = {"free", "clamped", "pinned", "Support", "BEAM_SUPPORT_", nullptr};

const char *SupportName(Support s) { return SupportNames[static_cast<int>(s)]; }

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
  if (p.left == Support::Pinned) hold[0] = NodeHold::Pin;
  if (p.right == Support::Pinned) hold[N - 1] = NodeHold::Pin;
  if (p.has_pivot) hold[BeamPivotNode(p)] = NodeHold::Pin; // y = 0, free rotation
  if (p.left == Support::Clamped) hold[0] = NodeHold::Clamp;
  if (p.right == Support::Clamped) hold[N - 1] = NodeHold::Clamp;
  if (p.has_clamp) {
    const PetscReal tol = 1e-9 * h;
    for (PetscInt i = 0; i < N; ++i) {
      const PetscReal x = i * h;
      if (x >= p.clamp_x0 - tol && x <= p.clamp_x1 + tol) hold[i] = NodeHold::Clamp;
    }
  }
  return hold;
}

std::vector<Curvature> BeamCurvatureKinds(const std::vector<NodeHold> &hold)
{
  const PetscInt         N = (PetscInt)hold.size();
  std::vector<Curvature> curvature(N, Curvature::None);
  auto                   held = [&](PetscInt i) { return hold[i] != NodeHold::None; };
  for (PetscInt k = 0; k < N; ++k) {
    const bool left_free  = k > 0 && !held(k - 1);
    const bool right_free = k < N - 1 && !held(k + 1);
    if (hold[k] == NodeHold::Clamp) {
      if (left_free && right_free) curvature[k] = Curvature::Standard; // a one-node "region" acts as a pin
      else if (right_free) curvature[k] = Curvature::MirrorRight;
      else if (left_free) curvature[k] = Curvature::MirrorLeft;
    } else if (k > 0 && k < N - 1) {
      curvature[k] = Curvature::Standard; // interior node (also next to a pinned one)
    } // free or pinned end node: no curvature term
  }
  return curvature;
}

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

PetscReal BeamFundamentalFrequencyEstimate(const BeamParams &p)
{
  // beta L of the lowest flexural mode for (left, right) supports.
  auto betaL = [](Support a, Support b) -> PetscReal {
    if (a > b) std::swap(a, b);
    if (a == Support::Free && b == Support::Free) return 4.73004;
    if (a == Support::Free && b == Support::Clamped) return 1.87510;
    if (a == Support::Free && b == Support::Pinned) return 3.92660;
    if (a == Support::Clamped && b == Support::Clamped) return 4.73004;
    if (a == Support::Clamped && b == Support::Pinned) return 3.92660;
    return M_PI; // pinned-pinned
  };
  PetscReal span = p.length, bl = betaL(p.left, p.right);
  if (p.has_clamp) {
    const PetscReal left_span = p.clamp_x0, right_span = p.length - p.clamp_x1;
    if (left_span >= right_span) {
      span = left_span;
      bl   = betaL(p.left, Support::Clamped);
    } else {
      span = right_span;
      bl   = betaL(Support::Clamped, p.right);
    }
    span = std::max(span, p.length / (p.nodes - 1));
  }
  return bl * bl * std::sqrt(p.EI / p.mu) / (span * span);
}

} // namespace beamimpact

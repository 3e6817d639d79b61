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
  m.roll = 0; // about the frame's axis: the parts' (a string bed's sigma z^2, the rolling part's)
  for (const auto &part : p.parts.present) part.second->AddRigidBodyOn(p, &m);
  BeamRigidBody b;
  b.mass         = m.m0;
  b.x_cm         = m.m1 / m.m0;
  b.inertia_end  = m.m2 + m.j;
  b.inertia_cm   = m.m2 - m.m1 * m.m1 / m.m0 + m.j;
  b.inertia_roll = p.parts.Rolls() ? m.roll : 0; // nothing rolls without the roll's part
  return b;
}

const PartParams *PartParamSet::Find(const char *name) const
{
  for (const auto &e : present)
    if (e.first == name) return e.second.get();
  return nullptr;
}

bool PartParamSet::Rolls() const
{
  for (const auto &e : present)
    if (e.second->Rolls()) return true;
  return false;
}

std::vector<PetscReal> PartParamSet::SystemKey() const
{
  std::vector<PetscReal> key;
  for (const auto &e : present) {
    const std::vector<PetscReal> k = e.second->SystemKey();
    key.insert(key.end(), k.begin(), k.end());
  }
  return key;
}

void PartParamSet::Set(const char *name, std::shared_ptr<const PartParams> p)
{
  for (auto it = present.begin(); it != present.end(); ++it)
    if (it->first == name) {
      if (p) it->second = std::move(p);
      else present.erase(it);
      return;
    }
  if (p) present.emplace_back(name, std::move(p));
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

ImpactStencil GridImpactStencil(PetscInt N, PetscReal L, PetscReal x_imp)
{
  ImpactStencil   st;
  const PetscReal h    = L / (N - 1);
  const PetscReal s    = std::min(std::max(x_imp, (PetscReal)0), L) / h;
  const PetscReal sr   = std::round(s);
  PetscInt        j    = std::abs(s - sr) < 1e-9 ? static_cast<PetscInt>(sr) : static_cast<PetscInt>(std::floor(s));
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
  auto      betaL = [](NodeHold a, NodeHold b) { return table[static_cast<int>(a)][static_cast<int>(b)]; };
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

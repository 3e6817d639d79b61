// The frame's twist as one more field of the beam. See torsion.hpp.
#include "model/torsion.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

void TorsionSectionMean(const BeamTorsion &t, const BeamParams &p, PetscReal a, PetscReal b, PetscReal *GJ,
                        PetscReal *rhoJ)
{
  SectionProperties s;
  if (p.section.source != SectionSource::Uniform && b > a) {
    s = SectionIntegral(p.section, a, b);
    s.GJ /= (b - a), s.rhoJ /= (b - a);
  }
  *GJ   = t.stiffness > 0 ? t.stiffness : s.GJ;
  *rhoJ = t.inertia > 0 ? t.inertia : s.rhoJ;
}

PetscInt TorsionAppend(const BeamTorsion &tor, const BeamParams &p, BeamDiscretization *d)
{
  const PetscInt              N = p.nodes, F = d->fields, G = F + 1;
  const PetscReal             L = p.length, h = L / (N - 1);
  const std::vector<NodeHold> hold = BeamNodeHolds(p);
  BeamDiscretizationWiden(d, G, 0.0);
  const auto roll = [&](PetscInt i) { return i * G + F; };
  for (PetscInt i = 0; i < N; ++i) { // the node's cell [x_i - h/2, x_i + h/2] within the beam
    const PetscReal a = std::max<PetscReal>(0, (i - 0.5) * h), b = std::min(L, (i + 0.5) * h);
    PetscReal       GJ, rhoJ;
    TorsionSectionMean(tor, p, a, b, &GJ, &rhoJ);
    d->mass[roll(i)] = rhoJ * (b - a);
    d->held[roll(i)] = HoldsRotation(hold[i]);
  }
  for (PetscInt k = 0; k + 1 < N; ++k) {
    PetscReal GJ, rhoJ;
    TorsionSectionMean(tor, p, k * h, (k + 1) * h, &GJ, &rhoJ);
    StrainTerm t; // 1/2 G J h ((phi_k+1 - phi_k)/h)^2
    t.n      = 2;
    t.dof[0] = roll(k), t.b[0] = -1.0 / h;
    t.dof[1] = roll(k + 1), t.b[1] = 1.0 / h;
    t.weight = GJ * h;
    t.owner  = roll(k);
    d->strain.push_back(t);
  }
  return F;
}

PetscReal TorsionFreeFrequency(PetscReal GJ, PetscReal rhoJ, PetscReal L, PetscInt n)
{
  return n / (2 * L) * std::sqrt(GJ / rhoJ);
}

} // namespace beamimpact

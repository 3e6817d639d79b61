// Euler-Bernoulli beam as a beam theory (model/beam_theory.hpp): one deflection dof per node,
// lumped mass mu h (half at the ends), and one curvature term per node,
//
//   U = (EI h / 2) sum_k w_k kappa_k^2,
//
// standard interior terms kappa_k = (y_k-1 - 2 y_k + y_k+1)/h^2 (w = 1) and, where a node's
// rotation is held (model/support.hpp: a clamped or guided end, the inner edge of a clamped
// region), the mirror ghost y_k-1 = y_k+1 across it: kappa_k = 2 (y_k+1 - y_k)/h^2 over the
// half cell (w = 1/2; y_k = 0 when the deflection is held too). A node whose rotation is free
// at an end (free, pinned) has no term: y'' = 0 there, the natural condition. A held deflection
// is a held dof.
#include "model/beam_theory.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

namespace {

// The mirror term at node k, whose rotation is held, toward its free neighbour j = k +- 1:
// 2 (y_j - y_k)/h^2 with weight 1/2 (the y_k entry only when y_k is free).
StrainTerm MirrorTerm(PetscInt k, PetscInt j, bool k_held, PetscReal ih2, PetscReal EI_h)
{
  StrainTerm t;
  t.owner  = k;
  t.n      = 1;
  t.dof[0] = j, t.b[0] = 2.0 * ih2;
  if (!k_held) t.n = 2, t.dof[1] = k, t.b[1] = -2.0 * ih2;
  t.weight = 0.5 * EI_h;
  return t;
}

} // namespace

void EulerBernoulliBuild(const BeamParams &p, BeamDiscretization *d)
{
  const PetscInt              N = p.nodes;
  const PetscReal             L = p.length, h = L / (N - 1), ih2 = 1.0 / (h * h);
  const std::vector<NodeHold> hold = BeamNodeHolds(p);
  std::vector<PetscReal>      EI_node(N);
  d->fields = 1;
  d->mass.resize(N);
  d->held.assign(N, 0);
  for (PetscInt i = 0; i < N; ++i) { // cell [x_i - h/2, x_i + h/2] within the beam
    const PetscReal         a = std::max<PetscReal>(0, (i - 0.5) * h), b = std::min(L, (i + 0.5) * h);
    const SectionProperties s = BeamSectionMean(p, a, b);
    d->mass[i]                = s.mu * h;
    EI_node[i]                = s.EI;
    d->held[i]                = HoldsDeflection(hold[i]);
  }
  d->mass[0] *= 0.5; // = mean mu over the half cell x (h/2)
  d->mass[N - 1] *= 0.5;
  d->frequency_unit = std::sqrt(p.EI / p.mu) / (L * L);
  d->strain.clear();
  for (PetscInt k = 0; k < N; ++k) {
    const bool left_free = k > 0 && !d->held[k - 1], right_free = k < N - 1 && !d->held[k + 1];
    const bool rotation = HoldsRotation(hold[k]), interior = k > 0 && k < N - 1;
    if (rotation && !(left_free && right_free && interior)) { // a held rotation with one free side: the mirror term
      if (right_free) d->strain.push_back(MirrorTerm(k, k + 1, d->held[k], ih2, EI_node[k] * h));
      else if (left_free) d->strain.push_back(MirrorTerm(k, k - 1, d->held[k], ih2, EI_node[k] * h));
      continue; // inside a clamped region: no term
    }
    if (!interior) continue; // a free or pinned end: y'' = 0
    StrainTerm t;            // interior (also next to or on a pinned node; a one-node clamped "region" acts as a pin)
    t.owner  = k;
    t.n      = 3;
    t.dof[0] = k - 1, t.dof[1] = k, t.dof[2] = k + 1;
    t.b[0] = ih2, t.b[1] = -2.0 * ih2, t.b[2] = ih2;
    t.weight = EI_node[k] * h;
    d->strain.push_back(t);
  }
}

} // namespace beamimpact

// Euler-Bernoulli beam as a beam theory (model/beam_theory.hpp): one deflection dof per node,
// lumped mass mu h (half at the ends), and one curvature term per node with the weights of
// model/beam.hpp (standard interior terms; half-weight mirror terms at clamps; none at free
// and pinned ends):  U = (EI h / 2) sum_k w_k kappa_k^2.
#include "model/beam_theory.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace beamimpact {

void EulerBernoulliBuild(const BeamParams &p, BeamDiscretization *d)
{
  const PetscInt              N = p.nodes;
  const PetscReal             h = p.length / (N - 1), ih2 = 1.0 / (h * h);
  const std::vector<NodeHold> hold      = BeamNodeHolds(p);
  const std::vector<Curvature> curvature = BeamCurvatureKinds(hold);
  std::vector<PetscReal>      EI(N); // N m^2, the mean EI over node k's cell (weights curvature term k)
  d->fields = 1;
  d->mass.resize(N);
  d->held.resize(N);
  for (PetscInt i = 0; i < N; ++i) { // cell [x_i - h/2, x_i + h/2] within the beam: the lumped mass is the integral of mu over it
    const PetscReal         a = std::max<PetscReal>(0, (i - 0.5) * h), b = std::min(p.length, (i + 0.5) * h);
    const SectionProperties s = BeamSectionMean(p, a, b);
    d->mass[i]                = s.mu * h;
    EI[i]                     = s.EI;
    d->held[i]                = hold[i] != NodeHold::None;
  }
  d->mass[0] *= 0.5; // = mean mu over the half cell x (h/2)
  d->mass[N - 1] *= 0.5;
  d->frequency_unit = std::sqrt(p.EI / p.mu) / (p.length * p.length);
  d->strain.clear();
  for (PetscInt k = 0; k < N; ++k) {
    StrainTerm t;
    t.owner = k;
    switch (curvature[k]) {
    case Curvature::Standard:
      t.n      = 3;
      t.dof[0] = k - 1, t.dof[1] = k, t.dof[2] = k + 1;
      t.b[0] = ih2, t.b[1] = -2.0 * ih2, t.b[2] = ih2;
      t.weight = EI[k] * h;
      break;
    case Curvature::MirrorRight:
      t.n      = 1;
      t.dof[0] = k + 1;
      t.b[0]   = 2.0 * ih2;
      t.weight = 0.5 * EI[k] * h;
      break;
    case Curvature::MirrorLeft:
      t.n      = 1;
      t.dof[0] = k - 1;
      t.b[0]   = 2.0 * ih2;
      t.weight = 0.5 * EI[k] * h;
      break;
    default: continue;
    }
    d->strain.push_back(t);
  }
}

} // namespace beamimpact

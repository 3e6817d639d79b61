// Euler-Bernoulli beam as a beam theory (model/beam_theory.hpp): one deflection dof per node,
// lumped mass mu h (half at the ends), and one curvature term per node with the weights of
// model/beam.hpp (standard interior terms; half-weight mirror terms at clamps; none at free
// and pinned ends):  U = (EI h / 2) sum_k w_k kappa_k^2.
#include "model/beam_theory.hpp"

#include <cmath>
#include <cstring>

namespace beamimpact {

void EulerBernoulliBuild(const BeamParams &p, BeamDiscretization *d)
{
  const BeamOperator op  = BeamOperatorBuild(p);
  const PetscReal    ih2 = 1.0 / (op.h * op.h);
  d->fields              = 1;
  d->mass                = op.mass;
  d->held                = op.held;
  d->frequency_unit      = std::sqrt(op.EI / op.mu) / (op.L * op.L);
  d->strain.clear();
  for (PetscInt k = 0; k < op.N; ++k) {
    StrainTerm t;
    t.owner = k;
    switch (op.curvature[k]) {
    case Curvature::Standard:
      t.n      = 3;
      t.dof[0] = k - 1, t.dof[1] = k, t.dof[2] = k + 1;
      t.b[0] = ih2, t.b[1] = -2.0 * ih2, t.b[2] = ih2;
      t.weight = op.EI_node[k] * op.h;
      break;
    case Curvature::MirrorRight:
      t.n      = 1;
      t.dof[0] = k + 1;
      t.b[0]   = 2.0 * ih2;
      t.weight = 0.5 * op.EI_node[k] * op.h;
      break;
    case Curvature::MirrorLeft:
      t.n      = 1;
      t.dof[0] = k - 1;
      t.b[0]   = 2.0 * ih2;
      t.weight = 0.5 * op.EI_node[k] * op.h;
      break;
    default: continue;
    }
    d->strain.push_back(t);
  }
}

} // namespace beamimpact

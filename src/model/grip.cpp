// The grip's weights per node. See grip.hpp.
#include "model/grip.hpp"

#include <algorithm>

namespace beamimpact {

std::vector<PetscReal> GripNodeWeights(const BeamGrip &grip, PetscInt nodes, PetscReal L)
{
  std::vector<PetscReal> w(nodes, 0.0);
  if (!grip.on || nodes < 2) return w;
  const PetscReal h = L / (nodes - 1);
  for (PetscInt i = 0; i < nodes; ++i) {
    const PetscReal a = std::max({0.0, i * h - 0.5 * h, grip.x_a}), b = std::min({L, i * h + 0.5 * h, grip.x_b});
    w[i] = b > a ? b - a : 0.0;
  }
  return w;
}

} // namespace beamimpact

// The hands on the handle (docs/model.md, "The hands"): a distributed spring-damper
// over [x_a, x_b] tying the handle's deflection to the swing's rigid frame. On the grid each node
// of the grip carries the share of the span that its dual cell [x_i - h/2, x_i + h/2] covers
// (the shares add up to x_b - x_a), so node i gets the spring k_i = k' w_i (N/m), the damper
// c_i = c' w_i (N s/m) and the hand mass m' w_i / (x_b - x_a) (kg). Plain numbers.
#pragma once

#include "model/beam.hpp"

#include <vector>

namespace beamimpact {

// The length (m) of [x_a, x_b] each of `nodes` nodes on [0, L] carries (zero outside the grip).
std::vector<PetscReal> GripNodeWeights(const BeamGrip &grip, PetscInt nodes, PetscReal L);

} // namespace beamimpact

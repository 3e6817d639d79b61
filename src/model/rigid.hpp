// Rigid-body model of the collision (docs/model.md: Eq. 11 of the paper): the beam as a rigid
// body of mass M (kg) and moment of inertia I_cm (kg m^2), struck at distance
// b_cm (m) from its centre of mass, hand force neglected.
//   M_e = M / (1 + M b_cm^2 / I_cm),  R = m_b / M_e,
//   e   = (sqrt(1 - f (1+R)) - R) / (1 + R),
// f (dimensionless) the fraction of the incident energy lost.
#pragma once

#include <petscsys.h>

namespace beamimpact {

// Effective mass (kg) of the beam at the impact point.
PetscReal RigidEffectiveMass(PetscReal M, PetscReal I_cm, PetscReal b_cm);
// ACOR of Eq. (11); NaN when f > 1/(1+R) (more energy lost than is available).
PetscReal RigidACOR(PetscReal ball_mass, PetscReal M_e, PetscReal f);
// The loss fraction f for which Eq. (11) returns acor (the "forced" rigid fit).
PetscReal RigidForcedLossFraction(PetscReal ball_mass, PetscReal M_e, PetscReal acor);

} // namespace beamimpact

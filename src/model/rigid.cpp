// Rigid-body collision model, Eq. (11) of the paper. See rigid.hpp.
#include "model/rigid.hpp"

#include <cmath>
#include <limits>

namespace beamimpact {

PetscReal RigidEffectiveMass(PetscReal M, PetscReal I_cm, PetscReal b_cm) { return M / (1.0 + M * b_cm * b_cm / I_cm); }

PetscReal RigidACOR(PetscReal ball_mass, PetscReal M_e, PetscReal f)
{
  const PetscReal R = ball_mass / M_e, disc = 1.0 - f * (1.0 + R);
  if (disc < 0) return std::numeric_limits<PetscReal>::quiet_NaN();
  return (std::sqrt(disc) - R) / (1.0 + R);
}

PetscReal RigidForcedLossFraction(PetscReal ball_mass, PetscReal M_e, PetscReal acor)
{
  const PetscReal R = ball_mass / M_e, s = acor * (1.0 + R) + R; // s = sqrt(1 - f (1+R))
  return (1.0 - s * s) / (1.0 + R);
}

} // namespace beamimpact

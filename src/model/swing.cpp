// A swinging bat and a pivoted rig as rigid bodies. See swing.hpp.
#include "model/swing.hpp"

#include <cmath>

namespace beamimpact {

PetscReal SwingSpeedAt(const SwingParams &s, const BeamRigidBody &body, PetscReal x)
{
  return s.bat_speed + s.bat_angular_velocity * (x - body.x_cm);
}

PetscReal SwingLawInertia(const SwingLaw &law, const BeamRigidBody &body)
{
  const PetscReal d = body.x_cm - law.pivot;
  return body.inertia_cm + body.mass * d * d;
}

PetscReal SwingLawFactor(const SwingLaw &law, const BeamRigidBody &body)
{
  if (!(law.reference_inertia > 0)) return 1;
  return std::pow(SwingLawInertia(law, body) / law.reference_inertia, -law.exponent);
}

SwingParams SwingFromLaw(const SwingLaw &law, const BeamRigidBody &body)
{
  const PetscReal s = SwingLawFactor(law, body);
  SwingParams     p;
  p.bat_angular_velocity = s * law.angular_velocity;
  p.bat_speed            = s * (law.pivot_speed + law.angular_velocity * (body.x_cm - law.pivot));
  return p;
}

PetscReal SwingCollisionEfficiency(PetscReal bbs, PetscReal v_ball, PetscReal V_x)
{
  return (bbs - V_x) / (v_ball + V_x);
}

PivotRig PivotRigOf(const BeamRigidBody &body, PetscReal x_pivot, PetscReal ball_mass, PetscReal x_imp)
{
  PivotRig        r;
  const PetscReal d = body.x_cm - x_pivot, b = x_imp - x_pivot;
  r.inertia_pivot = body.inertia_cm + body.mass * d * d;
  r.recoil_factor = ball_mass * b * b / r.inertia_pivot;
  return r;
}

PetscReal PivotBBCOR(const PivotRig &rig, PetscReal e_A) { return e_A * (1 + rig.recoil_factor) + rig.recoil_factor; }

} // namespace beamimpact

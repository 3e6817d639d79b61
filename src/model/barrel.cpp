// The barrel wall's hoop oscillator appended to a theory's discretization. See barrel.hpp.
#include "model/barrel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

PetscReal BarrelHoopStiffness(const BarrelHoop &hoop)
{
  const PetscReal omega = 2.0 * PETSC_PI * hoop.frequency;
  return hoop.mass * omega * omega;
}

PetscInt BarrelHoopAppend(const BarrelHoop &hoop, BeamDiscretization *d)
{
  const PetscInt wall = d->fields; // node 0's new field
  BeamDiscretizationWiden(d, d->fields + 1, hoop.mass);
  d->held[wall] = 0;
  StrainTerm s; // 1/2 k_h w^2
  s.n      = 1;
  s.dof[0] = wall;
  s.b[0]   = 1.0;
  s.weight = BarrelHoopStiffness(hoop);
  s.owner  = wall;
  d->strain.push_back(s);
  return wall;
}

bool BarrelWallThicknessApply(PetscReal t, std::vector<ProfileRow> *rows, std::string *why)
{
  PetscReal D = 0;
  char      text[256];
  for (const ProfileRow &r : *rows) D = std::max(D, r.D);
  for (const ProfileRow &r : *rows) {
    if (r.D < D * (1 - 1e-9)) continue;
    if (!(r.d > 0)) {
      std::snprintf(text, sizeof text,
                    "the barrel (the rows at the largest outer diameter, D = %g m) is solid at x = %g m: there is no "
                    "wall to change",
                    (double)D, (double)r.x);
      *why = text;
      return false;
    }
    if (!(t > 0 && t < r.D / 2)) {
      std::snprintf(text, sizeof text,
                    "the wall must be thinner than the barrel's outer radius D/2 = %g m (t >= D/2 is a solid section), "
                    "and > 0",
                    (double)(r.D / 2));
      *why = text;
      return false;
    }
  }
  for (ProfileRow &r : *rows)
    if (r.D >= D * (1 - 1e-9)) r.d = r.D - 2 * t;
  return true;
}

PetscReal SeriesSpringRestitution(PetscReal e0, PetscReal r) { return std::sqrt((e0 * e0 + r) / (1.0 + r)); }

} // namespace beamimpact

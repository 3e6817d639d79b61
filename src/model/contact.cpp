// The contact facade: each function asks the ball's law. See contact.hpp.
#include "model/contact.hpp"

#include <cmath>

namespace beamimpact {

PetscReal ContactForce(const BallParams &b, const ContactState &s, PetscReal c)
{
  return s.phase == ContactPhase::Separated ? 0.0 : b.law->Force(b, s, c);
}
PetscReal ContactStiffness(const BallParams &b, const ContactState &s, PetscReal c)
{
  return s.phase == ContactPhase::Separated ? 0.0 : b.law->Stiffness(b, s, c);
}
PetscReal ContactStoredEnergy(const BallParams &b, const ContactState &s, PetscReal c)
{
  return s.phase == ContactPhase::Separated ? 0.0 : b.law->Stored(b, s, c);
}
PetscReal ContactWork(const BallParams &b, const ContactState &s, PetscReal c)
{
  return s.work_offset + ContactStoredEnergy(b, s, c);
}

void ContactSwitch(const BallParams &b, ContactState *s, ContactPhase to, PetscReal c)
{
  const PetscReal before = ContactStoredEnergy(b, *s, c);
  if (to == ContactPhase::Unloading) {
    s->c_max = c;
    b.law->Unload(b, s, c);
  }
  s->phase = to;
  s->work_offset += before - ContactStoredEnergy(b, *s, c);
}

void ContactBegin(const BallParams &b, ContactState *s, PetscReal v) { b.law->Begin(b, s, v); }

bool      ContactHasHysteresis(const BallParams &b) { return b.law->Hysteretic(b); }
bool      ContactElastic(const BallParams &b) { return b.law->Elastic(); }
bool      ContactLinear(const BallParams &b) { return b.law->Linear(); }
PetscReal ContactLinearStiffness(const BallParams &b) { return b.law->LinearStiffness(b); }
PetscReal ContactUnloadingExponent(const BallParams &b, const ContactState &s)
{
  return b.law->UnloadingExponent(b, s);
}

PetscReal ContactTimeScale(const BallParams &b) { return b.law->TimeScale(b); }
PetscReal ContactTimeScale(const BallParams &b, PetscReal approach)
{
  BallParams at = b;
  if (approach > 0) at.speed = approach;
  return at.law->TimeScale(at);
}
PetscReal ContactCompressionScale(const BallParams &b) { return b.law->CompressionScale(b); }
PetscReal ContactStartExponent(const BallParams &b, PetscReal approach)
{
  BallParams at = b;
  if (approach > 0) at.speed = approach;
  ContactState    s;
  const PetscReal c = 1e-6 * at.law->CompressionScale(at);
  at.law->Begin(at, &s, at.speed);
  const PetscReal f1 = at.law->Force(at, s, c), f2 = at.law->Force(at, s, 2 * c);
  return f1 > 0 && f2 > 0 ? std::log2(f2 / f1) : 1.0;
}
PetscReal ContactStiffnessBound(const BallParams &b) { return b.law->StiffnessBound(b); }

PetscReal BallCorAt(const BallParams &b, PetscReal v) { return b.law->WallCor(b, v); }
PetscReal ContactWallMaxCompression(const BallParams &b, PetscReal v) { return b.law->WallMaxCompression(b, v); }
PetscReal ContactWallLoadingTime(const BallParams &b, PetscReal v) { return b.law->WallLoadingTime(b, v); }
PetscReal ContactWallUnloadingTime(const BallParams &b, PetscReal v) { return b.law->WallUnloadingTime(b, v); }
PetscReal ContactWallTime(const BallParams &b, PetscReal v)
{
  return ContactWallLoadingTime(b, v) + ContactWallUnloadingTime(b, v);
}

} // namespace beamimpact

// The registry of beam-end supports. See support.hpp. A new support is one entry of kSupports.
#include "model/support.hpp"

#include <strings.h>

namespace beamimpact {

namespace {

const SupportSpec kSupports[] = {
  {"free", "no moment and no shear force: y'' = 0, y''' = 0", NodeHold::None},
  {"clamped", "no deflection and no slope: y = 0, y' = 0 (Timoshenko: w = 0, psi = 0)", NodeHold::Clamp},
  {"pinned", "no deflection and no moment, free to rotate: y = 0, y'' = 0", NodeHold::Pin},
};

std::vector<const SupportSpec *> &Registered()
{
  static std::vector<const SupportSpec *> list = [] {
    std::vector<const SupportSpec *> l;
    for (const SupportSpec &s : kSupports) l.push_back(&s);
    return l;
  }();
  return list;
}

} // namespace

const Support Support::Free(&kSupports[0]);
const Support Support::Clamped(&kSupports[1]);
const Support Support::Pinned(&kSupports[2]);

const char *SupportName(Support s) { return s.Name(); }

std::vector<Support> Supports()
{
  std::vector<Support> v;
  for (const SupportSpec *s : Registered()) v.push_back(Support(s));
  return v;
}

std::vector<std::string> SupportNames()
{
  std::vector<std::string> v;
  for (const SupportSpec *s : Registered()) v.push_back(s->name);
  return v;
}

bool SupportFind(const std::string &name, Support *s)
{
  for (const SupportSpec *r : Registered())
    if (strcasecmp(r->name, name.c_str()) == 0) {
      *s = Support(r);
      return true;
    }
  return false;
}

void SupportRegister(const SupportSpec *spec)
{
  for (const SupportSpec *r : Registered())
    if (r == spec || strcasecmp(r->name, spec->name) == 0) return;
  Registered().push_back(spec);
}

PetscInt SupportRigidModes(Support left, Support right)
{
  // Holds on (a, b) of y = a + b x: a deflection at x = 0 is (1, 0), at x = L (1, L), a rotation
  // anywhere (0, 1). The rank of the rows present is what the holds take away.
  const NodeHold l = left.Holds(), r = right.Holds();
  const int      deflections = HoldsDeflection(l) + HoldsDeflection(r);
  const bool     rotation    = HoldsRotation(l) || HoldsRotation(r);
  const int      rank        = rotation ? 1 + (deflections > 0 ? 1 : 0) : deflections;
  return 2 - rank;
}

} // namespace beamimpact

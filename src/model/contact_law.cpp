// The registry of contact laws and what every law shares. See contact_law.hpp.
#include "model/contact_law.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <strings.h>

namespace beamimpact {

// The registry: each law is defined in its own file of model/contact_laws/ and registered here
// by its declaration and its entry in the list (-help order; the first is the default).
const ContactLaw &LinearContactLaw();
const ContactLaw &HysteresisContactLaw();
const ContactLaw &HertzContactLaw();

const std::vector<const ContactLaw *> &ContactLaws()
{
  static const std::vector<const ContactLaw *> laws = {
    &LinearContactLaw(),
    &HysteresisContactLaw(),
    &HertzContactLaw(),
  };
  return laws;
}

const ContactLaw *ContactLawFind(const char *name)
{
  for (const ContactLaw *law : ContactLaws())
    if (name && !strcasecmp(law->Name(), name)) return law;
  return nullptr;
}

std::vector<std::string> ContactLawNames()
{
  std::vector<std::string> names;
  for (const ContactLaw *law : ContactLaws()) names.push_back(law->Name());
  return names;
}

const char *ContactLawName(const ContactLaw *law) { return law ? law->Name() : "(none)"; }

BallParams::BallParams() { BallParamsUseLaw(this, ContactLaws().front()); }

void BallParamsUseLaw(BallParams *b, const ContactLaw *law)
{
  b->law = law;
  b->value.fill(0.0);
  b->cor_table = CorTable();
  int i        = 0;
  for (const OptionSpec &row : law->Options())
    if (row.kind == OptionKind::Real && i < kContactLawMaxValues)
      b->value[i++] = row.def.empty() ? 0.0 : std::strtod(row.def.c_str(), nullptr);
}

int ContactLawValueIndex(const ContactLaw &law, const char *name)
{
  const std::string want = std::string(name).rfind("-ball_", 0) == 0 ? name : "-ball_" + std::string(name);
  int               i    = 0;
  for (const OptionSpec &row : law.Options()) {
    if (row.kind != OptionKind::Real) continue;
    if (row.name == want) return i < kContactLawMaxValues ? i : -1;
    ++i;
  }
  return -1;
}

PetscReal BallValue(const BallParams &b, const char *name)
{
  const int i = ContactLawValueIndex(*b.law, name);
  return i < 0 ? std::numeric_limits<PetscReal>::quiet_NaN() : b.value[i];
}

bool BallValueSet(BallParams *b, const char *name, PetscReal v)
{
  const int i = ContactLawValueIndex(*b->law, name);
  if (i < 0) return false;
  b->value[i] = v;
  return true;
}

bool ContactLawInput::Given(const char *name) const
{
  for (const std::string &g : given)
    if (g == name) return true;
  return false;
}

std::string ContactLawInput::Text(const char *name) const
{
  const auto it = text.find(name);
  return it == text.end() ? std::string() : it->second;
}

PetscReal ContactLaw::LinearStiffness(const BallParams &) const { return std::numeric_limits<PetscReal>::quiet_NaN(); }

std::vector<ContactLawRecord> ContactLaw::Record(const BallParams &b) const
{
  std::vector<ContactLawRecord> out;
  int                           i = 0;
  for (const OptionSpec &row : Options()) {
    if (row.kind != OptionKind::Real) continue;
    ContactLawRecord r;
    r.name  = row.name.substr(1); // "-ball_k" -> "ball_k"
    r.unit  = row.unit;
    r.value = b.value[i++];
    out.push_back(r);
  }
  return out;
}

std::vector<ContactLawRecord> ContactLawRecordOf(const BallParams &b)
{
  std::vector<ContactLawRecord> out = b.law->Record(b);
  const PetscReal               v   = b.speed;
  auto                          add = [&](const char *name, const char *unit, PetscReal value) {
    ContactLawRecord r;
    r.name = name, r.unit = unit, r.value = value;
    out.push_back(r);
  };
  add("ball_wall_cor", "1", b.law->WallCor(b, v));
  add("ball_wall_contact_time", "s", b.law->WallLoadingTime(b, v) + b.law->WallUnloadingTime(b, v));
  add("ball_wall_max_compression", "m", b.law->WallMaxCompression(b, v));
  return out;
}

PetscReal PowerLawWallIntegral(PetscReal p)
{
  // B(1/p, 1/2) / p with B(a, b) = Gamma(a) Gamma(b) / Gamma(a + b), through lgamma (finite for any p >= 1).
  const PetscReal a = 1.0 / p;
  return std::exp(std::lgamma(a) + std::lgamma(0.5) - std::lgamma(a + 0.5)) / p;
}

} // namespace beamimpact

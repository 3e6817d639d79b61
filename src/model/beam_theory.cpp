// The registry of beam theories. See beam_theory.hpp.
#include "model/beam_theory.hpp"

#include <cstring>

namespace beamimpact {

namespace {
struct TheoryEntry {
  const char     *name;
  BeamTheoryBuild build;
};
// The registry: one line per theory.
const TheoryEntry kTheories[] = {
  {"euler", EulerBernoulliBuild},
  {"timoshenko", TimoshenkoBuild},
};
} // namespace

BeamTheoryBuild BeamTheoryFind(const char *name)
{
  for (const TheoryEntry &e : kTheories)
    if (!std::strcmp(e.name, name)) return e.build;
  return nullptr;
}

std::vector<const char *> BeamTheoryNames()
{
  std::vector<const char *> names;
  for (const TheoryEntry &e : kTheories) names.push_back(e.name);
  return names;
}

} // namespace beamimpact

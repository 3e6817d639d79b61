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

void BeamDiscretizationWiden(BeamDiscretization *d, PetscInt G, PetscReal mass)
{
  const PetscInt         F = d->fields, N = (PetscInt)d->mass.size() / F;
  const auto             renumber = [&](PetscInt dof) { return (dof / F) * G + dof % F; };
  std::vector<PetscReal> m((size_t)N * G, mass);
  std::vector<char>      held((size_t)N * G, 1);
  for (PetscInt i = 0; i < N * F; ++i) m[renumber(i)] = d->mass[i], held[renumber(i)] = d->held[i];
  for (StrainTerm &t : d->strain) {
    t.owner = renumber(t.owner);
    for (PetscInt q = 0; q < t.n; ++q) t.dof[q] = renumber(t.dof[q]);
  }
  d->fields = G;
  d->mass   = std::move(m);
  d->held   = std::move(held);
}

std::vector<const char *> BeamTheoryNames()
{
  std::vector<const char *> names;
  for (const TheoryEntry &e : kTheories) names.push_back(e.name);
  return names;
}

} // namespace beamimpact

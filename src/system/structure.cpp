// The registry of structure parts and the loops over it. See structure_part.hpp.
#include "system/structure_part.hpp"

#include "system/beam_system.hpp"

#include <algorithm>
#include <cstring>

namespace beamimpact {

// The parts, one file each in system/parts/: a part is its declaration here and its line in
// PartList, last (the order appends their fields: the dof numbering). The hands come first: they
// have no fields, their force term is summed before the absorber's, their summary line precedes
// the roll's, and their check against the roll (-grip_torsion_*) is made once all are configured.
const StructurePart &GripPart();     // system/parts/grip.cpp
const StructurePart &RollPart();     // system/parts/roll.cpp
const StructurePart &WallPart();     // system/parts/wall.cpp
const StructurePart &BedPart();      // system/parts/bed.cpp
const StructurePart &AbsorberPart(); // system/parts/absorber.cpp

namespace {

std::vector<const StructurePart *> PartList()
{
  std::vector<const StructurePart *> v;
  v.push_back(&GripPart());
  v.push_back(&RollPart());
  v.push_back(&WallPart());
  v.push_back(&BedPart());
  v.push_back(&AbsorberPart());
  return v;
}

} // namespace

const std::vector<const StructurePart *> &StructureParts()
{
  static const std::vector<const StructurePart *> parts = [] {
    const std::vector<const StructurePart *> v     = PartList();
    size_t                                   slots = 0; // every part present at once must fit the fixed slots
    for (const StructurePart *p : v) slots += p->Slots().size();
    PetscCheckAbort(slots <= (size_t)kMaxPartSlots, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                    "the structure parts declare %zu measure slots, more than kMaxPartSlots = %d", slots,
                    kMaxPartSlots);
    const auto accounts = 1 +
                          std::count_if(v.begin(), v.end(), [](const StructurePart *p) { return p->AccountName(); });
    PetscCheckAbort(accounts <= kMaxAccounts, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                    "the structure parts declare %d energy accounts with the beam's, more than kMaxAccounts = %d",
                    (int)accounts, kMaxAccounts);
    return v;
  }();
  return parts;
}

const StructurePart *StructurePartFind(const char *name)
{
  for (const StructurePart *p : StructureParts())
    if (!std::strcmp(p->Name(), name)) return p;
  return nullptr;
}

PetscInt StructureAccountCount()
{
  PetscInt n = 1;
  for (const StructurePart *p : StructureParts()) n += p->AccountName() ? 1 : 0;
  return n;
}

const StructurePart *StructureAccountPart(PetscInt a)
{
  for (const StructurePart *p : StructureParts())
    if (p->AccountName() && --a == 0) return p;
  return nullptr;
}

bool StructureAccountApart(PetscInt a)
{
  const StructurePart *p = StructureAccountPart(a);
  return p && p->AccountApart();
}

const char *StructureAccountName(PetscInt a) { return a == 0 ? "bending" : StructureAccountPart(a)->AccountName(); }

PetscInt StructureAccountOf(const StructurePart &part)
{
  PetscInt a = 0;
  for (const StructurePart *p : StructureParts()) {
    a += p->AccountName() ? 1 : 0;
    if (p == &part) return p->AccountName() ? a : 0;
  }
  return 0;
}

std::vector<PartInstance> StructurePartsBuild(const BeamParams &p, BeamDiscretization *d)
{
  std::vector<PartInstance> out;
  for (const StructurePart *part : StructureParts()) {
    const PartParams *q = p.parts.Find(part->Name());
    if (!q) continue;
    PartInstance s;
    s.part = part;
    for (const auto &e : p.parts.present)
      if (e.second.get() == q) s.params = e.second;
    s.first             = d->fields;
    const size_t before = d->strain.size();
    s.count             = part->BuildAfter(*q, p, out, d, &s.built);
    for (size_t k = before; k < d->strain.size(); ++k) d->strain[k].account = StructureAccountOf(*part);
    out.push_back(s);
  }
  return out;
}

void StructurePartsFinish(BeamSystem *sys)
{
  PetscInt slot = 0;
  for (PartInstance &s : sys->parts) {
    s.part->AddMasses(s, sys);
    s.part->ForceTerms(s, *sys, &sys->forces.terms);
    s.part->RigidPoints(s, &sys->rigid_points);
    s.slot0 = slot;
    s.slots = (PetscInt)s.part->Slots().size();
    slot += s.slots;
  }
}

PetscInt StructurePartSlotCount(const BeamSystem &sys)
{
  PetscInt n = 0;
  for (const PartInstance &s : sys.parts) n += s.slots;
  return n;
}

void StructurePartsMeasure(const BeamSystem &sys, const PartState &st, PetscReal *slot)
{
  for (const PartInstance &s : sys.parts) s.part->Measure(s, sys, st, slot + s.slot0);
}

bool StructurePartsPeaks(const BeamSystem &sys)
{
  for (const PartInstance &s : sys.parts)
    if (s.slots > 0 || s.part->Peaks()) return true;
  return false;
}

void StructurePartsMeasureFrame(const BeamSystem &sys, const FrameMeasures &fm, PetscReal *slot)
{
  for (const PartInstance &s : sys.parts) s.part->MeasureFrame(s, fm, slot + s.slot0);
}

std::string StructurePartsRefusalWith(const BeamParams &p)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name())) {
      const std::string why = part->RefusalWith(*q, p);
      if (!why.empty()) return why;
    }
  return "";
}

bool StructurePartsTieToFrame(const BeamParams &p)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (part->TiesToFrame(*q)) return true;
  return false;
}

bool StructurePartsMonitor(const BeamParams &p)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (part->Monitors(*q)) return true;
  return false;
}

bool StructurePartsFaceGrid(const BeamParams &p, BedGrid *g)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (part->FaceGrid(*q, p, g)) return true;
  return false;
}

bool StructurePartsStrike(const BeamParams &p, PetscReal x, PetscReal z)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (part->Strikes(*q, x, z)) return true;
  return false;
}

bool StructurePartsHaveFace(const BeamParams &p)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (part->HasFace(*q)) return true;
  return false;
}

std::string StructurePartsPointRefusal(const BeamParams &p, const char *what, PetscReal z, bool held)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name())) {
      const std::string why = part->PointRefusal(*q, what, z, held);
      if (!why.empty()) return why;
    }
  return "";
}

bool StructurePartsInPlane(const BeamParams &p, PetscReal x, PetscReal z, PetscReal *stiffness, PetscReal *mass)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (part->InPlane(*q, x, z, stiffness, mass)) return true;
  return false;
}

std::string StructurePartsModalRefusal(const BeamParams &p)
{
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p.parts.Find(part->Name()))
      if (const char *why = part->ModalRefusal(*q)) return why;
  return "";
}

} // namespace beamimpact

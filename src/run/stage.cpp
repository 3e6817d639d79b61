// The registry of the stages after the contact and the loops over it. See stage.hpp.
#include "run/stage.hpp"

namespace beamimpact {

// The stages, one file each in run/stages/: a stage is its declaration here and its line in
// RunStages(), in the order they run.
const RunStage &TangentialStage(); // run/stages/tangential.cpp
const RunStage &FlightStage();     // run/stages/flight.cpp

const std::vector<const RunStage *> &RunStages()
{
  static const std::vector<const RunStage *> stages = {&TangentialStage(), &FlightStage()};
  return stages;
}

PetscErrorCode RunStagesRun(const StageInput &in, ObliqueRecord *rec)
{
  const std::vector<const RunStage *> &stages = RunStages();

  PetscFunctionBeginUser;
  rec->stages.assign(stages.size(), nullptr);
  if (!in.sc->oblique.on) PetscFunctionReturn(0); // no run along a normal: nothing after it
  ImpactStageScope scope(ImpactStage::Setup);     // -log_view: each stage its own
  for (size_t k = 0; k < stages.size(); ++k) {
    if (!stages[k]->Applies(*in.sc)) continue;
    scope.Switch(stages[k]->Name());
    PetscCall(stages[k]->Run(in, rec, &rec->stages[k]));
  }
  PetscFunctionReturn(0);
}

bool RunStagesNeedForce(const Scenario &sc)
{
  if (!sc.oblique.on) return false;
  for (const RunStage *s : RunStages())
    if (s->Applies(sc) && s->NeedsForce()) return true;
  return false;
}

void RunStagesSeries(const ObliqueRecord &rec, ImpactSeries *S)
{
  const std::vector<const RunStage *> &stages = RunStages();
  for (size_t k = 0; k < stages.size() && k < rec.stages.size(); ++k)
    if (rec.stages[k]) stages[k]->Series(*rec.stages[k], S);
}

double StageColumnValue(double (*compute)(const StageFacts &), size_t stage, const Scenario &sc,
                        const ObliqueRecord &rec)
{
  StageFacts f;
  f.sc      = &sc;
  f.oblique = &rec;
  f.own     = stage < rec.stages.size() ? rec.stages[stage].get() : nullptr;
  return compute(f);
}

} // namespace beamimpact

// The registry of the stages after the run along the normal: the work done once the ball has
// left the bat along the contact's normal, from what that run recorded (its F_n(t)). One file
// each in run/stages/ and one line in RunStages() (run/stage.cpp), in the order they run: the
// oblique impact's tangential contact and exit (stages/tangential.cpp), then the batted ball's
// flight (stages/flight.cpp). A stage brings when it applies, its work, what it keeps of it (its
// own StageResult), its results columns, its series and its summary line. The driver
// (run/impact_driver.cpp), the exact modal reference, the outcome, the results table, the impact
// file and the summary loop over them: no code outside a stage's file names it.
//
// How a stage is added: docs/design.md, "Adding a stage after the contact".
#pragma once

#include "run/impact.hpp"
#include "run/oblique.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

namespace beamimpact {

// What a stage reads of the run along the normal.
struct StageInput {
  const Scenario     *sc     = nullptr; // as run: an oblique impact's projection on the normal (sc->oblique.on)
  const ImpactSeries *series = nullptr; // F_n and dF_n/dt at the run's every step (the tangential contact's drive)
  PetscReal           u_n    = 0;       // m/s, the ball's normal speed after the run, away from the bat
  ObliqueBeam         beam;             // the run's system, the ball's coupling, the second plane's truncation
};

// What a stage keeps of its work beyond the shared record (derived in the stage's file).
struct StageResult {
  virtual ~StageResult() = default;
};

// What a stage's column reads: the scenario as run, the shared record (the exit, the tangential
// contact) and the stage's own result (nullptr when it did not run).
struct StageFacts {
  const Scenario      *sc      = nullptr;
  const ObliqueRecord *oblique = nullptr;
  const StageResult   *own     = nullptr;
};

// A results column a stage registers: name, unit ("1": dimensionless), description (one line),
// when it applies (a predicate of the scenario, given or as run; NaN elsewhere) and in words,
// and how the outcome computes it.
struct StageColumn {
  const char *name, *unit, *description;
  bool (*applies)(const Scenario &sc);
  const char *applies_text;
  double (*compute)(const StageFacts &f);
};

class RunStage {
public:
  virtual ~RunStage() = default;
  // "tangential": registry key; -log_view's stage "beamimpact: <name>".
  virtual const char *Name() const = 0;
  // Whether it runs on sc (the scenario as given or as run: an oblique impact's projection).
  virtual bool Applies(const Scenario &sc) const = 0;
  // Its work after the stages before it (in.sc as run), into the shared record and *own.
  virtual PetscErrorCode Run(const StageInput &in, ObliqueRecord *rec,
                             std::shared_ptr<const StageResult> *own) const = 0;
  // Whether it reads the run's F_n(t) (StageInput::series): the run records it for the stages
  // (ImpactRecord::drive), apart from the series a user asked for.
  virtual bool                     NeedsForce() const { return false; }
  virtual std::vector<StageColumn> Columns() const { return {}; }
  // Its series from its own result, appended to S->keyed (/series/<name>).
  virtual void Series(const StageResult &, ImpactSeries *) const { }
  // The run summary's lines (each ending in a newline; "" for none) from the scenario as given and
  // its columns' values, in Columns()'s order, then SummaryColumns()'s (any module's, by name).
  virtual std::vector<const char *> SummaryColumns() const { return {}; }
  virtual std::string               Summary(const Scenario &, const std::vector<double> &) const { return ""; }
};

// The registry, in the order the stages run (run/stage.cpp).
const std::vector<const RunStage *> &RunStages();

// Every stage that applies to in.sc, in order, each in its own -log_view stage; rec->stages[k]:
// the k-th registered stage's own result (nullptr: it did not run).
PetscErrorCode RunStagesRun(const StageInput &in, ObliqueRecord *rec);

// Whether a stage that applies to sc (as run) needs the run's F_n(t).
bool RunStagesNeedForce(const Scenario &sc);

// Each stage's series from its own result, into S (the outcome).
void RunStagesSeries(const ObliqueRecord &rec, ImpactSeries *S);

// A column's value: compute (a column of the stage-th registered stage) on sc as run and rec.
double StageColumnValue(double (*compute)(const StageFacts &), size_t stage, const Scenario &sc,
                        const ObliqueRecord &rec);

} // namespace beamimpact

// -task convergence, the output: the HDF5 file (root attributes, /reference, /configs/<name>,
// /summary, /spatial) and the printed tables (each run, the reference, the observed orders, the
// cost at the target, the spatial study). The file's layout is in docs/convergence.md.
#pragma once

#include "io/run_record.hpp"
#include "studies/convergence_analysis.hpp"

#include <string>
#include <vector>

namespace beamimpact {

// A column of /configs/<name> (one row per level of the configuration), defined once: the file
// and the results reference (docs/results.md, beamimpact -help_markdown results) follow it.
struct ConvergenceRunColumn {
  const char *name;
  const char *unit;        // the dataset's unit attribute, as written ("1 (relative)")
  const char *description; // one line
  bool        integer;     // a count or a flag: an integer dataset
  double (*get)(const ConvergenceConfig &cfg, const ConvergenceRun &run);
};
const std::vector<ConvergenceRunColumn> &ConvergenceRunColumns();

// The file's root attributes: the scenario, its effective times and the plan.
PetscErrorCode ConvergenceRecordBuild(const Scenario &sc, const ConvergencePlan &plan, RunRecord *record);

// Writes the file on rank 0 of comm: the record, the reference (when the temporal study ran),
// every configuration's runs and orders, the summary, the spatial study (when it ran).
PetscErrorCode ConvergenceFileWrite(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                    const ConvergencePlan &plan, const ConvergenceReference *ref,
                                    const std::vector<std::vector<ConvergenceRun>> &all, const RunRecord &summary,
                                    const ConvergenceSpatial *sp);

// The printed tables.
PetscErrorCode ConvergencePrintRun(MPI_Comm comm, const ConvergenceConfig &cfg, const ConvergenceRun &run);
PetscErrorCode ConvergencePrintReference(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceReference &ref);
PetscErrorCode ConvergencePrintOrders(MPI_Comm comm, const ConvergencePlan &plan,
                                      const std::vector<std::vector<ConvergenceRun>> &all);
// The cost of each configuration at -convergence_target, the best PETSc configuration against
// the leapfrog baseline; the same numbers go to *summary for the file.
PetscErrorCode ConvergencePrintCostAtTarget(MPI_Comm comm, const ConvergencePlan &plan,
                                            const std::vector<std::vector<ConvergenceRun>> &all, RunRecord *summary);
// One N of the spatial study, and its continuum limit and observed orders.
PetscErrorCode ConvergencePrintSpatialLevel(MPI_Comm comm, PetscInt N, PetscReal h, const ConvergenceReference &ref);
PetscErrorCode ConvergencePrintSpatial(MPI_Comm comm, const ConvergenceSpatial &sp);

} // namespace beamimpact

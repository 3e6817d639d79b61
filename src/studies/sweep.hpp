// -task sweep: the outcome of many impacts (ACOR against impact point, ball speed, beam
// thickness, grid size, ...: any numeric option), farmed out over MPI ranks, in one HDF5 file.
//
//   mpirun -n 4 beamimpact -task sweep -sweep "impact_x=0:1.1:111,beam_thickness=4e-3;6e-3" -output acor.h5
//
// Four parts, kept apart:
//   * the plan (sweep_plan.hpp): which cases exist, the product of axes, each an option
//     of the program, and the scenario of a case (the options read with its values set);
//   * the case runner (here): case index -> one row of numbers (ImpactRun on a
//     group communicator, plus the rigid-body columns of Eq. 11); a case whose run
//     fails is a row too, with a status code, its reason and NaN numbers;
//   * the farm (sweep_farm.hpp): hands out case indices to groups of ranks with
//     dynamic load balancing, through an MPI-3 atomic counter on world rank 0
//     (no dedicated coordinator rank);
//   * the store (sweep_store.hpp): rows are journaled by each group leader as
//     they complete and the HDF5 file is rewritten atomically by rank 0 (see
//     docs/sweep.md), so the file is readable during the run, never corrupt
//     after kill -9, and a rerun of the same command resumes where the last one
//     stopped.
#pragma once

#include "run/impact.hpp"
#include "run/scenario.hpp"
#include "studies/sweep_plan.hpp"
#include "studies/sweep_store.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// The columns of a sweep row: case_index, one per axis (named after its option), status
// (SweepStatus), then the results table (run/results_table.hpp; its rigid_acor with f given by
// -rigid_loss_fraction).
std::vector<SweepColumn> SweepColumns(const SweepPlan &plan);

// Runs case `index` on comm (all its ranks) and returns its row on every rank; a case that
// fails gives a row with its status, NaN numbers and *reason (the error's first line).
// Errors out only when the case's scenario cannot be read (checked before any work). reuse
// (may be NULL): what the rank keeps across its cases; the row is the same with or without it,
// bit for bit.
struct SweepReuse;
PetscErrorCode SweepCaseRun(MPI_Comm comm, const SweepPlan &plan, PetscInt index, std::vector<double> *row,
                            std::string *reason, ImpactResult *result, SweepReuse *reuse = nullptr);

// What a rank keeps across the points it runs, so that a point redoes only what changes with
// it: the structure's scenario (only the point's parts read again: SweepCaseScenario) and the
// structure's system (BeamSystemBuild once per structure: ImpactStructure), dropped when a
// point is on another structure (a structure axis changes: beam_nodes, a beam_* property,
// ts_type, ...) or a shell's contact radius, resolved per point from the ball, changes.
struct SweepReuse {
  SweepScenarioCache     scenario;
  ImpactStructure        structure;
  std::vector<PetscReal> part_key;    // the structure parts' SystemKey the structure's system has (a shell's a, m)
  PetscInt               systems = 0; // systems built (structure.sys set by a run)
};

// The status of a failed run from its PETSc error code (SweepStatus).
int SweepStatusOfError(PetscErrorCode ierr);

// -task sweep: reads the options, runs the plan (resuming from -output when it
// holds part of the same sweep) and writes -output.
// The sweep's points that failed end it with a nonzero exit status: the program's exit
// status after TaskSweep (0, or 2 when some points of the file failed).
PetscErrorCode TaskSweep(MPI_Comm comm, const std::string &output);
int            SweepExitStatus();

} // namespace beamimpact

// -task sweep: the outcome of many impacts (ACOR against impact point, and
// later other parameters), farmed out over MPI ranks, in one HDF5 file.
//
//   mpirun -n 4 beamimpact -task sweep -sweep_x 0:1.1:111 -output acor.h5
//
// Three layers, kept apart:
//   * the plan: which cases exist (SweepPlan, a product of axes; now only x);
//   * the case runner: case index -> one row of numbers (ImpactRun on a group
//     communicator, plus the rigid-body columns of Eq. 11);
//   * the farm: hands out case indices to groups of ranks with dynamic load
//     balancing, through an MPI-3 atomic counter on world rank 0 (no dedicated
//     coordinator rank).
// Rows are journaled by each group leader as they complete and the HDF5 file
// is rewritten atomically by rank 0 (see sweep.cpp and docs/sweep.md), so the
// file is readable during the run, never corrupt after kill -9, and a rerun of
// the same command resumes where the last one stopped.
#pragma once

#include "model/beam.hpp"
#include "model/contact.hpp"
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <functional>
#include <string>
#include <vector>

namespace beamimpact {

// One swept parameter: its name (the column it fills), unit and values.
struct SweepAxis {
  std::string            name;   // "x": the impact point
  std::string            unit;   // "m"
  std::vector<PetscReal> values; // in the given order
};

// -sweep_* options and -rigid_loss_fraction. The cases are the product of the
// axes with the last axis varying fastest; case indices number them from 0.
struct SweepPlan {
  std::vector<SweepAxis> axes;                     // now exactly one: x
  std::string            x_spec;                   // -sweep_x as given (recorded in the file)
  PetscInt               ranks_per_case = 1;       // ranks solving one impact together (DMDA distributed over them)
  PetscReal              rigid_loss_fraction = 0;  // f of Eq. (11) for the rigid_acor column (dimensionless)
  PetscBool              quiet = PETSC_FALSE;      // no progress or summary lines
  PetscBool              restart = PETSC_FALSE;    // discard an existing -output file and its journal
  PetscReal              progress_interval = 2;    // s, at most one progress line per interval
  PetscReal              write_interval = 5;       // s, minimum time between live rewrites of the file

  PetscInt cases() const;
  // The value of every axis for case `index` (axis order).
  std::vector<PetscReal> CaseValues(PetscInt index) const;
};

// Parses a list of points: "start:stop:count" (count points from start to stop,
// both included, like numpy.linspace) or "x1,x2,...". Returns false with a
// reason in *why when the text is not of either form.
bool SweepParsePoints(const std::string &spec, std::vector<PetscReal> *values, std::string *why);

// Reads -sweep_x, -sweep_ranks_per_case, -sweep_quiet, -sweep_restart,
// -sweep_progress_interval, -sweep_write_interval and -rigid_loss_fraction;
// checks every point against the beam (on it, and not a held point).
PetscErrorCode SweepPlanFromOptions(MPI_Comm comm, const BeamParams &beam, SweepPlan *plan);

// The inputs of one case: the base scenario with the plan's axis values set (its monitor
// holds only -monitor_segment, whose peak is a column; no time series in a sweep).
Scenario SweepCaseFor(const SweepPlan &plan, const Scenario &base, PetscInt index);

// The columns of a sweep row: case_index, every ImpactResultColumns() quantity,
// rigid_acor (Eq. 11 with f given by -rigid_loss_fraction, M = mu L, I_cm = M L^2/12,
// b_cm = |x - L/2|) and rigid_forced_loss_fraction (the f for which Eq. 11
// gives acor_corrected).
struct SweepColumn {
  std::string name;
  std::string unit;
  bool        timing; // differs from run to run (wall_time): excluded from identity checks
};
const std::vector<SweepColumn> &SweepColumns();

// Runs case `index` on comm (all its ranks) and returns its row on every rank.
PetscErrorCode SweepCaseRun(MPI_Comm comm, const SweepPlan &plan, const Scenario &base, PetscInt index, std::vector<double> *row, ImpactResult *result);

// Dynamic load balancing without a coordinator rank: world rank 0 exposes two
// counters (next task, tasks done) in an MPI window; the leader of each group
// of ranks_per_case ranks takes the next task with MPI_Fetch_and_op and
// broadcasts it in its group. Ranks left over when the world size is not a
// multiple of ranks_per_case stay idle.
struct TaskFarm {
  MPI_Comm    world = MPI_COMM_NULL;
  MPI_Comm    group = MPI_COMM_NULL; // this rank's group; MPI_COMM_NULL on an idle rank
  PetscMPIInt world_rank = 0, world_size = 1, group_rank = 0, group_size = 1;
  PetscInt    ranks_per_case = 1, groups = 1;
  MPI_Win     win = MPI_WIN_NULL;
  void       *base = nullptr; // the counters (world rank 0 only)
};
PetscErrorCode TaskFarmCreate(MPI_Comm world, PetscInt ranks_per_case, TaskFarm *farm);
// Runs tasks 0..ntasks-1: run(group, task) on every rank of the group that
// takes it (the task counts as done when run returns on the group leader);
// between(done) on world rank 0 between its tasks and while it waits for the
// others. Returns on every rank once all tasks are done; idle ranks wait with
// short sleeps, not in a spinning MPI call.
PetscErrorCode TaskFarmRun(TaskFarm &farm, PetscInt ntasks, const std::function<PetscErrorCode(MPI_Comm, PetscInt)> &run, const std::function<PetscErrorCode(PetscInt)> &between);
PetscErrorCode TaskFarmDestroy(TaskFarm *farm);

// -task sweep: reads the options, runs the plan (resuming from -output when it
// holds part of the same sweep) and writes -output.
PetscErrorCode TaskSweep(MPI_Comm comm, const std::string &output);

} // namespace beamimpact

// Dynamic load balancing of a sweep's cases over MPI ranks, without a coordinator rank:
// groups of ranks take the next case from an MPI-3 atomic counter on world rank 0.
#pragma once

#include <petscsys.h>

#include <functional>

namespace beamimpact {

// World rank 0 exposes three counters (next task, tasks done, stop) in an MPI window; the
// leader of each group of ranks_per_case ranks takes the next task with
// MPI_Fetch_and_op and broadcasts it in its group. Ranks left over when the world
// size is not a multiple of ranks_per_case stay idle.
struct TaskFarm {
  MPI_Comm    world      = MPI_COMM_NULL;
  MPI_Comm    group      = MPI_COMM_NULL; // this rank's group; MPI_COMM_NULL on an idle rank
  PetscMPIInt world_rank = 0, world_size = 1, group_rank = 0, group_size = 1;
  PetscInt    ranks_per_case = 1, groups = 1;
  MPI_Win     win     = MPI_WIN_NULL;
  void       *base    = nullptr; // the counters (world rank 0 only)
  double      handout = 0;       // s this rank spent taking tasks from the counter and passing them on
};
PetscErrorCode TaskFarmCreate(MPI_Comm world, PetscInt ranks_per_case, TaskFarm *farm);
// Runs tasks 0..ntasks-1: run(group, task) on every rank of the group that
// takes it (the task counts as done when run returns on the group leader);
// between(done) on world rank 0 between its tasks and while it waits for the
// others. Returns on every rank once all tasks are done; idle ranks wait with
// short sleeps, not in a spinning MPI call. When between fails on rank 0 (its rewrite of the
// file on a full disk), no further task is handed out and every rank returns an error once its
// current task is done: rank 0 with between's, the others saying rank 0 stopped the farm (so
// that they all end together, app/main.cpp, not in MPI_Abort waiting for rank 0).
PetscErrorCode TaskFarmRun(TaskFarm &farm, PetscInt ntasks,
                           const std::function<PetscErrorCode(MPI_Comm, PetscInt)> &run,
                           const std::function<PetscErrorCode(PetscInt)>           &between);
PetscErrorCode TaskFarmDestroy(TaskFarm *farm);

} // namespace beamimpact

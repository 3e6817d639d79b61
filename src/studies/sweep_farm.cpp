// The task farm of a sweep. See sweep_farm.hpp.
#include "studies/sweep_farm.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <thread>

namespace beamimpact {

enum FarmCounter {
  FarmNext     = 0,
  FarmDone     = 1,
  FarmStop     = 2,
  FarmCounters = 3
};

static PetscErrorCode FarmFetchAdd(TaskFarm &f, FarmCounter which, int64_t add, int64_t *old)
{
  int64_t result = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, f.win));
  PetscCallMPI(MPI_Fetch_and_op(&add, &result, MPI_INT64_T, 0, (MPI_Aint)which, add ? MPI_SUM : MPI_NO_OP, f.win));
  PetscCallMPI(MPI_Win_unlock(0, f.win));
  if (old) *old = result;
  PetscFunctionReturn(0);
}

PetscErrorCode TaskFarmCreate(MPI_Comm world, PetscInt ranks_per_case, TaskFarm *farm)
{
  PetscFunctionBeginUser;
  farm->world = world;
  PetscCallMPI(MPI_Comm_rank(world, &farm->world_rank));
  PetscCallMPI(MPI_Comm_size(world, &farm->world_size));
  PetscCheck(ranks_per_case >= 1 && ranks_per_case <= farm->world_size, world, PETSC_ERR_ARG_OUTOFRANGE,
             "-sweep_ranks_per_case %" PetscInt_FMT " is not allowed with %d MPI ranks: use 1 <= ranks_per_case <= %d",
             ranks_per_case, farm->world_size, farm->world_size);
  farm->ranks_per_case = ranks_per_case;
  farm->groups         = farm->world_size / ranks_per_case;
  const int color      = farm->world_rank < farm->groups * ranks_per_case ? (int)(farm->world_rank / ranks_per_case)
                                                                          : MPI_UNDEFINED;
  PetscCallMPI(MPI_Comm_split(world, color, farm->world_rank, &farm->group));
  if (farm->group != MPI_COMM_NULL) {
    PetscCallMPI(MPI_Comm_rank(farm->group, &farm->group_rank));
    PetscCallMPI(MPI_Comm_size(farm->group, &farm->group_size));
  }
  MPI_Info info;
  PetscCallMPI(MPI_Info_create(&info));
  PetscCallMPI(MPI_Info_set(info, "accumulate_ops", "same_op_no_op"));
  const MPI_Aint bytes = farm->world_rank == 0 ? (MPI_Aint)(FarmCounters * sizeof(int64_t)) : 0;
  PetscCallMPI(MPI_Win_allocate(bytes, sizeof(int64_t), info, world, &farm->base, &farm->win));
  PetscCallMPI(MPI_Info_free(&info));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskFarmDestroy(TaskFarm *farm)
{
  PetscFunctionBeginUser;
  if (farm->win != MPI_WIN_NULL) PetscCallMPI(MPI_Win_free(&farm->win));
  if (farm->group != MPI_COMM_NULL) PetscCallMPI(MPI_Comm_free(&farm->group));
  PetscFunctionReturn(0);
}

// Rank 0 after between failed: no task is handed out any more (next pushed past the end) and
// the others see the stop flag.
static PetscErrorCode FarmStopAll(TaskFarm &f, PetscInt ntasks)
{
  PetscFunctionBeginUser;
  PetscCall(FarmFetchAdd(f, FarmNext, (int64_t)ntasks + 1, nullptr));
  PetscCall(FarmFetchAdd(f, FarmStop, 1, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskFarmRun(TaskFarm &farm, PetscInt ntasks,
                           const std::function<PetscErrorCode(MPI_Comm, PetscInt)> &run,
                           const std::function<PetscErrorCode(PetscInt)>           &between)
{
  int64_t        done = 0, stop = 0;
  PetscErrorCode failed = 0; // rank 0: between's error, returned once its group has stopped too

  PetscFunctionBeginUser;
  if (farm.world_rank == 0) {
    PetscCallMPI(MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, farm.win));
    for (int c = 0; c < FarmCounters; ++c) static_cast<int64_t *>(farm.base)[c] = 0;
    PetscCallMPI(MPI_Win_unlock(0, farm.win));
  }
  PetscCallMPI(MPI_Barrier(farm.world));
  if (farm.group != MPI_COMM_NULL) {
    for (;;) {
      int64_t      t  = -1;
      const double h0 = MPI_Wtime();
      if (farm.group_rank == 0 && !failed) {
        PetscCall(FarmFetchAdd(farm, FarmNext, 1, &t));
        if (t >= ntasks) t = -1;
      }
      if (farm.group_size > 1) PetscCallMPI(MPI_Bcast(&t, 1, MPI_INT64_T, 0, farm.group));
      farm.handout += MPI_Wtime() - h0;
      if (t < 0) break;
      PetscCall(run(farm.group, (PetscInt)t));
      const double h1 = MPI_Wtime();
      if (farm.group_rank == 0) PetscCall(FarmFetchAdd(farm, FarmDone, 1, &done));
      farm.handout += MPI_Wtime() - h1;
      if (farm.world_rank == 0 && (failed = between((PetscInt)done + 1))) PetscCall(FarmStopAll(farm, ntasks));
    }
  }
  PetscCall(failed);
  // Out of tasks: wait for the others with growing sleeps (an idle rank must
  // not spin in MPI and take a core from a working one).
  // The longest nap grows with the number of ranks so that rank 0 answers at
  // most a few thousand polls per second.
  const double nap_max = std::min(1.0, 2e-2 * std::ceil(farm.world_size / 64.0));
  double       nap     = 2e-4;
  for (;;) {
    PetscCall(FarmFetchAdd(farm, FarmDone, 0, &done));
    if (farm.world_rank == 0 && (failed = between((PetscInt)done))) {
      PetscCall(FarmStopAll(farm, ntasks));
      PetscCall(failed);
    }
    PetscCall(FarmFetchAdd(farm, FarmStop, 0, &stop));
    PetscCheck(!stop, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
               "the sweep was stopped by rank 0's error (its message is the run's)");
    if (done >= ntasks) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(farm.world_rank == 0 ? std::min(nap, 2e-2) : nap));
    nap = std::min(nap_max, nap * 1.5);
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

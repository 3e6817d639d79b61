// GoogleTest main for MPI + PETSc tests: gtest flags are parsed before
// PetscInitialize, only rank 0 prints, and the result is agreed on all ranks.
#include "app/registry.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

int main(int argc, char **argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  PetscCall(PetscInitialize(&argc, &argv, NULL, "beamimpact unit tests"));
  PetscCall(beamimpact::RegisterAll());
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank != 0) {
    auto &listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int local = RUN_ALL_TESTS(), global = 0;
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCall(PetscFinalize());
  return global;
}

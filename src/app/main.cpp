// beamimpact: a ball striking a flexible beam, bat or racket.
//
//   mpirun -n 2 beamimpact -options_file options/default.opts
//   beamimpact -task impact -impact_x 0.9 -ts_type cn -ts_dt 1e-5
//   beamimpact -task modes -beam_left clamped -modes_count 4
//
// The driver only initialises, dispatches the task and finalises. Errors are
// reported as one plain message (the option, the value, what is allowed);
// -error_traceback shows PETSc's full traceback instead.
#include "app/tasks.hpp"
#include "io/text.hpp"
#include "studies/sweep.hpp"

#include <slepcsys.h>

static const char help[] = "beamimpact: a ball striking a flexible beam (R. Cross, Am. J. Phys. 67, 692 (1999)).\n"
                           "  -task impact|modes, -output FILE.h5, and the -beam_, -ball_, -impact_, -monitor_, -modes_ and -ts_ options below.\n"
                           "  Example: mpirun -n 2 beamimpact -options_file options/default.opts\n\n";

int main(int argc, char **argv)
{
  PetscBool traceback = PETSC_FALSE;

  PetscCall(SlepcInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-error_traceback", &traceback, NULL));
  if (!traceback) PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  PetscErrorCode ierr = beamimpact::RunTask(PETSC_COMM_WORLD);
  if (ierr) {
    const std::string msg = beamimpact::LastErrorMessage(ierr);
    PetscMPIInt       rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank == 0) fprintf(stderr, "beamimpact: error: %s\n", msg.c_str());
    fflush(stderr);
    PetscMPIInt size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    if (size > 1) MPI_Abort(PETSC_COMM_WORLD, 1); // other ranks may be stuck in a collective
    PetscPopErrorHandler();
    SlepcFinalize();
    return 1;
  }
  if (!traceback) PetscCall(PetscPopErrorHandler());
  PetscCall(SlepcFinalize());
  return beamimpact::SweepExitStatus(); // 2: a sweep completed with failed points
}

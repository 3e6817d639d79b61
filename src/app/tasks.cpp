// Task drivers: option reading, runs, summaries and files. See tasks.hpp.
#include "app/tasks.hpp"

#include "studies/convergence.hpp"
#include "solvers/modal_reference.hpp"
#include "solvers/modes.hpp"
#include "io/options_util.hpp"
#include "io/scenario_options.hpp"
#include "studies/sweep.hpp"

#include <hdf5.h>
#include <petscts.h>

namespace beamimpact {

static const char *const ReferenceNames[] = {"ts", "modal", "Reference", "REFERENCE_", nullptr};
static const char *const TaskNames[] = {"impact", "modes", "sweep", "convergence", "Task", "TASK_", nullptr};

PetscErrorCode ImpactPrintSummary(MPI_Comm comm, const ImpactResult &r)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "x %.4f m  acor %.6f  acor_corrected %.6f  contact_time %.4e s  peak_force %.4e N  max_compression %.4e m  contacts %" PetscInt_FMT
                        "  steps %" PetscInt_FMT "  rejected %" PetscInt_FMT "  failed %" PetscInt_FMT "  fevals %" PetscInt_FMT "  wall %.3e s%s\n",
                        (double)r.x, (double)r.acor, (double)r.acor_corrected, (double)r.contact_time, (double)r.peak_force, (double)r.max_compression, r.contacts, r.steps + r.event_steps,
                        r.rejected_steps, r.failed_solves, r.function_evals, (double)r.wall_time, r.ended_in_contact ? "  (ended in contact: raise -impact_max_time)" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode TaskImpact(MPI_Comm comm, const std::string &output)
{
  Scenario     sc;
  ImpactResult res;

  PetscFunctionBeginUser;
  PetscCall(ScenarioFromOptions(comm, &sc));
  PetscEnum reference = (PetscEnum)0;
  PetscOptionsBegin(comm, NULL, "Impact task", "beamimpact");
  PetscCall(PetscOptionsEnum("-reference", "ts: integrate with the PETSc TS; modal: the exact modal solution (linear spring; no time step, only round-off)", "", ReferenceNames, reference, &reference, NULL));
  PetscOptionsEnd();
  if (reference == 1) {
    PetscCheck(!sc.monitor.any() && sc.monitor.snapshot_times.empty(), comm, PETSC_ERR_SUP, "-reference modal records no time series or snapshots: remove the -monitor_*/-snapshot_times options");
    PetscCall(OptionsCheckUnused(comm, {"ts_", "snes_", "ksp_", "pc_"})); // integrator options have no effect here
    PetscCall(ModalReferenceRun(sc, &res));
    PetscCall(PetscPrintf(comm, "ts %s (%s)  dt %.3e s\n", res.ts_type.c_str(), res.formulation.c_str(), (double)res.dt_nominal));
  } else {
    sc.impact.check_unused_options = PETSC_TRUE;
    sc.impact.report_setup         = PETSC_TRUE; // integrator, step and stability limit before the run
    PetscCall(ImpactRun(comm, sc, &res));
  }
  PetscCall(ImpactPrintSummary(comm, res));
  if (!output.empty()) {
    RunRecord rec;
    PetscCall(RunRecordBuild(sc, &res, &rec));
    PetscCall(ResultsWriteImpactFile(comm, output, rec, {res}, sc.beam));
    PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TaskModes(MPI_Comm comm, const std::string &output)
{
  BeamParams  beam;
  ModesParams mp;
  ModesResult modes;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(BeamParamsFromOptions(comm, &beam));
  const BeamOperator op = BeamOperatorBuild(beam);
  PetscCall(ModesParamsFromOptions(comm, &mp, &op));
  PetscCall(OptionsCheckUnused(comm));
  PetscCall(BeamModesCompute(comm, op, mp.count, &modes));
  PetscCall(PetscPrintf(comm, "modes of the %g m beam (%s-%s, N = %" PetscInt_FMT "):\n  mode  frequency (Hz)  period (ms)\n", (double)beam.length, SupportName(beam.left), SupportName(beam.right), beam.nodes));
  for (size_t q = 0; q < modes.frequency.size(); ++q)
    PetscCall(PetscPrintf(comm, "  %4d  %14.4f  %11.4f%s\n", (int)q + 1, (double)modes.frequency[q], (double)modes.period[q] * 1e3, modes.omega[q] == 0 ? "  (rigid)" : ""));
  if (!output.empty() && rank == 0) {
    RunRecord rec;
    PetscCall(RunRecordBuild(beam, &rec));
    hid_t file = H5Fcreate(output.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot create the HDF5 file", output.c_str());
    PetscCall(H5WriteAttributes(file, rec));
    hid_t g = H5Gcreate2(file, "modes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    PetscCall(H5WriteDataset1D(g, "frequency", modes.frequency, "Hz"));
    PetscCall(H5WriteDataset1D(g, "period", modes.period, "s"));
    PetscCall(H5WriteDataset1D(g, "omega", modes.omega, "rad/s"));
    H5Gclose(g);
    H5Fclose(file);
  }
  if (!output.empty()) PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode RunTask(MPI_Comm comm)
{
  PetscEnum task = (PetscEnum)Task::Impact;
  char      output[PETSC_MAX_PATH_LEN] = "";
  PetscBool set_output;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "beamimpact: task and output", "beamimpact");
  PetscCall(PetscOptionsEnum("-task", "What to compute", "", TaskNames, task, &task, NULL));
  PetscCall(PetscOptionsString("-output", "HDF5 file to write (default: <task>.h5; 'none' writes nothing)", "", output, output, sizeof(output), &set_output));
  PetscOptionsEnd();
  std::string out = set_output ? output : std::string(TaskNames[task]) + ".h5";
  if (out == "none") out.clear();
  switch ((Task)task) {
  case Task::Impact: PetscCall(TaskImpact(comm, out)); break;
  case Task::Modes: PetscCall(TaskModes(comm, out)); break;
  case Task::Sweep: PetscCall(TaskSweep(comm, out)); break;
  case Task::Convergence: PetscCall(TaskConvergence(comm, out)); break;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

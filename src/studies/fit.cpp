// -task fit: the task. See fit.hpp.
#include "studies/fit.hpp"

#include "base/options_util.hpp"
#include "studies/fit_problem.hpp"
#include "studies/sweep_notes.hpp"

#include <fstream>
#include <sstream>

namespace beamimpact {

namespace {

// Rank 0 reads -fit_data; every rank gets its text.
PetscErrorCode ReadDataText(MPI_Comm comm, const std::string &file, std::string *text)
{
  PetscMPIInt rank;
  long long   size = -1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::ifstream in(file, std::ios::binary);
    if (in) {
      std::ostringstream all;
      all << in.rdbuf();
      *text = all.str();
      size  = (long long)text->size();
    }
  }
  PetscCallMPI(MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, comm));
  PetscCheck(size >= 0, comm, PETSC_ERR_FILE_OPEN, "-fit_data %s cannot be read (no such file, or not readable)",
             file.c_str());
  text->resize((size_t)size);
  if (size > 0) PetscCallMPI(MPI_Bcast(&(*text)[0], (int)size, MPI_CHAR, 0, comm));
  PetscFunctionReturn(0);
}

// The settings, the parameters and the data, every error naming what is wrong.
PetscErrorCode FitSetUp(MPI_Comm comm, const std::string &output, FitProblem *f)
{
  std::string why, text;

  PetscFunctionBeginUser;
  f->world = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &f->rank));
  PetscCall(FitSettingsFromOptions(comm, output, &f->settings));
  PetscCheck(FitParseParameters(f->settings.parameters, &f->params, &why), comm, PETSC_ERR_ARG_WRONG,
             "-fit_parameters \"%s\" is not allowed: %s", f->settings.parameters.c_str(), why.c_str());
  PetscCall(ReadDataText(comm, f->settings.data, &text));
  PetscCheck(FitParseData(f->settings.data, text, *f->settings.task, f->settings.sigma, f->params, &f->data, &why),
             comm, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  PetscCall(FitCheckOutputs(comm, output, f->settings));
  CaseBatchSettings s;
  s.task         = f->settings.task;
  s.columns      = f->data.measured;
  s.store        = output;
  s.own_prefixes = {"fit_", "tao_"};
  s.restart      = f->settings.restart;
  s.stop_after   = f->settings.stop_after;
  s.who          = "fit";
  PetscCall(CaseBatchCreate(comm, s, &f->batch));
  PetscFunctionReturn(0);
}

PetscErrorCode FitAnnounce(const FitProblem &f, const std::string &output)
{
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(f.world, &size));
  std::string params;
  for (const FitParameter &q : f.params) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "\n  %s in [%g, %g]%s%s, %s, from %.10g (%s)", q.name.c_str(), q.lo, q.hi,
                  q.unit.empty() || q.unit == "1" ? "" : " ", q.unit == "1" ? "" : q.unit.c_str(),
                  q.log ? "log-scaled" : "linear", q.start, q.start_from.c_str());
    params += buf;
  }
  PetscCall(PetscPrintf(f.world,
                        "fit: %zu measured values (%zu rows of %s, -fit_task %s) on %d rank(s); %zu parameters:%s\n",
                        f.m(), f.data.rows.size(), f.data.file.c_str(), f.settings.task->name, (int)size, f.n(),
                        params.c_str()));
  PetscCall(PetscPrintf(f.world, "fit: weights: %s\n", f.data.sigma_text.c_str()));
  const CaseBatchCounts &c = f.batch.counts;
  if (c.loaded + c.loaded_journal > 0)
    PetscCall(PetscPrintf(f.world,
                          "fit: %d runs known from an earlier fit into %s (%d from its file, %d from the journals of a "
                          "run that stopped)\n",
                          (int)(c.loaded + c.loaded_journal), output.c_str(), (int)c.loaded, (int)c.loaded_journal));
  PetscFunctionReturn(0);
}

PetscErrorCode FitReportRuns(const FitProblem &f)
{
  CaseBatchCounts c;

  PetscFunctionBeginUser;
  PetscCall(CaseBatchGetCounts(f.batch, &c));
  PetscCall(PetscPrintf(f.world,
                        "fit: runs: %d computed (%.3g s of the ranks' time, %.3g s a run), %d answered from runs known "
                        "(this fit's or an earlier one's)\n",
                        (int)c.computed, c.run_time, c.computed ? c.run_time / c.computed : 0.0, (int)c.reused));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TaskFit(MPI_Comm comm, const std::string &output)
{
  FitProblem f;
  FitResult  res;

  PetscFunctionBeginUser;
  struct Guard { // an error return: the lock released, the journals kept, no collective call
    FitProblem &f;
    ~Guard()
    {
      SweepNotesAbandon();
      CaseBatchRelease(&f.batch);
    }
  } guard{f};
  PetscCall(SweepNotesBegin()); // each run's notes said once for the fit
  PetscCall(FitSetUp(comm, output, &f));
  PetscCall(FitAnnounce(f, output));
  PetscCall(FitSolve(f, &res)); // its first residual checks the options nobody read
  PetscCall(FitUncertaintyAtOptimum(f, &res));
  PetscCall(SweepNotesEnd(comm, f.batch.counts.computed));
  PetscCall(FitReportRuns(f));
  PetscCall(FitPrintSummary(f, res));
  PetscCall(FitWriteOutputs(f, res, output));
  PetscCall(CaseBatchDestroy(&f.batch));
  PetscFunctionReturn(0);
}

PetscErrorCode FitHelpOptions(MPI_Comm comm)
{
  FitSettings s;
  Tao         tao;

  PetscFunctionBeginUser;
  (void)FitSettingsFromOptions(comm, "", &s); // its checks' errors are not what -help asks
  if (!TaoCreate(comm, &tao)) {
    (void)FitTaoDefaults(tao);
    (void)TaoSetFromOptions(tao);
    (void)TaoDestroy(&tao);
  }
  PetscCall(OptionModulePrintHelp(comm, TaoOptionTable()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

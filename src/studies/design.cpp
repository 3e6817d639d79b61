// -task design: the task. See design.hpp.
#include "studies/design.hpp"

#include "base/options_util.hpp"
#include "studies/design_problem.hpp"
#include "studies/sweep_notes.hpp"

#include <cstdio>

namespace beamimpact {

namespace {

int g_exit_status = 0; // DesignExitStatus()

// The settings, the variables, the studies, the objective and the constraints, every error naming
// what is wrong; then the case batch (its journal and the rows of an earlier design into -output).
PetscErrorCode DesignSetUp(MPI_Comm comm, const std::string &output, DesignProblem *d)
{
  std::string why;

  PetscFunctionBeginUser;
  d->world = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &d->rank));
  DesignSettings &s = d->settings;
  PetscCall(DesignSettingsFromOptions(comm, output, &s));
  PetscCheck(FitParseParameters(s.variables, &d->vars, &why), comm, PETSC_ERR_ARG_WRONG,
             "-design_variables \"%s\" is not allowed: %s", s.variables.c_str(), why.c_str());
  PetscCheck(DesignParseStudies(s.studies, &d->studies, &why), comm, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  PetscCheck(DesignParseQuantity(s.objective, d->studies, &d->columns, &d->objective, &why), comm, PETSC_ERR_ARG_WRONG,
             "-design_objective \"%s\" is not allowed: %s", s.objective.c_str(), why.c_str());
  PetscCheck(DesignParseConstraints(s.constraints, d->studies, &d->columns, &d->constraints, &why), comm,
             PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  d->bat_numbers = d->objective.study < 0;
  for (const DesignConstraint &c : d->constraints) d->bat_numbers = d->bat_numbers || c.q.study < 0;
  for (const FitParameter &v : d->vars)
    for (const DesignStudy &st : d->studies)
      for (const CaseSetting &c : st.cases.front())
        PetscCheck(c.name != v.name, comm, PETSC_ERR_ARG_WRONG,
                   "-design_studies: the study %s sets %s, a design variable (-design_variables): a study may not set "
                   "what the design varies",
                   st.name.c_str(), v.name.c_str());
  PetscCall(DesignCheckOutputs(comm, output, s));
  CaseBatchSettings b;
  b.task         = CaseTaskFind("impact");
  b.columns      = d->columns;
  b.store        = output;
  b.own_prefixes = {"design_", "tao_"};
  b.restart      = s.restart;
  b.stop_after   = s.stop_after;
  b.who          = "design";
  PetscCall(CaseBatchCreate(comm, b, &d->batch));
  PetscFunctionReturn(0);
}

PetscErrorCode DesignAnnounce(const DesignProblem &d, const std::string &output)
{
  PetscMPIInt size;
  std::string text;
  size_t      points = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(d.world, &size));
  for (const FitParameter &q : d.vars) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "\n  %s in [%g, %g]%s%s, %s, from %.10g (%s)", q.name.c_str(), q.lo, q.hi,
                  q.unit.empty() || q.unit == "1" ? "" : " ", q.unit == "1" ? "" : q.unit.c_str(),
                  q.log ? "log-scaled" : "linear", q.start, q.start_from.c_str());
    text += buf;
  }
  for (const DesignStudy &s : d.studies) points += s.cases.size();
  PetscCall(PetscPrintf(d.world,
                        "design: %s %s under %zu constraint(s), %zu impacts a design (%zu studies), on %d rank(s); %zu "
                        "variables:%s\n",
                        d.settings.maximize ? "maximise" : "minimise", d.objective.text.c_str(), d.m(), points,
                        d.studies.size(), (int)size, d.n(), text.c_str()));
  const CaseBatchCounts &c = d.batch.counts;
  if (c.loaded + c.loaded_journal > 0)
    PetscCall(PetscPrintf(d.world,
                          "design: %d runs known from an earlier design into %s (%d from its file, %d from the "
                          "journals of a run that stopped)\n",
                          (int)(c.loaded + c.loaded_journal), output.c_str(), (int)c.loaded, (int)c.loaded_journal));
  PetscFunctionReturn(0);
}

PetscErrorCode DesignReportRuns(const DesignProblem &d)
{
  CaseBatchCounts c;

  PetscFunctionBeginUser;
  PetscCall(CaseBatchGetCounts(d.batch, &c));
  PetscCall(PetscPrintf(d.world,
                        "design: %zu designs evaluated; runs: %d computed (%.3g s of the ranks' time, %.3g s a run), "
                        "%d answered from runs known (this design's or an earlier one's)\n",
                        d.history.size(), (int)c.computed, c.run_time, c.computed ? c.run_time / c.computed : 0.0,
                        (int)c.reused));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TaskDesign(MPI_Comm comm, const std::string &output)
{
  DesignProblem d;
  DesignResult  res;

  PetscFunctionBeginUser;
  g_exit_status = 0;
  struct Guard { // an error return: the lock released, the journals kept, no collective call
    DesignProblem &d;
    ~Guard()
    {
      SweepNotesAbandon();
      CaseBatchRelease(&d.batch);
    }
  } guard{d};
  PetscCall(SweepNotesBegin());
  PetscCall(DesignSetUp(comm, output, &d));
  PetscCall(DesignAnnounce(d, output));
  PetscCall(DesignSolve(d, &res));
  PetscCall(SweepNotesEnd(comm, d.batch.counts.computed));
  PetscCall(DesignReportRuns(d));
  PetscCall(DesignPrintSummary(d, res));
  PetscCall(DesignWriteOutputs(d, res, output));
  PetscCall(CaseBatchDestroy(&d.batch));
  if (!res.feasible()) g_exit_status = kDesignInfeasibleStatus;
  PetscFunctionReturn(0);
}

int DesignExitStatus() { return g_exit_status; }

PetscErrorCode DesignHelpOptions(MPI_Comm comm)
{
  DesignSettings s;
  PetscFunctionBeginUser;
  (void)DesignSettingsFromOptions(comm, "", &s); // its checks' errors are not what -help asks
  PetscFunctionReturn(0);
}

} // namespace beamimpact

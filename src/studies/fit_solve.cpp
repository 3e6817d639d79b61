// -task fit's optimiser: TAO's least-squares solvers on the scaled parameters u in [0, 1]. See
// fit_problem.hpp.
//
// TAO runs on PETSC_COMM_SELF on every rank, each with the same numbers (the case batch gives every
// rank the same rows, computed once on one rank each), so each rank takes the same steps and asks
// for the same cases: the ranks share the runs, not the tiny dense algebra. PETSc's printing to
// stdout from the ranks other than 0 is dropped while TAO runs (its monitors and views would
// print once per rank), and let through again while the cases run.
//
// Defaults set before TaoSetFromOptions (so every -tao_* option wins): -tao_type brgn, its
// regularizer weight 0 (PETSc's default is 1e-4 with the proximal regularizer 1/2 lambda |u -
// u_prev|^2, which vanishes at convergence but damps each step: 0 makes it plain Gauss-Newton with
// bounds), gradient tolerances 0 (they do not fit residuals that are all noise) and at most 50
// iterations; brgn stops when no scaled parameter moves by more than -fit_xtol or chi^2 by less
// than -fit_ftol of itself.
#include "studies/fit_problem.hpp"
#include "studies/study_common.hpp"

#include "base/options_util.hpp"
#include "studies/sweep_notes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace beamimpact {

namespace {

// ---------------------------------------------------------------------------
// TAO's callbacks
// ---------------------------------------------------------------------------

PetscErrorCode FitTaoResidual(Tao, Vec X, Vec F, void *ctx)
{
  FitProblem         &f = *static_cast<FitProblem *>(ctx);
  std::vector<double> fitted, r;
  LoudScope           loud;

  PetscFunctionBeginUser;
  PetscCall(FitResidual(f, f.ToP(FromVec(X)), &fitted, &r));
  // after TAO and the first runs read theirs: a typo stops the fit now, not at its end (a rerun
  // that computes nothing reads no run's options: no check)
  if (!f.options_checked && f.batch.counts.computed > 0) {
    PetscCall(StudyOptionsCheckUnused(f.world));
    f.options_checked = true;
  }
  PetscCall(ToVec(r, F));
  PetscFunctionReturn(0);
}

PetscErrorCode FitTaoJacobian(Tao, Vec X, Mat J, Mat, void *ctx)
{
  FitProblem         &f = *static_cast<FitProblem *>(ctx);
  std::vector<double> Ju;
  LoudScope           loud;

  PetscFunctionBeginUser;
  PetscCall(FitJacobian(f, FromVec(X), f.settings.central, f.settings.step, &Ju));
  for (size_t i = 0; i < f.m(); ++i)
    for (size_t j = 0; j < f.n(); ++j)
      PetscCall(MatSetValue(J, (PetscInt)i, (PetscInt)j, Ju[i * f.n() + j], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// The monitor's context is a PetscContainer (brgn passes its monitors to its subsolver and takes
// a reference on their contexts, which must be PETSc objects).
PetscErrorCode FitTaoMonitor(Tao tao, void *ctx)
{
  FitProblem *f;
  Vec         X;
  PetscInt    it;
  LoudScope   loud;

  PetscFunctionBeginUser;
  PetscCall(PetscContainerGetPointer((PetscContainer)ctx, (void **)&f));
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(TaoGetIterationNumber(tao, &it));
  FitIteration h;
  h.iteration = it;
  h.p         = f->ToP(FromVec(X));
  std::vector<double> fitted, r;
  PetscCall(FitResidual(*f, h.p, &fitted, &r)); // known: the solver evaluated its iterate
  for (double x : r) h.chi2 += x * x;
  if (!f->history.empty())
    for (size_t j = 0; j < f->n(); ++j) {
      const double before = f->history.back().p[j];
      h.step              = std::max(h.step, std::fabs(h.p[j] - before) / std::max(std::fabs(before), 1e-300));
    }
  h.runs = f->batch.counts.computed;
  f->history.push_back(h);
  if (!f->settings.quiet) {
    std::string line;
    char        buf[200];
    std::snprintf(buf, sizeof buf, "fit: iteration %2d  chi2 %.6e ", (int)it, h.chi2);
    line = buf;
    for (size_t j = 0; j < f->n(); ++j) {
      std::snprintf(buf, sizeof buf, " %s %.8g", f->params[j].name.c_str(), h.p[j]);
      line += buf;
    }
    std::snprintf(buf, sizeof buf, "  (step %.2g, %d runs)", h.step, (int)h.runs);
    PetscCall(PetscPrintf(f->world, "%s%s\n", line.c_str(), buf));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FitContainerDestroy(void **ctx) { return PetscContainerDestroy((PetscContainer *)ctx); }

// brgn's subsolver: TAO's own tests first (every -tao_* tolerance), then the program's: no scaled
// parameter moved by more than -fit_xtol, or chi^2 changed by less than -fit_ftol of itself, since
// the last iteration (a fit whose residuals are noise stops when the steps are the differences'
// noise, not a gradient that never vanishes).
PetscErrorCode FitTaoConverged(Tao tao, void *ctx)
{
  FitProblem        &f = *static_cast<FitProblem *>(ctx);
  TaoConvergedReason reason;
  Vec                X;
  PetscInt           it;
  PetscReal          fc, gnorm, cnorm, xdiff;

  PetscFunctionBeginUser;
  PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  PetscCall(TaoGetSolutionStatus(tao, &it, &fc, &gnorm, &cnorm, &xdiff, &reason));
  PetscCall(TaoGetSolution(tao, &X));
  const std::vector<double> u = FromVec(X);
  if (reason == TAO_CONTINUE_ITERATING && it > 0 && f.u_prev_set) {
    double moved = 0;
    for (size_t j = 0; j < u.size(); ++j) moved = std::max(moved, std::fabs(u[j] - f.u_prev[j]));
    char text[160] = "";
    if (moved <= f.settings.xtol)
      std::snprintf(text, sizeof text, "no scaled parameter moved by more than -fit_xtol %g", f.settings.xtol);
    else if (std::fabs(f.f_prev - fc) <= f.settings.ftol * fc)
      std::snprintf(text, sizeof text, "chi^2 changed by less than -fit_ftol %g of itself", f.settings.ftol);
    if (text[0]) {
      f.stop = text;
      PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_STEPTOL));
    }
  }
  f.u_prev     = u;
  f.u_prev_set = true;
  f.f_prev     = fc;
  PetscFunctionReturn(0);
}

// The solver with the program's defaults, then the options (-tao_*).
PetscErrorCode FitTaoSetUp(FitProblem &f, Tao tao, Vec x, Vec xl, Vec xu, Vec r, Mat J)
{
  PetscContainer c;
  PetscBool      brgn;

  PetscFunctionBeginUser;
  PetscCall(FitTaoDefaults(tao));
  PetscCall(TaoSetSolution(tao, x));
  PetscCall(TaoSetVariableBounds(tao, xl, xu));
  PetscCall(TaoSetResidualRoutine(tao, r, FitTaoResidual, &f));
  PetscCall(TaoSetJacobianResidualRoutine(tao, J, J, FitTaoJacobian, &f));
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &c));
  PetscCall(PetscContainerSetPointer(c, &f));
  PetscCall(TaoSetMonitor(tao, FitTaoMonitor, c, FitContainerDestroy));
  PetscCall(TaoSetFromOptions(tao));
  PetscCall(PetscObjectTypeCompare((PetscObject)tao, TAOBRGN, &brgn));
  if (brgn) {
    Tao sub;
    PetscCall(TaoBRGNGetSubsolver(tao, &sub));
    PetscCall(TaoSetConvergenceTest(sub, FitTaoConverged, &f));
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FitTaoDefaults(Tao tao)
{
  PetscFunctionBeginUser;
  PetscCall(TaoSetType(tao, TAOBRGN));
  PetscCall(TaoSetTolerances(tao, 0, 0, 0));
  PetscCall(TaoSetMaximumIterations(tao, 50));
  PetscCall(TaoBRGNSetRegularizerWeight(tao, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode FitSolve(FitProblem &f, FitResult *res)
{
  Tao                tao;
  Vec                x, xl, xu, r;
  Mat                J;
  TaoType            type;
  TaoConvergedReason reason;
  QuietRanks         quiet(f.rank);

  PetscFunctionBeginUser;
  std::vector<double> p0;
  for (const FitParameter &q : f.params) p0.push_back(q.start);
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)f.n(), &x));
  PetscCall(ToVec(f.ToU(p0), x));
  PetscCall(VecDuplicate(x, &xl));
  PetscCall(VecDuplicate(x, &xu));
  PetscCall(VecSet(xl, 0.0));
  PetscCall(VecSet(xu, 1.0));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)f.m(), &r));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, (PetscInt)f.m(), (PetscInt)f.n(), NULL, &J));
  PetscCall(TaoCreate(PETSC_COMM_SELF, &tao));
  PetscCall(FitTaoSetUp(f, tao, x, xl, xu, r, J));
  PetscCall(TaoSolve(tao));
  PetscCall(TaoGetType(tao, &type));
  PetscCall(TaoGetConvergedReason(tao, &reason));
  PetscCall(TaoGetIterationNumber(tao, &res->iterations));
  Vec X;
  PetscCall(TaoGetSolution(tao, &X));
  res->p        = f.ToP(FromVec(X));
  res->tao_type = type;
  res->reason   = std::string(TaoConvergedReasons[reason]) + (f.stop.empty() ? "" : " (" + f.stop + ")");
  PetscCall(TaoDestroy(&tao));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&r));
  PetscCall(VecDestroy(&xu));
  PetscCall(VecDestroy(&xl));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

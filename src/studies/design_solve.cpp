// -task design's optimiser: TAO on the scaled variables u in [0, 1]. See design_problem.hpp.
//
// As -task fit's (fit_solve.cpp): TAO runs on PETSC_COMM_SELF on every rank with the same numbers
// (the case batch gives every rank the same rows), so each rank takes the same steps; the ranks
// share the runs. Without constraints the default is bqnls (a bound-constrained quasi-Newton
// method), with them almm (TAO's augmented Lagrangian, its subsolver bqnls over the bounds); the
// gradients and the constraints' Jacobian are differences of the variables, all the designs of
// one point in one batch. Defaults set before TaoSetFromOptions, so every -tao_* option wins: at
// most 50 iterations, -tao_gatol 1e-6, -tao_catol 1e-4 (the constraints scaled by their bounds);
// bqnls, blmvm and almm also stop when no scaled variable moves by more than -design_xtol.
#include "studies/design_problem.hpp"

#include "base/options_util.hpp"
#include "studies/study_common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

namespace {

// The gradient's results at the last point asked (TAO asks for the objective, the constraints and
// their Jacobian at the same point in turn).
struct GradientCache {
  std::vector<double> u, g, c, J;
  double              f     = 0;
  bool                valid = false;
};

struct SolveContext {
  DesignProblem *d;
  GradientCache  cache;
};

PetscErrorCode AtPoint(SolveContext &s, const std::vector<double> &u)
{
  PetscFunctionBeginUser;
  if (s.cache.valid && s.cache.u == u) PetscFunctionReturn(0);
  PetscCall(
    DesignGradient(*s.d, u, s.d->settings.central, s.d->settings.step, &s.cache.f, &s.cache.g, &s.cache.c, &s.cache.J));
  s.cache.u = u, s.cache.valid = true;
  // after TAO and the first runs read theirs: a typo stops the design now (a rerun that
  // computes nothing reads no run's options: no check)
  if (!s.d->options_checked && s.d->batch.counts.computed > 0) {
    PetscCall(StudyOptionsCheckUnused(s.d->world));
    s.d->options_checked = true;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TaoObjective(Tao, Vec X, PetscReal *f, void *ctx)
{
  SolveContext             &s = *static_cast<SolveContext *>(ctx);
  std::vector<DesignValues> v;
  LoudScope                 loud;
  PetscFunctionBeginUser;
  const std::vector<double> u = FromVec(X);
  if (s.cache.valid && s.cache.u == u) *f = s.cache.f;
  else {
    PetscCall(DesignEvaluate(*s.d, {u}, &v, 2)); // a trial point (an iterate once the monitor sees it)
    *f = (s.d->settings.maximize ? -1 : 1) * v[0].objective;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TaoObjectiveGradient(Tao, Vec X, PetscReal *f, Vec G, void *ctx)
{
  SolveContext &s = *static_cast<SolveContext *>(ctx);
  LoudScope     loud;
  PetscFunctionBeginUser;
  PetscCall(AtPoint(s, FromVec(X)));
  *f = s.cache.f;
  PetscCall(ToVec(s.cache.g, G));
  PetscFunctionReturn(0);
}

PetscErrorCode TaoConstraints(Tao, Vec X, Vec C, void *ctx)
{
  SolveContext &s = *static_cast<SolveContext *>(ctx);
  LoudScope     loud;
  PetscFunctionBeginUser;
  PetscCall(AtPoint(s, FromVec(X)));
  PetscCall(ToVec(s.cache.c, C));
  PetscFunctionReturn(0);
}

PetscErrorCode TaoConstraintsJacobian(Tao, Vec X, Mat J, Mat, void *ctx)
{
  SolveContext &s = *static_cast<SolveContext *>(ctx);
  LoudScope     loud;
  PetscFunctionBeginUser;
  PetscCall(AtPoint(s, FromVec(X)));
  const size_t m = s.d->m(), n = s.d->n();
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < n; ++j)
      PetscCall(MatSetValue(J, (PetscInt)i, (PetscInt)j, s.cache.J[i * n + j], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// Each iteration: the iterate's row marked with its KKT residual, a line, the program's step test.
PetscErrorCode TaoMonitorDesign(Tao tao, void *ctx)
{
  SolveContext             &s = *static_cast<SolveContext *>(ctx);
  DesignProblem            &d = *s.d;
  Vec                       X;
  PetscInt                  it;
  PetscReal                 f, gnorm, cnorm, xdiff;
  TaoConvergedReason        reason;
  std::vector<DesignValues> v;
  LoudScope                 loud;

  PetscFunctionBeginUser;
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(TaoGetSolutionStatus(tao, &it, &f, &gnorm, &cnorm, &xdiff, &reason));
  const std::vector<double> u = FromVec(X);
  PetscCall(DesignEvaluate(d, {u}, &v, 0)); // known: TAO evaluated its iterate
  DesignRecord &r = d.history[d.known.at(u)];
  r.kkt = gnorm, r.cnorm = cnorm, r.iteration = it;
  d.iteration = it + 1;
  if (!d.settings.quiet) {
    std::string line;
    char        buf[200];
    std::snprintf(buf, sizeof buf, "design: iteration %2d  objective %.8g  KKT %.3g%s", (int)it, v[0].objective,
                  (double)gnorm, v[0].feasible ? "" : "  (infeasible)");
    line = buf;
    for (size_t j = 0; j < d.n(); ++j)
      std::snprintf(buf, sizeof buf, "  %s %.8g", d.vars[j].name.c_str(), v[0].p[j]), line += buf;
    for (size_t i = 0; i < d.m(); ++i)
      std::snprintf(buf, sizeof buf, "  %s %.6g", d.constraints[i].q.text.c_str(), v[0].constraint[i]), line += buf;
    PetscCall(PetscPrintf(d.world, "%s  (%d runs)\n", line.c_str(), (int)d.batch.counts.computed));
  }
  PetscFunctionReturn(0);
}

// bqnls, blmvm, almm: TAO's own tests, then no scaled variable moved by more than -design_xtol (almm: at a feasible
// design, every constraint within -tao_catol).
PetscErrorCode TaoConvergedDesign(Tao tao, void *ctx)
{
  SolveContext      &s = *static_cast<SolveContext *>(ctx);
  TaoConvergedReason reason;
  Vec                X;
  PetscInt           it;
  PetscReal          fc, gnorm, cnorm, xdiff;

  PetscFunctionBeginUser;
  PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  PetscCall(TaoGetSolutionStatus(tao, &it, &fc, &gnorm, &cnorm, &xdiff, &reason));
  PetscCall(TaoGetSolution(tao, &X));
  const std::vector<double> u        = FromVec(X);
  const auto                known    = s.d->known.find(u); // the monitor evaluated the iterate
  const bool                feasible = known != s.d->known.end() && s.d->history[known->second].v.feasible;
  if (reason == TAO_CONTINUE_ITERATING && it > 0 && s.d->u_prev.size() == u.size() && feasible) {
    double moved = 0;
    for (size_t j = 0; j < u.size(); ++j) moved = std::max(moved, std::fabs(u[j] - s.d->u_prev[j]));
    if (moved <= s.d->settings.xtol) {
      char text[160];
      std::snprintf(text, sizeof text, "no scaled variable moved by more than -design_xtol %g",
                    (double)s.d->settings.xtol);
      s.d->stop = text;
      PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_STEPTOL));
    }
  }
  s.d->u_prev = u;
  PetscFunctionReturn(0);
}

// -tao_catol as TAO read it is the program's feasibility tolerance (DesignViolated). almm's PHR formulation
// (PETSc 3.18's default) replaces it by -tao_gatol in its set-up when both are set (the program sets both): a larger
// -tao_gatol would then let TAO stop "converged" at a design beyond -tao_catol, so a larger value is put back after
// TaoSetUp.
PetscErrorCode KeepConstraintTolerance(DesignProblem &d, Tao tao, DesignResult *res)
{
  PetscReal catol, crtol, used;
  PetscFunctionBeginUser;
  PetscCall(TaoGetConstraintTolerances(tao, &catol, &crtol));
  d.catol = catol;
  PetscCall(TaoSetUp(tao));
  PetscCall(TaoGetConstraintTolerances(tao, &used, NULL));
  if (used > catol) {
    PetscCall(TaoSetConstraintTolerances(tao, catol, crtol));
    res->notes.push_back(Fmt("almm's PHR formulation sets -tao_catol to -tao_gatol %g (PETSc 3.18); the program keeps "
                             "-tao_catol %g for TAO's test and the designs' feasibility",
                             (double)used, (double)catol));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SetUp(SolveContext &s, Tao tao, Vec x, Vec xl, Vec xu, Vec c, Mat J, DesignResult *res)
{
  PetscBool almm, own_test;
  TaoType   type;
  PetscFunctionBeginUser;
  PetscCall(DesignTaoDefaults(tao, s.d->m() > 0));
  PetscCall(TaoSetSolution(tao, x));
  PetscCall(TaoSetVariableBounds(tao, xl, xu));
  PetscCall(TaoSetObjective(tao, TaoObjective, &s));
  PetscCall(TaoSetObjectiveAndGradient(tao, NULL, TaoObjectiveGradient, &s));
  if (c) {
    PetscCall(TaoSetInequalityConstraintsRoutine(tao, c, TaoConstraints, &s));
    PetscCall(TaoSetJacobianInequalityRoutine(tao, J, J, TaoConstraintsJacobian, &s));
  }
  PetscCall(TaoSetFromOptions(tao));
  // after TaoSetFromOptions: almm copies the monitors set before it to its subsolver, whose iterates are not TAO's
  PetscCall(TaoSetMonitor(tao, TaoMonitorDesign, &s, NULL));
  PetscCall(TaoGetType(tao, &type));
  PetscCall(PetscObjectTypeCompare((PetscObject)tao, TAOALMM, &almm));
  PetscCheck(c || !almm, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
             "-tao_type almm needs constraints: give -design_constraints, or a bound-constrained solver (bqnls, "
             "blmvm)");
  PetscCheck(!c || almm, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
             "-tao_type %s ignores -design_constraints: with constraints the design needs almm (the default)", type);
  if (almm) {
    TaoALMMType t;
    PetscCall(TaoALMMGetType(tao, &t));
    res->almm_type = t == TAO_ALMM_PHR ? "phr" : "classic";
    for (const char *o : {"-tao_almm_mu_init", "-tao_almm_mu_factor"}) { // PHR sets both itself (PETSc 3.18)
      PetscBool given;
      PetscCall(PetscOptionsHasName(NULL, NULL, o, &given));
      if (given && t == TAO_ALMM_PHR)
        res->notes.push_back(Fmt("%s has no effect: almm's PHR formulation (the default) chooses its penalty itself; "
                                 "-tao_almm_type classic reads it",
                                 o));
    }
  }
  PetscCall(PetscObjectTypeCompareAny((PetscObject)tao, &own_test, TAOBQNLS, TAOBLMVM, TAOALMM, ""));
  if (own_test) PetscCall(TaoSetConvergenceTest(tao, TaoConvergedDesign, &s));
  PetscCall(KeepConstraintTolerance(*s.d, tao, res));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode DesignTaoDefaults(Tao tao, bool constrained)
{
  PetscFunctionBeginUser;
  PetscCall(TaoSetType(tao, constrained ? TAOALMM : TAOBQNLS));
  PetscCall(TaoSetTolerances(tao, 1e-6, 0, 0));
  PetscCall(TaoSetConstraintTolerances(tao, 1e-4, 0));
  PetscCall(TaoSetMaximumIterations(tao, 50));
  PetscFunctionReturn(0);
}

PetscErrorCode DesignSolve(DesignProblem &d, DesignResult *res)
{
  Tao                       tao;
  Vec                       x, xl, xu, c = NULL, X;
  Mat                       J = NULL;
  TaoType                   type;
  TaoConvergedReason        reason;
  PetscReal                 f, xdiff;
  QuietRanks                quiet(d.rank);
  SolveContext              s{&d, {}};
  std::vector<DesignValues> v;

  PetscFunctionBeginUser;
  std::vector<double> p0;
  for (const FitParameter &q : d.vars) p0.push_back(q.start);
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)d.n(), &x));
  PetscCall(ToVec(d.ToU(p0), x));
  PetscCall(VecDuplicate(x, &xl));
  PetscCall(VecDuplicate(x, &xu));
  PetscCall(VecSet(xl, 0.0));
  PetscCall(VecSet(xu, 1.0));
  if (d.m() > 0) {
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, (PetscInt)d.m(), &c));
    PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, (PetscInt)d.m(), (PetscInt)d.n(), NULL, &J));
  }
  PetscCall(TaoCreate(PETSC_COMM_SELF, &tao));
  PetscCall(SetUp(s, tao, x, xl, xu, c, J, res));
  PetscCall(TaoSolve(tao));
  PetscCall(TaoGetType(tao, &type));
  PetscCall(TaoGetSolutionStatus(tao, &res->iterations, &f, &res->kkt, &res->cnorm, &xdiff, &reason));
  PetscCall(TaoGetSolution(tao, &X));
  const std::vector<double> u = FromVec(X);
  PetscCall(DesignEvaluate(d, {u}, &v, 0));
  res->p = v[0].p, res->v = v[0], res->tao_type = type;
  res->reason                  = std::string(TaoConvergedReasons[reason]) + (d.stop.empty() ? "" : " (" + d.stop + ")");
  const std::vector<double> cs = DesignTaoConstraints(d, v[0]);
  for (size_t i = 0; i < d.m(); ++i)
    if (std::fabs(cs[i]) <= 1e-3) res->active.push_back(d.constraints[i].q.text);
  res->violated = DesignViolated(d, v[0]);
  PetscCall(TaoGetTolerances(tao, &res->gatol, NULL, NULL));
  PetscCall(TaoGetMaximumIterations(tao, &res->max_it));
  for (size_t k = 0; k < d.history.size(); ++k) {
    const DesignRecord &r = d.history[k];
    if (r.v.feasible &&
        (res->best_feasible < 0 ||
         (d.settings.maximize ? 1 : -1) * (r.v.objective - d.history[res->best_feasible].v.objective) > 0))
      res->best_feasible = (long)k;
  }
  for (size_t j = 0; j < d.n(); ++j)
    if (u[j] <= 1e-6 || u[j] >= 1 - 1e-6) res->at_bound.push_back(d.vars[j].name);
  PetscCall(TaoDestroy(&tao));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&c));
  PetscCall(VecDestroy(&xu));
  PetscCall(VecDestroy(&xl));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

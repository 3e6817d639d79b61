// The residuals and Jacobians of -task fit through the case batch. See fit_problem.hpp.
#include "studies/fit_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

std::vector<double> FitProblem::ToP(const std::vector<double> &u) const
{
  std::vector<double> p(n());
  for (size_t j = 0; j < n(); ++j) p[j] = params[j].FromInternal(u[j]);
  return p;
}

std::vector<double> FitProblem::ToU(const std::vector<double> &p) const
{
  std::vector<double> u(n());
  for (size_t j = 0; j < n(); ++j) u[j] = params[j].ToInternal(p[j]);
  return u;
}

std::vector<std::string> FitProblem::Names() const
{
  std::vector<std::string> names;
  for (const FitParameter &q : params) names.push_back(q.name);
  return names;
}

std::vector<double> FitScaleDerivative(const FitProblem &f, const std::vector<double> &u)
{
  std::vector<double> d(f.n());
  for (size_t j = 0; j < f.n(); ++j) {
    const FitParameter &q = f.params[j];
    d[j]                  = q.log ? q.FromInternal(u[j]) * std::log(q.hi / q.lo) : q.hi - q.lo;
  }
  return d;
}

namespace {

// The cases of one evaluation at p: each data row's settings and the parameters.
void AddCases(const FitProblem &f, const std::vector<double> &p, std::vector<CaseOptions> *cases)
{
  for (const CaseOptions &row : f.data.rows) {
    CaseOptions c = row;
    for (size_t j = 0; j < f.n(); ++j) c.push_back(CaseSetting{f.params[j].name, p[j]});
    cases->push_back(c);
  }
}

std::string ParametersText(const FitProblem &f, const std::vector<double> &p)
{
  std::string out;
  for (size_t j = 0; j < f.n(); ++j) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s=%.10g", out.empty() ? "" : ", ", f.params[j].name.c_str(), p[j]);
    out += buf;
  }
  return out;
}

// The measured values of evaluation e (rows[e * nrows + row]) as the program gives them; a failed
// run or a NaN value is an error naming the row and column.
PetscErrorCode Fitted(const FitProblem &f, const std::vector<CaseRow> &rows, size_t e, const std::vector<double> &p,
                      std::vector<double> *fitted)
{
  const size_t nrows = f.data.rows.size();

  PetscFunctionBeginUser;
  fitted->resize(f.m());
  for (size_t i = 0; i < f.m(); ++i) {
    const FitMeasurement &v   = f.data.values[i];
    const CaseRow        &row = rows[e * nrows + v.row];
    PetscCheck(row.status == SweepOk, f.world, PETSC_ERR_USER,
               "-fit_data %s %s: the run at %s failed (status %d, %s): %s", f.data.file.c_str(),
               FitRowText(f.data, v.row).c_str(), ParametersText(f, p).c_str(), row.status, SweepStatusName(row.status),
               row.reason.c_str());
    (*fitted)[i] = row.values[v.column];
    PetscCheck(std::isfinite((*fitted)[i]), f.world, PETSC_ERR_USER,
               "-fit_data %s %s, column '%s': the run at %s gives no value (%g): %s", f.data.file.c_str(),
               FitRowText(f.data, v.row).c_str(), f.data.measured[v.column].c_str(), ParametersText(f, p).c_str(),
               (*fitted)[i], row.reason.empty() ? "the column does not apply to this run" : row.reason.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FitResidual(FitProblem &f, const std::vector<double> &p, std::vector<double> *fitted,
                           std::vector<double> *r)
{
  std::vector<CaseOptions> cases;
  std::vector<CaseRow>     rows;

  PetscFunctionBeginUser;
  AddCases(f, p, &cases);
  PetscCall(CaseBatchRun(f.batch, cases, &rows));
  PetscCall(Fitted(f, rows, 0, p, fitted));
  r->resize(f.m());
  for (size_t i = 0; i < f.m(); ++i) (*r)[i] = ((*fitted)[i] - f.data.values[i].y) / f.data.values[i].sigma;
  PetscFunctionReturn(0);
}

PetscErrorCode FitJacobian(FitProblem &f, const std::vector<double> &u, bool central, double step,
                           std::vector<double> *J, std::vector<std::string> *at_bound)
{
  const size_t             n = f.n(), m = f.m();
  std::vector<CaseOptions> cases;
  std::vector<CaseRow>     rows;
  std::vector<double>      up(n), um(n); // each parameter's two points (um = u for a forward difference)

  PetscFunctionBeginUser;
  if (at_bound) at_bound->clear();
  AddCases(f, f.ToP(u), &cases); // evaluation 0: the point itself (known: TAO asked for its residual)
  for (size_t j = 0; j < n; ++j) {
    const FitParameter &q  = f.params[j];
    const double        p  = q.FromInternal(u[j]);
    const double        du = q.log ? std::log1p(step) / std::log(q.hi / q.lo)
                                   : step * std::max(std::fabs(p), 1e-3 * (q.hi - q.lo)) / (q.hi - q.lo);
    up[j] = u[j] + du, um[j] = central ? u[j] - du : u[j];
    if (up[j] > 1) up[j] = u[j], um[j] = u[j] - du; // at the upper bound: one-sided, downward
    if (um[j] < 0) um[j] = u[j], up[j] = u[j] + du;
    if (at_bound && central && (up[j] == u[j] || um[j] == u[j])) at_bound->push_back(q.name);
    for (double w : {up[j], um[j]}) {
      std::vector<double> v = u;
      v[j]                  = w;
      AddCases(f, f.ToP(v), &cases);
    }
  }
  PetscCall(CaseBatchRun(f.batch, cases, &rows));
  J->assign(m * n, 0.0);
  std::vector<double> plus, minus;
  for (size_t j = 0; j < n; ++j) {
    std::vector<double> v = u;
    v[j]                  = up[j];
    PetscCall(Fitted(f, rows, 1 + 2 * j, f.ToP(v), &plus));
    v[j] = um[j];
    PetscCall(Fitted(f, rows, 2 + 2 * j, f.ToP(v), &minus));
    for (size_t i = 0; i < m; ++i) (*J)[i * n + j] = (plus[i] - minus[i]) / f.data.values[i].sigma / (up[j] - um[j]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FitUncertaintyAtOptimum(FitProblem &f, FitResult *res)
{
  std::vector<double> Ju;

  PetscFunctionBeginUser;
  PetscCall(FitResidual(f, res->p, &res->fitted, &res->r));
  res->chi2 = 0;
  for (double x : res->r) res->chi2 += x * x;
  res->dof                    = (PetscInt)f.m() - (PetscInt)f.n();
  res->s2                     = f.data.absolute ? 1.0 : (res->dof > 0 ? res->chi2 / (double)res->dof : std::nan(""));
  const std::vector<double> u = f.ToU(res->p);
  PetscCall(FitJacobian(f, u, true, f.settings.covariance_step, &Ju, &res->at_bound));
  const std::vector<double> d = FitScaleDerivative(f, u);
  std::vector<double>       Jp(Ju.size());
  for (size_t i = 0; i < f.m(); ++i)
    for (size_t j = 0; j < f.n(); ++j) Jp[i * f.n() + j] = Ju[i * f.n() + j] / d[j];
  PetscCall(FitUncertaintyOf(Jp, f.m(), f.n(), res->p, res->s2, f.settings.identifiability, &res->u));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

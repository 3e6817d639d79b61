// -task design's designs: their values through the case batch, the bat's own numbers, and the
// differences of the scaled variables. See design_problem.hpp.
#include "studies/design_problem.hpp"

#include "io/beam_options.hpp"
#include "model/bat_maker.hpp"
#include "model/beam.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

std::vector<double> DesignProblem::ToP(const std::vector<double> &u) const
{
  std::vector<double> p(n());
  for (size_t j = 0; j < n(); ++j) p[j] = vars[j].FromInternal(u[j]);
  return p;
}

std::vector<double> DesignProblem::ToU(const std::vector<double> &p) const
{
  std::vector<double> u(n());
  for (size_t j = 0; j < n(); ++j) u[j] = vars[j].ToInternal(p[j]);
  return u;
}

namespace {

std::string VariablesText(const DesignProblem &d, const std::vector<double> &p)
{
  std::string out;
  for (size_t j = 0; j < d.n(); ++j) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s=%.10g", out.empty() ? "" : ", ", d.vars[j].name.c_str(), p[j]);
    out += buf;
  }
  return out;
}

// The bat's numbers of the design p: its beam read from the options with the variables set (and
// the options put back as they were).
PetscErrorCode BatNumbers(const DesignProblem &d, const std::vector<double> &p, std::map<std::string, double> *out)
{
  std::vector<std::pair<std::string, std::string>> given; // option -> its value before ("\1": not set)
  BeamParams                                       bp;

  PetscFunctionBeginUser;
  for (size_t j = 0; j < d.n(); ++j) {
    const std::string opt = "-" + d.vars[j].name;
    char              buf[4096];
    PetscBool         set;
    PetscCall(PetscOptionsGetString(NULL, NULL, opt.c_str(), buf, sizeof buf, &set));
    given.push_back({opt, set ? std::string(buf) : std::string("\1")});
    PetscCall(PetscOptionsClearValue(NULL, opt.c_str()));
    PetscCall(PetscOptionsSetValue(NULL, opt.c_str(), CaseSetting{d.vars[j].name, p[j]}.Value().c_str()));
  }
  const PetscErrorCode ierr = BeamParamsFromOptions(PETSC_COMM_SELF, &bp);
  for (const auto &g : given) {
    PetscCall(PetscOptionsClearValue(NULL, g.first.c_str()));
    if (g.second != "\1")
      PetscCall(PetscOptionsSetValue(NULL, g.first.c_str(), g.second.empty() ? NULL : g.second.c_str()));
  }
  PetscCheck(!ierr, PETSC_COMM_SELF, PETSC_ERR_USER,
             "-task design: the design %s describes no beam (its numbers: mass, drop, ...): see the error above",
             VariablesText(d, p).c_str());
  const BeamRigidBody b  = BeamRigidBodyOf(bp);
  const double        xp = d.settings.pivot - b.x_cm;
  double              D  = NAN;
  for (const ProfileRow &r : bp.section.profile) D = std::isnan(D) ? r.D : std::max(D, (double)r.D);
  *out = {{"mass", b.mass},
          {"drop", BatDrop(bp.length, b.mass)},
          {"balance", b.x_cm},
          {"inertia_knob", b.inertia_end},
          {"inertia_pivot", b.inertia_cm + b.mass * xp * xp},
          {"inertia_cm", b.inertia_cm},
          {"length", bp.length},
          {"diameter", D}};
  PetscFunctionReturn(0);
}

// The quantity q of design e from its rows (rows[first[s] + k]: study s's point k) or its bat numbers.
PetscErrorCode Quantity(const DesignProblem &d, const DesignQuantity &q, const std::vector<CaseRow> &rows,
                        size_t first_row, const std::map<std::string, double> &bat, const std::vector<double> &p,
                        double *value)
{
  PetscFunctionBeginUser;
  if (q.study < 0) {
    *value = bat.at(q.bat);
    PetscFunctionReturn(0);
  }
  size_t at = first_row;
  for (int s = 0; s < q.study; ++s) at += d.studies[s].cases.size();
  const DesignStudy &st  = d.studies[q.study];
  double             sum = 0, best = q.reduce == DesignReduce::Min ? INFINITY : -INFINITY;
  for (size_t k = 0; k < st.cases.size(); ++k) {
    const CaseRow &r = rows[at + k];
    PetscCheck(r.status == SweepOk, d.world, PETSC_ERR_USER,
               "-task design: %s at the design %s: the study %s's point %s failed (status %d, %s): %s", q.text.c_str(),
               VariablesText(d, p).c_str(), st.name.c_str(), CaseOptionsText(st.cases[k], false).c_str(), r.status,
               SweepStatusName(r.status), r.reason.c_str());
    const double x = r.values[q.column];
    PetscCheck(std::isfinite(x), d.world, PETSC_ERR_USER,
               "-task design: %s at the design %s: the study %s's point %s gives no value (%g): %s", q.text.c_str(),
               VariablesText(d, p).c_str(), st.name.c_str(), CaseOptionsText(st.cases[k], false).c_str(), x,
               r.reason.empty()
                 ? "the column does not apply to this run (a rig's bbcor needs -beam_pivot; a bbs a swing)"
                 : r.reason.c_str());
    sum += x;
    best = q.reduce == DesignReduce::Min ? std::min(best, x) : std::max(best, x);
  }
  *value = q.reduce == DesignReduce::Mean  ? sum / (double)st.cases.size()
         : q.reduce == DesignReduce::Value ? rows[at].values[q.column]
                                           : best;
  PetscFunctionReturn(0);
}

} // namespace

std::vector<double> DesignTaoConstraints(const DesignProblem &d, const DesignValues &v)
{
  std::vector<double> c(d.m());
  for (size_t i = 0; i < d.m(); ++i) {
    const DesignConstraint &k = d.constraints[i];
    c[i]                      = (k.upper ? k.bound - v.constraint[i] : v.constraint[i] - k.bound) / k.scale;
  }
  return c;
}

std::vector<size_t> DesignViolated(const DesignProblem &d, const DesignValues &v)
{
  std::vector<size_t>       out;
  const std::vector<double> c = DesignTaoConstraints(d, v);
  for (size_t i = 0; i < c.size(); ++i)
    if (!(c[i] >= -d.catol)) out.push_back(i); // NaN too
  return out;
}

static void PromoteRole(DesignRecord &r, int role)
{
  auto rank = [](int x) { return x == 0 ? 2 : x == 2 ? 1 : 0; }; // iterate > a point TAO asked for > a difference's
  if (rank(role) > rank(r.role)) r.role = role;
}

PetscErrorCode DesignEvaluate(DesignProblem &d, const std::vector<std::vector<double>> &us,
                              std::vector<DesignValues> *vals, int role)
{
  std::vector<CaseOptions> cases;
  std::vector<CaseRow>     rows;
  size_t                   per = 0; // points of one design
  PetscFunctionBeginUser;
  for (const DesignStudy &s : d.studies) per += s.cases.size();
  for (const std::vector<double> &u : us) {
    const std::vector<double> p = d.ToP(u);
    for (const DesignStudy &s : d.studies)
      for (const CaseOptions &c : s.cases) {
        CaseOptions e = c;
        for (size_t j = 0; j < d.n(); ++j) e.push_back(CaseSetting{d.vars[j].name, p[j]});
        cases.push_back(e);
      }
  }
  if (!cases.empty()) PetscCall(CaseBatchRun(d.batch, cases, &rows));
  vals->resize(us.size());
  for (size_t e = 0; e < us.size(); ++e) {
    DesignValues &v = (*vals)[e];
    v.p             = d.ToP(us[e]);
    std::map<std::string, double> bat;
    if (d.bat_numbers) PetscCall(BatNumbers(d, v.p, &bat));
    PetscCall(Quantity(d, d.objective, rows, e * per, bat, v.p, &v.objective));
    v.constraint.resize(d.m());
    for (size_t i = 0; i < d.m(); ++i)
      PetscCall(Quantity(d, d.constraints[i].q, rows, e * per, bat, v.p, &v.constraint[i]));
    v.feasible = DesignViolated(d, v).empty();
    auto it    = d.known.find(us[e]);
    if (it == d.known.end()) {
      DesignRecord r;
      r.v = v, r.iteration = d.iteration, r.role = role;
      d.known[us[e]] = d.history.size();
      d.history.push_back(r);
    } else PromoteRole(d.history[it->second], role);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode DesignGradient(DesignProblem &d, const std::vector<double> &u, bool central, double step, double *f,
                              std::vector<double> *g, std::vector<double> *c, std::vector<double> *J)
{
  const size_t                     n = d.n(), m = d.m();
  std::vector<std::vector<double>> us = {u};
  std::vector<double>              up(n), um(n);
  std::vector<DesignValues>        v;

  PetscFunctionBeginUser;
  for (size_t j = 0; j < n; ++j) {
    const FitParameter &q  = d.vars[j];
    const double        p  = q.FromInternal(u[j]);
    const double        du = q.log ? std::log1p(step) / std::log(q.hi / q.lo)
                                   : step * std::max(std::fabs(p), 1e-3 * (q.hi - q.lo)) / (q.hi - q.lo);
    up[j] = u[j] + du, um[j] = central ? u[j] - du : u[j];
    if (up[j] > 1) up[j] = u[j], um[j] = u[j] - du; // at the upper bound: one-sided, downward
    if (um[j] < 0) um[j] = u[j], up[j] = u[j] + du;
    for (double w : {up[j], um[j]}) {
      std::vector<double> x = u;
      x[j]                  = w;
      us.push_back(x);
    }
  }
  PetscCall(DesignEvaluate(d, us, &v, 1));  // one batch: the point TAO asked for and its neighbours
  PromoteRole(d.history[d.known.at(u)], 2); // an iterate once TAO's monitor says so
  const double sign = d.settings.maximize ? -1 : 1;
  *f                = sign * v[0].objective;
  *c                = DesignTaoConstraints(d, v[0]);
  g->assign(n, 0.0), J->assign(m * n, 0.0);
  for (size_t j = 0; j < n; ++j) {
    const DesignValues &a = v[1 + 2 * j], &b = v[2 + 2 * j];
    const double        h        = up[j] - um[j];
    (*g)[j]                      = sign * (a.objective - b.objective) / h;
    const std::vector<double> ca = DesignTaoConstraints(d, a), cb = DesignTaoConstraints(d, b);
    for (size_t i = 0; i < m; ++i) (*J)[i * n + j] = (ca[i] - cb[i]) / h;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

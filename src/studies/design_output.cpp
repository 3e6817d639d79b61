// -task design's outputs: the summary, the results file (/design: every design evaluated, the
// optimum; /case_batch: the runs) and the optimum as an options file. See design_problem.hpp; the
// layout is in docs/design-studies.md.
#include "studies/design_problem.hpp"

#include "studies/design.hpp"

#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "studies/study_common.hpp"
#include "studies/sweep_store.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace beamimpact {

namespace {

const char *const kOptionsMarker = "# beamimpact -task design: the optimum";

std::string VariablesText(const DesignProblem &d, const std::vector<double> &p)
{
  std::string out;
  for (size_t j = 0; j < d.n(); ++j)
    out += Fmt("%s%s %.8g%s", j ? ", " : "", d.vars[j].name.c_str(), p[j], UnitText(d.vars[j].unit).c_str());
  return out;
}

// An optimum beyond -tao_catol: each constraint violated, what to try, the best feasible design evaluated.
std::vector<std::string> InfeasibleLines(const DesignProblem &d, const DesignResult &res)
{
  std::vector<std::string>  l;
  const std::vector<double> c = DesignTaoConstraints(d, res.v);
  l.push_back(Fmt("INFEASIBLE: the run ended at a design that violates %zu constraint(s) by more than -tao_catol %g "
                  "(relative to the bound): not an optimum under the constraints, whatever TAO's reason says",
                  res.violated.size(), d.catol));
  for (size_t i : res.violated) {
    const DesignConstraint &k = d.constraints[i];
    l.push_back(Fmt("  violated: %s = %.8g%s, its bound %s %g (beyond it by %.3g of the bound)", k.q.text.c_str(),
                    res.v.constraint[i], UnitText(k.q.unit).c_str(), k.upper ? "<=" : ">=", k.bound, -c[i]));
  }
  std::string a = Fmt("try: a smaller -tao_gatol (it is %g), more -tao_max_it (it is %d)", res.gatol, (int)res.max_it);
  if (res.almm_type == "phr")
    a += ", -tao_almm_type classic with a larger -tao_almm_mu_init (almm's first penalty; PHR, the default, "
         "chooses its own and ignores it)";
  else if (res.almm_type == "classic") a += ", a larger -tao_almm_mu_init (almm's first penalty)";
  l.push_back(a + ", or a feasible start (-design_variables NAME=LO:HI:START)");
  if (res.best_feasible < 0) l.push_back("no design evaluated was feasible");
  else {
    const DesignRecord &r = d.history[res.best_feasible];
    l.push_back(Fmt("the best feasible design evaluated: /design row %ld (TAO's iteration %d): %s = %.10g; %s",
                    res.best_feasible, (int)r.iteration, d.objective.text.c_str(), r.v.objective,
                    VariablesText(d, r.v.p).c_str()));
  }
  return l;
}

// The optimum's lines, shared by the summary and the options file's header.
std::vector<std::string> ResultLines(const DesignProblem &d, const DesignResult &res)
{
  std::vector<std::string> l;
  l.push_back(Fmt("TAO %s: %s after %d iterations; KKT residual %.3g, constraint norm %.3g", res.tao_type.c_str(),
                  res.reason.c_str(), (int)res.iterations, res.kkt, res.cnorm));
  l.push_back(Fmt("%s %s = %.10g%s (the start's %.10g)", d.settings.maximize ? "maximised" : "minimised",
                  d.objective.text.c_str(), res.v.objective, UnitText(d.objective.unit).c_str(),
                  d.history.empty() ? NAN : d.history.front().v.objective));
  for (size_t j = 0; j < d.n(); ++j)
    l.push_back(Fmt("  %-28s %.10g%s (start %.6g, bounds %g:%g)", d.vars[j].name.c_str(), res.p[j],
                    UnitText(d.vars[j].unit).c_str(), d.vars[j].start, d.vars[j].lo, d.vars[j].hi));
  for (size_t i = 0; i < d.m(); ++i) {
    const DesignConstraint &c      = d.constraints[i];
    bool                    active = false;
    for (const std::string &a : res.active) active = active || a == c.q.text;
    l.push_back(Fmt("  %-28s %.8g%s %s %g%s", c.q.text.c_str(), res.v.constraint[i], UnitText(c.q.unit).c_str(),
                    c.upper ? "<=" : ">=", c.bound, active ? "  (active)" : ""));
  }
  for (const std::string &n : res.notes) l.push_back("note: " + n);
  if (res.feasible())
    l.push_back(d.m() ? Fmt("feasible: every constraint holds within -tao_catol %g of its bound (relative)", d.catol)
                      : "feasible: no constraints");
  else
    for (const std::string &x : InfeasibleLines(d, res)) l.push_back(x);
  for (const std::string &b : res.at_bound) l.push_back("note: " + b + " is at a bound of -design_variables");
  return l;
}

std::string OptionsText(const DesignProblem &d, const DesignResult &res, const std::string &output)
{
  std::ostringstream o;
  o << kOptionsMarker << ", ready to include: -options_file THIS_FILE\n";
  if (!res.feasible())
    o << "# INFEASIBLE: NOT an optimum under the constraints (a constraint beyond -tao_catol; the program's exit "
         "status "
      << kDesignInfeasibleStatus << "): see below\n";
  o << "# objective: " << (d.settings.maximize ? "maximise " : "minimise ") << d.objective.text
    << "; constraints: " << (d.settings.constraints.empty() ? "none" : d.settings.constraints) << "\n";
  o << "# studies: " << (d.settings.studies.empty() ? "none" : d.settings.studies) << "\n";
  o << "# " << d.history.size() << " designs evaluated; results in " << (output.empty() ? "(no -output)" : output)
    << "\n";
  for (const std::string &l : ResultLines(d, res)) o << "# " << l << "\n";
  for (size_t j = 0; j < d.n(); ++j) o << Fmt("-%s %.17g\n", d.vars[j].name.c_str(), res.p[j]);
  return o.str();
}

std::string ViolatedText(const DesignProblem &d, const DesignResult &res)
{
  std::string out;
  for (size_t i : res.violated) {
    const DesignConstraint &k = d.constraints[i];
    out += Fmt("%s%s = %.8g %s %g", out.empty() ? "" : ", ", k.q.text.c_str(), res.v.constraint[i], k.upper ? ">" : "<",
               k.bound);
  }
  return out;
}

PetscErrorCode WriteDesignGroup(const DesignProblem &d, const DesignResult &res, hid_t file)
{
  PetscFunctionBeginUser;
  const hid_t g = H5Gcreate2(file, "design", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /design");
  std::vector<std::string> names, cnames, units;
  std::vector<double>      start, lo, hi;
  for (const FitParameter &q : d.vars)
    names.push_back(q.name), units.push_back(q.unit.empty() ? "1" : q.unit), start.push_back(q.start),
      lo.push_back(q.lo), hi.push_back(q.hi);
  for (const DesignConstraint &c : d.constraints) cnames.push_back(c.Name());
  PetscCheck(H5WriteStringColumn(g, "variables", names, "text (the design variables: options without their dash)") &&
               H5WriteStringColumn(g, "variable_units", units, "text") &&
               H5WriteStringColumn(g, "objective_text", {d.objective.text},
                                   d.settings.maximize ? "text (maximised)" : "text (minimised)") &&
               (cnames.empty() ||
                H5WriteStringColumn(g, "constraints", cnames, "text (the datasets of the constraints' quantities)")),
             PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write /design's names");
  PetscCall(H5WriteDataset1D(g, "optimum", res.p, "each variable's (/design/variable_units)"));
  PetscCall(H5WriteDataset1D(g, "start", start, "each variable's"));
  PetscCall(H5WriteDataset1D(g, "lower", lo, "each variable's"));
  PetscCall(H5WriteDataset1D(g, "upper", hi, "each variable's"));
  std::vector<double> obj, feas, kkt, cn, it, role;
  for (const DesignRecord &r : d.history)
    obj.push_back(r.v.objective), feas.push_back(r.v.feasible), kkt.push_back(r.kkt), cn.push_back(r.cnorm),
      it.push_back(r.iteration), role.push_back(r.role);
  for (size_t j = 0; j < d.n(); ++j) {
    std::vector<double> x;
    for (const DesignRecord &r : d.history) x.push_back(r.v.p[j]);
    PetscCall(H5WriteDataset1D(g, d.vars[j].name.c_str(), x, d.vars[j].unit.empty() ? "1" : d.vars[j].unit.c_str()));
  }
  for (size_t i = 0; i < d.m(); ++i) {
    std::vector<double> x;
    for (const DesignRecord &r : d.history) x.push_back(r.v.constraint[i]);
    PetscCall(H5WriteDataset1D(g, d.constraints[i].Name().c_str(), x, d.constraints[i].q.unit.c_str()));
  }
  PetscCall(H5WriteDataset1D(g, "objective", obj, d.objective.unit.c_str()));
  PetscCall(H5WriteCounts1D(g, "feasible", feas, "1 (every constraint holds)"));
  PetscCall(H5WriteDataset1D(g, "kkt_residual", kkt,
                             "1 (TAO's gradient norm of the (Lagrangian of the) scaled problem at its iterates; NaN at "
                             "a difference's point)"));
  PetscCall(
    H5WriteDataset1D(g, "constraint_norm", cn, "1 (TAO's norm of the scaled constraints' violation at its iterates)"));
  PetscCall(H5WriteCounts1D(g, "iteration", it, "1 (TAO's iteration that asked for the design)"));
  PetscCall(H5WriteCounts1D(g, "role", role,
                            "1 (0: an iterate of TAO, 2: a point TAO asked for that no iteration took (a line search's "
                            "trial), 1: only a point of a difference)"));
  RunRecord a; // the optimum's status
  a.add("converged_feasible", (PetscInt)res.feasible());
  a.add("status", res.feasible() ? std::string("feasible: every constraint within -tao_catol of its bound")
                                 : "INFEASIBLE: the optimum violates " + ViolatedText(d, res) + " beyond -tao_catol");
  a.add("catol", d.catol);
  PetscCall(H5WriteAttributes(g, a));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode DesignRecordOf(const DesignProblem &d, const DesignResult &res, RunRecord *rec)
{
  PetscFunctionBeginUser;
  PetscCall(RunRecordProgram(rec));
  rec->options_used.clear(); // the readers' log holds the last run's values, not the design's
  rec->add("task", "design");
  rec->add("design_variables", d.settings.variables);
  rec->add("design_studies", d.settings.studies);
  rec->add("design_objective", d.objective.text);
  rec->add("design_goal", d.settings.maximize ? "maximize" : "minimize");
  rec->add("design_constraints", d.settings.constraints);
  rec->add("design_tao_type", res.tao_type);
  rec->add("design_converged_reason", res.reason);
  rec->add("design_iterations", res.iterations);
  rec->add("design_objective_value", res.v.objective);
  rec->add("design_feasible", (PetscInt)res.feasible());
  rec->add("design_kkt_residual", res.kkt);
  rec->add("design_designs", (PetscInt)d.history.size());
  rec->add("design_runs_computed", d.batch.counts.computed);
  rec->add("design_runs_reused", d.batch.counts.reused);
  rec->add("design_runs_loaded", d.batch.counts.loaded + d.batch.counts.loaded_journal);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode DesignCheckOutputs(MPI_Comm comm, const std::string &output, const DesignSettings &s)
{
  PetscFunctionBeginUser;
  PetscCall(
    StudyCheckOptionsOutput(comm, s.options_output, output, "-design_options_output", kOptionsMarker, "a design"));
  PetscFunctionReturn(0);
}

PetscErrorCode DesignPrintSummary(const DesignProblem &d, const DesignResult &res)
{
  PetscFunctionBeginUser;
  std::string out;
  for (const std::string &l : ResultLines(d, res)) out += "design: " + l + "\n";
  PetscCall(PetscPrintf(d.world, "%s", out.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode DesignWriteOutputs(DesignProblem &d, const DesignResult &res, const std::string &output)
{
  RunRecord rec;

  PetscFunctionBeginUser;
  if (!output.empty()) {
    PetscCall(DesignRecordOf(d, res, &rec));
    PetscCall(H5ResultsFileWrite(d.world, output, rec, [&](long long file) -> PetscErrorCode {
      PetscFunctionBeginUser;
      PetscCall(WriteDesignGroup(d, res, (hid_t)file));
      PetscCall(CaseBatchWrite(d.batch, file));
      PetscFunctionReturn(0);
    }));
    PetscCall(CaseBatchFinish(d.batch));
  }
  const std::string &opts = d.settings.options_output;
  PetscErrorCode     ierr = 0;
  if (!opts.empty() && d.rank == 0)
    ierr = StudyWriteAtomically(opts, OptionsText(d, res, output), "-design_options_output");
  PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, d.world));
  PetscCheck(!ierr || d.rank == 0, d.world, ierr, "-design_options_output %s could not be written", opts.c_str());
  PetscCall(ierr);
  if (!output.empty() && !opts.empty())
    PetscCall(PetscPrintf(d.world, "wrote %s and %s\n", output.c_str(), opts.c_str()));
  else if (!output.empty() || !opts.empty())
    PetscCall(PetscPrintf(d.world, "wrote %s\n", output.empty() ? opts.c_str() : output.c_str()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

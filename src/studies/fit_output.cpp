// -task fit's outputs: the summary, the results file (/fit and the case batch's rows) and the
// fitted values as an options file. See fit_problem.hpp; the layout is in docs/fit.md.
#include "studies/fit_problem.hpp"
#include "studies/study_common.hpp"

#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "studies/sweep_store.hpp"

#include <hdf5.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace beamimpact {

namespace {

const char *const kOptionsMarker = "# beamimpact -task fit: fitted values";

// The undetermined combinations, one line each.
std::vector<std::string> Warnings(const FitProblem &f, const FitResult &res)
{
  std::vector<std::string> w;
  std::string              determined; // the combinations the data do fix (when few)
  const size_t             nfixed = f.n() - res.u.undetermined.size();
  for (size_t k = 0; k < nfixed && nfixed <= 3; ++k)
    determined += (k ? "; " : "") + FitCombinationText(res.u, k, f.Names(), res.p);
  for (size_t k : res.u.undetermined)
    w.push_back(Fmt("warning: the parameters are not identifiable from these data: moving along %s changes no fitted "
                    "value (singular value %.2e of the largest, below "
                    "-fit_identifiability_tol %g), so that combination is not determined%s%s; the standard errors of "
                    "the parameters in it are infinite: fix one of them or add data that "
                    "separate them",
                    FitCombinationText(res.u, k, f.Names(), res.p).c_str(),
                    res.u.singular[0] > 0 ? res.u.singular[k] / res.u.singular[0] : 0.0, f.settings.identifiability,
                    determined.empty() ? "" : "; the data determine only ", determined.c_str()));
  for (const std::string &b : res.at_bound)
    w.push_back(
      "note: " + b +
      " is at a bound of -fit_parameters: its standard error assumes it could move past it (widen the bounds?)");
  return w;
}

std::string SigmaKind(const FitProblem &f, const FitResult &res)
{
  if (f.data.absolute) return "the sigma are standard deviations: the covariance is (J^T J)^-1";
  return Fmt("the sigma are relative weights: the covariance is s^2 (J^T J)^-1 with s^2 = chi^2/(m - n) = %.6g",
             res.s2);
}

// The options file's text: the header (data file and its SHA-256, chi^2, standard errors, warnings)
// and one line per parameter, its value exact (%.17g).
std::string OptionsText(const FitProblem &f, const FitResult &res, const std::string &output)
{
  std::ostringstream o;
  o << kOptionsMarker << ", ready to include: -options_file THIS_FILE\n";
  o << "# data: " << f.data.file << "  SHA-256 " << f.data.sha256 << "\n";
  o << "# each row runs -task " << f.settings.task->name << "; " << f.data.rows.size() << " rows, " << f.m()
    << " measured values, " << f.n() << " parameters; results in " << (output.empty() ? "(no -output)" : output)
    << "\n";
  o << Fmt("# TAO %s: %s after %d iterations\n", res.tao_type.c_str(), res.reason.c_str(), (int)res.iterations);
  o << Fmt("# chi^2 = %.6g for m - n = %d degrees of freedom (chi^2/(m - n) = %.6g); %s\n", res.chi2, (int)res.dof,
           res.dof > 0 ? res.chi2 / res.dof : NAN, SigmaKind(f, res).c_str());
  o << "# weights: " << f.data.sigma_text << "\n";
  for (size_t j = 0; j < f.n(); ++j)
    o << Fmt("#   %-28s %.10g +- %.3g%s (%.3g%%)\n", f.params[j].name.c_str(), res.p[j], res.u.standard_error[j],
             UnitText(f.params[j].unit).c_str(), 100 * res.u.standard_error[j] / std::fabs(res.p[j]));
  for (size_t a = 0; a < f.n(); ++a)
    for (size_t b = a + 1; b < f.n(); ++b)
      o << Fmt("#   correlation(%s, %s) = %.4f\n", f.params[a].name.c_str(), f.params[b].name.c_str(),
               res.u.correlation[a * f.n() + b]);
  for (const std::string &w : Warnings(f, res)) o << "# " << w << "\n";
  for (size_t j = 0; j < f.n(); ++j) o << Fmt("-%s %.17g\n", f.params[j].name.c_str(), res.p[j]);
  return o.str();
}

// /fit's datasets (rank 0).
PetscErrorCode WriteFitGroup(const FitProblem &f, const FitResult &res, hid_t file)
{
  const size_t n = f.n();

  PetscFunctionBeginUser;
  const hid_t g = H5Gcreate2(file, "fit", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /fit");
  std::vector<std::string> units, scales;
  std::vector<double>      start, lower, upper;
  for (const FitParameter &q : f.params) {
    units.push_back(q.unit.empty() ? "1" : q.unit), scales.push_back(q.log ? "log" : "linear");
    start.push_back(q.start), lower.push_back(q.lo), upper.push_back(q.hi);
  }
  PetscCheck(H5WriteStringColumn(g, "names", f.Names(), "text (the options fitted, without their dash)") &&
               H5WriteStringColumn(g, "unit", units, "text (each parameter's unit)") &&
               H5WriteStringColumn(g, "scale", scales, "text (how TAO saw it: linear or log over its bounds)"),
             PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write /fit's names");
  const char *each = "each parameter's (/fit/unit)";
  PetscCall(H5WriteDataset1D(g, "value", res.p, each));
  PetscCall(H5WriteDataset1D(g, "standard_error", res.u.standard_error, each));
  PetscCall(H5WriteDataset1D(g, "start", start, each));
  PetscCall(H5WriteDataset1D(g, "lower", lower, each));
  PetscCall(H5WriteDataset1D(g, "upper", upper, each));
  std::vector<std::vector<double>> corr(n), cov(n), vec(n);
  for (size_t a = 0; a < n; ++a) {
    corr[a].assign(res.u.correlation.begin() + a * n, res.u.correlation.begin() + (a + 1) * n);
    cov[a].assign(res.u.covariance.begin() + a * n, res.u.covariance.begin() + (a + 1) * n);
    vec[a].assign(res.u.vectors.begin() + a * n, res.u.vectors.begin() + (a + 1) * n);
  }
  PetscCall(H5WriteDataset2D(g, "correlation", corr, "1"));
  PetscCall(H5WriteDataset2D(g, "covariance", cov, "the product of the two parameters' units"));
  PetscCall(H5WriteDataset1D(g, "singular_values", res.u.singular,
                             "1 (of J diag(|p|): the weighted residuals per unit of log p)"));
  PetscCall(H5WriteDataset2D(g, "singular_vectors", vec,
                             "1 (row k: the right singular vector of singular_values[k], over log p)"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// /fit/residuals and /fit/history (rank 0).
PetscErrorCode WriteTables(const FitProblem &f, const FitResult &res, hid_t file)
{
  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(file, "fit/residuals", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /fit/residuals");
  std::vector<double>      row, line, y, sigma;
  std::vector<std::string> column, unit;
  for (const FitMeasurement &v : f.data.values) {
    row.push_back((double)v.row + 1), line.push_back(f.data.line[v.row]), y.push_back(v.y), sigma.push_back(v.sigma);
    column.push_back(f.data.measured[v.column]), unit.push_back(f.data.units[v.column]);
  }
  PetscCheck(H5WriteStringColumn(g, "column", column, "text (the measured column)") &&
               H5WriteStringColumn(g, "unit", unit, "text (the column's unit)"),
             PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write /fit/residuals");
  PetscCall(H5WriteCounts1D(g, "row", row, "1 (the data's row, from 1)"));
  PetscCall(H5WriteCounts1D(g, "line", line, "1 (the row's line in -fit_data)"));
  PetscCall(H5WriteDataset1D(g, "measured", y, "the column's (/fit/residuals/unit)"));
  PetscCall(H5WriteDataset1D(g, "sigma", sigma, "the column's (/fit/residuals/unit)"));
  PetscCall(H5WriteDataset1D(g, "fitted", res.fitted, "the column's (/fit/residuals/unit)"));
  PetscCall(H5WriteDataset1D(g, "weighted_residual", res.r, "1 ((fitted - measured)/sigma)"));
  H5Gclose(g);
  // /fit/rows: each data row's numeric settings (NaN where a row does not set the option), for plots.
  g = H5Gcreate2(file, "fit/rows", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /fit/rows");
  for (const std::string &name : f.data.option_columns) {
    std::vector<double> v;
    for (const CaseOptions &c : f.data.rows) {
      double x = NAN;
      for (const CaseSetting &s : c)
        if (s.name == name && s.text.empty()) x = s.value;
      v.push_back(x);
    }
    PetscCall(
      H5WriteDataset1D(g, name.c_str(), v, OptionUnit("-" + name).empty() ? "1" : OptionUnit("-" + name).c_str()));
  }
  H5Gclose(g);
  g = H5Gcreate2(file, "fit/history", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /fit/history");
  std::vector<double>              it, chi2, step, runs;
  std::vector<std::vector<double>> params;
  for (const FitIteration &h : f.history)
    it.push_back(h.iteration), chi2.push_back(h.chi2), step.push_back(h.step), runs.push_back(h.runs),
      params.push_back(h.p);
  PetscCall(H5WriteCounts1D(g, "iteration", it, "1"));
  PetscCall(H5WriteDataset1D(g, "chi2", chi2, "1"));
  PetscCall(H5WriteDataset1D(g, "step", step, "1 (largest relative change of a parameter since the last iteration)"));
  PetscCall(H5WriteCounts1D(g, "runs", runs, "1 (runs computed so far)"));
  PetscCall(
    H5WriteDataset2D(g, "parameters", params, "each parameter's (/fit/unit; columns in the order of /fit/names)"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode FitRecord(const FitProblem &f, const FitResult &res, RunRecord *rec)
{
  CaseBatchCounts c = f.batch.counts;

  PetscFunctionBeginUser;
  PetscCall(RunRecordProgram(rec));
  rec->options_used.clear(); // the readers' log holds the last run's values, not the fit's
  rec->add("task", "fit");
  rec->add("fit_task", f.settings.task->name);
  rec->add("fit_data", f.data.file);
  rec->add("fit_data_sha256", f.data.sha256);
  rec->add("fit_parameters", f.settings.parameters);
  rec->add("fit_tao_type", res.tao_type);
  rec->add("fit_converged_reason", res.reason);
  rec->add("fit_iterations", res.iterations);
  rec->add("fit_chi2", res.chi2);
  rec->add("fit_dof", res.dof);
  rec->add("fit_s2", res.s2);
  rec->add("fit_sigma", f.data.absolute ? "absolute" : "relative");
  rec->add("fit_sigma_text", f.data.sigma_text);
  rec->add("fit_condition", res.u.condition);
  rec->add("fit_undetermined", (PetscInt)res.u.undetermined.size());
  rec->add("fit_runs_computed", c.computed);
  rec->add("fit_runs_reused", c.reused);
  rec->add("fit_runs_loaded", c.loaded + c.loaded_journal);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode FitCheckOutputs(MPI_Comm comm, const std::string &output, const FitSettings &s)
{
  PetscFunctionBeginUser;
  PetscCall(StudyCheckOptionsOutput(comm, s.options_output, output, "-fit_options_output", kOptionsMarker, "a fit"));
  PetscFunctionReturn(0);
}

PetscErrorCode FitPrintSummary(const FitProblem &f, const FitResult &res)
{
  PetscFunctionBeginUser;
  if (f.rank != 0) PetscFunctionReturn(0);
  std::string out = Fmt("fit: TAO %s: %s after %d iterations\n", res.tao_type.c_str(), res.reason.c_str(),
                        (int)res.iterations);
  out += Fmt("  %-28s %-22s %-14s %s\n", "parameter", "value", "standard error", "(relative)");
  for (size_t j = 0; j < f.n(); ++j)
    out += Fmt("  %-28s %-22s %-14.4g (%.3g%%)\n", f.params[j].name.c_str(),
               Fmt("%.10g%s", res.p[j], UnitText(f.params[j].unit).c_str()).c_str(), res.u.standard_error[j],
               100 * res.u.standard_error[j] / std::fabs(res.p[j]));
  for (size_t a = 0; a < f.n(); ++a)
    for (size_t b = a + 1; b < f.n(); ++b)
      out += Fmt("  correlation(%s, %s) = %.4f\n", f.params[a].name.c_str(), f.params[b].name.c_str(),
                 res.u.correlation[a * f.n() + b]);
  out += Fmt("chi^2 = %.6g for %zu values and %zu parameters: chi^2/(m - n) = %.6g; %s\n", res.chi2, f.m(), f.n(),
             res.dof > 0 ? res.chi2 / res.dof : NAN, SigmaKind(f, res).c_str());
  out += Fmt("identifiability: singular values of J diag(|p|) from %.4g to %.4g (condition %.3g)\n",
             res.u.singular.front(), res.u.singular.back(), res.u.condition);
  for (const std::string &w : Warnings(f, res)) out += w + "\n";
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s", out.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode FitWriteOutputs(FitProblem &f, const FitResult &res, const std::string &output)
{
  RunRecord rec;

  PetscFunctionBeginUser;
  if (!output.empty()) {
    PetscCall(FitRecord(f, res, &rec));
    PetscCall(H5ResultsFileWrite(f.world, output, rec, [&](long long file) -> PetscErrorCode {
      PetscFunctionBeginUser;
      PetscCall(WriteFitGroup(f, res, (hid_t)file));
      PetscCall(WriteTables(f, res, (hid_t)file));
      PetscCall(CaseBatchWrite(f.batch, file));
      PetscFunctionReturn(0);
    }));
    PetscCall(CaseBatchFinish(f.batch)); // the file holds every run: the journals go
  }
  const std::string &opts = f.settings.options_output;
  PetscErrorCode     ierr = 0;
  if (!opts.empty() && f.rank == 0)
    ierr = StudyWriteAtomically(opts, OptionsText(f, res, output), "-fit_options_output");
  PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, f.world));
  PetscCheck(!ierr || f.rank == 0, f.world, ierr, "-fit_options_output %s could not be written", opts.c_str());
  PetscCall(ierr);
  if (!output.empty() && !opts.empty())
    PetscCall(PetscPrintf(f.world, "wrote %s and %s\n", output.c_str(), opts.c_str()));
  else if (!output.empty() || !opts.empty())
    PetscCall(PetscPrintf(f.world, "wrote %s\n", output.empty() ? opts.c_str() : output.c_str()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

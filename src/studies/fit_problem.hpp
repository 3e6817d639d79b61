// The least-squares problem of -task fit (studies/fit.hpp), shared by its parts: the residuals and
// Jacobians through the case batch (fit_problem.cpp), TAO (fit_solve.cpp) and the outputs
// (fit_output.cpp). The parameters TAO sees are scaled to u in [0, 1] (FitParameter).
#pragma once

#include "studies/case_batch.hpp"
#include "studies/fit_data.hpp"
#include "studies/fit_stats.hpp"

#include <petsctao.h>

#include <string>
#include <vector>

namespace beamimpact {

// One iteration of the optimiser, as its monitor saw it.
struct FitIteration {
  PetscInt            iteration = 0;
  double              chi2      = 0; // sum of the squared weighted residuals (1)
  double              step      = 0; // largest relative change of a parameter since the last iteration (1)
  PetscInt            runs      = 0; // runs computed so far
  std::vector<double> p;             // the parameters (their units)
};

// What the fit found: the optimum, its residuals and its uncertainty.
struct FitResult {
  std::vector<double>      p;         // the parameters at the optimum (their units)
  std::vector<double>      fitted, r; // the program's value and the weighted residual of each measured value
  double                   chi2 = 0;  // sum r^2 (1)
  PetscInt                 dof  = 0;  // m - n
  double                   s2   = 1;  // the covariance's scale: 1 (absolute sigma) or chi2/dof (relative)
  FitUncertainty           u;
  std::vector<std::string> at_bound;         // the parameters the optimum holds at a bound
  std::string              tao_type, reason; // TAO's type and why it stopped
  PetscInt                 iterations = 0;
};

struct FitProblem {
  MPI_Comm                  world = MPI_COMM_NULL;
  PetscMPIInt               rank  = 0;
  FitSettings               settings;
  std::vector<FitParameter> params;
  FitData                   data;
  CaseBatch                 batch;
  std::vector<FitIteration> history;
  std::vector<double>       u_prev; // the last iteration's scaled parameters (the step test)
  bool                      u_prev_set = false;
  double                    f_prev     = 0;          // the last iteration's objective (chi^2/2: the chi^2 test)
  std::string               stop;                    // which of the program's tests stopped brgn ("" none: TAO's own)
  bool                      options_checked = false; // the unused-option check ran (after the first residual)

  size_t                   m() const { return data.values.size(); }
  size_t                   n() const { return params.size(); }
  std::vector<double>      ToP(const std::vector<double> &u) const;
  std::vector<double>      ToU(const std::vector<double> &p) const;
  std::vector<std::string> Names() const;
};

// Collective: the program's value of every measured value at the parameters p (one batch, one run
// per row of the data), and the weighted residuals. A failed run or a value the run does not give
// is an error naming the data's row and column.
PetscErrorCode FitResidual(FitProblem &f, const std::vector<double> &p, std::vector<double> *fitted,
                           std::vector<double> *r);
// Collective: the Jacobian dr/du (m x n row-major) of the scaled parameters u by differences,
// rows x parameters in one batch: forward (a parameter at its upper bound steps down) or central;
// each step a relative change `step` of the parameter. *at_bound: the parameters whose central
// difference had to be one-sided.
PetscErrorCode FitJacobian(FitProblem &f, const std::vector<double> &u, bool central, double step,
                           std::vector<double> *J, std::vector<std::string> *at_bound = nullptr);
// dp/du of each parameter at u.
std::vector<double> FitScaleDerivative(const FitProblem &f, const std::vector<double> &u);

// The program's defaults, set before TaoSetFromOptions: brgn, its regularizer weight 0 (plain
// Gauss-Newton), gradient tolerances 0, 50 iterations.
PetscErrorCode FitTaoDefaults(Tao tao);
// Collective: TAO (on PETSC_COMM_SELF on every rank with the same numbers; -tao_* options last)
// from the start to the optimum; fills res->p, tao_type, reason, iterations and f.history.
PetscErrorCode FitSolve(FitProblem &f, FitResult *res);

// Collective: the residuals, the Jacobian (central, -fit_covariance_step) and the uncertainty at res->p.
PetscErrorCode FitUncertaintyAtOptimum(FitProblem &f, FitResult *res);

// Before any run: -output and -fit_options_output are writable and none is an input of the run.
PetscErrorCode FitCheckOutputs(MPI_Comm comm, const std::string &output, const FitSettings &s);
// The summary on rank 0 (parameters, standard errors, correlations, chi^2, warnings).
PetscErrorCode FitPrintSummary(const FitProblem &f, const FitResult &res);
// The results file (-output: /fit and /case_batch) and the options file; then the journals go.
PetscErrorCode FitWriteOutputs(FitProblem &f, const FitResult &res, const std::string &output);

} // namespace beamimpact

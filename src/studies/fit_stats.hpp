// The uncertainty of a least-squares fit at its optimum (docs/model.md section 17), as plain
// functions of numbers: from the weighted Jacobian J = dr/dp (m residuals r_i = (f_i - y_i)/sigma_i,
// n parameters p) the covariance C = s^2 (J^T J)^-1, the standard errors sqrt(C_jj), the
// correlations C_jk / sqrt(C_jj C_kk), and the singular value decomposition of J scaled by the
// parameters, J diag(|p|) = dr/dlog p: a singular value below tol times the largest names its
// right singular vector, a combination of the parameters' logarithms the data do not determine
// (E and rho fitted to a beam's frequencies alone: +0.71 log E - 0.71 log rho).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

struct FitUncertainty {
  std::vector<double>
    covariance; // n x n, row-major (the parameters' units: unit_j unit_k); +-inf where an undetermined direction enters
  std::vector<double> standard_error; // n (the parameters' units)
  std::vector<double> correlation;    // n x n, row-major (1)
  std::vector<double> singular;       // n singular values of J diag(|p|), descending (1: r per unit of log p)
  std::vector<double> vectors;        // n x n, row-major: row k the right singular vector of singular[k] (1)
  double              condition = 0;  // singular[0] / singular[n-1] (inf when the last is 0)
  std::vector<size_t> undetermined;   // the k whose singular[k] < tol singular[0]
};

// J: m x n row-major (dr_i/dp_j), p the parameters (a zero p_j is scaled by 1: its column stays
// dr/dp_j), s2 the variance scale (1 when the sigma are standard deviations; chi^2/(m - n) when they
// are relative weights), tol the relative singular value below which a direction is undetermined.
// LAPACK's dgesvd (as PETSc links it).
PetscErrorCode FitUncertaintyOf(const std::vector<double> &J, size_t m, size_t n, const std::vector<double> &p,
                                double s2, double tol, FitUncertainty *u);

// The combination of singular vector k, "+0.71 log beam_youngs_modulus - 0.71 log beam_density"
// (components of magnitude >= 0.01, the first positive; "d name" for a parameter at 0).
std::string FitCombinationText(const FitUncertainty &u, size_t k, const std::vector<std::string> &names,
                               const std::vector<double> &p);

} // namespace beamimpact

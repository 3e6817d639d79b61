// The uncertainty of a fit. See fit_stats.hpp.
#include "studies/fit_stats.hpp"

#include <petscblaslapack.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace beamimpact {

PetscErrorCode FitUncertaintyOf(const std::vector<double> &J, size_t m, size_t n, const std::vector<double> &p,
                                double s2, double tol, FitUncertainty *u)
{
  const double inf = std::numeric_limits<double>::infinity();

  PetscFunctionBeginUser;
  PetscCheck(J.size() == m * n && p.size() == n && m >= 1 && n >= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "FitUncertaintyOf: J has %zu entries for %zu x %zu", J.size(), m, n);
  std::vector<double> d(n),
    A(std::max(m, n) * n, 0.0); // A: J diag(d), column-major, m x n (padded to n rows when m < n)
  const size_t lda = std::max(m, n);
  for (size_t j = 0; j < n; ++j) {
    d[j] = p[j] != 0 ? std::fabs(p[j]) : 1.0;
    for (size_t i = 0; i < m; ++i) A[i + j * lda] = J[i * n + j] * d[j];
  }
  PetscBLASInt bm, bn, blda, ldu = 1, lwork = -1, info = 0;
  PetscCall(PetscBLASIntCast((PetscInt)lda, &bm));
  PetscCall(PetscBLASIntCast((PetscInt)n, &bn));
  blda = bm;
  std::vector<double> s(n), vt(n * n), work(1);
  double              dummy = 0;
  PetscCallBLAS("LAPACKgesvd", LAPACKgesvd_("N", "A", &bm, &bn, A.data(), &blda, s.data(), &dummy, &ldu, vt.data(), &bn,
                                            work.data(), &lwork, &info));
  lwork = (PetscBLASInt)work[0];
  work.resize((size_t)std::max<PetscBLASInt>(lwork, 1));
  PetscCallBLAS("LAPACKgesvd", LAPACKgesvd_("N", "A", &bm, &bn, A.data(), &blda, s.data(), &dummy, &ldu, vt.data(), &bn,
                                            work.data(), &lwork, &info));
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK dgesvd failed (info %d)", (int)info);
  u->singular = s;
  u->vectors.assign(n * n, 0.0);
  for (size_t k = 0; k < n; ++k)
    for (size_t j = 0; j < n; ++j) u->vectors[k * n + j] = vt[k + j * n]; // row k of V^T
  u->condition = s[n - 1] > 0 ? s[0] / s[n - 1] : inf;
  u->undetermined.clear();
  std::vector<bool>
    weak(n,
         false); // an undetermined direction: its variance is infinite, whatever round-off left of its singular value
  for (size_t k = 0; k < n; ++k)
    if (!(s[k] >= tol * s[0]) || s[0] == 0) u->undetermined.push_back(k), weak[k] = true;
  // C = s2 D V S^-2 V^T D (an undetermined direction's 1/s^2 infinite)
  u->covariance.assign(n * n, 0.0);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = 0; b < n; ++b) {
      double c = 0;
      for (size_t k = 0; k < n; ++k) {
        const double vv = u->vectors[k * n + a] * u->vectors[k * n + b];
        c += !weak[k] ? vv / (s[k] * s[k]) : (vv != 0 ? std::copysign(inf, vv) : 0.0);
      }
      u->covariance[a * n + b] = s2 * d[a] * d[b] * c;
    }
  u->standard_error.resize(n);
  for (size_t a = 0; a < n; ++a) u->standard_error[a] = std::sqrt(u->covariance[a * n + a]);
  u->correlation.assign(n * n, 0.0);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = 0; b < n; ++b) {
      const double q            = u->standard_error[a] * u->standard_error[b];
      u->correlation[a * n + b] = a == b ? 1.0
                                         : (std::isfinite(q) && q > 0 ? u->covariance[a * n + b] / q
                                                                      : std::numeric_limits<double>::quiet_NaN());
    }
  PetscFunctionReturn(0);
}

std::string FitCombinationText(const FitUncertainty &u, size_t k, const std::vector<std::string> &names,
                               const std::vector<double> &p)
{
  const size_t n     = names.size();
  size_t       first = 0; // the first component shown is positive
  while (first + 1 < n && std::fabs(u.vectors[k * n + first]) < 0.01) ++first;
  const double sign = u.vectors[k * n + first] < 0 ? -1.0 : 1.0;
  std::string  out;
  for (size_t j = 0; j < n; ++j) {
    const double v = sign * u.vectors[k * n + j];
    if (std::fabs(v) < 0.01) continue;
    char term[256];
    std::snprintf(term, sizeof term, "%s%.2f %s %s", out.empty() ? (v < 0 ? "-" : "+") : (v < 0 ? " - " : " + "),
                  std::fabs(v), p[j] != 0 ? "log" : "d", names[j].c_str());
    out += term;
  }
  return out;
}

} // namespace beamimpact

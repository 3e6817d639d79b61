// Imaginary-axis stability bound of an explicit Runge-Kutta tableau. See rk_stability.hpp.
#include "solvers/rk_stability.hpp"

#include <cmath>
#include <complex>
#include <vector>

namespace beamimpact {

PetscReal RKImaginaryStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b)
{
  using cplx = std::complex<double>;
  auto amp   = [&](double y) {
    const cplx         z(0.0, y);
    std::vector<cplx>  k(s);
    cplx               R = 1.0;
    for (PetscInt i = 0; i < s; ++i) {
      cplx sum = 0.0;
      for (PetscInt j = 0; j < i; ++j) sum += A[i * s + j] * k[j];
      k[i] = 1.0 + z * sum;
      R += z * b[i] * k[i];
    }
    return std::abs(R);
  };
  // Growth per step allowed: 1e-12 (1e-4 over 1e8 steps). RK2's |R(iy)| = 1 + y^4/8 + ...
  // exceeds it from y = 1.7e-3: such a method is reported unstable at any practical step.
  const double tol = 1e-12, dy = 1e-3;
  double       y   = 0.0;
  while (y < 20.0 && amp(y + dy) <= 1.0 + tol) y += dy;
  if (y < 0.05) return 0.0;
  double lo = y, hi = y + dy; // refine the edge
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (amp(mid) <= 1.0 + tol ? lo : hi) = mid;
  }
  return lo;
}

} // namespace beamimpact

// Imaginary-axis stability bound of an explicit Runge-Kutta tableau. See rk_stability.hpp.
#include "solvers/rk_stability.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace beamimpact {

namespace {

// |R(z)| of the explicit tableau.
double RKAmplification(PetscInt s, const PetscReal *A, const PetscReal *b, std::complex<double> z)
{
  using cplx = std::complex<double>;
  std::vector<cplx> k(s);
  cplx              R = 1.0;
  for (PetscInt i = 0; i < s; ++i) {
    cplx sum = 0.0;
    for (PetscInt j = 0; j < i; ++j) sum += A[i * s + j] * k[j];
    k[i] = 1.0 + z * sum;
    R += z * b[i] * k[i];
  }
  return std::abs(R);
}

} // namespace

PetscReal RKImaginaryStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b)
{
  auto amp = [&](double y) { return RKAmplification(s, A, b, std::complex<double>(0.0, y)); };
  // Growth per step allowed: 1e-12 (1e-4 over 1e8 steps). RK2's |R(iy)| = 1 + y^4/8 + ...
  // exceeds it from y = 1.7e-3: such a method is reported unstable at any practical step.
  const double tol = 1e-12, dy = 1e-3;
  double       y = 0.0;
  while (y < 20.0 && amp(y + dy) <= 1.0 + tol) y += dy;
  if (y < 0.05) return 0.0;
  double lo = y, hi = y + dy; // refine the edge
  for (int it = 0; it < 60; ++it) {
    const double mid                  = 0.5 * (lo + hi);
    (amp(mid) <= 1.0 + tol ? lo : hi) = mid;
  }
  return lo;
}

PetscReal RKDampedStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b, PetscReal omega_max,
                                 PetscReal alpha, PetscReal beta)
{
  using cplx = std::complex<double>;
  // The modes sampled at K frequencies up to omega_max (the growth of a mode varies smoothly
  // with w); each gives two eigenvalues, complex (zeta < 1) or real (overdamped).
  // rate: the largest |lambda|, omega_max unless a mode is overdamped (then w (zeta + sqrt(zeta^2 - 1))
  // of the most damped one, the real eigenvalue that limits the step, far beyond omega_max under
  // strong stiffness damping).
  const int         K    = 256;
  double            rate = omega_max;
  std::vector<cplx> lam;
  for (int k = 1; k <= K; ++k) {
    const double w = omega_max * k / K, zeta = alpha / (2 * w) + beta * w / 2;
    const cplx   r = std::sqrt(cplx(zeta * zeta - 1.0, 0.0));
    lam.push_back(w * (-zeta + r));
    lam.push_back(w * (-zeta - r));
    if (zeta > 1) rate = std::max(rate, w * (zeta + std::sqrt(zeta * zeta - 1.0)));
  }
  const double tol    = 1e-12;
  auto         stable = [&](double dt) {
    for (const cplx &l : lam)
      if (RKAmplification(s, A, b, dt * l) > 1.0 + tol) return false;
    return true;
  };
  // Scan up from 0 in steps of 0.01/rate (the bounds are 1.7-3.4/rate on the imaginary axis,
  // 2.0-3.3/rate on the negative real axis), then refine.
  const double dd = 0.01 / rate;
  double       dt = 0.0;
  while (dt < 50.0 / rate && stable(dt + dd)) dt += dd;
  if (dt < 0.05 / rate) return 0.0;
  double lo = dt, hi = dt + dd;
  for (int it = 0; it < 50; ++it) {
    const double mid        = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

} // namespace beamimpact

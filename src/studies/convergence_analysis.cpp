// -task convergence, the analysis. See convergence_analysis.hpp.
#include "studies/convergence_analysis.hpp"

#include "run/results_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamimpact {

namespace {

const PetscReal NaN = std::numeric_limits<PetscReal>::quiet_NaN();

} // namespace

ConvergenceOrder ConvergenceOrderOf(const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs,
                                    PetscReal floor, PetscReal ConvergenceRun::*err)
{
  std::vector<PetscReal> h, e;
  for (auto &r : runs) {
    h.push_back(r.failed ? NaN : ConvergenceStepOf(cfg, r));
    e.push_back(r.*err);
  }
  return ConvergenceObservedOrder(h, e, floor);
}

PetscReal ConvergenceStepOf(const ConvergenceConfig &cfg, const ConvergenceRun &run)
{
  return cfg.seq.kind == ConvergenceSequenceKind::Tolerance ? run.mean_step : run.dt;
}

ConvergenceOrder ConvergenceObservedOrder(const std::vector<PetscReal> &h, const std::vector<PetscReal> &e,
                                          PetscReal floor)
{
  ConvergenceOrder o;
  const size_t     n = std::min(h.size(), e.size());
  auto ok            = [&](size_t k) { return std::isfinite(h[k]) && h[k] > 0 && std::isfinite(e[k]) && e[k] > floor; };
  o.pairwise.assign(n, NaN);
  for (size_t k = 1; k < n; ++k)
    if (ok(k) && ok(k - 1) && h[k] != h[k - 1]) o.pairwise[k] = std::log(e[k - 1] / e[k]) / std::log(h[k - 1] / h[k]);
  PetscReal sx = 0, sy = 0, sxx = 0, sxy = 0;
  PetscInt  m = 0;
  for (size_t k = 0; k < n; ++k) {
    if (!ok(k)) continue;
    const PetscReal x = std::log(h[k]), y = std::log(e[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    m++;
  }
  o.used              = m;
  const PetscReal den = m * sxx - sx * sx;
  o.lsq               = m >= 2 && den > 0 ? (m * sxy - sx * sy) / den : NaN;
  return o;
}

bool ConvergenceRichardson(PetscReal A1, PetscReal A2, PetscReal A3, PetscReal r, PetscReal *p, PetscReal *A0)
{
  const PetscReal d12 = A1 - A2, d23 = A2 - A3;
  *p  = NaN;
  *A0 = A3;
  if (!(r > 1) || d23 == 0 || d12 == 0 || !std::isfinite(d12) || !std::isfinite(d23))
    return d23 == 0 && std::isfinite(A3);
  const PetscReal q = d12 / d23;
  if (!(q > 1)) return false; // differences must shrink, with one sign
  *p  = std::log(q) / std::log(r);
  *A0 = A3 - d23 / (std::pow(r, *p) - 1);
  return true;
}

PetscReal ConvergenceRichardsonError(const std::vector<PetscReal> &A, PetscReal r, bool relative, PetscReal *p)
{
  const size_t n = A.size();
  *p             = NaN;
  if (n < 2) return NaN;
  const PetscReal scale = relative ? std::abs(A[n - 1]) : 1.0;
  if (n < 3) return std::abs(A[n - 1] - A[n - 2]) / scale;
  PetscReal A0;
  if (ConvergenceRichardson(A[n - 3], A[n - 2], A[n - 1], r, p, &A0)) return std::abs(A[n - 1] - A0) / scale;
  return std::abs(A[n - 1] - A[n - 2]) / scale; // not asymptotic: the last difference
}

void ConvergenceMeasureAgainst(const ConvergenceReference &ref, ConvergenceRun *run)
{
  const ImpactResult &r = run->result, &R = ref.result;
  if (run->failed) {
    run
      ->acor_error                                                                                                = run
                       ->contact_time_error                                                                       = run
                                                ->peak_force_error                                                = run
                                                                       ->max_compression_error                    = run
                                                                                                   ->energy_error = NaN;
    run->exit_speed_error = run->launch_angle_error = run->spin_error = NaN;
    return;
  }
  auto col                   = [](const char *name, const ImpactResult &x) { return ImpactResultColumn(name)->Get(x); };
  run->exit_speed_error      = std::abs(col("exit_speed", r) - col("exit_speed", R)) / std::abs(col("exit_speed", R));
  run->launch_angle_error    = std::abs(col("launch_angle", r) - col("launch_angle", R)); // NaN unless oblique
  run->spin_error            = std::abs(col("spin", r) - col("spin", R)) / std::abs(col("spin", R));
  run->acor_error            = std::abs(r.acor - R.acor);
  run->contact_time_error    = std::abs(r.contact_time - R.contact_time) / R.contact_time;
  run->peak_force_error      = std::abs(r.peak_force - R.peak_force) / R.peak_force;
  run->max_compression_error = std::abs(r.max_compression - R.max_compression) / R.max_compression;
  run->energy_error          = std::abs(r.energy_error);
}

void ConvergenceSpatialAnalyse(ConvergenceSpatial *sp)
{
  const size_t n = sp->nodes.size();
  auto triples = [&](const std::vector<PetscReal> &A, std::vector<PetscReal> *order, PetscReal *limit, PetscReal *lsq) {
    order->assign(n, NaN);
    *limit = n ? A[n - 1] : NaN;
    for (size_t k = 2; k < n; ++k) {
      const PetscReal r1 = sp->h[k - 2] / sp->h[k - 1], r2 = sp->h[k - 1] / sp->h[k];
      PetscReal       p, A0;
      if (std::abs(r1 - r2) > 1e-9 * r2) continue; // Richardson needs a constant ratio
      if (ConvergenceRichardson(A[k - 2], A[k - 1], A[k], r2, &p, &A0)) {
        (*order)[k] = p;
        if (k == n - 1) *limit = A0;
      }
    }
    std::vector<PetscReal> e(n);
    for (size_t k = 0; k < n; ++k) e[k] = std::abs(A[k] - *limit);
    std::vector<PetscReal> h = sp->h;
    if (n) h.pop_back(), e.pop_back(); // the last level defines the limit with the extrapolation
    *lsq = ConvergenceObservedOrder(h, e, 0).lsq;
  };
  triples(sp->acor, &sp->acor_order, &sp->acor_limit, &sp->acor_order_lsq);
  triples(sp->contact_time, &sp->contact_time_order, &sp->contact_time_limit, &sp->contact_time_order_lsq);
  triples(sp->peak_force, &sp->peak_force_order, &sp->peak_force_limit, &sp->peak_force_order_lsq);
}

PetscInt ConvergenceFastestAtTarget(const std::vector<ConvergenceRun> &runs, PetscReal target, PetscReal *t)
{
  PetscInt lv = -1;
  *t          = 0;
  for (auto &r : runs)
    if (!r.failed && r.acor_error <= target && (lv < 0 || r.result.wall_time < *t)) {
      lv = r.level;
      *t = r.result.wall_time;
    }
  return lv;
}

PetscReal ConvergenceSmallestError(const std::vector<ConvergenceRun> &runs)
{
  PetscReal m = NaN;
  for (auto &r : runs)
    if (!r.failed && !(r.acor_error >= m)) m = r.acor_error;
  return m;
}

} // namespace beamimpact

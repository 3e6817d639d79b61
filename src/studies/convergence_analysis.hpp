// -task convergence, the analysis: the errors of each run against the reference, observed
// orders, Richardson extrapolation (the run reference's own error, the spatial study's continuum
// limit), the error floor, and the cost of reaching a target error.
#pragma once

#include "studies/convergence_runs.hpp"

#include <vector>

namespace beamimpact {

// Observed order of e(h) ~ C h^p: pairwise between consecutive levels and a
// least-squares fit of log e against log h over the levels with e > floor.
// Levels at or below the floor (or not finite) give NaN pairwise orders; the
// fit is NaN with fewer than two usable levels.
struct ConvergenceOrder {
  std::vector<PetscReal> pairwise; // pairwise[k]: between levels k-1 and k (pairwise[0] = NaN)
  PetscReal              lsq  = 0;
  PetscInt               used = 0; // levels in the fit
};
ConvergenceOrder ConvergenceObservedOrder(const std::vector<PetscReal> &h, const std::vector<PetscReal> &e,
                                          PetscReal floor);

// Richardson extrapolation of A(h) = A0 + C h^p from three levels with a common
// ratio r = h1/h2 = h2/h3: p = log(|A1-A2| / |A2-A3|) / log r and A0 = A3 + (A3-A2)/(r^p - 1).
// Returns false when the differences do not decrease (no asymptotic behaviour).
bool ConvergenceRichardson(PetscReal A1, PetscReal A2, PetscReal A3, PetscReal r, PetscReal *p, PetscReal *A0);

// The error of the last of a sequence of values A at levels refined by the ratio r: |A_last -
// A0| from Richardson over the last three (relative: divided by |A_last|); the last difference
// where they are not asymptotic or only two exist; NaN for one. *p: the observed order (NaN
// when not extrapolated).
PetscReal ConvergenceRichardsonError(const std::vector<PetscReal> &A, PetscReal r, bool relative, PetscReal *p);

// The errors of a run against the reference: ACOR absolute; contact time, peak force and
// maximum compression relative; the energy balance its own |energy_error| (NaN for a failed run).
void ConvergenceMeasureAgainst(const ConvergenceReference &ref, ConvergenceRun *run);

// Observed order of one configuration's runs for one error (e.g. &ConvergenceRun::acor_error)
// against ConvergenceStepOf; failed runs are left out.
ConvergenceOrder ConvergenceOrderOf(const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs,
                                    PetscReal floor, PetscReal ConvergenceRun::*err);

// The step measure of a run for order fits: the fixed step, or the mean step of an adaptive run.
PetscReal ConvergenceStepOf(const ConvergenceConfig &cfg, const ConvergenceRun &run);

// The spatial study's analysis: Richardson orders of each triple of N (a constant ratio of h),
// the continuum limit from the last three, least-squares orders of |A(h) - limit|.
void ConvergenceSpatialAnalyse(ConvergenceSpatial *sp);

// The fastest level of one configuration that reaches the ACOR error target (-1: none; *t its
// wall time, s), and the smallest ACOR error of its runs (NaN when all failed).
PetscInt  ConvergenceFastestAtTarget(const std::vector<ConvergenceRun> &runs, PetscReal target, PetscReal *t);
PetscReal ConvergenceSmallestError(const std::vector<ConvergenceRun> &runs);

} // namespace beamimpact

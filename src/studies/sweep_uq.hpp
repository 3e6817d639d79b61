// The statistics of a sampled sweep (-sweep with a distribution, -sweep_samples): every results
// column's mean, standard deviation, standard error and quantiles with their bootstrap standard
// errors, the probabilities of exceedance asked (-sweep_exceedance, Wilson intervals), and with
// -sweep_sobol the first and total Sobol' indices (Saltelli 2010, Jansen) with bootstrap intervals.
// The estimators are plain functions of the values (tested alone: tests/test_uq.cpp); the sweep's
// part (SweepUqCompute) applies them to the rows of each point of the grid axes, and writes
// /statistics, /exceedance and /sobol (docs/uncertainty.md).
#pragma once

#include <petscsys.h>

#include <cstdint>
#include <string>
#include <vector>

namespace beamimpact {

struct SweepStore;

// What one sample of values says: its size, mean, standard deviation (n - 1), the mean's
// standard error s / sqrt(n), the 5, 50 and 95 % quantiles (linear between order statistics, as
// numpy's default) and their bootstrap standard errors.
struct UqDescription {
  double count = 0;                        // values used (finite)
  double mean = NAN, std = NAN, sem = NAN; // in the values' unit
  double q[3]    = {NAN, NAN, NAN};        // q05, q50, q95
  double q_se[3] = {NAN, NAN, NAN};        // their standard errors (bootstrap)
};
extern const double kUqQuantiles[3]; // 0.05, 0.5, 0.95
// y's description; the NaN values left out. bootstrap: resamples (with the counter of the seed).
UqDescription UqDescribe(const std::vector<double> &y, uint64_t seed, int bootstrap);
// The quantile q of sorted values (linear between order statistics).
double UqQuantileSorted(const std::vector<double> &sorted, double q);

// Wilson's score interval of a proportion k of n at the normal quantile z (1.96: 95 %).
void UqWilson(double k, double n, double z, double *lo, double *hi);

// First and total Sobol' indices of one output from Saltelli's design: fA[j], fB[j] and fAB[i][j]
// (A with input i from B), j < N. S_i = mean((fB - m) (fAB_i - fA)) / V (Saltelli 2010, f centred on
// the mean m of fA and fB as SALib does, so that the estimate's variance does not grow with m), S_Ti = mean((fA
// - fAB_i)^2) / (2 V) (Jansen), V the variance of fA and fB together. Groups j with a NaN are left
// out. Intervals: the 2.5 and 97.5 % percentiles of `bootstrap` resamples of the groups.
struct UqSobol {
  std::vector<double> first, total; // one per input (1)
  std::vector<double> first_lo, first_hi, total_lo, total_hi;
  double              groups   = 0;   // N used
  double              variance = NAN; // V (the unit squared)
};
UqSobol UqSobolIndices(const std::vector<double> &fA, const std::vector<double> &fB,
                       const std::vector<std::vector<double>> &fAB, uint64_t seed, int bootstrap);

// One condition of -sweep_exceedance: "COLUMN>VALUE" (or >=, <, <=).
struct UqCondition {
  std::string text, column, op; // as written, without spaces
  double      threshold = 0;    // in the column's unit
  bool        Holds(double y) const
  {
    return op == ">" ? y > threshold : op == ">=" ? y >= threshold : op == "<" ? y < threshold : y <= threshold;
  }
};
// Parses "COL>V[,COL<=V...]": each column must be one of `columns`. False with a reason.
bool UqConditionsParse(const std::string &text, const std::vector<std::string> &columns,
                       std::vector<UqCondition> *conds, std::string *why);

// The sweep's statistics, per point of the grid axes (g < G; G = 1 without grid axes).
struct SweepUqColumn {
  std::string                name, unit;
  std::vector<UqDescription> d;     // per grid point
  std::vector<UqSobol>       sobol; // per grid point (-sweep_sobol)
};
struct SweepUqExceedance {
  UqCondition         c;
  std::vector<double> count, n, p, lo,
    hi; // per grid point: values beyond, values (finite, of points that ran), k/n, Wilson 95 %
};
struct SweepUq {
  bool                       done = false;
  std::vector<std::string>   inputs;         // the sampled axes, in order
  std::vector<size_t>        grid_axes;      // the plan's grid axes (indices)
  std::vector<PetscInt>      grid_first;     // per grid point: its first case (its grid axes' values)
  std::vector<double>        points, failed; // per grid point: rows used (A and B with -sweep_sobol), failed among them
  std::vector<SweepUqColumn> columns;
  std::vector<SweepUqExceedance> exceedance;
};

// Rank 0, the sweep complete: the statistics of S's rows (nothing for a sweep without sampled axes).
PetscErrorCode SweepUqCompute(const SweepStore &S, SweepUq *uq);
// Writes /statistics, /exceedance and /sobol into the file (an HDF5 file id).
PetscErrorCode SweepUqWrite(const SweepStore &S, const SweepUq &uq, long long file);
// Rank 0: the summary's lines (mean +- sem, std, quantiles of every column that varies; the
// exceedance probabilities; the Sobol' indices).
PetscErrorCode SweepUqPrint(const SweepStore &S, const SweepUq &uq);

} // namespace beamimpact

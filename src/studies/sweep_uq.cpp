// The statistics and Sobol' indices of a sampled sweep. See sweep_uq.hpp.
#include "studies/sweep_uq.hpp"

#include "io/h5_dims.hpp"
#include "io/results_h5.hpp"
#include "io/text.hpp"
#include "studies/sweep_sampling.hpp"
#include "studies/sweep_store.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

namespace beamimpact {

const double kUqQuantiles[3] = {0.05, 0.5, 0.95};

// Streams of the bootstrap's counter (studies/sweep_sampling.hpp: SampleUniform).
static const uint64_t kStreamBootstrap = 3ULL << 32, kStreamSobolBootstrap = 4ULL << 32;

double UqQuantileSorted(const std::vector<double> &v, double q)
{
  if (v.empty()) return NAN;
  const double h  = q * (double)(v.size() - 1);
  const size_t lo = (size_t)std::floor(h), hi = std::min(v.size() - 1, lo + 1);
  return v[lo] + (h - (double)lo) * (v[hi] - v[lo]);
}

// The quantiles of a bootstrap resample of sorted values, from the counts of each value drawn
// (no sort: the resample's order statistics are read off the cumulative counts).
static void ResampleQuantiles(const std::vector<double> &sorted, uint64_t seed, uint64_t b,
                              std::vector<PetscInt> &counts, double q[3])
{
  const size_t n = sorted.size();
  std::fill(counts.begin(), counts.end(), 0);
  for (size_t i = 0; i < n; ++i) ++counts[SampleIndex(seed, kStreamBootstrap + b, i, n)];
  // Order statistic r (0-based) of the resample: the value whose cumulative count passes r.
  auto order = [&](size_t r, size_t *k, size_t *cum) {
    while (*cum + (size_t)counts[*k] <= r) *cum += (size_t)counts[(*k)++];
    return sorted[*k];
  };
  size_t k = 0, cum = 0;
  for (int m = 0; m < 3; ++m) {
    const double h  = kUqQuantiles[m] * (double)(n - 1);
    const size_t lo = (size_t)std::floor(h);
    const double a  = order(lo, &k, &cum);
    size_t       k2 = k, cum2 = cum;
    const double c = order(std::min(n - 1, lo + 1), &k2, &cum2);
    q[m]           = a + (h - (double)lo) * (c - a);
  }
}

static double StdOf(const std::vector<double> &v)
{
  if (v.size() < 2) return NAN;
  const double m = std::accumulate(v.begin(), v.end(), 0.0) / (double)v.size();
  double       s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / (double)(v.size() - 1));
}

UqDescription UqDescribe(const std::vector<double> &y, uint64_t seed, int bootstrap)
{
  UqDescription       d;
  std::vector<double> v;
  for (double x : y)
    if (std::isfinite(x)) v.push_back(x);
  d.count = (double)v.size();
  if (v.empty()) return d;
  std::sort(v.begin(), v.end());
  d.mean = std::accumulate(v.begin(), v.end(), 0.0) / (double)v.size();
  d.std  = StdOf(v);
  d.sem  = d.std / std::sqrt((double)v.size());
  for (int m = 0; m < 3; ++m) d.q[m] = UqQuantileSorted(v, kUqQuantiles[m]);
  if (v.size() < 2) return d;
  std::vector<PetscInt>            counts(v.size());
  std::vector<std::vector<double>> qb(3);
  for (int b = 0; b < bootstrap; ++b) {
    double q[3];
    ResampleQuantiles(v, seed, (uint64_t)b, counts, q);
    for (int m = 0; m < 3; ++m) qb[m].push_back(q[m]);
  }
  for (int m = 0; m < 3; ++m) d.q_se[m] = StdOf(qb[m]);
  return d;
}

void UqWilson(double k, double n, double z, double *lo, double *hi)
{
  if (!(n > 0)) {
    *lo = *hi = NAN;
    return;
  }
  const double p = k / n, z2 = z * z, den = 1 + z2 / n;
  const double centre = (p + z2 / (2 * n)) / den, half = z / den * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  *lo = std::max(0.0, centre - half);
  *hi = std::min(1.0, centre + half);
}

// The indices from the groups `use` (indices j, repeats allowed).
static void SobolOf(const std::vector<double> &fA, const std::vector<double> &fB,
                    const std::vector<std::vector<double>> &fAB, const std::vector<size_t> &use, double *V,
                    std::vector<double> *S, std::vector<double> *ST)
{
  const size_t d    = fAB.size();
  double       mean = 0, var = 0;
  for (size_t j : use) mean += fA[j] + fB[j];
  mean /= 2.0 * (double)use.size();
  for (size_t j : use) var += (fA[j] - mean) * (fA[j] - mean) + (fB[j] - mean) * (fB[j] - mean);
  *V = var / (2.0 * (double)use.size());
  S->assign(d, NAN);
  ST->assign(d, NAN);
  for (size_t i = 0; i < d; ++i) {
    double s = 0, t = 0;
    for (size_t j : use) {
      s += (fB[j] - mean) *
           (fAB[i][j] - fA[j]); // centred (as SALib does): the estimator's variance does not grow with the mean
      t += (fA[j] - fAB[i][j]) * (fA[j] - fAB[i][j]);
    }
    (*S)[i]  = *V > 0 ? s / (double)use.size() / *V : NAN;
    (*ST)[i] = *V > 0 ? t / (2.0 * (double)use.size()) / *V : NAN;
  }
}

UqSobol UqSobolIndices(const std::vector<double> &fA, const std::vector<double> &fB,
                       const std::vector<std::vector<double>> &fAB, uint64_t seed, int bootstrap)
{
  UqSobol             r;
  const size_t        d = fAB.size();
  std::vector<size_t> ok;
  for (size_t j = 0; j < fA.size(); ++j) {
    bool finite = std::isfinite(fA[j]) && std::isfinite(fB[j]);
    for (size_t i = 0; i < d; ++i) finite = finite && std::isfinite(fAB[i][j]);
    if (finite) ok.push_back(j);
  }
  r.groups = (double)ok.size();
  r.first_lo.assign(d, NAN), r.first_hi.assign(d, NAN), r.total_lo.assign(d, NAN), r.total_hi.assign(d, NAN);
  if (ok.size() < 2) {
    r.first.assign(d, NAN), r.total.assign(d, NAN);
    return r;
  }
  SobolOf(fA, fB, fAB, ok, &r.variance, &r.first, &r.total);
  std::vector<std::vector<double>> bs(d), bt(d);
  std::vector<size_t>              use(ok.size());
  for (int b = 0; b < bootstrap; ++b) {
    for (size_t k = 0; k < ok.size(); ++k)
      use[k] = ok[SampleIndex(seed, kStreamSobolBootstrap + (uint64_t)b, k, ok.size())];
    double              V;
    std::vector<double> S, ST;
    SobolOf(fA, fB, fAB, use, &V, &S, &ST);
    for (size_t i = 0; i < d; ++i) {
      if (std::isfinite(S[i])) bs[i].push_back(S[i]);
      if (std::isfinite(ST[i])) bt[i].push_back(ST[i]);
    }
  }
  for (size_t i = 0; i < d; ++i) {
    std::sort(bs[i].begin(), bs[i].end());
    std::sort(bt[i].begin(), bt[i].end());
    r.first_lo[i] = UqQuantileSorted(bs[i], 0.025), r.first_hi[i] = UqQuantileSorted(bs[i], 0.975);
    r.total_lo[i] = UqQuantileSorted(bt[i], 0.025), r.total_hi[i] = UqQuantileSorted(bt[i], 0.975);
  }
  return r;
}

bool UqConditionsParse(const std::string &text, const std::vector<std::string> &columns,
                       std::vector<UqCondition> *conds, std::string *why)
{
  std::string all;
  for (char c : text)
    if (!std::isspace((unsigned char)c)) all += c;
  size_t a = 0;
  while (a <= all.size()) {
    const size_t      b    = std::min(all.find(',', a), all.size());
    const std::string item = all.substr(a, b - a);
    const size_t      at   = item.find_first_of("<>");
    UqCondition       c;
    c.text = item;
    if (at != std::string::npos) {
      c.column = item.substr(0, at);
      c.op     = item.substr(at, item.size() > at + 1 && item[at + 1] == '=' ? 2 : 1);
    }
    const std::string value = at == std::string::npos ? "" : item.substr(at + c.op.size());
    char             *end   = nullptr;
    c.threshold             = std::strtod(value.c_str(), &end);
    if (at == std::string::npos || value.empty() || *end != '\0' || !std::isfinite(c.threshold) || c.column.empty()) {
      *why = "'" + item + "' is not COLUMN>VALUE (or >=, <, <=; conditions separated by ','), e.g. bbcor>0.5";
      return false;
    }
    if (std::find(columns.begin(), columns.end(), c.column) == columns.end()) {
      std::string list;
      for (const std::string &n : columns) list += (list.empty() ? "" : ", ") + n;
      *why = "'" + c.column + "' is not a numeric column of /results: use one of " + list;
      return false;
    }
    conds->push_back(c);
    a = b + 1;
  }
  return true;
}

// ---------------------------------------------------------------------------
// The sweep's part
// ---------------------------------------------------------------------------

namespace {

// Whether a column gets statistics: numbers that vary from run to run or are the sampled inputs,
// not the case's index, its status, a grid axis or a timing.
bool Described(const SweepStore &S, size_t c)
{
  const SweepColumn &col = S.columns[c];
  if (col.timing || !col.labels.empty() || col.name == "case_index" || col.name == "status") return false;
  for (const SweepAxis &a : S.plan.axes)
    if (a.name == col.name) return a.sampled;
  return true;
}

// The rows of grid point g: per row of the sample (s < rows), its row in the store (null if absent).
std::vector<const std::vector<double> *> GridRows(const SweepStore &S, PetscInt g)
{
  const PetscInt                           rows = S.plan.SampleRows();
  std::vector<const std::vector<double> *> out((size_t)rows, nullptr);
  for (PetscInt s = 0; s < rows; ++s) {
    const auto it = S.rows.find(g * rows + s);
    if (it != S.rows.end()) out[(size_t)s] = &it->second;
  }
  return out;
}

} // namespace

PetscErrorCode SweepUqCompute(const SweepStore &S, SweepUq *uq)
{
  const SweepPlan &P = S.plan;

  PetscFunctionBeginUser;
  *uq = SweepUq();
  if (P.sampled.empty()) PetscFunctionReturn(0);
  const size_t   d = P.sampled.size(), block = P.sobol ? d + 2 : 1;
  const PetscInt rows = P.SampleRows(), G = P.cases() / rows;
  for (size_t k : P.sampled) uq->inputs.push_back(P.axes[k].name);
  for (size_t k = 0; k < P.axes.size(); ++k)
    if (!P.axes[k].sampled) uq->grid_axes.push_back(k);
  std::vector<std::string> numeric;
  for (size_t c = 0; c < S.columns.size(); ++c)
    if (Described(S, c)) numeric.push_back(S.columns[c].name);
  std::vector<UqCondition> conds;
  std::string              why;
  PetscCheck(UqConditionsParse(P.exceedance, numeric, &conds, &why) || P.exceedance.empty(), PETSC_COMM_SELF,
             PETSC_ERR_ARG_WRONG, "-sweep_exceedance \"%s\" is not allowed: %s", P.exceedance.c_str(), why.c_str());
  for (const UqCondition &c : conds) uq->exceedance.push_back({c, {}, {}, {}, {}, {}});
  for (size_t c = 0; c < S.columns.size(); ++c)
    if (Described(S, c)) uq->columns.push_back({S.columns[c].name, S.columns[c].unit, {}, {}});
  for (PetscInt g = 0; g < G; ++g) {
    const auto R = GridRows(S, g);
    uq->grid_first.push_back(g * rows);
    double used = 0, failed = 0;
    for (PetscInt s = 0; s < rows; ++s)
      if ((size_t)s % block < 2 && R[(size_t)s]) {
        ++used;
        failed += SweepFailed((*R[(size_t)s])[(size_t)S.status_column]) ? 1 : 0;
      }
    uq->points.push_back(used);
    uq->failed.push_back(failed);
    for (SweepUqColumn &col : uq->columns) {
      const size_t c = (size_t)(std::find_if(S.columns.begin(), S.columns.end(),
                                             [&](const SweepColumn &x) { return x.name == col.name; }) -
                                S.columns.begin());
      // The design's independent points: every row, or A and B of Saltelli's blocks.
      std::vector<double>              y, fA, fB;
      std::vector<std::vector<double>> fAB(d);
      for (PetscInt s = 0; s < rows; ++s) {
        const double v = R[(size_t)s] ? (*R[(size_t)s])[c] : NAN;
        const size_t k = (size_t)s % block;
        if (k < 2) y.push_back(v);
        if (P.sobol) (k == 0 ? fA : k == 1 ? fB : fAB[k - 2]).push_back(v);
      }
      col.d.push_back(UqDescribe(y, (uint64_t)P.seed, (int)P.bootstrap));
      if (P.sobol) col.sobol.push_back(UqSobolIndices(fA, fB, fAB, (uint64_t)P.seed, (int)P.bootstrap));
      for (SweepUqExceedance &e : uq->exceedance) {
        if (e.c.column != col.name) continue;
        double k = 0, n = 0, lo, hi;
        for (double v : y)
          if (std::isfinite(v)) n += 1, k += e.c.Holds(v) ? 1 : 0;
        UqWilson(k, n, 1.959963984540054, &lo, &hi);
        e.count.push_back(k), e.n.push_back(n), e.p.push_back(n > 0 ? k / n : NAN), e.lo.push_back(lo),
          e.hi.push_back(hi);
      }
    }
  }
  // Columns without a finite value anywhere (those that do not apply to this scene) are left out.
  uq->columns.erase(std::remove_if(uq->columns.begin(), uq->columns.end(),
                                   [](const SweepUqColumn &c) {
                                     return std::all_of(c.d.begin(), c.d.end(),
                                                        [](const UqDescription &x) { return x.count == 0; });
                                   }),
                    uq->columns.end());
  uq->done = true;
  PetscFunctionReturn(0);
}

namespace {

PetscErrorCode WriteTextAttribute(hid_t obj, const char *name, const std::vector<std::string> &text)
{
  std::vector<const char *> p;
  for (auto &t : text) p.push_back(t.c_str());
  const hsize_t n = text.size();
  PetscFunctionBeginUser;
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  hid_t      sp = H5Screate_simple(1, &n, NULL);
  hid_t      a  = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = a >= 0 && H5Awrite(a, t, p.data()) >= 0;
  if (a >= 0) H5Aclose(a);
  H5Sclose(sp);
  H5Tclose(t);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write the attribute %s", name);
  PetscFunctionReturn(0);
}

template <class F>
std::vector<double> PerGrid(const std::vector<UqDescription> &d, F f)
{
  std::vector<double> v;
  for (const UqDescription &x : d) v.push_back(f(x));
  return v;
}

// /statistics/<column>/{count, mean, std, sem, q05, q50, q95, q05_se, q50_se, q95_se}, one value per grid point.
PetscErrorCode WriteStatistics(const SweepStore &S, const SweepUq &uq, hid_t file)
{
  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(file, "statistics", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /statistics");
  PetscCall(WriteTextAttribute(g, "inputs", uq.inputs));
  PetscCall(H5WriteCounts1D(g, "points", uq.points, "1"));
  PetscCall(H5WriteCounts1D(g, "failed", uq.failed, "1"));
  for (size_t k : uq.grid_axes) { // the grid point's values of the grid axes
    std::vector<double> v;
    for (PetscInt first : uq.grid_first) v.push_back(S.plan.CaseValues(first)[k]);
    const SweepAxis &a = S.plan.axes[k];
    if (a.Text()) {
      std::vector<std::string> t;
      for (double x : v) t.push_back(a.labels[(size_t)x]);
      PetscCall(H5WriteText1D(g, a.name.c_str(), t, "text"));
    } else PetscCall(H5WriteDataset1D(g, a.name.c_str(), v, a.unit.c_str()));
  }
  PetscCall(H5DimsTable(g, "grid_point"));
  for (const SweepUqColumn &c : uq.columns) {
    hid_t       cg = H5Gcreate2(g, c.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const char *u  = c.unit.c_str();
    PetscCall(H5WriteCounts1D(cg, "count", PerGrid(c.d, [](const UqDescription &x) { return x.count; }), "1"));
    PetscCall(H5WriteDataset1D(cg, "mean", PerGrid(c.d, [](const UqDescription &x) { return x.mean; }), u));
    PetscCall(H5WriteDataset1D(cg, "std", PerGrid(c.d, [](const UqDescription &x) { return x.std; }), u));
    PetscCall(H5WriteDataset1D(cg, "sem", PerGrid(c.d, [](const UqDescription &x) { return x.sem; }), u));
    const char *q[3] = {"q05", "q50", "q95"}, *qs[3] = {"q05_se", "q50_se", "q95_se"};
    for (int m = 0; m < 3; ++m) {
      PetscCall(H5WriteDataset1D(cg, q[m], PerGrid(c.d, [m](const UqDescription &x) { return x.q[m]; }), u));
      PetscCall(H5WriteDataset1D(cg, qs[m], PerGrid(c.d, [m](const UqDescription &x) { return x.q_se[m]; }), u));
    }
    PetscCall(H5DimsTable(cg, "grid_point"));
    H5Gclose(cg);
  }
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// /exceedance/<condition>/{probability, ci_low, ci_high, count, n}.
PetscErrorCode WriteExceedance(const SweepUq &uq, hid_t file)
{
  PetscFunctionBeginUser;
  if (uq.exceedance.empty()) PetscFunctionReturn(0);
  hid_t g = H5Gcreate2(file, "exceedance", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  for (const SweepUqExceedance &e : uq.exceedance) {
    hid_t eg = H5Gcreate2(g, e.c.text.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    PetscCheck(eg >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /exceedance/%s", e.c.text.c_str());
    PetscCall(H5WriteDataset1D(eg, "probability", e.p, "1"));
    PetscCall(H5WriteDataset1D(eg, "ci_low", e.lo, "1 (Wilson's 95% interval)"));
    PetscCall(H5WriteDataset1D(eg, "ci_high", e.hi, "1 (Wilson's 95% interval)"));
    PetscCall(H5WriteCounts1D(eg, "count", e.count, "1"));
    PetscCall(H5WriteCounts1D(eg, "n", e.n, "1"));
    PetscCall(H5DimsTable(eg, "grid_point"));
    H5Gclose(eg);
  }
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// /sobol/<column>/{first, total} [grid point][input] and {first_ci, total_ci} [grid point][input][2].
PetscErrorCode WriteSobol(const SweepUq &uq, hid_t file)
{
  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(file, "sobol", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCall(WriteTextAttribute(g, "inputs", uq.inputs));
  for (const SweepUqColumn &c : uq.columns) {
    hid_t                            cg = H5Gcreate2(g, c.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<std::vector<double>> first, total, first_ci, total_ci;
    std::vector<double>              groups, variance;
    for (const UqSobol &s : c.sobol) {
      first.push_back(s.first);
      total.push_back(s.total);
      first_ci.emplace_back();
      total_ci.emplace_back();
      for (size_t i = 0; i < s.first.size(); ++i) {
        first_ci.back().insert(first_ci.back().end(), {s.first_lo[i], s.first_hi[i]});
        total_ci.back().insert(total_ci.back().end(), {s.total_lo[i], s.total_hi[i]});
      }
      groups.push_back(s.groups);
      variance.push_back(s.variance);
    }
    PetscCall(WriteTextAttribute(cg, "inputs", uq.inputs));
    PetscCall(H5WriteDataset2D(cg, "first", first, "1"));
    PetscCall(H5WriteDataset2D(cg, "total", total, "1"));
    PetscCall(H5WriteDataset3D(cg, "first_ci", first_ci, uq.inputs.size(), 2, "1 (bootstrap 95% interval: low, high)"));
    PetscCall(H5WriteDataset3D(cg, "total_ci", total_ci, uq.inputs.size(), 2, "1 (bootstrap 95% interval: low, high)"));
    PetscCall(H5WriteCounts1D(cg, "groups", groups, "1"));
    const std::string vu = c.unit.empty() || c.unit == "1" ? "1" : "(" + c.unit + ")^2";
    PetscCall(H5WriteDataset1D(cg, "variance", variance, vu.c_str()));
    for (const char *n : {"first", "total"}) PetscCall(H5DimsAttach(cg, n, {"grid_point", "sobol_input"}));
    for (const char *n : {"first_ci", "total_ci"})
      PetscCall(H5DimsAttach(cg, n, {"grid_point", "sobol_input", "interval_end"}));
    PetscCall(H5DimsTable(cg, "grid_point"));
    H5Gclose(cg);
  }
  H5Gclose(g);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode SweepUqWrite(const SweepStore &S, const SweepUq &uq, long long file)
{
  PetscFunctionBeginUser;
  if (!uq.done) PetscFunctionReturn(0);
  PetscCall(WriteStatistics(S, uq, (hid_t)file));
  PetscCall(WriteExceedance(uq, (hid_t)file));
  if (S.plan.sobol) PetscCall(WriteSobol(uq, (hid_t)file));
  PetscFunctionReturn(0);
}

PetscErrorCode SweepUqPrint(const SweepStore &S, const SweepUq &uq)
{
  PetscFunctionBeginUser;
  if (!uq.done) PetscFunctionReturn(0);
  for (size_t g = 0; g < uq.points.size(); ++g) {
    std::string at;
    for (size_t k : uq.grid_axes) {
      const SweepAxis &a = S.plan.axes[k];
      at += (at.empty() ? " at " : ", ") + a.name + " = " + a.Display(S.plan.CaseValues(uq.grid_first[g])[k]);
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "statistics%s: %.0f points%s, %.0f failed (left out); mean +- its standard error, std, "
                          "5/50/95%% quantiles:\n",
                          at.c_str(), uq.points[g], S.plan.sobol ? " (A and B of Saltelli's design)" : "",
                          uq.failed[g]));
    for (const SweepUqColumn &c : uq.columns) {
      const UqDescription &x = c.d[g];
      if (!(x.std > 1e-12 * std::fabs(x.mean))) continue; // the columns that vary (beyond rounding)
      const std::string u = c.unit.empty() || c.unit == "1" ? "" : " " + c.unit;
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-28s %.6g +- %.2g, std %.4g, %.5g / %.5g / %.5g%s\n", c.name.c_str(),
                            x.mean, x.sem, x.std, x.q[0], x.q[1], x.q[2], u.c_str()));
    }
    for (const SweepUqExceedance &e : uq.exceedance)
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "  P(%s) = %.4g (%.0f of %.0f), 95%% interval [%.4g, %.4g] (Wilson)\n",
                            e.c.text.c_str(), e.p[g], e.count[g], e.n[g], e.lo[g], e.hi[g]));
    if (!S.plan.sobol) continue;
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "sobol indices%s, first [95%% interval] / total [95%% interval], per input:\n", at.c_str()));
    for (const SweepUqColumn &c : uq.columns) {
      const UqSobol &s = c.sobol[g];
      if (c.d[g].std > 1e-12 * std::fabs(c.d[g].mean) &&
          std::find(uq.inputs.begin(), uq.inputs.end(), c.name) == uq.inputs.end()) {
        std::string line;
        for (size_t i = 0; i < uq.inputs.size(); ++i) {
          char buf[256];
          std::snprintf(buf, sizeof buf, "%s%s %.3f [%.3f, %.3f] / %.3f [%.3f, %.3f]", i ? "; " : "",
                        uq.inputs[i].c_str(), s.first[i], s.first_lo[i], s.first_hi[i], s.total[i], s.total_lo[i],
                        s.total_hi[i]);
          line += buf;
        }
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-28s %s\n", c.name.c_str(), line.c_str()));
      }
    }
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

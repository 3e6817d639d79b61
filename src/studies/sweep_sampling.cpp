// Sampled axes: distributions, their inverse CDFs and the unit-cube designs. See sweep_sampling.hpp.
#include "studies/sweep_sampling.hpp"

#include "io/text.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_qrng.h>
#include <gsl/gsl_randist.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace beamimpact {

namespace {

uint64_t Mix(uint64_t z) // SplitMix64's finaliser (Steele, Lea & Flood 2014)
{
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Streams of the counter: one per use, so that no two uses share a number.
const uint64_t kStreamLhsPermutation = 1ULL << 32, kStreamShift = 2ULL << 32;

bool Number(const std::string &text, double *v) { return TextFiniteNumber(text, v); }

std::vector<std::string> Split(const std::string &text, char sep)
{
  std::vector<std::string> parts;
  std::stringstream        ss(text);
  std::string              p;
  while (std::getline(ss, p, sep)) parts.push_back(Trim(p));
  if (!text.empty() && text.back() == sep) parts.push_back("");
  return parts;
}

struct LawForm {
  const char *name;
  SampleLaw   law;
  size_t      count;
  const char *form;
};
const LawForm kLaws[] = {
  {"normal", SampleLaw::Normal, 2, "normal:MEAN:STD"},
  {"truncnormal", SampleLaw::TruncNormal, 4, "truncnormal:MEAN:STD:LO:HI"},
  {"uniform", SampleLaw::Uniform, 2, "uniform:LO:HI"},
  {"lognormal", SampleLaw::LogNormal, 2, "lognormal:MEAN:STD"},
  {"triangular", SampleLaw::Triangular, 3, "triangular:LO:MODE:HI"},
};
const char *kAllowed = "normal:MEAN:STD, truncnormal:MEAN:STD:LO:HI, uniform:LO:HI, lognormal:MEAN:STD, "
                       "triangular:LO:MODE:HI, a table V1@W1;V2@W2;... or csv:FILE[:COLUMN]";

// The parameters' own conditions.
bool CheckParameters(const LawForm &f, const std::vector<double> &p, std::string *why)
{
  const char *bad = nullptr;
  switch (f.law) {
  case SampleLaw::Normal:
  case SampleLaw::LogNormal:
    if (!(p[1] > 0)) bad = "STD must be > 0";
    else if (f.law == SampleLaw::LogNormal && !(p[0] > 0)) bad = "MEAN must be > 0 (a lognormal value is positive)";
    break;
  case SampleLaw::TruncNormal:
    if (!(p[1] > 0)) bad = "STD must be > 0";
    else if (!(p[2] < p[3])) bad = "LO must be below HI";
    else if (gsl_cdf_ugaussian_P((p[3] - p[0]) / p[1]) - gsl_cdf_ugaussian_P((p[2] - p[0]) / p[1]) < 1e-12 &&
             gsl_cdf_ugaussian_Q((p[2] - p[0]) / p[1]) - gsl_cdf_ugaussian_Q((p[3] - p[0]) / p[1]) < 1e-12)
      bad = "[LO, HI] holds less than 1e-12 of the normal's probability";
    break;
  case SampleLaw::Uniform:
    if (!(p[0] < p[1])) bad = "LO must be below HI";
    break;
  case SampleLaw::Triangular:
    if (!(p[0] < p[2] && p[0] <= p[1] && p[1] <= p[2])) bad = "LO <= MODE <= HI with LO < HI";
    break;
  default:
    break;
  }
  if (bad) *why = std::string(f.form) + ": " + bad;
  return !bad;
}

bool ParseTable(const std::string &spec, bool whole, SampleDistribution *d, std::string *why)
{
  double total = 0;
  for (const std::string &item : Split(spec, ';')) {
    const size_t at = item.find('@');
    double       v, w;
    if (at == std::string::npos || !Number(item.substr(0, at), &v) || !Number(item.substr(at + 1), &w) || !(w > 0)) {
      *why = "'" + item + "' is not V@W (a number and its weight > 0); a table is V1@W1;V2@W2;...";
      return false;
    }
    if (whole && v != std::floor(v)) {
      *why = "'" + item + "': the option takes whole numbers";
      return false;
    }
    d->values.push_back(v);
    total += w;
    d->cumulative.push_back(total);
  }
  for (double &c : d->cumulative) c /= total;
  d->cumulative.back() = 1;
  d->law               = SampleLaw::Discrete;
  return true;
}

// csv:FILE[:COLUMN]: the numbers of one column ('#' lines skipped, a first line of names allowed).
bool ParseCsv(const std::string &rest, bool whole, SampleDistribution *d, std::string *why)
{
  const size_t colon  = rest.rfind(':');
  const bool   picked = colon != std::string::npos && rest.find('.', colon) == std::string::npos &&
                      rest.find('/', colon) == std::string::npos;
  const std::string file = picked ? rest.substr(0, colon) : rest, column = picked ? Trim(rest.substr(colon + 1)) : "";
  std::ifstream     in(file);
  if (!in) {
    *why = "csv:" + rest + ": cannot open " + file + " (" + std::strerror(errno) +
           "; a path in an options file is relative to that file's directory)";
    return false;
  }
  std::string line;
  long        col = -1;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    if (Trim(line).empty() || Trim(line)[0] == '#') continue;
    const std::vector<std::string> cells = Split(line, ',');
    double                         v;
    if (col < 0) { // the column: by name on a first line of names, by number, or the first
      col              = 0;
      const auto named = std::find(cells.begin(), cells.end(), column);
      if (!column.empty() && named != cells.end()) col = named - cells.begin();
      else if (!column.empty() && (!Number(column, &v) || v < 1 || v != std::floor(v) || v > (double)cells.size())) {
        *why = "csv:" + rest + ": column '" + column + "' is neither a name on the first line of " + file +
               " nor a number from 1 to " + std::to_string(cells.size());
        return false;
      } else if (!column.empty() && named == cells.end()) col = (long)v - 1;
      if (!Number(cells[col], &v)) continue; // the line of names
    }
    if ((size_t)col >= cells.size() || !Number(cells[col], &v) || (whole && v != std::floor(v))) {
      *why = file + ":" + std::to_string(lineno) + ": '" + ((size_t)col < cells.size() ? cells[col] : "") +
             "' is not " + (whole ? "a whole number" : "a number") + " (column " + std::to_string(col + 1) + ")";
      return false;
    }
    d->values.push_back(v);
  }
  if (d->values.size() < 2) {
    *why = "csv:" + rest + ": " + file + " holds " + std::to_string(d->values.size()) +
           " value(s): an empirical distribution needs at least 2";
    return false;
  }
  std::sort(d->values.begin(), d->values.end());
  d->law  = SampleLaw::Empirical;
  d->file = file;
  return true;
}

} // namespace

bool SampleSpecIsDistribution(const std::string &spec_in)
{
  const std::string spec = Trim(spec_in);
  if (spec.find('@') != std::string::npos || spec.compare(0, 4, "csv:") == 0) return true;
  // NAME:...: a law's name (a known one, or a word that is none: refused naming the laws); a
  // range start:stop:count starts with a number, a text list has no ':' outside quotes.
  const size_t colon = spec.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha((unsigned char)spec[0]) ||
      spec.find_first_of("'\";") != std::string::npos)
    return false;
  for (size_t k = 0; k < colon; ++k)
    if (!(std::isalnum((unsigned char)spec[k]) || spec[k] == '_')) return false;
  return true;
}

bool SampleDistributionParse(const std::string &spec_in, const std::string &unit, bool whole, SampleDistribution *d,
                             std::string *why)
{
  const std::string spec = Trim(spec_in);
  *d                     = SampleDistribution();
  if (spec.compare(0, 4, "csv:") == 0) return ParseCsv(spec.substr(4), whole, d, why);
  if (spec.find('@') != std::string::npos) return ParseTable(spec, whole, d, why);
  const std::vector<std::string> parts = Split(spec, ':');
  for (const LawForm &f : kLaws) {
    if (parts[0] != f.name) continue;
    if (whole) {
      *why = std::string(f.name) +
             " is a continuous law and the option takes whole numbers: use a table V1@W1;V2@W2;... or csv:FILE";
      return false;
    }
    if (parts.size() != f.count + 1) {
      *why = std::string(f.name) + " takes " + std::to_string(f.count) + " numbers: " + f.form +
             (unit.empty() ? "" : " (" + unit + ")");
      return false;
    }
    d->law = f.law;
    for (size_t k = 1; k < parts.size(); ++k) {
      double v;
      if (!Number(parts[k], &v)) {
        *why = std::string(f.form) + ": '" + parts[k] + "' is not a number" + (unit.empty() ? "" : " (" + unit + ")");
        return false;
      }
      d->p.push_back(v);
    }
    return CheckParameters(f, d->p, why);
  }
  *why = "'" + parts[0] + "' is not a distribution: use " + kAllowed;
  return false;
}

double SampleDistribution::Quantile(double u) const
{
  switch (law) {
  case SampleLaw::Normal:
    return p[0] + p[1] * gsl_cdf_ugaussian_Pinv(u);
  case SampleLaw::TruncNormal: {
    const double a = (p[2] - p[0]) / p[1], b = (p[3] - p[0]) / p[1];
    double       z;
    if (a > 0)
      z = gsl_cdf_ugaussian_Qinv(
        gsl_cdf_ugaussian_Q(a) -
        u * (gsl_cdf_ugaussian_Q(a) - gsl_cdf_ugaussian_Q(b))); // the upper tail: Q keeps its digits
    else z = gsl_cdf_ugaussian_Pinv(gsl_cdf_ugaussian_P(a) + u * (gsl_cdf_ugaussian_P(b) - gsl_cdf_ugaussian_P(a)));
    return std::min(p[3], std::max(p[2], p[0] + p[1] * z));
  }
  case SampleLaw::Uniform:
    return p[0] + u * (p[1] - p[0]);
  case SampleLaw::LogNormal: {
    const double s2 = std::log1p((p[1] / p[0]) * (p[1] / p[0]));
    return std::exp(std::log(p[0]) - 0.5 * s2 + std::sqrt(s2) * gsl_cdf_ugaussian_Pinv(u));
  }
  case SampleLaw::Triangular: {
    const double lo = p[0], c = p[1], hi = p[2], fc = (c - lo) / (hi - lo);
    return u < fc ? lo + std::sqrt(u * (hi - lo) * (c - lo)) : hi - std::sqrt((1 - u) * (hi - lo) * (hi - c));
  }
  case SampleLaw::Discrete:
    return values[std::lower_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin()];
  case SampleLaw::Empirical:
    return values[std::min(values.size() - 1, (size_t)(u * (double)values.size()))];
  }
  return NAN;
}

double SampleDistribution::Mean() const
{
  switch (law) {
  case SampleLaw::Normal:
  case SampleLaw::LogNormal:
    return p[0];
  case SampleLaw::TruncNormal: {
    const double a = (p[2] - p[0]) / p[1], b = (p[3] - p[0]) / p[1];
    return p[0] + p[1] * (gsl_ran_ugaussian_pdf(a) - gsl_ran_ugaussian_pdf(b)) /
                    (gsl_cdf_ugaussian_P(b) - gsl_cdf_ugaussian_P(a));
  }
  case SampleLaw::Uniform:
    return 0.5 * (p[0] + p[1]);
  case SampleLaw::Triangular:
    return (p[0] + p[1] + p[2]) / 3;
  default: {
    double m = 0;
    for (size_t k = 0; k < values.size(); ++k)
      m += values[k] *
           (law == SampleLaw::Discrete ? cumulative[k] - (k ? cumulative[k - 1] : 0) : 1.0 / (double)values.size());
    return m;
  }
  }
}

double SampleDistribution::Std() const
{
  switch (law) {
  case SampleLaw::Normal:
  case SampleLaw::LogNormal:
    return p[1];
  case SampleLaw::TruncNormal: {
    const double a = (p[2] - p[0]) / p[1], b = (p[3] - p[0]) / p[1],
                 Z  = gsl_cdf_ugaussian_P(b) - gsl_cdf_ugaussian_P(a);
    const double pa = gsl_ran_ugaussian_pdf(a), pb = gsl_ran_ugaussian_pdf(b);
    const double r = (pa - pb) / Z;
    return p[1] * std::sqrt(1 + (a * pa - b * pb) / Z - r * r);
  }
  case SampleLaw::Uniform:
    return (p[1] - p[0]) / std::sqrt(12.0);
  case SampleLaw::Triangular:
    return std::sqrt((p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - p[0] * p[1] - p[0] * p[2] - p[1] * p[2]) / 18);
  default: {
    const double m = Mean();
    double       v = 0;
    for (size_t k = 0; k < values.size(); ++k)
      v += (values[k] - m) * (values[k] - m) *
           (law == SampleLaw::Discrete ? cumulative[k] - (k ? cumulative[k - 1] : 0) : 1.0 / (double)values.size());
    return std::sqrt(v);
  }
  }
}

const char *SampleDesignName(SampleDesign d)
{
  switch (d) {
  case SampleDesign::Random:
    return "random";
  case SampleDesign::LHS:
    return "lhs";
  case SampleDesign::Sobol:
    return "sobol";
  case SampleDesign::Halton:
    return "halton";
  }
  return "?";
}

bool SampleDesignParse(const std::string &name, SampleDesign *d)
{
  for (SampleDesign c : {SampleDesign::Random, SampleDesign::LHS, SampleDesign::Sobol, SampleDesign::Halton})
    if (name == SampleDesignName(c)) {
      *d = c;
      return true;
    }
  return false;
}

double SampleUniform(uint64_t seed, uint64_t stream, uint64_t index)
{
  const uint64_t h = Mix(Mix(Mix(seed) ^ stream) ^ index);
  return ((double)(h >> 11) + 0.5) * 0x1p-53;
}

uint64_t SampleIndex(uint64_t seed, uint64_t stream, uint64_t index, uint64_t n)
{
  return std::min(n - 1, (uint64_t)(SampleUniform(seed, stream, index) * (double)n));
}

namespace {

void DesignLhs(uint64_t seed, PetscInt n, int dim, std::vector<double> *u)
{
  std::vector<PetscInt> perm((size_t)n);
  for (int j = 0; j < dim; ++j) {
    for (PetscInt i = 0; i < n; ++i) perm[i] = i;
    for (PetscInt k = n - 1; k > 0; --k)
      std::swap(perm[k], perm[SampleIndex(seed, kStreamLhsPermutation + (uint64_t)j, (uint64_t)k,
                                          (uint64_t)k + 1)]); // Fisher-Yates
    for (PetscInt i = 0; i < n; ++i)
      (*u)[(size_t)i * dim + j] = ((double)perm[i] + SampleUniform(seed, (uint64_t)j, (uint64_t)i)) / (double)n;
  }
}

// GSL's sequence, point 0 first (GSL's Sobol' starts at its point 1: with point 0 the first 2^m
// points are a (t, m, s)-net), each dimension scrambled from the seed.
void DesignSequence(bool sobol, uint64_t seed, PetscInt n, int dim, std::vector<double> *u)
{
  gsl_qrng             *q = gsl_qrng_alloc(sobol ? gsl_qrng_sobol : gsl_qrng_halton, (unsigned)dim);
  std::vector<double>   x((size_t)dim, 0.0);
  std::vector<uint32_t> shift((size_t)dim);
  std::vector<double>   offset((size_t)dim);
  for (int j = 0; j < dim; ++j) {
    shift[j]  = (uint32_t)SampleIndex(seed, kStreamShift + (uint64_t)j, 0, 1ULL << 30);
    offset[j] = SampleUniform(seed, kStreamShift + (uint64_t)j, 1);
  }
  for (PetscInt i = 0; i < n; ++i) {
    if (i > 0 || !sobol) gsl_qrng_get(q, x.data());
    for (int j = 0; j < dim; ++j) {
      double v;
      if (sobol) { // GSL's Sobol' points are multiples of 2^-30: a digital shift, the cell's centre
        const uint32_t k = (uint32_t)std::ldexp(x[j], 30);
        v                = std::ldexp((double)(k ^ shift[j]) + 0.5, -30);
      } else {
        v = x[j] + offset[j];
        v -= std::floor(v);
        if (v <= 0) v = 0x1p-53;
      }
      (*u)[(size_t)i * dim + j] = v;
    }
  }
  gsl_qrng_free(q);
}

} // namespace

bool SampleUnitDesign(SampleDesign design, uint64_t seed, PetscInt n, int dim, std::vector<double> *u, std::string *why)
{
  const int max = design == SampleDesign::Sobol ? 40 : design == SampleDesign::Halton ? 1229 : 1 << 20;
  if (dim > max) {
    *why = std::string(SampleDesignName(design)) + " points have at most " + std::to_string(max) +
           " dimensions (GSL's), " + std::to_string(dim) + " asked" +
           " (Saltelli's design for -sweep_sobol takes two per sampled axis): use -sweep_sampling random or lhs";
    return false;
  }
  u->assign((size_t)n * (size_t)dim, 0.0);
  switch (design) {
  case SampleDesign::Random:
    for (PetscInt i = 0; i < n; ++i)
      for (int j = 0; j < dim; ++j) (*u)[(size_t)i * dim + j] = SampleUniform(seed, (uint64_t)j, (uint64_t)i);
    break;
  case SampleDesign::LHS:
    DesignLhs(seed, n, dim, u);
    break;
  case SampleDesign::Sobol:
  case SampleDesign::Halton:
    DesignSequence(design == SampleDesign::Sobol, seed, n, dim, u);
    break;
  }
  return true;
}

std::vector<double> SampleSaltelliRows(const std::vector<double> &u, PetscInt n, int d)
{
  std::vector<double> rows;
  rows.reserve((size_t)n * (size_t)(d + 2) * (size_t)d);
  for (PetscInt j = 0; j < n; ++j) {
    const double *a = &u[(size_t)j * 2 * d], *b = a + d;
    rows.insert(rows.end(), a, a + d);
    rows.insert(rows.end(), b, b + d);
    for (int i = 0; i < d; ++i) {
      rows.insert(rows.end(), a, a + d);
      rows[rows.size() - (size_t)d + (size_t)i] = b[i];
    }
  }
  return rows;
}

} // namespace beamimpact

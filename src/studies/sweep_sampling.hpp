// Sampled axes of a sweep (-sweep "impact_x=normal:0.70:0.02,ball_speed=uniform:58:62"): the
// distribution of an option's value, and the designs on the unit cube (pseudo-random, Latin
// hypercube, scrambled Sobol' or Halton points) that its inverse CDF maps onto the option's values.
// Every point is a pure function of the seed, the design and its index (and of the number of
// points for the Latin hypercube and the sequences, which are computed whole), so that any rank,
// and a resumed run, computes the same values bit for bit. Saltelli's design for the Sobol'
// indices (the matrices A, B and A_B^(i)) is built from a design of twice the dimension.
#pragma once

#include <petscsys.h>

#include <cstdint>
#include <string>
#include <vector>

namespace beamimpact {

// The laws a sampled axis may follow.
enum class SampleLaw {
  Normal,
  TruncNormal,
  Uniform,
  LogNormal,
  Triangular,
  Discrete,
  Empirical
};

// One sampled axis's distribution; parameters in the unit of the axis's option.
struct SampleDistribution {
  SampleLaw           law = SampleLaw::Uniform;
  std::vector<double> p;          // normal: mean, std; truncnormal: mean, std, lo, hi; uniform: lo, hi;
                                  // lognormal: mean, std (of the value itself); triangular: lo, mode, hi
  std::vector<double> values;     // discrete: the values as written; empirical: the measured values, sorted
  std::vector<double> cumulative; // discrete: the cumulative probabilities (the last exactly 1)
  std::string         file;       // empirical: the CSV file read

  // The inverse CDF at u in (0, 1): the value of probability u below it.
  double Quantile(double u) const;
  // The distribution's mean and standard deviation (the truncated normal's and the empirical's exact).
  double Mean() const;
  double Std() const;
};

// Whether an axis's SPEC is a distribution (starts with a law's name and ':' or is a table v@p;...)
// rather than a grid (start:stop:count or a list).
bool SampleSpecIsDistribution(const std::string &spec);
// Parses a distribution SPEC: normal:MEAN:STD, truncnormal:MEAN:STD:LO:HI, uniform:LO:HI,
// lognormal:MEAN:STD, triangular:LO:MODE:HI, a table V1@W1;V2@W2;... (weights relative, > 0), or
// csv:FILE[:COLUMN] (the measured values of a CSV file's column, by name or number from 1, else the
// first; '#' comments; drawn with equal probability). whole: the option takes whole numbers (only a
// table or a CSV of whole numbers then). False with a reason in *why naming what is allowed.
bool SampleDistributionParse(const std::string &spec, const std::string &unit, bool whole, SampleDistribution *d,
                             std::string *why);

// How the unit-cube points are placed (-sweep_sampling).
enum class SampleDesign {
  Random,
  LHS,
  Sobol,
  Halton
};
const char *SampleDesignName(SampleDesign d);
bool        SampleDesignParse(const std::string &name, SampleDesign *d);

// A uniform number in (0, 1) that is a pure function of (seed, stream, index): SplitMix64's
// finaliser applied to the three in turn, its 53 high bits, centred ((k + 1/2) 2^-53).
double SampleUniform(uint64_t seed, uint64_t stream, uint64_t index);
// A whole number in [0, n) from the same counter (n > 0).
uint64_t SampleIndex(uint64_t seed, uint64_t stream, uint64_t index, uint64_t n);

// n points of dimension dim in (0, 1)^dim, row after row (u[i * dim + j]): random (SampleUniform of
// the seed, dimension j and index i), Latin hypercube (one point in each of n equal slices of every
// dimension: permutations and jitter from the seed), Sobol' (GSL's gsl_qrng_sobol, at most 40
// dimensions, each digitally shifted by a random 30-bit XOR from the seed, centred in its cell) or
// Halton (GSL's gsl_qrng_halton, at most 1229 dimensions, each shifted by a random amount modulo 1).
// False with a reason in *why.
bool SampleUnitDesign(SampleDesign design, uint64_t seed, PetscInt n, int dim, std::vector<double> *u,
                      std::string *why);

// Saltelli's design from a design u of n points of dimension 2d: point j gives the block of d + 2
// rows A_j (u's first d coordinates), B_j (its last d), then A_B^(i)_j for i = 0..d-1 (A_j with
// coordinate i taken from B_j); rows of d values, block after block (n (d + 2) rows).
std::vector<double> SampleSaltelliRows(const std::vector<double> &u, PetscInt n, int d);

} // namespace beamimpact

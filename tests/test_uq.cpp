// The sampled sweeps' pieces alone (studies/sweep_sampling.hpp, studies/sweep_uq.hpp): the
// designs (pure functions of seed and index, Latin hypercube strata, Sobol' balance), the inverse
// CDFs against their closed forms, the statistics against formulas, Wilson's interval, and the
// Sobol' estimators on the Ishigami function and a linear model, whose indices are known.
#include "studies/sweep_sampling.hpp"
#include "studies/sweep_uq.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <functional>
#include <numeric>

using namespace beamimpact;

TEST(Sampling, PureFunctionOfSeedAndIndex)
{
  std::vector<double> a, b, c;
  std::string         why;
  for (SampleDesign d : {SampleDesign::Random, SampleDesign::LHS, SampleDesign::Sobol, SampleDesign::Halton}) {
    ASSERT_TRUE(SampleUnitDesign(d, 7, 64, 3, &a, &why)) << why;
    ASSERT_TRUE(SampleUnitDesign(d, 7, 64, 3, &b, &why));
    ASSERT_TRUE(SampleUnitDesign(d, 8, 64, 3, &c, &why));
    EXPECT_EQ(a, b) << SampleDesignName(d);
    EXPECT_NE(a, c) << SampleDesignName(d) << ": the seed changes the points";
    for (double u : a) EXPECT_TRUE(u > 0 && u < 1) << SampleDesignName(d);
  }
  // Random: a prefix is the same points (point i does not depend on N).
  ASSERT_TRUE(SampleUnitDesign(SampleDesign::Random, 7, 16, 3, &b, &why));
  ASSERT_TRUE(SampleUnitDesign(SampleDesign::Random, 7, 64, 3, &a, &why));
  EXPECT_TRUE(std::equal(b.begin(), b.end(), a.begin()));
  ASSERT_TRUE(SampleUnitDesign(SampleDesign::Sobol, 7, 16, 3, &b, &why));
  ASSERT_TRUE(SampleUnitDesign(SampleDesign::Sobol, 7, 64, 3, &a, &why));
  EXPECT_TRUE(std::equal(b.begin(), b.end(), a.begin()));
}

TEST(Sampling, LatinHypercubeAndSobolStrata)
{
  std::vector<double> u;
  std::string         why;
  const int           n = 64, d = 4;
  ASSERT_TRUE(SampleUnitDesign(SampleDesign::LHS, 3, n, d, &u, &why));
  for (int j = 0; j < d; ++j) { // one point in each of the n slices of every dimension
    std::vector<int> hit(n, 0);
    for (int i = 0; i < n; ++i) ++hit[(int)(u[i * d + j] * n)];
    EXPECT_EQ(std::count(hit.begin(), hit.end(), 1), n) << "dimension " << j;
  }
  // Sobol' with point 0 and a digital shift: the first 2^m points put one in each of 2^m slices
  // of every dimension (a (0, m, 1)-net in each coordinate).
  ASSERT_TRUE(SampleUnitDesign(SampleDesign::Sobol, 3, n, d, &u, &why));
  for (int j = 0; j < d; ++j) {
    std::vector<int> hit(n, 0);
    for (int i = 0; i < n; ++i) ++hit[(int)(u[i * d + j] * n)];
    EXPECT_EQ(std::count(hit.begin(), hit.end(), 1), n) << "dimension " << j;
  }
  EXPECT_FALSE(SampleUnitDesign(SampleDesign::Sobol, 3, n, 41, &u, &why));
  EXPECT_NE(why.find("at most 40"), std::string::npos) << why;
}

TEST(Sampling, InverseCdfs)
{
  SampleDistribution d;
  std::string        why;
  ASSERT_TRUE(SampleDistributionParse("normal:0.7:0.02", "m", false, &d, &why)) << why;
  EXPECT_DOUBLE_EQ(d.Quantile(0.5), 0.7);
  EXPECT_NEAR(d.Quantile(0.975), 0.7 + 1.959963984540054 * 0.02, 1e-12);
  ASSERT_TRUE(SampleDistributionParse("truncnormal:0:1:-1:2", "m", false, &d, &why)) << why;
  EXPECT_NEAR(d.Quantile(1e-12), -1, 1e-9);
  EXPECT_NEAR(d.Quantile(1 - 1e-12), 2, 1e-9);
  // The truncated normal's mean 0 + (phi(-1) - phi(2)) / (Phi(2) - Phi(-1)).
  EXPECT_NEAR(d.Mean(), (0.24197072451914337 - 0.05399096651318806) / (0.9772498680518208 - 0.15865525393145707), 1e-12);
  ASSERT_TRUE(SampleDistributionParse("truncnormal:0:1:5:6", "m", false, &d, &why)) << why; // far in the upper tail
  EXPECT_GT(d.Quantile(0.5), 5);
  EXPECT_LT(d.Quantile(0.5), 5.3);
  ASSERT_TRUE(SampleDistributionParse("uniform:58:62", "m/s", false, &d, &why));
  EXPECT_DOUBLE_EQ(d.Quantile(0.25), 59);
  ASSERT_TRUE(SampleDistributionParse("lognormal:2:0.5", "1", false, &d, &why));
  const double s2 = std::log1p(0.0625);
  EXPECT_NEAR(d.Quantile(0.5), 2 * std::exp(-0.5 * s2), 1e-12); // the median exp(mu)
  ASSERT_TRUE(SampleDistributionParse("triangular:0:1:4", "1", false, &d, &why));
  EXPECT_NEAR(d.Quantile(0.25), 1, 1e-12); // F(mode) = (c - a) / (b - a)
  EXPECT_NEAR(d.Quantile(0.625), 4 - std::sqrt(0.375 * 4 * 3), 1e-12);
  ASSERT_TRUE(SampleDistributionParse("0.5@1;0.6@3", "1", false, &d, &why)) << why;
  EXPECT_EQ(d.Quantile(0.24), 0.5);
  EXPECT_EQ(d.Quantile(0.26), 0.6);
  EXPECT_NEAR(d.Mean(), 0.575, 1e-15);
  const std::string csv = ::testing::TempDir() + "uq_values.csv";
  std::ofstream(csv) << "# measured\nplayer,x\n1,0.12\n2,0.10\n3,0.14\n4,0.11\n";
  ASSERT_TRUE(SampleDistributionParse("csv:" + csv + ":x", "m", false, &d, &why)) << why;
  EXPECT_EQ(d.values, (std::vector<double>{0.10, 0.11, 0.12, 0.14}));
  EXPECT_EQ(d.Quantile(0.3), 0.11);
  ASSERT_TRUE(SampleDistributionParse("csv:" + csv + ":2", "m", false, &d, &why)) << why;
  EXPECT_NEAR(d.Mean(), 0.1175, 1e-15);
}

TEST(Sampling, RefusedSpecs)
{
  SampleDistribution d;
  std::string        why;
  EXPECT_FALSE(SampleDistributionParse("normal:0.7", "m", false, &d, &why));
  EXPECT_NE(why.find("normal:MEAN:STD"), std::string::npos) << why;
  EXPECT_FALSE(SampleDistributionParse("normal:0.7:-1", "m", false, &d, &why));
  EXPECT_NE(why.find("STD must be > 0"), std::string::npos) << why;
  EXPECT_FALSE(SampleDistributionParse("uniform:2:1", "m", false, &d, &why));
  EXPECT_FALSE(SampleDistributionParse("triangular:0:5:4", "m", false, &d, &why));
  EXPECT_FALSE(SampleDistributionParse("truncnormal:0:1:30:40", "m", false, &d, &why));
  EXPECT_FALSE(SampleDistributionParse("gauss:0:1", "m", false, &d, &why));
  EXPECT_NE(why.find("truncnormal:MEAN:STD:LO:HI"), std::string::npos) << why;
  EXPECT_FALSE(SampleDistributionParse("0.5@1;0.6@-1", "1", false, &d, &why));
  EXPECT_FALSE(SampleDistributionParse("normal:30:2", "1", true, &d, &why));
  EXPECT_NE(why.find("whole numbers"), std::string::npos) << why;
  EXPECT_FALSE(SampleDistributionParse("csv:/nonexistent/file.csv", "m", false, &d, &why));
  EXPECT_TRUE(SampleSpecIsDistribution("normal:0:1"));
  EXPECT_TRUE(SampleSpecIsDistribution("1@2;3@4"));
  EXPECT_FALSE(SampleSpecIsDistribution("0:1.1:111"));
  EXPECT_FALSE(SampleSpecIsDistribution("rk;cn"));
}

TEST(Statistics, AgainstFormulas)
{
  std::vector<double> y;
  for (int i = 1; i <= 101; ++i) y.push_back(i);
  y.push_back(NAN); // left out
  const UqDescription d = UqDescribe(y, 1, 200);
  EXPECT_EQ(d.count, 101);
  EXPECT_DOUBLE_EQ(d.mean, 51);
  EXPECT_NEAR(d.std, std::sqrt(101.0 * 102 / 12), 1e-12); // the variance of 1..n with n - 1: n (n + 1) / 12
  EXPECT_NEAR(d.sem, d.std / std::sqrt(101.0), 1e-12);
  EXPECT_DOUBLE_EQ(d.q[0], 6);
  EXPECT_DOUBLE_EQ(d.q[1], 51);
  EXPECT_DOUBLE_EQ(d.q[2], 96);
  // The median's standard error of a uniform sample: sqrt(q (1 - q) / n) / f = 0.5 / sqrt(n) * 101
  // = 5.0; the bootstrap's, of a discrete sample, within 30 %.
  EXPECT_NEAR(d.q_se[1], 5.0, 1.5);
  EXPECT_EQ(UqDescribe(y, 1, 200).q_se[1], d.q_se[1]); // the seed decides the bootstrap
}

TEST(Statistics, Wilson)
{
  double lo, hi;
  UqWilson(0, 10, 1.96, &lo, &hi); // k = 0: [0, z^2 / (n + z^2)]
  EXPECT_EQ(lo, 0);
  EXPECT_NEAR(hi, 1.96 * 1.96 / (10 + 1.96 * 1.96), 1e-12);
  UqWilson(50, 100, 1.96, &lo, &hi);
  EXPECT_NEAR(0.5 - lo, hi - 0.5, 1e-12);
  EXPECT_NEAR(hi, 0.5 + 1.96 / (1 + 1.96 * 1.96 / 100) * std::sqrt(0.25 / 100 + 1.96 * 1.96 / 40000), 1e-12);
}

TEST(Statistics, Conditions)
{
  std::vector<UqCondition> c;
  std::string              why;
  ASSERT_TRUE(UqConditionsParse("bbcor>0.5, acor<=0.3", {"bbcor", "acor"}, &c, &why)) << why;
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[0].Holds(0.51));
  EXPECT_FALSE(c[0].Holds(0.5));
  EXPECT_TRUE(c[1].Holds(0.3));
  EXPECT_EQ(c[1].text, "acor<=0.3");
  c.clear();
  EXPECT_FALSE(UqConditionsParse("bbcorr>0.5", {"bbcor", "acor"}, &c, &why));
  EXPECT_NE(why.find("bbcor, acor"), std::string::npos) << why;
  EXPECT_FALSE(UqConditionsParse("bbcor=0.5", {"bbcor"}, &c, &why));
}

namespace {

// Saltelli's design on [-pi, pi]^3 (or [0, 1]^d for the linear model) and f at every row.
void Design(SampleDesign design, int n, int d, const std::function<double(const double *)> &f, double lo, double hi, std::vector<double> *fA, std::vector<double> *fB,
            std::vector<std::vector<double>> *fAB)
{
  std::vector<double> u;
  std::string         why;
  ASSERT_TRUE(SampleUnitDesign(design, 11, n, 2 * d, &u, &why)) << why;
  std::vector<double> rows = SampleSaltelliRows(u, n, d);
  for (double &x : rows) x = lo + (hi - lo) * x;
  fAB->assign(d, {});
  for (int j = 0; j < n; ++j) {
    const double *block = &rows[(size_t)j * (d + 2) * d];
    fA->push_back(f(block));
    fB->push_back(f(block + d));
    for (int i = 0; i < d; ++i) (*fAB)[i].push_back(f(block + (2 + i) * d));
  }
}

} // namespace

TEST(Sobol, Ishigami)
{
  auto ishigami = [](const double *x) { return std::sin(x[0]) + 7 * std::pow(std::sin(x[1]), 2) + 0.1 * std::pow(x[2], 4) * std::sin(x[0]); };
  const double S[3] = {0.3139, 0.4424, 0}, ST[3] = {0.5576, 0.4424, 0.2437}; // analytic (a = 7, b = 0.1)
  for (SampleDesign design : {SampleDesign::Sobol, SampleDesign::Random}) {
    std::vector<double>              fA, fB;
    std::vector<std::vector<double>> fAB;
    Design(design, 8192, 3, ishigami, -M_PI, M_PI, &fA, &fB, &fAB);
    const UqSobol r   = UqSobolIndices(fA, fB, fAB, 5, 200);
    const double  tol = design == SampleDesign::Sobol ? 0.01 : 0.04;
    EXPECT_NEAR(r.variance, 13.8446, 13.8446 * (design == SampleDesign::Sobol ? 0.01 : 0.04)); // a^2/8 + b pi^4/5 + b^2 pi^8/18 + 1/2
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(r.first[i], S[i], tol) << SampleDesignName(design) << " S_" << i + 1;
      EXPECT_NEAR(r.total[i], ST[i], tol) << SampleDesignName(design) << " S_T" << i + 1;
      // The 95 % bootstrap intervals hold the analytic values (widened by 0.005 for the digits quoted).
      EXPECT_LE(r.first_lo[i], S[i] + 0.005) << SampleDesignName(design) << " S_" << i + 1;
      EXPECT_GE(r.first_hi[i], S[i] - 0.005) << SampleDesignName(design) << " S_" << i + 1;
      EXPECT_LE(r.total_lo[i], ST[i] + 0.005) << SampleDesignName(design) << " S_T" << i + 1;
      EXPECT_GE(r.total_hi[i], ST[i] - 0.005) << SampleDesignName(design) << " S_T" << i + 1;
      EXPECT_LT(r.first_hi[i] - r.first_lo[i], 0.15);
    }
  }
}

TEST(Sobol, LinearModelAndNaN)
{
  // y = 1 x1 + 2 x2 + 0 x3 with independent uniform inputs: S_i = S_Ti = a_i^2 / sum a_j^2 = 0.2, 0.8, 0.
  auto                             linear = [](const double *x) { return x[0] + 2 * x[1]; };
  std::vector<double>              fA, fB;
  std::vector<std::vector<double>> fAB;
  Design(SampleDesign::Sobol, 1024, 3, linear, 0, 1, &fA, &fB, &fAB);
  fA[5] = NAN; // a failed run: its group is left out
  const UqSobol r = UqSobolIndices(fA, fB, fAB, 5, 100);
  EXPECT_EQ(r.groups, 1023);
  const double want[3] = {0.2, 0.8, 0};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.first[i], want[i], 0.01) << i;
    EXPECT_NEAR(r.total[i], want[i], 0.01) << i;
  }
  EXPECT_EQ(r.total[2], 0); // x3 never changes f: fAB_3 == fA exactly
  EXPECT_EQ(r.total_hi[2], 0);
}

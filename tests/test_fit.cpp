// -task fit's pieces as plain functions: the covariance of a straight-line fit against the textbook
// formulas, a combination the data cannot determine named from the singular vectors (and its
// standard errors infinite), the parameters' scales and starts, and the table's columns, weights
// and errors (each naming the file, line and column).
#include "studies/fit_data.hpp"
#include "studies/fit_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace beamimpact;

TEST(FitStats, StraightLineCovariance)
{
  // y = a + b x with standard deviations sigma_i: r_i = (a + b x_i - y_i)/sigma_i, dr/da = 1/sigma_i, dr/db = x_i/sigma_i.
  const std::vector<double> x = {0, 1, 2, 4, 7}, sigma = {0.5, 1, 1, 2, 0.7};
  std::vector<double>       J;
  double                    S = 0, Sx = 0, Sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    J.push_back(1 / sigma[i]), J.push_back(x[i] / sigma[i]);
    S += 1 / (sigma[i] * sigma[i]), Sx += x[i] / (sigma[i] * sigma[i]), Sxx += x[i] * x[i] / (sigma[i] * sigma[i]);
  }
  const double   D = S * Sxx - Sx * Sx, a = 1.5, b = -0.25;
  FitUncertainty u;
  ASSERT_EQ(0, FitUncertaintyOf(J, x.size(), 2, {a, b}, 1.0, 1e-8, &u));
  EXPECT_NEAR(Sxx / D, u.covariance[0], 1e-13 * Sxx / D);
  EXPECT_NEAR(S / D, u.covariance[3], 1e-13 * S / D);
  EXPECT_NEAR(-Sx / D, u.covariance[1], 1e-13 * Sx / D);
  EXPECT_NEAR(std::sqrt(Sxx / D), u.standard_error[0], 1e-13);
  EXPECT_NEAR(-Sx / std::sqrt(S * Sxx), u.correlation[1], 1e-13);
  EXPECT_TRUE(u.undetermined.empty());
  FitUncertainty relative; // relative weights: the covariance scales with s^2
  ASSERT_EQ(0, FitUncertaintyOf(J, x.size(), 2, {a, b}, 3.0, 1e-8, &relative));
  EXPECT_NEAR(3 * Sxx / D, relative.covariance[0], 1e-13 * Sxx / D);
}

TEST(FitStats, UndeterminedCombinationIsNamed)
{
  // f = g(E/rho): dr/dE = g'/E, dr/drho = -g'/rho, so J diag(p) has columns c and -c.
  const double        E = 7e10, rho = 2700;
  const std::vector<double> g = {1.0, 2.0, -0.5};
  std::vector<double> J;
  for (double gi : g) J.push_back(gi / E), J.push_back(-gi / rho);
  FitUncertainty u;
  ASSERT_EQ(0, FitUncertaintyOf(J, g.size(), 2, {E, rho}, 1.0, 1e-8, &u));
  ASSERT_EQ(1u, u.undetermined.size());
  EXPECT_EQ(1u, u.undetermined[0]);
  EXPECT_LT(u.singular[1], 1e-14 * u.singular[0]);
  EXPECT_EQ("+0.71 log E + 0.71 log rho", FitCombinationText(u, 1, {"E", "rho"}, {E, rho}));
  EXPECT_EQ("+0.71 log E - 0.71 log rho", FitCombinationText(u, 0, {"E", "rho"}, {E, rho}));
  EXPECT_TRUE(std::isinf(u.standard_error[0]) && std::isinf(u.standard_error[1]));
  // A small difference between the columns, well above the tolerance: determined, finite.
  J[1] *= 1.001;
  ASSERT_EQ(0, FitUncertaintyOf(J, g.size(), 2, {E, rho}, 1.0, 1e-8, &u));
  EXPECT_TRUE(u.undetermined.empty());
  EXPECT_TRUE(std::isfinite(u.standard_error[0]));
}

TEST(FitData, ParametersScaleAndStart)
{
  std::vector<FitParameter> p;
  std::string               why;
  ASSERT_TRUE(FitParseParameters("ball_k=1e4:1e5, beam_youngs_modulus=5e10:9e10:6e10", &p, &why)) << why;
  ASSERT_EQ(2u, p.size());
  EXPECT_TRUE(p[0].log);  // a decade
  EXPECT_FALSE(p[1].log); // less
  EXPECT_NEAR(std::sqrt(1e4 * 1e5), p[0].start, 1e-9); // the middle of a log scale
  EXPECT_EQ(6e10, p[1].start);
  EXPECT_EQ("N/m", p[0].unit);
  for (double u : {0.0, 0.3, 1.0}) EXPECT_NEAR(u, p[0].ToInternal(p[0].FromInternal(u)), 1e-15);
  EXPECT_NEAR(1e4, p[0].FromInternal(0), 1e-9);
  EXPECT_NEAR(1e5, p[0].FromInternal(1), 1e-9);
  EXPECT_NEAR(0.25, p[1].ToInternal(6e10), 1e-15);
  EXPECT_FALSE(FitParseParameters("ball_k=5e4:1e4", &p, &why));
  EXPECT_NE(std::string::npos, why.find("LO < HI")) << why;
  EXPECT_FALSE(FitParseParameters("no_such_option=1:2", &p, &why));
  EXPECT_NE(std::string::npos, why.find("-no_such_option is not a real-valued option")) << why;
  EXPECT_FALSE(FitParseParameters("ball_k=1e4:5e4:6e4", &p, &why));
  EXPECT_NE(std::string::npos, why.find("not a number within its bounds")) << why;
  EXPECT_FALSE(FitParseParameters("ball_k=1e4", &p, &why));
}

TEST(FitData, ColumnsWeightsAndErrors)
{
  std::vector<FitParameter> p;
  std::string               why;
  FitData                   d;
  const CaseTask           &impact = *CaseTaskFind("impact");
  ASSERT_TRUE(FitParseParameters("ball_k=1e4:5e4:2e4", &p, &why)) << why;
  const std::string text = "# a comment\nimpact_x, ball_speed, acor, contact_time, acor_sigma\n\n0.3, 1, 0.5, 3e-3, 0.01\n0.6, 2, 0.6, , 0.02\n";
  ASSERT_TRUE(FitParseData("t.csv", text, impact, "", p, &d, &why)) << why;
  EXPECT_EQ((std::vector<std::string>{"impact_x", "ball_speed"}), d.option_columns);
  EXPECT_EQ((std::vector<std::string>{"acor", "contact_time"}), d.measured);
  ASSERT_EQ(3u, d.values.size()); // the empty contact_time: not measured
  EXPECT_EQ(0.01, d.values[0].sigma);
  EXPECT_EQ(3e-3, d.values[1].sigma); // relative: the column's RMS
  EXPECT_EQ(0.02, d.values[2].sigma);
  EXPECT_FALSE(d.absolute);
  EXPECT_EQ(5, d.line[1]);
  EXPECT_EQ(0.6, d.rows[1][0].value);
  ASSERT_TRUE(FitParseData("t.csv", text, impact, "contact_time=1e-5", p, &d, &why)) << why;
  EXPECT_TRUE(d.absolute);
  EXPECT_EQ(1e-5, d.values[1].sigma);
  EXPECT_FALSE(FitParseData("t.csv", "impact_x,acor,foo\n0.3,0.5,1\n", impact, "", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("column 'foo' is neither an option")) << why;
  EXPECT_FALSE(FitParseData("t.csv", "impact_x,acor\n0.3,0.5\n0.4,abc\n", impact, "", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("t.csv line 3, column 'acor': 'abc' is not a number")) << why;
  EXPECT_FALSE(FitParseData("t.csv", "impact_x,acor\n0.3,0.5,7\n", impact, "", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("line 2: 3 cells, the header has 2")) << why;
  EXPECT_FALSE(FitParseData("t.csv", "ball_k,acor\n2e4,0.5\n", impact, "", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("also a fitted parameter")) << why;
  EXPECT_FALSE(FitParseData("t.csv", "impact_x,acor,acor_sigma\n0.3,0.5,0\n", impact, "", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("column 'acor_sigma': a standard deviation must be > 0")) << why;
  EXPECT_FALSE(FitParseData("t.csv", "impact_x,acor\n0.3,0.5\n", impact, "peak_force=1", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("-fit_sigma peak_force: no measured column")) << why;
}

// A spreadsheet's CSV: a UTF-8 byte order mark and CR or CR LF line ends read as the plain file is
// (the BOM made the first column "'<BOM>impact_x' is neither an option ...", CR-only lines one
// header 'contact_time0.3...'); a UTF-16 file refused naming its encoding (issue 34).
TEST(FitData, ByteOrderMarkAndLineEnds)
{
  std::vector<FitParameter> p;
  std::string               why;
  FitData                   plain, d;
  const CaseTask           &impact = *CaseTaskFind("impact");
  ASSERT_TRUE(FitParseParameters("ball_k=1e4:5e4", &p, &why)) << why;
  ASSERT_TRUE(FitParseData("t.csv", "impact_x,acor\n0.3,0.5\n0.6,0.4\n", impact, "", p, &plain, &why)) << why;
  for (const std::string &text : {std::string("\xEF\xBB\xBFimpact_x,acor\n0.3,0.5\n0.6,0.4\n"), std::string("impact_x,acor\r0.3,0.5\r0.6,0.4\r"),
                                 std::string("\xEF\xBB\xBFimpact_x,acor\r\n0.3,0.5\r\n0.6,0.4\r\n")}) {
    ASSERT_TRUE(FitParseData("t.csv", text, impact, "", p, &d, &why)) << why;
    EXPECT_EQ(plain.option_columns, d.option_columns);
    EXPECT_EQ(plain.measured, d.measured);
    ASSERT_EQ(2u, d.rows.size());
    EXPECT_EQ(0.6, d.rows[1][0].value);
    EXPECT_EQ(3, d.line[1]); // the lines counted as an editor shows them
  }
  EXPECT_FALSE(FitParseData("t.csv", std::string("\xFF\xFEi\0m\0", 6), impact, "", p, &d, &why));
  EXPECT_NE(std::string::npos, why.find("-fit_data t.csv: the file is UTF-16 text (it starts with the bytes FF FE)")) << why;
}

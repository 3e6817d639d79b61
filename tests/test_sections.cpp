// Real bats: section files and their errors, varying Euler-Bernoulli and Timoshenko beams.
// The frequencies are checked against independent references: finite-element eigen-solves
// written here (Hermite cubic Euler-Bernoulli elements and quadratic Timoshenko elements with
// consistent masses, Gauss quadrature, elements split at the profile's rows), and the
// analytic frequency equation of a uniform pinned-pinned Timoshenko beam.
#include "io/beam_options.hpp"
#include "io/section_file.hpp"
#include "io/text.hpp"
#include "model/beam_theory.hpp"
#include "system/beam_system.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscblaslapack.h>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

using namespace beamimpact;

namespace {

const std::string kSource = BEAMIMPACT_SOURCE_DIR;

// A scratch file with the given text; removed at the end of the scope.
class TempFile {
public:
  explicit TempFile(const std::string &text)
  {
    char name[] = "/tmp/beamimpact-section-XXXXXX";
    const int fd = mkstemp(name);
    EXPECT_GE(fd, 0);
    close(fd);
    path_ = name;
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string &path() const { return path_; }

private:
  std::string path_;
};

class ScopedOptions {
public:
  explicit ScopedOptions(std::vector<std::pair<std::string, std::string>> kv) : kv_(std::move(kv))
  {
    for (auto &o : kv_) EXPECT_EQ(0, PetscOptionsSetValue(NULL, o.first.c_str(), o.second.empty() ? NULL : o.second.c_str()));
  }
  ~ScopedOptions()
  {
    for (auto &o : kv_) EXPECT_EQ(0, PetscOptionsClearValue(NULL, o.first.c_str()));
  }

private:
  std::vector<std::pair<std::string, std::string>> kv_;
};

// Reads the -beam_* options with PETSc's error printing silenced; *msg: the error's text.
PetscErrorCode ReadBeam(BeamParams *p, std::string *msg)
{
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  const PetscErrorCode ierr = BeamParamsFromOptions(PETSC_COMM_WORLD, p);
  PetscCall(PetscPopErrorHandler());
  if (ierr) *msg = LastErrorMessage(ierr);
  return ierr;
}

BeamParams FromOptions(std::vector<std::pair<std::string, std::string>> kv)
{
  ScopedOptions o(std::move(kv));
  BeamParams    p;
  std::string   msg;
  EXPECT_EQ(0, ReadBeam(&p, &msg)) << msg;
  return p;
}

// ---------------------------------------------------------------- dense eigen-solves

// Eigenvalues of the symmetric-definite pencil (K, M), n x n column-major, ascending.
std::vector<double> PencilEigenvalues(std::vector<double> K, std::vector<double> M, PetscBLASInt n)
{
  std::vector<double> w(n);
  PetscBLASInt        itype = 1, lwork = -1, info = 0;
  double              q;
  LAPACKsygv_(&itype, "N", "U", &n, K.data(), &n, M.data(), &n, w.data(), &q, &lwork, &info);
  lwork = (PetscBLASInt)q;
  std::vector<double> work(lwork);
  LAPACKsygv_(&itype, "N", "U", &n, K.data(), &n, M.data(), &n, w.data(), work.data(), &lwork, &info);
  EXPECT_EQ(0, info);
  return w;
}

// Flexible frequencies (Hz) from ascending eigenvalues omega^2, skipping `rigid` rigid modes.
std::vector<double> Hz(const std::vector<double> &lam, size_t rigid, size_t count)
{
  std::vector<double> f;
  for (size_t k = rigid; k < rigid + count && k < lam.size(); ++k) f.push_back(std::sqrt(std::max(lam[k], 0.0)) / (2 * M_PI));
  return f;
}

// Frequencies of the program's semi-discrete system (the banded K and lumped M, free dofs).
std::vector<double> SystemHz(const BeamParams &p, size_t rigid, size_t count)
{
  const BeamSystem      S = test::SystemOf(p);
  std::vector<PetscInt> dofs;
  for (PetscInt d = 0; d < S.ndof; ++d)
    if (!S.held[d]) dofs.push_back(d);
  const PetscBLASInt  n = (PetscBLASInt)dofs.size();
  std::vector<double> K((size_t)n * n, 0.0), M((size_t)n * n, 0.0);
  std::vector<PetscInt>  cols(2 * S.bw + 1);
  std::vector<PetscReal> vals(2 * S.bw + 1);
  for (PetscInt a = 0; a < n; ++a) {
    const PetscInt nz = BeamSystemStiffnessRow(S, dofs[a], cols.data(), vals.data());
    for (PetscInt q = 0; q < nz; ++q) {
      const PetscInt b = (PetscInt)(std::lower_bound(dofs.begin(), dofs.end(), cols[q]) - dofs.begin());
      K[(size_t)b * n + a] = vals[q];
    }
    M[(size_t)a * n + a] = S.mass[dofs[a]];
  }
  return Hz(PencilEigenvalues(K, M, n), rigid, count);
}

// Element boundaries: the section's rows, each piece between rows split into equal elements
// of at most L / count (so no element straddles a kink of the profile, and none is much
// shorter than the rest: tiny Hermite elements would make K ill-conditioned).
std::vector<double> ElementEdges(const BeamParams &p, int count)
{
  std::vector<double> knots;
  if (p.section.source == SectionSource::Profile)
    for (const ProfileRow &r : p.section.profile) knots.push_back(r.x);
  else if (p.section.source == SectionSource::Table)
    for (const PropertiesRow &r : p.section.table) knots.push_back(r.x);
  else knots = {0.0, p.length};
  std::vector<double> edges{knots[0]};
  const double        target = (knots.back() - knots.front()) / count;
  for (size_t j = 0; j + 1 < knots.size(); ++j) {
    const int per = std::max(1, (int)std::ceil((knots[j + 1] - knots[j]) / target - 1e-9));
    for (int s = 1; s <= per; ++s) edges.push_back(knots[j] + (knots[j + 1] - knots[j]) * s / per);
  }
  return edges;
}

// 5-point Gauss-Legendre on [0, 1].
const double kGx[5] = {0.5 - 0.4530899229693320, 0.5 - 0.2692346550528416, 0.5, 0.5 + 0.2692346550528416, 0.5 + 0.4530899229693320};
const double kGw[5] = {0.1184634425280945, 0.2393143352496832, 0.2844444444444444, 0.2393143352496832, 0.1184634425280945};

// Free-free Euler-Bernoulli reference: Hermite cubic elements (dofs w, w' per node).
std::vector<double> HermiteEulerHz(const BeamParams &p, int elements, size_t count)
{
  const std::vector<double> e = ElementEdges(p, elements);
  const PetscBLASInt        n = 2 * (PetscBLASInt)e.size();
  std::vector<double>       K((size_t)n * n, 0.0), M((size_t)n * n, 0.0);
  for (size_t el = 0; el + 1 < e.size(); ++el) {
    const double le = e[el + 1] - e[el];
    for (int g = 0; g < 5; ++g) {
      const double            s = kGx[g], wq = kGw[g] * le;
      const SectionProperties q = BeamSectionAt(p, e[el] + s * le);
      const double N[4]   = {1 - 3 * s * s + 2 * s * s * s, le * (s - 2 * s * s + s * s * s), 3 * s * s - 2 * s * s * s, le * (-s * s + s * s * s)};
      const double B[4]   = {(-6 + 12 * s) / (le * le), (-4 + 6 * s) / le, (6 - 12 * s) / (le * le), (-2 + 6 * s) / le};
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const size_t i = 2 * el + a, j = 2 * el + b;
          K[j * n + i] += wq * q.EI * B[a] * B[b];
          M[j * n + i] += wq * q.mu * N[a] * N[b];
        }
    }
  }
  return Hz(PencilEigenvalues(K, M, n), 2, count);
}

// Free-free Timoshenko reference: quadratic elements for w and psi (3 nodes, 2 dofs each),
// full 5-point quadrature of bending and mass, reduced 2-point quadrature of shear.
std::vector<double> QuadraticTimoshenkoHz(const BeamParams &p, int elements, size_t count)
{
  const std::vector<double> e     = ElementEdges(p, elements);
  const size_t              nel   = e.size() - 1;
  const PetscBLASInt        n     = (PetscBLASInt)(2 * (2 * nel + 1));
  const double              g2[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  std::vector<double>       K((size_t)n * n, 0.0), M((size_t)n * n, 0.0);
  auto shape = [](double s, double L[3], double dL[3]) {
    L[0] = 2 * (s - 0.5) * (s - 1), L[1] = -4 * s * (s - 1), L[2] = 2 * s * (s - 0.5);
    dL[0] = 4 * s - 3, dL[1] = -8 * s + 4, dL[2] = 4 * s - 1;
  };
  for (size_t el = 0; el < nel; ++el) {
    const double le = e[el + 1] - e[el];
    auto         W  = [&](int a) { return (size_t)(2 * (2 * el + a)); }; // w dof of local node a; psi is +1
    double       L[3], dL[3];
    for (int g = 0; g < 5; ++g) {
      shape(kGx[g], L, dL);
      const double            wq = kGw[g] * le;
      const SectionProperties q  = BeamSectionAt(p, e[el] + kGx[g] * le);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          K[(W(b) + 1) * n + W(a) + 1] += wq * q.EI * dL[a] * dL[b] / (le * le);
          M[W(b) * n + W(a)] += wq * q.mu * L[a] * L[b];
          M[(W(b) + 1) * n + W(a) + 1] += wq * q.rhoI * L[a] * L[b];
        }
    }
    for (int g = 0; g < 2; ++g) {
      shape(g2[g], L, dL);
      const double            wq = 0.5 * le;
      const SectionProperties q  = BeamSectionAt(p, e[el] + g2[g] * le);
      double                  B[6]; // shear strain w' - psi over (w0, psi0, w1, psi1, w2, psi2)
      size_t                  idx[6];
      for (int a = 0; a < 3; ++a) B[2 * a] = dL[a] / le, B[2 * a + 1] = -L[a], idx[2 * a] = W(a), idx[2 * a + 1] = W(a) + 1;
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b) K[idx[b] * n + idx[a]] += wq * q.kGA * B[a] * B[b];
    }
  }
  return Hz(PencilEigenvalues(K, M, n), 2, count);
}

// Observed order of convergence from errors at h and h/2.
double Order(double e_coarse, double e_fine) { return std::log2(std::abs(e_coarse) / std::abs(e_fine)); }

// Checks second-order convergence of the first `count` flexible frequencies to `ref`.
void ExpectSecondOrder(const BeamParams &base, const std::vector<double> &ref, size_t count, double fine_tol, const char *what)
{
  std::vector<std::vector<double>> f;
  const PetscInt                   n0       = base.theory == "timoshenko" ? 81 : 161; // the Timoshenko beam is 10x closer at equal N
  const PetscInt                   grids[3] = {n0, 2 * n0 - 1, 4 * n0 - 3};
  for (PetscInt N : grids) {
    BeamParams p = base;
    p.nodes      = N;
    f.push_back(SystemHz(p, 2, count));
  }
  for (size_t k = 0; k < count; ++k) {
    const double e0 = f[0][k] - ref[k], e1 = f[1][k] - ref[k], e2 = f[2][k] - ref[k];
    // The slope of log|error| against log h over the three grids: steps in the section (a
    // knob, a wall change) fall differently between nodes on each grid, so single ratios scatter.
    const double slope = 0.5 * Order(e0, e2);
    std::printf("  %s mode %zu: ref %.3f Hz, errors %.2e %.2e %.2e, orders %.2f %.2f, fitted %.2f\n", what, k + 1, ref[k], e0 / ref[k], e1 / ref[k], e2 / ref[k], Order(e0, e1), Order(e1, e2), slope);
    EXPECT_GT(slope, 1.8) << what << " mode " << k + 1;
    EXPECT_LT(slope, 2.5) << what << " mode " << k + 1;
    EXPECT_LT(std::abs(e2) / ref[k], fine_tol) << what << " mode " << k + 1;
  }
}

std::vector<std::pair<std::string, std::string>> R161(const char *theory)
{
  return {{"-beam_profile", kSource + "/options/bats/r161.profile"}, {"-beam_youngs_modulus", "1.814e10"}, {"-beam_density", "649"}, {"-beam_shear_modulus", "1.05e9"}, {"-beam_theory", theory}};
}

std::vector<std::pair<std::string, std::string>> AluminiumBat(const char *theory)
{
  return {{"-beam_profile", kSource + "/options/bats/aluminium-bat.profile"}, {"-beam_youngs_modulus", "7.2e10"}, {"-beam_density", "2810"}, {"-beam_shear_modulus", "2.7e10"},
          {"-beam_poisson", "0.33"}, {"-beam_theory", theory}};
}

} // namespace

// ---------------------------------------------------------------- section formulas

TEST(Section, RoundFormulasAndCowper)
{
  EXPECT_NEAR(M_PI * 0.01 * 0.01 / 4, RoundArea(0.01, 0), 1e-18);
  EXPECT_NEAR(M_PI * (1.6e-7 - 1e-8) / 64, RoundSecondMoment(0.02, 0.01), 1e-22);
  EXPECT_NEAR(6 * 1.3 / (7 + 1.8), CowperRound(0.3, 0), 1e-15); // solid circle: 0.886
  EXPECT_NEAR(0.5, CowperRound(0.3, 1.0 - 1e-9), 0.04);       // thin tube: 2(1+nu)/(4+3nu) = 0.53
  EXPECT_NEAR(10 * 1.3 / (12 + 3.3), CowperRectangle(0.3), 1e-15);
}

TEST(Section, ProfileInterpolatesDiameters)
{
  BeamParams p;
  p.section.source   = SectionSource::Profile;
  p.section.profile  = {{0.0, 0.02, 0.0}, {1.0, 0.04, 0.02}};
  p.section.material = {2e11, 8000, 8e10, 0.3, 0};
  const SectionProperties s = SectionAt(p.section, 0.25); // D = 0.025, d = 0.005
  EXPECT_NEAR(8000 * RoundArea(0.025, 0.005), s.mu, 1e-12);
  EXPECT_NEAR(2e11 * RoundSecondMoment(0.025, 0.005), s.EI, 1e-9);
  EXPECT_NEAR(CowperRound(0.3, 0.2) * 8e10 * RoundArea(0.025, 0.005), s.kGA, 1e-3);
}

// ---------------------------------------------------------------- file errors

TEST(SectionFile, BadProfilesNameFileAndLine)
{
  std::vector<ProfileRow> rows;
  std::string             why;
  EXPECT_FALSE(ProfileFileRead("/nonexistent/bat.profile", &rows, &why));
  EXPECT_NE(std::string::npos, why.find("/nonexistent/bat.profile: cannot open")) << why;
  struct Case {
    const char *text, *expect;
  } cases[] = {
    {"# only a comment\n\n", ": the file has no rows"},
    {"0 0.05\n", "one row"},
    {"0 0.05\n0.5 0.06\n0.5 0.06\n", ":3: x = 0.5 does not increase"},
    {"0 0.05\n# c\n0.5 -0.01\n", ":3: outer diameter D = -0.01 is not allowed"},
    {"0 0.05 0.05\n0.5 0.06\n", ":1: inner diameter d = 0.05 is not allowed"},
    {"0 0.05\n0.5 nan\n", ":2: 'nan' is not a finite number"},
    {"0 0.05\n0.5 0.06x\n", ":2: '0.06x' is not a number"},
    {"0 0.05 0.01 7\n0.5 0.06\n", ":1: a profile row is 'x D' or 'x D d'"},
  };
  for (const Case &c : cases) {
    TempFile f(c.text);
    EXPECT_FALSE(ProfileFileRead(f.path(), &rows, &why)) << c.text;
    EXPECT_NE(std::string::npos, why.find(f.path())) << why;
    EXPECT_NE(std::string::npos, why.find(c.expect)) << why << " (expected '" << c.expect << "')";
  }
}

TEST(SectionFile, BadPropertiesNameFileAndLine)
{
  std::vector<PropertiesRow> rows;
  bool                       shear, torsion;
  std::string                why;
  struct Case {
    const char *text, *expect;
  } cases[] = {
    {"0 100 0.5\n0.5 100 0.5 1e5 1e-5\n", ":2: a properties row"},
    {"0 100 0.5 1e5\n0.5 100 0.5 1e5\n", ":1: a properties row"},
    {"0 100 0.5\n0.5 0 0.5\n", ":2: EI = 0 is not allowed"},
    {"0 100 0.5 1e5 -1\n0.5 100 0.5 1e5 1e-5\n", ":1: rhoI = -1 is not allowed"},
    {"0 100 0.5\n-1 100 0.5\n", ":2: x = -1 does not increase"},
  };
  for (const Case &c : cases) {
    TempFile f(c.text);
    EXPECT_FALSE(PropertiesFileRead(f.path(), &rows, &shear, &torsion, &why)) << c.text;
    EXPECT_NE(std::string::npos, why.find(c.expect)) << why << " (expected '" << c.expect << "')";
  }
  TempFile good("# x EI mu kGA rhoI\n0.1 100 0.5 1e5 1e-5\n0.6 50 0.25 5e4 5e-6 # end\n");
  ASSERT_TRUE(PropertiesFileRead(good.path(), &rows, &shear, &torsion, &why)) << why;
  EXPECT_TRUE(shear);
  EXPECT_FALSE(torsion);
  ASSERT_EQ(2u, rows.size());
  EXPECT_EQ(0.6, rows[1].x);
  TempFile twist("0 100 0.5 1e5 1e-5 40 2e-3\n0.5 100 0.5 1e5 1e-5 60 4e-3\n");
  ASSERT_TRUE(PropertiesFileRead(twist.path(), &rows, &shear, &torsion, &why)) << why;
  EXPECT_TRUE(shear && torsion);
  EXPECT_EQ(60, rows[1].s.GJ);
  EXPECT_EQ(4e-3, rows[1].s.rhoJ);
}

TEST(SectionOptions, BadCombinationsNameTheOption)
{
  TempFile    profile("0 0.05\n0.8 0.06\n");
  struct Case {
    std::vector<std::pair<std::string, std::string>> kv;
    const char                                      *expect;
  } cases[] = {
    {{{"-beam_profile", profile.path()}}, "needs the material"},
    {{{"-beam_profile", "/nonexistent/x.profile"}, {"-beam_youngs_modulus", "1e10"}, {"-beam_density", "600"}}, "-beam_profile: /nonexistent/x.profile: cannot open"},
    {{{"-beam_profile", profile.path()}, {"-beam_youngs_modulus", "1e10"}, {"-beam_density", "600"}, {"-beam_length", "1"}}, "do not also give -beam_length"},
    {{{"-beam_profile", profile.path()}, {"-beam_youngs_modulus", "1e10"}, {"-beam_density", "600"}, {"-beam_theory", "timoshenko"}}, "needs -beam_shear_modulus"},
    {{{"-beam_theory", "timoshenko"}}, "needs -beam_shear_modulus"},
    {{{"-beam_theory", "timoshenko"}, {"-beam_EI", "10"}, {"-beam_mu", "1"}, {"-beam_shear_modulus", "1e9"}}, "not the EI,mu set"},
    {{{"-beam_theory", "reissner"}}, "-beam_theory reissner is not known: use one of euler, timoshenko"},
    {{{"-beam_poisson", "0.7"}}, "-beam_poisson 0.7 is not allowed"},
  };
  for (const Case &c : cases) {
    ScopedOptions o(c.kv);
    BeamParams    p;
    std::string   msg;
    EXPECT_NE(0, ReadBeam(&p, &msg)) << c.expect;
    EXPECT_NE(std::string::npos, msg.find(c.expect)) << msg << " (expected '" << c.expect << "')";
  }
}

// ---------------------------------------------------------------- uniform = one case

TEST(SectionProfile, UniformProfileIsTheUniformBeam)
{
  const double E = 7e10, rho = 2700, G = 2.6e10, D = 0.03;
  TempFile     f("# a rod\n0.2 0.03\n1.3 0.03\n");
  for (const char *theory : {"euler", "timoshenko"}) {
    const BeamParams pp = FromOptions({{"-beam_profile", f.path()}, {"-beam_youngs_modulus", "7e10"}, {"-beam_density", "2700"}, {"-beam_shear_modulus", "2.6e10"}, {"-beam_theory", theory}});
    EXPECT_NEAR(1.1, pp.length, 1e-15);
    BeamParams pu = pp;
    pu.section    = BeamSection();
    pu.EI         = E * RoundSecondMoment(D, 0);
    pu.mu         = rho * RoundArea(D, 0);
    pu.rhoI       = rho * RoundSecondMoment(D, 0);
    pu.kGA        = CowperRound(0.3, 0) * G * RoundArea(D, 0);
    const BeamSystem a = test::SystemOf(pp), b = test::SystemOf(pu);
    ASSERT_EQ(a.band.size(), b.band.size());
    double kmax = 0;
    for (PetscReal v : b.band) kmax = std::max(kmax, std::abs(v));
    for (size_t i = 0; i < a.band.size(); ++i) EXPECT_NEAR(a.band[i], b.band[i], 1e-13 * kmax) << theory << " band " << i;
    for (size_t i = 0; i < a.mass.size(); ++i) EXPECT_NEAR(a.mass[i], b.mass[i], 1e-14 * b.mass[i]) << theory << " mass " << i;
    EXPECT_NEAR(pu.EI, pp.EI, 1e-12 * pu.EI);
    EXPECT_NEAR(pu.mu, pp.mu, 1e-12 * pu.mu);
  }
}

// ---------------------------------------------------------------- Timoshenko

// Rigid motions (w = 1; w = x, psi = 1) carry no strain: K annihilates them, so a free-free
// Timoshenko bat conserves momentum as the Euler-Bernoulli beam does.
TEST(Timoshenko, RigidMotionsAreFreeOfStrain)
{
  const BeamParams p = FromOptions(R161("timoshenko"));
  const BeamSystem S = test::SystemOf(p);
  ASSERT_EQ(2, S.fields);
  std::vector<PetscReal> y(S.ndof), f(S.ndof);
  for (int mode = 0; mode < 2; ++mode) {
    for (PetscInt i = 0; i < S.nodes; ++i) y[S.Dof(i, 0)] = mode == 0 ? 1.0 : S.NodeX(i), y[S.Dof(i, 1)] = mode == 0 ? 0.0 : 1.0;
    BeamSystemStiffnessApply(S, y.data(), 2, 0, S.ndof, f.data(), 1);
    double fmax = 0, kmax = 0;
    for (PetscInt d = 0; d < S.ndof; ++d) fmax = std::max(fmax, std::abs(f[d]));
    for (PetscReal v : S.band) kmax = std::max(kmax, std::abs(v));
    EXPECT_LT(fmax, 1e-13 * kmax) << "rigid mode " << mode;
    EXPECT_LT(BeamSystemStrainEnergy(S, y.data(), 2, 0, S.ndof), 1e-24 * kmax);
  }
}

// A uniform pinned-pinned Timoshenko beam: w = W sin kx, psi = P cos kx with k = n pi / L,
//   (kGA k^2 - rhoA w^2)(EI k^2 + kGA - rhoI w^2) = (kGA k)^2 : the lower root.
TEST(Timoshenko, UniformPinnedMatchesTheFrequencyEquation)
{
  BeamParams p;
  const double E = 7e10, G = 2.6e10, rho = 2700, a = 0.05, b = 0.03, kappa = 5.0 / 6.0;
  p.length = 0.5, p.left = p.right = Support::Pinned, p.theory = "timoshenko";
  p.EI = E * b * a * a * a / 12, p.mu = rho * a * b, p.rhoI = rho * b * a * a * a / 12, p.kGA = kappa * G * a * b;
  std::vector<double> ref, euler;
  for (int n = 1; n <= 4; ++n) {
    const double k = n * M_PI / p.length, A = p.mu * p.rhoI, B = -(p.mu * (p.EI * k * k + p.kGA) + p.rhoI * p.kGA * k * k), C = p.kGA * k * k * p.EI * k * k;
    ref.push_back(std::sqrt((-B - std::sqrt(B * B - 4 * A * C)) / (2 * A)) / (2 * M_PI));
    euler.push_back(k * k * std::sqrt(p.EI / p.mu) / (2 * M_PI));
  }
  EXPECT_LT(ref[3], 0.85 * euler[3]); // shear matters here: the test can tell the theories apart
  std::vector<std::vector<double>> f;
  for (PetscInt N : {41, 81, 161}) {
    p.nodes = N;
    f.push_back(SystemHz(p, 0, 4));
  }
  for (size_t k = 0; k < 4; ++k) {
    const double e0 = f[0][k] - ref[k], e1 = f[1][k] - ref[k], e2 = f[2][k] - ref[k];
    std::printf("  pinned mode %zu: %.3f Hz (Euler-Bernoulli %.3f), errors %.2e %.2e %.2e, orders %.2f %.2f\n", k + 1, ref[k], euler[k], e0 / ref[k], e1 / ref[k], e2 / ref[k], Order(e0, e1), Order(e1, e2));
    EXPECT_NEAR(2.0, Order(e1, e2), 0.1) << "mode " << k + 1;
    EXPECT_LT(std::abs(e2) / ref[k], 2e-3) << "mode " << k + 1;
  }
}

// A slender Timoshenko beam is the Euler-Bernoulli beam, and shear locking (a stiffening
// growing like (L/a)^2 on a coarse grid) is absent: at N = 41 the free-free frequencies of a
// strip 183 and 1833 times longer than thick are within the grid's O(h^2) error of the
// analytic Euler-Bernoulli values (beta L = 4.7300, 7.8532, 10.9956).
TEST(Timoshenko, ThinLimitHasNoLocking)
{
  const double betaL[3] = {4.730040745, 7.853204624, 10.99560784};
  for (double a : {0.006, 0.0006}) {
    BeamParams t = test::AluminiumBeam(1.1, 41);
    t.theory     = "timoshenko";
    t.EI         = 7e10 * 0.032 * a * a * a / 12, t.mu = 2700 * 0.032 * a;
    t.rhoI       = 2700 * 0.032 * a * a * a / 12;
    t.kGA        = CowperRectangle(0.33) * 2.6e10 * a * 0.032;
    const std::vector<double> f = SystemHz(t, 2, 3);
    for (size_t k = 0; k < 3; ++k) {
      const double exact = betaL[k] * betaL[k] * std::sqrt(t.EI / t.mu) / (1.1 * 1.1) / (2 * M_PI);
      EXPECT_NEAR(exact, f[k], 0.01 * exact) << "a = " << a << ", mode " << k + 1;
    }
  }
}

// ---------------------------------------------------------------- bats against references

TEST(BatFrequencies, R161EulerConvergesToHermiteReference)
{
  const BeamParams p = FromOptions(R161("euler"));
  ExpectSecondOrder(p, HermiteEulerHz(p, 300, 5), 5, 2e-3, "R161 Euler-Bernoulli");
}

TEST(BatFrequencies, R161TimoshenkoConvergesToQuadraticReference)
{
  const BeamParams p = FromOptions(R161("timoshenko"));
  ExpectSecondOrder(p, QuadraticTimoshenkoHz(p, 300, 5), 5, 2e-3, "R161 Timoshenko");
}

TEST(BatFrequencies, HollowBatEulerAndTimoshenko)
{
  const BeamParams e = FromOptions(AluminiumBat("euler")), t = FromOptions(AluminiumBat("timoshenko"));
  ExpectSecondOrder(e, HermiteEulerHz(e, 300, 5), 5, 2e-3, "aluminium Euler-Bernoulli");
  ExpectSecondOrder(t, QuadraticTimoshenkoHz(t, 300, 5), 5, 2e-3, "aluminium Timoshenko");
}

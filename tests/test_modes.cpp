// Mode frequencies of the discrete beam (BeamModesCompute, SLEPc) against the
// continuum beta-L reference (BeamModesAnalytic, docs/model.md), for the
// paper's aluminium beam: E = 7e10 Pa, rho = 2700 kg/m^3, b = 32 mm, a = 6 mm,
// L = 1.1 m. Runs at 1 and 2 MPI ranks: the solve is on PETSC_COMM_WORLD.
//
//   mpiexec -n 2 ./test_modes
#include "solvers/modes.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace beamimpact;

namespace {

constexpr PetscReal kLength = 1.1; // m

BeamParams Aluminium(Support left, Support right, PetscInt nodes)
{
  return test::AluminiumBeam(kLength, nodes, left, right); // the paper's 6 mm x 32 mm section
}

// sqrt(EI/mu)/L^2 (rad/s): omega_n = (beta_n L)^2 times this.
PetscReal Unit(const BeamParams &p) { return std::sqrt(p.EI / p.mu) / (p.length * p.length); }

// Relative errors of the first n flexural modes of the discrete beam against the
// continuum reference; also checks the rigid modes and the result's bookkeeping.
void FlexuralErrors(Support left, Support right, PetscInt nodes, PetscInt n, std::vector<PetscReal> *err, std::vector<PetscReal> *betah = nullptr)
{
  const BeamParams   p     = Aluminium(left, right, nodes);
  const BeamSystem sys = test::SystemOf(p);
  const PetscInt     rigid = BeamModesRigidCount(left, right);
  ModesResult        r;
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, n + rigid, &r));
  ASSERT_EQ((size_t)(n + rigid), r.omega.size());
  ASSERT_EQ((size_t)(n + rigid), r.frequency.size());
  ASSERT_EQ((size_t)(n + rigid), r.period.size());
  EXPECT_EQ(rigid, r.rigid_count);
  for (PetscInt m = 0; m < rigid; ++m) {
    EXPECT_EQ(0.0, r.omega[m]) << "rigid mode " << m;
    EXPECT_EQ(0.0, r.frequency[m]);
    EXPECT_EQ(0.0, r.period[m]);
  }
  for (PetscInt m = rigid; m < n + rigid; ++m) {
    EXPECT_NEAR(r.omega[m] / (2 * M_PI), r.frequency[m], 1e-12 * r.frequency[m]);
    EXPECT_NEAR(1.0 / r.frequency[m], r.period[m], 1e-12 * r.period[m]);
    if (m > rigid) {
      EXPECT_GT(r.omega[m], r.omega[m - 1]);
    }
  }
  std::vector<PetscReal> ref;
  ASSERT_EQ(0, BeamModesAnalytic(left, right, p.length, p.EI, p.mu, n, &ref));
  err->resize(n);
  if (betah) betah->resize(n);
  for (PetscInt k = 0; k < n; ++k) {
    (*err)[k] = r.omega[rigid + k] / ref[k] - 1.0;
    if (betah) (*betah)[k] = std::sqrt(ref[k] / Unit(p)) / (nodes - 1); // beta_k h
  }
}

struct SupportCase {
  Support     left, right;
  const char *name;
};
const SupportCase kCases[] = {
  {Support::Free, Support::Free, "free-free"},
  {Support::Clamped, Support::Free, "clamped-free"},
  {Support::Pinned, Support::Free, "pinned-free"},
};

} // namespace

// beta L recovered from BeamModesAnalytic equals the tables of docs/model.md (5 decimals),
// whichever end carries which support.
TEST(ModesAnalytic, MatchesModelTables)
{
  const PetscReal EI = 40.0, mu = 0.5, L = 1.1, unit = std::sqrt(EI / mu) / (L * L);
  struct Row {
    Support                l, r;
    std::vector<PetscReal> betaL;
  };
  const Row rows[] = {
    {Support::Free, Support::Free, {4.73004, 7.85320, 10.99561, 14.13717}},
    {Support::Clamped, Support::Free, {1.87510, 4.69409, 7.85476, 10.99554}},
    {Support::Free, Support::Clamped, {1.87510, 4.69409, 7.85476, 10.99554}},
    {Support::Pinned, Support::Free, {3.92660, 7.06858, 10.21018}},
    {Support::Free, Support::Pinned, {3.92660, 7.06858, 10.21018}},
  };
  for (const Row &row : rows) {
    std::vector<PetscReal> w;
    ASSERT_EQ(0, BeamModesAnalytic(row.l, row.r, L, EI, mu, (PetscInt)row.betaL.size(), &w));
    ASSERT_EQ(row.betaL.size(), w.size());
    for (size_t n = 0; n < w.size(); ++n) EXPECT_NEAR(row.betaL[n], std::sqrt(w[n] / unit), 6e-6) << SupportName(row.l) << "-" << SupportName(row.r) << " mode " << n + 1;
  }
}

// Beyond the tables: the roots satisfy the characteristic equations and approach
// the asymptotes (2n+1)pi/2 (free-free), (2n-1)pi/2 (clamped-free), (4n+1)pi/4
// (pinned-free); pinned-pinned is n pi; clamped-clamped shares free-free's roots.
TEST(ModesAnalytic, CharacteristicEquationsBeyondTables)
{
  const PetscReal        EI = 1.0, mu = 1.0, L = 1.0; // omega = (beta L)^2
  std::vector<PetscReal> ff, cf, pf, pp, cc, cp;
  const PetscInt         n = 12;
  ASSERT_EQ(0, BeamModesAnalytic(Support::Free, Support::Free, L, EI, mu, n, &ff));
  ASSERT_EQ(0, BeamModesAnalytic(Support::Clamped, Support::Free, L, EI, mu, n, &cf));
  ASSERT_EQ(0, BeamModesAnalytic(Support::Pinned, Support::Free, L, EI, mu, n, &pf));
  ASSERT_EQ(0, BeamModesAnalytic(Support::Pinned, Support::Pinned, L, EI, mu, n, &pp));
  ASSERT_EQ(0, BeamModesAnalytic(Support::Clamped, Support::Clamped, L, EI, mu, n, &cc));
  ASSERT_EQ(0, BeamModesAnalytic(Support::Pinned, Support::Clamped, L, EI, mu, n, &cp));
  for (PetscInt k = 1; k <= n; ++k) {
    const PetscReal xf = std::sqrt(ff[k - 1]), xc = std::sqrt(cf[k - 1]), xp = std::sqrt(pf[k - 1]);
    EXPECT_NEAR(1.0, std::cos(xf) * std::cosh(xf), 1e-9 * std::cosh(xf)) << "free-free n=" << k;
    EXPECT_NEAR(-1.0, std::cos(xc) * std::cosh(xc), 1e-9 * std::cosh(xc)) << "clamped-free n=" << k;
    EXPECT_NEAR(std::tan(xp), std::tanh(xp), 1e-9 / std::pow(std::cos(xp), 2)) << "pinned-free n=" << k;
    if (k >= 3) { // the roots approach the asymptotes as ~2 e^{-beta L}
      EXPECT_NEAR((2 * k + 1) * M_PI / 2, xf, 1e-3) << "free-free n=" << k;
      EXPECT_NEAR((2 * k - 1) * M_PI / 2, xc, 1e-3) << "clamped-free n=" << k;
      EXPECT_NEAR((4 * k + 1) * M_PI / 4, xp, 1e-3) << "pinned-free n=" << k;
    }
    EXPECT_NEAR(k * M_PI, std::sqrt(pp[k - 1]), 1e-13 * k);
    EXPECT_NEAR(ff[k - 1], cc[k - 1], 1e-12 * ff[k - 1]);
    EXPECT_NEAR(pf[k - 1], cp[k - 1], 1e-12 * pf[k - 1]);
  }
  // omega scales as sqrt(EI/(mu L^4)).
  std::vector<PetscReal> scaled;
  ASSERT_EQ(0, BeamModesAnalytic(Support::Clamped, Support::Free, 2.0, 9.0, 4.0, 1, &scaled));
  EXPECT_NEAR(cf[0] * std::sqrt(9.0 / 4.0) / 4.0, scaled[0], 1e-13 * scaled[0]);
}

TEST(ModesAnalytic, RejectsBadArguments)
{
  std::vector<PetscReal> w;
  PetscCallVoid(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  EXPECT_NE(0, BeamModesAnalytic(Support::Free, Support::Free, -1.0, 1.0, 1.0, 2, &w));
  EXPECT_NE(0, BeamModesAnalytic(Support::Free, Support::Free, 1.0, 0.0, 1.0, 2, &w));
  EXPECT_NE(0, BeamModesAnalytic(Support::Free, Support::Free, 1.0, 1.0, 1.0, -1, &w));
  static const SupportSpec other = {"other", "a support without a beta-L table", NodeHold::Guide};
  EXPECT_EQ(PETSC_ERR_SUP, BeamModesAnalytic(Support(&other), Support::Free, 1.0, 1.0, 1.0, 2, &w));
  PetscCallVoid(PetscPopErrorHandler());
}

TEST(ModesAnalytic, RigidCounts)
{
  EXPECT_EQ(2, BeamModesRigidCount(Support::Free, Support::Free));
  EXPECT_EQ(1, BeamModesRigidCount(Support::Pinned, Support::Free));
  EXPECT_EQ(1, BeamModesRigidCount(Support::Free, Support::Pinned));
  EXPECT_EQ(0, BeamModesRigidCount(Support::Clamped, Support::Free));
  EXPECT_EQ(0, BeamModesRigidCount(Support::Pinned, Support::Pinned));
}

// N = 41: rigid modes exactly 0 first; the fundamental within 0.5% of the
// continuum; every one of the first four flexural modes within (beta_n h)^2/4,
// the second-order error bound of this scheme (its interior stencil alone
// lowers omega by (beta h)^2/12; the ends add at most twice that).
// N = 81: the first four flexural modes within 0.5%.
TEST(BeamModes, FirstFourFlexuralModesMatchContinuum)
{
  for (const SupportCase &c : kCases) {
    std::vector<PetscReal> e41, bh41, e81;
    FlexuralErrors(c.left, c.right, 41, 4, &e41, &bh41);
    FlexuralErrors(c.left, c.right, 81, 4, &e81);
    ASSERT_EQ(4u, e41.size());
    ASSERT_EQ(4u, e81.size());
    EXPECT_LT(std::abs(e41[0]), 5e-3) << c.name << " fundamental at N = 41";
    for (int k = 0; k < 4; ++k) {
      EXPECT_LT(std::abs(e41[k]), bh41[k] * bh41[k] / 4) << c.name << " mode " << k + 1 << " at N = 41";
      EXPECT_LT(std::abs(e81[k]), 5e-3) << c.name << " mode " << k + 1 << " at N = 81";
    }
  }
}

// Second order: the fundamental's error shrinks 4x per halving of h.
TEST(BeamModes, FundamentalConvergesAtSecondOrder)
{
  for (const SupportCase &c : kCases) {
    std::vector<PetscReal> e[3];
    const PetscInt         nodes[3] = {41, 81, 161};
    for (int g = 0; g < 3; ++g) FlexuralErrors(c.left, c.right, nodes[g], 1, &e[g]);
    for (int g = 0; g < 2; ++g) {
      const PetscReal ratio = e[g][0] / e[g + 1][0];
      EXPECT_GE(ratio, 3.5) << c.name << " N = " << nodes[g] << " -> " << nodes[g + 1];
      EXPECT_LE(ratio, 4.5) << c.name << " N = " << nodes[g] << " -> " << nodes[g + 1];
    }
  }
}

// On fine grids K is ill-conditioned (omega_max/omega_1 ~ 1e5 at N = 641): the
// rigid modes must still come out as exactly 0 and the fundamental keep its
// second-order error (the solver's own eigenvalue alone would not: its round-off
// ~ eps ||M^-1 K|| is 1e-4 (EI/mu)/L^4 there).
TEST(BeamModes, FineGridKeepsRigidModesAndSecondOrder)
{
  for (const SupportCase &c : kCases) {
    std::vector<PetscReal> e321, e641;
    FlexuralErrors(c.left, c.right, 321, 1, &e321);
    FlexuralErrors(c.left, c.right, 641, 1, &e641);
    const PetscReal ratio = e321[0] / e641[0];
    EXPECT_GE(ratio, 3.5) << c.name;
    EXPECT_LE(ratio, 4.5) << c.name;
  }
}

// The first flexural mode of the free-free beam has its nodes at x/L = 0.2242 and 0.7758.
TEST(BeamModes, FreeFreeFundamentalNodes)
{
  const BeamParams                    p  = Aluminium(Support::Free, Support::Free, 41);
  const BeamSystem sys = test::SystemOf(p);
  ModesResult                         r;
  std::vector<std::vector<PetscReal>> shapes;
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, 3, &r, &shapes));
  ASSERT_EQ(2, r.rigid_count);
  ASSERT_EQ(3u, shapes.size());
  const std::vector<PetscReal> &phi = shapes[2];
  ASSERT_EQ((size_t)sys.nodes, phi.size());
  std::vector<PetscReal> zeros; // x/L of the sign changes, by linear interpolation
  for (PetscInt i = 0; i + 1 < sys.nodes; ++i)
    if ((phi[i] < 0) != (phi[i + 1] < 0)) zeros.push_back((i + phi[i] / (phi[i] - phi[i + 1])) * sys.h / sys.L);
  ASSERT_EQ(2u, zeros.size());
  const PetscReal hL = sys.h / sys.L;
  EXPECT_NEAR(0.2242, zeros[0], hL);
  EXPECT_NEAR(0.7758, zeros[1], hL);
  EXPECT_NEAR(1.0, zeros[0] + zeros[1], 1e-9); // symmetric mode
  EXPECT_GT(phi[0], 0.0);                      // sign convention: first sizeable node positive
}

// Shapes solve K phi = omega^2 M phi (checked with the factored stiffness action of the
// system, BeamSystemStiffnessApply, where the solver had the assembled rows), are M-orthonormal, vanish at held nodes, and the rigid ones are
// rigid motions: a + b x for free-free, b x about the pin at x = 0.
TEST(BeamModes, ShapesAreMOrthonormalEigenvectors)
{
  for (const SupportCase &c : kCases) {
    const BeamSystem sys = test::SystemOf(Aluminium(c.left, c.right, 41));
    const PetscInt                      count = 6;
    ModesResult                         r;
    std::vector<std::vector<PetscReal>> shapes;
    ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, count, &r, &shapes));
    ASSERT_EQ((size_t)count, shapes.size());
    std::vector<PetscReal> f(sys.nodes);
    for (PetscInt a = 0; a < count; ++a) {
      const std::vector<PetscReal> &phi = shapes[a];
      for (PetscInt i = 0; i < sys.nodes; ++i) {
        if (sys.held[i]) {
          EXPECT_EQ(0.0, phi[i]);
        }
      }
      for (PetscInt b = 0; b < count; ++b) {
        PetscReal dot = 0;
        for (PetscInt i = 0; i < sys.nodes; ++i) dot += sys.mass[i] * phi[i] * shapes[b][i];
        EXPECT_NEAR(a == b ? 1.0 : 0.0, dot, 1e-9) << c.name << " modes " << a << "," << b;
      }
      BeamSystemStiffnessApply(sys, phi.data(), 1, 0, sys.nodes, f.data(), 1);
      const PetscReal w2 = r.omega[a] * r.omega[a];
      PetscReal       res = 0, scale = 0; // scale: max_i sum_j |K_ij phi_j| + omega^2 m_i |phi_i|
      for (PetscInt i = 0; i < sys.nodes; ++i) {
        if (sys.held[i]) continue;
        PetscInt  cols[5];
        PetscReal vals[5], s = w2 * sys.mass[i] * std::abs(phi[i]);
        const PetscInt n = BeamSystemStiffnessRow(sys, i, cols, vals);
        for (PetscInt q = 0; q < n; ++q) s += std::abs(vals[q] * phi[cols[q]]);
        res   = std::max(res, std::abs(f[i] - w2 * sys.mass[i] * phi[i]));
        scale = std::max(scale, s);
      }
      EXPECT_LT(res, 1e-8 * scale) << c.name << " mode " << a;
    }
    for (PetscInt a = 0; a < r.rigid_count; ++a) {
      // Least-squares fit phi ~ c0 + c1 x (free-free) or c1 x (pinned at x = 0).
      const std::vector<PetscReal> &phi = shapes[a];
      PetscReal                     s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
      for (PetscInt i = 0; i < sys.nodes; ++i) {
        const PetscReal x = i * sys.h;
        s0 += 1, s1 += x, s2 += x * x, t0 += phi[i], t1 += x * phi[i];
      }
      PetscReal c0 = 0, c1 = t1 / s2;
      if (c.left == Support::Free) {
        const PetscReal det = s0 * s2 - s1 * s1;
        c0                  = (t0 * s2 - t1 * s1) / det;
        c1                  = (s0 * t1 - s1 * t0) / det;
      }
      PetscReal dev = 0, amax = 0;
      for (PetscInt i = 0; i < sys.nodes; ++i) {
        dev  = std::max(dev, std::abs(phi[i] - c0 - c1 * i * sys.h));
        amax = std::max(amax, std::abs(phi[i]));
      }
      EXPECT_LT(dev, 1e-9 * amax) << c.name << " rigid mode " << a;
    }
  }
}

// A handle clamped over [0.62, 0.72] m of a 0.72 m beam free at x = 0 vibrates as a
// 0.62 m clamped-free beam.
TEST(BeamModes, ClampedRegionActsAsClampedEnd)
{
  BeamParams p = Aluminium(Support::Free, Support::Free, 73); // h = 1 cm
  p.length     = 0.72;
  p.has_clamp  = true;
  p.clamp_x0   = 0.62;
  p.clamp_x1   = 0.72;
  const BeamSystem sys = test::SystemOf(p);
  ASSERT_EQ(62, BeamFreeDofCount(sys));
  ModesResult r;
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, 4, &r));
  EXPECT_EQ(0, r.rigid_count);
  std::vector<PetscReal> ref;
  ASSERT_EQ(0, BeamModesAnalytic(Support::Clamped, Support::Free, 0.62, p.EI, p.mu, 4, &ref));
  const PetscReal unit = std::sqrt(p.EI / p.mu) / (0.62 * 0.62);
  for (int k = 0; k < 4; ++k) {
    const PetscReal bh = std::sqrt(ref[k] / unit) * sys.h / 0.62;
    EXPECT_LT(std::abs(r.omega[k] / ref[k] - 1), bh * bh / 4) << "mode " << k + 1;
  }
}

// All modes of a tiny beam: as many as free nodes, below the Gershgorin bound of the
// system; two rigid ones for free-free.
TEST(BeamModes, AllModesOfASmallBeam)
{
  const BeamSystem sys = test::SystemOf(Aluminium(Support::Free, Support::Free, 7));
  ModesResult        r;
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, 7, &r));
  EXPECT_EQ(2, r.rigid_count);
  const PetscReal bound = BeamSystemMaxFrequencyBound(sys, BeamSystemCoupling(sys, 0.0), 0.0, 0.0);
  for (int m = 2; m < 7; ++m) {
    EXPECT_GT(r.omega[m], r.omega[m - 1]);
    EXPECT_LE(r.omega[m], bound * (1 + 1e-12));
  }
  // Sum of omega^2 = trace(M^-1 K): the eigenvalues of a 7x7 problem checked as a whole.
  PetscReal trace = 0, sum = 0;
  for (PetscInt i = 0; i < sys.nodes; ++i) {
    PetscInt  cols[5];
    PetscReal vals[5];
    PetscInt  n = BeamSystemStiffnessRow(sys, i, cols, vals);
    for (PetscInt q = 0; q < n; ++q)
      if (cols[q] == i) trace += vals[q] / sys.mass[i];
  }
  for (PetscReal w : r.omega) sum += w * w;
  EXPECT_NEAR(trace, sum, 1e-10 * trace);
}

// The distributed solve equals a serial solve of the same beam, and every rank
// holds the same numbers.
TEST(BeamModes, ParallelMatchesSerialAndRanksAgree)
{
  const BeamSystem sys = test::SystemOf(Aluminium(Support::Clamped, Support::Free, 81));
  ModesResult                         rw, rs;
  std::vector<std::vector<PetscReal>> sw, ss;
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, 5, &rw, &sw));
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_SELF, sys, 5, &rs, &ss));
  for (int m = 0; m < 5; ++m) {
    EXPECT_NEAR(rs.omega[m], rw.omega[m], 1e-10 * rs.omega[m]);
    for (PetscInt i = 0; i < sys.nodes; ++i) EXPECT_NEAR(ss[m][i], sw[m][i], 1e-8);
    PetscReal lo = rw.omega[m], hi = rw.omega[m];
    ASSERT_EQ(MPI_SUCCESS, MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPIU_REAL, MPI_MIN, PETSC_COMM_WORLD));
    ASSERT_EQ(MPI_SUCCESS, MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD));
    EXPECT_EQ(lo, hi) << "mode " << m << " differs between ranks";
  }
}

TEST(BeamModes, CountOutOfRangeIsRefused)
{ // 5 free nodes
  const BeamSystem sys = test::SystemOf(Aluminium(Support::Clamped, Support::Free, 6));
  ModesResult        r;
  PetscCallVoid(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  EXPECT_EQ(PETSC_ERR_ARG_OUTOFRANGE, BeamModesCompute(PETSC_COMM_WORLD, sys, 0, &r));
  EXPECT_EQ(PETSC_ERR_ARG_OUTOFRANGE, BeamModesCompute(PETSC_COMM_WORLD, sys, 6, &r));
  PetscCallVoid(PetscPopErrorHandler());
  EXPECT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, 5, &r));
  EXPECT_EQ(5u, r.omega.size());
}

TEST(ModesParams, FromOptions)
{
  const BeamSystem sys = test::SystemOf(Aluminium(Support::Free, Support::Free, 41));
  ModesParams        p;
  ASSERT_EQ(0, ModesParamsFromOptions(PETSC_COMM_WORLD, &p));
  EXPECT_EQ(4, p.count);

  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-modes_count", "6"));
  EXPECT_EQ(0, ModesParamsFromOptions(PETSC_COMM_WORLD, &p, &sys));
  EXPECT_EQ(6, p.count);

  PetscCallVoid(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-modes_count", "0"));
  EXPECT_EQ(PETSC_ERR_ARG_OUTOFRANGE, ModesParamsFromOptions(PETSC_COMM_WORLD, &p));
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-modes_count", "42")); // 41 free nodes
  EXPECT_EQ(PETSC_ERR_ARG_OUTOFRANGE, ModesParamsFromOptions(PETSC_COMM_WORLD, &p, &sys));
  PetscCallVoid(PetscPopErrorHandler());
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-modes_count"));
}

// Two fields a node (a hand-made system: field 1 an uncoupled copy of the beam with masses
// x3): the modes are those of the one-field beam and those of the copy at omega / sqrt(3),
// counted over free dofs; a mode of the beam has the one-field shape as its deflection, a
// mode of the copy has no deflection.
TEST(BeamModes, TwoFieldSystemHasTheModesOfBothFields)
{
  const BeamSystem one = test::SystemOf(Aluminium(Support::Clamped, Support::Free, 41));
  const BeamSystem two = test::TwoFieldCopies(one, 3.0);
  EXPECT_EQ(2 * BeamFreeDofCount(one), BeamFreeDofCount(two));
  ModesResult                         r1, r2;
  std::vector<std::vector<PetscReal>> s1, s2;
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, one, 6, &r1, &s1));
  ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, two, 6, &r2, &s2));
  std::vector<std::pair<PetscReal, PetscInt>> expect; // omega, one-field mode (-1: the copy's)
  for (PetscInt m = 0; m < 6; ++m) expect.push_back({r1.omega[m], m}), expect.push_back({r1.omega[m] / std::sqrt(3.0), -1});
  std::sort(expect.begin(), expect.end());
  EXPECT_EQ(0, r2.rigid_count);
  for (PetscInt m = 0; m < 6; ++m) {
    EXPECT_NEAR(expect[m].first, r2.omega[m], 1e-10 * expect[m].first) << "mode " << m;
    ASSERT_EQ((size_t)one.nodes, s2[m].size());
    PetscReal dev = 0, amax = 0;
    for (PetscInt i = 0; i < one.nodes; ++i) {
      const PetscReal ref = expect[m].second >= 0 ? s1[expect[m].second][i] : 0.0;
      dev                 = std::max(dev, std::abs(s2[m][i] - ref));
      amax                = std::max(amax, std::abs(ref));
    }
    EXPECT_LT(dev, 1e-7 * std::max(amax, 1.0)) << "mode " << m;
  }
}

// The rigid modes the held dofs allow, for any supports (the count BeamModesCompute checks its
// lowest modes against): free-free 2, a pin or a pivot 1, a clamped end or region 0; and every
// computed set at a moderate N passes that check with exactly that many rigid modes.
TEST(BeamModes, RigidCountFromTheHeldDofs)
{
  struct Case {
    Support  left, right;
    PetscInt rigid;
  };
  for (const Case &c : {Case{Support::Free, Support::Free, 2}, Case{Support::Pinned, Support::Free, 1}, Case{Support::Free, Support::Pinned, 1}, Case{Support::Clamped, Support::Free, 0},
                        Case{Support::Pinned, Support::Pinned, 0}}) {
    const BeamSystem sys = test::SystemOf(Aluminium(c.left, c.right, 41));
    EXPECT_EQ(c.rigid, BeamSystemRigidCount(sys)) << SupportName(c.left) << "-" << SupportName(c.right);
    EXPECT_EQ(BeamModesRigidCount(c.left, c.right), BeamSystemRigidCount(sys));
    ModesResult r;
    ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, 4, &r));
    EXPECT_EQ(c.rigid, r.rigid_count);
  }
  BeamParams pivot = Aluminium(Support::Free, Support::Free, 41);
  pivot.has_pivot  = true;
  pivot.pivot_x    = 0.2;
  EXPECT_EQ(1, BeamSystemRigidCount(test::SystemOf(pivot)));
  BeamParams clamp = Aluminium(Support::Free, Support::Free, 41);
  clamp.has_clamp  = true;
  clamp.clamp_x0   = 0.0;
  clamp.clamp_x1   = 0.1;
  EXPECT_EQ(0, BeamSystemRigidCount(test::SystemOf(clamp)));
}

// The Euler-Bernoulli beam as the system assembles it (system/beam_system.hpp: the theory's
// curvature terms, K from the force operator) against formulas (docs/model.md, section 6):
// symmetry and null space of K, the 5-point stencil EI/h^3 (1,-4,6,-4,1) and the
// ghost-node rows at the ends, fourth differences of polynomials, energies,
// masses, the impact stencil and the -beam_* options reader.
#include "io/beam_options.hpp"
#include "model/beam.hpp"
#include "system/beam_system.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {



BeamParams Aluminium(Support left, Support right, PetscInt nodes, PetscReal length = 1.1)
{
  return test::AluminiumBeam(length, nodes, left, right); // the paper's 6 mm x 32 mm section
}

struct Config {
  const char *name;
  BeamParams  p;
};

// The support configurations the tests run over.
std::vector<Config> Configs(PetscInt nodes)
{
  std::vector<Config> c = {
    {"free-free", Aluminium(Support::Free, Support::Free, nodes)},
    {"clamped-free", Aluminium(Support::Clamped, Support::Free, nodes)},
    {"pinned-free", Aluminium(Support::Pinned, Support::Free, nodes)},
    {"free-clamped", Aluminium(Support::Free, Support::Clamped, nodes)},
    {"clamped-pinned", Aluminium(Support::Clamped, Support::Pinned, nodes)},
    {"free-free, clamped region", Aluminium(Support::Free, Support::Free, nodes)},
  };
  BeamParams &q = c.back().p; // a handle held over the last ~10% of the beam
  q.has_clamp   = true;
  q.clamp_x0    = 0.9 * q.length;
  q.clamp_x1    = q.length;
  return c;
}

// The Euler-Bernoulli system of a beam, and its uniform section's EI (N m^2).
struct Beam {
  BeamSystem sys;
  PetscInt   N;
  PetscReal  h, L, EI, mu;
};
Beam Build(const BeamParams &p)
{
  Beam b{test::SystemOf(p), p.nodes, 0, p.length, p.EI, p.mu};
  b.h = b.sys.h;
  return b;
}

// Dense K (N x N, zero rows and columns at held nodes) from BeamSystemStiffnessRow.
std::vector<PetscReal> DenseK(const Beam &op)
{
  std::vector<PetscReal> K(op.N * op.N, 0.0);
  for (PetscInt i = 0; i < op.N; ++i) {
    PetscInt  cols[5];
    PetscReal vals[5];
    const PetscInt n = BeamSystemStiffnessRow(op.sys, i, cols, vals);
    for (PetscInt q = 0; q < n; ++q) K[i * op.N + cols[q]] = vals[q];
  }
  return K;
}

PetscReal MaxAbs(const std::vector<PetscReal> &a)
{
  PetscReal m = 0;
  for (PetscReal v : a) m = std::max(m, std::abs(v));
  return m;
}


// Eigenvalues (ascending, N/m) of K restricted to the free nodes.
std::vector<PetscReal> FreeEigenvalues(const Beam &op)
{
  const std::vector<PetscReal> K = DenseK(op);
  std::vector<PetscInt>        f;
  for (PetscInt i = 0; i < op.N; ++i)
    if (!op.sys.held[i]) f.push_back(i);
  const PetscInt         n = (PetscInt)f.size();
  std::vector<PetscReal> A(n * n);
  for (PetscInt a = 0; a < n; ++a)
    for (PetscInt b = 0; b < n; ++b) A[a * n + b] = K[f[a] * op.N + f[b]];
  return JacobiEigenvalues(A, n);
}

// The Jacobi routine itself, on a matrix with known eigenvalues: the second
// difference tridiag(-1, 2, -1) of size n has 2 - 2 cos(k pi/(n+1)), k = 1..n.
TEST(EulerBernoulliSystemHelpers, JacobiEigenvalues)
{
  const PetscInt         n = 12;
  std::vector<PetscReal> A(n * n, 0.0);
  for (PetscInt i = 0; i < n; ++i) {
    A[i * n + i] = 2;
    if (i > 0) A[i * n + i - 1] = A[(i - 1) * n + i] = -1;
  }
  const std::vector<PetscReal> w = JacobiEigenvalues(A, n);
  for (PetscInt k = 1; k <= n; ++k) EXPECT_NEAR(2 - 2 * std::cos(k * M_PI / (n + 1)), w[k - 1], 1e-13);
}

std::vector<PetscReal> RandomVector(const Beam &op, unsigned seed)
{
  std::mt19937                              gen(seed);
  std::uniform_real_distribution<PetscReal> u(-1e-3, 1e-3);
  std::vector<PetscReal>                    y(op.N);
  for (PetscInt i = 0; i < op.N; ++i) y[i] = op.sys.held[i] ? 0.0 : u(gen);
  return y;
}

std::vector<PetscReal> Apply(const Beam &op, const std::vector<PetscReal> &y)
{
  std::vector<PetscReal> f(op.N);
  BeamSystemStiffnessApply(op.sys, y.data(), 1, 0, op.N, f.data(), 1);
  return f;
}

// Options set for one scope, cleared after (the options database is global).
class ScopedOptions {
public:
  explicit ScopedOptions(std::vector<std::pair<std::string, std::string>> kv) : kv_(std::move(kv))
  {
    for (auto &o : kv_) EXPECT_EQ(0, PetscOptionsSetValue(NULL, o.first.c_str(), o.second.c_str()));
  }
  ~ScopedOptions()
  {
    for (auto &o : kv_) EXPECT_EQ(0, PetscOptionsClearValue(NULL, o.first.c_str()));
  }

private:
  std::vector<std::pair<std::string, std::string>> kv_;
};

// BeamParamsFromOptions with PETSc's error printing silenced: returns its error code.
PetscErrorCode ReadQuietly(BeamParams *p)
{
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  const PetscErrorCode ierr = BeamParamsFromOptions(PETSC_COMM_WORLD, p);
  PetscCall(PetscPopErrorHandler());
  return ierr;
}

} // namespace

TEST(EulerBernoulliSystem, StiffnessIsSymmetric)
{
  for (const Config &c : Configs(41)) {
    const Beam                   op = Build(c.p);
    const std::vector<PetscReal> K  = DenseK(op);
    const PetscReal              kmax = MaxAbs(K);
    ASSERT_GT(kmax, 0.0);
    for (PetscInt i = 0; i < op.N; ++i)
      for (PetscInt j = 0; j < i; ++j) ASSERT_NEAR(K[i * op.N + j], K[j * op.N + i], 1e-14 * kmax) << c.name << " K(" << i << "," << j << ")";
  }
}

TEST(EulerBernoulliSystem, HeldNodes)
{
  const PetscInt N = 41;
  for (const Config &c : Configs(N)) {
    const Beam op = Build(c.p);
    EXPECT_EQ(c.p.left != Support::Free, (bool)op.sys.held[0]) << c.name;
    if (!c.p.has_clamp) {
      EXPECT_EQ(c.p.right != Support::Free, (bool)op.sys.held[N - 1]) << c.name;
    }
    for (PetscInt i = 1; i < N - 1; ++i) {
      const PetscReal x    = i * op.h;
      const bool      held = c.p.has_clamp && x >= c.p.clamp_x0 - 1e-12 && x <= c.p.clamp_x1 + 1e-12;
      EXPECT_EQ(held, (bool)op.sys.held[i]) << c.name << " node " << i;
      PetscInt  cols[5];
      PetscReal vals[5];
      if (held) {
        EXPECT_EQ(0, BeamSystemStiffnessRow(op.sys, i, cols, vals));
      }
    }
  }
}

// Free-free: K 1 = K x = 0 (rigid translation and rotation), the null space is
// exactly these two, and the forces K y carry no net force or moment.
TEST(EulerBernoulliSystem, FreeFreeNullSpaceIsRigidMotion)
{
  const Beam                   op   = Build(Aluminium(Support::Free, Support::Free, 41));
  const std::vector<PetscReal> K    = DenseK(op);
  const PetscReal              kmax = MaxAbs(K);
  std::vector<PetscReal>       one(op.N, 1.0), x(op.N);
  for (PetscInt i = 0; i < op.N; ++i) x[i] = i * op.h;
  for (PetscInt i = 0; i < op.N; ++i) {
    PetscReal k1 = 0, kx = 0;
    for (PetscInt j = 0; j < op.N; ++j) {
      k1 += K[i * op.N + j] * one[j];
      kx += K[i * op.N + j] * x[j];
    }
    EXPECT_NEAR(0.0, k1, 1e-13 * kmax) << "row " << i;
    EXPECT_NEAR(0.0, kx, 1e-13 * kmax * op.L) << "row " << i;
  }
  const std::vector<PetscReal> f1 = Apply(op, one), fx = Apply(op, x);
  EXPECT_LT(MaxAbs(f1), 1e-13 * kmax);
  EXPECT_LT(MaxAbs(fx), 1e-13 * kmax * op.L);

  const std::vector<PetscReal> w = FreeEigenvalues(op);
  const PetscReal              wmax = w.back();
  PetscInt                     nzero = 0;
  for (PetscReal v : w) {
    EXPECT_GT(v, -1e-12 * wmax); // positive semi-definite
    nzero += std::abs(v) < 1e-10 * wmax;
  }
  EXPECT_EQ(2, nzero);
  EXPECT_GT(w[2], 1e-7 * wmax); // the first flexural eigenvalue is far from 0

  for (unsigned seed = 1; seed <= 5; ++seed) {
    const std::vector<PetscReal> y = RandomVector(op, seed);
    const std::vector<PetscReal> f = Apply(op, y);
    PetscReal                    force = 0, moment = 0, fabs = 0;
    for (PetscInt i = 0; i < op.N; ++i) {
      force += f[i];
      moment += i * op.h * f[i];
      fabs += std::abs(f[i]);
    }
    EXPECT_NEAR(0.0, force, 1e-13 * fabs) << "net force, seed " << seed;
    EXPECT_NEAR(0.0, moment, 1e-13 * fabs * op.L) << "net moment, seed " << seed;
  }
}

// Interior rows are EI/h^3 (1, -4, 6, -4, 1); the end rows are the ghost-node
// stencils of the supports: free  y'' = y''' = 0:  (1, -2, 1), (-2, 5, -4, 1);
// clamped y_-1 = y_1: (7, -4, 1); pinned y_-1 = -y_1: (5, -4, 1).
TEST(EulerBernoulliSystem, StencilRows)
{
  struct Expect {
    Support                l;
    PetscInt               row, first_col;
    std::vector<PetscReal> v;
  };
  const Expect ends[] = {
    {Support::Free, 0, 0, {1, -2, 1}},
    {Support::Free, 1, 0, {-2, 5, -4, 1}},
    {Support::Clamped, 1, 1, {7, -4, 1}},
    {Support::Clamped, 2, 1, {-4, 6, -4, 1}},
    {Support::Pinned, 1, 1, {5, -4, 1}},
  };
  for (const Expect &e : ends) {
    const Beam op = Build(Aluminium(e.l, Support::Free, 21));
    const PetscReal    c  = op.EI / (op.h * op.h * op.h);
    PetscInt           cols[5];
    PetscReal          vals[5];
    const PetscInt     n = BeamSystemStiffnessRow(op.sys, e.row, cols, vals);
    ASSERT_EQ((PetscInt)e.v.size(), n) << SupportName(e.l) << " row " << e.row;
    for (PetscInt q = 0; q < n; ++q) {
      EXPECT_EQ(e.first_col + q, cols[q]);
      EXPECT_NEAR(e.v[q] * c, vals[q], 1e-12 * c) << SupportName(e.l) << " row " << e.row << " col " << cols[q];
    }
  }
  for (const Config &cfg : Configs(21)) {
    const Beam op = Build(cfg.p);
    const PetscReal    c  = op.EI / (op.h * op.h * op.h);
    const PetscReal    s[5] = {1, -4, 6, -4, 1};
    for (PetscInt i = 2; i < op.N - 2; ++i) {
      bool interior = true;
      for (PetscInt j = i - 2; j <= i + 2; ++j) interior = interior && !op.sys.held[j];
      if (!interior) continue;
      PetscInt  cols[5];
      PetscReal vals[5];
      ASSERT_EQ(5, BeamSystemStiffnessRow(op.sys, i, cols, vals)) << cfg.name << " row " << i;
      for (PetscInt q = 0; q < 5; ++q) {
        EXPECT_EQ(i - 2 + q, cols[q]);
        EXPECT_NEAR(s[q] * c, vals[q], 1e-12 * c) << cfg.name << " row " << i;
      }
    }
  }
}

// The factored action (BeamSystemStiffnessApply) agrees with the assembled rows, also over sub-ranges (one
// rank's part) with a strided array.
TEST(EulerBernoulliSystem, ApplyMatchesRows)
{
  for (const Config &c : Configs(33)) {
    const Beam                   op = Build(c.p);
    const std::vector<PetscReal> K  = DenseK(op), y = RandomVector(op, 7);
    const PetscReal              kmax = MaxAbs(K) * MaxAbs(y);
    std::vector<PetscReal>       ys(2 * op.N), f(2 * op.N, -1.0);
    for (PetscInt i = 0; i < op.N; ++i) ys[2 * i] = y[i];
    const PetscInt splits[] = {0, 1, 5, 16, 31, op.N};
    for (int s = 0; s + 1 < 6; ++s) BeamSystemStiffnessApply(op.sys, ys.data(), 2, splits[s], splits[s + 1], f.data(), 2);
    for (PetscInt i = 0; i < op.N; ++i) {
      PetscReal ky = 0;
      for (PetscInt j = 0; j < op.N; ++j) ky += K[i * op.N + j] * y[j];
      EXPECT_NEAR(ky, f[2 * i], 1e-13 * kmax) << c.name << " node " << i;
      if (op.sys.held[i]) {
        EXPECT_EQ(0.0, f[2 * i]);
      }
    }
  }
}

// Fourth difference of polynomials on a free-free beam: x^2 and x^3 give 0 in the
// interior, x^4 gives EI/h^3 * 24 h^4 = 24 EI h ((K y)_i approximates EI y'''' h).
TEST(EulerBernoulliSystem, FourthDifferenceOfPolynomials)
{
  const Beam op = Build(Aluminium(Support::Free, Support::Free, 21));
  const PetscReal    ref = 24 * op.EI * op.h;
  for (int p = 0; p <= 4; ++p) {
    std::vector<PetscReal> y(op.N);
    for (PetscInt i = 0; i < op.N; ++i) y[i] = std::pow(i * op.h, p);
    const std::vector<PetscReal> f = Apply(op, y);
    for (PetscInt i = 2; i < op.N - 2; ++i) EXPECT_NEAR(p == 4 ? ref : 0.0, f[i], 1e-8 * ref) << "x^" << p << " node " << i;
  }
  // Near a free end, x^2 (constant curvature 2) gives the end forces of the
  // moment jump: (K y)_0 = 2 EI/h, (K y)_1 = -2 EI/h, (K y)_i = 0 beyond.
  std::vector<PetscReal> y(op.N);
  for (PetscInt i = 0; i < op.N; ++i) y[i] = std::pow(i * op.h, 2);
  const std::vector<PetscReal> f = Apply(op, y);
  EXPECT_NEAR(2 * op.EI / op.h, f[0], 1e-9 * op.EI / op.h);
  EXPECT_NEAR(-2 * op.EI / op.h, f[1], 1e-9 * op.EI / op.h);
}

// U = 1/2 y^T K y (every support), U splits over curvature ranges, and the
// curvature energy of y = x^2 is (EI h / 2) * 4 per interior node.
TEST(EulerBernoulliSystem, StrainEnergyIsHalfYKY)
{
  for (const Config &c : Configs(41)) {
    const Beam                   op = Build(c.p);
    const std::vector<PetscReal> K  = DenseK(op);
    for (unsigned seed = 11; seed <= 13; ++seed) {
      const std::vector<PetscReal> y = RandomVector(op, seed);
      PetscReal                    yKy = 0;
      for (PetscInt i = 0; i < op.N; ++i)
        for (PetscInt j = 0; j < op.N; ++j) yKy += y[i] * K[i * op.N + j] * y[j];
      const PetscReal U = BeamSystemStrainEnergy(op.sys, y.data(), 1, 0, op.N);
      EXPECT_NEAR(0.5 * yKy, U, 1e-12 * U) << c.name;
      EXPECT_GT(U, 0.0);
      const PetscReal Usplit = BeamSystemStrainEnergy(op.sys, y.data(), 1, 0, 17) + BeamSystemStrainEnergy(op.sys, y.data(), 1, 17, op.N);
      EXPECT_NEAR(U, Usplit, 1e-14 * U) << c.name;
    }
  }
  const Beam             op = Build(Aluminium(Support::Free, Support::Free, 41));
  std::vector<PetscReal> y(op.N);
  for (PetscInt i = 0; i < op.N; ++i) y[i] = std::pow(i * op.h, 2);
  EXPECT_NEAR(2 * op.EI * op.h * (op.N - 2), BeamSystemStrainEnergy(op.sys, y.data(), 1, 0, op.N), 1e-10 * op.EI * op.L);
}

// Lumped mass: mu h, half at the ends, total mu L; T = 1/2 sum m v^2 for a
// translation (1/2 mu L v^2) and a rotation v = x (trapezoid rule of mu x^2).
TEST(EulerBernoulliSystem, MassAndKineticEnergy)
{
  for (const Config &c : Configs(41)) {
    const Beam op = Build(c.p);
    PetscReal          M  = 0;
    for (PetscReal m : op.sys.mass) M += m;
    EXPECT_NEAR(c.p.mu * c.p.length, M, 1e-13 * M) << c.name;
    EXPECT_NEAR(0.5 * c.p.mu * op.h, op.sys.mass[0], 1e-15);
    EXPECT_NEAR(0.5 * c.p.mu * op.h, op.sys.mass[op.N - 1], 1e-15);
    EXPECT_NEAR(c.p.mu * op.h, op.sys.mass[op.N / 2], 1e-15);
  }
  const Beam             op = Build(Aluminium(Support::Free, Support::Free, 41));
  const PetscReal        v0 = 2.5, L = op.L, h = op.h;
  std::vector<PetscReal> v(2 * op.N, v0), x(op.N);
  EXPECT_NEAR(0.5 * op.mu * L * v0 * v0, BeamSystemKineticEnergy(op.sys, v.data(), 2, 0, op.N), 1e-13);
  for (PetscInt i = 0; i < op.N; ++i) x[i] = i * h;
  const PetscReal T = BeamSystemKineticEnergy(op.sys, x.data(), 1, 0, 20) + BeamSystemKineticEnergy(op.sys, x.data(), 1, 20, op.N);
  EXPECT_NEAR(0.5 * op.mu * (L * L * L / 3 + h * h * L / 6), T, 1e-13);
}

// A clamped end makes K positive definite on the free nodes; a pin at one end
// of an otherwise free beam leaves one zero eigenvalue (rotation about the pin).
TEST(EulerBernoulliSystem, SupportsRemoveRigidModes)
{
  struct Case {
    Support  l, r;
    bool     clamp;
    PetscInt zeros;
  };
  const Case cases[] = {
    {Support::Clamped, Support::Free, false, 0}, {Support::Free, Support::Clamped, false, 0}, {Support::Clamped, Support::Clamped, false, 0},
    {Support::Pinned, Support::Free, false, 1},  {Support::Pinned, Support::Pinned, false, 0}, {Support::Free, Support::Free, true, 0},
  };
  for (const Case &cs : cases) {
    BeamParams p = Aluminium(cs.l, cs.r, 41);
    if (cs.clamp) {
      p.has_clamp = true;
      p.clamp_x0  = 0.62;
      p.clamp_x1  = 0.72;
    }
    const Beam op = Build(p);
    if (cs.l == Support::Clamped) {
      EXPECT_TRUE(op.sys.held[0]);
      EXPECT_FALSE(op.sys.held[1]);
    }
    const std::vector<PetscReal> w = FreeEigenvalues(op);
    PetscInt                     nzero = 0;
    for (PetscReal v : w) nzero += std::abs(v) < 1e-10 * w.back();
    EXPECT_EQ(cs.zeros, nzero) << SupportName(cs.l) << "-" << SupportName(cs.r) << (cs.clamp ? " with clamp" : "");
    EXPECT_GT(w[cs.zeros], 1e-8 * w.back());
  }
}

TEST(EulerBernoulliSystem, ImpactStencil)
{
  const Beam op = Build(Aluminium(Support::Free, Support::Free, 41));
  ImpactStencil      s  = GridImpactStencil(op.N, op.L, 7 * op.h); // on a node
  EXPECT_EQ(7, s.j);
  EXPECT_NEAR(1.0, s.w, 1e-12);
  s = GridImpactStencil(op.N, op.L, (12 + 0.3) * op.h); // between nodes 12 and 13
  EXPECT_EQ(12, s.j);
  EXPECT_NEAR(0.7, s.w, 1e-12);
  s = GridImpactStencil(op.N, op.L, 0.0);
  EXPECT_EQ(0, s.j);
  EXPECT_NEAR(1.0, s.w, 1e-12);
  s = GridImpactStencil(op.N, op.L, op.L); // all weight on the last node
  EXPECT_EQ(op.N - 2, s.j);
  EXPECT_NEAR(0.0, s.w, 1e-12);
  // The hat functions reproduce a linear field exactly: w x_j + (1-w) x_{j+1} = x_imp.
  for (PetscReal x : {0.0, 0.013, 0.55, 0.9, 1.0999, 1.1}) {
    s = GridImpactStencil(op.N, op.L, x);
    ASSERT_GE(s.j, 0);
    ASSERT_LT(s.j, op.N - 1);
    EXPECT_GE(s.w, 0.0);
    EXPECT_LE(s.w, 1.0);
    EXPECT_NEAR(x, s.w * s.j * op.h + (1 - s.w) * (s.j + 1) * op.h, 1e-12) << "x_imp = " << x;
  }
}

TEST(BeamParamsOptions, DefaultsAreThePapersAluminiumBeam)
{
  BeamParams p;
  ASSERT_EQ(0, BeamParamsFromOptions(PETSC_COMM_WORLD, &p));
  EXPECT_NEAR(2700 * 0.006 * 0.032, p.mu, 1e-12);
  EXPECT_NEAR(7e10 * 0.032 * 0.006 * 0.006 * 0.006 / 12, p.EI, 1e-9);
  EXPECT_NEAR(1.1, p.length, 1e-15);
  EXPECT_EQ(41, p.nodes);
  EXPECT_EQ(Support::Free, p.left);
  EXPECT_EQ(Support::Free, p.right);
  EXPECT_FALSE(p.has_clamp);
  EXPECT_EQ("E,rho,a,b", p.input.parameter_set);
}

// The tennis racket's parameter set: mu = M/L, EI = (E/rho) mu a^2 / 12.
TEST(BeamParamsOptions, MassLengthThicknessSet)
{
  ScopedOptions o({{"-beam_mass", "0.32"}, {"-beam_length", "0.72"}, {"-beam_thickness", "0.02"}, {"-beam_youngs_over_density", "1e7"},
                   {"-beam_left", "free"}, {"-beam_right", "pinned"}, {"-beam_clamp", "0.62,0.72"}, {"-beam_nodes", "73"}});
  BeamParams    p;
  ASSERT_EQ(0, BeamParamsFromOptions(PETSC_COMM_WORLD, &p));
  const PetscReal mu = 0.32 / 0.72;
  EXPECT_NEAR(mu, p.mu, 1e-14);
  EXPECT_NEAR(1e7 * mu * 0.02 * 0.02 / 12, p.EI, 1e-12);
  EXPECT_NEAR(0.72, p.length, 1e-15);
  EXPECT_EQ(73, p.nodes);
  EXPECT_EQ(Support::Pinned, p.right);
  EXPECT_TRUE(p.has_clamp);
  EXPECT_NEAR(0.62, p.clamp_x0, 1e-15);
  EXPECT_NEAR(0.72, p.clamp_x1, 1e-15);
  EXPECT_EQ("M,L,a,E/rho", p.input.parameter_set);
}

TEST(BeamParamsOptions, EIMuSet)
{
  ScopedOptions o({{"-beam_EI", "12.5"}, {"-beam_mu", "0.75"}});
  BeamParams    p;
  ASSERT_EQ(0, BeamParamsFromOptions(PETSC_COMM_WORLD, &p));
  EXPECT_EQ(12.5, p.EI);
  EXPECT_EQ(0.75, p.mu);
}

TEST(BeamParamsOptions, BadInputIsRefused)
{
  const std::vector<std::vector<std::pair<std::string, std::string>>> bad = {
    {{"-beam_density", "2700"}, {"-beam_EI", "40"}, {"-beam_mu", "0.5"}}, // contradicting sets
    {{"-beam_EI", "40"}},                                                 // half a set
    {{"-beam_mass", "0.32"}, {"-beam_youngs_modulus", "7e10"}, {"-beam_youngs_over_density", "1e7"}},
    {{"-beam_nodes", "3"}},
    {{"-beam_length", "-1"}},
    {{"-beam_thickness", "0"}},
    {{"-beam_clamp", "0.9,0.5"}},
    {{"-beam_clamp", "0,1.1"}}, // holds every node
  };
  for (const auto &set : bad) {
    ScopedOptions o(set);
    BeamParams    p;
    EXPECT_NE(0, ReadQuietly(&p)) << set.front().first << " " << set.front().second;
  }
  BeamParams p; // the database is clean again
  EXPECT_EQ(0, ReadQuietly(&p));
}

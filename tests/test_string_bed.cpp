// The string bed in a held frame (model/string_bed, system/string_bed_operator,
// solvers/string_bed_modes) against the membrane's analytic results and the independent
// reference scripts/references/membrane.py (its numbers quoted with their line of
// scripts/references/README.md): the rectangle's f_mn with unequal tensions at order 2, the
// circle's Bessel modes and the ellipse's Mathieu fundamental at order ~2 (the cut arms'
// distances; the staircase would be order 1), the static deflection under a central patch, and
// the same frequencies on 1 and 4 ranks.
//
//   mpiexec -n 4 ./test_string_bed --gtest_filter='StringBedParallel.*'
#include "model/string_bed.hpp"
#include "solvers/string_bed_modes.hpp"
#include "system/string_bed_operator.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace beamimpact;

namespace {

// A bed of tension per length N_x, N_z and areal mass sigma = 0.2 kg/m^2 (membrane.py's), from
// strings 1 cm apart: T = N s, lambda = sigma s / 2.
StringBedParams Bed(HeadShape shape, PetscReal length, PetscReal width, PetscReal Nx, PetscReal Nz, PetscInt nodes)
{
  StringBedParams p;
  p.shape           = shape;
  p.head_length     = length;
  p.head_width      = width;
  p.spacing         = 0.01;
  p.spacing_crosses = 0.01;
  p.tension         = Nx * p.spacing;
  p.tension_crosses = Nz * p.spacing_crosses;
  p.linear_density  = 0.2 * 0.01 / 2;
  p.nodes           = nodes;
  p.frame           = "held";
  return p;
}

std::vector<PetscReal> Frequencies(MPI_Comm comm, const StringBedParams &p, PetscInt count)
{
  StringBedModes m;
  EXPECT_EQ(0, StringBedModesCompute(comm, StringBedGrid(p), StringBedMembrane(p), count, &m));
  return m.frequency;
}

} // namespace

TEST(StringBedModel, WovenBedFormulas)
{
  StringBedParams p;
  p.tension = 240, p.tension_crosses = 200, p.spacing = 0.015, p.spacing_crosses = 0.02, p.linear_density = 1.5e-3;
  const Membrane m = StringBedMembrane(p);
  EXPECT_DOUBLE_EQ(m.N_x, 240 / 0.015);
  EXPECT_DOUBLE_EQ(m.N_z, 200 / 0.02);
  EXPECT_DOUBLE_EQ(m.sigma, 1.5e-3 / 0.015 + 1.5e-3 / 0.02);
  p.nodes = 61, p.head_length = 0.34, p.head_width = 0.24;
  const BedGrid g = StringBedGrid(p); // h_z ~ h_x from the aspect
  EXPECT_EQ(g.nz, 43);
  EXPECT_NEAR(g.hz / g.hx, 1.0, 0.01);
}

// The stiffness is symmetric, its rows sum to zero inside and are positive at the edge, and a cut arm's distance
// is the exact one to the ellipse.
TEST(StringBedModel, SymmetricRowsAndEdgeDistances)
{
  const StringBedParams p = Bed(HeadShape::Ellipse, 0.34, 0.25, 17500, 15300, 41);
  const BedGrid         g = StringBedGrid(p);
  const Membrane        m = StringBedMembrane(p);
  const PetscInt        di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1}, back[4] = {1, 0, 3, 2};
  PetscInt              cut = 0;
  for (PetscInt j = 0; j < g.nz; ++j)
    for (PetscInt i = 0; i < g.nx; ++i) {
      const BedRow r = BedStiffnessRow(g, m, i, j);
      if (r.held) continue;
      PetscReal sum = 0;
      for (int d = 0; d < 4; ++d) {
        sum += r.off[d];
        if (r.off[d] == 0) {
          ++cut;
          continue;
        }
        const BedRow q = BedStiffnessRow(g, m, i + di[d], j + dj[d]);
        ASSERT_FALSE(q.held);
        EXPECT_EQ(r.off[d], q.off[back[d]]) << "node " << i << "," << j;
      }
      // the row sums to zero away from the outline (w = const is free of strain there) and is
      // positive where an arm is cut (the edge a spring to ground, N h / l with l <= h)
      bool any_cut = false;
      for (int d = 0; d < 4; ++d) any_cut = any_cut || r.off[d] == 0;
      if (any_cut) EXPECT_GT(r.diag + sum, 0.5 * std::min(m.N_x * g.hz / g.hx, m.N_z * g.hx / g.hz)) << "node " << i << "," << j;
      else EXPECT_NEAR(r.diag + sum, 0, 1e-12 * r.diag) << "node " << i << "," << j;
    }
  EXPECT_GT(cut, 0);
  // the edge along x at z = 0.1: x_e = 0.17 sqrt(1 - 0.64) = 0.102
  EXPECT_NEAR(BedEdgeDistance(g, 0.05, 0.1, 0), 0.102 - 0.05, 1e-12);
  EXPECT_NEAR(BedEdgeDistance(g, 0.05, 0.1, 3), 0.1 + 0.125 * std::sqrt(1 - std::pow(0.05 / 0.17, 2)), 1e-12);
}

// Rectangle 0.30 x 0.20 m, N_x 18000, N_z 14000 N/m: the six lowest f_mn (membrane.py, README
// "rectangle 0.30 x 0.20 m ... 829.1562, 1198.9579, 1414.2136, 1639.3596, 1658.3124, 2000.0000 Hz"),
// at h = 1 cm and 5 mm: the error falls by 4.
TEST(StringBedModes, RectangleUnequalTensionsOrderTwo)
{
  const PetscReal exact[6] = {829.1562, 1198.9579, 1414.2136, 1639.3596, 1658.3124, 2000.0000};
  const Membrane  m        = StringBedMembrane(Bed(HeadShape::Rectangle, 0.30, 0.20, 18000, 14000, 31));
  for (int q = 0; q < 6; ++q) { // the formula against the reference's table
    std::vector<PetscReal> f;
    for (PetscInt i = 1; i <= 6; ++i)
      for (PetscInt k = 1; k <= 6; ++k) f.push_back(MembraneRectangleFrequency(m, 0.30, 0.20, i, k));
    std::sort(f.begin(), f.end());
    EXPECT_NEAR(f[q], exact[q], 1e-4);
  }
  const std::vector<PetscReal> coarse = Frequencies(PETSC_COMM_WORLD, Bed(HeadShape::Rectangle, 0.30, 0.20, 18000, 14000, 31), 6);
  const std::vector<PetscReal> fine   = Frequencies(PETSC_COMM_WORLD, Bed(HeadShape::Rectangle, 0.30, 0.20, 18000, 14000, 61), 6);
  for (int q = 0; q < 6; ++q) {
    const PetscReal e1 = std::abs(coarse[q] / exact[q] - 1), e2 = std::abs(fine[q] / exact[q] - 1);
    EXPECT_LT(e2, 3e-3) << "mode " << q + 1;
    EXPECT_NEAR(e1 / e2, 4.0, 0.3) << "mode " << q + 1 << ": " << coarse[q] << ", " << fine[q] << " Hz against " << exact[q];
  }
}

// The observed order between grids of n and 2n - 1 nodes, for each frequency against its exact value.
static std::vector<PetscReal> Orders(const std::vector<PetscReal> &exact, const std::vector<PetscReal> &coarse, const std::vector<PetscReal> &fine)
{
  std::vector<PetscReal> p;
  for (size_t q = 0; q < exact.size(); ++q) p.push_back(std::log2(std::abs(coarse[q] / exact[q] - 1) / std::abs(fine[q] / exact[q] - 1)));
  return p;
}

// Circle R = 0.15 m, N = 16000 N/m: f_01 = 2.404826 / (2 pi R) sqrt(N/sigma) = 721.7012 Hz and
// f_11 = 3.831706 / (2 pi R) sqrt(N/sigma) = 1149.9158 Hz (a pair; README "circle R = 0.15 m").
TEST(StringBedModes, CircleBesselOrderTwo)
{
  const Membrane m = StringBedMembrane(Bed(HeadShape::Ellipse, 0.30, 0.30, 16000, 16000, 41));
  EXPECT_NEAR(MembraneCircleFrequency(m, 0.15, 2.404825557695773), 721.7012, 1e-4);
  EXPECT_NEAR(MembraneCircleFrequency(m, 0.15, 3.831705970207512), 1149.9158, 1e-4);
  const std::vector<PetscReal> exact  = {721.7012, 1149.9158, 1149.9158};
  const std::vector<PetscReal> coarse = Frequencies(PETSC_COMM_WORLD, Bed(HeadShape::Ellipse, 0.30, 0.30, 16000, 16000, 41), 3);
  const std::vector<PetscReal> fine   = Frequencies(PETSC_COMM_WORLD, Bed(HeadShape::Ellipse, 0.30, 0.30, 16000, 16000, 81), 3);
  const std::vector<PetscReal> order  = Orders(exact, coarse, fine);
  for (size_t q = 0; q < exact.size(); ++q) {
    EXPECT_LT(std::abs(fine[q] / exact[q] - 1), 2e-3) << "mode " << q + 1 << ": " << fine[q];
    EXPECT_GT(order[q], 1.6) << "mode " << q + 1 << ": " << coarse[q] << ", " << fine[q] << " Hz against " << exact[q];
  }
}

// Ellipse 0.34 x 0.25 m (semi-axes 0.170, 0.125), N_x 17500, N_z 15300 N/m: the fundamental
// 761.2215 Hz from the radial Mathieu function (README "the same ellipse, N_x = 17500,
// N_z = 15300 (mapped to equal tension on axes a/sqrt(N_x), b/sqrt(N_z)) | 761.2215 Hz"), and
// with equal tensions N = 16000: 759.1312 Hz ("ellipse 0.170 x 0.125 m, Mathieu").
TEST(StringBedModes, EllipseMathieuOrderTwo)
{
  const struct {
    PetscReal Nx, Nz, f;
  } cases[] = {{17500, 15300, 761.2215}, {16000, 16000, 759.1312}};
  for (const auto &c : cases) {
    const std::vector<PetscReal> coarse = Frequencies(PETSC_COMM_WORLD, Bed(HeadShape::Ellipse, 0.34, 0.25, c.Nx, c.Nz, 41), 1);
    const std::vector<PetscReal> fine   = Frequencies(PETSC_COMM_WORLD, Bed(HeadShape::Ellipse, 0.34, 0.25, c.Nx, c.Nz, 81), 1);
    const PetscReal              order  = Orders({c.f}, coarse, fine)[0];
    EXPECT_LT(std::abs(fine[0] / c.f - 1), 2e-3) << fine[0] << " Hz against " << c.f;
    EXPECT_GT(order, 1.6) << coarse[0] << ", " << fine[0] << " Hz against " << c.f;
  }
}

// A uniform pressure of total force F on the central disc of radius c of a circular bed of radius
// R: centre deflection F / (2 pi N) (ln(R/c) + 1/2) (README: "uniform pressure: centre
// 2 pi N/(ln(R/c) + 1/2)", 39974 N/m at c = 2 cm), at the shipped grid (61 nodes).
TEST(StringBedStatic, PatchCentreDeflection)
{
  const PetscReal       N = 16000, R = 0.15, c = 0.02, F = 100;
  const StringBedParams p = Bed(HeadShape::Ellipse, 2 * R, 2 * R, N, N, 61);
  const BedGrid         g = StringBedGrid(p);
  std::vector<PetscReal> f(g.nx * g.nz, 0.0), w;
  PetscInt               in = 0;
  for (PetscInt pass = 0; pass < 2; ++pass)
    for (PetscInt j = 0; j < g.nz; ++j)
      for (PetscInt i = 0; i < g.nx; ++i)
        if (std::hypot(g.X(i), g.Z(j)) < c) {
          if (pass == 0) ++in;
          else f[j * g.nx + i] = F / in; // the patch's nodes share F
        }
  ASSERT_EQ(0, StringBedStaticSolve(PETSC_COMM_WORLD, g, StringBedMembrane(p), f, &w));
  const PetscReal w0 = w[(g.nz / 2) * g.nx + g.nx / 2], exact = MembranePatchCentreDeflection(N, R, c, F);
  EXPECT_NEAR(F / exact, 39974, 1.0); // the stiffness of the formula
  EXPECT_NEAR(w0 / exact, 1.0, 0.03) << "centre deflection " << w0 << " m against " << exact;
  printf("patch: %d nodes, centre deflection %.6e m, formula %.6e m, ratio %.5f\n", (int)in, (double)w0, (double)exact, (double)(w0 / exact));
}

// The same bed on every rank of the world (4 in the np4 run) and on one rank alone: the same
// frequencies to 1e-10.
TEST(StringBedParallel, SameFrequenciesOnOneAndManyRanks)
{
  const StringBedParams        p     = Bed(HeadShape::Ellipse, 0.34, 0.25, 17500, 15300, 41);
  const std::vector<PetscReal> all   = Frequencies(PETSC_COMM_WORLD, p, 6);
  const std::vector<PetscReal> alone = Frequencies(PETSC_COMM_SELF, p, 6);
  ASSERT_EQ(all.size(), alone.size());
  for (size_t q = 0; q < all.size(); ++q) EXPECT_NEAR(all[q] / alone[q], 1.0, 1e-10) << "mode " << q + 1;
}

// The semi-discrete system (system/beam_system.hpp) against the Euler-Bernoulli kernel of
// model/beam.hpp (assembled there row by row from the curvature derivatives, independently of
// the strain terms) and against its own invariants: the factored action B^T W B y equals the
// band, U = y^T K y / 2, rigid motions of a free beam are in the null space to round-off, and
// an unknown theory is refused by name.
#include "model/beam.hpp"
#include "system/beam_system.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

std::vector<BeamParams> Configurations()
{
  std::vector<BeamParams> c;
  c.push_back(AluminiumBeam(1.1, 41));
  c.push_back(AluminiumBeam(0.3, 23, Support::Clamped, Support::Free));
  c.push_back(AluminiumBeam(0.72, 37, Support::Free, Support::Pinned));
  BeamParams r = AluminiumBeam(1.1, 57);
  r.has_clamp  = true;
  r.clamp_x0   = 0.9;
  r.clamp_x1   = 1.1;
  c.push_back(r);
  return c;
}

} // namespace

TEST(System, StiffnessEqualsTheEulerBernoulliRows)
{
  for (const BeamParams &p : Configurations()) {
    const BeamOperator op  = BeamOperatorBuild(p);
    const BeamSystem   sys = SystemOf(p);
    ASSERT_EQ(sys.ndof, op.N);
    EXPECT_EQ(sys.bw, 2);
    const PetscReal scale = op.EI / std::pow(op.h, 3);
    for (PetscInt i = 0; i < op.N; ++i) {
      PetscInt  c1[5], c2[5];
      PetscReal v1[5], v2[5];
      const PetscInt n1 = BeamStiffnessRow(op, i, c1, v1), n2 = BeamSystemStiffnessRow(sys, i, c2, v2);
      ASSERT_EQ(n1, n2) << "row " << i;
      for (PetscInt q = 0; q < n1; ++q) {
        EXPECT_EQ(c1[q], c2[q]);
        EXPECT_NEAR(v1[q], v2[q], 1e-13 * scale);
      }
      EXPECT_EQ(op.mass[i], sys.mass[i]);
      EXPECT_EQ(op.held[i], sys.held[i]);
    }
  }
}

TEST(System, FactoredActionEqualsBandAndEnergy)
{
  std::mt19937                     gen(7);
  std::uniform_real_distribution<> u(-1e-3, 1e-3);
  for (const BeamParams &p : Configurations()) {
    const BeamSystem       sys = SystemOf(p);
    std::vector<PetscReal> y(sys.ndof), f(sys.ndof), g(sys.ndof, 0.0);
    for (PetscInt i = 0; i < sys.ndof; ++i) y[i] = sys.held[i] ? 0.0 : u(gen);
    // In pieces, as ranks would evaluate it.
    const PetscInt cut = sys.ndof / 3;
    BeamSystemStiffnessApply(sys, y.data(), 1, 0, cut, f.data(), 1);
    BeamSystemStiffnessApply(sys, y.data(), 1, cut, sys.ndof, f.data(), 1);
    PetscReal kmax = 0, yKy = 0;
    for (PetscInt i = 0; i < sys.ndof; ++i) {
      std::vector<PetscInt>  c(2 * sys.bw + 1);
      std::vector<PetscReal> v(2 * sys.bw + 1);
      const PetscInt         n = BeamSystemStiffnessRow(sys, i, c.data(), v.data());
      for (PetscInt q = 0; q < n; ++q) {
        g[i] += v[q] * y[c[q]];
        kmax = std::max(kmax, std::abs(v[q]));
      }
      yKy += y[i] * g[i];
    }
    for (PetscInt i = 0; i < sys.ndof; ++i) EXPECT_NEAR(f[i], g[i], 1e-12 * kmax * 1e-3) << "dof " << i;
    const PetscReal U = BeamSystemStrainEnergy(sys, y.data(), 1, 0, cut) + BeamSystemStrainEnergy(sys, y.data(), 1, cut, sys.ndof);
    EXPECT_NEAR(U, 0.5 * yKy, 1e-12 * std::abs(U));
  }
}

// Momentum of a free beam is conserved to round-off only if the elastic forces of any
// deflection sum to zero with no moment, to round-off relative to the forces themselves
// (not to |K| |y|): a smooth bend on top of a large rigid motion.
TEST(System, ElasticForcesHaveNoResultant)
{
  const BeamSystem       sys = SystemOf(AluminiumBeam(1.1, 161));
  std::vector<PetscReal> y(sys.ndof), f(sys.ndof);
  for (PetscInt i = 0; i < sys.ndof; ++i) y[i] = 1e-2 + 2e-2 * sys.NodeX(i) + 1e-5 * std::sin(M_PI * sys.NodeX(i) / sys.L);
  BeamSystemStiffnessApply(sys, y.data(), 1, 0, sys.ndof, f.data(), 1);
  PetscReal F = 0, Mx = 0, fabs = 0;
  for (PetscInt i = 0; i < sys.ndof; ++i) {
    F += f[i];
    Mx += sys.NodeX(i) * f[i];
    fabs += std::abs(f[i]);
  }
  EXPECT_LT(std::abs(F), 1e-12 * fabs);
  EXPECT_LT(std::abs(Mx), 1e-12 * fabs * sys.L);
  EXPECT_LT(BeamSystemStrainEnergy(sys, y.data(), 1, 0, sys.ndof), 1.01 * 0.5 * AluminiumBeam(1.1).EI * std::pow(M_PI / sys.L, 4) * 1e-10 * sys.L / 2);
}

TEST(System, CouplingWeightsAndHeldDofs)
{
  const BeamSystem      sys = SystemOf(AluminiumBeam(1.1, 12));
  const ContactCoupling g   = BeamSystemCoupling(sys, 0.25);
  EXPECT_EQ(g.dof[0], 2);
  EXPECT_NEAR(g.w[0], 0.5, 1e-12);
  EXPECT_NEAR(g.w[0] + g.w[1], 1.0, 1e-15);
  BeamParams p = AluminiumBeam(1.1, 12, Support::Clamped, Support::Free);
  const BeamSystem      cl = SystemOf(p);
  const ContactCoupling gc = BeamSystemCoupling(cl, 0.05); // between the clamped node 0 and node 1
  EXPECT_EQ(gc.w[0], 0.0);
  EXPECT_NEAR(gc.w[1], 0.5, 1e-12);
}

TEST(System, UnknownTheoryIsRefused)
{
  BeamParams  p = AluminiumBeam(1.1);
  BeamSystem  sys;
  std::string why;
  p.theory = "bernoulli-euler";
  EXPECT_FALSE(BeamSystemBuild(p, &sys, &why));
  EXPECT_NE(why.find("bernoulli-euler"), std::string::npos);
}

// The factored form of a statically determinate beam (solvers/beam_flexibility.hpp, issue 21
// at N = 40961): its static flexibility against the primal path (K's banded Cholesky, exact at
// N = 641) and the pinned-pinned formula; its lowest modes against the primal shift-and-invert
// solve at N = 641 and against the continuum beta-L values of the free-free beam, whose O(h^2)
// error it follows at every refinement up to N = 40961 (where the primal path is refused); the
// modal engine taking it by itself on fine grids.
#include "solvers/beam_flexibility.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/modes.hpp"
#include "test_helpers.hpp"

#include <cmath>
#include <string>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

ModalTruncation Truncation(ModalModes kind, PetscInt count, PetscReal tol, PetscReal T)
{
  ModalTruncation t;
  t.modes        = kind;
  t.count        = count;
  t.tolerance    = tol;
  t.contact_time = T;
  t.cost_warn = t.progress = 0;
  return t;
}

// omega_1..omega_count of the flexible modes (rad/s), by the factored form.
std::vector<PetscReal> FactoredOmegas(const BeamSystem &sys, PetscInt count)
{
  BeamFactor                          F;
  std::string                         why;
  std::vector<PetscReal>              lambda;
  std::vector<std::vector<PetscReal>> phis;
  EXPECT_TRUE(BeamFactorCreate(sys, &F, &why)) << why;
  EXPECT_EQ(0, BeamModesLowestFactored(PETSC_COMM_SELF, sys, F, count + (PetscInt)F.rigid.size(), 0, &lambda, &phis));
  std::vector<PetscReal> w;
  for (size_t k = F.rigid.size(); k < lambda.size(); ++k) w.push_back(std::sqrt(lambda[k]));
  return w;
}

// The paper's aluminium bar as a Timoshenko beam (G = 26 GPa, kappa = 5/6).
BeamParams Timoshenko(PetscInt nodes)
{
  BeamParams p = AluminiumBeam(1.1, nodes);
  p.theory     = "timoshenko";
  p.kGA        = 5.0 / 6.0 * 26e9 * 0.006 * 0.032;
  p.rhoI       = 2700 * 0.032 * std::pow(0.006, 3) / 12;
  return p;
}

std::vector<PetscReal> Continuum(const BeamParams &p, PetscInt count)
{
  std::vector<PetscReal> w;
  EXPECT_EQ(0, BeamModesAnalytic(p.left, p.right, p.length, p.EI, p.mu, count, &w));
  return w;
}

} // namespace

// Which structures are statically determinate: free, pinned-free, cantilevered and
// pinned-pinned Euler-Bernoulli beams and a free Timoshenko beam are; a beam clamped at both
// ends is not (two redundant reactions), nor a propped cantilever (one).
TEST(FactoredForm, AppliesWhereStaticallyDeterminate)
{
  BeamFactor  F;
  std::string why;
  for (auto s : {std::pair{Support::Free, Support::Free}, {Support::Pinned, Support::Free}, {Support::Clamped, Support::Free}, {Support::Pinned, Support::Pinned}})
    EXPECT_TRUE(BeamFactorCreate(SystemOf(AluminiumBeam(1.1, 41, s.first, s.second)), &F, &why)) << why;
  EXPECT_EQ(0u, F.rigid.size()); // pinned-pinned: no rigid motion, no temporary support
  EXPECT_TRUE(BeamFactorCreate(SystemOf(Timoshenko(41)), &F, &why)) << why;
  EXPECT_EQ(2u, F.rigid.size());
  EXPECT_EQ(80, F.m); // 40 elements: bending and shear
  EXPECT_FALSE(BeamFactorCreate(SystemOf(AluminiumBeam(1.1, 41, Support::Clamped, Support::Clamped)), &F, &why));
  EXPECT_NE(std::string::npos, why.find("not statically determinate")) << why;
  EXPECT_FALSE(BeamFactorCreate(SystemOf(AluminiumBeam(1.1, 41, Support::Clamped, Support::Pinned)), &F, &why));
}

// G = f^T K^+ f by the factored form (a sum of squares) against the primal path's (banded
// Cholesky with iterative refinement, exact at N = 641) for the paper's beam at three points;
// G_r of 12 modes against the sum over the other modes of the dense basis, gamma_k^2 / w_k^2
// (G less the 12 modes' sum, the partial solve's, was 2e-7 off it at x = 0.55: its gamma_k
// carry ~1e-10 of G; beam_modes.hpp); and the pinned-pinned beam's centre against the primal
// path and L^3/(48 EI) (to the grid's O(h^2)).
TEST(FactoredForm, FlexibilityMatchesThePrimalPathAndTheFormula)
{
  const BeamSystem sys = SystemOf(AluminiumBeam(1.1, 641));
  BeamFactor       F;
  ASSERT_TRUE(BeamFactorCreate(sys, &F));
  std::shared_ptr<const BeamModes> some, all;
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, Truncation(ModalModes::Count, 12, 0, 0), &some));
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, Truncation(ModalModes::All, 0, 0, 0), &all));
  ASSERT_EQ(std::string("slepc"), some->method); // N = 641: the primal path
  for (double x : {0.55, 0.88, 0.9}) {
    const ContactCoupling  g = BeamSystemCoupling(sys, x);
    std::vector<PetscReal> f(F.n, 0.0), u(F.n);
    for (PetscInt d = 0; d < F.n; ++d) f[d] = g.WeightOf(F.dof[d]);
    PetscReal G;
    BeamFactorFlexibility(F, f.data(), u.data(), &G);
    const ModalCorrection *c;
    ASSERT_EQ(0, some->StaticCorrection(g, &c));
    EXPECT_NEAR(c->G, G, 1e-10 * G) << "x = " << x;
    PetscReal fu = 0, tail = 0;
    for (PetscInt d = 0; d < F.n; ++d) fu += f[d] * u[d];
    EXPECT_NEAR(G, fu, 1e-12 * G); // |m'|^2 = f^T u
    for (PetscInt k = some->Count(); k < all->Count(); ++k) { // the modes left out, from the dense basis
      PetscReal gk = 0;
      for (PetscInt d = 0; d < F.n; ++d) gk += f[d] * all->B.Phi[d + (size_t)k * F.n] / std::sqrt(F.mass[d]);
      tail += gk * gk / (all->B.omega[k] * all->B.omega[k]);
    }
    EXPECT_NEAR(c->Gr, tail, 1e-9 * tail) << "x = " << x;
  }
  const BeamParams pp  = AluminiumBeam(1.1, 641, Support::Pinned, Support::Pinned);
  const BeamSystem spp = SystemOf(pp);
  ASSERT_TRUE(BeamFactorCreate(spp, &F));
  const ContactCoupling  g = BeamSystemCoupling(spp, 0.55);
  std::vector<PetscReal> f(F.n, 0.0);
  for (PetscInt d = 0; d < F.n; ++d) f[d] = g.WeightOf(F.dof[d]);
  PetscReal G;
  BeamFactorFlexibility(F, f.data(), nullptr, &G);
  const PetscReal h = 1.1 / 640;
  EXPECT_NEAR(std::pow(1.1, 3) / (48 * pp.EI), G, 3 * (h / 1.1) * (h / 1.1) * G); // O(h^2): 4.9e-6 here
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, spp, Truncation(ModalModes::Count, 5, 0, 0), &some));
  const ModalCorrection *c;
  ASSERT_EQ(0, some->StaticCorrection(g, &c));
  EXPECT_NEAR(c->G, G, 1e-10 * G);
}

// The lowest flexible modes of the paper's free-free beam at N = 641: the factored form against
// the primal shift-and-invert solve (exact there) to 1e-10, and against the continuum to the
// grid's O(h^2) (the lumped-mass stencil lowers each frequency, by less than (beta h)^2 / 4);
// the Timoshenko bar's likewise against its primal solve.
TEST(FactoredForm, ModesMatchThePrimalPathAndTheContinuum)
{
  const BeamParams                    p   = AluminiumBeam(1.1, 641);
  const BeamSystem                    sys = SystemOf(p);
  const std::vector<PetscReal>        wf  = FactoredOmegas(sys, 8), wc = Continuum(p, 8);
  std::vector<PetscReal>              lambda;
  std::vector<std::vector<PetscReal>> phis;
  ASSERT_EQ(0, BeamModesLowest(PETSC_COMM_SELF, sys, 10, 0, &lambda, &phis));
  ASSERT_EQ(8u, wf.size());
  for (size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(std::sqrt(lambda[k + 2]), wf[k], 1e-10 * wf[k]) << "mode " << k + 1;
    EXPECT_LT(wf[k], wc[k]) << "mode " << k + 1;
    const PetscReal betah = std::sqrt(wc[k] / std::sqrt(p.EI / p.mu)) * p.length / (p.nodes - 1);
    EXPECT_GT(wf[k], (1 - 0.25 * betah * betah) * wc[k]) << "mode " << k + 1;
  }
  const BeamSystem             tim = SystemOf(Timoshenko(161));
  const std::vector<PetscReal> wt  = FactoredOmegas(tim, 8);
  ASSERT_EQ(0, BeamModesLowest(PETSC_COMM_SELF, tim, 10, 0, &lambda, &phis));
  for (size_t k = 0; k < 8; ++k) EXPECT_NEAR(std::sqrt(lambda[k + 2]), wt[k], 1e-10 * wt[k]) << "Timoshenko, mode " << k + 1;
}

// omega_1..omega_5 of the paper's free-free beam at N = 2561, 10241 and 40961 (nested grids):
// the discretisation error e_N = omega_N / omega - 1 falls by 16 per refinement (O(h^2)), so
// e_40961 is predicted from the two coarser grids as e_10241^2 / e_2561; the factored form
// meets the prediction to 1e-11 at N = 40961 (where e is 2.5e-9 to 2e-8). The primal path's
// round-off there is eps 16 (L/h)^4 ~ 1e4 times the fundamental's scale: refused (the modes of
// the engine come from the factored form by themselves: ModalTruncation.FactoredOnFineGrids).
TEST(FactoredForm, ModesConvergeAtOrderTwoUpTo40961Nodes)
{
  std::vector<std::vector<PetscReal>> e;
  for (PetscInt N : {2561, 10241, 40961}) {
    const BeamParams             p  = AluminiumBeam(1.1, N);
    const std::vector<PetscReal> wf = FactoredOmegas(SystemOf(p), 5), wc = Continuum(p, 5);
    e.emplace_back();
    for (size_t k = 0; k < 5; ++k) e.back().push_back(wf[k] / wc[k] - 1);
  }
  for (size_t k = 0; k < 5; ++k) {
    const PetscReal predicted = e[1][k] * e[1][k] / e[0][k];
    EXPECT_NEAR(16.0, e[0][k] / e[1][k], 1e-3) << "mode " << k + 1;
    EXPECT_LT(e[2][k], 0.0);
    EXPECT_NEAR(predicted, e[2][k], 1e-11) << "mode " << k + 1 << ": e at 2561, 10241, 40961 = " << e[0][k] << ", " << e[1][k] << ", " << e[2][k];
  }
}

// The modal engine on a fine grid takes the factored form by itself (where the primal path's
// index passes 1: N = 10241 for the paper's beam, whose static correction the primal path lost,
// G_r = 0): the method says so, the kept modes are below the cut-off, G_r is positive and below
// G; at N = 40961 the modes are available (the primal path alone was refused).
TEST(ModalTruncation, FactoredOnFineGrids)
{
  const BeamSystem                 sys = SystemOf(AluminiumBeam(1.1, 10241));
  std::shared_ptr<const BeamModes> m;
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, Truncation(ModalModes::Count, 40, 0, 0), &m));
  EXPECT_EQ(std::string("slepc, factored form"), m->method);
  EXPECT_EQ(2, m->rigid);
  EXPECT_EQ(40, m->Count());
  const ModalCorrection *c;
  ASSERT_EQ(0, m->StaticCorrection(BeamSystemCoupling(sys, 0.88), &c));
  EXPECT_GT(c->Gr, 0.0);
  EXPECT_LT(c->Gr, 1e-3 * c->G);
  EXPECT_NE(std::string::npos, BeamModesSummary(*m, c).find("factored form"));
  std::string why;
  EXPECT_TRUE(BeamModesAvailable(SystemOf(AluminiumBeam(1.1, 40961)), &why)) << why;
  EXPECT_FALSE(BeamModesAvailable(SystemOf(AluminiumBeam(1.1, 40961, Support::Clamped, Support::Clamped)), &why));
  EXPECT_NE(std::string::npos, why.find("does not apply")) << why;
}

// -task modes (BeamModesCompute) takes the factored form where the modal engine does: at
// N = 2561 the paper's free beam is solved on K (shift-and-invert), at N = 10241 by the
// factored form; the discretisation error against the continuum falls by 16.000 from one to
// the other (O(h^2): the two paths agree on the trend), and the rigid modes are exactly 0.
TEST(FactoredForm, TaskModesTakesItOnFineGrids)
{
  std::vector<std::vector<PetscReal>> e;
  std::vector<std::string>            method;
  for (PetscInt N : {2561, 10241}) {
    const BeamParams p   = AluminiumBeam(1.1, N);
    const BeamSystem sys = SystemOf(p);
    ModesResult      r;
    ASSERT_EQ(0, BeamModesCompute(PETSC_COMM_SELF, sys, 7, &r, nullptr));
    const std::vector<PetscReal> wc = Continuum(p, 5);
    ASSERT_EQ(7u, r.omega.size());
    EXPECT_EQ(2, r.rigid_count);
    EXPECT_EQ(0.0, r.omega[0]);
    EXPECT_EQ(0.0, r.omega[1]);
    e.emplace_back();
    for (size_t k = 0; k < 5; ++k) e.back().push_back(r.omega[2 + k] / wc[k] - 1);
    method.push_back(r.method);
  }
  EXPECT_EQ("shift-and-invert on K", method[0]);
  EXPECT_EQ("factored form", method[1]);
  for (size_t k = 0; k < 5; ++k) EXPECT_NEAR(16.0, e[0][k] / e[1][k], 1e-3) << "mode " << k + 1 << ": e at 2561, 10241 = " << e[0][k] << ", " << e[1][k];
}

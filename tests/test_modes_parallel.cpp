// The beam's modes distributed where the structure is (issue 21): the partial eigen-solve of the
// factored form on the run's communicator (its Krylov basis split over the ranks) against the same
// solve on PETSC_COMM_SELF in the same process (one rank's, the serial solve), and the callers of
// BeamModesShared on one communicator: -ts_type modal, the modal reference (straight and
// oblique) on the run's ranks, each against its one-rank self. On 1 rank the two are the same
// solve (bit for bit); on 2 ranks they agree to round-off (the reductions' order).
#include "run/modal_reference.hpp"
#include "run/reference.hpp"
#include "solvers/beam_flexibility.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/modes.hpp"
#include "test_helpers.hpp"

#include <algorithm>
#include <cmath>
#include <string>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

ModalTruncation Count(PetscInt count)
{
  ModalTruncation t;
  t.modes     = ModalModes::Count;
  t.count     = count;
  t.cost_warn = t.progress = 0;
  return t;
}

int Size()
{
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return size;
}

// The point's modal values gamma_k = sum_q w_q phi_k(d_q) of modes over all dofs.
std::vector<PetscReal> PointValues(const ContactCoupling &g, const std::vector<std::vector<PetscReal>> &phis)
{
  std::vector<PetscReal> v;
  for (const auto &phi : phis) {
    PetscReal s = 0;
    for (PetscInt q = 0; q < g.n; ++q) s += g.w[q] * phi[g.dof[q]];
    v.push_back(s);
  }
  return v;
}

// The sign that aligns mode b with mode a (an eigenvector's sign is the solver's).
PetscReal Alignment(const BeamSystem &sys, const std::vector<PetscReal> &a, const std::vector<PetscReal> &b)
{
  PetscReal d = 0;
  for (PetscInt i = 0; i < sys.ndof; ++i) d += sys.mass[i] * a[i] * b[i];
  return d < 0 ? -1.0 : 1.0;
}

} // namespace

// The factored form at N = 10241 (the paper's free beam; the primal path's index is past its
// switch): 42 modes (2 rigid) on PETSC_COMM_WORLD and on PETSC_COMM_SELF, frequencies and the
// point's modal values (x = 0.88 m) to 1e-10 relative; each mode M-orthonormal to round-off.
TEST(ModesParallel, FactoredSameAsOneRank)
{
  const BeamSystem sys = SystemOf(AluminiumBeam(1.1, 10241));
  BeamFactor       F;
  ASSERT_TRUE(BeamModesFactoredForm(sys, &F));
  std::vector<PetscReal>              lw, ls;
  std::vector<std::vector<PetscReal>> pw, ps;
  ASSERT_EQ(0, BeamModesLowestFactored(PETSC_COMM_WORLD, sys, F, 42, 0, &lw, &pw));
  ASSERT_EQ(0, BeamModesLowestFactored(PETSC_COMM_SELF, sys, F, 42, 0, &ls, &ps));
  ASSERT_EQ(42u, lw.size());
  ASSERT_EQ(42u, ls.size());
  const ContactCoupling  g  = BeamSystemCoupling(sys, 0.88);
  std::vector<PetscReal> gw = PointValues(g, pw), gs = PointValues(g, ps);
  PetscReal              gmax = 0, worst_l = 0, worst_g = 0;
  for (PetscReal v : gs) gmax = std::max(gmax, std::abs(v));
  for (size_t k = 0; k < 42; ++k) {
    if (k < 2) {
      EXPECT_EQ(0.0, lw[k]);
      continue;
    }
    worst_l = std::max(worst_l, std::abs(lw[k] / ls[k] - 1));
    worst_g = std::max(worst_g, std::abs(Alignment(sys, ps[k], pw[k]) * gw[k] - gs[k]) / gmax);
    PetscReal norm = 0;
    for (PetscInt i = 0; i < sys.ndof; ++i) norm += sys.mass[i] * pw[k][i] * pw[k][i];
    EXPECT_NEAR(1.0, norm, 1e-12) << "mode " << k;
  }
  EXPECT_LE(worst_l, 1e-10) << "omega^2 on " << Size() << " rank(s) against one";
  EXPECT_LE(worst_g, 1e-10) << "the point's modal values on " << Size() << " rank(s) against one";
  if (Size() == 1) { // the same solve
    EXPECT_EQ(lw, ls);
    EXPECT_EQ(gw, gs);
  }
  std::printf("factored modes on %d rank(s) against one: omega^2 %.2e, point values %.2e (relative)\n", Size(), (double)worst_l, (double)worst_g);
}

// BeamModesShared keeps one cache per group of ranks: the run's communicator and PETSC_COMM_SELF
// are the same group on one rank (the second call is reused) and two on two ranks (both
// computed, so a rank-local call can neither fill nor evict the run's cache). The two bases
// agree to round-off, and so do their static corrections at the point.
TEST(ModesParallel, SharedPerGroupOfRanks)
{
  const BeamSystem                 sys = SystemOf(AluminiumBeam(1.1, 10241));
  std::shared_ptr<const BeamModes> mw, ms;
  PetscInt                         c0, r0, c1, r1;
  BeamModesCacheCounts(&c0, &r0);
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_WORLD, sys, Count(30), &mw));
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, Count(30), &ms));
  BeamModesCacheCounts(&c1, &r1);
  EXPECT_EQ(Size() == 1 ? 1 : 2, c1 - c0);
  EXPECT_EQ(Size() == 1 ? 1 : 0, r1 - r0);
  EXPECT_EQ(std::string("slepc, factored form"), mw->method);
  ASSERT_EQ(mw->Count(), ms->Count());
  for (PetscInt k = mw->rigid; k < mw->Count(); ++k) EXPECT_NEAR(mw->B.omega[k], ms->B.omega[k], 1e-10 * ms->B.omega[k]) << "mode " << k;
  const ModalCorrection *cw, *cs;
  ASSERT_EQ(0, mw->StaticCorrection(BeamSystemCoupling(sys, 0.88), &cw));
  ASSERT_EQ(0, ms->StaticCorrection(BeamSystemCoupling(sys, 0.88), &cs));
  EXPECT_NEAR(cw->Gr, cs->Gr, 1e-9 * cs->Gr);
  EXPECT_GT(cs->Gr, 0.0);
}

// -ts_type modal and the truncated modal reference on the run's ranks at N = 10241 (the factored
// form, 30 modes and the static correction): each rank's ACOR against the same run on
// PETSC_COMM_SELF (one rank's), to 1e-10; the reference and the integrator agree to its step.
TEST(ModesParallel, ImpactSameAsOneRank)
{
  Scenario sc;
  sc.beam              = AluminiumBeam(1.1, 10241);
  sc.ball              = Superball();
  sc.impact.x          = 0.88;
  sc.impact.window     = 0;
  const auto   options = std::vector<std::pair<std::string, std::string>>{{"-ts_type", "modal"}, {"-ts_dt", "2e-7"}, {"-modal_modes", "30"}};
  ImpactResult tw      = RunImpact(PETSC_COMM_WORLD, sc.beam, sc.ball, sc.impact, options);
  ImpactResult ts      = RunImpact(PETSC_COMM_SELF, sc.beam, sc.ball, sc.impact, options);
  ImpactResult rw, rs;
  ASSERT_EQ(0, ModalReferenceRun(PETSC_COMM_WORLD, sc, Count(30), &rw));
  ASSERT_EQ(0, ModalReferenceRun(PETSC_COMM_SELF, sc, Count(30), &rs));
  ASSERT_TRUE(std::isfinite(ts.acor) && ts.acor > 0);
  EXPECT_NEAR(tw.acor, ts.acor, 1e-10 * ts.acor) << "-ts_type modal on " << Size() << " rank(s) against one";
  EXPECT_NEAR(rw.acor, rs.acor, 1e-10 * rs.acor) << "the modal reference on " << Size() << " rank(s) against one";
  EXPECT_EQ(std::string("exact, truncated"), rw.formulation);
  EXPECT_NEAR(tw.acor, rw.acor, 1e-6 * rw.acor); // the integrator against its exact reference
  std::printf("ACOR on %d rank(s) against one: -ts_type modal %.2e, reference %.2e (relative)\n", Size(), std::abs(tw.acor / ts.acor - 1), std::abs(rw.acor / rs.acor - 1));
}

// The oblique impact's exact reference with a truncated basis (-reference modal -modal_modes 12,
// the R161 bat flexible in its second plane): the normal run's modes and the second plane's on
// the run's ranks, against the same reference on PETSC_COMM_SELF.
TEST(ModesParallel, ObliqueModalReferenceSameAsOneRank)
{
  Scenario sc            = LinearBallR161();
  sc.ball.speed          = 40;
  sc.impact.offset       = 0.015;
  sc.ball.spin           = 150;
  sc.ball.friction       = 0.5;
  sc.ball.tangential_cor = 0.3;
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-modal_modes", "12"));
  ReferenceSolution w, s;
  EXPECT_EQ(0, ReferenceMethodFind("modal")->run(PETSC_COMM_WORLD, sc, ReferenceSettings(), &w));
  EXPECT_EQ(0, ReferenceMethodFind("modal")->run(PETSC_COMM_SELF, sc, ReferenceSettings(), &s));
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-modal_modes"));
  ASSERT_TRUE(std::isfinite(test::Col(s.result, "spin")) && std::isfinite(test::Col(s.result, "bat_vibration_tangential")));
  EXPECT_EQ(12, s.result.modal.kept);
  EXPECT_NEAR(w.result.bbs, s.result.bbs, 1e-10 * s.result.bbs);
  EXPECT_NEAR(test::Col(w.result, "spin"), test::Col(s.result, "spin"), 1e-10 * std::abs(test::Col(s.result, "spin")));
  EXPECT_NEAR(test::Col(w.result, "bat_vibration_tangential"), test::Col(s.result, "bat_vibration_tangential"), 1e-9 * test::Col(s.result, "bat_vibration_tangential"));
}

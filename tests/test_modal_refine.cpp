// The refinement of the modal engine's bases (solvers/modal_basis.hpp, docs/model.md §12): every
// mode by inverse iteration where the stiffness' band is narrow (every beam: its results as
// before, bit for bit), only the modes whose residual asks for it where the band is wide (a
// string bed, whose half-bandwidth is twice its fields per node). Checked on a ball on a held
// bed (an ellipse 34 x 24 cm, 35 nodes along, 627 free dofs, half-bandwidth 51) against the same
// runs with every mode refined (-modal_refine all, the refinement before): -ts_type modal, a
// stepped contact with the modal free flight, and the exact modal reference, ACOR, contact time
// and peak force to 1e-9 (they agree to ~1e-15); the basis' residuals and frequencies; modes
// spoiled on purpose found and refined back; the strung racket (a free frame: a beam's spread in
// its bending modes, 26 of 746 modes refined) as with every mode refined.
#include "run/modal_reference.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/modal_basis.hpp"
#include "test_helpers.hpp"

#include <cmath>
#include <string>
#include <vector>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

using Extra = std::vector<std::pair<std::string, std::string>>;

// The held bed of the strung racket's strings (250 N, 15 and 17.9 mm apart, an ellipse 34 x 24
// cm), `nodes` along its length, struck near its centre by a linear tennis ball (57 g, k = 2e4
// N/m, 1 m/s), the free flight followed to the window's end.
Scenario HeldBed(PetscInt nodes)
{
  Scenario sc;
  ReadScene({}, {{"-strings_frame", "held"}, {"-head_length", "0.34"}, {"-head_width", "0.24"}, {"-strings_tension", "250"}, {"-strings_spacing", "0.015"}, {"-strings_spacing_crosses", "0.0179"},
                 {"-strings_nodes", std::to_string(nodes)}, {"-ball_mass", "0.057"}, {"-ball_radius", "0.0335"}, {"-ball_law", "linear"}, {"-ball_k", "2e4"}, {"-ball_speed", "1"}},
            &sc.beam, &sc.ball);
  sc.impact.x = 0.17;
  return sc;
}

ImpactResult RunWith(const Scenario &sc, const Extra &options) { return test::RunWith(PETSC_COMM_WORLD, sc, options); }

// The system's every mode (the dense basis), refined by need and refined all.
void EveryModeByNeedAndAll(const BeamSystem &sys, std::shared_ptr<const BeamModes> *need, std::shared_ptr<const BeamModes> *all)
{
  ModalTruncation t;
  t.modes     = ModalModes::All;
  t.cost_warn = t.progress = 0;
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, t, need));
  t.refine_all = true;
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, t, all));
}

void ExpectSameImpact(const ImpactResult &all, const ImpactResult &need, const char *what)
{
  EXPECT_EQ(all.contacts, need.contacts) << what;
  EXPECT_NEAR(all.acor, need.acor, 1e-9) << what;
  EXPECT_NEAR(all.contact_time, need.contact_time, 1e-9 * all.contact_time) << what;
  EXPECT_NEAR(all.peak_force, need.peak_force, 1e-9 * all.peak_force) << what;
}

// The strung racket (options/base/racket-strung.opts: the frame's bending and roll, the bed on
// its 25 nodes across), struck off the axis by the linear tennis ball.
Scenario StrungRacket()
{
  Scenario sc;
  ReadScene({"options/base/racket-strung.opts"}, {{"-ball_mass", "0.057"}, {"-ball_radius", "0.0335"}, {"-ball_law", "linear"}, {"-ball_k", "2e4"}, {"-ball_speed", "1"}}, &sc.beam, &sc.ball);
  sc.impact.x = 0.15;
  sc.impact.z = 0.05;
  return sc;
}

// Every flexible mode's residual (ModalResiduals) within the threshold of the refinement by need,
// or, for a mode that was refined, within 4 times the every-mode basis' (the refinement's own
// round-off floor: up to 9e-11 for the strung racket's first bending mode, either way).
void ExpectResidualsAsEveryMode(const BeamModes &need, const BeamModes &all)
{
  const std::vector<PetscReal> rn = ModalResiduals(need.S, false, need.B.Phi, need.Count()), ra = ModalResiduals(all.S, false, all.B.Phi, all.Count());
  for (PetscInt k = need.rigid; k < need.Count(); ++k) EXPECT_LE(rn[k], std::max(ModalRefineResidual(), 4 * ra[k])) << "mode " << k << " of " << need.Count();
}

} // namespace

// Which systems refine every mode: the banded LU of a mode costs 4 n kl^2, nothing next to the
// decomposition's 4 n^2 a mode for a beam (half-bandwidth 3 for Euler-Bernoulli, 4 for
// Timoshenko, 23 with a shell's three harmonics, whose whole refinement is then below 2e9
// flops), more than it for a bed (59 for the held bed of 41 nodes along: twice its fields per
// node). The beams of the suite keep the refinement of every mode.
TEST(ModalRefine, EveryModeWhereTheBandIsNarrow)
{
  BeamParams bat, shell;
  BallParams ball;
  ReadScene({"options/bats/r161.opts", "options/balls/baseball.opts"}, {{"-beam_theory", "timoshenko"}, {"-beam_nodes", "161"}}, &bat, &ball);
  ReadScene({"options/scenes/bbcor-shell.opts"}, {{"-beam_nodes", "41"}}, &shell, &ball);
  for (const BeamParams &p : {AluminiumBeam(1.1, 11), AluminiumBeam(1.1, 161), AluminiumBeam(1.1, 2561), AluminiumBeam(1.1, 641, Support::Clamped, Support::Free), bat, shell}) {
    const ModalSystem S = ModalSystemBeamOnly(SystemOf(p));
    EXPECT_TRUE(ModalRefinesEveryMode(S.n, ModalRefineHalfWidth(S), S.n)) << p.nodes << " nodes, " << S.n << " free dofs, half-bandwidth " << ModalRefineHalfWidth(S);
  }
  const ModalSystem bed = ModalSystemBeamOnly(SystemOf(HeldBed(35).beam));
  EXPECT_GT(ModalRefineHalfWidth(bed), 40);
  EXPECT_FALSE(ModalRefinesEveryMode(bed.n, ModalRefineHalfWidth(bed), bed.n));
}

// The held bed's dense basis refined by need against every mode refined: few modes refined,
// every residual within the threshold, the same frequencies; the impact by -ts_type modal, by cn
// with the modal free flight over the window, and by the exact modal reference, the same to 1e-9.
TEST(ModalRefine, HeldBedAsWithEveryModeRefined)
{
  const Scenario   sc  = HeldBed(35);
  const BeamSystem sys = SystemOf(sc.beam);
  std::shared_ptr<const BeamModes> need, all;
  ASSERT_NO_FATAL_FAILURE(EveryModeByNeedAndAll(sys, &need, &all));
  ASSERT_EQ(need->Count(), all->Count());
  const PetscInt n = need->Count();
  EXPECT_GT(n, 600);
  EXPECT_TRUE(need->B.by_need);
  EXPECT_FALSE(all->B.by_need);
  EXPECT_EQ(n, all->B.refined);
  EXPECT_LT(need->B.refined, n / 20) << "the bed's h^-2 spread leaves few modes with a residual above 1e-12 of their eigenvalue";
  const std::vector<PetscReal> rel = ModalResiduals(need->S, false, need->B.Phi, n);
  PetscReal                    worst = 0, dw = 0, orth = 0;
  for (PetscInt k = 0; k < n; ++k) {
    worst = std::max(worst, rel[k]);
    dw    = std::max(dw, std::abs(need->B.omega[k] / all->B.omega[k] - 1));
  }
  for (PetscInt k = 0; k < n; k += 37) // orthonormal to round-off
    for (PetscInt l = 0; l < n; l += 41) {
      PetscReal dot = 0;
      for (PetscInt d = 0; d < n; ++d) dot += need->B.Phi[d + (size_t)k * n] * need->B.Phi[d + (size_t)l * n];
      orth = std::max(orth, std::abs(dot - (k == l ? 1.0 : 0.0)));
    }
  EXPECT_LE(worst, ModalRefineResidual());
  EXPECT_LT(dw, 1e-13);
  EXPECT_LT(orth, 1e-13);

  const ImpactResult ma = RunWith(sc, {{"-ts_type", "modal"}, {"-modal_refine", "all"}}), mn = RunWith(sc, {{"-ts_type", "modal"}});
  ExpectSameImpact(ma, mn, "-ts_type modal");
  EXPECT_NEAR(ColumnOf(ma, "bed_energy_end"), ColumnOf(mn, "bed_energy_end"), 1e-9 * ColumnOf(ma, "bed_energy_end"));
  const Extra        cn = {{"-ts_type", "cn"}, {"-ts_dt", "2e-5"}, {"-ts_adapt_type", "none"}};
  Extra              cn_all = cn;
  cn_all.push_back({"-modal_refine", "all"});
  const ImpactResult ca = RunWith(sc, cn_all), cnn = RunWith(sc, cn);
  ExpectSameImpact(ca, cnn, "cn, the modal free flight");
  EXPECT_NEAR(ColumnOf(ca, "bed_energy_end"), ColumnOf(cnn, "bed_energy_end"), 1e-9 * ColumnOf(ca, "bed_energy_end")); // at the window's end, from the free flight's modes
  EXPECT_GT(ColumnOf(ca, "bed_energy_end"), 0.0);

  ModalTruncation every;
  every.modes = ModalModes::All;
  ImpactResult ra, rn;
  every.refine_all = true;
  ASSERT_EQ(0, ModalReferenceRun(sc, every, &ra));
  every.refine_all = false;
  ASSERT_EQ(0, ModalReferenceRun(sc, every, &rn));
  ExpectSameImpact(ra, rn, "-reference modal");
  EXPECT_NEAR(ra.acor, ma.acor, 1e-5) << "the modal integrator's own time error only";
}

// The refinement by need at work: modes of the held bed's basis spoiled on purpose (pairs of
// neighbours, and a low mode with a far one, turned by 1e-7 rad, as a poor solver would leave
// them) are found by their residuals, refined back by the sparse LU's inverse iteration and
// made orthogonal to the rest: the every-mode basis again, to round-off; the others untouched.
TEST(ModalRefine, SpoiledModesFoundAndRefinedBack)
{
  const BeamSystem sys = SystemOf(HeldBed(35).beam);
  ModalTruncation  t;
  t.modes      = ModalModes::All;
  t.cost_warn  = t.progress = 0;
  t.refine_all = true;
  std::shared_ptr<const BeamModes> all;
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, t, &all));
  const PetscInt         n   = all->Count();
  std::vector<PetscReal> Phi = all->B.Phi, lambda(n);
  for (PetscInt k = 0; k < n; ++k) lambda[k] = all->B.omega[k] * all->B.omega[k];
  const std::vector<std::pair<PetscInt, PetscInt>> spoil = {{0, 1}, {10, 11}, {300, 301}, {2, 600}};
  for (auto [a, b] : spoil) {
    const PetscReal c = std::cos(1e-7), s = std::sin(1e-7);
    for (PetscInt d = 0; d < n; ++d) {
      const PetscReal x = Phi[d + (size_t)a * n], y = Phi[d + (size_t)b * n];
      Phi[d + (size_t)a * n] = c * x - s * y;
      Phi[d + (size_t)b * n] = s * x + c * y;
    }
  }
  ModalBasis B;
  ASSERT_EQ(0, ModalBasisFromModes(all->S, lambda, std::move(Phi), &B));
  EXPECT_TRUE(B.by_need);
  EXPECT_EQ(8, B.refined);
  PetscReal worst = 0, dw = 0, dphi = 0;
  const std::vector<PetscReal> rel = ModalResiduals(all->S, false, B.Phi, n);
  for (PetscInt k = 0; k < n; ++k) {
    worst = std::max(worst, rel[k]);
    dw    = std::max(dw, std::abs(B.omega[k] / all->B.omega[k] - 1));
    PetscReal dot = 0;
    for (PetscInt d = 0; d < n; ++d) dot += B.Phi[d + (size_t)k * n] * all->B.Phi[d + (size_t)k * n];
    dphi = std::max(dphi, 1 - std::abs(dot));
  }
  EXPECT_LE(worst, ModalRefineResidual());
  EXPECT_LT(dw, 1e-13);
  EXPECT_LT(dphi, 1e-13) << "each mode the every-mode basis' own (1 - |cos| of the angle)";
}

// The strung racket's free frame has a beam's h^-4 spread in its bending modes: 26 of its 746
// modes are refined (by the sparse LU); -ts_type modal and the stepped contact's free flight as
// with every mode refined.
TEST(ModalRefine, StrungRacketAsWithEveryModeRefined)
{
  const Scenario   sc  = StrungRacket();
  const BeamSystem sys = SystemOf(sc.beam);
  std::shared_ptr<const BeamModes> need, all;
  ASSERT_NO_FATAL_FAILURE(EveryModeByNeedAndAll(sys, &need, &all));
  EXPECT_TRUE(need->B.by_need);
  EXPECT_GT(need->B.refined, 0);
  EXPECT_LT(need->B.refined, need->Count() / 10);
  ExpectResidualsAsEveryMode(*need, *all);
  PetscReal dw = 0;
  for (PetscInt k = need->rigid; k < need->Count(); ++k) dw = std::max(dw, std::abs(need->B.omega[k] / all->B.omega[k] - 1));
  EXPECT_LT(dw, 1e-12);
  const ImpactResult ma = RunWith(sc, {{"-ts_type", "modal"}, {"-modal_refine", "all"}}), mn = RunWith(sc, {{"-ts_type", "modal"}});
  ExpectSameImpact(ma, mn, "-ts_type modal");
  EXPECT_NEAR(ColumnOf(ma, "bed_energy_end"), ColumnOf(mn, "bed_energy_end"), 1e-9 * ColumnOf(ma, "bed_energy_end"));
  EXPECT_NEAR(ma.vibration_fraction, mn.vibration_fraction, 1e-9);
}

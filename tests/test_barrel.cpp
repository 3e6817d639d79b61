// The barrel wall's hoop oscillator in series with the ball (issue 23; -barrel_hoop_frequency,
// -barrel_hoop_mass; model/barrel.hpp): (a) the system: one more field, the wall a mode at f_h
// exactly, one more coupling entry, the rigid motions untouched; (b) a very stiff wall returns the
// beam-only result, the difference falling as r = k_b/k_h; (c) a light wall spring with the
// hysteretic ball on a rigid target gives the closed-form series spring e^2 = (e0^2 + r)/(1 + r)
// (MODEL.md section 9; scripts/references/series_spring.py); (d) energy conserved without losses
// and a free bat's momentum conserved, the wall's energy apart; (e) every tool on the same wall:
// the exact modal reference, rk4, cn, the leapfrog and -ts_type modal agree.
#include "model/barrel.hpp"
#include "run/modal_reference.hpp"
#include "solvers/leapfrog.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

const Opts kRK4 = {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-7"}};
const Opts kCN  = {{"-ts_type", "cn"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-6"}};

// The beam with the hoop oscillator f_h (Hz), m_h (kg): the wall part configured through its
// options (-barrel_hoop_frequency f -barrel_hoop_mass m) as on a hollow barrel (a tube's profile:
// the options refuse a uniform beam), then carried by this beam (the series wall's physics does
// not need the barrel's section).
BeamParams WithHoop(BeamParams p, PetscReal f, PetscReal m)
{
  BeamParams barrel = p;
  barrel.section.source = SectionSource::Profile;
  barrel.section.profile = {{0.0, 0.06, 0.055}, {p.length, 0.06, 0.055}};
  barrel = WithPart(barrel, "wall", {{"-barrel_hoop_frequency", {f}}, {"-barrel_hoop_mass", {m}}});
  p.parts.Set("wall", std::shared_ptr<const PartParams>(barrel.parts.present.at(0).second));
  return p;
}

BarrelHoop Hoop(PetscReal f, PetscReal m)
{
  BarrelHoop h;
  h.frequency = f, h.mass = m;
  return h;
}

// The hoop oscillator's dof (node 0's field of the wall part).
PetscInt WallDof(const BeamSystem &sys)
{
  const PartInstance *w = PartIn(sys, "wall");
  EXPECT_NE(w, nullptr);
  return w ? sys.Dof(0, w->first) : -1;
}

ImpactResult Reference(const Scenario &sc)
{
  ImpactResult r;
  EXPECT_EQ(0, ModalReferenceRun(sc, &r));
  return r;
}

} // namespace

// (a) The wall is one more field, free only at node 0, with the mass m_h and the spring k_h
// alone on its row; the coupling gains the entry (wall, 1); a rigid motion leaves the wall at
// rest, so K annihilates it as before; both theories.
TEST(BarrelHoop, SystemCarriesTheWallAsOneMode)
{
  for (const char *theory : {"euler", "timoshenko"}) {
    BeamParams beam = AluminiumBeam(1.1, 21);
    if (std::string(theory) == "timoshenko") beam.kGA = 1e6, beam.rhoI = 1e-6;
    beam.theory          = theory;
    const BeamSystem bare = SystemOf(beam);
    const BeamParams hp   = WithHoop(beam, 1500.0, 0.02);
    const BeamSystem sys  = SystemOf(hp);
    ASSERT_EQ(sys.fields, bare.fields + 1) << theory;
    ASSERT_EQ(sys.beam_fields, bare.fields);
    const PetscInt wall_dof = WallDof(sys);
    ASSERT_EQ(wall_dof, bare.fields) << "node 0's new field";
    PetscInt free_wall = 0;
    for (PetscInt i = 0; i < sys.nodes; ++i) free_wall += sys.held[sys.Dof(i, sys.fields - 1)] ? 0 : 1;
    EXPECT_EQ(free_wall, 1);
    const PetscReal k_h = 0.02 * std::pow(2 * PETSC_PI * 1500.0, 2);
    EXPECT_DOUBLE_EQ(BarrelHoopStiffness(Hoop(1500.0, 0.02)), k_h);
    PetscInt  cols[64];
    PetscReal vals[64];
    const PetscInt n = BeamSystemStiffnessRow(sys, wall_dof, cols, vals);
    ASSERT_EQ(n, 1) << "the wall's spring ties it to nothing but its rest shape";
    EXPECT_DOUBLE_EQ(vals[0] / sys.mass[wall_dof], std::pow(2 * PETSC_PI * 1500.0, 2)) << "its mode at f_h";
    // the beam's rows are the bare beam's, renumbered
    for (PetscInt i = 0; i < bare.nodes; ++i)
      for (PetscInt f = 0; f < bare.fields; ++f) {
        PetscInt  cb[64], cs[64];
        PetscReal vb[64], vs[64];
        const PetscInt nb = BeamSystemStiffnessRow(bare, bare.Dof(i, f), cb, vb), ns = BeamSystemStiffnessRow(sys, sys.Dof(i, f), cs, vs);
        ASSERT_EQ(nb, ns);
        for (PetscInt q = 0; q < nb; ++q) {
          EXPECT_EQ(cs[q], (cb[q] / bare.fields) * sys.fields + cb[q] % bare.fields);
          EXPECT_EQ(vs[q], vb[q]);
        }
        EXPECT_EQ(sys.mass[sys.Dof(i, f)], bare.mass[bare.Dof(i, f)]);
      }
    const ContactCoupling g = BeamSystemCoupling(sys, 0.8), g0 = BeamSystemCoupling(bare, 0.8);
    ASSERT_EQ(g.n, g0.n + 1);
    EXPECT_EQ(g.dof[g.n - 1], wall_dof);
    EXPECT_EQ(g.w[g.n - 1], 1.0);
    const std::vector<PetscReal> v = BeamSystemRigidVelocity(sys, 0.3, 1.7);
    EXPECT_EQ(v[wall_dof], 0.0);
    std::vector<PetscReal> f(sys.ndof);
    BeamSystemStiffnessApply(sys, v.data(), sys.fields, 0, sys.ndof, f.data(), sys.fields);
    for (PetscInt d = 0; d < sys.ndof; ++d) EXPECT_LT(std::abs(f[d]), 1e-6) << theory << " dof " << d;
  }
}

// (b) A very stiff wall is no wall: the exact modal reference with the wall against without, the
// difference of O(r) = k_b / k_h, and ten times smaller for a wall ten times stiffer.
TEST(BarrelHoop, StiffWallReturnsTheBeamOnlyResult)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball();
  ImpactParams     ip;
  ip.x                 = 0.9;
  ip.window            = 0;
  const ImpactResult b = Reference(Scenario(beam, ball, ip));
  PetscReal          prev = 0;
  for (PetscReal f : {2e4, 2e5}) { // Hz; m_h = 0.01 kg: r = 1.3e-4, 1.3e-6
    const BeamParams   hp = WithHoop(beam, f, 0.01);
    const PetscReal    r  = BallValue(ball, "k") / BarrelHoopStiffness(Hoop(f, 0.01));
    const ImpactResult w  = Reference(Scenario(hp, ball, ip));
    const PetscReal    d  = std::abs(w.acor - b.acor);
    PetscPrintf(PETSC_COMM_WORLD, "stiff wall f_h %g Hz, r %.2e: acor %.12f against %.12f without (diff %.2e), contact time %.9g against %.9g\n", (double)f, (double)r, (double)w.acor,
                (double)b.acor, (double)d, (double)w.contact_time, (double)b.contact_time);
    EXPECT_LT(d, 2 * r) << "the beam-only result to O(r)";
    EXPECT_NEAR(w.contact_time / b.contact_time, 1.0, 2 * r);
    if (prev > 0) {
      EXPECT_LT(d, 0.2 * prev) << "the difference falls with r";
    }
    prev = d;
  }
}

// (c) The massless limit (MODEL.md section 9): the hysteretic ball (e0^2 = 2/(n+1) on a rigid
// wall) on a rigid heavy target through a wall spring k_h = k_b / r whose mass is 1e-3 of the
// ball's: e^2 = (e0^2 + r) / (1 + r), for r = 0.25, 1, 4. The wall's leftover energy is the
// limit's error: it shrinks with the wall's mass.
TEST(BarrelHoop, LightWallSpringIsTheSeriesSpring)
{
  const BeamParams target = WallBeam(1e10, 1e5);
  const BallParams ball   = Superball("hysteresis");
  const PetscReal  e0     = std::sqrt(2.0 / (BallValue(ball, "n") + 1)), k_b = BallValue(ball, "k1");
  ImpactParams     ip;
  ip.x      = 0.55;
  ip.window = 0;
  for (PetscReal r : {0.25, 1.0, 4.0}) {
    PetscReal err_prev = 0;
    for (PetscReal ratio : {1e-2, 1e-3}) { // m_h / m_b
      const PetscReal    m_h = ratio * ball.mass, f_h = std::sqrt(k_b / r / m_h) / (2 * PETSC_PI);
      const ImpactResult w   = RunImpact(PETSC_COMM_WORLD, WithHoop(target, f_h, m_h), ball, ip, {{"-ts_type", "cn"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-7"}});
      const PetscReal    e   = SeriesSpringRestitution(e0, r), err = std::abs(w.acor - e);
      PetscPrintf(PETSC_COMM_WORLD, "series spring r %g, m_h/m_b %g (f_h %.0f Hz): acor %.6f, closed form %.6f (diff %.2e), wall energy left %.2e of E_in\n", (double)r, (double)ratio, (double)f_h,
                  (double)w.acor, (double)e, (double)err, (double)(ColumnOf(w, "shell_energy_end") /
                            (0.5 * ball.mass * ball.speed * ball.speed)));
      EXPECT_LT(err, ratio == 1e-3 ? 2e-3 : 2e-2) << "r " << r;
      if (err_prev > 0) {
        EXPECT_LT(err, err_prev) << "closer as the wall gets lighter";
      }
      err_prev = err;
    }
  }
}

// (c') The wall's mass (series_spring.py (2), normal modes of the two-mass oscillator): the
// elastic baseball (m_b = 0.145 kg, k = 1.43109e6 N/m, pi sqrt(m_b/k) = 1 ms) on a wall of mass
// mu m_b on k_h = m_h (Omega w_b)^2, w_b = sqrt(k/m_b), on a rigid target: the restitution and
// contact time to the first separation, from the script's table (no reload in these rows).
TEST(BarrelHoop, MassiveWallAgainstTheTwoMassClosedForm)
{
  const BeamParams target = WallBeam(1e10, 1e5);
  BallParams       ball   = Superball();
  ball.mass               = 0.145;
  ball.speed              = 26.8;
  ASSERT_TRUE(BallValueSet(&ball, "k", 1.43109e6));
  const PetscReal w_b = std::sqrt(BallValue(ball, "k") / ball.mass);
  ImpactParams    ip;
  ip.x      = 0.55;
  ip.window = 0;
  struct Row {
    PetscReal mu, Omega, e, tc; // 1, 1, 1, s: series_spring.py (2), 'e exact', 'tc exact ms'
  };
  for (const Row &row : {Row{0.2, 4.0, 0.9958464372, 1.136230e-3}, Row{0.5, 3.0, 0.9702311902, 1.092883e-3}, Row{1.0, 2.0, 0.9738148669, 1.185838e-3}}) {
    const PetscReal    m_h = row.mu * ball.mass, f_h = row.Omega * w_b / (2 * PETSC_PI);
    const ImpactResult r   = Reference(Scenario(WithHoop(target, f_h, m_h), ball, ip));
    PetscPrintf(PETSC_COMM_WORLD, "two-mass wall mu %g Omega %g: acor %.10f (closed form %.10f), contact time %.6f ms (%.6f)\n", (double)row.mu, (double)row.Omega, (double)r.acor, (double)row.e,
                (double)(r.contact_time * 1e3), (double)(row.tc * 1e3));
    EXPECT_NEAR(r.acor, row.e, 2e-6) << "mu " << row.mu; // the target's own compliance: r ~ 1e-6
    EXPECT_NEAR(r.contact_time / row.tc, 1.0, 2e-6);
  }
}

// (d) Without losses the total (ball, beam, wall) is conserved; a free bat's momentum and angular
// momentum are conserved (the wall carries none); the wall's energy is apart from the beam's and
// nonzero; the contact time lengthens with the wall's compliance.
TEST(BarrelHoop, EnergyAndMomentumOfAFreeBat)
{
  const BeamParams   beam = WithHoop(AluminiumBeam(1.1, 41), 400.0, 0.02); // r = 0.16, the wall's period 2.5 ms, the contact's 4.6 ms
  const BallParams   ball = Superball();
  ImpactParams       ip;
  ip.x                 = 0.9;
  ip.window            = 4e-3;
  const ImpactResult r = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, kRK4);
  EXPECT_LT(std::abs(r.energy_error), 1e-9);
  EXPECT_LT(std::abs(r.linear_momentum_error), 1e-12);
  EXPECT_LT(std::abs(r.angular_momentum_error), 1e-12);
  EXPECT_GT(ColumnOf(r, "shell_energy_peak"), 1e-3 * 0.5 * ball.mass * ball.speed * ball.speed);
  EXPECT_GT(ColumnOf(r, "wall_deflection_peak"), 0);
  const PetscReal k_h = BarrelHoopStiffness(Hoop(400.0, 0.02));
  const double peak = ColumnOf(r, "wall_deflection_peak"), energy = ColumnOf(r, "shell_energy_peak");
  EXPECT_LE(peak, r.peak_force / k_h * 2.0 + 1e-12) << "at most twice the static deflection under the peak force";
  EXPECT_NEAR(energy, 0.5 * k_h * peak * peak, 0.6 * energy) << "the same order as its stored energy at its largest";
  ImpactParams       ip0 = ip;
  const ImpactResult b   = RunImpact(PETSC_COMM_WORLD, AluminiumBeam(1.1, 41), ball, ip0, kRK4);
  EXPECT_GT(r.contact_time, b.contact_time) << "a compliant wall lengthens the contact";
}

// (e) One wall, every tool: the exact modal reference, rk4, cn (second order, error ~ 1e-5 at
// this step), the leapfrog and -ts_type modal give the same ACOR and contact time.
TEST(BarrelHoop, EveryToolAgrees)
{
  const BeamParams beam = WithHoop(AluminiumBeam(1.1, 41), 800.0, 0.02);
  const BallParams ball = Superball();
  ImpactParams     ip;
  ip.x                   = 0.9;
  ip.window              = 0;
  const Scenario     sc(beam, ball, ip);
  const ImpactResult ref = Reference(sc);
  const ImpactResult rk  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, kRK4);
  const ImpactResult cn  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, kCN);
  const ImpactResult md  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "modal"}});
  LeapfrogParams     lp;
  lp.dt = 1e-7;
  ImpactResult lf;
  ASSERT_EQ(0, LeapfrogRun(sc, lp, &lf));
  PetscPrintf(PETSC_COMM_WORLD, "wall f_h 800 Hz: acor reference %.10f, rk4 %.10f, cn %.10f, leapfrog %.10f, modal %.10f\n", (double)ref.acor, (double)rk.acor, (double)cn.acor, (double)lf.acor,
              (double)md.acor);
  EXPECT_NEAR(rk.acor, ref.acor, 1e-8);
  EXPECT_NEAR(cn.acor, ref.acor, 1e-4);
  EXPECT_NEAR(lf.acor, ref.acor, 1e-4);
  EXPECT_NEAR(md.acor, ref.acor, 1e-6);
  EXPECT_NEAR(rk.contact_time / ref.contact_time, 1.0, 1e-7);
  EXPECT_NEAR(ColumnOf(rk, "shell_energy_end"), ColumnOf(ref, "shell_energy_end"), 1e-6 * 0.5 * ball.mass);
  const BeamParams   bare = AluminiumBeam(1.1, 41);
  const ImpactResult b    = Reference(Scenario(bare, ball, ip));
  EXPECT_GT(std::abs(ref.acor - b.acor), 1e-3) << "a wall this soft changes the ACOR";
}

// -barrel_wall_thickness: the rows at the largest outer diameter (the barrel) get d = D - 2 t,
// the rest of the profile is the file's; refused on a solid barrel and for t >= D/2.
TEST(BarrelWall, ThicknessOverridesTheBarrelRows)
{
  const std::vector<ProfileRow> bat = {{0.0, 0.046, 0.034}, {0.45, 0.052, 0.047}, {0.53, 0.0667, 0.0617}, {0.84, 0.0667, 0.0617}};
  std::vector<ProfileRow>       rows = bat;
  std::string                   why;
  ASSERT_TRUE(BarrelWallThicknessApply(0.004, &rows, &why)) << why;
  for (size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k].D, bat[k].D);
    EXPECT_NEAR(rows[k].d, k >= 2 ? 0.0667 - 0.008 : bat[k].d, 1e-15) << k;
  }
  rows = bat;
  EXPECT_FALSE(BarrelWallThicknessApply(0.0667 / 2, &rows, &why));
  EXPECT_NE(why.find("outer radius"), std::string::npos) << why;
  std::vector<ProfileRow> solid = {{0.0, 0.03, 0.0}, {0.84, 0.06, 0.0}};
  EXPECT_FALSE(BarrelWallThicknessApply(0.003, &solid, &why));
  EXPECT_NE(why.find("solid"), std::string::npos) << why;
}

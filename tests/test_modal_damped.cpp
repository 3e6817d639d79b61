// The exact modal reference of a Rayleigh-damped beam in contact (solvers/modal_damped.hpp):
// without damping the damped first-order phase is the undamped modal phase; with damping the
// reference agrees with TS runs to their accuracy (the TS error falling with the step); its
// energy balance KE + U + D closes to round-off, with D checked against a quadrature of v^T C v.
#include "run/modal_reference.hpp"
#include "solvers/modal_damped.hpp"
#include "test_helpers.hpp"

#include <cmath>
#include <cstdio>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

BeamParams Damped(BeamParams p, double alpha, double beta)
{
  p.damping_mass      = alpha;
  p.damping_stiffness = beta;
  return p;
}

ImpactResult Modal(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip)
{
  ImpactResult r;
  EXPECT_EQ(ModalReferenceRun(Scenario{beam, ball, ip, MonitorRequest()}, &r), 0);
  return r;
}

struct Case {
  const char *name;
  BeamParams  beam;
  double      x;
  PetscInt    contacts;
};

std::vector<Case> Cases(double alpha, double beta)
{
  return {{"free 1.1 m, centre", Damped(AluminiumBeam(1.1, 41), alpha, beta), 0.55, 1},
          {"free 1.1 m, x = 0.9", Damped(AluminiumBeam(1.1, 41), alpha, beta), 0.9, 1},
          {"clamped 0.3 m, x = 0.29", Damped(AluminiumBeam(0.3, 41, Support::Clamped, Support::Free), alpha, beta), 0.29, 2}};
}

} // namespace

// alpha = beta = 0: the damped first-order phase of the contact system (forced) is the
// undamped modal phase: c and its derivatives, the state, and the separation time.
TEST(ModalDamped, WithoutDampingItIsTheUndampedPhase)
{
  for (const Case &c : Cases(0.0, 0.0)) {
    const BeamSystem  sys = SystemOf(c.beam);
    const BallParams  b   = Superball();
    const ModalSystem S   = ModalSystemBuild(sys, BeamSystemCoupling(sys, c.x), b.mass, BallValue(b, "k"));
    ModalBasis        B;
    ModalDampedBasis  DB;
    ASSERT_EQ(ModalBasisBuild(S, true, &B), 0);
    ASSERT_EQ(ModalDampedBasisBuild(S, true, &DB), 0);
    printf("%s: eigenvector condition number %.3g, %d rigid modes\n", c.name, DB.cond, (int)(S.n - (PetscInt)DB.flex.size()));
    EXPECT_LT(DB.cond, 1e4);
    std::vector<PetscReal> q(S.n, 0.0), qd(S.n, 0.0);
    qd[S.n - 1] = b.speed;
    ModalPhase       ph;
    ModalDampedPhase dp;
    ph.S = dp.S = &S;
    ph.B        = &B;
    dp.B        = &DB;
    ph.From(q, qd);
    dp.From(q, qd);
    for (PetscReal s : {0.0, 1e-4, 1e-3, 2.5e-3}) {
      for (int p = 0; p < 3; ++p) EXPECT_NEAR(ph.Derivative(s, p), dp.Derivative(s, p), 1e-10 * ph.Bound(p > 0 ? p : 1) / (p > 0 ? 1 : B.omega.back())) << c.name << " s " << s << " p " << p;
      std::vector<PetscReal> q1, qd1, q2, qd2;
      ph.State(s, q1, qd1);
      dp.State(s, q2, qd2);
      for (PetscInt d = 0; d < S.n; ++d) {
        EXPECT_NEAR(q1[d], q2[d], 1e-10 * b.speed * 1e-2) << c.name;
        EXPECT_NEAR(qd1[d], qd2[d], 1e-10 * b.speed) << c.name;
      }
    }
    EXPECT_EQ(0.0, dp.Dissipated(1e-3));
    const PetscReal s_min = 1e-13 * ContactTimeScale(b);
    PetscReal       s1, s2;
    ASSERT_TRUE(ModalFirstCrossing(ph, 0, +1.0, 0.1, s_min, &s1));
    ASSERT_TRUE(ModalFirstCrossing(dp, 0, +1.0, 0.1, s_min, &s2));
    EXPECT_NEAR(s1, s2, 1e-10 * s1) << c.name;
  }
}

// A vanishing damping (beta = 1e-16 s) takes the damped path through the whole run: the
// outcome is the undamped reference's to 1e-10.
TEST(ModalDamped, VanishingDampingRunIsTheUndampedReference)
{
  const std::vector<Case> zero = Cases(0.0, 0.0), tiny = Cases(0.0, 1e-16);
  for (size_t i = 0; i < zero.size(); ++i) {
    ImpactParams ip;
    ip.x                  = zero[i].x;
    const ImpactResult r0 = Modal(zero[i].beam, Superball(), ip);
    const ImpactResult r1 = Modal(tiny[i].beam, Superball(), ip);
    printf("%s: acor %.15f vs %.15f, contact time %.15e vs %.15e\n", zero[i].name, r0.acor, r1.acor, r0.contact_time, r1.contact_time);
    EXPECT_EQ(r0.contacts, zero[i].contacts) << zero[i].name;
    EXPECT_EQ(r1.contacts, r0.contacts) << zero[i].name;
    EXPECT_NEAR(r1.acor, r0.acor, 1e-10) << zero[i].name;
    EXPECT_NEAR(r1.contact_time, r0.contact_time, 1e-10 * r0.contact_time) << zero[i].name;
    EXPECT_NEAR(r1.contact_time_total, r0.contact_time_total, 1e-10 * r0.contact_time_total) << zero[i].name;
    EXPECT_NEAR(r1.peak_force, r0.peak_force, 1e-10 * r0.peak_force) << zero[i].name;
    EXPECT_LT(std::abs(r1.energy_error), 1e-10);
  }
}

// The damped beam (alpha = 2 1/s, beta = 2e-6 s) against Crank-Nicolson at dt and dt/2 (its
// error falls by 4 and is within the bound) and a 5(4) run at rtol 1e-12: ACOR, contact time,
// contacts, peak force and the dissipated energy.
TEST(ModalDamped, MatchesTSRunsToTheirAccuracy)
{
  for (const Case &c : Cases(2.0, 2e-6)) {
    ImpactParams ip;
    ip.x                   = c.x;
    const BallParams   b   = Superball();
    const ImpactResult ref = Modal(c.beam, b, ip);
    EXPECT_EQ(ref.contacts, c.contacts) << c.name;
    EXPECT_LT(std::abs(ref.energy_error), 1e-10) << c.name;
    EXPECT_GT(ref.damping_fraction, 1e-3) << c.name;
    double err_cn[2], err_total[2];
    for (int l = 0; l < 2; ++l) {
      char dt[32];
      snprintf(dt, sizeof(dt), "%.17g", 2e-6 / (1 << l));
      const ImpactResult cn = RunImpact(PETSC_COMM_SELF, c.beam, b, ip, {{"-ts_type", "cn"}, {"-ts_dt", dt}});
      EXPECT_EQ(cn.contacts, ref.contacts) << c.name;
      err_cn[l]    = std::abs(cn.acor - ref.acor);
      err_total[l] = std::abs(cn.contact_time_total / ref.contact_time_total - 1);
      printf("%s: cn dt %s: acor error %.2e, contact time %.2e, total %.2e, peak force %.2e, D %.2e (relative)\n", c.name, dt, err_cn[l], std::abs(cn.contact_time / ref.contact_time - 1),
             std::abs(cn.contact_time_total / ref.contact_time_total - 1),
             std::abs(cn.peak_force / ref.peak_force - 1), std::abs(cn.beam_dissipated_end / ref.beam_dissipated_end - 1));
      EXPECT_LT(err_cn[l], 2e-5 / (1 << (2 * l))) << c.name;
      EXPECT_NEAR(cn.contact_time, ref.contact_time, 1e-5 * ref.contact_time);
    }
    EXPECT_NEAR(err_cn[0] / err_cn[1], 4.0, 0.2) << c.name << ": second order onto the reference";
    EXPECT_NEAR(err_total[0] / err_total[1], 4.0, 0.2) << c.name;
    const ImpactResult rk = RunImpact(PETSC_COMM_SELF, c.beam, b, ip, {{"-ts_type", "rk"}, {"-ts_rk_type", "5dp"}, {"-ts_rtol", "1e-12"}, {"-ts_atol", "1e-15"}});
    printf("%s: modal acor %.12f, contact time %.10e s, D %.6e J (%.4f of E_in), energy balance %.1e, rk5dp: acor error %.2e, contact time %.2e, total %.2e, peak force %.2e, D %.2e, "
           "its energy balance %.1e\n",
           c.name, ref.acor, ref.contact_time, ref.beam_dissipated_end, ref.damping_fraction, ref.energy_error, std::abs(rk.acor - ref.acor), std::abs(rk.contact_time / ref.contact_time - 1),
           std::abs(rk.contact_time_total / ref.contact_time_total - 1), std::abs(rk.peak_force / ref.peak_force - 1), std::abs(rk.beam_dissipated_end / ref.beam_dissipated_end - 1),
           rk.energy_error);
    EXPECT_EQ(rk.contacts, ref.contacts) << c.name;
    EXPECT_NEAR(rk.acor, ref.acor, 1e-9) << c.name;
    EXPECT_NEAR(rk.contact_time, ref.contact_time, 1e-9 * ref.contact_time) << c.name;
    // The 5(4) run's second contact is its least accurate measure (4e-8 in the clamped case,
    // where Crank-Nicolson's total converges onto the reference at ratio 4.00).
    EXPECT_NEAR(rk.contact_time_total, ref.contact_time_total, 1e-7 * ref.contact_time_total) << c.name;
    EXPECT_NEAR(rk.peak_force, ref.peak_force, 1e-9 * ref.peak_force) << c.name;
    EXPECT_NEAR(rk.beam_dissipated_end, ref.beam_dissipated_end, 1e-8 * ref.beam_dissipated_end) << c.name;
  }
}

// The dissipated energy of a contact phase in closed form against a composite 4-point
// Gauss-Legendre quadrature of v^T C v (BeamSystemDissipationRate on the phase's velocities),
// and the phase's own energy balance E(0) = E(s) + D(s), heavy stiffness damping included
// (beta = 1e-4 s: the grid modes overdamped).
TEST(ModalDamped, DissipationMatchesQuadratureAndBalances)
{
  static const double xg[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double wg[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  struct Damping {
    double alpha, beta;
  };
  for (const Damping &dmp : {Damping{2.0, 2e-6}, Damping{0.0, 1e-4}, Damping{20.0, 0.0}}) {
    const BeamSystem  sys = SystemOf(Damped(AluminiumBeam(1.1, 41), dmp.alpha, dmp.beta));
    const BallParams  b   = Superball();
    const ModalSystem S   = ModalSystemBuild(sys, BeamSystemCoupling(sys, 0.9), b.mass, BallValue(b, "k"));
    ModalDampedBasis  DB;
    ASSERT_EQ(ModalDampedBasisBuild(S, true, &DB), 0);
    std::vector<PetscReal> q(S.n, 0.0), qd(S.n, 0.0), qs, qds, v(sys.ndof);
    qd[S.n - 1] = b.speed;
    ModalDampedPhase dp;
    dp.S = &S;
    dp.B = &DB;
    dp.From(q, qd);
    auto energy = [&](const std::vector<PetscReal> &y, const std::vector<PetscReal> &yd) {
      std::vector<PetscReal> shape(sys.ndof, 0.0);
      PetscReal              E = 0, c = 0;
      for (PetscInt d = 0; d < S.n; ++d) {
        E += 0.5 * S.mass[d] * yd[d] * yd[d];
        c += S.g[d] * y[d];
        if (S.dof[d] >= 0) shape[S.dof[d]] = y[d];
      }
      return E + BeamSystemStrainEnergy(sys, shape.data(), sys.fields, 0, sys.ndof) + 0.5 * S.k * c * c;
    };
    const PetscReal T = 3e-3, E0 = energy(q, qd);
    const int       panels = 4000;
    PetscReal       Dq     = 0;
    for (int i = 0; i < panels; ++i)
      for (int g = 0; g < 4; ++g) {
        const PetscReal s = T * (i + 0.5 + 0.5 * xg[g]) / panels;
        dp.State(s, qs, qds);
        std::fill(v.begin(), v.end(), 0.0);
        for (PetscInt d = 0; d + 1 < S.n; ++d) v[S.dof[d]] = qds[d];
        Dq += 0.5 * T / panels * wg[g] * BeamSystemDissipationRate(sys, v.data(), sys.fields, 0, sys.ndof);
      }
    const PetscReal D = dp.Dissipated(T);
    dp.State(T, qs, qds);
    const PetscReal E1 = energy(qs, qds);
    printf("alpha %g beta %g: cond %.3g, D %.10e J, quadrature %.10e J (rel. diff %.1e), energy balance (E1 + D - E0)/E0 = %.1e\n", dmp.alpha, dmp.beta, DB.cond, D, Dq, D / Dq - 1,
           (E1 + D - E0) / E0);
    EXPECT_GT(D, 1e-4 * E0);
    EXPECT_NEAR(D, Dq, 1e-10 * E0);
    EXPECT_NEAR(E1 + D, E0, 1e-11 * E0);
  }
}

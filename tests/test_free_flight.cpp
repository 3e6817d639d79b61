// The beam's modes computed once per beam (solvers/beam_modes.hpp) and the exact free flight
// after a separation (run/free_flight.hpp): the cache, the exact rigid modes, the rigorous
// first-root search against brute-force sampling, and the state it hands back.
#include "run/free_flight.hpp"
#include "run/impact_problem.hpp"
#include "test_helpers.hpp"

#include <cmath>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

BeamParams Timoshenko(BeamParams p)
{
  const PetscReal E = 7e10, G = 2.6e10, rho = 2700, a = 0.006, b = 0.032;
  p.theory = "timoshenko";
  p.kGA    = 5.0 / 6.0 * G * a * b;
  p.rhoI   = rho * b * a * a * a / 12;
  (void)E;
  return p;
}

// Momentum sum m v of the translational dofs carried by mode k (mass-normalised), over sqrt(M).
PetscReal SpuriousMomentum(const BeamModes &m, PetscInt k)
{
  const PetscInt n = m.S.n;
  PetscReal      r = 0, M = 0;
  for (PetscInt d = 0; d < n; ++d)
    if (m.S.dof[d] % m.sys.fields == 0) {
      r += std::sqrt(m.S.mass[d]) * m.B.Phi[(size_t)k * n + d];
      M += m.S.mass[d];
    }
  return std::abs(r) / std::sqrt(M);
}

} // namespace

// One decomposition per beam: the same system again is a cache hit (the same object), a
// different beam (support, grid, theory, damping) a new one.
TEST(BeamModes, ComputedOncePerBeam)
{
  PetscInt c0, r0, c1, r1;
  BeamModesCacheCounts(&c0, &r0);
  const BeamSystem                 a = SystemOf(AluminiumBeam(1.1, 41)), b = SystemOf(AluminiumBeam(1.1, 41));
  std::shared_ptr<const BeamModes> ma, mb, mc, md;
  ASSERT_EQ(BeamModesShared(a, &ma), 0);
  ASSERT_EQ(BeamModesShared(b, &mb), 0);
  EXPECT_EQ(ma.get(), mb.get());
  ASSERT_EQ(BeamModesShared(SystemOf(AluminiumBeam(1.1, 41, Support::Clamped)), &mc), 0);
  EXPECT_NE(mc.get(), ma.get());
  BeamParams damped = AluminiumBeam(1.1, 41);
  damped.damping_stiffness = 1e-6;
  ASSERT_EQ(BeamModesShared(SystemOf(damped), &md), 0);
  EXPECT_NE(md.get(), ma.get());
  BeamModesCacheCounts(&c1, &r1);
  EXPECT_EQ(c1 - c0, 3);
  EXPECT_EQ(r1 - r0, 1);
}

// The modes as supported: free-free has exactly two rigid modes (omega 0, exact rigid
// motions: the flexible modes carry no momentum), then the analytic beta L = 4.73004;
// clamped-free none, beta L = 1.87510; pinned one; Timoshenko free-free two.
TEST(BeamModes, RigidModesAreExactAndFrequenciesMatch)
{
  struct Case {
    BeamParams p;
    int        rigid;
    double     betaL;
  };
  const BeamParams free = AluminiumBeam(1.1, 81);
  for (const Case &c : {Case{free, 2, 4.73004}, Case{AluminiumBeam(1.1, 81, Support::Clamped), 0, 1.87510}, Case{AluminiumBeam(1.1, 81, Support::Pinned), 1, 3.92660},
                        Case{Timoshenko(free), 2, 4.73004}}) {
    std::shared_ptr<const BeamModes> m;
    ASSERT_EQ(BeamModesShared(SystemOf(c.p), &m), 0);
    for (int k = 0; k < c.rigid; ++k) EXPECT_EQ(m->B.omega[k], 0.0) << c.p.theory;
    const double w1 = c.betaL * c.betaL * std::sqrt(c.p.EI / (c.p.mu * std::pow(c.p.length, 4)));
    EXPECT_NEAR(m->B.omega[c.rigid] / w1, 1.0, 2e-3) << c.p.theory << " rigid " << c.rigid;
    if (c.rigid == 2) {
      for (PetscInt k = 2; k < m->S.n; ++k) EXPECT_LT(SpuriousMomentum(*m, k), 1e-14) << "mode " << k;
    }
  }
}

// The search against brute force: a state with content in the first modes and the ball
// drifting at various speeds (near misses, a return, a clean escape). The rigorous root is
// never after the first sign change of a fine sampling, c is 0 there to round-off, and every
// sample before it is negative. The state handed back gives the same c, and with damping the
// beam's energy plus the dissipated energy is constant.
TEST(FreeFlight, FirstRootAgainstBruteForce)
{
  for (double beta : {0.0, 2e-6}) {
    BeamParams p              = AluminiumBeam(0.3, 41, Support::Clamped);
    p.damping_stiffness       = beta;
    const BeamSystem      sys = SystemOf(p);
    const ContactCoupling g   = BeamSystemCoupling(sys, 0.29);
    std::shared_ptr<const BeamModes> m;
    ASSERT_EQ(BeamModesShared(sys, &m), 0);
    // A deflection in the first three modes, moving.
    FullState s;
    s.y.assign(sys.ndof, 0.0);
    s.v.assign(sys.ndof, 0.0);
    const PetscInt n = m->S.n;
    for (PetscInt d = 0; d < n; ++d) {
      const PetscReal im = 1 / std::sqrt(m->S.mass[d]);
      s.y[m->S.dof[d]]   = im * (1e-4 * m->B.Phi[d] + 3e-5 * m->B.Phi[n + d] - 1e-5 * m->B.Phi[2 * n + d]);
      s.v[m->S.dof[d]]   = im * (2e-2 * m->B.Phi[d] - 1e-2 * m->B.Phi[n + d]);
    }
    const PetscReal yimp = g.w[0] * s.y[g.dof[0]] + g.w[1] * s.y[g.dof[1]];
    int             found = 0, none = 0;
    for (double vb : {-0.3, -0.05, -0.02, -0.01, -0.005, 0.0, 0.01}) {
      s.ball_y = yimp - 1e-5;
      s.ball_v = vb;
      FreeFlight ff;
      FreeFlightStart(m, g, 0.0, s, &ff);
      const PetscReal s_end = 0.05;
      PetscReal       root  = -1;
      const bool      hit   = FreeFlightFirstContact(ff, s_end, 1e-15, &root);
      // brute force
      const int K     = 200000;
      double    brute = -1;
      for (int i = 1; i <= K; ++i) {
        const double t = s_end * i / K;
        if (FreeFlightCompression(ff, t, 0) >= 0) {
          brute = t;
          break;
        }
      }
      if (brute > 0) {
        ASSERT_TRUE(hit) << "vb " << vb << ": sampling finds a contact at " << brute;
        EXPECT_LE(root, brute + 1e-14) << "vb " << vb;
        EXPECT_GT(root, brute - s_end / K - 1e-14) << "vb " << vb;
        found++;
      } else if (hit) { // a root between the samples: a touch shorter than the sampling step
        EXPECT_GE(FreeFlightCompression(ff, root, 0), 0.0);
      } else none++;
      if (hit) {
        PetscReal       mag;
        const PetscReal c0 = FreeFlightCompression(ff, root, 0, &mag);
        EXPECT_NEAR(c0, 0.0, 1e-13 * mag);
        FullState at;
        FreeFlightState(ff, root, &at);
        const PetscReal c = at.ball_y - (g.w[0] * at.y[g.dof[0]] + g.w[1] * at.y[g.dof[1]]);
        EXPECT_NEAR(c, 0.0, 1e-12 * std::abs(at.ball_y) + 1e-15);
      }
      // Energy + dissipated is constant along the flight.
      FullState a, b;
      FreeFlightState(ff, 0.0, &a);
      FreeFlightState(ff, 0.03, &b);
      auto energy = [&](const FullState &x) {
        return BeamSystemKineticEnergy(sys, x.v.data(), sys.fields, 0, sys.ndof) + BeamSystemStrainEnergy(sys, x.y.data(), sys.fields, 0, sys.ndof) + x.dissipated;
      };
      EXPECT_NEAR(energy(b), energy(a), 1e-11 * energy(a)); // the modal energy is the system's to round-off
      if (beta > 0) {
        EXPECT_GT(b.dissipated, 0.0);
      }
    }
    EXPECT_GE(found, 3) << "the cases must include contacts";
    EXPECT_GE(none, 1) << "and an escape";
  }
}

// Through the driver: the 30 cm clamped beam struck at 29 cm catches the ball again; the
// modal free flight finds the second contact and agrees with time integration, on the same
// events; the -impact_window 0 run of the same impact has one contact.
TEST(FreeFlight, DoubleImpactAsTimeIntegration)
{
  const BeamParams beam = AluminiumBeam(0.3, 41, Support::Clamped, Support::Free);
  ImpactParams     ip;
  ip.x        = 0.29;
  ip.after    = ImpactAfter::Time;
  const auto t = RunImpact(PETSC_COMM_WORLD, beam, Superball(), ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}});
  ip.after     = ImpactAfter::Modal;
  const auto m = RunImpact(PETSC_COMM_WORLD, beam, Superball(), ip, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}});
  EXPECT_GE(m.contacts, 2);
  EXPECT_EQ(m.contacts, t.contacts);
  EXPECT_NEAR(m.acor, t.acor, 1e-5);
  ASSERT_EQ(m.events.size(), t.events.size());
  for (size_t i = 0; i < m.events.size(); ++i) {
    EXPECT_EQ(m.events[i].kind, t.events[i].kind);
    EXPECT_NEAR(m.events[i].time, t.events[i].time, 1e-6) << i;
  }
  EXPECT_LT(m.steps, t.steps / 3);
  EXPECT_LT(std::abs(m.energy_error), 1e-9);
}

// -ts_type modal hands the free flight its own modal state and takes the flight's end back in
// modes (Stepper::GetModalState/SetModalState: no projection through the physical state); the
// same double impact with the free flight stepped by the same integrator (-impact_after time:
// the exact flow over steps, the second contact found by the event locator) has the same
// contacts at the same times (to the event locator's tolerance), and the same ACOR and energy balance.
TEST(FreeFlight, ModalIntegratorHandsItsModesToTheFlight)
{
  const BeamParams beam = AluminiumBeam(0.3, 41, Support::Clamped, Support::Free);
  ImpactParams     ip;
  ip.x        = 0.29;
  ip.after    = ImpactAfter::Time;
  const auto t = RunImpact(PETSC_COMM_WORLD, beam, Superball(), ip, {{"-ts_type", "modal"}});
  ip.after     = ImpactAfter::Modal;
  const auto m = RunImpact(PETSC_COMM_WORLD, beam, Superball(), ip, {{"-ts_type", "modal"}});
  EXPECT_GE(m.contacts, 2);
  EXPECT_EQ(m.contacts, t.contacts);
  EXPECT_NEAR(m.acor, t.acor, 1e-10);
  ASSERT_EQ(m.events.size(), t.events.size());
  for (size_t i = 0; i < m.events.size(); ++i) {
    EXPECT_EQ(m.events[i].kind, t.events[i].kind);
    EXPECT_NEAR(m.events[i].time, t.events[i].time, 1e-8) << i; // the event locator's tolerance (a maximum compression: 9e-10 apart)
  }
  EXPECT_LT(m.steps, t.steps / 3);
  EXPECT_LT(std::abs(m.energy_error), 1e-9); // the contact's own (4.3e-10), the flight adds none
  EXPECT_NEAR(m.energy_error, t.energy_error, 1e-12);
}

// The flight from modal coordinates (FreeFlightStartModal) is the flight from the physical
// state they stand for (FreeFlightStart, which projects it): the same coupling, bounds and
// compression, and its end in modes (FreeFlightModalState) expands to FreeFlightState's.
TEST(FreeFlight, StartInModesIsStartInDofs)
{
  const BeamSystem                 sys = SystemOf(AluminiumBeam(1.1, 81));
  std::shared_ptr<const BeamModes> modes;
  ModalTruncation                  t;
  t.modes = ModalModes::Count;
  t.count = 30;
  ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, t, &modes));
  const PetscInt n = modes->S.n, nm = modes->Count();
  ModalState     q;
  for (PetscInt k = 0; k < nm; ++k) q.z.push_back(1e-4 * std::cos(0.7 * k)), q.zd.push_back(0.02 * std::sin(1.3 * k + 0.2));
  q.ball_y = -1e-4, q.ball_v = -0.4, q.dissipated = 0.01;
  FullState s; // M^{-1/2} Phi z over the free dofs
  s.y.assign(sys.ndof, 0.0), s.v.assign(sys.ndof, 0.0);
  for (PetscInt k = 0; k < nm; ++k)
    for (PetscInt d = 0; d < n; ++d) {
      s.y[modes->S.dof[d]] += modes->B.Phi[(size_t)k * n + d] * q.z[k] / std::sqrt(modes->S.mass[d]);
      s.v[modes->S.dof[d]] += modes->B.Phi[(size_t)k * n + d] * q.zd[k] / std::sqrt(modes->S.mass[d]);
    }
  s.ball_y = q.ball_y, s.ball_v = q.ball_v, s.dissipated = q.dissipated;
  const ContactCoupling g = BeamSystemCoupling(sys, 0.83);
  FreeFlight            a, b;
  FreeFlightStart(modes, g, 0.0, s, &a);
  FreeFlightStartModal(modes, g, 0.0, q, &b);
  ASSERT_EQ(a.gamma.size(), b.gamma.size());
  for (PetscInt k = 0; k < nm; ++k) {
    EXPECT_EQ(a.gamma[k], b.gamma[k]) << k; // the same sum over the coupled dofs
    EXPECT_NEAR(a.z[k], b.z[k], 1e-13 * 1e-4) << k;
    EXPECT_NEAR(a.zd[k], b.zd[k], 1e-13 * 0.02) << k;
  }
  EXPECT_NEAR(a.L1, b.L1, 1e-12 * a.L1);
  EXPECT_NEAR(a.L2, b.L2, 1e-12 * a.L2);
  for (PetscReal x : {0.0, 1.1e-3, 7.3e-3}) {
    EXPECT_NEAR(FreeFlightCompression(a, x, 0), FreeFlightCompression(b, x, 0), 1e-12 * 1e-3);
    ModalState e;
    FullState  f;
    FreeFlightModalState(b, x, &e);
    FreeFlightState(b, x, &f);
    EXPECT_EQ(f.ball_y, e.ball_y);
    EXPECT_EQ(f.ball_v, e.ball_v);
    EXPECT_EQ(f.dissipated, e.dissipated);
    const PetscInt d = modes->S.dof[n / 3]; // one free dof, expanded from e by hand
    PetscReal      y = 0, ymax = 0;
    for (PetscInt k = 0; k < nm; ++k) y += modes->B.Phi[(size_t)k * n + n / 3] * e.z[k] / std::sqrt(modes->S.mass[n / 3]);
    for (PetscReal v : f.y) ymax = std::max(ymax, std::abs(v));
    EXPECT_NEAR(f.y[d], y, 1e-13 * ymax) << "s = " << x;
  }
}

// The energy per mode after the ball has left: its sum is the beam's kinetic and strain energy
// of the state the free flight holds (an independent sum over the dofs, the strain energy from
// the strain terms), at the separation and later, for every mode and for the 20 lowest (the
// state is then the kept modes' part); a free beam's two rigid modes come first, with frequency 0.
TEST(FreeFlight, ModeEnergiesSumToTheBeamEnergy)
{
  const BeamSystem sys = SystemOf(AluminiumBeam(1.1, 81));
  for (PetscInt kept : {(PetscInt)0, (PetscInt)20}) {
    std::shared_ptr<const BeamModes> modes;
    ModalTruncation                  t;
    t.modes = kept ? ModalModes::Count : ModalModes::All;
    t.count = kept;
    ASSERT_EQ(0, BeamModesShared(PETSC_COMM_SELF, sys, t, &modes));
    ASSERT_EQ(kept ? kept : sys.ndof, modes->Count());
    FullState s0;
    s0.y.assign(sys.ndof, 0.0);
    s0.v.assign(sys.ndof, 0.0);
    for (PetscInt i = 0; i < sys.nodes; ++i) { // a moving, bent beam: rigid and flexible content
      const PetscReal x = sys.NodeX(i) / sys.L;
      s0.y[sys.Dof(i)]  = 1e-3 * std::sin(3 * M_PI * x) * x;
      s0.v[sys.Dof(i)]  = 0.3 + 0.2 * x + 0.05 * std::cos(7 * M_PI * x);
    }
    s0.ball_y = -1e-3;
    s0.ball_v = -0.5;
    FreeFlight ff;
    FreeFlightStart(modes, BeamSystemCoupling(sys, 0.9), 0.0, s0, &ff);
    for (PetscReal s : {0.0, 3.7e-3}) {
      FullState st;
      FreeFlightState(ff, s, &st);
      const PetscReal E = BeamSystemKineticEnergy(sys, st.v.data(), sys.fields, 0, sys.ndof) + BeamSystemStrainEnergy(sys, st.y.data(), sys.fields, 0, sys.ndof);
      PetscReal       sum = 0;
      const auto      e   = FreeFlightModeEnergies(ff, s);
      ASSERT_EQ((size_t)modes->Count(), e.size());
      for (const ModeEnergy &m : e) sum += m.energy;
      EXPECT_NEAR(E, sum, 1e-12 * E) << "s = " << s << ", modes " << kept;
      EXPECT_TRUE(e[0].rigid && e[1].rigid && !e[2].rigid);
      EXPECT_EQ(0.0, e[0].frequency);
      EXPECT_EQ(0.0, e[1].frequency);
      EXPECT_NEAR(modes->B.omega[2] / (2 * M_PI), e[2].frequency, 1e-12 * e[2].frequency);
      // The translation: P^2 / 2M of the state, P summed over the dofs.
      PetscReal P = 0, Mtot = 0;
      for (PetscInt i = 0; i < sys.nodes; ++i) P += sys.mass[sys.Dof(i)] * st.v[sys.Dof(i)], Mtot += sys.mass[sys.Dof(i)];
      EXPECT_NEAR(P * P / (2 * Mtot), e[0].energy, 1e-12 * E);
    }
  }
}

// The run's problem (run/impact_problem.hpp) reads the modal engine's options once, where a
// consumer of the modes runs, with the run's time scale and load: one truncation for -ts_type
// modal and the free flight (T = ContactTimeScale at the approach speed, the ball's coupling as
// the load), none where nothing uses modes (rk with -impact_after time, or a window of 0 after the
// separation); the modal reference keeps every mode unless -modal_modes is given.
TEST(ImpactProblem, TruncationReadOnceWhereTheModesAreUsed)
{
  Scenario sc{AluminiumBeam(1.1, 41), Superball(), ImpactParams()};
  sc.impact.x     = 0.9;
  sc.impact.after = ImpactAfter::Time;
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-modal_modes", "8"));
  const auto build = [&](const char *ts_type, ImpactMethod method, ImpactProblem *pb) {
    ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-ts_type", ts_type));
    ASSERT_EQ(0, ImpactProblemBuild(PETSC_COMM_WORLD, sc, method, nullptr, pb));
  };
  ImpactProblem pb;
  build("rk", ImpactMethod::Stepped, &pb);
  EXPECT_FALSE(pb.modal_used);
  EXPECT_EQ(pb.truncation.modes, ModalModes::Auto); // not read: the engine's default
  build("modal", ImpactMethod::Stepped, &pb);
  EXPECT_TRUE(pb.modal_used);
  EXPECT_EQ(pb.ts_type, "modal");
  EXPECT_EQ(pb.truncation.modes, ModalModes::Count);
  EXPECT_EQ(pb.truncation.count, 8);
  EXPECT_EQ(pb.truncation.contact_time, ContactTimeScale(sc.ball, sc.ball.speed)); // a beam at rest: v_ball
  EXPECT_EQ(pb.truncation.force_exponent, ContactStartExponent(sc.ball, sc.ball.speed));
  ASSERT_GT(pb.g.n, 0);
  ASSERT_EQ(pb.truncation.at.n, pb.g.n); // weighed under the ball's load (-modal_weight share)
  for (PetscInt q = 0; q < pb.g.n; ++q) EXPECT_EQ(pb.truncation.at.dof[q], pb.g.dof[q]);
  EXPECT_EQ(ImpactProblemPlaneTruncation(pb).at.n, 0); // an oblique hit's second plane: no load
  sc.impact.after = ImpactAfter::Modal;                  // rk, the free flight in modes
  build("rk", ImpactMethod::Stepped, &pb);
  EXPECT_TRUE(pb.after_modal);
  EXPECT_TRUE(pb.modal_used);
  EXPECT_EQ(pb.truncation.count, 8);
  sc.impact.window = 0; // no free flight follows
  build("rk", ImpactMethod::Stepped, &pb);
  EXPECT_FALSE(pb.modal_used);
  build("rk", ImpactMethod::ModalReference, &pb);
  EXPECT_EQ(pb.truncation.modes, ModalModes::Count); // -modal_modes given: the truncated exact solution
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-modal_modes"));
  build("rk", ImpactMethod::ModalReference, &pb);
  EXPECT_EQ(pb.truncation.modes, ModalModes::All); // not given: every mode, the dense one
  ASSERT_EQ(0, PetscOptionsClearValue(NULL, "-ts_type"));
}

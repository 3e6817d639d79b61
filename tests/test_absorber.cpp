// The tuned vibration absorber (-absorber x_a,m_a,f_a,zeta; system/parts/absorber.cpp, docs/model.md),
// the first member of the structure-part registry (system/structure_part.hpp), checked against
// formulas: (a) the system: one more field, free at one node, its spring's row k_a (1, -w, -(1-w)),
// its mass in the rigid body and the free mass, the rigid motions kept; (b) the two-mass closed
// form on a stiff free beam, w^2 = k_a (1/m_a + 1/M_e); (c) MODEL.md section 16's split of a mode by
// an undamped tuned absorber, (f+-/f)^2 = 1 + mu/2 +- sqrt(mu + mu^2/4), and a negligible mass
// leaving the modes; (d) Den Hartog's optimum: two equal receptance peaks of K - w^2 M + i w C
// near sqrt(1 + 2/mu) times the static modal deflection; (e) a free beam struck with the dashpot:
// the energy closes (rk4, error falling as dt^4), momentum and angular momentum kept to round-off,
// the dashpot's work in beam_dissipated_end; (f) the modal tools refuse the dashpot; (g) without
// -absorber no column of it applies.
#include "run/modal_reference.hpp"
#include "run/results_table.hpp"
#include "solvers/modes.hpp"
#include "system/structure_part.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <complex>
#include <cstdio>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {

const PetscReal kPi = PETSC_PI;

// The beam with an absorber, through the part's own option module (as -absorber would).
BeamParams WithAbsorber(BeamParams p, PetscReal x, PetscReal m, PetscReal f, PetscReal zeta)
{
  const StructurePart *part = StructurePartFind("absorber");
  EXPECT_NE(part, nullptr);
  PartOptionValues v;
  v.given["-absorber"] = {x, m, f, zeta};
  std::shared_ptr<const PartParams> q;
  std::string                       why;
  EXPECT_TRUE(part->Configure(v, p, &q, &why)) << why;
  p.parts.Set("absorber", q);
  return p;
}

std::string Refusal(const BeamParams &p, std::vector<PetscReal> values)
{
  PartOptionValues v;
  v.given["-absorber"] = values;
  std::shared_ptr<const PartParams> q;
  std::string                       why;
  EXPECT_FALSE(StructurePartFind("absorber")->Configure(v, p, &q, &why));
  return why;
}

ModesResult Modes(const BeamSystem &sys, PetscInt count, std::vector<std::vector<PetscReal>> *shapes = nullptr)
{
  ModesResult r;
  EXPECT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, count, &r, shapes));
  return r;
}

// The driving-point receptance |y_d / F| (m/N) of dof d at angular frequency w: (K - w^2 M + i w C) y
// = e_d over the free dofs, solved densely (Gaussian elimination with partial pivoting).
PetscReal Receptance(const BeamSystem &sys, PetscInt d, PetscReal w)
{
  std::vector<PetscInt> freedofs, index(sys.ndof, -1);
  for (PetscInt q = 0; q < sys.ndof; ++q)
    if (!sys.held[q]) index[q] = (PetscInt)freedofs.size(), freedofs.push_back(q);
  const size_t                      n = freedofs.size();
  std::vector<std::complex<double>> A(n * n, 0.0), b(n, 0.0);
  PetscInt                          cols[64];
  PetscReal                         vals[64];
  for (size_t r = 0; r < n; ++r) {
    const PetscInt i = freedofs[r];
    A[r * n + r] -= w * w * sys.mass[i];
    for (PetscInt k = 0, c = BeamSystemStiffnessRow(sys, i, cols, vals); k < c; ++k) A[r * n + index[cols[k]]] += vals[k];
    for (PetscInt k = 0, c = BeamSystemDampingRow(sys, i, cols, vals); k < c; ++k)
      A[r * n + index[cols[k]]] += std::complex<double>(0, w * vals[k]);
  }
  b[index[d]] = 1;
  for (size_t k = 0; k < n; ++k) {
    size_t p = k;
    for (size_t r = k + 1; r < n; ++r)
      if (std::abs(A[r * n + k]) > std::abs(A[p * n + k])) p = r;
    for (size_t c = 0; c < n; ++c) std::swap(A[k * n + c], A[p * n + c]);
    std::swap(b[k], b[p]);
    for (size_t r = k + 1; r < n; ++r) {
      const std::complex<double> f = A[r * n + k] / A[k * n + k];
      for (size_t c = k; c < n; ++c) A[r * n + c] -= f * A[k * n + c];
      b[r] -= f * b[k];
    }
  }
  for (size_t k = n; k-- > 0;) {
    for (size_t c = k + 1; c < n; ++c) b[k] -= A[k * n + c] * b[c];
    b[k] /= A[k * n + k];
  }
  return std::abs(b[index[d]]);
}

} // namespace

// (a) One more field, free only at x_a's left node, of mass m_a; its spring's row is k_a times
// (1, -w, -(1 - w)) on (u, y_j, y_j+1); m_a joins the rigid body and the free mass; a free beam keeps
// its two rigid motions (the spring is internal).
TEST(Absorber, SystemCarriesTheMassOnItsSpring)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const PetscReal  x = 0.09, m = 0.05, f = 40, h = 1.1 / 40, w = 1 - (x - 3 * h) / h; // between nodes 3 and 4
  const BeamSystem bare = SystemOf(beam), sys = SystemOf(WithAbsorber(beam, x, m, f, 0));
  ASSERT_EQ(sys.fields, bare.fields + 1);
  PetscInt free_u = 0, u = -1;
  for (PetscInt i = 0; i < sys.nodes; ++i)
    if (!sys.held[sys.Dof(i, 1)]) ++free_u, u = sys.Dof(i, 1);
  ASSERT_EQ(free_u, 1);
  EXPECT_EQ(u, sys.Dof(3, 1));
  EXPECT_EQ(sys.mass[u], m);
  const PetscReal k = m * std::pow(2 * kPi * f, 2);
  PetscInt        cols[64];
  PetscReal       vals[64];
  const PetscInt  n = BeamSystemStiffnessRow(sys, u, cols, vals);
  ASSERT_EQ(n, 3);
  const PetscInt  expect_cols[3] = {sys.Dof(3), u, sys.Dof(4)};
  const PetscReal expect_vals[3] = {-k * w, k, -k * (1 - w)};
  for (PetscInt q = 0; q < 3; ++q) {
    EXPECT_EQ(cols[q], expect_cols[q]);
    EXPECT_NEAR(vals[q], expect_vals[q], 1e-12 * k);
  }
  EXPECT_NEAR(BeamSystemFreeMass(sys), BeamSystemFreeMass(bare) + m, 1e-14);
  const BeamRigidBody b0 = BeamRigidBodyOf(beam), b1 = BeamRigidBodyOf(WithAbsorber(beam, x, m, f, 0));
  EXPECT_NEAR(b1.mass, b0.mass + m, 1e-14);
  EXPECT_NEAR(b1.x_cm, (b0.mass * b0.x_cm + m * x) / (b0.mass + m), 1e-14);
  EXPECT_NEAR(b1.inertia_end, b0.inertia_end + m * x * x, 1e-14);
  EXPECT_EQ(BeamSystemRigidMotions(sys).size(), 2u) << "translation and rotation, the absorber carried along";
}

// (b) A free, very stiff beam (EI x 1e6: its flexible modes above 20 kHz) is a rigid body of mass
// M_e at x_a (1/M_e = 1/M + (x_a - x_cm)^2 / I_cm, from the lumped masses); with the absorber the
// lowest flexible mode is the two-mass one, w^2 = k_a (1/m_a + 1/M_e).
TEST(Absorber, TwoMassClosedFormOnAStiffFreeBeam)
{
  BeamParams beam = AluminiumBeam(1.1, 41);
  beam.EI *= 1e6;
  for (const PetscReal x : {0.0, 0.0825, 0.55, 1.0}) {
    const PetscReal  m = 0.04, f = 35;
    const BeamSystem sys = SystemOf(WithAbsorber(beam, x, m, f, 0));
    PetscReal        M = 0, Mx = 0, Mxx = 0;
    for (PetscInt i = 0; i < sys.nodes; ++i) {
      const PetscReal mi = sys.mass[sys.Dof(i)], xi = i * sys.h;
      M += mi, Mx += mi * xi, Mxx += mi * xi * xi;
    }
    const PetscReal x_cm = Mx / M, I_cm = Mxx - M * x_cm * x_cm;
    const PetscReal M_e = 1 / (1 / M + (x - x_cm) * (x - x_cm) / I_cm), k = m * std::pow(2 * kPi * f, 2);
    const PetscReal expect = std::sqrt(k * (1 / m + 1 / M_e));
    const ModesResult r    = Modes(sys, 3);
    EXPECT_EQ(r.rigid_count, 2) << x;
    std::printf("two-mass: x_a %g m: omega %.10g rad/s, closed form %.10g rad/s\n", x, r.omega[2], expect);
    EXPECT_NEAR(r.omega[2] / expect, 1.0, 1e-6) << "x_a " << x << ": " << r.omega[2] << " rad/s against " << expect;
  }
}

// (c) A pinned-pinned beam's fundamental f (mass-normalised shape phi, phi(L/2)^2 = 2/M) with an
// undamped absorber tuned to f at midspan, mu = m_a phi(x_a)^2: the mode splits into
// (f+-/f)^2 = 1 + mu/2 +- sqrt(mu + mu^2/4) (MODEL.md section 16), to the next symmetric mode's
// share, O(mu f^2/(f_3^2 - f^2)) ~ 1e-4 at mu = 0.01; a negligible mass (1e-10 kg: mu ~ 4e-10) leaves
// the beam's modes unchanged to 1e-9.
TEST(Absorber, TunedAbsorberSplitsTheMode)
{
  const BeamParams                    beam = AluminiumBeam(1.1, 41, Support::Pinned, Support::Pinned);
  std::vector<std::vector<PetscReal>> shapes;
  const ModesResult                   bare = Modes(SystemOf(beam), 4, &shapes);
  const PetscReal                     f = bare.frequency[0], phi = shapes[0][20];
  for (const PetscReal mu : {0.01, 0.04}) {
    const PetscReal   m = mu / (phi * phi);
    const ModesResult r = Modes(SystemOf(WithAbsorber(beam, 0.55, m, f, 0)), 3);
    const PetscReal   lo = 1 + mu / 2 - std::sqrt(mu + mu * mu / 4), hi = 1 + mu / 2 + std::sqrt(mu + mu * mu / 4);
    std::printf("split: mu %g: (f-/f)^2 %.6f (formula %.6f), (f+/f)^2 %.6f (formula %.6f)\n", mu,
                std::pow(r.frequency[0] / f, 2), lo, std::pow(r.frequency[1] / f, 2), hi);
    EXPECT_NEAR(std::pow(r.frequency[0] / f, 2), lo, 2 * mu * 1.0 / 80) << "mu " << mu;
    EXPECT_NEAR(std::pow(r.frequency[1] / f, 2), hi, 2 * mu * 1.0 / 80) << "mu " << mu;
    EXPECT_NEAR(r.frequency[2] / bare.frequency[1], 1.0, 1e-9) << "the antisymmetric mode has a node at x_a";
  }
  const ModesResult light = Modes(SystemOf(WithAbsorber(beam, 0.3, 1e-10, 1e4, 0)), 4);
  for (PetscInt k = 0; k < 4; ++k) EXPECT_NEAR(light.frequency[k] / bare.frequency[k], 1.0, 1e-9) << k;
}

// (d) Den Hartog's optimum for the fundamental of the pinned-pinned beam (mu = 0.05): f_a = f/(1 + mu),
// zeta = sqrt(3 mu / (8 (1 + mu)^3)). The driving-point receptance at x_a has two peaks, equal to a
// few %, each near sqrt(1 + 2/mu) phi^2 / w^2 (the static modal deflection times Den Hartog's
// amplification).
TEST(Absorber, DenHartogOptimumGivesEqualPeaks)
{
  const BeamParams                    beam = AluminiumBeam(1.1, 41, Support::Pinned, Support::Pinned);
  std::vector<std::vector<PetscReal>> shapes;
  const ModesResult                   bare = Modes(SystemOf(beam), 1, &shapes);
  const PetscReal  f = bare.frequency[0], phi = shapes[0][20], mu = 0.05, m = mu / (phi * phi);
  const PetscReal  zeta = std::sqrt(3 * mu / (8 * std::pow(1 + mu, 3)));
  const BeamSystem sys  = SystemOf(WithAbsorber(beam, 0.55, m, f / (1 + mu), zeta));
  ASSERT_TRUE(sys.Damped());
  const PetscInt         d = sys.Dof(20);
  const PetscReal        w1 = 2 * kPi * f;
  std::vector<PetscReal> H;
  const int              n = 6000;
  for (int k = 0; k <= n; ++k) H.push_back(Receptance(sys, d, w1 * (0.7 + 0.6 * k / n)));
  std::vector<PetscReal> peaks;
  for (int k = 1; k < n; ++k)
    if (H[k] > H[k - 1] && H[k] >= H[k + 1]) peaks.push_back(H[k]);
  ASSERT_EQ(peaks.size(), 2u) << "two peaks around f";
  std::printf("Den Hartog: peaks %.6g and %.6g m/N, sqrt(1 + 2/mu) phi^2/w^2 = %.6g m/N\n", peaks[0], peaks[1],
              std::sqrt(1 + 2 / mu) * phi * phi / (w1 * w1));
  EXPECT_NEAR(peaks[0] / peaks[1], 1.0, 0.03) << peaks[0] << " and " << peaks[1] << " m/N";
  const PetscReal den_hartog = std::sqrt(1 + 2 / mu) * phi * phi / (w1 * w1);
  for (PetscReal p : peaks) EXPECT_NEAR(p / den_hartog, 1.0, 0.05) << p << " m/N against " << den_hartog;
}

// (e) A free beam struck by the ball, the absorber damped: the energy closes with the dashpot's
// work (rk4 at a fixed step: its error falls ~16x when dt halves), momentum and angular momentum
// are kept to round-off (the spring and dashpot are internal), and the dashpot dissipates. (Tuned
// near the beam's fundamental, the absorber keeps drawing energy from it over the 20 ms.)
TEST(Absorber, EnergyClosesAndMomentumIsKeptOnAFreeBeam)
{
  const BeamParams beam = WithAbsorber(AluminiumBeam(1.1, 41), 0.0825, 0.05, 30, 0.1);
  BallParams       ball = Superball("linear");
  ImpactParams     ip;
  ip.x      = 0.9;
  ip.window = 0.02; // past the absorber's first swings (30 Hz)
  PetscReal err[2];
  for (int k = 0; k < 2; ++k) {
    const char        *dt = k ? "4e-6" : "8e-6";
    const ImpactResult r  = RunImpact(PETSC_COMM_WORLD, beam, ball, ip,
                                      {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", dt}});
    err[k]                = std::abs(r.energy_error);
    EXPECT_LT(std::abs(r.linear_momentum_error), 1e-12) << dt;
    EXPECT_LT(std::abs(r.angular_momentum_error), 1e-12) << dt;
    EXPECT_GT(r.beam_dissipated_end, 1e-3 * r.energy_in) << "the dashpot's work";
    EXPECT_GE(ImpactResultColumn("absorber_energy_peak")->Get(r), ImpactResultColumn("absorber_energy_end")->Get(r));
    EXPECT_GT(ImpactResultColumn("absorber_stroke_peak")->Get(r), 0);
  }
  std::printf("energy error %.3g at dt 8e-6 s, %.3g at 4e-6 s (ratio %.1f)\n", err[0], err[1], err[0] / err[1]);
  EXPECT_LT(err[1], 1e-7);
  EXPECT_GT(err[0] / err[1], 10) << err[0] << " at 8e-6 s, " << err[1] << " at 4e-6 s";
}

// (f) The dashpot is not proportional damping: the modal reference and -ts_type modal refuse it;
// undamped, the modal reference carries the absorber and agrees with rk4.
TEST(Absorber, ModalToolsRefuseTheDashpot)
{
  Scenario sc;
  sc.beam     = WithAbsorber(AluminiumBeam(1.1, 41), 0.0825, 0.05, 30, 0.1);
  sc.ball     = Superball("linear");
  sc.impact.x = 0.9;
  std::string why;
  EXPECT_FALSE(ModalReferenceApplies(sc, &why));
  EXPECT_NE(why.find("-absorber"), std::string::npos) << why;
  std::string why_ts;
  EXPECT_FALSE(ForceOperatorModal(SystemOf(sc.beam), nullptr, nullptr, &why_ts));
  EXPECT_NE(why_ts.find("-absorber"), std::string::npos) << why_ts;
  sc.beam = WithAbsorber(AluminiumBeam(1.1, 41), 0.0825, 0.05, 30, 0);
  EXPECT_TRUE(ModalReferenceApplies(sc, &why)) << why;
  sc.impact.window = 0;
  ImpactResult ref;
  ASSERT_EQ(0, ModalReferenceRun(sc, &ref));
  const ImpactResult rk = RunImpact(PETSC_COMM_WORLD, sc.beam, sc.ball, sc.impact,
                                    {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-6"}});
  std::printf("modal reference acor %.10f, rk4 %.10f\n", ref.acor, rk.acor);
  EXPECT_NEAR(rk.acor, ref.acor, 1e-6) << "the exact modal reference and rk4 on the same absorber";
  EXPECT_NEAR(ImpactResultColumn("absorber_energy_end")->Get(rk), ImpactResultColumn("absorber_energy_end")->Get(ref),
              1e-6 * rk.energy_in);
}

// (g) Refusals name -absorber and the value; without -absorber none of its columns applies.
TEST(Absorber, RefusalsAndAbsence)
{
  const BeamParams beam = AluminiumBeam(1.1, 41, Support::Clamped, Support::Free);
  EXPECT_NE(Refusal(beam, {1.2, 0.05, 30, 0}).find("off the beam"), std::string::npos);
  EXPECT_NE(Refusal(beam, {0.5, 0, 30, 0}).find("m_a = 0 kg must be > 0"), std::string::npos);
  EXPECT_NE(Refusal(beam, {0.5, 0.05, -1, 0}).find("f_a = -1 Hz must be > 0"), std::string::npos);
  EXPECT_NE(Refusal(beam, {0.5, 0.05, 30, -0.1}).find("zeta = -0.1 must be >= 0"), std::string::npos);
  EXPECT_NE(Refusal(beam, {0, 0.05, 30, 0}).find("on a held node"), std::string::npos);
  Scenario sc;
  sc.beam = AluminiumBeam(1.1, 41);
  for (const ResultColumn &c : ImpactResultColumns())
    if (c.owner == StructurePartFind("absorber")) {
      EXPECT_FALSE(c.Applies(sc)) << c.name;
      EXPECT_STREQ(c.applies_text, "with -absorber") << c.name;
    }
  sc.beam = WithAbsorber(sc.beam, 0.5, 0.05, 30, 0);
  EXPECT_TRUE(ImpactResultColumn("absorber_energy_end")->Applies(sc));
}

// The semi-discrete system (system/beam_system.hpp) and its force operator
// (system/force_operator.hpp) against formulas: the clamped region's mirror rows, mode
// frequencies against the beta L tables at second order in h, the Timoshenko element rows,
// the grip's springs, dampers and hands on the diagonal, Rayleigh C = alpha M + beta K on
// random vectors, the dissipation rate v^T C v (relative to the swing's frame for the grip),
// the affine form f = K y + C v + f(0, 0, t) and its Jacobians, the hands' work as the frame's
// momentum term, the dissipation rule on cubics, the contact coupling as a list; and the
// system's own invariants (factored action = band, U = y^T K y / 2, rigid motions force-free).
#include "solvers/modal_basis.hpp"
#include "system/beam_system.hpp"
#include "system/dissipation.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
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

// Dense matrices (ndof x ndof, row-major) from the rows of K and C.
std::vector<PetscReal> Dense(const BeamSystem &S, bool damping)
{
  std::vector<PetscReal> A((size_t)S.ndof * S.ndof, 0.0);
  std::vector<PetscInt>  c(2 * S.bw + 1);
  std::vector<PetscReal> v(2 * S.bw + 1);
  for (PetscInt i = 0; i < S.ndof; ++i) {
    const PetscInt n = damping ? BeamSystemDampingRow(S, i, c.data(), v.data()) : BeamSystemStiffnessRow(S, i, c.data(), v.data());
    for (PetscInt q = 0; q < n; ++q) A[(size_t)i * S.ndof + c[q]] = v[q];
  }
  return A;
}

std::vector<PetscReal> MatVec(const std::vector<PetscReal> &A, const std::vector<PetscReal> &x)
{
  const size_t           n = x.size();
  std::vector<PetscReal> y(n, 0.0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) y[i] += A[i * n + j] * x[j];
  return y;
}

PetscReal MaxAbs(const std::vector<PetscReal> &a)
{
  PetscReal m = 0;
  for (PetscReal x : a) m = std::max(m, std::abs(x));
  return m;
}

std::vector<PetscReal> Random(const BeamSystem &S, unsigned seed, PetscReal scale)
{
  std::mt19937                     gen(seed);
  std::uniform_real_distribution<> u(-scale, scale);
  std::vector<PetscReal>           y(S.ndof);
  for (PetscInt i = 0; i < S.ndof; ++i) y[i] = S.held[i] ? 0.0 : u(gen);
  return y;
}


// omega^2 (ascending) of K phi = omega^2 M phi over the free dofs: M^{-1/2} K M^{-1/2}.
std::vector<PetscReal> Omega2(const BeamSystem &S)
{
  const std::vector<PetscReal> K = Dense(S, false);
  std::vector<PetscInt>        f;
  for (PetscInt i = 0; i < S.ndof; ++i)
    if (!S.held[i]) f.push_back(i);
  const PetscInt         n = (PetscInt)f.size();
  std::vector<PetscReal> A(n * n);
  for (PetscInt a = 0; a < n; ++a)
    for (PetscInt b = 0; b < n; ++b) A[a * n + b] = K[(size_t)f[a] * S.ndof + f[b]] / std::sqrt(S.mass[f[a]] * S.mass[f[b]]);
  return JacobiEigenvalues(A, n);
}

// The paper's beam, free-free, held by the hands over [0, 0.15] m, Rayleigh-damped, and a swing's
// frame (a rigid motion) for it.
BeamGrip Hands()
{
  BeamGrip g;
  g.on = true, g.x_a = 0.0, g.x_b = 0.15, g.stiffness = 1e5, g.damping = 100, g.mass = 0.2;
  return g;
}
BeamParams GrippedDamped(const BeamGrip &g = Hands())
{
  BeamParams p        = AluminiumBeam(1.1, 23);
  p.damping_mass      = 3.0;
  p.damping_stiffness = 2e-6;
  return WithGrip(p, g);
}
// The share of node i in the grip g: |[x_i - h/2, x_i + h/2] n [x_a, x_b] n [0, L]| (m).
PetscReal GripShare(const BeamGrip &g, const BeamSystem &S, PetscInt i)
{
  const PetscReal a = std::max({0.0, (i - 0.5) * S.h, g.x_a}), b = std::min({S.L, (i + 0.5) * S.h, g.x_b});
  return std::max(0.0, b - a);
}
FrameMotion Swing(const BeamSystem &S)
{
  FrameMotion f;
  f.v = BeamSystemRigidVelocity(S, -0.7, -1.5);
  return f;
}

} // namespace

// At the inner edge of a clamped region (node c held with zero slope, c - 1 free), the mirror
// ghost y_{c+1} = y_{c-1} (docs/model.md, section 6) gives the rows of the clamped end:
// row c-1 = EI/h^3 (1, -4, 7), row c-2 = EI/h^3 (1, -4, 6, -4) (the held column dropped).
TEST(System, ClampedRegionEdgeRowsAreTheMirrorRows)
{
  BeamParams p = AluminiumBeam(1.1, 56); // h = 2 cm
  p.has_clamp  = true;
  p.clamp_x0   = 0.9;
  p.clamp_x1   = 1.1;
  const BeamSystem S = SystemOf(p);
  const PetscInt   c = 45; // x = 0.9
  ASSERT_TRUE(S.held[c]);
  ASSERT_FALSE(S.held[c - 1]);
  const PetscReal unit = p.EI / std::pow(S.h, 3);
  PetscInt        cols[5];
  PetscReal       vals[5];
  const struct {
    PetscInt               row;
    std::vector<PetscReal> v;
  } rows[] = {{c - 1, {1, -4, 7}}, {c - 2, {1, -4, 6, -4}}};
  for (const auto &r : rows) {
    const PetscInt n = BeamSystemStiffnessRow(S, r.row, cols, vals);
    ASSERT_EQ((PetscInt)r.v.size(), n) << "row " << r.row;
    for (PetscInt q = 0; q < n; ++q) {
      EXPECT_EQ(r.row - 2 + q, cols[q]);
      EXPECT_NEAR(r.v[q] * unit, vals[q], 1e-12 * unit) << "row " << r.row << " col " << cols[q];
    }
  }
  EXPECT_EQ(0, BeamSystemStiffnessRow(S, c, cols, vals));
}

// The flexural frequencies of the discrete beam converge to (beta_n L)^2 sqrt(EI/mu)/L^2 at
// second order in h: the error falls by 4 when h halves (free-free and clamped-free, modes 1-3).
TEST(System, ModeFrequenciesConvergeAtSecondOrder)
{
  const struct {
    Support   left;
    PetscInt  rigid;
    PetscReal betaL[3];
  } cases[] = {{Support::Free, 2, {4.730040745, 7.853204624, 10.99560784}}, {Support::Clamped, 0, {1.875104069, 4.694091133, 7.854757438}}};
  for (const auto &c : cases) {
    PetscReal err[2][3];
    for (int level = 0; level < 2; ++level) {
      const BeamParams             p = AluminiumBeam(1.1, level ? 41 : 21, c.left, Support::Free);
      const std::vector<PetscReal> w2 = Omega2(SystemOf(p));
      const PetscReal              unit = std::sqrt(p.EI / p.mu) / (p.length * p.length);
      for (PetscInt r = 0; r < c.rigid; ++r) EXPECT_LT(std::abs(w2[r]), 1e-9 * w2.back()) << "rigid mode " << r;
      EXPECT_GT(w2[c.rigid], 1e-3 * unit * unit);
      for (int k = 0; k < 3; ++k) err[level][k] = std::sqrt(w2[c.rigid + k]) / (c.betaL[k] * c.betaL[k] * unit) - 1;
    }
    for (int k = 0; k < 3; ++k) {
      const PetscReal ratio = err[0][k] / err[1][k];
      EXPECT_GT(ratio, 3.6) << SupportName(c.left) << " mode " << k + 1;
      EXPECT_LT(ratio, 4.4) << SupportName(c.left) << " mode " << k + 1;
      EXPECT_LT(std::abs(err[1][k]), 0.03) << SupportName(c.left) << " mode " << k + 1;
    }
  }
}

// Timoshenko (model/timoshenko.cpp): one-point shear and exact bending per element give, at an
// interior node i (dofs w_i, psi_i), the rows
//   w_i:   w_{i-1} -kGA/h, psi_{i-1} -kGA/2, w_i 2 kGA/h, psi_i 0, w_{i+1} -kGA/h, psi_{i+1} kGA/2
//   psi_i: w_{i-1} kGA/2, psi_{i-1} -EI/h + kGA h/4, w_i 0, psi_i 2 EI/h + kGA h/2,
//          w_{i+1} -kGA/2, psi_{i+1} -EI/h + kGA h/4
// and the lumped masses rho A h and rho I h (half at the ends).
TEST(System, TimoshenkoRows)
{
  BeamParams p = AluminiumBeam(1.1, 21);
  p.theory     = "timoshenko";
  p.kGA        = 5e6; // N
  p.rhoI       = 2e-5; // kg m
  const BeamSystem S = SystemOf(p);
  ASSERT_EQ(2, S.fields);
  const PetscReal h = S.h, k = p.kGA, EI = p.EI, i0 = 7;
  PetscInt        cols[16];
  PetscReal       vals[16];
  auto            row = [&](PetscInt d) {
    std::map<PetscInt, PetscReal> r;
    const PetscInt                n = BeamSystemStiffnessRow(S, d, cols, vals);
    for (PetscInt q = 0; q < n; ++q) r[cols[q]] = vals[q];
    return r;
  };
  const PetscInt w = S.Dof(i0, 0), s = S.Dof(i0, 1);
  const std::map<PetscInt, PetscReal> expect_w = {{w - 2, -k / h}, {w - 1, -k / 2}, {w + 2, -k / h}, {w + 3, k / 2}, {w, 2 * k / h}};
  const std::map<PetscInt, PetscReal> expect_s = {{s - 3, k / 2}, {s - 2, -EI / h + k * h / 4}, {s, 2 * EI / h + k * h / 2}, {s + 1, -k / 2}, {s + 2, -EI / h + k * h / 4}};
  for (const auto &c : {std::make_pair(w, expect_w), std::make_pair(s, expect_s)}) {
    const auto r = row(c.first);
    EXPECT_EQ(c.second.size(), r.size()) << "dof " << c.first;
    for (const auto &e : c.second) {
      ASSERT_TRUE(r.count(e.first)) << "dof " << c.first << " col " << e.first;
      EXPECT_NEAR(e.second, r.at(e.first), 1e-12 * std::abs(e.second)) << "dof " << c.first << " col " << e.first;
    }
  }
  EXPECT_NEAR(p.mu * h, S.mass[w], 1e-15);
  EXPECT_NEAR(p.rhoI * h, S.mass[s], 1e-18);
  EXPECT_NEAR(0.5 * p.rhoI * h, S.mass[1], 1e-18);
}

// The grip over [x_a, x_b]: node i gets the share w_i = |[x_i - h/2, x_i + h/2] n [x_a, x_b]|
// of the span, the spring k' w_i on K's diagonal, the damper c' w_i on C's, and the hands' mass
// m_hand w_i / (x_b - x_a); nothing else changes.
TEST(System, GripSpringsDampersAndHandsOnTheDiagonal)
{
  BeamGrip g          = Hands();
  g.x_a               = 0.03; // not on a node: shares of partial cells
  g.x_b               = 0.17;
  BeamParams p        = GrippedDamped(g);
  p.damping_mass      = 0;
  p.damping_stiffness = 0;
  BeamParams free_p   = WithoutGrip(p);
  const BeamSystem G = SystemOf(p), F = SystemOf(free_p);
  ASSERT_TRUE(G.TiedToFrame());
  ASSERT_FALSE(F.TiedToFrame());
  ASSERT_TRUE(G.Damped());
  ASSERT_FALSE(F.Damped());
  const std::vector<PetscReal> KG = Dense(G, false), KF = Dense(F, false), CG = Dense(G, true);
  PetscReal                    span = 0;
  for (PetscInt i = 0; i < G.nodes; ++i) {
    const PetscReal wi = GripShare(g, G, i);
    span += wi;
    for (PetscInt j = 0; j < G.ndof; ++j) {
      const size_t ij = (size_t)i * G.ndof + j;
      EXPECT_NEAR(KG[ij] - KF[ij], i == j ? g.stiffness * wi : 0.0, 1e-12 * std::abs(KF[(size_t)i * G.ndof + i])) << i << "," << j;
      EXPECT_NEAR(CG[ij], i == j ? g.damping * wi : 0.0, 1e-12 * g.damping * G.h) << i << "," << j;
    }
    EXPECT_NEAR(G.mass[i] - F.mass[i], g.mass * wi / (g.x_b - g.x_a), 1e-15) << "node " << i;
  }
  EXPECT_NEAR(span, g.x_b - g.x_a, 1e-15);
}

// C = alpha M + beta K: its rows, its action on random vectors (with and without a frame at
// rest), and the dissipation rate v^T C v as a sum of squares that adds up over a partition.
TEST(System, RayleighDampingIsAlphaMPlusBetaK)
{
  const PetscReal alpha = 7.0, beta = 3e-5;
  for (BeamParams p : Configurations()) {
    const BeamSystem K0 = SystemOf(p);
    p.damping_mass      = alpha;
    p.damping_stiffness = beta;
    const BeamSystem             S = SystemOf(p);
    const std::vector<PetscReal> K = Dense(K0, false), C = Dense(S, true);
    ASSERT_TRUE(S.Damped());
    const PetscReal kmax = MaxAbs(K);
    for (PetscInt i = 0; i < S.ndof; ++i)
      for (PetscInt j = 0; j < S.ndof; ++j) {
        const PetscReal expect = S.held[i] || S.held[j] ? 0.0 : (i == j ? alpha * S.mass[i] : 0.0) + beta * K[(size_t)i * S.ndof + j];
        ASSERT_NEAR(expect, C[(size_t)i * S.ndof + j], 1e-13 * beta * kmax) << i << "," << j;
      }
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const std::vector<PetscReal> v = Random(S, seed, 1.0), kv = MatVec(K, v);
      std::vector<PetscReal>       cv(S.ndof);
      BeamSystemDampingApply(S, v.data(), 1, 0, S.ndof, cv.data(), 1);
      PetscReal vcv = 0, scale = 0;
      for (PetscInt i = 0; i < S.ndof; ++i) {
        const PetscReal expect = S.held[i] ? 0.0 : alpha * S.mass[i] * v[i] + beta * kv[i];
        scale                  = std::max(scale, std::abs(alpha * S.mass[i] * v[i]) + std::abs(beta * kv[i]));
        EXPECT_NEAR(expect, cv[i], 1e-12 * scale) << "dof " << i;
        vcv += v[i] * (alpha * S.mass[i] * v[i] + beta * kv[i]);
      }
      const PetscReal rate = BeamSystemDissipationRate(S, v.data(), 1, 0, S.ndof);
      EXPECT_GT(rate, 0.0);
      EXPECT_NEAR(vcv, rate, 1e-12 * rate);
      const PetscInt cut = S.ndof / 3;
      EXPECT_NEAR(rate, BeamSystemDissipationRate(S, v.data(), 1, 0, cut) + BeamSystemDissipationRate(S, v.data(), 1, cut, S.ndof), 1e-13 * rate);
    }
  }
}

// Every term is affine in (y, v): f(y, v, t) = K y + C (v - v_f) + k (-v_f t) over the grip,
// i.e. K y + C v + f(0, 0, t), with K and C the assembled Jacobians; checked for the gripped,
// damped beam with a moving frame, over a partition of the dofs (as ranks), at two times.
TEST(ForceOperator, ForceIsAffineWithItsJacobians)
{
  const BeamGrip g = Hands();
  const BeamParams             p     = GrippedDamped();
  const BeamSystem             S     = SystemOf(p);
  const FrameMotion            frame = Swing(S);
  const std::vector<PetscReal> K = Dense(S, false), C = Dense(S, true);
  for (PetscReal t : {0.0, 3e-3}) {
    const std::vector<PetscReal> y = Random(S, 5, 1e-3), v = Random(S, 6, 1.0), ky = MatVec(K, y), cv = MatVec(C, v);
    std::vector<PetscReal>       f(S.ndof), drive(S.ndof);
    ForceState                   s;
    s.y = y.data(), s.v = v.data(), s.t = t, s.frame = &frame;
    const PetscInt cut = 9;
    ForceOperatorApply(S, s, 0, cut, f.data(), 1);
    ForceOperatorApply(S, s, cut, S.ndof, f.data(), 1);
    ForceOperatorDrive(S, t, &frame, 0, S.ndof, drive.data(), 1);
    PetscReal scale = 0;
    for (PetscInt i = 0; i < S.ndof; ++i) scale = std::max(scale, std::abs(ky[i]) + std::abs(cv[i]));
    for (PetscInt i = 0; i < S.ndof; ++i) {
      // the drive by its formula: -k_i v_f,i t - c_i v_f,i on the gripped nodes
      const PetscReal k_i = g.stiffness * GripShare(g, S, i), c_i = g.damping * GripShare(g, S, i);
      EXPECT_NEAR(-k_i * frame.v[i] * t - c_i * frame.v[i], drive[i], 1e-14 * (std::abs(k_i * frame.v[i] * t) + std::abs(c_i * frame.v[i]))) << "dof " << i;
      EXPECT_NEAR(ky[i] + cv[i] + drive[i], f[i], 1e-12 * scale) << "t " << t << " dof " << i;
    }
  }
}

// The dissipation rate with the frame: alpha v^T M v + beta v^T K v + sum c_i (v_i - v_f,i)^2
// (the grip's dampers resist the motion relative to the hands), never negative; and the damping
// force C (v - v_ref) whose product with v gives it.
TEST(ForceOperator, DissipationRateIsRelativeToTheFrame)
{
  const BeamGrip g = Hands();
  BeamParams       p = GrippedDamped();
  const BeamSystem S = SystemOf(p);
  BeamParams       q = p;
  q                = WithoutGrip(q);
  q.damping_mass   = 0;
  q.damping_stiffness = 0;
  const BeamSystem             F     = SystemOf(q); // K of the beam alone
  const FrameMotion            frame = Swing(S);
  const std::vector<PetscReal> K = Dense(F, false);
  const std::vector<PetscReal> v = Random(S, 8, 1.0), kv = MatVec(K, v);
  PetscReal                    expect = 0, cv_expect = 0;
  for (PetscInt i = 0; i < S.ndof; ++i) {
    const PetscReal c_i = g.damping * GripShare(g, S, i); // the grip's damper
    const PetscReal u   = v[i] - frame.v[i];
    expect += p.damping_mass * S.mass[i] * v[i] * v[i] + p.damping_stiffness * v[i] * kv[i] + c_i * u * u;
    cv_expect += v[i] * (p.damping_mass * S.mass[i] * v[i] + p.damping_stiffness * kv[i] + c_i * u);
  }
  ForceState s;
  s.v = v.data(), s.frame = &frame;
  const PetscReal rate = ForceOperatorDissipationRate(S, s, 0, S.ndof);
  EXPECT_NEAR(expect, rate, 1e-12 * rate);
  std::vector<PetscReal> cv(S.ndof);
  ForceOperatorDampingApply(S, s, 0, S.ndof, cv.data(), 1);
  PetscReal vcv = 0;
  for (PetscInt i = 0; i < S.ndof; ++i) vcv += v[i] * cv[i];
  EXPECT_NEAR(cv_expect, vcv, 1e-12 * std::abs(cv_expect));
  // v equal to the frame's velocity (a rigid motion): only alpha dissipates
  s.v = frame.v.data();
  PetscReal rigid = 0;
  for (PetscInt i = 0; i < S.ndof; ++i) rigid += p.damping_mass * S.mass[i] * frame.v[i] * frame.v[i];
  EXPECT_NEAR(rigid, ForceOperatorDissipationRate(S, s, 0, S.ndof), 1e-10 * rigid);
}

// The hands' work in closed form: along the equations M a = -f (no ball), the frame's momentum
// term Q = v_f^T M v + alpha v_f^T M y changes at the rate of the power the frame puts in,
// dQ/dt = v_f^T M a + alpha v_f^T M v = -sum v_f,i f_grip,i; and the force on the frame and its
// moment are the grip's k_i (y_i - v_f,i t) + c_i (v_i - v_f,i) and their moment about x = 0.
TEST(ForceOperator, HandsWorkIsTheFramesMomentumTerm)
{
  const BeamGrip g = Hands();
  const BeamParams             p     = GrippedDamped();
  const BeamSystem             S     = SystemOf(p);
  const FrameMotion            frame = Swing(S);
  const std::vector<PetscReal> y = Random(S, 9, 1e-3), v = Random(S, 10, 1.0);
  ForceState                   s;
  s.y = y.data(), s.v = v.data(), s.t = 2e-3, s.frame = &frame;
  std::vector<PetscReal> f(S.ndof);
  ForceOperatorApply(S, s, 0, S.ndof, f.data(), 1);
  PetscReal dQ = 0, Q = 0, Qy = 0, scale = 0;
  for (PetscInt i = 0; i < S.ndof; ++i) {
    dQ += frame.v[i] * S.mass[i] * (-f[i] / S.mass[i]) + p.damping_mass * frame.v[i] * S.mass[i] * v[i];
    scale += std::abs(frame.v[i] * f[i]);
    Q += frame.v[i] * S.mass[i] * v[i];
    Qy += frame.v[i] * S.mass[i] * y[i];
  }
  EXPECT_NEAR(dQ, ForceOperatorDrivePower(S, s, 0, S.ndof), 1e-12 * scale);
  EXPECT_NEAR(Q + p.damping_mass * Qy, ForceOperatorFrameMomentum(S, s, 0, S.ndof), 1e-14 * std::abs(Q));
  // the reaction, from the grip's formula on each node
  PetscReal force = 0, moment = 0, F = 0, Mx = 0;
  ForceOperatorFrameReaction(S, s, 0, S.ndof, &force, &moment);
  for (PetscInt i = 0; i < S.ndof; ++i) {
    const PetscReal fi = g.stiffness * GripShare(g, S, i) * (y[i] - frame.v[i] * s.t) + g.damping * GripShare(g, S, i) * (v[i] - frame.v[i]);
    F += fi;
    Mx += S.NodeX(i) * fi;
  }
  EXPECT_NEAR(F, force, 1e-13 * std::abs(F));
  EXPECT_NEAR(Mx, moment, 1e-13 * std::abs(Mx));
  // a frame at rest does no work
  s.frame = nullptr;
  EXPECT_EQ(0.0, ForceOperatorFrameMomentum(S, s, 0, S.ndof));
  EXPECT_EQ(0.0, ForceOperatorDrivePower(S, s, 0, S.ndof));
}

// The modal tools take M, K and the damping from the operator: C = alpha M + beta K for a
// Rayleigh-damped beam; a grip is not modal and says so.
TEST(ForceOperator, ModalToolsSeeRayleighAndRefuseTheGrip)
{
  BeamParams p        = AluminiumBeam(1.1, 21);
  p.damping_mass      = 2.5;
  p.damping_stiffness = 4e-6;
  const BeamSystem S  = SystemOf(p);
  const ModalSystem M = ModalSystemBeamOnly(S);
  PetscReal        alpha = -1, beta = -1;
  ASSERT_TRUE(M.Rayleigh(&alpha, &beta));
  EXPECT_EQ(2.5, alpha);
  EXPECT_EQ(4e-6, beta);
  ModalSystem U = M;
  U.damping     = false;
  ASSERT_TRUE(U.Rayleigh(&alpha, &beta));
  EXPECT_EQ(0.0, alpha);
  EXPECT_EQ(0.0, beta);
  const BeamSystem G = SystemOf(GrippedDamped());
  std::string      why;
  EXPECT_FALSE(ModalSystemBeamOnly(G).Rayleigh(&alpha, &beta, &why));
  EXPECT_NE(std::string::npos, why.find("-grip")) << why;
  const DampingScales d = ForceOperatorDampingScales(G);
  EXPECT_EQ(2e-6, d.stiffness);
  EXPECT_GT(d.mass_rate, 3.0); // alpha plus the grip's largest c_i/m_i
}

// The dissipation rule D += h/2 (P0 + P1) + h^2/12 (P0' - P1') integrates a cubic P exactly
// over uneven steps; RollBack undoes a step, Set continues from a given D.
TEST(DissipationRule, ExactForCubicsAndUndoesSteps)
{
  auto P  = [](PetscReal t) { return 2.0 + 3.0 * t - 5.0 * t * t + 7.0 * t * t * t; };
  auto Pd = [](PetscReal t) { return 3.0 - 10.0 * t + 21.0 * t * t; };
  auto I  = [](PetscReal t) { return 2.0 * t + 1.5 * t * t - 5.0 / 3 * t * t * t + 1.75 * t * t * t * t; };
  DissipationIntegral D;
  D.Restart(P(0), Pd(0));
  PetscReal t = 0;
  for (PetscReal h : {0.1, 0.37, 0.05, 0.2}) {
    t += h;
    D.Step(h, P(t), Pd(t));
  }
  EXPECT_NEAR(I(t), D.dissipated, 1e-14 * I(t));
  const PetscReal before = D.dissipated;
  D.Step(0.3, P(t + 0.3), Pd(t + 0.3));
  D.RollBack();
  EXPECT_EQ(before, D.dissipated);
  EXPECT_EQ(P(t), D.rate);
  // a quartic is not integrated exactly (the rule is of order 4, not 5)
  DissipationIntegral Q;
  Q.Restart(0, 0);
  Q.Step(1.0, 1.0, 4.0); // P = t^4 on [0, 1]: 1/5 exactly, the rule gives 1/2 - 4/12 = 1/6
  EXPECT_GT(std::abs(Q.dissipated - 0.2), 1e-2);
  Q.Set(5.0);
  EXPECT_EQ(5.0, Q.dissipated);
}

// The ball's coupling is a list of (dof, weight): the two hat entries today; the same weight
// split into two entries on one dof couples the same (weights, the modal system's g, the
// stability bound).
TEST(ContactCoupling, EntriesAsAList)
{
  const BeamSystem      S = SystemOf(AluminiumBeam(1.1, 12));
  const ContactCoupling g = BeamSystemCoupling(S, 0.25);
  ASSERT_EQ(2, g.n);
  ContactCoupling split = g;
  split.n               = 3;
  split.w[1]            = 0.5 * g.w[1];
  split.dof[2]          = g.dof[1];
  split.w[2]            = 0.5 * g.w[1];
  for (PetscInt d = 0; d < S.ndof; ++d) {
    EXPECT_EQ(g.Couples(d), split.Couples(d));
    EXPECT_NEAR(g.WeightOf(d), split.WeightOf(d), 1e-16);
  }
  EXPECT_FALSE(g.Couples(g.dof[0] + 5));
  EXPECT_EQ(0.0, g.WeightOf(g.dof[0] + 5));
  const ModalSystem a = ModalSystemBuild(S, g, 0.042, 2e4), b = ModalSystemBuild(S, split, 0.042, 2e4);
  for (PetscInt d = 0; d < a.n; ++d) EXPECT_NEAR(a.g[d], b.g[d], 1e-16) << "free dof " << d;
  const PetscReal wa = BeamSystemMaxFrequencyBound(S, g, 2e4, 0.042), wb = BeamSystemMaxFrequencyBound(S, split, 2e4, 0.042);
  EXPECT_NEAR(wa, wb, 1e-14 * wa);
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

// Euler-Bernoulli beam operator on a uniform grid: supports, curvature terms,
// stiffness action, energies and the -beam_* options. See beam.hpp.
#include "model/beam.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

static const char *const SupportNames[] = {"free", "clamped", "pinned", "Support", "BEAM_SUPPORT_", nullptr};

const char *SupportName(Support s) { return SupportNames[static_cast<int>(s)]; }

BeamOperator BeamOperatorBuild(const BeamParams &p)
{
  BeamOperator op;
  op.N  = p.nodes;
  op.L  = p.length;
  op.h  = p.length / (p.nodes - 1);
  op.EI = p.EI;
  op.mu = p.mu;
  const PetscInt N = op.N;
  op.mass.assign(N, p.mu * op.h);
  op.mass[0] *= 0.5;
  op.mass[N - 1] *= 0.5;

  // clamp_held: held with zero slope (clamped end, clamped region); pin_held: y = 0 only.
  std::vector<char> clamp_held(N, 0), pin_held(N, 0);
  if (p.left == Support::Clamped) clamp_held[0] = 1;
  if (p.left == Support::Pinned) pin_held[0] = 1;
  if (p.right == Support::Clamped) clamp_held[N - 1] = 1;
  if (p.right == Support::Pinned) pin_held[N - 1] = 1;
  if (p.has_clamp) {
    const PetscReal tol = 1e-9 * op.h;
    for (PetscInt i = 0; i < N; ++i) {
      const PetscReal x = i * op.h;
      if (x >= p.clamp_x0 - tol && x <= p.clamp_x1 + tol) clamp_held[i] = 1;
    }
  }
  op.held.assign(N, 0);
  for (PetscInt i = 0; i < N; ++i) op.held[i] = clamp_held[i] || pin_held[i];

  op.curvature.assign(N, Curvature::None);
  for (PetscInt k = 0; k < N; ++k) {
    const bool left_free  = k > 0 && !op.held[k - 1];
    const bool right_free = k < N - 1 && !op.held[k + 1];
    if (clamp_held[k]) {
      if (left_free && right_free) op.curvature[k] = Curvature::Standard; // a one-node "region" acts as a pin
      else if (right_free) op.curvature[k] = Curvature::MirrorRight;
      else if (left_free) op.curvature[k] = Curvature::MirrorLeft;
    } else if (k > 0 && k < N - 1) {
      op.curvature[k] = Curvature::Standard; // interior node (also next to a pinned one)
    } // free or pinned end node: no curvature term
  }
  return op;
}

static inline PetscReal CurvatureWeight(Curvature c)
{
  switch (c) {
  case Curvature::Standard: return 1.0;
  case Curvature::MirrorRight:
  case Curvature::MirrorLeft: return 0.5;
  default: return 0.0;
  }
}

PetscReal BeamCurvature(const BeamOperator &op, const PetscReal *y, PetscInt stride, PetscInt k)
{
  const PetscReal ih2 = 1.0 / (op.h * op.h);
  switch (op.curvature[k]) {
  case Curvature::Standard: return (y[(k - 1) * stride] - 2.0 * y[k * stride] + y[(k + 1) * stride]) * ih2;
  case Curvature::MirrorRight: return 2.0 * y[(k + 1) * stride] * ih2;
  case Curvature::MirrorLeft: return 2.0 * y[(k - 1) * stride] * ih2;
  default: return 0.0;
  }
}

PetscReal BeamCurvatureDerivative(const BeamOperator &op, PetscInt k, PetscInt i)
{
  const PetscReal ih2 = 1.0 / (op.h * op.h);
  switch (op.curvature[k]) {
  case Curvature::Standard: return i == k ? -2.0 * ih2 : (std::abs(i - k) == 1 ? ih2 : 0.0);
  case Curvature::MirrorRight: return i == k + 1 ? 2.0 * ih2 : 0.0;
  case Curvature::MirrorLeft: return i == k - 1 ? 2.0 * ih2 : 0.0;
  default: return 0.0;
  }
}

void BeamStiffnessApply(const BeamOperator &op, const PetscReal *y, PetscInt stride, PetscInt i0, PetscInt i1, PetscReal *f, PetscInt fstride)
{
  const PetscInt  N = op.N;
  const PetscReal c = op.EI * op.h;
  // Weighted curvatures w_k kappa_k for k in [i0-1, i1], kept in a 3-entry window.
  auto wk = [&](PetscInt k) -> PetscReal {
    if (k < 0 || k >= N) return 0.0;
    const Curvature kind = op.curvature[k];
    return kind == Curvature::None ? 0.0 : CurvatureWeight(kind) * BeamCurvature(op, y, stride, k);
  };
  PetscReal wprev = wk(i0 - 1), wcur = wk(i0);
  for (PetscInt i = i0; i < i1; ++i) {
    const PetscReal wnext = wk(i + 1);
    PetscReal       s     = 0.0;
    if (!op.held[i]) {
      if (i > 0) s += wprev * BeamCurvatureDerivative(op, i - 1, i);
      s += wcur * BeamCurvatureDerivative(op, i, i);
      if (i < N - 1) s += wnext * BeamCurvatureDerivative(op, i + 1, i);
    }
    f[i * fstride] = c * s;
    wprev          = wcur;
    wcur           = wnext;
  }
}

PetscInt BeamStiffnessRow(const BeamOperator &op, PetscInt i, PetscInt cols[5], PetscReal vals[5])
{
  if (op.held[i]) return 0;
  PetscReal row[5] = {0, 0, 0, 0, 0}; // columns i-2 .. i+2
  for (PetscInt k = std::max<PetscInt>(0, i - 1); k <= std::min<PetscInt>(op.N - 1, i + 1); ++k) {
    const PetscReal w = CurvatureWeight(op.curvature[k]);
    if (w == 0.0) continue;
    const PetscReal di = BeamCurvatureDerivative(op, k, i);
    if (di == 0.0) continue;
    for (PetscInt l = k - 1; l <= k + 1; ++l) {
      if (l < 0 || l >= op.N) continue;
      row[l - i + 2] += w * di * BeamCurvatureDerivative(op, k, l);
    }
  }
  PetscInt n = 0;
  for (PetscInt d = 0; d < 5; ++d) {
    const PetscInt l = i + d - 2;
    if (l < 0 || l >= op.N || op.held[l] || row[d] == 0.0) continue;
    cols[n]   = l;
    vals[n++] = op.EI * op.h * row[d];
  }
  return n;
}

PetscReal BeamStrainEnergy(const BeamOperator &op, const PetscReal *y, PetscInt stride, PetscInt k0, PetscInt k1)
{
  PetscReal U = 0.0;
  for (PetscInt k = k0; k < k1; ++k) {
    const PetscReal w = CurvatureWeight(op.curvature[k]);
    if (w == 0.0) continue;
    const PetscReal kap = BeamCurvature(op, y, stride, k);
    U += w * kap * kap;
  }
  return 0.5 * op.EI * op.h * U;
}

PetscReal BeamKineticEnergy(const BeamOperator &op, const PetscReal *v, PetscInt stride, PetscInt i0, PetscInt i1)
{
  PetscReal T = 0.0;
  for (PetscInt i = i0; i < i1; ++i) T += op.mass[i] * v[i * stride] * v[i * stride];
  return 0.5 * T;
}

ImpactStencil BeamImpactStencil(const BeamOperator &op, PetscReal x_imp) { return GridImpactStencil(op.N, op.L, x_imp); }

ImpactStencil GridImpactStencil(PetscInt N, PetscReal L, PetscReal x_imp)
{
  ImpactStencil   st;
  const PetscReal h  = L / (N - 1);
  const PetscReal s  = std::min(std::max(x_imp, (PetscReal)0), L) / h;
  const PetscReal sr = std::round(s);
  PetscInt        j  = std::abs(s - sr) < 1e-9 ? static_cast<PetscInt>(sr) : static_cast<PetscInt>(std::floor(s));
  PetscReal       frac = std::abs(s - sr) < 1e-9 ? 0.0 : s - j;
  j                    = std::max<PetscInt>(0, j);
  if (j >= N - 1) { // at (or past) the x = L end: all weight on the last node
    j    = N - 2;
    frac = 1.0;
  }
  st.j = j;
  st.w = 1.0 - frac;
  return st;
}

PetscReal BeamMaxFrequencyBound(const BeamOperator &op, const ImpactStencil &s, PetscReal k_extra, PetscReal m_extra)
{
  PetscReal lam = 0.0;
  for (PetscInt i = 0; i < op.N; ++i) {
    if (op.held[i]) continue;
    PetscInt  cols[5];
    PetscReal vals[5];
    const PetscInt n   = BeamStiffnessRow(op, i, cols, vals);
    PetscReal      sum = 0.0;
    for (PetscInt q = 0; q < n; ++q) sum += std::abs(vals[q]);
    PetscReal g = i == s.j ? s.w : (i == s.j + 1 ? 1.0 - s.w : 0.0);
    if (g != 0.0) sum += k_extra * g * (1.0 + 1.0); // |g_i| (|w| + |1-w| + 1)
    lam = std::max(lam, sum / op.mass[i]);
  }
  if (m_extra > 0) lam = std::max(lam, 2.0 * k_extra / m_extra);
  return std::sqrt(lam);
}

PetscReal BeamFundamentalFrequencyEstimate(const BeamParams &p)
{
  // beta L of the lowest flexural mode for (left, right) supports.
  auto betaL = [](Support a, Support b) -> PetscReal {
    if (a > b) std::swap(a, b);
    if (a == Support::Free && b == Support::Free) return 4.73004;
    if (a == Support::Free && b == Support::Clamped) return 1.87510;
    if (a == Support::Free && b == Support::Pinned) return 3.92660;
    if (a == Support::Clamped && b == Support::Clamped) return 4.73004;
    if (a == Support::Clamped && b == Support::Pinned) return 3.92660;
    return M_PI; // pinned-pinned
  };
  PetscReal span = p.length, bl = betaL(p.left, p.right);
  if (p.has_clamp) {
    const PetscReal left_span = p.clamp_x0, right_span = p.length - p.clamp_x1;
    if (left_span >= right_span) {
      span = left_span;
      bl   = betaL(p.left, Support::Clamped);
    } else {
      span = right_span;
      bl   = betaL(Support::Clamped, p.right);
    }
    span = std::max(span, p.length / (p.nodes - 1));
  }
  return bl * bl * std::sqrt(p.EI / p.mu) / (span * span);
}

PetscErrorCode BeamParamsCheck(MPI_Comm comm, const BeamParams &p)
{
  PetscFunctionBeginUser;
  PetscCheck(p.length > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_length %g is not allowed: the length must be > 0 (m)", (double)p.length);
  PetscCheck(p.EI > 0 && std::isfinite(p.EI), comm, PETSC_ERR_ARG_OUTOFRANGE, "bending stiffness EI = %g is not allowed: it must be > 0 (N m^2)", (double)p.EI);
  PetscCheck(p.mu > 0 && std::isfinite(p.mu), comm, PETSC_ERR_ARG_OUTOFRANGE, "mass per length mu = %g is not allowed: it must be > 0 (kg/m)", (double)p.mu);
  PetscCheck(p.damping_mass >= 0 && std::isfinite(p.damping_mass), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_damping_mass %g is not allowed: alpha must be >= 0 (1/s)", (double)p.damping_mass);
  PetscCheck(p.damping_stiffness >= 0 && std::isfinite(p.damping_stiffness), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_damping_stiffness %g is not allowed: beta must be >= 0 (s)", (double)p.damping_stiffness);
  PetscCheck(p.nodes >= 5, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_nodes %" PetscInt_FMT " is not allowed: at least 5 nodes are needed", p.nodes);
  if (p.has_clamp) {
    PetscCheck(p.clamp_x0 >= 0 && p.clamp_x1 <= p.length && p.clamp_x0 < p.clamp_x1, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-beam_clamp %g,%g is not allowed: need 0 <= x0 < x1 <= L = %g (m)", (double)p.clamp_x0, (double)p.clamp_x1, (double)p.length);
    const BeamOperator op    = BeamOperatorBuild(p);
    PetscInt           nfree = 0;
    for (char held : op.held) nfree += !held;
    PetscCheck(nfree >= 3, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_clamp %g,%g holds all but %" PetscInt_FMT " of the %" PetscInt_FMT " nodes: at least 3 must stay free", (double)p.clamp_x0,
               (double)p.clamp_x1, nfree, p.nodes);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BeamParamsFromOptions(MPI_Comm comm, BeamParams *p)
{
  // Defaults: the paper's aluminium beam, 1.1 m x 6 mm x 32 mm.
  PetscReal E = 7e10, rho = 2700, a = 0.006, b = 0.032, M = 0, Erho = 0, EI = 0, mu = 0;
  PetscBool setE = PETSC_FALSE, setrho = PETSC_FALSE, seta = PETSC_FALSE, setb = PETSC_FALSE, setM = PETSC_FALSE, setErho = PETSC_FALSE, setEI = PETSC_FALSE, setmu = PETSC_FALSE;
  PetscEnum left = (PetscEnum)p->left, right = (PetscEnum)p->right;
  PetscReal clamp[2] = {0, 0};
  PetscInt  nclamp   = 2;
  PetscBool setclamp = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Beam: geometry, material and supports (SI units)", "beamimpact");
  PetscCall(PetscOptionsReal("-beam_length", "Beam length L (m)", "", p->length, &p->length, NULL));
  PetscCall(PetscOptionsReal("-beam_thickness", "Thickness a in the direction of motion (m)", "", a, &a, &seta));
  PetscCall(PetscOptionsReal("-beam_width", "Width b (m); with E and rho", "", b, &b, &setb));
  PetscCall(PetscOptionsReal("-beam_youngs_modulus", "Young's modulus E (Pa); with rho, a, b", "", E, &E, &setE));
  PetscCall(PetscOptionsReal("-beam_density", "Density rho (kg/m^3); with E, a, b", "", rho, &rho, &setrho));
  PetscCall(PetscOptionsReal("-beam_mass", "Total mass M (kg); with -beam_youngs_over_density and a", "", M, &M, &setM));
  PetscCall(PetscOptionsReal("-beam_youngs_over_density", "E/rho (N m/kg); with -beam_mass and a", "", Erho, &Erho, &setErho));
  PetscCall(PetscOptionsReal("-beam_EI", "Bending stiffness EI (N m^2); with -beam_mu", "", EI, &EI, &setEI));
  PetscCall(PetscOptionsReal("-beam_mu", "Mass per length mu (kg/m); with -beam_EI", "", mu, &mu, &setmu));
  PetscCall(PetscOptionsInt("-beam_nodes", "Number of grid nodes N (>= 5)", "", p->nodes, &p->nodes, NULL));
  PetscCall(PetscOptionsEnum("-beam_left", "Support at x = 0", "", SupportNames, left, &left, NULL));
  PetscCall(PetscOptionsEnum("-beam_right", "Support at x = L", "", SupportNames, right, &right, NULL));
  PetscCall(PetscOptionsReal("-beam_damping_mass", "Rayleigh damping alpha (1/s): C = alpha M + beta K, zeta = alpha/(2 omega) + beta omega/2", "", p->damping_mass, &p->damping_mass, NULL));
  PetscCall(PetscOptionsReal("-beam_damping_stiffness", "Rayleigh damping beta (s)", "", p->damping_stiffness, &p->damping_stiffness, NULL));
  PetscCall(PetscOptionsRealArray("-beam_clamp", "Clamped region x0,x1 (m) held fixed (a handle in a vice)", "", clamp, &nclamp, &setclamp));
  PetscOptionsEnd();

  p->left  = (Support)left;
  p->right = (Support)right;
  if (setclamp) {
    PetscCheck(nclamp == 2, comm, PETSC_ERR_ARG_WRONG, "-beam_clamp takes two numbers x0,x1 (m); got %" PetscInt_FMT, nclamp);
    p->has_clamp = true;
    p->clamp_x0  = clamp[0];
    p->clamp_x1  = clamp[1];
  }

  BeamMaterialInput &in = p->input;
  if (setEI || setmu) {
    PetscCheck(setEI && setmu, comm, PETSC_ERR_ARG_WRONG, "-beam_EI and -beam_mu go together: give both (got only %s)", setEI ? "-beam_EI" : "-beam_mu");
    PetscCheck(!(setE || setrho || seta || setb || setM || setErho), comm, PETSC_ERR_ARG_INCOMP,
               "contradicting beam parameter sets: -beam_EI/-beam_mu fix the beam; do not also give %s", setE ? "-beam_youngs_modulus" : setrho ? "-beam_density" : seta ? "-beam_thickness" : setb ? "-beam_width" : setM ? "-beam_mass" : "-beam_youngs_over_density");
    p->EI            = EI;
    p->mu            = mu;
    in.parameter_set = "EI,mu";
  } else if (setM || setErho) {
    PetscCheck(setM && setErho, comm, PETSC_ERR_ARG_WRONG, "-beam_mass and -beam_youngs_over_density go together (with -beam_thickness): give both (got only %s)", setM ? "-beam_mass" : "-beam_youngs_over_density");
    PetscCheck(!(setE || setrho || setb), comm, PETSC_ERR_ARG_INCOMP, "contradicting beam parameter sets: -beam_mass with E/rho fixes the beam; do not also give %s",
               setE ? "-beam_youngs_modulus" : setrho ? "-beam_density" : "-beam_width");
    PetscCheck(M > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_mass %g is not allowed: it must be > 0 (kg)", (double)M);
    PetscCheck(Erho > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_youngs_over_density %g is not allowed: it must be > 0 (N m/kg)", (double)Erho);
    PetscCheck(a > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_thickness %g is not allowed: it must be > 0 (m)", (double)a);
    PetscCheck(p->length > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_length %g is not allowed: the length must be > 0 (m)", (double)p->length);
    p->mu                  = M / p->length;
    p->EI                  = Erho * p->mu * a * a / 12.0; // E b a^3/12 = (E/rho) (rho a b) a^2/12
    in.mass                = M;
    in.youngs_over_density = Erho;
    in.thickness           = a;
    in.parameter_set       = "M,L,a,E/rho";
  } else {
    PetscCheck(E > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_youngs_modulus %g is not allowed: it must be > 0 (Pa)", (double)E);
    PetscCheck(rho > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_density %g is not allowed: it must be > 0 (kg/m^3)", (double)rho);
    PetscCheck(a > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_thickness %g is not allowed: it must be > 0 (m)", (double)a);
    PetscCheck(b > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_width %g is not allowed: it must be > 0 (m)", (double)b);
    p->mu              = rho * a * b;
    p->EI              = E * b * a * a * a / 12.0;
    in.youngs_modulus  = E;
    in.density         = rho;
    in.thickness       = a;
    in.width           = b;
    in.parameter_set   = "E,rho,a,b";
  }
  PetscCall(BeamParamsCheck(comm, *p));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The semi-discrete system: assembly of K from the strain terms, and its actions. See
// beam_system.hpp.
#include "system/beam_system.hpp"

#include "model/grip.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

bool BeamSystemBuild(const BeamParams &p, BeamSystem *sys, std::string *why)
{
  const BeamTheoryBuild build = BeamTheoryFind(p.theory.c_str());
  if (!build) {
    *why = "unknown beam theory '" + p.theory + "'";
    return false;
  }
  BeamDiscretization d;
  build(p, &d);
  BeamSystem &S    = *sys;
  S.nodes          = p.nodes;
  S.fields         = d.fields;
  S.ndof           = p.nodes * d.fields;
  S.L              = p.length;
  S.h              = p.length / (p.nodes - 1);
  S.mass           = std::move(d.mass);
  S.held           = std::move(d.held);
  S.strain         = std::move(d.strain);
  S.frequency_unit = d.frequency_unit;
  S.damping_mass      = p.damping_mass;
  S.damping_stiffness = p.damping_stiffness;
  std::stable_sort(S.strain.begin(), S.strain.end(), [](const StrainTerm &a, const StrainTerm &b) { return a.owner < b.owner; });
  S.strain_begin.assign(S.ndof + 1, 0);
  for (const StrainTerm &t : S.strain) S.strain_begin[t.owner + 1]++;
  for (PetscInt q = 0; q < S.ndof; ++q) S.strain_begin[q + 1] += S.strain_begin[q];
  // K = sum_k weight_k b_k b_k^T, without the rows and columns of held dofs.
  S.bw    = 0;
  S.reach = 0;
  for (const StrainTerm &t : S.strain)
    for (PetscInt a = 0; a < t.n; ++a) {
      S.reach = std::max(S.reach, std::abs(t.dof[a] - t.owner));
      for (PetscInt b = 0; b < t.n; ++b) S.bw = std::max(S.bw, std::abs(t.dof[a] - t.dof[b]));
    }
  const PetscInt width = 2 * S.bw + 1;
  S.band.assign((size_t)width * S.ndof, 0.0);
  for (const StrainTerm &t : S.strain)
    for (PetscInt a = 0; a < t.n; ++a) {
      const PetscInt i = t.dof[a];
      if (S.held[i]) continue;
      for (PetscInt b = 0; b < t.n; ++b) {
        const PetscInt j = t.dof[b];
        if (S.held[j]) continue;
        S.band[(size_t)width * i + (j - i + S.bw)] += t.weight * (t.b[a] * t.b[b]); // symmetric to the bit
      }
    }
  if (p.grip.on) { // the hands: k_i on the diagonal of K, c_i in C, the hand mass on the dofs
    const std::vector<PetscReal> w    = GripNodeWeights(p.grip, S.nodes, S.L);
    const PetscReal              span = p.grip.x_b - p.grip.x_a;
    S.grip_k.assign(S.ndof, 0.0);
    S.grip_c.assign(S.ndof, 0.0);
    S.grip_v.assign(S.ndof, 0.0);
    for (PetscInt i = 0; i < S.nodes; ++i) {
      const PetscInt d = S.Dof(i);
      if (S.held[d] || w[i] == 0.0) continue;
      S.grip_k[d] = p.grip.stiffness * w[i];
      S.grip_c[d] = p.grip.damping * w[i];
      S.mass[d] += p.grip.mass * w[i] / span;
      S.band[(size_t)width * d + S.bw] += S.grip_k[d];
      S.grip_damping += S.grip_c[d];
    }
  }
  return true;
}

ContactCoupling BeamSystemCoupling(const BeamSystem &sys, PetscReal x_imp)
{
  const ImpactStencil st = GridImpactStencil(sys.nodes, sys.L, x_imp);
  ContactCoupling     g;
  g.x      = x_imp;
  g.dof[0] = sys.Dof(st.j);
  g.dof[1] = sys.Dof(st.j + 1);
  g.w[0]   = sys.held[g.dof[0]] ? 0.0 : st.w;
  g.w[1]   = sys.held[g.dof[1]] ? 0.0 : 1.0 - st.w;
  return g;
}

// K y in the factored form B^T (W (B y)): each strain (curvature, shear) is formed first and
// then spread back, so a rigid motion gives exactly what its strains give (round-off relative
// to K y, not to |K| |y|): momentum of a free beam is conserved to round-off. The band form
// would lose eps |K| |y| ~ eps omega_max^2 m |y| per evaluation.
void BeamSystemStiffnessApply(const BeamSystem &sys, const PetscReal *y, PetscInt ns, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt os)
{
  const PetscInt F  = sys.fields;
  auto           yi = [&](PetscInt d) { return F == 1 ? y[d * ns] : y[(d / F) * ns + d % F]; };
  auto           fi = [&](PetscInt d) -> PetscReal & { return F == 1 ? f[d * os] : f[(d / F) * os + d % F]; };
  for (PetscInt d = d0; d < d1; ++d) fi(d) = 0.0;
  const PetscInt k0 = sys.strain_begin[std::max<PetscInt>(0, d0 - sys.reach)], k1 = sys.strain_begin[std::min<PetscInt>(sys.ndof, d1 + sys.reach)];
  for (PetscInt k = k0; k < k1; ++k) {
    const StrainTerm &t = sys.strain[k];
    PetscReal         e = 0.0;
    for (PetscInt q = 0; q < t.n; ++q) e += t.b[q] * yi(t.dof[q]);
    e *= t.weight;
    for (PetscInt q = 0; q < t.n; ++q)
      if (t.dof[q] >= d0 && t.dof[q] < d1) fi(t.dof[q]) += t.b[q] * e;
  }
  if (sys.Gripped())
    for (PetscInt d = d0; d < d1; ++d)
      if (sys.grip_k[d] != 0.0) fi(d) += sys.grip_k[d] * yi(d);
  for (PetscInt d = d0; d < d1; ++d)
    if (sys.held[d]) fi(d) = 0.0;
}

PetscInt BeamSystemStiffnessRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals)
{
  if (sys.held[i]) return 0;
  const PetscInt   bw = sys.bw;
  const PetscReal *r  = sys.band.data() + (size_t)(2 * bw + 1) * i;
  PetscInt         n  = 0;
  for (PetscInt j = std::max<PetscInt>(0, i - bw); j <= std::min<PetscInt>(sys.ndof - 1, i + bw); ++j) {
    if (sys.held[j] || r[j - i + bw] == 0.0) continue;
    cols[n]   = j;
    vals[n++] = r[j - i + bw];
  }
  return n;
}

PetscReal BeamSystemStrainEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt ns, PetscInt d0, PetscInt d1)
{
  const PetscInt F = sys.fields;
  PetscReal      U = 0.0;
  for (PetscInt k = sys.strain_begin[d0]; k < sys.strain_begin[d1]; ++k) {
    const StrainTerm &t = sys.strain[k];
    PetscReal         e = 0.0;
    for (PetscInt q = 0; q < t.n; ++q) e += t.b[q] * y[(t.dof[q] / F) * ns + t.dof[q] % F];
    U += t.weight * e * e;
  }
  return 0.5 * U;
}

PetscReal BeamSystemKineticEnergy(const BeamSystem &sys, const PetscReal *v, PetscInt ns, PetscInt d0, PetscInt d1)
{
  const PetscInt F = sys.fields;
  PetscReal      T = 0.0;
  for (PetscInt i = d0; i < d1; ++i) {
    const PetscReal vi = v[(i / F) * ns + i % F];
    T += sys.mass[i] * vi * vi;
  }
  return 0.5 * T;
}

std::vector<PetscReal> BeamSystemRigidVelocity(const BeamSystem &sys, PetscReal v0, PetscReal slope)
{
  std::vector<PetscReal> v(sys.ndof, 0.0);
  for (PetscInt i = 0; i < sys.nodes; ++i)
    for (PetscInt f = 0; f < sys.fields; ++f) {
      const PetscInt d = sys.Dof(i, f);
      if (!sys.held[d]) v[d] = f == 0 ? v0 + slope * sys.NodeX(i) : slope;
    }
  return v;
}

std::vector<PetscReal> BeamSystemSwingVelocity(const BeamSystem &sys, const SwingParams &swing, const BeamRigidBody &body)
{
  // -(V_cm + Omega (x - x_cm)) = -(V_cm - Omega x_cm) - Omega x
  return BeamSystemRigidVelocity(sys, -(swing.bat_speed - swing.bat_angular_velocity * body.x_cm), -swing.bat_angular_velocity);
}

PetscReal BeamSystemFreeMass(const BeamSystem &sys)
{
  PetscReal M = 0;
  for (PetscInt i = 0; i < sys.nodes; ++i) M += sys.held[sys.Dof(i)] ? 0.0 : sys.mass[sys.Dof(i)];
  return M;
}

PetscReal BeamSystemMaxFrequencyBound(const BeamSystem &sys, const ContactCoupling &g, PetscReal k_extra, PetscReal m_extra)
{
  const PetscInt width = 2 * sys.bw + 1;
  PetscReal      lam   = 0.0;
  for (PetscInt i = 0; i < sys.ndof; ++i) {
    if (sys.held[i]) continue;
    PetscReal sum = 0.0;
    for (PetscInt o = 0; o < width; ++o) {
      const PetscInt j = i + o - sys.bw;
      if (j >= 0 && j < sys.ndof && !sys.held[j]) sum += std::abs(sys.band[(size_t)width * i + o]);
    }
    for (PetscInt q = 0; q < 2; ++q)
      if (g.dof[q] == i && g.w[q] != 0.0) sum += k_extra * g.w[q] * (std::abs(g.w[0]) + std::abs(g.w[1]) + 1.0);
    lam = std::max(lam, sum / sys.mass[i]);
  }
  if (m_extra > 0) lam = std::max(lam, 2.0 * k_extra / m_extra);
  return std::sqrt(lam);
}

void BeamSystemDampingApply(const BeamSystem &sys, const PetscReal *v, PetscInt ns, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt os)
{
  const PetscInt  F = sys.fields;
  const PetscReal a = sys.damping_mass, b = sys.damping_stiffness;
  if (b != 0.0) BeamSystemStiffnessApply(sys, v, ns, d0, d1, f, os);
  for (PetscInt d = d0; d < d1; ++d) {
    PetscReal      &fd = f[(d / F) * os + d % F];
    const PetscReal vd = v[(d / F) * ns + d % F];
    fd                 = sys.held[d] ? 0.0 : (b != 0.0 ? b * fd : 0.0) + a * sys.mass[d] * vd;
    if (sys.Gripped() && !sys.held[d]) fd += sys.grip_c[d] * (vd - sys.grip_v[d]) - b * sys.grip_k[d] * vd; // beta damps the beam's K only
  }
}

PetscReal BeamSystemDissipationRate(const BeamSystem &sys, const PetscReal *v, PetscInt ns, PetscInt d0, PetscInt d1)
{
  const PetscReal a = sys.damping_mass, b = sys.damping_stiffness;
  PetscReal       r = 0.0;
  if (a != 0.0) r += 2 * a * BeamSystemKineticEnergy(sys, v, ns, d0, d1);
  if (b != 0.0) r += 2 * b * BeamSystemStrainEnergy(sys, v, ns, d0, d1);
  if (sys.grip_damping > 0) {
    const PetscInt F = sys.fields;
    for (PetscInt d = d0; d < d1; ++d) {
      const PetscReal u = v[(d / F) * ns + d % F] - sys.grip_v[d];
      r += sys.grip_c[d] * u * u;
    }
  }
  return r;
}

PetscReal BeamSystemGripEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt ns, PetscInt d0, PetscInt d1, PetscReal t)
{
  const PetscInt F = sys.fields;
  PetscReal      U = 0.0;
  if (!sys.Gripped()) return 0.0;
  for (PetscInt d = d0; d < d1; ++d) {
    const PetscReal u = y[(d / F) * ns + d % F] - sys.grip_v[d] * t;
    U += sys.grip_k[d] * u * u;
  }
  return 0.5 * U;
}

void BeamSystemGripForce(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs, PetscInt d0, PetscInt d1, PetscReal t, PetscReal *force, PetscReal *moment)
{
  const PetscInt F = sys.fields;
  if (!sys.Gripped()) return;
  for (PetscInt d = d0; d < d1; ++d) {
    if (sys.grip_k[d] == 0.0 && sys.grip_c[d] == 0.0) continue;
    const PetscReal f = sys.grip_k[d] * (y[(d / F) * ys + d % F] - sys.grip_v[d] * t) + sys.grip_c[d] * (v[(d / F) * vs + d % F] - sys.grip_v[d]);
    *force += f;
    *moment += sys.NodeX(d / F) * f;
  }
}

PetscReal BeamSystemGripDrive(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs, PetscInt d0, PetscInt d1)
{
  const PetscInt F = sys.fields;
  PetscReal      Q = 0.0;
  if (!sys.Gripped()) return 0.0;
  for (PetscInt d = d0; d < d1; ++d) Q += sys.grip_v[d] * sys.mass[d] * (v[(d / F) * vs + d % F] + sys.damping_mass * y[(d / F) * ys + d % F]);
  return Q;
}

PetscReal BeamSystemGripFrameAt(const BeamSystem &sys, const ContactCoupling &g)
{
  return sys.Gripped() ? g.w[0] * sys.grip_v[g.dof[0]] + g.w[1] * sys.grip_v[g.dof[1]] : 0.0;
}

PetscReal BeamSystemGripRate(const BeamSystem &sys)
{
  PetscReal r = 0.0;
  if (sys.Gripped())
    for (PetscInt d = 0; d < sys.ndof; ++d) r = std::max(r, sys.grip_c[d] / sys.mass[d]);
  return r;
}

ContactScales ContactScalesOf(const BeamSystem &sys, const BallParams &ball)
{
  // A ball heavier than the beam has a contact several times shorter than on a wall:
  // T_r = T_c sqrt(M / (M + m_b)) <= T_c, with M the beam's mass that can move.
  ContactScales   s;
  const PetscReal M = BeamSystemFreeMass(sys);
  s.time            = ContactTimeScale(ball) * std::sqrt(M / (M + ball.mass));
  s.compression     = ContactCompressionScale(ball);
  s.speed           = ball.speed;
  s.stiffness       = ContactStiffnessBound(ball);
  return s;
}

} // namespace beamimpact

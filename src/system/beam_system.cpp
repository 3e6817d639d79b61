// The semi-discrete system: built from the theory and the force terms, and its actions. See
// beam_system.hpp.
#include "system/beam_system.hpp"

#include "model/barrel.hpp"
#include "model/shell.hpp"

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
  S                = BeamSystem();
  S.beam_fields    = d.fields;
  if (p.hoop.on) S.wall_dof = BarrelHoopAppend(p.hoop, &d), S.wall_stiffness = BarrelHoopStiffness(p.hoop);
  if (p.shell.on) {
    const ShellLayout shell = ShellAppend(p, &d);
    S.shell_first           = shell.first;
    S.shell_harmonics       = shell.harmonics;
    S.shell_contact_radius  = std::max<PetscReal>(0, p.shell.contact_radius);
    S.shell_radius.assign(p.nodes, 0.0);
    for (PetscInt i = 0; i < p.nodes; ++i) {
      PetscReal t;
      ShellWallAt(p, p.length * i / (p.nodes - 1), &S.shell_radius[i], &t);
    }
  }
  S.nodes          = p.nodes;
  S.fields         = d.fields;
  S.ndof           = p.nodes * d.fields;
  S.L              = p.length;
  S.h              = p.length / (p.nodes - 1);
  S.mass           = std::move(d.mass);
  S.held           = std::move(d.held);
  S.strain         = std::move(d.strain);
  S.frequency_unit = d.frequency_unit;
  ForceOperatorCreate(p, &S); // the force terms (a grip adds the hands' mass)
  BeamSystemAssemble(&S);
  return true;
}

void BeamSystemAssemble(BeamSystem *sys)
{
  BeamSystem &S = *sys;
  std::stable_sort(S.strain.begin(), S.strain.end(), [](const StrainTerm &a, const StrainTerm &b) { return a.owner < b.owner; });
  S.strain_begin.assign(S.ndof + 1, 0);
  for (const StrainTerm &t : S.strain) S.strain_begin[t.owner + 1]++;
  for (PetscInt q = 0; q < S.ndof; ++q) S.strain_begin[q + 1] += S.strain_begin[q];
  S.bw    = 0; // of B^T W B; the force terms may widen it
  S.reach = 0;
  for (const StrainTerm &t : S.strain)
    for (PetscInt a = 0; a < t.n; ++a) {
      S.reach = std::max(S.reach, std::abs(t.dof[a] - t.owner));
      for (PetscInt b = 0; b < t.n; ++b) S.bw = std::max(S.bw, std::abs(t.dof[a] - t.dof[b]));
    }
  ForceOperatorAssemble(&S); // K and C
}

ContactCoupling BeamSystemCoupling(const BeamSystem &sys, PetscReal x_imp)
{
  const ImpactStencil st = GridImpactStencil(sys.nodes, sys.L, x_imp);
  ContactCoupling     g;
  g.x      = x_imp;
  g.n      = 2; // the hat entries of the two nodes around the point
  g.dof[0] = sys.Dof(st.j);
  g.dof[1] = sys.Dof(st.j + 1);
  g.w[0]   = sys.held[g.dof[0]] ? 0.0 : st.w;
  g.w[1]   = sys.held[g.dof[1]] ? 0.0 : 1.0 - st.w;
  if (sys.wall_dof >= 0) g.dof[g.n] = sys.wall_dof, g.w[g.n++] = 1.0; // the wall under the ball, in series
  if (sys.shell_harmonics.empty()) return g;
  // each harmonic's W_n under the ball's patch (outward: the inward displacement is -W_n)
  const PetscReal a = sys.shell_contact_radius, R = st.w * sys.shell_radius[st.j] + (1 - st.w) * sys.shell_radius[st.j + 1];
  const std::vector<std::pair<PetscInt, PetscReal>> nodes = ShellPatchNodeWeights(sys.nodes, sys.L, x_imp, a);
  for (size_t k = 0; k < sys.shell_harmonics.size(); ++k) {
    const PetscReal wn = ShellPatchHarmonicWeight(sys.shell_harmonics[k], a, R);
    for (const auto &[i, wi] : nodes) {
      if (g.n == ContactCoupling::kMaxEntries) return g; // refused before: ShellPatchEntries
      const PetscInt d = i * sys.fields + sys.shell_first + 3 * (PetscInt)k + 2;
      g.dof[g.n]       = d;
      g.w[g.n++]       = sys.held[d] ? 0.0 : -(wn * wi);
    }
  }
  return g;
}

void BeamSystemStiffnessApply(const BeamSystem &sys, const PetscReal *y, PetscInt ns, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt os)
{
  ForceState s; // the deflection alone, at rest: f = K y
  s.y  = y;
  s.ys = ns;
  ForceOperatorApply(sys, s, d0, d1, f, os);
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

PetscInt BeamSystemDampingRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals)
{
  const ForceOperator &op = sys.forces;
  if (sys.held[i] || !sys.Damped()) return 0;
  const PetscInt bw = sys.bw;
  PetscInt       n  = 0;
  for (PetscInt j = std::max<PetscInt>(0, i - bw); j <= std::min<PetscInt>(sys.ndof - 1, i + bw); ++j) {
    PetscReal c = op.damping_band.empty() ? 0.0 : op.damping_band[(size_t)(2 * bw + 1) * i + (j - i + bw)];
    if (j == i && !op.damping_diag.empty()) c += op.damping_diag[i];
    if (sys.held[j] || c == 0.0) continue;
    cols[n]   = j;
    vals[n++] = c;
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

void BeamSystemWallEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs, PetscInt d0, PetscInt d1, PetscReal *stored, PetscReal *kinetic)
{
  const PetscInt F = sys.fields;
  PetscReal      U = 0.0, T = 0.0;
  *stored = *kinetic = 0.0;
  if (F == sys.beam_fields) return; // no wall
  for (PetscInt i = d0; i < d1; ++i) {
    if (i % F < sys.beam_fields) continue;
    const PetscReal vi = v[(i / F) * vs + i % F];
    T += sys.mass[i] * vi * vi;
    for (PetscInt k = sys.strain_begin[i]; k < sys.strain_begin[i + 1]; ++k) {
      const StrainTerm &t = sys.strain[k];
      PetscReal         e = 0.0;
      for (PetscInt q = 0; q < t.n; ++q) e += t.b[q] * y[(t.dof[q] / F) * ys + t.dof[q] % F];
      U += t.weight * e * e;
    }
  }
  *stored  = 0.5 * U;
  *kinetic = 0.5 * T;
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
      if (!sys.held[d]) v[d] = f == 0 ? v0 + slope * sys.NodeX(i) : (sys.Rotation(f) ? slope : 0.0);
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
  PetscReal      lam = 0.0, gsum = 0.0; // gsum: sum_q |w_q|
  for (PetscInt q = 0; q < g.n; ++q) gsum = q == 0 ? std::abs(g.w[q]) : gsum + std::abs(g.w[q]);
  for (PetscInt i = 0; i < sys.ndof; ++i) {
    if (sys.held[i]) continue;
    PetscReal sum = 0.0;
    for (PetscInt o = 0; o < width; ++o) {
      const PetscInt j = i + o - sys.bw;
      if (j >= 0 && j < sys.ndof && !sys.held[j]) sum += std::abs(sys.band[(size_t)width * i + o]);
    }
    for (PetscInt q = 0; q < g.n; ++q)
      if (g.dof[q] == i && g.w[q] != 0.0) sum += k_extra * std::abs(g.w[q]) * (gsum + 1.0); // Gershgorin: |entries| (a shell's weights are negative)
    lam = std::max(lam, sum / sys.mass[i]);
  }
  if (m_extra > 0) lam = std::max(lam, 2.0 * k_extra / m_extra);
  return std::sqrt(lam);
}

void BeamSystemDampingApply(const BeamSystem &sys, const PetscReal *v, PetscInt ns, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt os)
{
  ForceState s; // the frame at rest
  s.v  = v;
  s.vs = ns;
  ForceOperatorDampingApply(sys, s, d0, d1, f, os);
}

PetscReal BeamSystemDissipationRate(const BeamSystem &sys, const PetscReal *v, PetscInt ns, PetscInt d0, PetscInt d1)
{
  ForceState s; // the frame at rest
  s.v  = v;
  s.vs = ns;
  return ForceOperatorDissipationRate(sys, s, d0, d1);
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

// The semi-discrete system: built from the theory and the force terms, and its actions. See
// beam_system.hpp.
#include "system/beam_system.hpp"

#include <petscblaslapack.h>

#include <algorithm>
#include <array>
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
  BeamSystem &S = *sys;
  S             = BeamSystem();
  S.beam_fields = d.fields;
  S.field_account.assign(d.fields, 0);
  S.parts = StructurePartsBuild(p, &d); // the registered parts' fields, in registry order
  S.field_z.assign(d.fields, NAN);
  for (const PartInstance &s : S.parts) {
    S.field_account.resize(s.first + s.count, StructureAccountOf(*s.part));
    for (PetscInt f = s.first; f < s.first + s.count; ++f) S.field_z[f] = s.part->FieldZ(s, f);
  }
  for (PetscInt f = 0; f < d.fields; ++f)
    if (S.Face(f)) S.face_fields.push_back(f);
  S.nodes          = p.nodes;
  S.fields         = d.fields;
  S.ndof           = p.nodes * d.fields;
  S.L              = p.length;
  S.h              = p.length / (p.nodes - 1);
  S.mass           = std::move(d.mass);
  S.held           = std::move(d.held);
  S.strain         = std::move(d.strain);
  S.frequency_unit = d.frequency_unit;
  ForceOperatorCreate(p, &S); // the force terms
  StructurePartsFinish(&S);   // the parts' masses (the hands), force terms after them, their rigid points
  BeamSystemAssemble(&S);
  return true;
}

void BeamSystemAssemble(BeamSystem *sys)
{
  BeamSystem &S = *sys;
  std::stable_sort(S.strain.begin(), S.strain.end(),
                   [](const StrainTerm &a, const StrainTerm &b) { return a.owner < b.owner; });
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

ContactCoupling BeamSystemCoupling(const BeamSystem &sys, PetscReal x_imp, PetscReal z_imp)
{
  ContactCoupling g;
  g.x = x_imp;
  g.z = z_imp;
  for (const PartInstance &s : sys.parts) // a part the point strikes (the bed under the ball's disc)
    if (s.part->CoupleInstead(s, sys, x_imp, z_imp, &g)) return g;
  const ImpactStencil st = GridImpactStencil(sys.nodes, sys.L, x_imp);
  g.n                    = 2; // the hat entries of the two nodes around the point
  g.dof[0]               = sys.Dof(st.j);
  g.dof[1]               = sys.Dof(st.j + 1);
  g.w[0]                 = sys.held[g.dof[0]] ? 0.0 : st.w;
  g.w[1]                 = sys.held[g.dof[1]] ? 0.0 : 1.0 - st.w;
  for (const PartInstance &s : sys.parts) s.part->Couple(s, sys, st, z_imp, &g); // the parts' (the roll's, the wall's)
  return g;
}

void BeamSystemStiffnessApply(const BeamSystem &sys, const PetscReal *y, PetscInt ns, PetscInt d0, PetscInt d1,
                              PetscReal *f, PetscInt os)
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

void BeamSystemAccountEnergies(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs,
                               PetscInt d0, PetscInt d1, PetscReal *stored, PetscReal *kinetic)
{
  const PetscInt F = sys.fields;
  for (PetscInt a = 0; a < StructureAccountCount(); ++a) stored[a] = kinetic[a] = 0.0;
  for (PetscInt i = d0; i < d1; ++i) {
    const PetscReal vi = v[(i / F) * vs + i % F];
    kinetic[sys.AccountOf(i % F)] += 0.5 * sys.mass[i] * vi * vi;
  }
  for (PetscInt k = sys.strain_begin[d0]; k < sys.strain_begin[d1]; ++k) {
    const StrainTerm &t = sys.strain[k];
    PetscReal         e = 0.0;
    for (PetscInt q = 0; q < t.n; ++q) e += t.b[q] * y[(t.dof[q] / F) * ys + t.dof[q] % F];
    stored[t.account] += 0.5 * t.weight * e * e;
  }
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

namespace {

// The velocity field of a rigid motion: v0 + slope x (+ roll z on a string bed's deflections) on
// the deflections, slope on a Timoshenko section's rotation, roll on the frame's roll; with
// `holds`, 0 on the held dofs.
std::vector<PetscReal> RigidField(const BeamSystem &sys, PetscReal v0, PetscReal slope, PetscReal roll, bool holds)
{
  std::vector<PetscReal> v(sys.ndof, 0.0);
  const PetscInt         phi = sys.RollField();
  for (PetscInt d = 0; d < sys.ndof; ++d) {
    const PetscInt f = d % sys.fields;
    if (holds && sys.held[d]) continue;
    if (sys.Deflection(f)) v[d] = v0 + slope * sys.NodeX(d / sys.fields) + roll * sys.DofZ(d);
    else if (sys.Rotation(f)) v[d] = slope;
    else if (f == phi) v[d] = roll;
  }
  for (const RigidPoint &r : sys.rigid_points) // a part's point deflections: the beam's motion there
    if (!(holds && sys.held[r.dof])) v[r.dof] = v0 + slope * r.x;
  return v;
}

} // namespace

std::vector<PetscReal> BeamSystemRigidVelocity(const BeamSystem &sys, PetscReal v0, PetscReal slope, PetscReal roll)
{
  return RigidField(sys, v0, slope, roll, true);
}

std::vector<std::vector<PetscReal>> BeamSystemRigidCandidates(const BeamSystem &sys)
{
  std::vector<std::vector<PetscReal>> c;
  c.push_back(RigidField(sys, 1, 0, 0, false));
  c.push_back(RigidField(sys, 0, 1.0 / sys.L, 0, false)); // scaled like the translation (a slope of 1/L)
  if (sys.RollField() >= 0) c.push_back(RigidField(sys, 0, 0, 1.0 / sys.L, false));
  return c;
}

std::vector<std::vector<PetscReal>> BeamSystemRigidMotions(const BeamSystem &sys)
{
  const std::vector<std::vector<PetscReal>> c = BeamSystemRigidCandidates(sys);
  const int                                 k = (int)c.size();
  // The null space of H (the candidates' values at the held dofs): eigenvectors of H^T H for
  // eigenvalues below 1e-12 of its trace (LAPACK's syev on the k x k matrix, k <= 3).
  PetscReal A[9] = {0}, lambda[3] = {0}, work[32];
  for (PetscInt d = 0; d < sys.ndof; ++d)
    if (sys.held[d] && !sys.Face(d % sys.fields)) // a face's held dofs (a string bed's) are not unknowns: their
                                                  // strings' mass moves with the frame, they hold nothing
      for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b) A[a * k + b] += c[a][d] * c[b][d];
  PetscReal trace = 0;
  for (int a = 0; a < k; ++a) trace += A[a * k + a];
  PetscBLASInt n = k, lwork = 32, info = 0;
  LAPACKsyev_("V", "U", &n, A, &n, lambda, work, &lwork, &info); // column e of A: the eigenvector of lambda[e]
  if (info != 0) return {};
  PetscReal kmax = 0;
  for (PetscReal b : sys.band) kmax = std::max(kmax, std::abs(b));
  std::vector<std::vector<PetscReal>> out;
  std::vector<PetscReal>              f(sys.ndof);
  for (int e = 0; e < k; ++e) {
    if (trace > 0 && lambda[e] > 1e-12 * trace) continue;
    std::vector<PetscReal> v(sys.ndof, 0.0);
    PetscReal              vmax = 0, fmax = 0;
    for (PetscInt d = 0; d < sys.ndof; ++d) {
      if (!sys.held[d])
        for (int a = 0; a < k; ++a) v[d] += A[e * k + a] * c[a][d];
      vmax = std::max(vmax, std::abs(v[d]));
    }
    BeamSystemStiffnessApply(sys, v.data(), sys.fields, 0, sys.ndof, f.data(), sys.fields);
    for (PetscInt d = 0; d < sys.ndof; ++d) fmax = std::max(fmax, std::abs(f[d]));
    if (vmax > 0 && fmax <= 1e-9 * kmax * vmax) out.push_back(std::move(v));
  }
  return out;
}

std::vector<PetscReal> BeamSystemSwingVelocity(const BeamSystem &sys, const SwingParams &swing,
                                               const BeamRigidBody &body)
{
  // -(V_cm + Omega (x - x_cm)) = -(V_cm - Omega x_cm) - Omega x
  return BeamSystemRigidVelocity(sys, -(swing.bat_speed - swing.bat_angular_velocity * body.x_cm),
                                 -swing.bat_angular_velocity);
}

PetscReal BeamSystemFreeMass(const BeamSystem &sys)
{
  PetscReal M = 0;
  for (PetscInt d = 0; d < sys.ndof; ++d) M += sys.held[d] || !sys.Deflection(d % sys.fields) ? 0.0 : sys.mass[d];
  for (const RigidPoint &r : sys.rigid_points) M += sys.held[r.dof] ? 0.0 : sys.mass[r.dof];
  return M;
}

PetscReal BeamSystemMaxFrequencyBound(const BeamSystem &sys, const ContactCoupling &g, PetscReal k_extra,
                                      PetscReal m_extra, PetscInt *where)
{
  if (where) *where = -1;
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
      if (g.dof[q] == i && g.w[q] != 0.0)
        sum += k_extra * std::abs(g.w[q]) * (gsum + 1.0); // Gershgorin: |entries| (a shell's weights are negative)
    if (sum / sys.mass[i] > lam) {
      lam = sum / sys.mass[i];
      if (where) *where = i;
    }
  }
  if (m_extra > 0 && 2.0 * k_extra / m_extra > lam) {
    lam = 2.0 * k_extra / m_extra;
    if (where) *where = -1;
  }
  return std::sqrt(lam);
}

PetscInt BeamSystemDominantAccount(const BeamSystem &sys, const PetscInt *dof, const PetscReal *e, PetscInt n,
                                   PetscReal *share)
{
  PetscReal sum = 0, by[kMaxAccounts] = {0};
  for (PetscInt r = 0; r < n; ++r) by[sys.AccountOf((dof ? dof[r] : r) % sys.fields)] += e[r], sum += e[r];
  const PetscInt best = (PetscInt)(std::max_element(by, by + StructureAccountCount()) - by);
  if (share) *share = sum > 0 ? by[best] / sum : 0;
  return best;
}

const char *BeamSystemPartWords(const BeamSystem &sys, PetscInt dof)
{
  if (dof < 0) return "the ball's contact spring";
  for (const PartInstance &p : sys.parts) // a registered part's fields
    if (dof % sys.fields >= p.first && dof % sys.fields < p.first + p.count) return p.part->Words();
  return sys.Rotation(1) ? "the beam's shear and its sections' rotation" : "the beam's bending";
}

void BeamSystemDampingApply(const BeamSystem &sys, const PetscReal *v, PetscInt ns, PetscInt d0, PetscInt d1,
                            PetscReal *f, PetscInt os)
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

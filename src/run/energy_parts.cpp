// The structure's energy at the end, split into rigid motions and parts. See energy_parts.hpp.
#include "run/energy_parts.hpp"

#include <cmath>
#include <limits>
#include <set>

namespace beamimpact {

namespace {

// The velocity field of motion r over the dofs (held dofs 0).
std::vector<PetscReal> RigidField(const BeamSystem &sys, const RigidMotion &r)
{
  switch (r.kind) {
  case RigidKind::Translation:
    return BeamSystemRigidVelocity(sys, 1, 0, 0);
  case RigidKind::Rotation:
    return BeamSystemRigidVelocity(sys, -r.x_axis, 1, 0);
  default:
    return BeamSystemRigidVelocity(sys, 0, 0, 1);
  }
}

// Account a's momenta along the three kinds of field: sum m v over its deflections (kg m/s), sum m x v
// plus a section's spin (kg m^2/s), sum m z v plus the roll's rho J phi_t (kg m^2/s). A part's are
// its deflections' across the face (StateMeasures::account_momentum); the beam's account holds the
// translation and moment the others do not, the rolling part's (BeamSystem::RollField) the roll.
void AccountMomenta(const BeamSystem &sys, const StateMeasures &m, PetscInt a, PetscReal out[3])
{
  const PetscInt A = StructureAccountCount(), roll = sys.RollField() >= 0 ? sys.AccountOf(sys.RollField()) : -1;
  for (int k = 0; k < 3; ++k) out[k] = a == 0 ? 0 : m.account_momentum[a][k];
  if (a == 0) {
    out[0] = m.beam_momentum, out[1] = m.beam_moment;
    for (PetscInt b = 1; b < A; ++b) out[0] -= m.account_momentum[b][0], out[1] -= m.account_momentum[b][1];
  }
  if (a == roll) {
    out[2] = m.beam_roll;
    for (PetscInt b = 0; b < A; ++b)
      if (b != roll) out[2] -= m.account_momentum[b][2];
  }
}

// Account a's energy, kinetic and strain (J): a part's as measured, the beam's the rest of beam_kinetic
// and beam_strain (an account apart, the wall's, is not in them).
PetscReal AccountEnergy(const StateMeasures &m, PetscInt a)
{
  if (a != 0) return m.account_energy[a];
  PetscReal e = m.beam_kinetic + m.beam_strain;
  for (PetscInt b = 1; b < StructureAccountCount(); ++b)
    if (!StructureAccountApart(b)) e -= m.account_energy[b];
  return e;
}

// The momentum of part p along motion r: <c_r, v> over its dofs.
PetscReal MomentumAlong(const RigidMotion &r, const PetscReal P[3])
{
  switch (r.kind) {
  case RigidKind::Translation:
    return P[0];
  case RigidKind::Rotation:
    return P[1] - r.x_axis * P[0];
  default:
    return P[2];
  }
}

} // namespace

const char *RigidKindName(RigidKind k)
{
  static const char *const names[kRigidKinds] = {"translation", "rotation", "roll"};
  return names[(int)k];
}

std::vector<RigidMotion> ReportedRigidMotions(const BeamParams &beam)
{
  std::vector<RigidMotion> out;
  if (beam.has_clamp || beam.left == Support::Clamped || beam.right == Support::Clamped)
    return out;            // a clamp holds the roll too
  std::set<PetscInt> pins; // the nodes held by a pin
  if (beam.left == Support::Pinned) pins.insert(0);
  if (beam.right == Support::Pinned) pins.insert(beam.nodes - 1);
  if (beam.has_pivot) pins.insert(BeamPivotNode(beam));
  if (pins.empty()) out.push_back({RigidKind::Translation, 0}), out.push_back({RigidKind::Rotation, 0});
  else if (pins.size() == 1) out.push_back({RigidKind::Rotation, *pins.begin() * beam.length / (beam.nodes - 1)});
  if (beam.parts.Rolls()) out.push_back({RigidKind::Roll, 0});
  return out;
}

bool HasRigidMotion(const BeamParams &beam, RigidKind k)
{
  for (const RigidMotion &r : ReportedRigidMotions(beam))
    if (r.kind == k) return true;
  return false;
}

EnergySplit EnergySplitOf(const BeamParams &beam, const BeamSystem &sys, const StateMeasures &m)
{
  const std::vector<RigidMotion> motions = ReportedRigidMotions(beam);
  const int                      k       = (int)motions.size(); // <= 3
  EnergySplit                    out;
  for (PetscReal &e : out.rigid) e = std::numeric_limits<PetscReal>::quiet_NaN();
  // The Gram matrices <c_a, c_b> of the fields per part, and the momenta <c_a, v> per part.
  const PetscInt                      A                      = StructureAccountCount();
  PetscReal                           Gp[kMaxAccounts][3][3] = {}, G[3][3] = {}, mup[kMaxAccounts][3] = {}, mu[3] = {};
  std::vector<std::vector<PetscReal>> c;
  for (const RigidMotion &r : motions) c.push_back(RigidField(sys, r));
  for (PetscInt d = 0; d < sys.ndof; ++d) {
    const PetscInt p = sys.AccountOf(d % sys.fields);
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) Gp[p][a][b] += sys.mass[d] * c[a][d] * c[b][d];
  }
  for (PetscInt p = 0; p < A; ++p) {
    PetscReal P[3];
    AccountMomenta(sys, m, p, P);
    for (int a = 0; a < k; ++a) mup[p][a] = MomentumAlong(motions[a], P), mu[a] += mup[p][a];
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) G[a][b] += Gp[p][a][b];
  }
  // Gram-Schmidt in the mass inner product, in the order of the motions: e_j = sum_a C[j][a] c_a.
  // The projection of v on them is v_r = sum_a alpha_a c_a; E_j = <e_j, v>^2 / 2 <e_j, e_j>.
  PetscReal C[3][3] = {}, norm[3] = {}, alpha[3] = {};
  auto      inner = [&](const PetscReal *x, const PetscReal *y) {
    PetscReal s = 0;
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) s += x[a] * G[a][b] * y[b];
    return s;
  };
  for (int j = 0; j < k; ++j) {
    C[j][j] = 1;
    for (int i = 0; i < j; ++i) {
      if (norm[i] <= 0) continue;
      const PetscReal proj = inner(C[j], C[i]) / norm[i];
      for (int a = 0; a < k; ++a) C[j][a] -= proj * C[i][a];
    }
    norm[j] = inner(C[j], C[j]);
    if (!(norm[j] > 1e-12 * G[j][j])) { // no inertia of its own (a roll of I_x = 0): nothing in it
      norm[j] = 0, out.rigid[(int)motions[j].kind] = 0;
      continue;
    }
    PetscReal s = 0;
    for (int a = 0; a < k; ++a) s += C[j][a] * mu[a];
    out.rigid[(int)motions[j].kind] = s * s / (2 * norm[j]);
    for (int a = 0; a < k; ++a) alpha[a] += s / norm[j] * C[j][a];
  }
  // Each part's flexible energy: its energy less its dofs' share of the rigid velocity field,
  // 1/2 sum_p m (v - v_r)^2 = T_p - <v_r, v>_p + 1/2 <v_r, v_r>_p, the strain unchanged.
  for (PetscInt p = 0; p < A; ++p) {
    PetscReal cross = 0, self = 0;
    for (int a = 0; a < k; ++a) {
      cross += alpha[a] * mup[p][a];
      for (int b = 0; b < k; ++b) self += alpha[a] * Gp[p][a][b] * alpha[b];
    }
    out.flexible[p] = AccountEnergy(m, p) - cross + 0.5 * self;
  }
  return out;
}

void ModeEnergiesLabel(const BeamParams &beam, const BeamModes &modes, std::vector<ModeEnergy> *energies)
{
  const BeamSystem              &sys     = modes.sys;
  const ModalSystem             &S       = modes.S;
  const PetscInt                 n       = S.n;
  const std::vector<RigidMotion> motions = ReportedRigidMotions(beam);
  // The reported motions over the free dofs in mass-normalised coordinates (sqrt(m) c),
  // orthonormalised in their order: a rigid mode is the one it overlaps most.
  std::vector<PetscReal> U;
  std::vector<RigidKind> kinds;
  for (const RigidMotion &r : motions) {
    const std::vector<PetscReal> c = RigidField(sys, r);
    std::vector<PetscReal>       u(n);
    PetscReal                    size = 0;
    for (PetscInt q = 0; q < n; ++q) u[q] = std::sqrt(S.mass[q]) * c[S.dof[q]], size += u[q] * u[q];
    if (!(size > 0)) continue;
    ModalOrthonormalize(U, n, (PetscInt)kinds.size(), 2, u.data());
    U.insert(U.end(), u.begin(), u.end());
    kinds.push_back(r.kind);
  }
  for (size_t k = 0; k < energies->size(); ++k) {
    ModeEnergy      &E   = (*energies)[k];
    const PetscReal *phi = &modes.B.Phi[k * n];
    if (E.rigid) {
      PetscReal best = -1;
      E.part         = "rigid";
      for (size_t j = 0; j < kinds.size(); ++j) {
        PetscReal o = 0;
        for (PetscInt q = 0; q < n; ++q) o += phi[q] * U[j * n + q];
        if (std::abs(o) > best) best = std::abs(o), E.part = RigidKindName(kinds[j]);
      }
      continue;
    }
    E.part = modes.PartLabels()[k];
  }
}

} // namespace beamimpact

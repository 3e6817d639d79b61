// The beam's modes, computed once per beam. See beam_modes.hpp.
#include "solvers/beam_modes.hpp"

#include <array>
#include <cmath>
#include <deque>

namespace beamimpact {

namespace {

// Everything of the system that the modes depend on, compared exactly: M, the held dofs, and
// K and C of the force operator (the same M, K and C have the same modes and decay rates).
bool SameBeam(const BeamSystem &a, const BeamSystem &b)
{
  return a.nodes == b.nodes && a.fields == b.fields && a.ndof == b.ndof && a.bw == b.bw && a.mass == b.mass && a.held == b.held && a.band == b.band &&
         a.forces.damping_band == b.forces.damping_band && a.forces.damping_diag == b.forces.damping_diag;
}

// The beam's rigid motions that its held dofs allow: deflection a + b x (field 0) and rotation
// b (field 1, Timoshenko), zero on every held dof, and verified to be strain-free (K v = 0 to
// round-off of the factored K). Each as a full dof vector.
std::vector<std::vector<PetscReal>> RigidMotions(const BeamSystem &sys)
{
  const PetscInt         nd = sys.ndof, nf = sys.fields;
  std::vector<PetscReal> c[2] = {std::vector<PetscReal>(nd, 0.0), std::vector<PetscReal>(nd, 0.0)};
  for (PetscInt d = 0; d < nd; ++d) {
    const PetscInt f = d % nf;
    c[0][d]          = f == 0 ? 1.0 : 0.0;
    c[1][d]          = f == 0 ? sys.NodeX(d / nf) / sys.L : (f == 1 ? 1.0 / sys.L : 0.0);
  }
  // Combinations a c0 + b c1 vanishing on the held dofs: the null space of the 2-column H.
  PetscReal hh[2][2] = {{0, 0}, {0, 0}}; // H^T H
  for (PetscInt d = 0; d < nd; ++d)
    if (sys.held[d])
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) hh[i][j] += c[i][d] * c[j][d];
  std::vector<std::array<PetscReal, 2>> combos;
  const PetscReal                       tr = hh[0][0] + hh[1][1], det = hh[0][0] * hh[1][1] - hh[0][1] * hh[1][0];
  if (tr == 0.0) combos = {{1.0, 0.0}, {0.0, 1.0}};
  else if (std::abs(det) <= 1e-12 * tr * tr) { // rank 1: the eigenvector of H^T H for eigenvalue 0
    if (hh[0][0] >= hh[1][1]) combos = {{-hh[0][1], hh[0][0]}};
    else combos = {{hh[1][1], -hh[1][0]}};
  }
  std::vector<std::vector<PetscReal>> out;
  std::vector<PetscReal>              f(nd);
  for (const auto &ab : combos) {
    std::vector<PetscReal> v(nd);
    PetscReal              vmax = 0, fmax = 0, kmax = 0;
    for (PetscInt d = 0; d < nd; ++d) {
      v[d] = sys.held[d] ? 0.0 : ab[0] * c[0][d] + ab[1] * c[1][d];
      vmax = std::max(vmax, std::abs(v[d]));
    }
    for (PetscReal b : sys.band) kmax = std::max(kmax, std::abs(b));
    BeamSystemStiffnessApply(sys, v.data(), nf, 0, nd, f.data(), 1);
    for (PetscInt d = 0; d < nd; ++d) fmax = std::max(fmax, std::abs(f[d]));
    if (vmax > 0 && fmax <= 1e-9 * kmax * vmax) out.push_back(v);
  }
  return out;
}

// The zero cluster of the computed basis (omega below 1e-3 frequency units; every flexural
// mode of a beam is above 1) replaced by the exact rigid motions, and the flexible modes made
// orthogonal to them (twice, classical Gram-Schmidt). syev and inverse iteration find the
// null space only to eps omega_max^2 / omega_1^2 (1e-11 at N = 41, worse on finer grids), so
// that the computed flexible modes carry a little momentum and a free beam would lose some
// over a window; with the exact rigid modes momentum and angular momentum are kept to
// round-off. Their omega is exactly 0 and they decay only by alpha (C phi = alpha M phi).
void ExactRigidModes(BeamModes *m)
{
  const ModalSystem &S = m->S;
  const PetscInt     n = S.n;
  ModalBasis        &B = m->B;
  PetscInt           nz = 0;
  while (nz < n && B.omega[nz] < 1e-3 * m->sys.frequency_unit) nz++;
  const auto rigid = RigidMotions(m->sys);
  if (nz > 0 && (PetscInt)rigid.size() == nz) {
    for (PetscInt k = 0; k < nz; ++k) { // M^{1/2} v on the free dofs, orthonormal
      PetscReal *phi = &B.Phi[(size_t)k * n];
      for (PetscInt d = 0; d < n; ++d) phi[d] = std::sqrt(S.mass[d]) * rigid[k][S.dof[d]];
      ModalOrthonormalize(B.Phi, n, k, 2, phi);
    }
    for (PetscInt k = nz; k < n; ++k) ModalOrthonormalize(B.Phi, n, nz, 2, &B.Phi[(size_t)k * n]);
  }
  PetscReal alpha, beta; // C = alpha M + beta K: a rigid mode decays by alpha alone (K phi = 0)
  S.Rayleigh(&alpha, &beta);
  for (PetscInt k = 0; k < nz; ++k) {
    B.omega[k] = 0;
    B.rate[k]  = 0.5 * alpha;
  }
}

std::deque<std::shared_ptr<const BeamModes>> cache; // most recent first
PetscInt                                     n_computed = 0, n_reused = 0;

} // namespace

bool BeamModesAvailable(const BeamSystem &sys, std::string *why)
{
  PetscInt n = 0;
  if (!ForceOperatorModal(sys, nullptr, nullptr, why)) return false; // a force term the modes cannot carry (the grip: a drive in time, a damper not proportional)
  for (PetscInt d = 0; d < sys.ndof; ++d) n += sys.held[d] ? 0 : 1;
  if (n > BeamModesMaxDofs) {
    if (why) *why = "the beam has " + std::to_string(n) + " free dofs, above the " + std::to_string(BeamModesMaxDofs) + " of the dense modal decomposition";
    return false;
  }
  return true;
}

PetscErrorCode BeamModesShared(const BeamSystem &sys, std::shared_ptr<const BeamModes> *modes)
{
  std::string why;

  PetscFunctionBeginUser;
  for (auto it = cache.begin(); it != cache.end(); ++it)
    if (SameBeam((*it)->sys, sys)) {
      *modes = *it;
      if (it != cache.begin()) {
        cache.erase(it);
        cache.push_front(*modes);
      }
      n_reused++;
      PetscFunctionReturn(0);
    }
  PetscCheck(BeamModesAvailable(sys, &why), PETSC_COMM_SELF, PETSC_ERR_SUP, "the beam's modes: %s", why.c_str());
  auto          m  = std::make_shared<BeamModes>();
  const double  w0 = MPI_Wtime();
  m->sys           = sys;
  m->S             = ModalSystemBeamOnly(m->sys);
  PetscCall(ModalBasisBuild(m->S, false, &m->B));
  ExactRigidModes(m.get());
  m->build_seconds = MPI_Wtime() - w0;
  n_computed++;
  cache.push_front(m);
  while ((int)cache.size() > BeamModesCacheSize) cache.pop_back();
  *modes = m;
  PetscFunctionReturn(0);
}

void BeamModesCacheCounts(PetscInt *computed, PetscInt *reused)
{
  *computed = n_computed;
  *reused   = n_reused;
}

} // namespace beamimpact

// The exact free vibration after a separation. See free_flight.hpp.
#include "run/free_flight.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace beamimpact {

PetscErrorCode StepperGatherState(Stepper &st, const BeamSystem &sys, FullState *s)
{
  StateView   v;
  PetscMPIInt size;
  MPI_Comm    comm = st.Comm();

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(st.ViewBegin(&v));
  const PetscInt         nf = sys.fields, d0 = v.d0, d1 = v.d1;
  std::vector<PetscReal> own(2 * (d1 - d0));
  for (PetscInt d = d0; d < d1; ++d) {
    own[2 * (d - d0)]     = v.y[(d / nf) * v.y_stride + d % nf];
    own[2 * (d - d0) + 1] = v.v[(d / nf) * v.v_stride + d % nf];
  }
  s->ball_y     = v.ball_y;
  s->ball_v     = v.ball_v;
  s->dissipated = st.Dissipated();
  PetscCall(st.ViewEnd(&v));
  std::vector<PetscReal> all(2 * sys.ndof);
  if (size == 1) all = own;
  else {
    std::vector<PetscMPIInt> counts(size), displs(size);
    const PetscMPIInt        mine = (PetscMPIInt)own.size();
    PetscCallMPI(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
    for (PetscMPIInt r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
    PetscCallMPI(
      MPI_Allgatherv(own.data(), mine, MPIU_REAL, all.data(), counts.data(), displs.data(), MPIU_REAL, comm));
  }
  s->y.resize(sys.ndof);
  s->v.resize(sys.ndof);
  for (PetscInt d = 0; d < sys.ndof; ++d) {
    s->y[d] = all[2 * d];
    s->v[d] = all[2 * d + 1];
  }
  PetscFunctionReturn(0);
}

namespace {

// sup over s >= 0 of |z_k^(p)| for mode k (p = 0, 1, 2).
PetscReal ModeSup(const BeamModes &m, PetscInt k, PetscReal z, PetscReal zd, int p)
{
  const PetscReal w = m.B.omega[k], sigma = m.B.rate[k];
  if (sigma > 0) return ModalModeBound(w, sigma, z, zd, p);
  if (w == 0.0) return p == 0 ? PETSC_INFINITY : (p == 1 ? std::abs(zd) : 0.0);
  return std::hypot(z, zd / w) * std::pow(w, p);
}

// Mode k at s: z, z', z''.
void ModeAt(const BeamModes &m, PetscInt k, PetscReal z, PetscReal zd, PetscReal s, PetscReal d[3])
{
  const PetscReal w = m.B.omega[k], sigma = m.B.rate[k];
  if (sigma > 0) {
    ModalModeAt(w, sigma, z, zd, s, &d[0], &d[1]);
    d[2] = -2 * sigma * d[1] - w * w * d[0];
  } else if (w == 0.0) {
    d[0] = z + zd * s;
    d[1] = zd;
    d[2] = 0;
  } else {
    const PetscReal cs = std::cos(w * s), sn = std::sin(w * s);
    d[0] = z * cs + zd * sn / w;
    d[1] = -z * w * sn + zd * cs;
    d[2] = -w * w * d[0];
  }
}

// Beam energy (J) of modal coordinates: 1/2 sum (zd^2 + w^2 z^2) (mass-normalised modes).
PetscReal ModalEnergyOf(const BeamModes &m, const std::vector<PetscReal> &z, const std::vector<PetscReal> &zd)
{
  PetscReal E = 0;
  for (size_t k = 0; k < z.size(); ++k) E += 0.5 * (zd[k] * zd[k] + m.B.omega[k] * m.B.omega[k] * z[k] * z[k]);
  return E;
}

} // namespace

namespace {

// gamma_k = sum_q w_q phi_k[d_q] / sqrt(m_{d_q}) over the coupled free dofs (the coupling's
// few entries, in the free dofs' order: the dense dot product's value, its other terms being
// zeros), the beam's energy and the bounds on c', c'' over s >= 0, from ff's z, zd.
void FreeFlightCouple(const ContactCoupling &g, FreeFlight *ff)
{
  const BeamModes       &m = *ff->modes;
  const PetscInt         n = m.S.n, nm = m.Count();
  std::vector<PetscInt>  coupled;
  std::vector<PetscReal> gw;
  for (PetscInt d = 0; d < n; ++d) {
    PetscReal w = 0;
    for (PetscInt q = 0; q < g.n; ++q)
      if (m.S.dof[d] == g.dof[q]) w += g.w[q] / std::sqrt(m.S.mass[d]);
    if (w != 0.0) coupled.push_back(d), gw.push_back(w);
  }
  ff->gamma.assign(nm, 0.0);
  for (PetscInt k = 0; k < nm; ++k) {
    const PetscReal *phi = &m.B.Phi[(size_t)k * n];
    PetscReal        c   = 0;
    for (size_t j = 0; j < coupled.size(); ++j) c += phi[coupled[j]] * gw[j];
    ff->gamma[k] = c;
  }
  ff->energy0 = ModalEnergyOf(m, ff->z, ff->zd);
  ff->L1      = std::abs(ff->vb0);
  ff->L2      = 0;
  for (PetscInt k = 0; k < nm; ++k) {
    if (ff->gamma[k] == 0.0) continue;
    ff->L1 += std::abs(ff->gamma[k]) * ModeSup(m, k, ff->z[k], ff->zd[k], 1);
    ff->L2 += std::abs(ff->gamma[k]) * ModeSup(m, k, ff->z[k], ff->zd[k], 2);
  }
}

} // namespace

void FreeFlightStart(std::shared_ptr<const BeamModes> modes, const ContactCoupling &g, PetscReal t0, const FullState &s,
                     FreeFlight *ff)
{
  const BeamModes &m = *modes;
  const PetscInt   n = m.S.n, nm = m.Count(); // free dofs, modes kept
  *ff             = FreeFlight();
  ff->modes       = modes;
  ff->t0          = t0;
  ff->yb0         = s.ball_y;
  ff->vb0         = s.ball_v;
  ff->dissipated0 = s.dissipated;
  ff->z.assign(nm, 0.0);
  ff->zd.assign(nm, 0.0);
  // z = Phi^T M^{1/2} q over the free dofs.
  std::vector<PetscReal> sy(n), sv(n);
  for (PetscInt d = 0; d < n; ++d) {
    const PetscReal sm = std::sqrt(m.S.mass[d]);
    sy[d]              = sm * s.y[m.S.dof[d]];
    sv[d]              = sm * s.v[m.S.dof[d]];
  }
  for (PetscInt k = 0; k < nm; ++k) {
    const PetscReal *phi = &m.B.Phi[(size_t)k * n];
    PetscReal        a = 0, b = 0;
    for (PetscInt d = 0; d < n; ++d) {
      a += phi[d] * sy[d];
      b += phi[d] * sv[d];
    }
    ff->z[k]  = a;
    ff->zd[k] = b;
  }
  FreeFlightCouple(g, ff);
}

void FreeFlightStartModal(std::shared_ptr<const BeamModes> modes, const ContactCoupling &g, PetscReal t0,
                          const ModalState &s, FreeFlight *ff)
{
  *ff             = FreeFlight();
  ff->modes       = modes;
  ff->t0          = t0;
  ff->yb0         = s.ball_y;
  ff->vb0         = s.ball_v;
  ff->dissipated0 = s.dissipated;
  ff->z           = s.z;
  ff->zd          = s.zd;
  FreeFlightCouple(g, ff);
}

PetscReal FreeFlightCompression(const FreeFlight &ff, PetscReal s, int p, PetscReal *mag)
{
  const BeamModes &m = *ff.modes;
  PetscReal        c = 0, a = 0, d[3];
  if (p == 0) c = ff.yb0 + ff.vb0 * s, a = std::abs(ff.yb0) + std::abs(ff.vb0 * s);
  else if (p == 1) c = ff.vb0, a = std::abs(ff.vb0);
  for (size_t k = 0; k < ff.z.size(); ++k) {
    if (ff.gamma[k] == 0.0) continue;
    ModeAt(m, (PetscInt)k, ff.z[k], ff.zd[k], s, d);
    c -= ff.gamma[k] * d[p];
    a += std::abs(ff.gamma[k] * d[p]);
  }
  if (mag) *mag = a;
  return c;
}

bool FreeFlightFirstContact(FreeFlight &ff, PetscReal s_end, PetscReal s_min, PetscReal *root)
{
  const PetscReal eps = std::numeric_limits<PetscReal>::epsilon();
  PetscReal       mag, s = 0;
  auto            f_at = [&](PetscReal x) {
    ff.evals++;
    const PetscReal c = FreeFlightCompression(ff, x, 0, &mag);
    return -c - 64 * eps * mag; // f less its round-off: f > 0 here means c < 0 for sure
  };
  if (s_end <= 0) return false;
  PetscReal f = f_at(s);
  // Leave the separation we start on (c within the event tolerance of 0, falling).
  for (int guard = 0; f <= 0; ++guard) {
    if (s >= s_end) return false;
    if (guard > 200) { // c did not become negative: the ball is still (or again) touching
      *root = s;
      return true;
    }
    s = std::min(s_end, s + s_min * std::pow(2.0, std::min(guard, 40)));
    f = f_at(s);
  }
  for (long it = 0; s < s_end; ++it) {
    if (it > 100000000L) { // cannot happen with a positive s_min; a guard against a bound gone wrong
      *root = s;
      return true;
    }
    const PetscReal fd = -FreeFlightCompression(ff, s, 1);
    PetscReal       d  = ff.L1 > 0 ? f / ff.L1 : PETSC_INFINITY;
    if (ff.L2 > 0) d = std::max(d, (fd + std::sqrt(fd * fd + 2 * ff.L2 * f)) / ff.L2);
    else if (fd < 0) d = std::max(d, -f / fd);
    else d = PETSC_INFINITY;
    d                  = std::max(d * (1 - 1e-9), s_min);
    const PetscReal sn = std::min(s_end, s + d);
    const PetscReal fn = f_at(sn);
    if (fn <= 0) { // a root in (s, sn]: bisect to round-off, the contact side
      PetscReal a = s, b = sn;
      for (int k = 0; k < 200 && b - a > 4 * eps * b; ++k) {
        const PetscReal mid = 0.5 * (a + b);
        ff.evals++;
        (-FreeFlightCompression(ff, mid, 0) > 0 ? a : b) = mid;
      }
      *root = b;
      return true;
    }
    s = sn;
    f = fn;
  }
  return false;
}

void FreeFlightState(const FreeFlight &ff, PetscReal s, FullState *out)
{
  const BeamModes       &m = *ff.modes;
  const PetscInt         n = m.S.n, nm = m.Count();
  std::vector<PetscReal> zs(nm), zds(nm), yy(n, 0.0), vv(n, 0.0);
  PetscReal              d[3];
  for (PetscInt k = 0; k < nm; ++k) {
    ModeAt(m, k, ff.z[k], ff.zd[k], s, d);
    zs[k]  = d[0];
    zds[k] = d[1];
  }
  for (PetscInt k = 0; k < nm; ++k) {
    const PetscReal *phi = &m.B.Phi[(size_t)k * n];
    for (PetscInt r = 0; r < n; ++r) {
      yy[r] += phi[r] * zs[k];
      vv[r] += phi[r] * zds[k];
    }
  }
  out->y.assign(m.sys.ndof, 0.0);
  out->v.assign(m.sys.ndof, 0.0);
  for (PetscInt r = 0; r < n; ++r) {
    const PetscReal im = 1 / std::sqrt(m.S.mass[r]);
    out->y[m.S.dof[r]] = im * yy[r];
    out->v[m.S.dof[r]] = im * vv[r];
  }
  out->ball_y     = ff.yb0 + ff.vb0 * s;
  out->ball_v     = ff.vb0;
  out->dissipated = ff.dissipated0 + (m.sys.Damped() ? ff.energy0 - ModalEnergyOf(m, zs, zds) : 0.0);
}

void FreeFlightModalState(const FreeFlight &ff, PetscReal s, ModalState *out)
{
  const BeamModes &m  = *ff.modes;
  const PetscInt   nm = m.Count();
  PetscReal        d[3];
  out->z.resize(nm);
  out->zd.resize(nm);
  for (PetscInt k = 0; k < nm; ++k) {
    ModeAt(m, k, ff.z[k], ff.zd[k], s, d);
    out->z[k]  = d[0];
    out->zd[k] = d[1];
  }
  out->ball_y     = ff.yb0 + ff.vb0 * s;
  out->ball_v     = ff.vb0;
  out->dissipated = ff.dissipated0 + (m.sys.Damped() ? ff.energy0 - ModalEnergyOf(m, out->z, out->zd) : 0.0);
}

std::vector<ModeEnergy> FreeFlightModeEnergies(const FreeFlight &ff, PetscReal s)
{
  const BeamModes        &m = *ff.modes;
  std::vector<ModeEnergy> e(ff.z.size());
  PetscReal               d[3];
  for (size_t k = 0; k < e.size(); ++k) {
    const PetscReal w = m.B.omega[k];
    ModeAt(m, (PetscInt)k, ff.z[k], ff.zd[k], s, d);
    e[k].frequency = w / (2 * M_PI);
    e[k].energy    = 0.5 * (d[1] * d[1] + w * w * d[0] * d[0]);
    e[k].rigid     = (PetscInt)k < m.rigid;
  }
  return e;
}

} // namespace beamimpact

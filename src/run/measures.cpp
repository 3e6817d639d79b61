// Measures of the current state of a stepper. See measures.hpp.
#include "run/measures.hpp"

#include "solvers/beam_modes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace beamimpact {

namespace {

// Per-mode weights of the beam's momenta, computed once per basis (ModalMomentaOf). A unit rate
// of mode k moves free dof r at phi_k[r] / sqrt(m_r) (mass-normalised, solvers/beam_modes.hpp),
// so its momentum sum m v over the beam's deflections (field 0) is sum_r sqrt(m_r) phi_k[r] and
// its moment about x = 0 the same with x_r, plus a Timoshenko section's spin sqrt(m_r) phi_k[r]:
// the sums MeasureState takes over the dofs, moved onto the modes.
struct ModalMomenta {
  std::weak_ptr<const BeamModes> basis;
  std::vector<PetscReal>         momentum, moment; // kg^{1/2}, kg^{1/2} m per mode
};

const ModalMomenta &ModalMomentaOf(const std::shared_ptr<const BeamModes> &modes)
{
  static ModalMomenta last; // the last basis measured: a sweep's points share it
  if (last.basis.lock() == modes) return last;
  const BeamSystem      &sys = modes->sys;
  const ModalSystem     &S   = modes->S;
  const PetscInt         n = S.n, F = sys.fields, nm = modes->Count();
  std::vector<PetscReal> sm(n), x(n);
  std::vector<int>       kind(n); // 0: the deflection (field 0), 1: a section's rotation, 2: neither
  for (PetscInt r = 0; r < n; ++r) {
    const PetscInt d = S.dof[r], f = d % F;
    sm[r]   = std::sqrt(S.mass[r]);
    x[r]    = sys.NodeX(d / F);
    kind[r] = f == 0 ? 0 : f == 1 && sys.Rotation(1) ? 1 : 2;
  }
  last.momentum.assign(nm, 0.0);
  last.moment.assign(nm, 0.0);
  for (PetscInt k = 0; k < nm;
       ++k) { // compensated sums (Neumaier): a rigid mode's n terms of one sign, its weight to round-off
    const PetscReal *phi = &modes->B.Phi[(size_t)k * n];
    PetscReal        p = 0, q = 0, cp = 0, cq = 0;
    auto             add = [](PetscReal &sum, PetscReal &c, PetscReal a) {
      const PetscReal t = sum + a;
      c += std::abs(sum) >= std::abs(a) ? (sum - t) + a : (a - t) + sum;
      sum = t;
    };
    for (PetscInt r = 0; r < n; ++r) {
      if (kind[r] == 0) add(p, cp, sm[r] * phi[r]), add(q, cq, sm[r] * x[r] * phi[r]);
      else if (kind[r] == 1) add(q, cq, sm[r] * phi[r]);
    }
    last.momentum[k] = p + cp;
    last.moment[k]   = q + cq;
  }
  last.basis = modes;
  return last;
}

// Whether the system has parts whose energies are kept apart from the beam's (a barrel wall, the
// frame's roll, a string bed): without, their sums are 0 and BeamSystemAccountEnergies is not needed.
bool SeparateParts(const BeamSystem &S)
{
  for (PetscInt f = 0; f < S.fields; ++f)
    if (S.AccountOf(f) != 0) return true;
  return false;
}

// MeasureState's layout of `sums` after G (the end of its point velocities): the force operator's
// four frame terms, the wall's share of the compression (G + 4), the roll momentum (G + 5), then
// kAccountSums for each energy account (AccountSums), then the registered parts' slots (PartSlots).
constexpr PetscInt kAccountSums = 5;
// Account a's sums: its stored and kinetic energy (an account apart from the beam's: the wall's), or
// its stored plus kinetic energy and 0; its deflections' momentum, moment and roll momentum.
PetscInt AccountSums(PetscInt G, PetscInt a) { return G + 6 + kAccountSums * a; }
PetscInt PartSlots(PetscInt G) { return AccountSums(G, StructureAccountCount()); }

// Whether the measures of a state held in modes can be taken in them: the energies are then sums
// over the modes (mass-normalised: kinetic 1/2 sum zd_k^2, strain 1/2 sum w_k^2 z_k^2) and the
// momenta the projections above. Not with a monitor that asks for the physical state (point
// velocities, a segment's energy), nor with parts whose energies are kept apart (a barrel wall,
// the frame's roll, a string bed) or a term tied to the frame (the hands' springs and work): those are taken
// over the dofs, as are the registered parts' (their measures and rigid points).
bool MeasuresInModes(const BeamSystem &S, const MeasureContext &ctx, const MonitorRequest *mon)
{
  if (mon && (mon->segment || !mon->velocity_at.empty())) return false;
  return !SeparateParts(S) && !S.TiedToFrame() && !ForceOperatorDriven(S, ctx.frame) && S.parts.empty();
}

// The registered parts' share of the owned dofs: their rigid points' momentum *p and moment *l
// about x = 0, their slots.
void PartsMeasure(const BeamSystem &S, const StateView &sv, PetscReal *p, PetscReal *l, PetscReal *slot)
{
  const PetscInt F = S.fields;
  for (const RigidPoint &r : S.rigid_points) {
    if (r.dof < sv.d0 || r.dof >= sv.d1 || S.held[r.dof]) continue;
    const PetscReal mv = S.mass[r.dof] * sv.v[(r.dof / F) * sv.v_stride + r.dof % F];
    *p += mv, *l += r.x * mv;
  }
  PartState ps;
  ps.y = sv.y, ps.v = sv.v, ps.ys = sv.y_stride, ps.vs = sv.v_stride, ps.d0 = sv.d0, ps.d1 = sv.d1;
  StructurePartsMeasure(S, ps, slot);
}

// The structure's measures from the sums over the state (MeasureState's layout of `sums`, G the
// end of its point velocities) and the bed's largest deflection.
void StructureFromSums(const BeamSystem &S, PetscInt G, const std::vector<PetscReal> &sums, PetscReal bed_max,
                       StateMeasures *m)
{
  PetscReal T = sums[0], U = sums[1]; // without the shares of the accounts apart (the wall's)
  m->apart_energy = 0;
  for (PetscInt a = 1; a < StructureAccountCount(); ++a) {
    const PetscReal *e   = &sums[AccountSums(G, a)];
    m->account_energy[a] = e[0] + e[1];
    for (int k = 0; k < 3; ++k) m->account_momentum[a][k] = e[2 + k];
    if (StructureAccountApart(a)) T -= e[1], U -= e[0], m->apart_energy += e[0] + e[1];
  }
  m->beam_kinetic     = T;
  m->beam_strain      = U;
  m->apart_deflection = sums[G + 4];
  m->face_deflection  = bed_max;
  m->beam_roll        = sums[G + 5];
  m->beam_momentum    = sums[2];
  m->beam_moment      = sums[3];
  m->segment_kinetic  = sums[4];
  m->terms_stored     = sums[G];
  m->frame_force      = sums[G + 2];
  m->frame_moment     = sums[G + 3];
  for (size_t k = PartSlots(G); k < sums.size(); ++k) m->part_slot[k - PartSlots(G)] = sums[k]; // the parts' slots
}

// The measures from the sums over the state (MeasureState's layout of `sums`, G the end of its
// point velocities) and the bed's largest deflection, with the contact, the ball (m->ball_y and
// m->ball_v set) and the stepper's dissipation.
PetscErrorCode MeasuresFinish(Stepper &stepper, const MeasureContext &ctx, PetscInt G,
                              const std::vector<PetscReal> &sums, PetscReal bed_max, StateMeasures *m,
                              std::vector<PetscReal> *point_v)
{
  const BeamSystem &S = *ctx.sys;

  PetscFunctionBeginUser;
  PetscCall(MeasureBall(stepper, ctx, m));
  const BallParams &ball = *ctx.ball;
  StructureFromSums(S, G, sums, bed_max, m);
  m->roll_momentum    = sums[G + 5] + ball.mass * ctx.g->z * m->ball_v;
  m->momentum         = sums[2] + ball.mass * m->ball_v;
  m->angular_momentum = sums[3] + ball.mass * ctx.g->x * m->ball_v;
  m->beam_dissipated  = stepper.Dissipated();
  if (ForceOperatorDriven(S, ctx.frame))
    m->frame_work = sums[G + 1] + ball.mass * FrameMotionAt(*ctx.frame, *ctx.g) * m->ball_v -
                    ctx.frame->q0; // 0 for a frame at rest
  if (point_v) point_v->assign(sums.begin() + 5, sums.begin() + G);
  FrameMeasures fm; // the parts tied to the frame: their slots from its terms
  fm.stored = m->terms_stored, fm.work = m->frame_work, fm.force = m->frame_force, fm.moment = m->frame_moment;
  StructurePartsMeasureFrame(S, fm, m->part_slot);
  PetscFunctionReturn(0);
}

// -ts_type modal after a step: the measures in modes, O(modes), without writing the physical
// state (O(n modes)); *done false when the stepper's state is not in modes.
PetscErrorCode MeasureInModes(Stepper &stepper, const MeasureContext &ctx, PetscInt G, std::vector<PetscReal> &sums,
                              StateMeasures *m, std::vector<PetscReal> *point_v, bool *done)
{
  PetscFunctionBeginUser;
  *done = false;
  std::shared_ptr<const BeamModes> modes;
  ModalState                       ms;
  bool                             in_modes;
  PetscCall(stepper.ModalStateUnwritten(&modes, &ms, &in_modes));
  if (in_modes) {
    const ModalMomenta &w     = ModalMomentaOf(modes);
    const PetscReal    *omega = modes->B.omega.data();
    PetscReal           T = 0, U = 0, P = 0, L = 0;
    for (PetscInt k = 0; k < (PetscInt)ms.z.size(); ++k) {
      T += ms.zd[k] * ms.zd[k];
      U += omega[k] * omega[k] * ms.z[k] * ms.z[k];
      P += w.momentum[k] * ms.zd[k];
      L += w.moment[k] * ms.zd[k];
    }
    sums[0] = 0.5 * T, sums[1] = 0.5 * U, sums[2] = P, sums[3] = L;
    m->ball_y = ms.ball_y;
    m->ball_v = ms.ball_v;
    PetscCall(MeasuresFinish(stepper, ctx, G, sums, 0.0, m, point_v)); // the same on every rank: no reduction
    *done = true;
  }
  PetscFunctionReturn(0);
}

// The owned dofs' kinetic energy, the force operator's stored energy and frame terms, the
// accounts' energies and the wall's share of the compression (sums[0], sums[1], sums[G ... G + 4],
// AccountSums).
void MeasureEnergies(const BeamSystem &S, const MeasureContext &ctx, const StateView &sv, PetscReal t, PetscInt G,
                     std::vector<PetscReal> &sums)
{
  const PetscInt F = S.fields;
  ForceState     fs;
  fs.y     = sv.y;
  fs.ys    = sv.y_stride;
  fs.v     = sv.v;
  fs.vs    = sv.v_stride;
  fs.t     = t;
  fs.frame = ctx.frame;
  sums[0]  = BeamSystemKineticEnergy(S, sv.v, sv.v_stride, sv.d0, sv.d1);
  ForceOperatorEnergy(S, fs, sv.d0, sv.d1, &sums[1], &sums[G]);
  sums[G + 1] = ForceOperatorFrameMomentum(S, fs, sv.d0, sv.d1);
  ForceOperatorFrameReaction(S, fs, sv.d0, sv.d1, &sums[G + 2], &sums[G + 3]);
  if (SeparateParts(S)) { // else 0
    PetscReal stored[kMaxAccounts], kinetic[kMaxAccounts];
    BeamSystemAccountEnergies(S, sv.y, sv.y_stride, sv.v, sv.v_stride, sv.d0, sv.d1, stored, kinetic);
    for (PetscInt a = 1; a < StructureAccountCount(); ++a) {
      PetscReal *e = &sums[AccountSums(G, a)];
      if (StructureAccountApart(a)) e[0] = stored[a], e[1] = kinetic[a];
      else e[0] = stored[a] + kinetic[a];
    }
  }
  for (PetscInt q = 0; q < ctx.g->n;
       ++q) { // the wall's share of the compression: its displacement under the ball, into the bat
    const PetscInt d = ctx.g->dof[q];
    if (d >= sv.d0 && d < sv.d1 && StructureAccountApart(S.AccountOf(d % F)))
      sums[G + 4] += ctx.g->w[q] * sv.y[(d / F) * sv.y_stride + d % F];
  }
}

// The owned nodes' momenta (the deflections, the beam's field 0 and a string bed's, and the
// rotations) into sums[2], sums[3], the roll's and each account's deflections' (AccountSums), then
// the registered parts'; returns the bed's largest deflection from the frame on this rank (0
// without a bed).
PetscReal MeasureMomenta(const BeamSystem &S, const StateView &sv, PetscInt G, std::vector<PetscReal> &sums)
{
  const PetscInt F   = S.fields;
  auto           vel = [&](PetscInt node) { return sv.v[node * sv.v_stride]; };
  const PetscInt n0 = sv.d0 / F, n1 = sv.d1 / F;
  PetscReal      bed_max = 0;
  const PetscInt roll    = S.RollField();
  for (PetscInt i = n0; i < n1; ++i) {
    const PetscReal mi = S.mass[S.Dof(i)], x = S.NodeX(i);
    sums[2] += mi * vel(i);
    sums[3] += mi * x * vel(i);
    if (S.Rotation(1))
      sums[3] += S.mass[S.Dof(i, 1)] *
                 sv.v[i * sv.v_stride + 1]; // sections' spin (Timoshenko): conserved with the rest
    if (roll >= 0) sums[G + 5] += S.mass[S.Dof(i, roll)] * sv.v[i * sv.v_stride + roll];
    if (S.face_fields.empty()) continue;
    const PetscReal y = sv.y[i * sv.y_stride], phi = roll >= 0 ? sv.y[i * sv.y_stride + roll] : 0.0;
    for (const PetscInt f : S.face_fields) { // a string bed's nodes across the face (StructurePart::FieldZ)
      const PetscInt d = S.Dof(i, f);
      if (S.held[d]) continue;
      const PetscReal mv = S.mass[d] * sv.v[i * sv.v_stride + f], z = S.field_z[f];
      PetscReal      *own = &sums[AccountSums(G, S.AccountOf(f)) + 2];
      sums[2] += mv, sums[3] += x * mv, sums[G + 5] += z * mv;
      own[0] += mv, own[1] += x * mv, own[2] += z * mv;
      bed_max = std::max(bed_max, std::abs(sv.y[i * sv.y_stride + f] - y - z * phi));
    }
  }
  if (!S.parts.empty()) PartsMeasure(S, sv, &sums[2], &sums[3], sums.data() + PartSlots(G)); // (no slots: its end)
  return bed_max;
}

// The kinetic energy of -monitor_segment's sections (sums[4]) and the velocities at
// -monitor_velocity_at's points (sums[5 ...]) on the owned nodes.
void MeasureSegmentAndPoints(const BeamSystem &S, const StateView &sv, const MonitorRequest *mon,
                             const std::vector<PetscReal> &points, std::vector<PetscReal> &sums)
{
  const PetscInt F = S.fields, np = (PetscInt)points.size(), n0 = sv.d0 / F, n1 = sv.d1 / F;
  auto           vel = [&](PetscInt node) { return sv.v[node * sv.v_stride]; };
  if (mon && mon->segment) { // the frame's sections in [x0, x1]: every field of theirs (the deflections, a Timoshenko
                             // section's spin, the roll, a shell's wall) but a string bed's
    const PetscReal tol = 1e-9 * S.h;
    for (PetscInt i = n0; i < n1; ++i) {
      const PetscReal x = S.NodeX(i);
      if (x < mon->segment_x0 - tol || x > mon->segment_x1 + tol) continue;
      for (PetscInt f = 0; f < F; ++f) {
        if (S.Face(f)) continue;
        const PetscReal v = sv.v[i * sv.v_stride + f];
        sums[4] += 0.5 * S.mass[S.Dof(i, f)] * v * v;
      }
    }
  }
  for (PetscInt q = 0; q < np; ++q) {
    const ImpactStencil st = GridImpactStencil(S.nodes, S.L, points[q]);
    if (st.j >= n0 && st.j < n1) sums[5 + q] += st.w * vel(st.j);
    if (st.j + 1 >= n0 && st.j + 1 < n1) sums[5 + q] += (1 - st.w) * vel(st.j + 1);
  }
}

} // namespace

PetscErrorCode MeasureBall(Stepper &stepper, const MeasureContext &ctx, StateMeasures *m)
{
  const BallParams &ball = *ctx.ball;
  PetscReal         cdot;

  PetscFunctionBeginUser;
  PetscCall(stepper.Compression(&m->c, &cdot));
  m->force        = ContactForce(ball, *ctx.contact, m->c);
  m->c_rate       = cdot;
  m->force_rate   = ContactStiffness(ball, *ctx.contact, m->c) * cdot;
  m->ball_kinetic = 0.5 * ball.mass * m->ball_v * m->ball_v;
  m->ball_stored  = ContactStoredEnergy(ball, *ctx.contact, m->c);
  m->ball_work    = ContactWork(ball, *ctx.contact, m->c);
  PetscFunctionReturn(0);
}

PetscErrorCode MeasureState(Stepper &stepper, const MeasureContext &ctx, const MonitorRequest *mon, StateMeasures *m,
                            std::vector<PetscReal> *point_v)
{
  static const std::vector<PetscReal> none;
  const std::vector<PetscReal>       &points = mon ? mon->velocity_at : none;
  const BeamSystem                   &S      = *ctx.sys;
  StateView                           sv;

  PetscFunctionBeginUser;
  const PetscInt np = (PetscInt)points.size();
  const PetscInt
    G = 5 +
        np; // the force operator's other terms: stored energy, the frame's momentum term, force on the frame, moment
  // + the wall's displacement, the roll's momentum, each account's sums; then the registered parts' slots
  std::vector<PetscReal> sums(PartSlots(G) + StructurePartSlotCount(S), 0.0);
  if (MeasuresInModes(S, ctx, mon)) { // -ts_type modal after a step
    bool done;
    PetscCall(MeasureInModes(stepper, ctx, G, sums, m, point_v, &done));
    if (done) PetscFunctionReturn(0);
  }
  PetscCall(stepper.ViewBegin(&sv));
  MeasureEnergies(S, ctx, sv, stepper.Time(), G, sums);
  PetscReal bed_max = MeasureMomenta(S, sv, G, sums); // reduced in place below
  MeasureSegmentAndPoints(S, sv, mon, points, sums);
  m->ball_y = sv.ball_y;
  m->ball_v = sv.ball_v;
  PetscCall(stepper.ViewEnd(&sv));
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(stepper.Comm(), &size));
  if (size > 1)
    PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, sums.data(), (PetscMPIInt)sums.size(), MPIU_REAL, MPIU_SUM, stepper.Comm()));
  if (size > 1 && !S.face_fields.empty())
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bed_max, 1, MPIU_REAL, MPIU_MAX, stepper.Comm()));
  PetscCall(MeasuresFinish(stepper, ctx, G, sums, bed_max, m, point_v));
  PetscFunctionReturn(0);
}

PetscErrorCode MeasureStructureStates(MPI_Comm comm, const MeasureContext &ctx, const SampleRange &r,
                                      const std::vector<PetscReal> &y, const std::vector<PetscReal> &v,
                                      const std::vector<PetscReal> &t, std::vector<StateMeasures> *m)
{
  const BeamSystem &S = *ctx.sys;
  const PetscInt    G = 5, width = PartSlots(G) + StructurePartSlotCount(S), count = (PetscInt)t.size();
  const size_t      ne = (size_t)(r.e1 - r.e0);
  PetscMPIInt       size;

  PetscFunctionBeginUser;
  std::vector<PetscReal> sums((size_t)width * count, 0.0), bed_max(count, 0.0);
  for (PetscInt s = 0; s < count; ++s) { // as MeasureState's view of the stepper's state
    StateView sv;
    sv.y = y.data() + s * ne - r.e0, sv.v = v.data() + s * ne - r.e0;
    sv.y_stride = sv.v_stride = S.fields;
    sv.d0 = r.d0, sv.d1 = r.d1;
    std::vector<PetscReal> one(width, 0.0);
    MeasureEnergies(S, ctx, sv, t[s], G, one);
    bed_max[s] = MeasureMomenta(S, sv, G, one);
    std::copy(one.begin(), one.end(), sums.begin() + (size_t)s * width);
  }
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size > 1) {
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (PetscMPIInt)sums.size(), MPIU_REAL, MPIU_SUM, comm));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, bed_max.data(), (PetscMPIInt)count, MPIU_REAL, MPIU_MAX, comm));
  }
  m->assign(count, StateMeasures());
  for (PetscInt s = 0; s < count; ++s) {
    const std::vector<PetscReal> one(sums.begin() + (size_t)s * width, sums.begin() + (size_t)(s + 1) * width);
    StructureFromSums(S, G, one, bed_max[s], &(*m)[s]);
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

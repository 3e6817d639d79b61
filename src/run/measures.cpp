// Measures of the current state of a stepper. See measures.hpp.
#include "run/measures.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

PetscErrorCode MeasureState(Stepper &stepper, const MeasureContext &ctx, const MonitorRequest *mon, StateMeasures *m, std::vector<PetscReal> *point_v)
{
  static const std::vector<PetscReal> none;
  const std::vector<PetscReal>       &points = mon ? mon->velocity_at : none;
  const BeamSystem                   &S      = *ctx.sys;
  const PetscInt                      F      = S.fields;
  StateView                           sv;

  PetscFunctionBeginUser;
  PetscCall(stepper.ViewBegin(&sv));
  const PetscInt         np = (PetscInt)points.size();
  const PetscInt         G  = 5 + np; // the force operator's other terms: stored energy, the frame's momentum term, force on the frame, moment
  std::vector<PetscReal> sums(G + 10, 0.0); // + the wall's stored and kinetic energy and displacement, the twist's and bed's energies, the roll's momentum
  ForceState             fs;
  fs.y     = sv.y;
  fs.ys    = sv.y_stride;
  fs.v     = sv.v;
  fs.vs    = sv.v_stride;
  fs.t     = stepper.Time();
  fs.frame = ctx.frame;
  sums[0]  = BeamSystemKineticEnergy(S, sv.v, sv.v_stride, sv.d0, sv.d1);
  ForceOperatorEnergy(S, fs, sv.d0, sv.d1, &sums[1], &sums[G]);
  sums[G + 1] = ForceOperatorFrameMomentum(S, fs, sv.d0, sv.d1);
  ForceOperatorFrameReaction(S, fs, sv.d0, sv.d1, &sums[G + 2], &sums[G + 3]);
  PetscReal stored[kParts], kinetic[kParts];
  BeamSystemPartEnergies(S, sv.y, sv.y_stride, sv.v, sv.v_stride, sv.d0, sv.d1, stored, kinetic);
  sums[G + 4] = stored[(int)Part::Wall], sums[G + 5] = kinetic[(int)Part::Wall];
  sums[G + 7] = stored[(int)Part::Twist] + kinetic[(int)Part::Twist];
  sums[G + 8] = stored[(int)Part::Bed] + kinetic[(int)Part::Bed];
  for (PetscInt q = 0; q < ctx.g->n; ++q) { // the wall's share of the compression: its displacement under the ball, into the bat
    const PetscInt d = ctx.g->dof[q];
    if (S.Wall(d % F) && d >= sv.d0 && d < sv.d1) sums[G + 6] += ctx.g->w[q] * sv.y[(d / F) * sv.y_stride + d % F];
  }
  // The deflections (the beam's field 0 and a string bed's) and the rotations of the owned nodes.
  auto           vel = [&](PetscInt node) { return sv.v[node * sv.v_stride]; };
  const PetscInt n0 = sv.d0 / F, n1 = sv.d1 / F;
  PetscReal      bed_max = 0;
  for (PetscInt i = n0; i < n1; ++i) {
    const PetscReal mi = S.mass[S.Dof(i)], x = S.NodeX(i);
    sums[2] += mi * vel(i);
    sums[3] += mi * x * vel(i);
    if (S.Rotation(1)) sums[3] += S.mass[S.Dof(i, 1)] * sv.v[i * sv.v_stride + 1]; // sections' spin (Timoshenko): conserved with the rest
    if (S.roll_field >= 0) sums[G + 9] += S.mass[S.Dof(i, S.roll_field)] * sv.v[i * sv.v_stride + S.roll_field];
    if (S.bed_first < 0) continue;
    const PetscReal y = sv.y[i * sv.y_stride], phi = S.roll_field >= 0 ? sv.y[i * sv.y_stride + S.roll_field] : 0.0;
    for (PetscInt j = 0; j < S.bed.nz; ++j) {
      const PetscInt d = S.Dof(i, S.bed_first + j);
      if (S.held[d]) continue;
      const PetscReal mv = S.mass[d] * sv.v[i * sv.v_stride + S.bed_first + j], z = S.bed.Z(j);
      sums[2] += mv, sums[3] += x * mv, sums[G + 9] += z * mv;
      bed_max = std::max(bed_max, std::abs(sv.y[i * sv.y_stride + S.bed_first + j] - y - z * phi));
    }
  }
  if (mon && mon->segment) {
    const PetscReal tol = 1e-9 * S.h;
    for (PetscInt i = n0; i < n1; ++i) {
      const PetscReal x = S.NodeX(i);
      if (x >= mon->segment_x0 - tol && x <= mon->segment_x1 + tol) sums[4] += 0.5 * S.mass[S.Dof(i)] * vel(i) * vel(i);
    }
  }
  for (PetscInt q = 0; q < np; ++q) {
    const ImpactStencil st = GridImpactStencil(S.nodes, S.L, points[q]);
    if (st.j >= n0 && st.j < n1) sums[5 + q] += st.w * vel(st.j);
    if (st.j + 1 >= n0 && st.j + 1 < n1) sums[5 + q] += (1 - st.w) * vel(st.j + 1);
  }
  m->ball_y = sv.ball_y;
  m->ball_v = sv.ball_v;
  PetscCall(stepper.ViewEnd(&sv));
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(stepper.Comm(), &size));
  if (size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (PetscMPIInt)sums.size(), MPIU_REAL, MPIU_SUM, stepper.Comm()));
  if (size > 1 && S.bed_first >= 0) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bed_max, 1, MPIU_REAL, MPIU_MAX, stepper.Comm()));
  PetscReal cdot;
  PetscCall(stepper.Compression(&m->c, &cdot));
  const BallParams &ball = *ctx.ball;
  m->force               = ContactForce(ball, *ctx.contact, m->c);
  m->c_rate              = cdot;
  m->force_rate          = ContactStiffness(ball, *ctx.contact, m->c) * cdot;
  m->ball_kinetic        = 0.5 * ball.mass * m->ball_v * m->ball_v;
  m->ball_stored         = ContactStoredEnergy(ball, *ctx.contact, m->c);
  m->ball_work           = ContactWork(ball, *ctx.contact, m->c);
  m->beam_kinetic        = sums[0] - sums[G + 5]; // without the wall's share (exact: 0 without a wall)
  m->beam_strain         = sums[1] - sums[G + 4];
  m->shell_energy        = sums[G + 4] + sums[G + 5];
  m->wall_deflection     = sums[G + 6];
  m->twist_energy        = sums[G + 7];
  m->bed_energy          = sums[G + 8];
  m->bed_deflection      = bed_max;
  m->beam_roll           = sums[G + 9];
  m->roll_momentum       = sums[G + 9] + ball.mass * ctx.g->z * m->ball_v;
  m->momentum            = sums[2] + ball.mass * m->ball_v;
  m->angular_momentum    = sums[3] + ball.mass * ctx.g->x * m->ball_v;
  m->beam_momentum       = sums[2];
  m->beam_moment         = sums[3];
  m->segment_kinetic     = sums[4];
  m->beam_dissipated     = stepper.Dissipated();
  m->grip_stored = sums[G];
  m->grip_force  = sums[G + 2];
  m->grip_moment = sums[G + 3];
  if (ForceOperatorDriven(S, ctx.frame)) m->hand_work = sums[G + 1] + ball.mass * FrameMotionAt(*ctx.frame, *ctx.g) * m->ball_v - ctx.frame->q0; // 0 for a frame at rest
  if (point_v) point_v->assign(sums.begin() + 5, sums.begin() + G);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

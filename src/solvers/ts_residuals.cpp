// The TS residuals of the impact, one per formulation (ts_problem.hpp):
//   explicit      du/dt = [v; -(f(y, v, t) - g F)/m; v_b; -F/m_b]
//   IMEX          G(u, u') = [y' - v; v' + f(y, v, t)/m; y_b' - v_b; v_b'] = [0; g F/m; 0; -F/m_b]
//   implicit      G(u, u') = [y' - v; v' + (f(y, v, t) - g F)/m; y_b' - v_b; v_b' + F/m_b] = 0
//   second order  G(x, x', x'') = [a + (f(y, y', t) - g F)/m; a_b + F/m_b] = 0
// with f the internal forces of the system's force operator (system/force_operator.hpp: the
// elastic strain terms, damping, the grip to the swing's frame), m and g from the system and
// F the contact law at the compression c = y_b - g^T y.
#include "solvers/ts_problem.hpp"

#include <petscdmcomposite.h>

#include <algorithm>

namespace beamimpact {

// out = (f(y, v, t) - g F)/m for the owned dofs (0 where held); y, v and out are beam arrays by
// global node with node strides ys, vs and os (pointing at the field block to read or write).
// v (ghosted like y) is given for a damped beam only: without it the velocity parts are left
// out at no cost.
static void BeamAcceleration(TSProblem &P, PetscReal t, const PetscScalar *y, PetscInt ys, const PetscScalar *v,
                             PetscInt vs, PetscReal F, PetscScalar *out, PetscInt os)
{
  const BeamSystem &S  = *P.sys;
  const TSLayout   &L  = P.L;
  const PetscInt    nf = L.fields;
  ForceState        s;
  s.y     = y;
  s.ys    = ys;
  s.v     = v;
  s.vs    = vs;
  s.t     = t;
  s.frame = P.frame;
  ForceOperatorApply(S, s, L.D0(), L.D1(), out, os);
  if (F != 0.0)
    for (PetscInt q = 0; q < P.g.n; ++q) {
      const PetscInt d = P.g.dof[q], node = d / nf;
      if (node >= L.xs && node < L.xe && P.g.w[q] != 0.0) out[node * os + d % nf] -= P.g.w[q] * F;
    }
  for (PetscInt d = L.D0(); d < L.D1(); ++d) {
    PetscScalar &o = out[(d / nf) * os + d % nf];
    o              = S.held[d] ? 0.0 : o / S.mass[d];
  }
}

PetscErrorCode TSRHSExplicit(TS ts, PetscReal t, Vec U, Vec G, void *ctx)
{
  TSProblem      &P  = *static_cast<TSProblem *>(ctx);
  const TSLayout &L  = P.L;
  const PetscInt  nf = L.fields, dof = L.dof;
  TSStateRead     s;
  TSStateWrite    o;
  PetscReal       c;

  PetscFunctionBeginUser;
  P.count.func++;
  PetscCall(TSStateReadBegin(L, U, &s));
  PetscCall(TSCompression(P, s.beam, dof, s.ball[0], &c));
  const PetscReal F = ContactForce(P.ball, *P.contact, c);
  PetscCall(TSStateWriteBegin(L, G, &o));
  BeamAcceleration(P, t, s.beam, dof, P.sys->Damped() ? s.beam + nf : nullptr, dof, F, o.beam + nf, dof);
  for (PetscInt d = L.D0(); d < L.D1(); ++d) {
    const PetscInt k = (d / nf) * dof + d % nf;
    o.beam[k + nf]   = -o.beam[k + nf];
    o.beam[k]        = P.sys->held[d] ? 0.0 : s.beam[k + nf];
  }
  if (o.ball) {
    o.ball[0] = s.ball[1];
    o.ball[1] = -F / P.ball.mass;
  }
  PetscCall(TSStateWriteEnd(L, G, &o));
  PetscCall(TSStateReadEnd(L, U, &s));
  PetscFunctionReturn(0);
}

PetscErrorCode TSRHSContact(TS ts, PetscReal t, Vec U, Vec G, void *ctx)
{
  TSProblem         &P  = *static_cast<TSProblem *>(ctx);
  const TSLayout    &L  = P.L;
  const PetscInt     nf = L.fields, dof = L.dof;
  PetscReal          c;
  Vec                Ub, Ur;
  const PetscScalar *u, *r;
  PetscScalar        ball_y = 0;

  PetscFunctionBeginUser;
  P.count.func++;
  PetscCall(DMCompositeGetAccess(L.pack, U, &Ub, &Ur)); // owned values suffice: no ghost scatter
  PetscCall(VecGetArrayRead(Ub, &u));
  PetscCall(VecGetArrayRead(Ur, &r));
  if (L.rank == 0) ball_y = r[0];
  PetscCall(TSCompression(P, u - L.xs * dof, dof, ball_y, &c));
  PetscCall(VecRestoreArrayRead(Ur, &r));
  PetscCall(VecRestoreArrayRead(Ub, &u));
  PetscCall(DMCompositeRestoreAccess(L.pack, U, &Ub, &Ur));
  const PetscReal F = ContactForce(P.ball, *P.contact, c);
  TSStateWrite    o;
  PetscCall(VecZeroEntries(G));
  PetscCall(TSStateWriteBegin(L, G, &o));
  for (PetscInt q = 0; q < P.g.n; ++q) {
    const PetscInt d = P.g.dof[q], node = d / nf;
    if (node >= L.xs && node < L.xe && P.g.w[q] != 0.0)
      o.beam[node * dof + nf + d % nf] += P.g.w[q] * F / P.sys->mass[d];
  }
  if (o.ball) o.ball[1] = -F / P.ball.mass;
  PetscCall(TSStateWriteEnd(L, G, &o));
  PetscFunctionReturn(0);
}

PetscErrorCode TSIFunctionBeam(TS ts, PetscReal t, Vec U, Vec Udot, Vec G, void *ctx)
{
  TSProblem         &P  = *static_cast<TSProblem *>(ctx);
  const TSLayout    &L  = P.L;
  const PetscInt     nf = L.fields, dof = L.dof;
  TSStateRead        s;
  TSStateWrite       o;
  PetscReal          F = 0;
  const PetscScalar *ud, *udr;
  Vec                Udb, Udr;

  PetscFunctionBeginUser;
  P.count.func++;
  PetscCall(TSStateReadBegin(L, U, &s));
  if (P.form == Formulation::Implicit) { // IMEX leaves the contact force to TSRHSContact
    PetscReal c;
    PetscCall(TSCompression(P, s.beam, dof, s.ball[0], &c));
    F = ContactForce(P.ball, *P.contact, c);
  }
  PetscCall(DMCompositeGetAccess(L.pack, Udot, &Udb, &Udr));
  PetscCall(VecGetArrayRead(Udb, &ud));
  PetscCall(VecGetArrayRead(Udr, &udr));
  const PetscScalar *udot = ud - dof * L.xs;
  PetscCall(TSStateWriteBegin(L, G, &o));
  BeamAcceleration(P, t, s.beam, dof, P.sys->Damped() ? s.beam + nf : nullptr, dof, F, o.beam + nf, dof);
  for (PetscInt d = L.D0(); d < L.D1(); ++d) {
    const PetscInt k = (d / nf) * dof + d % nf;
    o.beam[k + nf] += udot[k + nf];
    o.beam[k] = udot[k] - (P.sys->held[d] ? 0.0 : s.beam[k + nf]);
  }
  if (o.ball) {
    o.ball[0] = udr[0] - s.ball[1];
    o.ball[1] = udr[1] + F / P.ball.mass;
  }
  PetscCall(TSStateWriteEnd(L, G, &o));
  PetscCall(VecRestoreArrayRead(Udr, &udr));
  PetscCall(VecRestoreArrayRead(Udb, &ud));
  PetscCall(DMCompositeRestoreAccess(L.pack, Udot, &Udb, &Udr));
  PetscCall(TSStateReadEnd(L, U, &s));
  PetscFunctionReturn(0);
}

PetscErrorCode TSI2FunctionBeam(TS ts, PetscReal t, Vec X, Vec V, Vec A, Vec G, void *ctx)
{
  TSProblem         &P      = *static_cast<TSProblem *>(ctx);
  const TSLayout    &L      = P.L;
  const PetscInt     nf     = L.fields;
  const bool         damped = P.sys->Damped();
  TSStateRead        s, sv;
  TSStateWrite       o;
  PetscReal          c;
  const PetscScalar *ab, *ar;
  Vec                Ab, Ar;

  PetscFunctionBeginUser;
  P.count.func++;
  PetscCall(TSStateReadBegin(L, X, &s));
  if (damped) PetscCall(TSStateReadBegin(L, V, &sv)); // ghosted velocities for C x
  PetscCall(TSCompression(P, s.beam, nf, s.ball[0], &c));
  const PetscReal F = ContactForce(P.ball, *P.contact, c);
  PetscCall(DMCompositeGetAccess(L.pack, A, &Ab, &Ar));
  PetscCall(VecGetArrayRead(Ab, &ab));
  PetscCall(VecGetArrayRead(Ar, &ar));
  const PetscScalar *acc = ab - nf * L.xs;
  PetscCall(TSStateWriteBegin(L, G, &o));
  BeamAcceleration(P, t, s.beam, nf, damped ? sv.beam : nullptr, nf, F, o.beam, nf);
  for (PetscInt d = L.D0(); d < L.D1(); ++d) o.beam[d] += acc[d];
  if (o.ball) o.ball[0] = ar[0] + F / P.ball.mass;
  PetscCall(TSStateWriteEnd(L, G, &o));
  PetscCall(VecRestoreArrayRead(Ar, &ar));
  PetscCall(VecRestoreArrayRead(Ab, &ab));
  PetscCall(DMCompositeRestoreAccess(L.pack, A, &Ab, &Ar));
  if (damped) PetscCall(TSStateReadEnd(L, V, &sv));
  PetscCall(TSStateReadEnd(L, X, &s));
  PetscFunctionReturn(0);
}

PetscErrorCode TSDissipationRate(TSProblem &P, PetscReal t, Vec X, Vec V, PetscReal *rate, PetscReal *rate_dot)
{
  const BeamSystem &S  = *P.sys;
  const TSLayout   &L  = P.L;
  const PetscInt    nf = L.fields, dof = L.dof, nown = L.D1() - L.D0();
  TSStateRead       s, sv;
  PetscReal         c, sums[2] = {0, 0};

  PetscFunctionBeginUser;
  PetscCall(TSStateReadBegin(L, X, &s));
  if (V) PetscCall(TSStateReadBegin(L, V, &sv));
  const PetscScalar *v  = V ? sv.beam : s.beam + nf;
  const PetscInt     vs = V ? nf : dof;
  PetscCall(TSCompression(P, s.beam, dof, s.ball[0], &c));
  const PetscReal         F   = ContactForce(P.ball, *P.contact, c);
  std::vector<PetscReal> &acc = P.rate_acc, &cv = P.rate_cv; // -a and C v of the owned dofs
  acc.resize(nown);
  cv.resize(nown);
  ForceState fs; // the velocities relative to the frame
  fs.v     = v;
  fs.vs    = vs;
  fs.t     = t;
  fs.frame = P.frame;
  BeamAcceleration(P, t, s.beam, dof, v, vs, F, acc.data() - L.D0(), nf);
  ForceOperatorDampingApply(S, fs, L.D0(), L.D1(), cv.data() - L.D0(), nf);
  sums[0] = ForceOperatorDissipationRate(S, fs, L.D0(), L.D1());
  for (PetscInt k = 0; k < nown; ++k) sums[1] -= 2 * acc[k] * cv[k];
  if (V) PetscCall(TSStateReadEnd(L, V, &sv));
  PetscCall(TSStateReadEnd(L, X, &s));
  if (L.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPIU_REAL, MPIU_SUM, L.comm));
  *rate     = sums[0];
  *rate_dot = sums[1];
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// One ball-beam impact as a PETSc TS problem: DM layout, residuals and
// Jacobians for each formulation, the event-driven contact, and the outcome.
// See impact.hpp for the model and MODEL.md section 3 for the numerics.
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include "io/options_util.hpp"
#include "solvers/ts_galpha2.hpp"

#include <petscdmcomposite.h>
#include <petscdmda.h>
#include <petscdmredundant.h>
#include <petscts.h>
#include <petsc/private/tsimpl.h> // ts->ops->rollback: whether a type can locate events

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>

namespace beamimpact {

static const char *const EventNames[] = {"contact", "max_compression", "reload", "separation"};
const char *ContactEventName(ContactEventKind k) { return EventNames[static_cast<int>(k)]; }

namespace {

enum class Formulation { Explicit, IMEX, Implicit, SecondOrder };
const char *FormulationName(Formulation f)
{
  switch (f) {
  case Formulation::Explicit: return "explicit";
  case Formulation::IMEX: return "imex";
  case Formulation::Implicit: return "implicit";
  default: return "second-order";
  }
}

// Everything the PETSc callbacks need: the plain operator and contact law, the
// DM layout, and counters. One per impact.
struct ImpactProblem {
  MPI_Comm      comm;
  PetscMPIInt   size = 1, rank = 0;
  BeamOperator  op;
  BallParams    ball;
  ContactState  contact;
  ImpactStencil stencil;
  PetscReal     x_imp = 0; // m
  Formulation   form  = Formulation::Explicit;
  PetscInt      dof   = 2; // per node: (y, v), or y only for the second-order form
  DM            pack = nullptr, da = nullptr, red = nullptr;
  PetscInt      xs = 0, xe = 0; // owned nodes
  std::vector<PetscInt> node_owner_start; // first node of each rank
  std::vector<PetscInt> rstart;           // first composite global index of each rank
  Mat           J = nullptr, J0 = nullptr; // J0: the constant part (no shift, no contact), assembled once
  // Jacobian cache: the matrix is reassembled (and refactored) only when these change.
  PetscReal     jac_shift = -1, jac_kc = -1;
  bool          jac_contact = false;
  // Counters.
  PetscInt      n_func = 0, n_jac = 0, n_jac_assembled = 0;
};

// Composite global index of beam node i, component d, and of ball component d.
PetscInt NodeIndex(const ImpactProblem &P, PetscInt i, PetscInt d)
{
  const auto     it = std::upper_bound(P.node_owner_start.begin(), P.node_owner_start.end(), i);
  const PetscInt r  = static_cast<PetscInt>(it - P.node_owner_start.begin()) - 1;
  return P.rstart[r] + (i - P.node_owner_start[r]) * P.dof + d;
}
PetscInt BallIndex(const ImpactProblem &P, PetscInt d)
{
  const PetscInt nodes0 = P.node_owner_start.size() > 1 ? P.node_owner_start[1] : P.op.N;
  return P.rstart[0] + nodes0 * P.dof + d;
}

// Read access to a composite state vector: beam values by global node index
// (ghosted, width 2) and the ball's values on every rank.
struct StateView {
  const PetscScalar *beam = nullptr; // beam[i*dof + d], i in the ghosted range
  PetscScalar        ball[2] = {0, 0};
  Vec                Ub = nullptr, Ur = nullptr;
  const PetscScalar *arr = nullptr;
  bool               local = false;
};

PetscErrorCode StateBegin(ImpactProblem &P, Vec U, StateView *s)
{
  PetscFunctionBeginUser;
  if (P.size == 1) {
    PetscCall(DMCompositeGetAccess(P.pack, U, &s->Ub, &s->Ur));
    PetscCall(VecGetArrayRead(s->Ub, &s->arr));
    s->beam = s->arr;
    const PetscScalar *r;
    PetscCall(VecGetArrayRead(s->Ur, &r));
    for (PetscInt d = 0; d < P.dof; ++d) s->ball[d] = r[d];
    PetscCall(VecRestoreArrayRead(s->Ur, &r));
  } else {
    PetscInt gxs;
    s->local = true;
    PetscCall(DMCompositeGetLocalVectors(P.pack, &s->Ub, &s->Ur));
    PetscCall(DMCompositeScatter(P.pack, U, s->Ub, s->Ur));
    PetscCall(DMDAGetGhostCorners(P.da, &gxs, NULL, NULL, NULL, NULL, NULL));
    PetscCall(VecGetArrayRead(s->Ub, &s->arr));
    s->beam = s->arr - gxs * P.dof;
    const PetscScalar *r;
    PetscCall(VecGetArrayRead(s->Ur, &r));
    for (PetscInt d = 0; d < P.dof; ++d) s->ball[d] = r[d];
    PetscCall(VecRestoreArrayRead(s->Ur, &r));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode StateEnd(ImpactProblem &P, Vec U, StateView *s)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(s->Ub, &s->arr));
  if (s->local) PetscCall(DMCompositeRestoreLocalVectors(P.pack, &s->Ub, &s->Ur));
  else PetscCall(DMCompositeRestoreAccess(P.pack, U, &s->Ub, &s->Ur));
  PetscFunctionReturn(0);
}

// Write access to the owned part of a composite vector.
struct OutView {
  PetscScalar *beam = nullptr; // beam[i*dof + d] for owned i (global node index)
  PetscScalar *ball = nullptr; // nullptr on ranks other than 0
  Vec          Fb = nullptr, Fr = nullptr;
  PetscScalar *arr = nullptr, *rarr = nullptr;
};

PetscErrorCode OutBegin(ImpactProblem &P, Vec F, OutView *o)
{
  PetscFunctionBeginUser;
  PetscCall(DMCompositeGetAccess(P.pack, F, &o->Fb, &o->Fr));
  PetscCall(VecGetArray(o->Fb, &o->arr));
  PetscCall(VecGetArray(o->Fr, &o->rarr));
  o->beam = o->arr - P.xs * P.dof;
  o->ball = P.rank == 0 ? o->rarr : nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode OutEnd(ImpactProblem &P, Vec F, OutView *o)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArray(o->Fr, &o->rarr));
  PetscCall(VecRestoreArray(o->Fb, &o->arr));
  PetscCall(DMCompositeRestoreAccess(P.pack, F, &o->Fb, &o->Fr));
  PetscFunctionReturn(0);
}

// c = y_b - (w y_j + (1-w) y_{j+1}) from the owned part of a view with stride dof,
// component d (0: displacement gives c, 1: velocity gives dc/dt). Sum over ranks.
PetscErrorCode CompressionFromView(ImpactProblem &P, const PetscScalar *beam, PetscInt stride, PetscInt d, PetscScalar ball_value, PetscReal *c)
{
  const ImpactStencil &s = P.stencil;
  PetscReal            v = P.rank == 0 ? ball_value : 0.0;

  PetscFunctionBeginUser;
  if (s.j >= P.xs && s.j < P.xe) v -= s.w * beam[s.j * stride + d];
  if (s.j + 1 >= P.xs && s.j + 1 < P.xe) v -= (1.0 - s.w) * beam[(s.j + 1) * stride + d];
  if (P.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPIU_REAL, MPIU_SUM, P.comm));
  *c = v;
  PetscFunctionReturn(0);
}

// acc_i = ((K y)_i - f_contact,i) / m_i for owned nodes into out[i*ostride] (0 for held nodes).
void BeamAcceleration(const ImpactProblem &P, const PetscScalar *y, PetscInt stride, PetscReal F, PetscScalar *out, PetscInt ostride)
{
  BeamStiffnessApply(P.op, y, stride, P.xs, P.xe, out, ostride);
  const ImpactStencil &s = P.stencil;
  if (F != 0.0) {
    if (s.j >= P.xs && s.j < P.xe) out[s.j * ostride] -= s.w * F;
    if (s.j + 1 >= P.xs && s.j + 1 < P.xe) out[(s.j + 1) * ostride] -= (1.0 - s.w) * F;
  }
  for (PetscInt i = P.xs; i < P.xe; ++i) out[i * ostride] = P.op.held[i] ? 0.0 : out[i * ostride] / P.op.mass[i];
}

// Explicit form: du/dt = [v; -(K y - f)/m; v_b; -F/m_b].
PetscErrorCode RHSExplicit(TS ts, PetscReal t, Vec U, Vec G, void *ctx)
{
  ImpactProblem &P = *static_cast<ImpactProblem *>(ctx);
  StateView      s;
  OutView        o;
  PetscReal      c;

  PetscFunctionBeginUser;
  P.n_func++;
  PetscCall(StateBegin(P, U, &s));
  PetscCall(CompressionFromView(P, s.beam, 2, 0, s.ball[0], &c));
  const PetscReal F = ContactForce(P.ball, P.contact, c);
  PetscCall(OutBegin(P, G, &o));
  BeamAcceleration(P, s.beam, 2, F, o.beam + 1, 2);
  for (PetscInt i = P.xs; i < P.xe; ++i) {
    o.beam[2 * i + 1] = -o.beam[2 * i + 1];
    o.beam[2 * i]     = P.op.held[i] ? 0.0 : s.beam[2 * i + 1];
  }
  if (o.ball) {
    o.ball[0] = s.ball[1];
    o.ball[1] = -F / P.ball.mass;
  }
  PetscCall(OutEnd(P, G, &o));
  PetscCall(StateEnd(P, U, &s));
  PetscFunctionReturn(0);
}

// IMEX explicit part: the contact force only.
PetscErrorCode RHSContact(TS ts, PetscReal t, Vec U, Vec G, void *ctx)
{
  ImpactProblem &P = *static_cast<ImpactProblem *>(ctx);
  PetscReal      c;
  Vec            Ub, Ur;
  const PetscScalar *u, *r;
  PetscScalar    ball_y = 0;

  PetscFunctionBeginUser;
  P.n_func++;
  PetscCall(DMCompositeGetAccess(P.pack, U, &Ub, &Ur));
  PetscCall(VecGetArrayRead(Ub, &u));
  PetscCall(VecGetArrayRead(Ur, &r));
  if (P.rank == 0) ball_y = r[0];
  PetscCall(CompressionFromView(P, u - P.xs * 2, 2, 0, ball_y, &c));
  PetscCall(VecRestoreArrayRead(Ur, &r));
  PetscCall(VecRestoreArrayRead(Ub, &u));
  PetscCall(DMCompositeRestoreAccess(P.pack, U, &Ub, &Ur));
  const PetscReal F = ContactForce(P.ball, P.contact, c);
  OutView         o;
  PetscCall(VecZeroEntries(G));
  PetscCall(OutBegin(P, G, &o));
  const ImpactStencil &st = P.stencil;
  if (st.j >= P.xs && st.j < P.xe && !P.op.held[st.j]) o.beam[2 * st.j + 1] = st.w * F / P.op.mass[st.j];
  if (st.j + 1 >= P.xs && st.j + 1 < P.xe && !P.op.held[st.j + 1]) o.beam[2 * (st.j + 1) + 1] = (1.0 - st.w) * F / P.op.mass[st.j + 1];
  if (o.ball) o.ball[1] = -F / P.ball.mass;
  PetscCall(OutEnd(P, G, &o));
  PetscFunctionReturn(0);
}

// Implicit first-order form: G = [y' - v; v' + (K y - f)/m; y_b' - v_b; v_b' + F/m_b]
// with the contact force f, F included for implicit types and left to the RHS for IMEX.
PetscErrorCode IFunction(TS ts, PetscReal t, Vec U, Vec Udot, Vec G, void *ctx)
{
  ImpactProblem &P = *static_cast<ImpactProblem *>(ctx);
  StateView      s;
  OutView        o;
  PetscReal      F = 0;
  const PetscScalar *ud, *udr;
  Vec            Udb, Udr;

  PetscFunctionBeginUser;
  P.n_func++;
  PetscCall(StateBegin(P, U, &s));
  if (P.form == Formulation::Implicit) {
    PetscReal c;
    PetscCall(CompressionFromView(P, s.beam, 2, 0, s.ball[0], &c));
    F = ContactForce(P.ball, P.contact, c);
  }
  PetscCall(DMCompositeGetAccess(P.pack, Udot, &Udb, &Udr));
  PetscCall(VecGetArrayRead(Udb, &ud));
  PetscCall(VecGetArrayRead(Udr, &udr));
  const PetscScalar *udot = ud - 2 * P.xs;
  PetscCall(OutBegin(P, G, &o));
  BeamAcceleration(P, s.beam, 2, F, o.beam + 1, 2);
  for (PetscInt i = P.xs; i < P.xe; ++i) {
    o.beam[2 * i + 1] += udot[2 * i + 1];
    o.beam[2 * i] = udot[2 * i] - (P.op.held[i] ? 0.0 : s.beam[2 * i + 1]);
  }
  if (o.ball) {
    o.ball[0] = udr[0] - s.ball[1];
    o.ball[1] = udr[1] + F / P.ball.mass;
  }
  PetscCall(OutEnd(P, G, &o));
  PetscCall(VecRestoreArrayRead(Udr, &udr));
  PetscCall(VecRestoreArrayRead(Udb, &ud));
  PetscCall(DMCompositeRestoreAccess(P.pack, Udot, &Udb, &Udr));
  PetscCall(StateEnd(P, U, &s));
  PetscFunctionReturn(0);
}

// Second-order form (alpha2): F = [a + (K y - f)/m; a_b + F/m_b].
PetscErrorCode I2Function(TS ts, PetscReal t, Vec X, Vec V, Vec A, Vec G, void *ctx)
{
  ImpactProblem &P = *static_cast<ImpactProblem *>(ctx);
  StateView      s;
  OutView        o;
  PetscReal      c;
  const PetscScalar *ab, *ar;
  Vec            Ab, Ar;

  PetscFunctionBeginUser;
  P.n_func++;
  PetscCall(StateBegin(P, X, &s));
  PetscCall(CompressionFromView(P, s.beam, 1, 0, s.ball[0], &c));
  const PetscReal F = ContactForce(P.ball, P.contact, c);
  PetscCall(DMCompositeGetAccess(P.pack, A, &Ab, &Ar));
  PetscCall(VecGetArrayRead(Ab, &ab));
  PetscCall(VecGetArrayRead(Ar, &ar));
  const PetscScalar *acc = ab - P.xs;
  PetscCall(OutBegin(P, G, &o));
  BeamAcceleration(P, s.beam, 1, F, o.beam, 1);
  for (PetscInt i = P.xs; i < P.xe; ++i) o.beam[i] += acc[i];
  if (o.ball) o.ball[0] = ar[0] + F / P.ball.mass;
  PetscCall(OutEnd(P, G, &o));
  PetscCall(VecRestoreArrayRead(Ar, &ar));
  PetscCall(VecRestoreArrayRead(Ab, &ab));
  PetscCall(DMCompositeRestoreAccess(P.pack, A, &Ab, &Ar));
  PetscCall(StateEnd(P, X, &s));
  PetscFunctionReturn(0);
}

// Assembles J = shift * I + [first order: [0 -I; (K + kc g g^T)/m 0]] or
// [second order: (K + kc g g^T)/m] entry by entry, with every entry of the final pattern
// (contact coupling and held rows as explicit zeros). Called once, with shift = kc = 0, to
// build the constant part J0 and fix the pattern; AssembleJacobian then updates J from J0.
PetscErrorCode AssembleJacobianFull(ImpactProblem &P, PetscReal shift, PetscReal kc)
{
  const bool           first = P.dof == 2;
  const ImpactStencil &st    = P.stencil;
  const PetscInt       cp[3] = {st.j, st.j + 1, -1}; // coupled dofs (node, node, ball)
  const PetscReal      g[3]  = {-st.w, -(1.0 - st.w), 1.0};
  const PetscInt       dpos  = 0;                    // displacement component (first in both forms)
  const PetscInt       dvel  = first ? 1 : 0;        // row component carrying the dynamics

  PetscFunctionBeginUser;
  P.n_jac_assembled++;
  auto colidx = [&](PetscInt q) { return cp[q] < 0 ? BallIndex(P, dpos) : NodeIndex(P, cp[q], dpos); };
  for (PetscInt i = P.xs; i < P.xe; ++i) {
    std::map<PetscInt, PetscScalar> row;
    const PetscInt                  ry = NodeIndex(P, i, 0), rv = NodeIndex(P, i, dvel);
    if (first) {
      PetscScalar vals[2] = {shift, P.op.held[i] ? 0.0 : -1.0};
      PetscInt    cols[2] = {ry, rv};
      PetscCall(MatSetValues(P.J, 1, &ry, 2, cols, vals, INSERT_VALUES));
    }
    row[rv] = shift;
    if (!P.op.held[i]) {
      PetscInt  cols[5];
      PetscReal vals[5];
      const PetscInt n = BeamStiffnessRow(P.op, i, cols, vals);
      for (PetscInt q = 0; q < n; ++q) row[NodeIndex(P, cols[q], dpos)] += vals[q] / P.op.mass[i];
    }
    for (PetscInt p = 0; p < 2; ++p) {
      if (cp[p] != i) continue;
      for (PetscInt q = 0; q < 3; ++q) row[colidx(q)] += P.op.held[i] ? 0.0 : kc * g[p] * g[q] / P.op.mass[i];
    }
    std::vector<PetscInt>    cols;
    std::vector<PetscScalar> vals;
    for (auto &e : row) {
      cols.push_back(e.first);
      vals.push_back(e.second);
    }
    PetscCall(MatSetValues(P.J, 1, &rv, (PetscInt)cols.size(), cols.data(), vals.data(), INSERT_VALUES));
  }
  if (P.rank == 0) {
    const PetscInt by = BallIndex(P, 0), bv = BallIndex(P, dvel);
    if (first) {
      PetscScalar vals[2] = {shift, -1.0};
      PetscInt    cols[2] = {by, bv};
      PetscCall(MatSetValues(P.J, 1, &by, 2, cols, vals, INSERT_VALUES));
    }
    std::map<PetscInt, PetscScalar> row;
    row[bv] = shift;
    for (PetscInt q = 0; q < 3; ++q) row[colidx(q)] += kc * g[2] * g[q] / P.ball.mass;
    std::vector<PetscInt>    cols;
    std::vector<PetscScalar> vals;
    for (auto &e : row) {
      cols.push_back(e.first);
      vals.push_back(e.second);
    }
    PetscCall(MatSetValues(P.J, 1, &bv, (PetscInt)cols.size(), cols.data(), vals.data(), INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(P.J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P.J, MAT_FINAL_ASSEMBLY));
  P.jac_shift = shift;
  P.jac_kc    = kc;
  PetscFunctionReturn(0);
}

// J = J0 + shift I + kc g g^T / m: a copy of the constant part (same pattern: a memcpy),
// a diagonal shift, and the 3x3 contact block added on the rows that own it.
PetscErrorCode AssembleJacobian(ImpactProblem &P, PetscReal shift, PetscReal kc)
{
  const ImpactStencil &st   = P.stencil;
  const PetscInt       cp[3] = {st.j, st.j + 1, -1};
  const PetscReal      g[3]  = {-st.w, -(1.0 - st.w), 1.0};
  const PetscInt       dvel  = P.dof == 2 ? 1 : 0;

  PetscFunctionBeginUser;
  P.n_jac_assembled++;
  PetscCall(MatCopy(P.J0, P.J, SAME_NONZERO_PATTERN));
  PetscCall(MatShift(P.J, shift));
  if (kc != 0.0) {
    PetscInt cols[3];
    for (PetscInt q = 0; q < 3; ++q) cols[q] = cp[q] < 0 ? BallIndex(P, 0) : NodeIndex(P, cp[q], 0);
    for (PetscInt p = 0; p < 3; ++p) {
      const bool ball = cp[p] < 0;
      if (ball ? P.rank != 0 : !(cp[p] >= P.xs && cp[p] < P.xe)) continue;
      if (!ball && P.op.held[cp[p]]) continue;
      const PetscInt  row = ball ? BallIndex(P, dvel) : NodeIndex(P, cp[p], dvel);
      const PetscReal m   = ball ? P.ball.mass : P.op.mass[cp[p]];
      PetscScalar     vals[3];
      for (PetscInt q = 0; q < 3; ++q) vals[q] = kc * g[p] * g[q] / m;
      PetscCall(MatSetValues(P.J, 1, &row, 3, cols, vals, ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(P.J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P.J, MAT_FINAL_ASSEMBLY));
  P.jac_shift = shift;
  P.jac_kc    = kc;
  PetscFunctionReturn(0);
}

PetscErrorCode UpdateJacobian(ImpactProblem &P, Vec X, PetscReal shift)
{
  PetscReal kc = 0;

  PetscFunctionBeginUser;
  P.n_jac++;
  if (P.jac_contact && P.contact.phase != ContactPhase::Separated) {
    StateView s;
    PetscReal c;
    PetscCall(StateBegin(P, X, &s));
    PetscCall(CompressionFromView(P, s.beam, P.dof, 0, s.ball[0], &c));
    PetscCall(StateEnd(P, X, &s));
    kc = ContactStiffness(P.ball, P.contact, c);
  }
  if (shift != P.jac_shift || kc != P.jac_kc) PetscCall(AssembleJacobian(P, shift, kc));
  PetscFunctionReturn(0);
}

PetscErrorCode IJacobian(TS ts, PetscReal t, Vec U, Vec Udot, PetscReal shift, Mat A, Mat B, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(UpdateJacobian(*static_cast<ImpactProblem *>(ctx), U, shift));
  PetscFunctionReturn(0);
}

PetscErrorCode I2Jacobian(TS ts, PetscReal t, Vec X, Vec V, Vec A, PetscReal shiftV, PetscReal shiftA, Mat J, Mat B, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(UpdateJacobian(*static_cast<ImpactProblem *>(ctx), X, shiftA));
  PetscFunctionReturn(0);
}

// Compression and its rate at the current TS state.
PetscErrorCode CurrentCompression(ImpactProblem &P, TS ts, PetscReal *c, PetscReal *cdot)
{
  Vec                X, V = nullptr, Xb, Xr, Vb = nullptr, Vr = nullptr;
  const PetscScalar *x, *xr, *v = nullptr, *vr = nullptr;

  PetscFunctionBeginUser;
  if (P.form == Formulation::SecondOrder) PetscCall(TS2GetSolution(ts, &X, &V));
  else PetscCall(TSGetSolution(ts, &X));
  PetscCall(DMCompositeGetAccess(P.pack, X, &Xb, &Xr));
  PetscCall(VecGetArrayRead(Xb, &x));
  PetscCall(VecGetArrayRead(Xr, &xr));
  PetscReal vals[2] = {0, 0};
  const PetscInt stride = P.dof;
  if (V) {
    PetscCall(DMCompositeGetAccess(P.pack, V, &Vb, &Vr));
    PetscCall(VecGetArrayRead(Vb, &v));
    PetscCall(VecGetArrayRead(Vr, &vr));
  }
  {
    const ImpactStencil &s = P.stencil;
    const PetscScalar   *bx = x - P.xs * stride, *bv = V ? v - P.xs : x - P.xs * stride;
    const PetscInt       vd = V ? 0 : 1, vstride = V ? 1 : stride;
    if (P.rank == 0) {
      vals[0] = xr[0];
      vals[1] = V ? vr[0] : xr[1];
    }
    if (s.j >= P.xs && s.j < P.xe) {
      vals[0] -= s.w * bx[s.j * stride];
      vals[1] -= s.w * bv[s.j * vstride + vd];
    }
    if (s.j + 1 >= P.xs && s.j + 1 < P.xe) {
      vals[0] -= (1 - s.w) * bx[(s.j + 1) * stride];
      vals[1] -= (1 - s.w) * bv[(s.j + 1) * vstride + vd];
    }
  }
  if (V) {
    PetscCall(VecRestoreArrayRead(Vr, &vr));
    PetscCall(VecRestoreArrayRead(Vb, &v));
    PetscCall(DMCompositeRestoreAccess(P.pack, V, &Vb, &Vr));
  }
  PetscCall(VecRestoreArrayRead(Xr, &xr));
  PetscCall(VecRestoreArrayRead(Xb, &x));
  PetscCall(DMCompositeRestoreAccess(P.pack, X, &Xb, &Xr));
  if (P.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, vals, 2, MPIU_REAL, MPIU_SUM, P.comm));
  *c    = vals[0];
  *cdot = vals[1];
  PetscFunctionReturn(0);
}

// Energies, momenta and point velocities of the current state (all ranks agree).
struct StateMeasures {
  PetscReal ball_y = 0, ball_v = 0, c = 0, force = 0;
  PetscReal ball_kinetic = 0, ball_stored = 0, ball_work = 0, beam_kinetic = 0, beam_strain = 0;
  PetscReal momentum = 0, angular_momentum = 0; // kg m/s, kg m^2/s about x = 0 (beam and ball)
  PetscReal beam_momentum = 0, beam_moment = 0;   // sum m_i v_i (kg m/s), sum m_i x_i v_i (kg m^2/s)
  PetscReal segment_kinetic = 0;                  // J, monitored segment
  PetscReal total() const { return ball_kinetic + ball_work + beam_kinetic + beam_strain; }
};

// Measures the current state; with a monitor request also the point velocities and the
// segment's kinetic energy (one reduction for all).
PetscErrorCode MeasureState(ImpactProblem &P, TS ts, const MonitorRequest *mon, StateMeasures *m, std::vector<PetscReal> *point_v)
{
  static const std::vector<PetscReal> none;
  const std::vector<PetscReal>       &points = mon ? mon->velocity_at : none;
  Vec       X, V = nullptr;
  StateView s;

  PetscFunctionBeginUser;
  if (P.form == Formulation::SecondOrder) PetscCall(TS2GetSolution(ts, &X, &V));
  else PetscCall(TSGetSolution(ts, &X));
  PetscCall(StateBegin(P, X, &s));
  const PetscScalar *v = nullptr, *varr = nullptr;
  Vec                Vb = nullptr, Vr = nullptr;
  PetscScalar        ball_v;
  PetscInt           vstride;
  if (V) {
    const PetscScalar *vr;
    PetscCall(DMCompositeGetAccess(P.pack, V, &Vb, &Vr));
    PetscCall(VecGetArrayRead(Vb, &varr));
    PetscCall(VecGetArrayRead(Vr, &vr));
    ball_v = P.rank == 0 ? vr[0] : 0.0;
    PetscCall(VecRestoreArrayRead(Vr, &vr));
    if (P.size > 1) PetscCallMPI(MPI_Bcast(&ball_v, 1, MPIU_SCALAR, 0, P.comm));
    v       = varr - P.xs;
    vstride = 1;
  } else {
    v       = s.beam + 1;
    ball_v  = s.ball[1];
    vstride = 2;
  }
  const PetscInt np = (PetscInt)points.size();
  std::vector<PetscReal> sums(5 + np, 0.0);
  sums[0] = BeamKineticEnergy(P.op, v, vstride, P.xs, P.xe);
  sums[1] = BeamStrainEnergy(P.op, s.beam, P.dof, P.xs, P.xe);
  for (PetscInt i = P.xs; i < P.xe; ++i) {
    sums[2] += P.op.mass[i] * v[i * vstride];
    sums[3] += P.op.mass[i] * i * P.op.h * v[i * vstride];
  }
  if (mon && mon->segment) {
    const PetscReal tol = 1e-9 * P.op.h;
    for (PetscInt i = P.xs; i < P.xe; ++i) {
      const PetscReal x = i * P.op.h;
      if (x >= mon->segment_x0 - tol && x <= mon->segment_x1 + tol) sums[4] += 0.5 * P.op.mass[i] * v[i * vstride] * v[i * vstride];
    }
  }
  for (PetscInt q = 0; q < np; ++q) {
    const ImpactStencil st = BeamImpactStencil(P.op, points[q]);
    if (st.j >= P.xs && st.j < P.xe) sums[5 + q] += st.w * v[st.j * vstride];
    if (st.j + 1 >= P.xs && st.j + 1 < P.xe) sums[5 + q] += (1 - st.w) * v[(st.j + 1) * vstride];
  }
  if (P.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (PetscMPIInt)sums.size(), MPIU_REAL, MPIU_SUM, P.comm));
  PetscReal cdot;
  if (V) {
    PetscCall(VecRestoreArrayRead(Vb, &varr));
    PetscCall(DMCompositeRestoreAccess(P.pack, V, &Vb, &Vr));
  }
  PetscCall(StateEnd(P, X, &s));
  PetscCall(CurrentCompression(P, ts, &m->c, &cdot));
  m->ball_y           = s.ball[0];
  m->ball_v           = ball_v;
  m->force            = ContactForce(P.ball, P.contact, m->c);
  m->ball_kinetic     = 0.5 * P.ball.mass * ball_v * ball_v;
  m->ball_stored      = ContactStoredEnergy(P.ball, P.contact, m->c);
  m->ball_work        = ContactWork(P.ball, P.contact, m->c);
  m->beam_kinetic     = sums[0];
  m->beam_strain      = sums[1];
  m->momentum         = sums[2] + P.ball.mass * ball_v;
  m->angular_momentum = sums[3] + P.ball.mass * P.x_imp * ball_v;
  m->beam_momentum    = sums[2];
  m->beam_moment      = sums[3];
  m->segment_kinetic  = sums[4];
  if (point_v) point_v->assign(sums.begin() + 5, sums.end());
  PetscFunctionReturn(0);
}

// Beam displacement y(x) on rank 0 (gathered in natural node order).
PetscErrorCode GatherDisplacement(ImpactProblem &P, TS ts, std::vector<PetscReal> *y)
{
  Vec                X, Xb, Xr, y0, yall;
  VecScatter         sc;
  PetscInt           n;

  PetscFunctionBeginUser;
  if (P.form == Formulation::SecondOrder) {
    Vec V;
    PetscCall(TS2GetSolution(ts, &X, &V));
  } else PetscCall(TSGetSolution(ts, &X));
  PetscCall(DMCompositeGetAccess(P.pack, X, &Xb, &Xr));
  PetscCall(VecGetLocalSize(Xb, &n));
  PetscCall(VecCreateMPI(P.comm, n / P.dof, PETSC_DETERMINE, &y0));
  {
    const PetscScalar *x;
    PetscScalar       *o;
    PetscCall(VecGetArrayRead(Xb, &x));
    PetscCall(VecGetArray(y0, &o));
    for (PetscInt i = 0; i < n / P.dof; ++i) o[i] = x[i * P.dof];
    PetscCall(VecRestoreArray(y0, &o));
    PetscCall(VecRestoreArrayRead(Xb, &x));
  }
  PetscCall(DMCompositeRestoreAccess(P.pack, X, &Xb, &Xr));
  PetscCall(VecScatterCreateToZero(y0, &sc, &yall));
  PetscCall(VecScatterBegin(sc, y0, yall, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, y0, yall, INSERT_VALUES, SCATTER_FORWARD));
  if (P.rank == 0) {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(yall, &a));
    y->assign(a, a + P.op.N);
    PetscCall(VecRestoreArrayRead(yall, &a));
  }
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&yall));
  PetscCall(VecDestroy(&y0));
  PetscFunctionReturn(0);
}

// Newton on the acceleration-scaled residual cannot go below its round-off floor
// ~ eps * omega_max^2 * max|y| (the 5-point stencil cancels terms of size omega_max^2 y),
// which on fine grids, stiff beams or after long flights exceeds rtol * |F_0|. Accept a
// residual within 100x that floor (after at least one iteration) instead of stalling.
struct NewtonFloor {
  ImpactProblem *P      = nullptr;
  TS             ts     = nullptr;
  PetscReal      omega2 = 0; // (rad/s)^2, bound on omega_max^2
};

PetscErrorCode ConvergedWithRoundoffFloor(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm, SNESConvergedReason *reason, void *ctx)
{
  NewtonFloor &nf = *static_cast<NewtonFloor *>(ctx);

  PetscFunctionBeginUser;
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, NULL));
  if (*reason != SNES_CONVERGED_ITERATING || it < 1) PetscFunctionReturn(0);
  ImpactProblem &P = *nf.P;
  Vec            X, V, Xb, Xr;
  if (P.form == Formulation::SecondOrder) PetscCall(TS2GetSolution(nf.ts, &X, &V));
  else PetscCall(TSGetSolution(nf.ts, &X));
  PetscCall(DMCompositeGetAccess(P.pack, X, &Xb, &Xr));
  const PetscScalar *x;
  PetscReal          ymax = 0;
  PetscCall(VecGetArrayRead(Xb, &x));
  for (PetscInt i = 0; i < P.xe - P.xs; ++i) ymax = std::max(ymax, std::abs(x[i * P.dof]));
  PetscCall(VecRestoreArrayRead(Xb, &x));
  PetscCall(DMCompositeRestoreAccess(P.pack, X, &Xb, &Xr));
  if (P.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &ymax, 1, MPIU_REAL, MPIU_MAX, P.comm));
  const PetscReal floor = 100 * PETSC_MACHINE_EPSILON * nf.omega2 * ymax * std::sqrt((PetscReal)P.op.N);
  if (fnorm <= floor) *reason = SNES_CONVERGED_FNORM_ABS;
  PetscFunctionReturn(0);
}

Formulation FormulationOfType(const char *type)
{
  auto is = [&](const char *t) { return std::string(type) == t; };
  if (is(TSALPHA2)) return Formulation::SecondOrder;
  if (is(TSRK) || is(TSEULER) || is(TSSSP) || is(TSGLEE) || is(TSMPRK) || is(TSBASICSYMPLECTIC)) return Formulation::Explicit;
  if (is(TSARKIMEX) || is(TSEIMEX) || is(TSMIMEX)) return Formulation::IMEX;
  return Formulation::Implicit;
}

// Sets up the DMs for the formulation.
PetscErrorCode CreateLayout(ImpactProblem &P)
{
  PetscFunctionBeginUser;
  PetscCall(DMDACreate1d(P.comm, DM_BOUNDARY_NONE, P.op.N, P.dof, 2, NULL, &P.da));
  PetscCall(DMSetUp(P.da));
  PetscCall(DMDASetFieldName(P.da, 0, "y"));
  if (P.dof == 2) PetscCall(DMDASetFieldName(P.da, 1, "v"));
  PetscCall(DMRedundantCreate(P.comm, 0, P.dof, &P.red));
  PetscCall(DMCompositeCreate(P.comm, &P.pack));
  PetscCall(DMCompositeAddDM(P.pack, P.da));
  PetscCall(DMCompositeAddDM(P.pack, P.red));
  PetscCall(DMSetUp(P.pack));
  PetscInt xs, xm;
  PetscCall(DMDAGetCorners(P.da, &xs, NULL, NULL, &xm, NULL, NULL));
  P.xs = xs;
  P.xe = xs + xm;
  const PetscInt *lx;
  PetscCall(DMDAGetOwnershipRanges(P.da, &lx, NULL, NULL));
  P.node_owner_start.assign(P.size, 0);
  for (PetscMPIInt r = 1; r < P.size; ++r) P.node_owner_start[r] = P.node_owner_start[r - 1] + lx[r - 1];
  Vec            U;
  const PetscInt *ranges;
  PetscCall(DMCreateGlobalVector(P.pack, &U));
  PetscCall(VecGetOwnershipRanges(U, &ranges));
  P.rstart.assign(ranges, ranges + P.size);
  // Check the index formulas against the composite's own numbering once.
  IS *is;
  PetscCall(DMCompositeGetGlobalISs(P.pack, &is));
  if (P.rank == 0) {
    const PetscInt *idx;
    PetscCall(ISGetIndices(is[1], &idx));
    PetscCheck(idx[0] == BallIndex(P, 0), P.comm, PETSC_ERR_PLIB, "composite numbering of the ball (%" PetscInt_FMT ") differs from the assumed %" PetscInt_FMT, idx[0], BallIndex(P, 0));
    PetscCall(ISRestoreIndices(is[1], &idx));
  }
  {
    const PetscInt *idx;
    PetscInt        n;
    PetscCall(ISGetLocalSize(is[0], &n));
    PetscCall(ISGetIndices(is[0], &idx));
    PetscCheck(n == 0 || idx[0] == NodeIndex(P, P.xs, 0), P.comm, PETSC_ERR_PLIB, "composite numbering of the beam differs from the assumed one");
    PetscCall(ISRestoreIndices(is[0], &idx));
  }
  PetscCall(ISDestroy(&is[0]));
  PetscCall(ISDestroy(&is[1]));
  PetscCall(PetscFree(is));
  PetscCall(VecDestroy(&U));
  PetscFunctionReturn(0);
}

PetscErrorCode CreateJacobianMatrix(ImpactProblem &P)
{
  Vec      U;
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(P.pack, &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecDestroy(&U));
  PetscCall(MatCreateAIJ(P.comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE, 12, NULL, 8, NULL, &P.J));
  PetscCall(MatSetOption(P.J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatSetOption(P.J, MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  PetscCall(AssembleJacobianFull(P, 0.0, 0.0)); // the constant part; fixes the pattern (coupling entries as zeros)
  PetscCall(MatDuplicate(P.J, MAT_COPY_VALUES, &P.J0));
  P.n_jac_assembled = 0;
  P.jac_shift       = -1; // force the first real assembly
  PetscFunctionReturn(0);
}

} // namespace

PetscReal RKImaginaryStabilityBound(PetscInt s, const PetscReal *A, const PetscReal *b)
{
  using cplx = std::complex<double>;
  auto amp   = [&](double y) {
    const cplx         z(0.0, y);
    std::vector<cplx>  k(s);
    cplx               R = 1.0;
    for (PetscInt i = 0; i < s; ++i) {
      cplx sum = 0.0;
      for (PetscInt j = 0; j < i; ++j) sum += A[i * s + j] * k[j];
      k[i] = 1.0 + z * sum;
      R += z * b[i] * k[i];
    }
    return std::abs(R);
  };
  // Growth per step allowed: 1e-12 (1e-4 over 1e8 steps). RK2's |R(iy)| = 1 + y^4/8 + ...
  // exceeds it from y = 1.7e-3: such a method is reported unstable at any practical step.
  const double tol = 1e-12, dy = 1e-3;
  double       y   = 0.0;
  while (y < 20.0 && amp(y + dy) <= 1.0 + tol) y += dy;
  if (y < 0.05) return 0.0;
  double lo = y, hi = y + dy; // refine the edge
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (amp(mid) <= 1.0 + tol ? lo : hi) = mid;
  }
  return lo;
}

ImpactTimes ImpactTimesOf(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip)
{
  ImpactTimes     t;
  const PetscReal omega1 = BeamFundamentalFrequencyEstimate(beam);
  t.window               = ip.window >= 0 ? ip.window : 2 * (2 * M_PI / omega1);
  t.max_time             = ip.max_time > 0 ? ip.max_time : 4 * t.window + 100 * ContactTimeScale(ball);
  return t;
}

PetscErrorCode ImpactParamsFromOptions(MPI_Comm comm, const BeamParams &beam, ImpactParams *p)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Impact: where the ball strikes and how long to follow it", "beamimpact");
  PetscCall(PetscOptionsReal("-impact_x", "Impact point, metres from the x = 0 end", "", p->x, &p->x, NULL));
  PetscCall(PetscOptionsReal("-impact_window", "Time followed after each separation (s); < 0: two fundamental periods of the beam", "", p->window, &p->window, NULL));
  PetscCall(PetscOptionsReal("-impact_max_time", "Cap on the simulated time (s); < 0: 4 windows + 100 contact times", "", p->max_time, &p->max_time, NULL));
  PetscCall(PetscOptionsReal("-impact_event_tol", "Events are located until |indicator| (c/c_scale or dc/dt/v_i) is below this", "", p->event_tol, &p->event_tol, NULL));
  PetscCall(PetscOptionsInt("-impact_max_contacts", "Stop with an error after this many separate contacts", "", p->max_contacts, &p->max_contacts, NULL));
  PetscCall(PetscOptionsBool("-impact_energy_check", "Stop when the total energy grows beyond -impact_energy_growth_tol", "", p->energy_check, &p->energy_check, NULL));
  PetscCall(PetscOptionsReal("-impact_energy_growth_tol", "Allowed energy growth, relative to the incident kinetic energy", "", p->energy_growth_tol, &p->energy_growth_tol, NULL));
  PetscOptionsEnd();
  PetscCheck(p->x >= 0 && p->x <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_x %g is not allowed: the impact point must lie on the beam, 0 <= x <= L = %g (m)", (double)p->x, (double)beam.length);
  {
    const BeamOperator  op = BeamOperatorBuild(beam);
    const ImpactStencil st = BeamImpactStencil(op, p->x);
    const bool          on_held = (st.w > 0 && op.held[st.j]) && (st.w < 1 ? op.held[st.j + 1] : true);
    const bool          on_held_right = st.w == 0 && op.held[st.j + 1];
    PetscCheck(!(on_held || on_held_right), comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-impact_x %g is not allowed: that point is held fixed (a clamped or pinned support or inside -beam_clamp); strike a point that can move", (double)p->x);
  }
  PetscCheck(p->event_tol > 0 && p->event_tol < 1e-2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_event_tol %g is not allowed: use a value in (0, 1e-2)", (double)p->event_tol);
  PetscCheck(p->max_contacts >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_max_contacts %" PetscInt_FMT " is not allowed: at least 1", p->max_contacts);
  PetscCheck(p->energy_growth_tol > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-impact_energy_growth_tol %g is not allowed: it must be > 0", (double)p->energy_growth_tol);
  PetscFunctionReturn(0);
}

PetscErrorCode MonitorRequestFromOptions(MPI_Comm comm, const BeamParams &beam, MonitorRequest *m)
{
  PetscReal pts[64], times[256];
  PetscInt  npts = 64, ntimes = 256;
  PetscBool setpts = PETSC_FALSE, settimes = PETSC_FALSE;
  PetscReal seg[2] = {0, 0};
  PetscInt  nseg   = 2;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Monitors: time series and snapshots, written only when asked", "beamimpact");
  PetscCall(PetscOptionsBool("-monitor_ball", "Record ball position, velocity, compression and force at every step", "", m->ball, &m->ball, NULL));
  PetscCall(PetscOptionsBool("-monitor_energy", "Record ball kinetic, stored and dissipated energy and beam kinetic and strain energy at every step", "", m->energy, &m->energy, NULL));
  PetscCall(PetscOptionsRealArray("-monitor_velocity_at", "Record the beam velocity at these points x1,x2,... (m) at every step", "", pts, &npts, &setpts));
  PetscCall(PetscOptionsRealArray("-snapshot_times", "Record the beam displacement y(x) at these times t1,t2,... (s)", "", times, &ntimes, &settimes));
  PetscCall(PetscOptionsRealArray("-monitor_segment", "Record the kinetic energy of the beam segment x0,x1 (m) at every step, and its peak", "", seg, &nseg, &m->segment));
  PetscCall(PetscOptionsReal("-monitor_segment_until", "Take the segment's peak over t <= this (s); < 0: the whole run", "", m->segment_until, &m->segment_until, NULL));
  PetscOptionsEnd();
  if (m->segment) {
    PetscCheck(nseg == 2 && seg[0] >= 0 && seg[0] < seg[1] && seg[1] <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-monitor_segment needs two points 0 <= x0 < x1 <= L = %g (m); got %" PetscInt_FMT " value(s) %g,%g", (double)beam.length, nseg, (double)seg[0], (double)(nseg > 1 ? seg[1] : 0));
    m->segment_x0 = seg[0];
    m->segment_x1 = seg[1];
  }
  if (setpts) {
    for (PetscInt q = 0; q < npts; ++q)
      PetscCheck(pts[q] >= 0 && pts[q] <= beam.length, comm, PETSC_ERR_ARG_OUTOFRANGE, "-monitor_velocity_at %g is not allowed: points must lie on the beam, 0 <= x <= %g (m)", (double)pts[q], (double)beam.length);
    m->velocity_at.assign(pts, pts + npts);
  }
  if (settimes) {
    for (PetscInt q = 0; q < ntimes; ++q) PetscCheck(times[q] >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-snapshot_times %g is not allowed: times must be >= 0 (s)", (double)times[q]);
    m->snapshot_times.assign(times, times + ntimes);
    std::sort(m->snapshot_times.begin(), m->snapshot_times.end());
  }
  PetscFunctionReturn(0);
}

namespace {

} // namespace

int ContactCrossedEvent(ContactPhase phase, const EventIndicators &a, const EventIndicators &b, PetscReal tol)
{
  switch (phase) {
  case ContactPhase::Loading:
    if (a.cdot > -tol && b.cdot <= 0 && !(a.cdot <= 0 && b.cdot >= a.cdot)) return static_cast<int>(ContactEventKind::MaxCompression);
    if (a.c > -tol && b.c <= 0 && !(a.c <= 0 && b.c >= a.c)) return static_cast<int>(ContactEventKind::Separation); // only if dc/dt was missed
    return -1;
  case ContactPhase::Unloading: {
    const bool sep = a.c > 0 && b.c <= 0, rel = a.cdot < tol && b.cdot >= 0 && !(a.cdot >= 0 && b.cdot <= a.cdot);
    if (sep && rel) { // the earlier root by linear interpolation
      const PetscReal ts = a.c / (a.c - b.c), tr = a.cdot / (a.cdot - b.cdot);
      return static_cast<int>(tr < ts ? ContactEventKind::Reload : ContactEventKind::Separation);
    }
    if (sep) return static_cast<int>(ContactEventKind::Separation);
    if (rel) return static_cast<int>(ContactEventKind::Reload);
    return -1;
  }
  case ContactPhase::Separated: return a.c < 0 && b.c >= 0 ? static_cast<int>(ContactEventKind::ContactStart) : -1;
  }
  return -1;
}

PetscReal ContactEventIndicator(ContactEventKind k, const EventIndicators &g)
{
  return (k == ContactEventKind::MaxCompression || k == ContactEventKind::Reload) ? g.cdot : g.c;
}

bool ContactEventFalling(ContactEventKind k) { return k == ContactEventKind::MaxCompression || k == ContactEventKind::Separation; }

PetscErrorCode ContactEventApply(MPI_Comm comm, ContactEventKind kind, PetscReal te, PetscReal c, const BallParams &ball, const ImpactTimes &times, const char *method, ContactState *state,
                                 ContactTimeline *tl, ImpactResult *res, bool *force_changed)
{
  PetscFunctionBeginUser;
  *force_changed = true;
  switch (kind) {
  case ContactEventKind::MaxCompression:
    *force_changed = ContactHasHysteresis(ball);
    ContactSwitch(ball, state, ContactPhase::Unloading, c);
    break;
  case ContactEventKind::Reload:
    *force_changed = ContactHasHysteresis(ball);
    ContactSwitch(ball, state, ContactPhase::Loading, c);
    break;
  case ContactEventKind::Separation:
    if (state->phase == ContactPhase::Loading && ContactHasHysteresis(ball)) {
      // The unloading branch was never applied: the ball would leave without its hysteresis loss.
      char after[96] = "";
      for (const ContactEvent &e : res->events)
        if (e.kind == ContactEventKind::Reload) PetscCall(PetscSNPrintf(after, sizeof(after), " after the reload located at t = %g s", (double)e.time));
      SETERRQ(comm, PETSC_ERR_PLIB,
              "the ball separated at t = %g s while the hysteretic law was still in its loading branch: the maximum-compression event was missed%s, so the unloading (lossy) branch was skipped and "
              "the result would be wrong; none is reported (%s; a defect of the event location: a different step changes whether it is hit)",
              (double)te, after, method);
    }
    ContactSwitch(ball, state, ContactPhase::Separated, c);
    if (res->contacts == 1) res->contact_time = te - tl->contact_start;
    res->contact_time_total += te - tl->contact_start;
    tl->t_stop = std::min(times.max_time, te + times.window);
    break;
  case ContactEventKind::ContactStart:
    ContactSwitch(ball, state, ContactPhase::Loading, c);
    res->contacts++;
    tl->contact_start = te;
    tl->t_stop        = times.max_time;
    break;
  }
  const PetscReal F = ContactForce(ball, *state, c);
  res->events.push_back({kind, te, c, F});
  if (kind == ContactEventKind::MaxCompression) {
    res->max_compression = std::max(res->max_compression, c);
    res->peak_force      = std::max(res->peak_force, F);
  }
  PetscFunctionReturn(0);
}

namespace {

} // namespace

PetscErrorCode ImpactRun(MPI_Comm comm, const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, const MonitorRequest &mon, ImpactResult *res)
{
  ImpactProblem P;
  TS            ts;
  TSAdapt       adapt;
  Vec           U = nullptr, V = nullptr;
  char          type_opt[256] = TSRK;
  PetscBool     flg;

  PetscFunctionBeginUser;
  *res   = ImpactResult();
  res->x = ip.x;
  P.comm = comm;
  PetscCallMPI(MPI_Comm_size(comm, &P.size));
  PetscCallMPI(MPI_Comm_rank(comm, &P.rank));
  P.op      = BeamOperatorBuild(beam);
  P.ball    = ball;
  P.x_imp   = ip.x;
  P.stencil = BeamImpactStencil(P.op, ip.x);
  P.contact = ContactState(); // touching, loading

  // The formulation depends on the TS type: read it before building the problem.
  PetscCall(PetscOptionsGetString(NULL, NULL, "-ts_type", type_opt, sizeof(type_opt), &flg));
  P.form        = FormulationOfType(type_opt);
  P.dof         = P.form == Formulation::SecondOrder ? 1 : 2;
  P.jac_contact = P.form == Formulation::Implicit || P.form == Formulation::SecondOrder;
  res->formulation = FormulationName(P.form);
  PetscCall(CreateLayout(P));

  // Scales of the problem.
  // Contact time scale against the moving beam: the ball's mass reduced with the beam's
  // (held nodes excluded), T_r = T_c sqrt(M/(M + m_b)) <= T_c. A ball heavier than the beam
  // has a contact several times shorter than on a wall; steps, caps and warnings use T_r.
  PetscReal beam_mass_free = 0;
  for (PetscInt i = 0; i < P.op.N; ++i) beam_mass_free += P.op.held[i] ? 0.0 : P.op.mass[i];
  const PetscReal t_contact = ContactTimeScale(ball) * std::sqrt(beam_mass_free / (beam_mass_free + ball.mass));
  const PetscReal c_scale   = ContactCompressionScale(ball);
  const PetscReal v_scale   = ball.speed;
  const ImpactTimes times   = ImpactTimesOf(beam, ball, ip);
  const PetscReal t_cap     = times.max_time;
  const PetscReal k_bound   = ball.law == ContactLawKind::Linear ? ball.k : std::max(ball.m, ball.n) * ball.k1 * std::pow(2 * c_scale, ball.m - 1);
  res->omega_max_bound      = BeamMaxFrequencyBound(P.op, P.stencil, k_bound, ball.mass);

  PetscCall(TSGAlpha2Register()); // -ts_type alpha2: generalized-alpha with a consistent restart (ts_galpha2.hpp)
  PetscCall(TSCreate(comm, &ts));
  PetscCall(TSSetType(ts, type_opt));
  PetscCall(TSSetDM(ts, P.pack));
  PetscCall(TSSetProblemType(ts, TS_NONLINEAR));
  PetscCall(DMCreateGlobalVector(P.pack, &U));
  switch (P.form) {
  case Formulation::Explicit: PetscCall(TSSetRHSFunction(ts, NULL, RHSExplicit, &P)); break;
  case Formulation::IMEX:
    PetscCall(CreateJacobianMatrix(P));
    PetscCall(TSSetIFunction(ts, NULL, IFunction, &P));
    PetscCall(TSSetIJacobian(ts, P.J, P.J, IJacobian, &P));
    PetscCall(TSSetRHSFunction(ts, NULL, RHSContact, &P));
    break;
  case Formulation::Implicit:
    PetscCall(CreateJacobianMatrix(P));
    PetscCall(TSSetIFunction(ts, NULL, IFunction, &P));
    PetscCall(TSSetIJacobian(ts, P.J, P.J, IJacobian, &P));
    break;
  case Formulation::SecondOrder:
    PetscCall(CreateJacobianMatrix(P));
    PetscCall(TSSetI2Function(ts, NULL, I2Function, &P));
    PetscCall(TSSetI2Jacobian(ts, P.J, P.J, I2Jacobian, &P));
    break;
  }
  if (P.form != Formulation::Explicit) { // direct solves of the (banded) Jacobian by default
    SNES snes;
    KSP  ksp;
    PC   pc;
    PetscCall(TSGetSNES(ts, &snes));
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    if (P.size > 1) PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }

  // Defaults that options override: a step resolving the contact, capped so one
  // step cannot hold two events.
  const PetscReal dt_cap = t_contact / 8;
  PetscCall(TSSetTimeStep(ts, t_contact / 200));
  PetscCall(TSSetMaxTime(ts, 1e30)); // the event loop below decides when to stop
  PetscCall(TSSetMaxSteps(ts, PETSC_MAX_INT));
  PetscCall(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSGetAdapt(ts, &adapt));
  PetscCall(TSAdaptSetStepLimits(adapt, PETSC_DEFAULT, dt_cap));
  PetscCall(TSSetFromOptions(ts));
  {
    TSType    type;
    PetscBool same;
    PetscCall(TSGetType(ts, &type));
    PetscCall(PetscStrcmp(type, type_opt, &same));
    PetscCheck(same, comm, PETSC_ERR_ARG_WRONG, "TS type changed from %s to %s after setup: set -ts_type on the command line or in an options file", type_opt, type);
    res->ts_type = type;
  }
  NewtonFloor newton_floor;
  if (P.form != Formulation::Explicit) {
    PetscBool user_test;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-snes_convergence_test", &user_test));
    if (!user_test) {
      SNES snes;
      newton_floor = {&P, ts, res->omega_max_bound * res->omega_max_bound};
      PetscCall(TSGetSNES(ts, &snes));
      PetscCall(SNESSetConvergenceTest(snes, ConvergedWithRoundoffFloor, &newton_floor, NULL));
    }
  }
  PetscCall(TSSetErrorIfStepFails(ts, PETSC_FALSE)); // failures are explained by check_step below
  PetscCall(TSSetUp(ts));
  if (ip.check_unused_options) PetscCall(OptionsCheckUnused(comm));
  if (P.form != Formulation::Explicit) { // the last Newton solve's residual history explains a failure (check_step)
    SNES snes;
    PetscCall(TSGetSNES(ts, &snes));
    PetscCall(SNESSetConvergenceHistory(snes, NULL, NULL, PETSC_DECIDE, PETSC_TRUE));
  }
  PetscCheck(ts->ops->rollback, comm, PETSC_ERR_SUP,
             "-ts_type %s cannot roll back a step, so contact start, maximum compression and separation cannot be located as events; "
             "use one that can: rk (e.g. -ts_rk_type 4 or 5dp), cn, theta, beuler, bdf, arkimex, rosw, alpha, alpha2",
             res->ts_type.c_str());

  // Explicit stability: the imaginary-axis bound of the tableau over omega_max.
  PetscBool   fixed_step;
  std::string rk_type; // -ts_rk_type, for messages
  PetscCall(PetscObjectTypeCompare((PetscObject)adapt, TSADAPTNONE, &fixed_step));
  if (P.form == Formulation::Explicit) {
    PetscCheck(res->ts_type == TSRK, comm, PETSC_ERR_SUP, "-ts_type %s is explicit but not rk: only rk tableaus have a computed stability limit here; use -ts_type rk", res->ts_type.c_str());
    PetscInt         s;
    const PetscReal *A, *b;
    PetscCall(TSRKGetTableau(ts, &s, &A, &b, NULL, NULL, NULL, NULL, NULL));
    const PetscReal ystar = RKImaginaryStabilityBound(s, A, b);
    TSRKType        rktype;
    PetscCall(TSRKGetType(ts, &rktype));
    rk_type = rktype;
    PetscCheck(ystar > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-ts_rk_type %s is unstable for an undamped oscillation at any step (its stability region does not contain the imaginary axis); use -ts_rk_type 3bs, 4 or 5dp, or an implicit type (cn, bdf, alpha2)",
               rktype);
    res->dt_stable = ystar / res->omega_max_bound;
    PetscReal dt;
    PetscCall(TSGetTimeStep(ts, &dt));
    PetscBool dt_set;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_dt", &dt_set));
    if (!dt_set) PetscCall(TSSetTimeStep(ts, std::min(dt, 0.9 * res->dt_stable)));
    else if (fixed_step)
      PetscCheck(dt <= res->dt_stable, comm, PETSC_ERR_ARG_OUTOFRANGE,
                 "-ts_dt %g is above the stability limit dt_max = %g s of -ts_type rk -ts_rk_type %s on this grid (N = %" PetscInt_FMT ", omega_max <= %g rad/s); use -ts_dt <= %g, fewer nodes, or an implicit type",
                 (double)dt, (double)res->dt_stable, rktype, P.op.N, (double)res->omega_max_bound, (double)res->dt_stable);
  }
  PetscReal dt_nominal;
  PetscCall(TSGetTimeStep(ts, &dt_nominal));
  PetscCheck(dt_nominal > 0 && std::isfinite(dt_nominal), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ts_dt %g is not allowed: the time step must be > 0 (s)", (double)dt_nominal);
  if (ip.report_setup) {
    PetscCall(PetscPrintf(comm, "ts %s (%s)  dt %.3e s%s\n", res->ts_type.c_str(), res->formulation.c_str(), (double)dt_nominal, fixed_step ? "" : " (initial; adaptive)"));
    if (res->dt_stable > 0) PetscCall(PetscPrintf(comm, "explicit stability limit dt_max %.4e s (omega_max <= %.4e rad/s)\n", (double)res->dt_stable, (double)res->omega_max_bound));
  }
  // Can the step or the tolerance resolve the contact? (docs/stability.md: T_r/400 verified to 1e-3 in the ACOR.)
  // Said once, by the run that reports its set-up (not by every case of a sweep or study).
  const PetscReal t_resolve = t_contact;
  if (!ip.report_setup) {
  } else if (fixed_step && dt_nominal > dt_cap)
    PetscCall(PetscPrintf(comm, "WARNING: fixed step -ts_dt %g s is more than 1/8 of the contact time scale %g s: the contact is poorly resolved and events may be missed\n", (double)dt_nominal, (double)t_contact));
  else if (fixed_step && dt_nominal > t_resolve / 100)
    PetscCall(PetscPrintf(comm, "WARNING: fixed step -ts_dt %g s resolves the contact time scale %g s with only %.0f steps: errors of 1e-3 or more in the ACOR are possible; use -ts_dt <= %.2e (T_r/400)\n", (double)dt_nominal,
                          (double)t_resolve, (double)(t_resolve / dt_nominal), (double)(t_resolve / 400)));
  if (!fixed_step && ip.report_setup) {
    PetscReal atol, rtol;
    PetscCall(TSGetTolerances(ts, &atol, NULL, &rtol, NULL));
    if (rtol > 1e-4 || atol > 1e-3 * c_scale)
      PetscCall(PetscPrintf(comm,
                            "WARNING: adaptive step with -ts_rtol %g -ts_atol %g cannot resolve the contact (compression scale %.3g m, contact time %.3g s): errors of 1e-3 or more in the ACOR are possible; "
                            "use -ts_atol <= %.1e (1e-5 of the compression scale) and -ts_rtol <= 1e-6, or a fixed -ts_dt <= %.2e (T_r/400)\n",
                            (double)rtol, (double)atol, (double)c_scale, (double)t_resolve, (double)(1e-5 * c_scale), (double)(t_resolve / 400)));
  }
  res->dt_nominal = dt_nominal;

  // Initial state: beam at rest, ball touching at x_imp moving in +y.
  PetscCall(VecZeroEntries(U));
  {
    OutView o;
    PetscCall(OutBegin(P, U, &o));
    if (o.ball) o.ball[0] = 0; // position: just touching
    if (o.ball && P.dof == 2) o.ball[1] = ball.speed;
    PetscCall(OutEnd(P, U, &o));
  }
  if (P.form == Formulation::SecondOrder) {
    PetscCall(VecDuplicate(U, &V));
    PetscCall(VecZeroEntries(V));
    OutView o;
    PetscCall(OutBegin(P, V, &o));
    if (o.ball) o.ball[0] = ball.speed;
    PetscCall(OutEnd(P, V, &o));
    PetscCall(TS2SetSolution(ts, U, V));
  } else PetscCall(TSSetSolution(ts, U));
  PetscCall(TSSetTime(ts, 0.0));
  PetscCall(TSSetStepNumber(ts, 0));

  // Recording.
  StateMeasures m0;
  PetscCall(MeasureState(P, ts, nullptr, &m0, nullptr));
  const PetscReal E0 = m0.total(), p0 = m0.momentum, L0 = m0.angular_momentum;
  ImpactSeries   &S  = res->series;
  S.velocity_at.assign(mon.velocity_at.size(), {});
  S.velocity_at_x = mon.velocity_at;
  auto record = [&](PetscReal t) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (!mon.any() && !ip.energy_check) PetscFunctionReturn(0);
    StateMeasures          m;
    std::vector<PetscReal> pv;
    PetscCall(MeasureState(P, ts, &mon, &m, &pv));
    if (ip.energy_check) {
      const PetscReal growth = (m.total() - E0) / E0;
      if (growth > ip.energy_growth_tol) {
        // Name the likely cause from the formulation and the step actually taken.
        const PetscReal dt_last = ts->ptime - ts->ptime_prev;
        char            cause[512];
        if (P.form == Formulation::Explicit && fixed_step)
          PetscCall(PetscSNPrintf(cause, sizeof(cause), "the fixed step is %.3g x the stability limit dt_max = %g s computed for this grid and contact; use a smaller -ts_dt", (double)(dt_last / res->dt_stable), (double)res->dt_stable));
        else if (P.form == Formulation::Explicit)
          PetscCall(PetscSNPrintf(cause, sizeof(cause), "the error controller let the step reach the explicit stability limit dt_max = %g s; tighten -ts_rtol/-ts_atol or use a fixed -ts_dt below dt_max", (double)res->dt_stable));
        else if (P.form == Formulation::IMEX)
          PetscCall(PetscSNPrintf(cause, sizeof(cause), "-ts_type %s treats the contact force explicitly, and the step is too large for the contact stiffness (contact time scale %g s); reduce %s or use a fully implicit type (cn, bdf, alpha2)",
                                  res->ts_type.c_str(), (double)t_contact, fixed_step ? "-ts_dt" : "-ts_rtol/-ts_atol"));
        else
          PetscCall(PetscSNPrintf(cause, sizeof(cause), "the %s does not resolve the contact (contact time scale %g s); reduce %s", fixed_step ? "step" : "tolerance", (double)t_contact, fixed_step ? "-ts_dt" : "-ts_rtol/-ts_atol"));
        SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, "energy grew by %.3g of the incident kinetic energy at t = %g s (-ts_type %s%s%s, %s step %g s): with the %s law energy can only be %s; likely cause: %s", (double)growth, (double)t,
                res->ts_type.c_str(), rk_type.empty() ? "" : " -ts_rk_type ", rk_type.c_str(), fixed_step ? "fixed" : "adaptive, last", (double)dt_last, ContactLawName(ball.law),
                ball.law == ContactLawKind::Linear ? "conserved" : "lost", cause);
      }
    }
    if (!mon.any()) PetscFunctionReturn(0);
    S.time.push_back(t);
    if (mon.ball) {
      S.ball_y.push_back(m.ball_y);
      S.ball_v.push_back(m.ball_v);
      S.compression.push_back(m.c);
      S.force.push_back(m.force);
    }
    if (mon.energy) {
      S.ball_kinetic.push_back(m.ball_kinetic);
      S.ball_stored.push_back(m.ball_stored);
      S.ball_dissipated.push_back(m.ball_work - m.ball_stored);
      S.beam_kinetic.push_back(m.beam_kinetic);
      S.beam_strain.push_back(m.beam_strain);
      S.total_energy.push_back(m.total());
    }
    for (size_t q = 0; q < pv.size(); ++q) S.velocity_at[q].push_back(pv[q]);
    if (mon.segment) {
      S.segment_kinetic.push_back(m.segment_kinetic);
      if ((mon.segment_until < 0 || t <= mon.segment_until * (1 + 1e-12)) && m.segment_kinetic > res->segment_kinetic_peak) {
        res->segment_kinetic_peak      = m.segment_kinetic;
        res->segment_kinetic_peak_time = t;
      }
    }
    PetscFunctionReturn(0);
  };
  size_t next_snapshot = 0;
  auto   take_snapshots = [&](PetscReal t) -> PetscErrorCode {
    PetscFunctionBeginUser;
    while (next_snapshot < mon.snapshot_times.size() && mon.snapshot_times[next_snapshot] <= t * (1 + 1e-12) + 1e-15) {
      std::vector<PetscReal> y;
      PetscCall(GatherDisplacement(P, ts, &y));
      S.snapshot_time.push_back(mon.snapshot_times[next_snapshot]);
      S.snapshot_y.push_back(y);
      ++next_snapshot;
    }
    PetscFunctionReturn(0);
  };
  PetscCall(record(0.0));
  PetscCall(take_snapshots(0.0));

  auto indicators = [&](EventIndicators *g) -> PetscErrorCode {
    PetscReal c, cd;
    PetscFunctionBeginUser;
    PetscCall(CurrentCompression(P, ts, &c, &cd));
    PetscCheck(std::isfinite(c) && std::isfinite(cd), comm, PETSC_ERR_FP,
               "the solution is not finite (NaN/Inf) at t = %g s with -ts_type %s: the step is unstable%s", (double)ts->ptime, res->ts_type.c_str(),
               res->dt_stable > 0 ? " (explicit: keep dt below dt_max)" : "");
    g->c    = c / c_scale;
    g->cdot = cd / v_scale;
    PetscFunctionReturn(0);
  };
  auto check_step = [&]() -> PetscErrorCode {
    TSConvergedReason reason;
    PetscFunctionBeginUser;
    PetscCall(TSGetConvergedReason(ts, &reason));
    if (reason == TS_DIVERGED_NONLINEAR_SOLVE) {
      // Explain the last Newton solve from its residual history (recorded since set-up).
      SNES                snes;
      PetscReal          *hist = nullptr, rtol;
      PetscInt           *hits = nullptr, nh = 0, its = 0;
      SNESConvergedReason sr;
      PetscCall(TSGetSNES(ts, &snes));
      PetscCall(SNESGetConvergenceHistory(snes, &hist, &hits, &nh));
      PetscCall(SNESGetConvergedReason(snes, &sr));
      PetscCall(SNESGetIterationNumber(snes, &its));
      PetscCall(SNESGetTolerances(snes, NULL, &rtol, NULL, NULL, NULL));
      const PetscReal f0 = nh > 0 ? hist[0] : 0, flast = nh > 0 ? hist[nh - 1] : 0;
      PetscReal       fmax_after = 0, fmin_later = std::numeric_limits<PetscReal>::max();
      for (PetscInt k = 1; k < nh; ++k) fmax_after = std::max(fmax_after, hist[k]);
      for (PetscInt k = 2; k < nh; ++k) fmin_later = std::min(fmin_later, hist[k]);
      // The first Newton step removed almost all of the residual (the problem is linear within a
      // contact phase) and what is left is round-off: the next steps made no progress, or it is
      // within 10x the round-off estimate eps omega_max^2 |u| of the stiffness term.
      Vec X, V;
      if (P.form == Formulation::SecondOrder) PetscCall(TS2GetSolution(ts, &X, &V));
      else PetscCall(TSGetSolution(ts, &X));
      PetscReal unorm;
      PetscCall(VecNorm(X, NORM_2, &unorm));
      const PetscReal floor_est = PETSC_MACHINE_EPSILON * res->omega_max_bound * res->omega_max_bound * unorm;
      const bool      stalled   = nh >= 2 && f0 > 0 && hist[1] <= 1e-2 * f0 && ((nh >= 3 && fmin_later >= 0.1 * hist[1]) || flast <= 10 * floor_est);
      if (stalled)
        SETERRQ(comm, PETSC_ERR_NOT_CONVERGED,
                "time stepping stopped at t = %g s with -ts_type %s: the Newton iteration stalled at a residual norm of %.2e after its first step reduced it from %.2e (SNES %s after %" PetscInt_FMT
                " iterations): that is the round-off level of this grid (eps omega_max^2 |u| = %.1e with omega_max <= %.3g rad/s), above -snes_rtol %g x the initial norm, so the solve cannot converge; "
                "set -snes_atol %.0e (ten times the stalled residual)",
                (double)ts->ptime, res->ts_type.c_str(), (double)flast, (double)f0, SNESConvergedReasons[sr], its, (double)floor_est, (double)res->omega_max_bound, (double)rtol, (double)(10 * fmax_after));
      SETERRQ(comm, PETSC_ERR_NOT_CONVERGED,
              "time stepping stopped at t = %g s with -ts_type %s: the nonlinear (Newton) solve failed (SNES %s after %" PetscInt_FMT " iterations, residual norm %.2e from %.2e); reduce -ts_dt or check -snes_* and -ksp_* options (%s)",
              (double)ts->ptime, res->ts_type.c_str(), SNESConvergedReasons[sr], its, (double)flast, (double)f0, TSConvergedReasons[reason]);
    }
    if (reason < 0) {
      const char *why = reason == TS_DIVERGED_STEP_REJECTED ? "too many steps were rejected by the error controller; loosen -ts_rtol/-ts_atol or raise -ts_max_reject" : "the integrator diverged";
      SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, "time stepping stopped at t = %g s with -ts_type %s: %s (%s)", (double)ts->ptime, res->ts_type.c_str(), why, TSConvergedReasons[reason]);
    }
    PetscFunctionReturn(0);
  };

  // Event-driven time stepping.
  const double wall0   = MPI_Wtime();
  PetscReal       t = 0;
  ContactTimeline timeline;
  timeline.t_stop = t_cap;
  PetscReal    dt_next = dt_nominal;
  EventIndicators g0;
  PetscCall(indicators(&g0));
  res->contacts = 1;
  res->events.push_back({ContactEventKind::ContactStart, 0.0, 0.0, 0.0});
  PetscInt event_steps = 0, steps = 0;
  while (t < timeline.t_stop * (1 - 1e-14)) {
    // Land exactly on the stop time and on the next snapshot time.
    PetscReal target = timeline.t_stop;
    if (next_snapshot < mon.snapshot_times.size()) target = std::min(target, mon.snapshot_times[next_snapshot]);
    PetscReal dt = fixed_step ? dt_next : std::min(dt_next, dt_cap);
    if (t + dt > target) dt = target - t;
    PetscCall(TSSetTimeStep(ts, dt));
    PetscCall(TSStep(ts));
    PetscCall(check_step());
    steps++;
    EventIndicators g1;
    PetscCall(indicators(&g1));
    const int ev = ContactCrossedEvent(P.contact.phase, g0, g1, ip.event_tol);
    if (ev >= 0) {
      // Locate: bracket [ta, tb] with the base of the last step at ta. Illinois
      // iterations re-step from the base onto the estimated root until the
      // indicator is within tolerance on the post-event side.
      const auto kind    = static_cast<ContactEventKind>(ev);
      const bool falling = ContactEventFalling(kind);
      PetscReal  ta = t, tb = ts->ptime, ga = ContactEventIndicator(kind, g0), gb = ContactEventIndicator(kind, g1);
      const PetscReal step_len = tb - ta; // a located event is within 1e-4 of this: an O(1e-8 dt^2) local error at a C^0 force switch
      bool       at_post = true;
      int        side    = 0;
      for (int it = 0;; ++it) {
        if (at_post && std::abs(gb) <= ip.event_tol) break;
        if (!at_post && std::abs(ga) <= ip.event_tol) break; // on the root from the pre-event side: as good
        PetscCheck(it < 100, comm, PETSC_ERR_NOT_CONVERGED, "event %s could not be located in [%g, %g] s with -ts_type %s (indicator %g -> %g)", ContactEventName(kind), (double)ta, (double)tb, res->ts_type.c_str(),
                   (double)ga, (double)gb);
        PetscReal tn = tb - gb * (tb - ta) / (gb - ga);
        if (!(tn > ta && tn < tb)) tn = 0.5 * (ta + tb);
        // Never re-step by a vanishing amount (implicit second-order schemes are
        // ill-conditioned there): a bracket this narrow is located; take the post side.
        const PetscReal min_step = 1e-4 * step_len;
        if (tn - ta < min_step) tn = std::min(tb, ta + min_step);
        if (tb - ta <= 2 * min_step) {
          if (at_post) break;
          tn = tb;
        }
        if (at_post) PetscCall(TSRollBack(ts));
        PetscCall(TSSetTimeStep(ts, tn - ta));
        PetscCall(TSStep(ts));
        PetscCall(check_step());
        event_steps++;
        EventIndicators gn;
        PetscCall(indicators(&gn));
        const PetscReal gv   = ContactEventIndicator(kind, gn);
        const bool      post = falling ? gv <= 0 : gv >= 0;
        if (post) {
          tb = ts->ptime;
          gb = gv;
          if (side == 1) ga *= 0.5; // Illinois
          side    = 1;
          at_post = true;
        } else {
          ta = ts->ptime;
          ga = gv;
          if (side == -1) gb *= 0.5;
          side    = -1;
          at_post = false;
        }
      }
      // Apply the event at the located state.
      PetscReal c, cd;
      PetscCall(CurrentCompression(P, ts, &c, &cd));
      const PetscReal te = ts->ptime;
      bool            rhs_changed;
      char            method[128];
      PetscCall(PetscSNPrintf(method, sizeof(method), "-ts_type %s", res->ts_type.c_str()));
      PetscCall(ContactEventApply(comm, kind, te, c, ball, times, method, &P.contact, &timeline, res, &rhs_changed));
      if (kind == ContactEventKind::ContactStart && res->contacts > ip.max_contacts) { // physical chatter, or an integration gone wrong? The energy tells.
        StateMeasures mc;
        PetscCall(MeasureState(P, ts, nullptr, &mc, nullptr));
        const PetscReal growth = (mc.total() - E0) / E0;
        if (growth > ip.energy_growth_tol)
          SETERRQ(comm, PETSC_ERR_NOT_CONVERGED,
                  "more than -impact_max_contacts %" PetscInt_FMT " separate contacts by t = %g s, and the energy has grown by %.3g of the incident kinetic energy: the integration is unstable or inaccurate (not a physical chatter); reduce %s",
                  ip.max_contacts, (double)te, (double)growth, fixed_step ? "-ts_dt" : "-ts_rtol/-ts_atol");
        SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, "more than -impact_max_contacts %" PetscInt_FMT " separate contacts by t = %g s: the ball is chattering on the beam", ip.max_contacts, (double)te);
      }
      if (rhs_changed) PetscCall(TSRestartStep(ts));
      PetscCall(indicators(&g1));
    }
    t  = ts->ptime;
    g0 = g1;
    PetscReal suggested;
    PetscCall(TSGetTimeStep(ts, &suggested));
    dt_next = fixed_step ? dt_nominal : suggested;
    PetscCall(record(t));
    PetscCall(take_snapshots(t));
  }
  res->wall_time = MPI_Wtime() - wall0;
  res->ended_in_contact = P.contact.phase != ContactPhase::Separated ? PETSC_TRUE : PETSC_FALSE;
  if (res->ended_in_contact) {
    res->contact_time_total += t - timeline.contact_start;
    if (res->contacts == 1) res->contact_time = t - timeline.contact_start;
  }

  // Outcome and invariants.
  StateMeasures m1;
  PetscCall(MeasureState(P, ts, nullptr, &m1, nullptr));
  PetscCheck(std::isfinite(m1.ball_v) && std::isfinite(m1.total()) && std::isfinite(m1.momentum) && std::isfinite(m1.angular_momentum), comm, PETSC_ERR_FP,
             "the solution is not finite (NaN/Inf) at the end of the run, t = %g s, with -ts_type %s: no result is reported; the step is unstable%s", (double)t, res->ts_type.c_str(),
             res->dt_stable > 0 ? " (explicit: keep dt below dt_max)" : "");
  res->final_time             = t;
  res->ball_final_velocity    = m1.ball_v;
  res->acor                   = -m1.ball_v / ball.speed;
  res->acor_corrected         = ball.law == ContactLawKind::Linear ? res->acor * ball.loss_factor : res->acor;
  res->energy_error           = (m1.total() - E0) / E0;
  res->linear_momentum_error  = (m1.momentum - p0) / (ball.mass * ball.speed);
  res->angular_momentum_error = (m1.angular_momentum - L0) / (ball.mass * ball.speed * beam.length);
  res->beam_kinetic_end       = m1.beam_kinetic;
  res->beam_strain_end        = m1.beam_strain;
  res->ball_dissipated_end    = m1.ball_work - m1.ball_stored;
  {
    // Rigid-body part of the beam's motion about its centre of mass (held nodes never move).
    PetscReal M = 0, Mx = 0, Mxx = 0;
    for (PetscInt i = 0; i < P.op.N; ++i) {
      if (P.op.held[i]) continue;
      const PetscReal x = i * P.op.h;
      M += P.op.mass[i];
      Mx += P.op.mass[i] * x;
      Mxx += P.op.mass[i] * x * x;
    }
    const PetscReal x_cm = Mx / M, I_cm = Mxx - M * x_cm * x_cm;
    const PetscReal L_cm = m1.beam_moment - x_cm * m1.beam_momentum;
    const PetscReal Ein  = 0.5 * ball.mass * ball.speed * ball.speed;
    const PetscReal Etr = m1.beam_momentum * m1.beam_momentum / (2 * M), Erot = I_cm > 0 ? L_cm * L_cm / (2 * I_cm) : 0;
    const PetscReal ball_loss = ball.law == ContactLawKind::Linear ? (1 - ball.loss_factor * ball.loss_factor) * m1.ball_kinetic : res->ball_dissipated_end;
    res->ball_loss_fraction   = ball_loss / Ein;
    res->translation_fraction = Etr / Ein;
    res->rotation_fraction    = Erot / Ein;
    res->vibration_fraction   = (m1.beam_kinetic + m1.beam_strain - Etr - Erot) / Ein;
  }
  if (mon.segment && mon.segment_until > 0)
    PetscCheck(t >= mon.segment_until * (1 - 1e-12), comm, PETSC_ERR_ARG_INCOMP, "-monitor_segment_until %g s is beyond the end of the run (%g s): raise -impact_window so the run lasts that long", (double)mon.segment_until, (double)t);
  res->steps                  = steps;
  res->event_steps            = event_steps;
  PetscCall(TSGetStepRejections(ts, &res->rejected_steps));
  if (P.form != Formulation::Explicit) PetscCall(TSGetSNESFailures(ts, &res->failed_solves));
  res->function_evals      = P.n_func;
  res->jacobian_evals      = P.n_jac;
  res->jacobian_assemblies = P.n_jac_assembled;
  if (P.form != Formulation::Explicit) {
    PetscCall(TSGetSNESIterations(ts, &res->nonlinear_its));
    PetscCall(TSGetKSPIterations(ts, &res->linear_its));
  }

  PetscCall(TSDestroy(&ts));
  PetscCall(VecDestroy(&U));
  PetscCall(VecDestroy(&V));
  PetscCall(MatDestroy(&P.J));
  PetscCall(MatDestroy(&P.J0));
  PetscCall(DMDestroy(&P.pack));
  PetscCall(DMDestroy(&P.da));
  PetscCall(DMDestroy(&P.red));
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactRun(MPI_Comm comm, const Scenario &sc, ImpactResult *res) { return ImpactRun(comm, sc.beam, sc.ball, sc.impact, sc.monitor, res); }

} // namespace beamimpact

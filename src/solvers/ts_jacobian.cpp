// The TS Jacobian J = shift I + d(residual)/du of the implicit, IMEX and second-order forms:
//   first order   [[shift I, -I], [(K + kc g g^T)/m, shift I + C/m]]  (ball rows alike)
//   second order  shift_A I + shift_V C/m + (K + kc g g^T)/m
// K = df/dy and C = df/dv of the force operator (BeamSystemStiffnessRow, BeamSystemDampingRow;
// C only for a damped beam: the undamped pattern and values are unchanged), kc = dF/dc of the
// contact law in its current phase, g the coupling's entries and the ball. The constant part J0
// is assembled once with the final pattern (contact entries as explicit zeros); a change of
// shift (shift_V) or contact stiffness copies it, shifts the diagonal, adds shift_V Jd (second
// order, damped; Jd = C/m on J0's pattern) and the contact block, so the LU is redone only when
// one of them changes.
#include "solvers/ts_problem.hpp"

#include <petscdm.h>

#include <map>

namespace beamimpact {

namespace {

// The coupling vector (dc/du over the coupled beam dofs and the ball, last) and its columns.
struct CouplingBlock {
  PetscInt  n = 0; // the coupling's entries and the ball
  PetscInt  cols[ContactCoupling::kMaxEntries + 1];
  PetscReal g[ContactCoupling::kMaxEntries + 1];
};
CouplingBlock CouplingBlockOf(const TSProblem &P)
{
  CouplingBlock b;
  for (PetscInt q = 0; q < P.g.n; ++q) {
    b.cols[q] = P.L.DofIndex(P.g.dof[q], false);
    b.g[q]    = -P.g.w[q];
  }
  b.n           = P.g.n + 1;
  b.cols[P.g.n] = P.L.BallIndex(0);
  b.g[P.g.n]    = 1.0;
  return b;
}

PetscErrorCode SetRow(Mat J, PetscInt r, const std::map<PetscInt, PetscScalar> &row)
{
  std::vector<PetscInt>    cols;
  std::vector<PetscScalar> vals;

  PetscFunctionBeginUser;
  for (auto &e : row) {
    cols.push_back(e.first);
    vals.push_back(e.second);
  }
  PetscCall(MatSetValues(J, 1, &r, (PetscInt)cols.size(), cols.data(), vals.data(), INSERT_VALUES));
  PetscFunctionReturn(0);
}

// Every entry of the pattern, with shift = kc = 0: the constant part J0. With damping_only
// (second order, damped beam) the same pattern holds Jd = C/m instead (C's entries lie on K's
// pattern and the diagonal).
PetscErrorCode AssembleConstantPart(TSProblem &P, Mat J, bool damping_only = false)
{
  const BeamSystem   &S     = *P.sys;
  const TSLayout     &L     = P.L;
  const bool          first = L.dof == 2 * L.fields;
  const CouplingBlock cb    = CouplingBlockOf(P);
  const PetscInt      width = 2 * S.bw + 1;
  std::vector<PetscInt>  cols(width);
  std::vector<PetscReal> vals(width);

  PetscFunctionBeginUser;
  for (PetscInt d = L.D0(); d < L.D1(); ++d) {
    std::map<PetscInt, PetscScalar> row;
    const PetscInt                  ry = L.DofIndex(d, false), rv = L.DofIndex(d, first);
    if (first) {
      PetscScalar v[2] = {0.0, S.held[d] ? 0.0 : -1.0};
      PetscInt    c[2] = {ry, rv};
      PetscCall(MatSetValues(J, 1, &ry, 2, c, v, INSERT_VALUES));
    }
    row[rv] = 0.0;
    if (!damping_only) { // K/m in the position columns
      const PetscInt n = BeamSystemStiffnessRow(S, d, cols.data(), vals.data());
      for (PetscInt q = 0; q < n; ++q) row[L.DofIndex(cols[q], false)] += vals[q] / S.mass[d];
    }
    if (S.Damped() && (first || damping_only)) { // C/m: the velocity columns (first order) or Jd (second order)
      const PetscInt n = BeamSystemDampingRow(S, d, cols.data(), vals.data());
      for (PetscInt q = 0; q < n; ++q) row[L.DofIndex(cols[q], first)] += vals[q] / S.mass[d];
    }
    for (PetscInt p = 0; p < P.g.n; ++p)
      if (P.g.dof[p] == d)
        for (PetscInt q = 0; q < cb.n; ++q) row[cb.cols[q]] += 0.0;
    PetscCall(SetRow(J, rv, row));
  }
  if (L.rank == 0) {
    const PetscInt by = L.BallIndex(0), bv = L.BallIndex(first ? 1 : 0);
    if (first) {
      PetscScalar v[2] = {0.0, -1.0};
      PetscInt    c[2] = {by, bv};
      PetscCall(MatSetValues(J, 1, &by, 2, c, v, INSERT_VALUES));
    }
    std::map<PetscInt, PetscScalar> row;
    row[bv] = 0.0;
    for (PetscInt q = 0; q < cb.n; ++q) row[cb.cols[q]] += 0.0;
    PetscCall(SetRow(J, bv, row));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// J = J0 + shift I + kc g g^T / m: a copy of the constant part (same pattern: a memcpy),
// a diagonal shift, and the contact block (the coupled dofs and the ball) added on the rows
// that own it.
PetscErrorCode AssembleJacobian(TSProblem &P, PetscReal shift, PetscReal shiftV, PetscReal kc)
{
  const TSLayout     &L     = P.L;
  const bool          first = L.dof == 2 * L.fields;
  const CouplingBlock cb    = CouplingBlockOf(P);

  PetscFunctionBeginUser;
  P.count.assembled++;
  PetscCall(MatCopy(P.jac.J0, P.jac.J, SAME_NONZERO_PATTERN));
  if (P.jac.Jd) PetscCall(MatAXPY(P.jac.J, shiftV, P.jac.Jd, SAME_NONZERO_PATTERN));
  PetscCall(MatShift(P.jac.J, shift));
  if (kc != 0.0)
    for (PetscInt p = 0; p < cb.n; ++p) {
      const bool     ball = p == cb.n - 1;
      const PetscInt d    = ball ? -1 : P.g.dof[p];
      if (ball ? L.rank != 0 : !(d / L.fields >= L.xs && d / L.fields < L.xe)) continue;
      if (!ball && P.sys->held[d]) continue;
      const PetscInt  row = ball ? L.BallIndex(first ? 1 : 0) : L.DofIndex(d, first);
      const PetscReal m   = ball ? P.ball.mass : P.sys->mass[d];
      PetscScalar     vals[ContactCoupling::kMaxEntries + 1];
      for (PetscInt q = 0; q < cb.n; ++q) vals[q] = kc * cb.g[p] * cb.g[q] / m;
      PetscCall(MatSetValues(P.jac.J, 1, &row, cb.n, cb.cols, vals, ADD_VALUES));
    }
  PetscCall(MatAssemblyBegin(P.jac.J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P.jac.J, MAT_FINAL_ASSEMBLY));
  P.jac.shift  = shift;
  P.jac.shiftV = shiftV;
  P.jac.kc     = kc;
  PetscFunctionReturn(0);
}

// shiftV matters only with Jd (second order, damped); otherwise it is passed as 0.
PetscErrorCode UpdateJacobian(TSProblem &P, Vec X, PetscReal shift, PetscReal shiftV)
{
  PetscReal kc = 0;

  PetscFunctionBeginUser;
  P.count.jac++;
  if (P.jac.contact && P.contact->phase != ContactPhase::Separated) {
    TSStateRead s;
    PetscReal   c;
    PetscCall(TSStateReadBegin(P.L, X, &s));
    PetscCall(TSCompression(P, s.beam, P.L.dof, s.ball[0], &c));
    PetscCall(TSStateReadEnd(P.L, X, &s));
    kc = ContactStiffness(P.ball, *P.contact, c);
  }
  if (shift != P.jac.shift || kc != P.jac.kc || shiftV != P.jac.shiftV) PetscCall(AssembleJacobian(P, shift, shiftV, kc));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TSIJacobianBeam(TS ts, PetscReal t, Vec U, Vec Udot, PetscReal shift, Mat A, Mat B, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(UpdateJacobian(*static_cast<TSProblem *>(ctx), U, shift, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode TSI2JacobianBeam(TS ts, PetscReal t, Vec X, Vec V, Vec A, PetscReal shiftV, PetscReal shiftA, Mat J, Mat B, void *ctx)
{
  TSProblem &P = *static_cast<TSProblem *>(ctx);

  PetscFunctionBeginUser;
  PetscCall(UpdateJacobian(P, X, shiftA, P.jac.Jd ? shiftV : 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode TSJacobianCreate(TSProblem &P)
{
  Vec      U;
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(P.L.pack, &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecDestroy(&U));
  const bool     vcols = P.sys->Damped() && P.L.dof == 2 * P.L.fields; // first order, damped: K/m also in the velocity columns
  const PetscInt width = (vcols ? 2 : 1) * (2 * P.sys->bw + 1);
  PetscCall(MatCreateAIJ(P.L.comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE, width + 7, NULL, width + 3, NULL, &P.jac.J));
  PetscCall(MatSetOption(P.jac.J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatSetOption(P.jac.J, MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  PetscCall(AssembleConstantPart(P, P.jac.J)); // fixes the pattern (coupling entries as zeros)
  PetscCall(MatDuplicate(P.jac.J, MAT_COPY_VALUES, &P.jac.J0));
  if (P.sys->Damped() && P.L.dof == P.L.fields) { // second order: Jd = C/m on the same pattern
    PetscCall(MatDuplicate(P.jac.J, MAT_DO_NOT_COPY_VALUES, &P.jac.Jd));
    PetscCall(AssembleConstantPart(P, P.jac.Jd, true));
  }
  P.jac.shift = -1; // the first real assembly happens at the first solve
  PetscFunctionReturn(0);
}

PetscErrorCode TSJacobianDestroy(TSProblem &P)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&P.jac.J));
  PetscCall(MatDestroy(&P.jac.J0));
  PetscCall(MatDestroy(&P.jac.Jd));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

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
//
// The program's default solve (PCSHELL, see JacobianCache in ts_problem.hpp) never assembles
// J: the beam's part B is factored once per shift and kept with the context, the contact's
// rank-one term is inverted by Sherman-Morrison, and J is applied as a shell.
#include "solvers/ts_problem.hpp"

#include "solvers/irk_stage_pc.hpp"

#include <petscdm.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>

namespace beamimpact {

namespace {

// The LU's solver type on size ranks (nullptr: none given): SuperLU_DIST on more than one rank
// refused (the reason below).
PetscErrorCode SuperluDistCheck(MPI_Comm comm, PetscMPIInt size, const char *type)
{
  PetscFunctionBeginUser;
  PetscCheck(size == 1 || !type || std::string(type) != MATSOLVERSUPERLU_DIST, comm, PETSC_ERR_SUP,
             "-pc_factor_mat_solver_type superlu_dist is refused on %d ranks: PETSc 3.18's SuperLU_DIST interface "
             "frees its process grid twice and corrupts the heap; use mumps (the default on more than one rank) or "
             "superlu_dist on one rank",
             (int)size);
  PetscFunctionReturn(0);
}

// The LU of a Jacobian: -pc_factor_mat_ordering_type and -pc_factor_mat_solver_type read (mumps
// on more than one rank unless another is given). SuperLU_DIST on more than one rank is refused:
// PETSc 3.18's interface frees its process grid twice when the factor and then the DM's
// communicator are destroyed (valgrind: superlu_gridexit from MatDestroy, then again from
// Petsc_Superlu_dist_keyval_Delete_Fn), which corrupted the heap and aborted the run after it.
PetscErrorCode JacobianLUSetUp(PC pc, PetscMPIInt size)
{
  MatSolverType type = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PCSetType(pc, PCLU));
  if (size > 1) PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCall(PCSetFromOptions(pc));
  PetscCall(PCFactorGetMatSolverType(pc, &type));
  PetscCall(SuperluDistCheck(PetscObjectComm((PetscObject)pc), size, type));
  PetscFunctionReturn(0);
}

// The LU options as the program's own factor will read them at its first solve (JacobianLUSetUp,
// after the set-up's check of unused options): read now, so that they count as used, and
// superlu_dist on more than one rank refused before any step.
PetscErrorCode JacobianLUOptionsRead(MPI_Comm comm, PetscMPIInt size)
{
  char      type[64] = "", ordering[64] = "";
  PetscBool given;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-pc_factor_mat_ordering_type", ordering, sizeof ordering, &given));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-pc_factor_mat_solver_type", type, sizeof type, &given));
  PetscCall(SuperluDistCheck(comm, size, given ? type : nullptr));
  PetscFunctionReturn(0);
}

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
// pattern and the diagonal). Without coupling: no contact entries (B0, Bd of the rank-one
// path, whose pattern does not depend on the contact point).
PetscErrorCode AssembleConstantPart(TSProblem &P, Mat J, bool damping_only = false, bool coupling = true)
{
  const BeamSystem      &S     = *P.sys;
  const TSLayout        &L     = P.L;
  const bool             first = L.dof == 2 * L.fields;
  const CouplingBlock    cb    = CouplingBlockOf(P);
  const PetscInt         width = 2 * S.bw + 1;
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
    for (PetscInt p = 0; coupling && p < P.g.n; ++p)
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
    for (PetscInt q = 0; coupling && q < cb.n; ++q) row[cb.cols[q]] += 0.0;
    PetscCall(SetRow(J, bv, row));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// J = J0 + shift I (+ shiftV Jd) + kc g g^T / m: a copy of the constant part (same pattern: a
// memcpy), a diagonal shift, and the contact block (the coupled dofs and the ball) added on the
// rows that own it.
PetscErrorCode AssembleShifted(TSProblem &P, Mat J, Mat J0, Mat Jd, PetscReal shift, PetscReal shiftV, PetscReal kc)
{
  const TSLayout     &L     = P.L;
  const bool          first = L.dof == 2 * L.fields;
  const CouplingBlock cb    = CouplingBlockOf(P);

  PetscFunctionBeginUser;
  PetscCall(MatCopy(J0, J, SAME_NONZERO_PATTERN));
  if (Jd) PetscCall(MatAXPY(J, shiftV, Jd, SAME_NONZERO_PATTERN));
  PetscCall(MatShift(J, shift));
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
      PetscCall(MatSetValues(J, 1, &row, cb.n, cb.cols, vals, ADD_VALUES));
    }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// The assembled path's J (-pc_type lu and others).
PetscErrorCode AssembleJacobian(TSProblem &P, PetscReal shift, PetscReal shiftV, PetscReal kc)
{
  PetscFunctionBeginUser;
  P.count.assembled++;
  PetscCall(AssembleShifted(P, P.jac.J, P.jac.J0, P.jac.Jd, shift, shiftV, kc));
  P.jac.shift  = shift;
  P.jac.shiftV = shiftV;
  P.jac.kc     = kc;
  PetscFunctionReturn(0);
}

// J's storage with its final pattern (the coupling entries as zeros), J0 its constant part and,
// second order and damped, Jd = C/m on the same pattern.
PetscErrorCode CreateAssembled(TSProblem &P, Mat *J, Mat *J0, Mat *Jd)
{
  Vec      U;
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(P.L.pack, &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecDestroy(&U));
  const bool vcols = P.sys->Damped() &&
                     P.L.dof == 2 * P.L.fields; // first order, damped: K/m also in the velocity columns
  const PetscInt width = (vcols ? 2 : 1) * (2 * P.sys->bw + 1);
  PetscCall(MatCreateAIJ(P.L.comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE, width + 7, NULL, width + 3, NULL, J));
  PetscCall(MatSetOption(*J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatSetOption(*J, MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  PetscCall(AssembleConstantPart(P, *J)); // fixes the pattern (coupling entries as zeros)
  PetscCall(MatDuplicate(*J, MAT_COPY_VALUES, J0));
  if (P.sys->Damped() && P.L.dof == P.L.fields) { // second order: Jd = C/m on the same pattern
    PetscCall(MatDuplicate(*J, MAT_DO_NOT_COPY_VALUES, Jd));
    PetscCall(AssembleConstantPart(P, *Jd, true));
  }
  PetscFunctionReturn(0);
}

// --- The rank-one path -------------------------------------------------------------------

constexpr size_t kBeamFactors     = 4; // shifts kept: the nominal step's and the event location's
PetscInt         n_factorizations = 0;

// v^T x over v's few entries (the coupled dofs and the ball), summed over ranks.
PetscErrorCode CouplingDot(const TSProblem &P, Vec x, PetscReal *dot)
{
  const PetscScalar *a;
  PetscReal          s = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(x, &a));
  for (size_t q = 0; q < P.jac.v_idx.size(); ++q) s += P.jac.v_val[q] * a[P.jac.v_idx[q]];
  PetscCall(VecRestoreArrayRead(x, &a));
  if (P.L.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPIU_REAL, MPIU_SUM, P.L.comm));
  *dot = s;
  PetscFunctionReturn(0);
}

// v^T x as CouplingDot, and whether every entry of x is finite (a scan of the owned entries),
// in one reduction.
PetscErrorCode CouplingDotFinite(const TSProblem &P, Vec x, PetscReal *dot, bool *finite)
{
  const PetscScalar *a;
  PetscInt           n;
  PetscReal          s[2] = {0, 0}; // the dot product, the ranks with a non-finite entry

  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &a));
  for (size_t q = 0; q < P.jac.v_idx.size(); ++q) s[0] += P.jac.v_val[q] * a[P.jac.v_idx[q]];
  for (PetscInt i = 0; i < n; ++i)
    if (!std::isfinite(a[i])) {
      s[1] = 1;
      break;
    }
  PetscCall(VecRestoreArrayRead(x, &a));
  if (P.L.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s, 2, MPIU_REAL, MPIU_SUM, P.L.comm));
  *dot    = s[0];
  *finite = s[1] == 0;
  PetscFunctionReturn(0);
}

// u = D^-1 g on the rows of the coupled dofs and the ball (velocity rows in first-order form;
// none on a held dof), v = g on their position columns; a new point's generation.
PetscErrorCode SetCouplingVectors(TSProblem &P)
{
  const TSLayout     &L     = P.L;
  const bool          first = L.dof == 2 * L.fields;
  const CouplingBlock cb    = CouplingBlockOf(P);

  PetscFunctionBeginUser;
  if (!P.jac.u) {
    PetscCall(DMCreateGlobalVector(L.pack, &P.jac.u));
    PetscCall(VecDuplicate(P.jac.u, &P.jac.v));
  }
  PetscCall(VecZeroEntries(P.jac.u));
  PetscCall(VecZeroEntries(P.jac.v));
  for (PetscInt p = 0; p < cb.n; ++p) {
    const bool     ball = p == cb.n - 1;
    const PetscInt d    = ball ? -1 : P.g.dof[p];
    if (ball ? L.rank != 0 : !(d / L.fields >= L.xs && d / L.fields < L.xe)) continue;
    PetscCall(VecSetValue(P.jac.v, cb.cols[p], cb.g[p], ADD_VALUES));
    if (!ball && P.sys->held[d]) continue;
    const PetscInt  row = ball ? L.BallIndex(first ? 1 : 0) : L.DofIndex(d, first);
    const PetscReal m   = ball ? P.ball.mass : P.sys->mass[d];
    PetscCall(VecSetValue(P.jac.u, row, cb.g[p] / m, ADD_VALUES));
  }
  for (Vec x : {P.jac.u, P.jac.v}) {
    PetscCall(VecAssemblyBegin(x));
    PetscCall(VecAssemblyEnd(x));
  }
  { // v's owned entries, for CouplingDot
    const PetscScalar *a;
    PetscInt           lo, hi;
    P.jac.v_idx.clear();
    P.jac.v_val.clear();
    PetscCall(VecGetOwnershipRange(P.jac.v, &lo, &hi));
    PetscCall(VecGetArrayRead(P.jac.v, &a));
    for (PetscInt p = 0; p < cb.n; ++p)
      if (cb.cols[p] >= lo && cb.cols[p] < hi && a[cb.cols[p] - lo] != 0.0 &&
          std::find(P.jac.v_idx.begin(), P.jac.v_idx.end(), cb.cols[p] - lo) == P.jac.v_idx.end()) {
        P.jac.v_idx.push_back(cb.cols[p] - lo);
        P.jac.v_val.push_back(a[cb.cols[p] - lo]);
      }
    PetscCall(VecRestoreArrayRead(P.jac.v, &a));
  }
  P.jac.point++;
  for (BeamFactor &f : P.jac.factors) f.used /= 2; // uses by recent points count most
  P.jac.shift = P.jac.kc = P.jac.shiftV = -1;      // the first Jacobian of the run is counted, as on a fresh TS
  P.jac.current                         = nullptr;
  PetscFunctionReturn(0);
}

// The factor of B at (shift, shiftV): kept, or assembled and factored in the least recently
// used slot; with w = B^-1 u for the current point.
PetscErrorCode BeamFactorAt(TSProblem &P, PetscReal shift, PetscReal shiftV, BeamFactor **out)
{
  JacobianCache &jac = P.jac;
  BeamFactor    *f   = nullptr;

  PetscFunctionBeginUser;
  for (BeamFactor &c : jac.factors)
    if (c.shift == shift && c.shiftV == shiftV) f = &c;
  if (!f) {
    jac.factors.reserve(kBeamFactors); // (no reallocation: `current` points into it)
    if (jac.factors.size() < kBeamFactors) jac.factors.emplace_back();
    f = &jac.factors.front(); // the least used (the nominal step's stays; event-location steps are one-off)
    for (BeamFactor &c : jac.factors)
      if (c.used < f->used) f = &c;
    f->used = 0;
    if (!f->B) {
      PetscCall(MatDuplicate(jac.B0, MAT_COPY_VALUES, &f->B));
      PetscCall(KSPCreate(P.L.comm, &f->ksp));
      PetscCall(KSPSetType(f->ksp, KSPPREONLY));
      PC pc;
      PetscCall(KSPGetPC(f->ksp, &pc));
      PetscCall(JacobianLUSetUp(pc, P.L.size));
      PetscCall(VecDuplicate(jac.u, &f->w));
    } else PetscCall(MatCopy(jac.B0, f->B, SAME_NONZERO_PATTERN));
    if (jac.Bd) PetscCall(MatAXPY(f->B, shiftV, jac.Bd, SAME_NONZERO_PATTERN));
    PetscCall(MatShift(f->B, shift));
    PetscCall(KSPSetOperators(f->ksp, f->B, f->B));
    PetscCall(KSPSetUp(f->ksp)); // the LU
    f->shift  = shift;
    f->shiftV = shiftV;
    f->point  = -1;
    jac.factored++;
    n_factorizations++;
  }
  if (f->point != jac.point) {
    PetscCall(KSPSolve(f->ksp, jac.u, f->w));
    PetscCall(CouplingDotFinite(P, f->w, &f->vw, &f->finite));
    f->point = jac.point;
  }
  f->used++;
  *out = f;
  PetscFunctionReturn(0);
}

// J x = B x + kc u (v^T x).
PetscErrorCode RankOneMult(Mat J, Vec x, Vec y)
{
  TSProblem *P;
  PetscReal  s;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(J, &P));
  PetscCall(MatMult(P->jac.current->B, x, y));
  if (P->jac.kc != 0.0) {
    PetscCall(CouplingDot(*P, x, &s));
    PetscCall(VecAXPY(y, P->jac.kc * s, P->jac.u));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FallbackDestroy(AssembledFallback &F)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&F.J));
  PetscCall(MatDestroy(&F.J0));
  PetscCall(MatDestroy(&F.Jd));
  PetscCall(KSPDestroy(&F.ksp));
  F = AssembledFallback();
  PetscFunctionReturn(0);
}

// z = J^-1 b with the assembled J at the current (shift, kc), LU-factored when they changed:
// PETSc's own path (-pc_type lu), for a solve the rank-one formula could not do (`why`). Said
// once per context; each such solve in -info.
PetscErrorCode AssembledFallbackSolve(TSProblem &P, Vec b, Vec z, const char *why)
{
  AssembledFallback &F = P.jac.fallback;

  PetscFunctionBeginUser;
  if (!F.J) {
    PetscCall(CreateAssembled(P, &F.J, &F.J0, &F.Jd));
    PetscCall(KSPCreate(P.L.comm, &F.ksp));
    PetscCall(KSPSetType(F.ksp, KSPPREONLY));
    PC pc;
    PetscCall(KSPGetPC(F.ksp, &pc));
    PetscCall(JacobianLUSetUp(pc, P.L.size));
  }
  if (F.shift != P.jac.shift || F.shiftV != P.jac.shiftV || F.kc != P.jac.kc) {
    PetscCall(AssembleShifted(P, F.J, F.J0, F.Jd, P.jac.shift, P.jac.shiftV, P.jac.kc));
    PetscCall(KSPSetOperators(F.ksp, F.J, F.J));
    PetscCall(KSPSetUp(F.ksp)); // the LU
    F.shift  = P.jac.shift;
    F.shiftV = P.jac.shiftV;
    F.kc     = P.jac.kc;
  }
  PetscCall(KSPSolve(F.ksp, b, z));
  if (P.jac.fallbacks++ == 0)
    PetscCall(PetscPrintf(P.L.comm,
                          "note: the rank-one solve of the Jacobian (the beam's LU kept, the contact by "
                          "Sherman-Morrison) broke down: %s; that solve, and any other where it breaks down, used the "
                          "assembled LU (-pc_type lu does every solve so)\n",
                          why));
  PetscCall(PetscInfo(NULL, "rank-one solve broke down (%s): the assembled LU at shift %g, kc %g N/m\n", why,
                      (double)P.jac.shift, (double)P.jac.kc));
  PetscFunctionReturn(0);
}

// z = J^-1 b by Sherman-Morrison on B's factor: z = B^-1 b - kc w (v^T B^-1 b) / (1 + kc v^T w),
// or by the assembled J where that step cannot be trusted (B^-1 b or w not finite, the
// denominator not finite or cancelling: RankOneDenominator).
PetscErrorCode RankOneApply(PC pc, Vec b, Vec z)
{
  TSProblem *P;
  PetscReal  a, den;
  bool       finite;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &P));
  const BeamFactor &f = *P->jac.current;
  PetscCall(KSPSolve(f.ksp, b, z));
  if (P->jac.kc == 0.0) PetscFunctionReturn(0); // J = B
  PetscCall(CouplingDotFinite(*P, z, &a, &finite));
  if (finite && f.finite && RankOneDenominator(P->jac.kc, f.vw, &den)) {
    PetscCall(VecAXPY(z, -P->jac.kc * a / den, f.w));
    PetscFunctionReturn(0);
  }
  char why[160]; // (std::snprintf: PETSc's %g would write 0 as "0.")
  if (!f.finite || !finite)
    std::snprintf(why, sizeof why, "B^-1 %s is not finite (the beam's factor at shift %g)", f.finite ? "b" : "u",
                  (double)P->jac.shift);
  else
    std::snprintf(why, sizeof why, "1 + kc v^T B^-1 u = %g with kc = %g N/m, v^T B^-1 u = %g",
                  (double)(1 + P->jac.kc * f.vw), (double)P->jac.kc, (double)f.vw);
  PetscCall(AssembledFallbackSolve(*P, b, z, why));
  PetscFunctionReturn(0);
}

// shiftV matters only with Jd (second order, damped); otherwise it is passed as 0. The count
// of assemblies is of changes of J (the assembled path's LU), in either path.
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
  if (shift == P.jac.shift && kc == P.jac.kc && shiftV == P.jac.shiftV) PetscFunctionReturn(0);
  if (!P.jac.rank_one) PetscFunctionReturn(AssembleJacobian(P, shift, shiftV, kc));
  P.count.assembled++;
  if (shift != P.jac.shift || shiftV != P.jac.shiftV || !P.jac.current)
    PetscCall(BeamFactorAt(P, shift, shiftV, &P.jac.current));
  P.jac.shift  = shift;
  P.jac.shiftV = shiftV;
  P.jac.kc     = kc;
  PetscFunctionReturn(0);
}

PetscErrorCode SetJacobianOnTS(TSProblem &P, TS ts)
{
  PetscFunctionBeginUser;
  if (P.form == Formulation::SecondOrder) PetscCall(TSSetI2Jacobian(ts, P.jac.J, P.jac.J, TSI2JacobianBeam, &P));
  else PetscCall(TSSetIJacobian(ts, P.jac.J, P.jac.J, TSIJacobianBeam, &P));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TSIJacobianBeam(TS ts, PetscReal t, Vec U, Vec Udot, PetscReal shift, Mat A, Mat B, void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(UpdateJacobian(*static_cast<TSProblem *>(ctx), U, shift, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode TSI2JacobianBeam(TS ts, PetscReal t, Vec X, Vec V, Vec A, PetscReal shiftV, PetscReal shiftA, Mat J,
                                Mat B, void *ctx)
{
  TSProblem &P = *static_cast<TSProblem *>(ctx);

  PetscFunctionBeginUser;
  PetscCall(
    UpdateJacobian(P, X, shiftA, P.jac.Jd || P.jac.Bd ? shiftV : 0.0)); // Jd: the assembled path, Bd: the rank-one path
  PetscFunctionReturn(0);
}

PetscErrorCode TSJacobianCreate(TSProblem &P)
{
  PetscFunctionBeginUser;
  PetscCall(CreateAssembled(P, &P.jac.J, &P.jac.J0, &P.jac.Jd));
  P.jac.shift = -1; // the first real assembly happens at the first solve
  PetscFunctionReturn(0);
}

PetscErrorCode TSJacobianDestroy(TSProblem &P)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&P.jac.J));
  PetscCall(MatDestroy(&P.jac.J0));
  PetscCall(MatDestroy(&P.jac.Jd));
  for (BeamFactor &f : P.jac.factors) {
    PetscCall(MatDestroy(&f.B));
    PetscCall(KSPDestroy(&f.ksp));
    PetscCall(VecDestroy(&f.w));
  }
  P.jac.factors.clear();
  P.jac.current = nullptr;
  PetscCall(FallbackDestroy(P.jac.fallback));
  PetscCall(MatDestroy(&P.jac.B0));
  PetscCall(MatDestroy(&P.jac.Bd));
  PetscCall(VecDestroy(&P.jac.u));
  PetscCall(VecDestroy(&P.jac.v));
  PetscFunctionReturn(0);
}

PetscInt TSJacobianFactorizations() { return n_factorizations; }

bool RankOneDenominator(PetscReal kc, PetscReal vw, PetscReal *den)
{
  *den = 1 + kc * vw;
  return std::isfinite(kc) && std::isfinite(*den) && std::abs(*den) > kRankOneCancellation * (1 + std::abs(kc * vw));
}

namespace {

// What B0 and Bd are made of (the stiffness band, the masses, the held dofs, the damping rows):
// a 64-bit FNV-1a hash over their bytes, O(N) a point. A context serves one grid and type, but a
// sweep may change the beam's values on it (its thickness, material, supports).
std::uint64_t StructureFingerprint(const TSProblem &P)
{
  const BeamSystem &S   = *P.sys;
  std::uint64_t     h   = 1469598103934665603ull;
  auto              add = [&h](const void *p, size_t n) {
    const unsigned char *b = static_cast<const unsigned char *>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  add(S.band.data(), S.band.size() * sizeof(PetscReal));
  add(S.mass.data(), S.mass.size() * sizeof(PetscReal));
  add(S.held.data(), S.held.size());
  if (S.Damped()) {
    std::vector<PetscInt>  cols(2 * S.bw + 1);
    std::vector<PetscReal> vals(2 * S.bw + 1);
    for (PetscInt d = P.L.D0(); d < P.L.D1(); ++d) {
      const PetscInt m = BeamSystemDampingRow(S, d, cols.data(), vals.data());
      add(cols.data(), m * sizeof(PetscInt));
      add(vals.data(), m * sizeof(PetscReal));
    }
  }
  return h;
}

// B0 (and Bd, second order damped) of the structure, without the coupling entries; the factors
// of another structure's B dropped.
PetscErrorCode BuildBeamPart(TSProblem &P)
{
  Vec      U;
  PetscInt n;

  PetscFunctionBeginUser;
  for (BeamFactor &f : P.jac.factors) {
    PetscCall(MatDestroy(&f.B));
    PetscCall(KSPDestroy(&f.ksp));
    PetscCall(VecDestroy(&f.w));
  }
  P.jac.factors.clear();
  P.jac.current = nullptr;
  PetscCall(MatDestroy(&P.jac.B0));
  PetscCall(MatDestroy(&P.jac.Bd));
  PetscCall(DMCreateGlobalVector(P.L.pack, &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecDestroy(&U));
  const bool     vcols = P.sys->Damped() && P.L.dof == 2 * P.L.fields;
  const PetscInt width = (vcols ? 2 : 1) * (2 * P.sys->bw + 1);
  PetscCall(
    MatCreateAIJ(P.L.comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE, width + 3, NULL, width + 3, NULL, &P.jac.B0));
  PetscCall(MatSetOption(P.jac.B0, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatSetOption(P.jac.B0, MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  PetscCall(AssembleConstantPart(P, P.jac.B0, false, false));
  if (P.sys->Damped() && P.L.dof == P.L.fields) {
    PetscCall(MatDuplicate(P.jac.B0, MAT_DO_NOT_COPY_VALUES, &P.jac.Bd));
    PetscCall(AssembleConstantPart(P, P.jac.Bd, true, false));
  }
  P.jac.structure = StructureFingerprint(P);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TSJacobianSetDefaultPC(TSProblem &P, PC pc)
{
  PetscFunctionBeginUser;
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, &P));
  PetscCall(PCShellSetApply(pc, RankOneApply));
  PetscCall(PCShellSetName(pc, "rank-one: the beam's LU kept per shift, the contact by Sherman-Morrison"));
  PetscFunctionReturn(0);
}

// After the options: the rank-one path if the preconditioner is still the program's shell
// (B0, Bd without the coupling entries; J a shell), else (and for irk) the assembled J.
PetscErrorCode TSJacobianInstall(TSProblem &P, TS ts)
{
  SNES      snes;
  KSP       ksp;
  PC        pc;
  PetscBool shell, irk;

  PetscFunctionBeginUser;
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCSHELL, &shell));
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, TSIRK, &irk));
  P.jac.rank_one = shell && !irk; // irk's shell is the stage LU (irk_stage_pc.hpp), built from the assembled J
  if (P.jac.rank_one) PetscCall(JacobianLUOptionsRead(P.L.comm, P.L.size)); // the program's LU, at its first solve
  if (!P.jac.rank_one) {
    PetscCall(TSJacobianCreate(P));
    PetscCall(SetJacobianOnTS(P, ts));
    PetscFunctionReturn(0);
  }
  Vec      U;
  PetscInt n, N;
  PetscCall(DMCreateGlobalVector(P.L.pack, &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecGetSize(U, &N));
  PetscCall(VecDestroy(&U));
  PetscCall(BuildBeamPart(P));
  PetscCall(MatCreateShell(P.L.comm, n, n, N, N, &P, &P.jac.J));
  PetscCall(MatShellSetOperation(P.jac.J, MATOP_MULT, (void (*)(void))RankOneMult));
  PetscCall(SetCouplingVectors(P));
  PetscCall(SetJacobianOnTS(P, ts));
  PetscFunctionReturn(0);
}

// A reused context's next point: the rank-one path keeps B0 and the factors (u, v and the w's
// anew); the assembled path rebuilds J for the new contact point's pattern.
PetscErrorCode TSJacobianNewPoint(TSProblem &P, TS ts)
{
  PetscFunctionBeginUser;
  if (P.jac.rank_one) {
    if (StructureFingerprint(P) != P.jac.structure)
      PetscCall(BuildBeamPart(P));              // another beam on the same grid: its own factors
    PetscCall(FallbackDestroy(P.jac.fallback)); // its pattern holds the last point
    PetscCall(SetCouplingVectors(P));
    PetscFunctionReturn(0);
  }
  PetscCall(TSJacobianDestroy(P));
  const bool contact = P.jac.contact;
  P.jac              = JacobianCache();
  P.jac.contact      = contact;
  PetscCall(TSJacobianCreate(P));
  PetscCall(SetJacobianOnTS(P, ts));
  PetscCall(IrkStageNewJacobian(ts, P.jac.J)); // -ts_type irk: its stage matrix over the new J
  PetscFunctionReturn(0);
}

} // namespace beamimpact

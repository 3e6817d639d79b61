// The stage-system LU of -ts_type irk (irk_stage_pc.hpp).
#include "solvers/irk_stage_pc.hpp"

#include <petscdm.h>
#include <petsc/private/tsimpl.h> // ts->data: TSIRK's stage vector (IrkStageLayout)

#include <algorithm>
#include <cstring>
#include <vector>

namespace beamimpact {

namespace {

PetscInt n_factorizations = 0;

// The PC's state: the stage matrix A, its LU, and what A was built from: J (its id and nonzero
// state; its values are J0 + shift I + the contact's kc block, so the values of (shift, shiftV,
// kc) it was assembled at, ts_jacobian.cpp) and S and T as the KAIJ held them.
struct IrkStagePC {
  TSProblem               *P        = nullptr;
  Mat                      A        = nullptr; // (s n) x (s n), AIJ
  KSP                      ksp      = nullptr; // preonly + LU of A
  PetscObjectId            jid      = 0;       // the J A was built from (P.jac.J)
  PetscObjectState         jnonzero = -1;
  PetscReal                shift = -1, shiftV = -1, kc = -1; // what J held
  PetscInt                 s  = 0;
  bool                     tI = true; // T is the identity
  std::vector<PetscScalar> S, T;      // s x s, column-major
};

// The KAIJ's S and T (T empty: the identity), and whether they differ from what A holds;
// compared in place, copied only when they changed (this runs at every PC apply).
PetscErrorCode ReadShifts(IrkStagePC &c, Mat K, bool *changed)
{
  const PetscScalar *S, *T;
  PetscInt           p, q;

  PetscFunctionBeginUser;
  PetscCall(MatKAIJGetSRead(K, &p, &q, &S));
  PetscCheck(p == q && p > 0 && S, PetscObjectComm((PetscObject)K), PETSC_ERR_SUP,
             "-ts_type irk: the stage matrix's shift block is %" PetscInt_FMT " x %" PetscInt_FMT
             ", expected s x s with s = -ts_irk_nstages",
             p, q);
  const size_t n      = (size_t)(p * q);
  const bool   s_same = p == c.s && c.S.size() == n && std::equal(S, S + n, c.S.begin());
  if (!s_same) c.S.assign(S, S + n);
  PetscCall(MatKAIJRestoreSRead(K, &S));
  PetscCall(MatKAIJGetTRead(K, NULL, NULL, &T));
  bool identity = true;
  if (T)
    for (PetscInt i = 0; i < p; ++i)
      for (PetscInt j = 0; j < p; ++j) identity = identity && T[i + p * j] == (i == j ? 1.0 : 0.0);
  const bool t_same = identity ? c.T.empty() : c.T.size() == n && std::equal(T, T + n, c.T.begin());
  if (!t_same) {
    if (identity) c.T.clear();
    else c.T.assign(T, T + n);
  }
  PetscCall(MatKAIJRestoreTRead(K, &T));
  *changed = !s_same || !t_same;
  c.s      = p;
  c.tI     = identity;
  PetscFunctionReturn(0);
}

// A with its pattern from J's rows (J's columns c s + j of each stage row, and the stage
// coupling r s + j) and the LU's solver.
PetscErrorCode CreateStageMatrix(IrkStagePC &c, Mat J)
{
  PetscInt        rs, re, N, nc;
  const PetscInt *cols;
  const PetscInt  s = c.s, width = c.tI ? 1 : s; // stage columns per column of J

  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&c.A));
  PetscCall(MatGetOwnershipRange(J, &rs, &re));
  PetscCall(MatGetSize(J, &N, NULL));
  std::vector<PetscInt> d((re - rs) * s), o((re - rs) * s);
  for (PetscInt r = rs; r < re; ++r) {
    PetscInt nd = 0;
    PetscCall(MatGetRow(J, r, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc; ++k) nd += cols[k] >= rs && cols[k] < re;
    for (PetscInt i = 0; i < s; ++i) {
      d[(r - rs) * s + i] = std::min(nd * width + s, (re - rs) * s);
      o[(r - rs) * s + i] = (nc - nd) * width;
    }
    PetscCall(MatRestoreRow(J, r, &nc, &cols, NULL));
  }
  PetscCall(MatCreateAIJ(PetscObjectComm((PetscObject)J), (re - rs) * s, (re - rs) * s, N * s, N * s, 0, d.data(), 0,
                         o.data(), &c.A));
  if (!c.ksp) {
    PC          pc;
    PetscMPIInt size;
    PetscCall(KSPCreate(PetscObjectComm((PetscObject)J), &c.ksp));
    PetscCall(KSPSetType(c.ksp, KSPPREONLY));
    PetscCall(KSPGetPC(c.ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)J), &size));
    if (size > 1) PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }
  PetscFunctionReturn(0);
}

// A's entries from J, S and T (IrkStageEntry), then its LU; *ok false when the factorization
// failed (a zero pivot, MUMPS' INFOG(1) < 0: PETSc records it on the PC, it does not raise).
PetscErrorCode FillAndFactor(IrkStagePC &c, Mat J, bool *ok)
{
  PetscInt                 rs, re, nc;
  const PetscInt          *cols;
  const PetscScalar       *vals;
  const PetscInt           s = c.s;
  const PetscScalar       *T = c.tI ? nullptr : c.T.data();
  std::vector<PetscInt>    ac;
  std::vector<PetscScalar> av;

  PetscFunctionBeginUser;
  PetscCall(MatZeroEntries(c.A));
  PetscCall(MatGetOwnershipRange(J, &rs, &re));
  for (PetscInt r = rs; r < re; ++r) {
    PetscCall(MatGetRow(J, r, &nc, &cols, &vals));
    for (PetscInt i = 0; i < s; ++i) {
      const PetscInt row = r * s + i;
      ac.clear();
      av.clear();
      for (PetscInt k = 0; k < nc; ++k)
        for (PetscInt j = c.tI ? i : 0; j < (c.tI ? i + 1 : s); ++j) {
          ac.push_back(cols[k] * s + j);
          av.push_back(IrkStageEntry(s, c.S.data(), T, i, j, vals[k], false));
        }
      for (PetscInt j = 0; j < s; ++j) { // the diagonal block's shift (J's own part added above)
        ac.push_back(r * s + j);
        av.push_back(IrkStageEntry(s, c.S.data(), T, i, j, 0.0, true));
      }
      PetscCall(MatSetValues(c.A, 1, &row, (PetscInt)ac.size(), ac.data(), av.data(), ADD_VALUES));
    }
    PetscCall(MatRestoreRow(J, r, &nc, &cols, &vals));
  }
  PetscCall(MatAssemblyBegin(c.A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(c.A, MAT_FINAL_ASSEMBLY));
  PetscCall(KSPSetOperators(c.ksp, c.A, c.A));
  PetscCall(KSPSetUp(c.ksp)); // the LU
  n_factorizations++;
  PC             lu;
  PCFailedReason failed;
  PetscCall(KSPGetPC(c.ksp, &lu));
  PetscCall(PCGetFailedReason(lu, &failed));
  *ok = failed == PC_NOERROR;
  PetscFunctionReturn(0);
}

// A and its LU for the KAIJ the outer KSP holds now: rebuilt when J is another matrix or
// its pattern changed, refilled and refactored when J's values, S or T changed. A failed
// factorization is not remembered as current: the next application factors again.
PetscErrorCode StageUpdate(PC pc, IrkStagePC &c)
{
  const JacobianCache &jac = c.P->jac;
  Mat                  K, J = jac.J;
  PetscBool            kaij;
  PetscObjectId        id;
  PetscObjectState     nz;
  bool                 shifts = true;

  PetscFunctionBeginUser;
  PetscCall(PCGetOperators(pc, NULL, &K));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)K, &kaij, MATSEQKAIJ, MATMPIKAIJ, ""));
  PetscCheck(kaij && J && !jac.rank_one, PetscObjectComm((PetscObject)pc), PETSC_ERR_SUP,
             "the irk stage preconditioner needs TSIRK's KAIJ stage matrix and the assembled Jacobian (-ts_type irk)");
  const PetscInt s0  = c.s;
  const bool     tI0 = c.tI;
  PetscCall(ReadShifts(c, K, &shifts));
  PetscCall(PetscObjectGetId((PetscObject)J, &id));
  PetscCall(MatGetNonzeroState(J, &nz));
  const bool values = jac.shift != c.shift || jac.shiftV != c.shiftV || jac.kc != c.kc;
  if (!c.A || id != c.jid || nz != c.jnonzero || c.s != s0 || c.tI != tI0) PetscCall(CreateStageMatrix(c, J));
  else if (!values && !shifts) PetscFunctionReturn(0);
  bool ok = false;
  PetscCall(FillAndFactor(c, J, &ok));
  if (!ok) {
    c.jid = 0;
    PetscFunctionReturn(0);
  }
  c.jid      = id;
  c.jnonzero = nz;
  c.shift    = jac.shift;
  c.shiftV   = jac.shiftV;
  c.kc       = jac.kc;
  PetscFunctionReturn(0);
}

PetscErrorCode StageApply(PC pc, Vec x, Vec y)
{
  IrkStagePC *c;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &c));
  PetscCall(StageUpdate(pc, *c));
  PetscCall(KSPSolve(c->ksp, x, y));
  PetscCall(
    KSPCheckSolve(c->ksp, pc, y)); // a failed LU: the PC marked failed and y Inf, so the outer KSP and SNES stop on it
  PetscFunctionReturn(0);
}

PetscErrorCode StageDestroy(PC pc)
{
  IrkStagePC *c;

  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &c));
  PetscCall(MatDestroy(&c->A));
  PetscCall(KSPDestroy(&c->ksp));
  delete c;
  PetscFunctionReturn(0);
}

} // namespace

PetscScalar IrkStageEntry(PetscInt s, const PetscScalar *S, const PetscScalar *T, PetscInt i, PetscInt j,
                          PetscScalar Jrc, bool diagonal)
{
  const PetscScalar t = T ? T[i + s * j] : (i == j ? 1.0 : 0.0);
  return Jrc * t + (diagonal ? S[i + s * j] : 0.0);
}

PetscErrorCode IrkStagePCSet(TSProblem &P, PC pc)
{
  PetscFunctionBeginUser;
  PetscCall(PCSetType(pc, PCSHELL));
  IrkStagePC *c = new IrkStagePC;
  c->P          = &P;
  PetscCall(PCShellSetContext(pc, c));
  PetscCall(PCShellSetApply(pc, StageApply));
  PetscCall(PCShellSetDestroy(pc, StageDestroy));
  PetscCall(PCShellSetName(pc, "irk stages: the (s n) x (s n) stage matrix assembled from J and factored (LU; MUMPS on "
                               "more than one rank)"));
  PetscFunctionReturn(0);
}

namespace {

// TSIRK's Jacobian (SNESTSFormJacobian: J at the last stage, then S = A^-1/dt written into the
// KAIJ), and then, on more than one rank, J's state bumped by a (no-op) assembly: PETSc 3.18's
// MPIKAIJ multiplies by copies of S in its per-rank blocks, rebuilt only when J's state changes,
// so a new step size with an unchanged J (event location in a linear contact) kept the old S
// and GMRES took 13-18 iterations against the exact preconditioner.
PetscErrorCode IrkFormJacobian(SNES snes, Vec Z, Mat K, Mat Kp, void *ctx)
{
  PetscMPIInt size;
  Mat         J;

  PetscFunctionBeginUser;
  PetscCall(SNESTSFormJacobian(snes, Z, K, Kp, ctx));
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)K), &size));
  if (size == 1) PetscFunctionReturn(0);
  PetscCall(MatKAIJGetAIJ(K, &J));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode IrkStageAfterSetUp(TS ts)
{
  SNES      snes;
  Mat       K;
  PetscBool irk, kaij;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, TSIRK, &irk));
  if (!irk) PetscFunctionReturn(0);
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetJacobian(snes, &K, NULL, NULL, NULL));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)K, &kaij, MATSEQKAIJ, MATMPIKAIJ, ""));
  PetscCheck(kaij, PetscObjectComm((PetscObject)ts), PETSC_ERR_PLIB,
             "-ts_type irk: after its set-up the Newton solver's matrix is not TSIRK's KAIJ stage matrix");
  PetscCall(SNESSetJacobian(snes, K, K, IrkFormJacobian, ts));
  PetscFunctionReturn(0);
}

PetscErrorCode IrkStageNewJacobian(TS ts, Mat J)
{
  SNES      snes;
  Mat       K;
  PetscBool irk;
  PetscInt  s;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, TSIRK, &irk));
  if (!irk) PetscFunctionReturn(0);
  PetscCall(TSIRKGetNumStages(ts, &s));
  std::vector<PetscScalar> S(s * s, 0.0), T(s * s, 0.0); // S = A^-1/dt: TSIRK writes it at each Jacobian
  for (PetscInt i = 0; i < s; ++i) T[i + s * i] = 1.0;
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(MatCreateKAIJ(J, s, s, S.data(), T.data(), &K));
  PetscCall(SNESSetJacobian(snes, K, K, IrkFormJacobian,
                            ts)); // as TSSetUp_IRK and IrkStageAfterSetUp (TSSetIJacobian just set J itself there)
  PetscCall(MatDestroy(&K));      // the SNES holds it
  PetscFunctionReturn(0);
}

namespace {
// The leading members of PETSc 3.18's TS_IRK (src/ts/impls/implicit/irk/irk.c), as far as Z.
struct TSIRKLeading {
  char     *method_name;
  PetscInt  order, nstages;
  PetscBool stiffly_accurate;
  PetscInt  pinterp;
  void     *tableau;
  Vec       U0, Z;
};
} // namespace

PetscErrorCode IrkStageLayout(TS ts, DM dm)
{
  PetscBool   irk;
  PetscMPIInt size;
  PetscInt    s, n, bs;
  TSIRKType   type;
  Vec         U, Z;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, TSIRK, &irk));
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)ts), &size));
  if (!irk || size == 1) PetscFunctionReturn(0);
  PetscCall(TSIRKGetNumStages(ts, &s));
  PetscCall(TSIRKGetType(ts, &type));
  TSIRKLeading *data = static_cast<TSIRKLeading *>(ts->data);
  PetscCheck(data && data->nstages == s && data->method_name && type && !std::strcmp(data->method_name, type),
             PetscObjectComm((PetscObject)ts), PETSC_ERR_SUP,
             "-ts_type irk on %d ranks: this PETSc's TSIRK is not laid out as 3.18's, so its stage vector cannot be "
             "split as the state is; run irk on one rank",
             (int)size);
  if (data->Z) PetscFunctionReturn(0); // set up already
  PetscCall(DMCreateGlobalVector(dm, &U));
  PetscCall(VecGetLocalSize(U, &n));
  PetscCall(VecGetBlockSize(U, &bs));
  PetscCall(VecDestroy(&U));
  PetscCall(VecCreate(PetscObjectComm((PetscObject)ts), &Z));
  PetscCall(VecSetSizes(Z, s * n, PETSC_DETERMINE));
  PetscCall(VecSetBlockSize(Z, s * bs));
  PetscCall(VecSetFromOptions(Z));
  data->Z = Z; // TSSetUp_IRK keeps a Z it finds; TSReset_IRK destroys it
  PetscFunctionReturn(0);
}

PetscInt IrkStagePCFactorizations() { return n_factorizations; }

} // namespace beamimpact

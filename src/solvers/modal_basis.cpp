// Modal tools of the semi-discrete system. See modal_basis.hpp.
#include "solvers/modal_basis.hpp"

#include <petscblaslapack.h>
#include <petscmat.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>

namespace beamimpact {

extern "C" void dgbtrf_(const int *m, const int *n, const int *kl, const int *ku, double *ab, const int *ldab,
                        int *ipiv, int *info);
extern "C" void dsyevd_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w,
                        double *work, const int *lwork, int *iwork, const int *liwork,
                        int *info); // not in PETSc 3.18's petscblaslapack.h
extern "C" void dgbtrs_(const char *trans, const int *n, const int *kl, const int *ku, const int *nrhs,
                        const double *ab, const int *ldab, const int *ipiv, double *b, const int *ldb, int *info);

namespace {
// The dense modes' phases as -log_view events, registered together on first use: the matrix, its
// decomposition, the refinement (residuals, sparse LUs, re-orthogonalisation) and the quotients.
enum ModalPhase {
  kModalMatrix,
  kModalEigen,
  kModalRefine,
  kModalQuotients
};
PetscLogEvent ModalEvent(ModalPhase p)
{
  static const std::vector<PetscLogEvent> ids = [] {
    PetscClassId  cid = 0;
    PetscLogEvent id  = 0;
    (void)PetscClassIdRegister("beamimpact modes", &cid);
    std::vector<PetscLogEvent> v;
    for (const char *name : {"ModalMatrix", "ModalEigen", "ModalRefine", "ModalQuotients"}) {
      (void)PetscLogEventRegister(name, cid, &id);
      v.push_back(id);
    }
    return v;
  }();
  return ids[p];
}
} // namespace

ModalSystem ModalSystemBuild(const BeamSystem &sys, const ContactCoupling &g, PetscReal ball_mass, PetscReal k)
{
  ModalSystem S;
  S.sys = &sys;
  S.k   = k;
  for (PetscInt d = 0; d < sys.ndof; ++d) {
    if (sys.held[d]) continue;
    S.dof.push_back(d);
    S.mass.push_back(sys.mass[d]);
    S.g.push_back(g.Couples(d) ? -g.WeightOf(d) : 0.0);
  }
  S.dof.push_back(-1);
  S.mass.push_back(ball_mass);
  S.g.push_back(1.0);
  S.n = (PetscInt)S.dof.size();
  return S;
}

bool ModalSystem::Rayleigh(PetscReal *alpha, PetscReal *beta, std::string *why) const
{
  *alpha = *beta = 0;
  if (!ForceOperatorModal(*sys, alpha, beta, why)) return false;
  if (!damping || !sys->Damped()) *alpha = *beta = 0;
  return true;
}

ModalSystem ModalSystemBeamOnly(const BeamSystem &sys)
{
  ModalSystem S;
  S.sys  = &sys;
  S.ball = false;
  for (PetscInt d = 0; d < sys.ndof; ++d) {
    if (sys.held[d]) continue;
    S.dof.push_back(d);
    S.mass.push_back(sys.mass[d]);
    S.g.push_back(0.0);
  }
  S.n = (PetscInt)S.dof.size();
  return S;
}

void ModalOrthonormalize(const std::vector<PetscReal> &Phi, PetscInt n, PetscInt count, int passes, PetscReal *phi)
{
  for (int pass = 0; pass < passes; ++pass)
    for (PetscInt l = 0; l < count; ++l) {
      const PetscReal *psi = &Phi[(size_t)l * n];
      PetscReal        dot = 0;
      for (PetscInt d = 0; d < n; ++d) dot += phi[d] * psi[d];
      for (PetscInt d = 0; d < n; ++d) phi[d] -= dot * psi[d];
    }
  PetscReal nrm = 0;
  for (PetscInt d = 0; d < n; ++d) nrm += phi[d] * phi[d];
  nrm = std::sqrt(nrm);
  for (PetscInt d = 0; d < n; ++d) phi[d] /= nrm;
}

namespace {

// An entry of A = M^{-1/2} K_p M^{-1/2}: (row free dof, column free dof, value).
struct BandEntry {
  PetscInt  r, c;
  PetscReal v;
};

// Band order of the free dofs: beam dofs in dof order with the ball right after the later of
// the dofs it touches (its two nodes' deflections, fields apart).
std::vector<int> BandOrder(const ModalSystem &S)
{
  const PetscInt n = S.n, nb = S.BeamDofs();
  PetscInt       after = -1;
  for (PetscInt d = 0; d < nb; ++d)
    if (S.g[d] != 0.0) after = d;
  std::vector<int> pos(n); // free dof -> band position
  int              p = 0;
  if (S.ball && after < 0) pos[n - 1] = p++;
  for (PetscInt d = 0; d < nb; ++d) {
    pos[d] = p++;
    if (S.ball && d == after) pos[n - 1] = p++;
  }
  return pos;
}

// The nonzeros of A, from the rows of K and, in contact, the spring k g g^T.
std::vector<BandEntry> BandEntries(const ModalSystem &S, bool contact)
{
  const PetscInt         n = S.n;
  std::vector<PetscInt>  free_of_dof(S.sys->ndof, -1);
  std::vector<BandEntry> entries;
  std::vector<PetscInt>  cols(2 * S.sys->bw + 1);
  std::vector<PetscReal> vals(2 * S.sys->bw + 1);
  for (PetscInt d = 0; d < S.BeamDofs(); ++d) free_of_dof[S.dof[d]] = d;
  for (PetscInt d = 0; d < S.BeamDofs(); ++d) {
    const PetscInt nc = BeamSystemStiffnessRow(*S.sys, S.dof[d], cols.data(), vals.data());
    for (PetscInt q = 0; q < nc; ++q) {
      const PetscInt c = free_of_dof[cols[q]];
      entries.push_back({d, c, vals[q] / std::sqrt(S.mass[d] * S.mass[c])});
    }
  }
  if (contact)
    for (PetscInt r = 0; r < n; ++r)
      for (PetscInt c = 0; c < n; ++c)
        if (S.g[r] != 0.0 && S.g[c] != 0.0)
          entries.push_back({r, c, S.k * S.g[r] * S.g[c] / std::sqrt(S.mass[r] * S.mass[c])});
  return entries;
}

// y = A x with A = M^{-1/2} K_p M^{-1/2} in the factored form of K (the strains first,
// BeamSystemStiffnessApply): its round-off is relative to A x, not to |A| |x| as the band's is.
void ModalApply(const ModalSystem &S, bool contact, const PetscReal *x, std::vector<PetscReal> &q,
                std::vector<PetscReal> &f, PetscReal *y)
{
  const BeamSystem &sys = *S.sys;
  PetscReal         c   = 0;
  std::fill(q.begin(), q.end(), 0.0);
  for (PetscInt d = 0; d < S.n; ++d) {
    const PetscReal qd = x[d] / std::sqrt(S.mass[d]);
    if (d < S.BeamDofs()) q[S.dof[d]] = qd;
    c += S.g[d] * qd;
  }
  BeamSystemStiffnessApply(sys, q.data(), sys.fields, 0, sys.ndof, f.data(), sys.fields);
  for (PetscInt d = 0; d < S.n; ++d)
    y[d] = ((d < S.BeamDofs() ? f[S.dof[d]] : 0.0) + (contact ? S.k * S.g[d] * c : 0.0)) / std::sqrt(S.mass[d]);
}

// Two steps of inverse iteration on phi (unit length, orientation kept), solve(b) overwriting b
// by (A - sigma I)^{-1} b from a factorization of the assembled A, each solve corrected once with
// its residual in the factored form (ModalApply). The assembled entries carry the round-off of
// their assembly (eps |K|, ~eps omega_max^2 per entry): solved against them alone, a low mode is
// the assembled matrix's, off the system's by ~eps omega_max^2 / gap (the reference's ACOR off by
// 1e-8 at N = 641); the correction makes it the factored system's.
template <class Solve>
void InverseSteps(const ModalSystem &S, bool contact, PetscReal sigma, Solve &&solve, PetscReal *phi)
{
  const PetscInt         n = S.n;
  std::vector<double>    x(n), ax(n), res(n);
  std::vector<PetscReal> q(S.sys->ndof), f(S.sys->ndof);
  for (int it = 0; it < 2; ++it) {
    for (PetscInt d = 0; d < n; ++d) x[d] = phi[d];
    solve(x);
    ModalApply(S, contact, x.data(), q, f, ax.data());
    for (PetscInt d = 0; d < n; ++d) res[d] = phi[d] - (ax[d] - sigma * x[d]);
    solve(res);
    for (PetscInt d = 0; d < n; ++d) x[d] += res[d];
    PetscReal nrm = 0, sgn = 0; // keep the orientation
    for (PetscInt d = 0; d < n; ++d) nrm += x[d] * x[d], sgn += x[d] * phi[d];
    nrm = std::sqrt(nrm);
    for (PetscInt d = 0; d < n; ++d) phi[d] = (sgn < 0 ? -1 : 1) * x[d] / nrm;
  }
}

// InverseSteps with the banded LU of A - sigma I (LAPACK dgbtrf; ab of leading dimension
// 2 kl + ku + 1): 4 n kl^2 flops to factor.
PetscErrorCode InverseIterate(const ModalSystem &S, bool contact, const std::vector<BandEntry> &entries,
                              const std::vector<int> &pos, int kl, PetscReal sigma, PetscReal *phi)
{
  const int           n = (int)pos.size(), ku = kl, ldab = 2 * kl + ku + 1, one = 1;
  std::vector<double> ab((size_t)ldab * n, 0.0), r(n);
  std::vector<int>    ipiv(n);
  int                 info;

  PetscFunctionBeginUser;
  for (const BandEntry &e : entries) {
    const int i = pos[e.r], j = pos[e.c];
    ab[(size_t)(kl + ku + i - j) + (size_t)j * ldab] += e.v;
  }
  for (int i = 0; i < n; ++i) ab[(size_t)(kl + ku) + (size_t)i * ldab] -= sigma;
  dgbtrf_(&n, &n, &kl, &ku, ab.data(), &ldab, ipiv.data(), &info);
  PetscCheck(info >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK dgbtrf failed (info %d)", info);
  if (info > 0) PetscFunctionReturn(0); // exactly singular: the vector is already exact
  InverseSteps(
    S, contact, sigma,
    [&](std::vector<double> &b) { // b in free-dof order, overwritten by (LU)^{-1} b
      for (int d = 0; d < n; ++d) r[pos[d]] = b[d];
      dgbtrs_("N", &n, &kl, &ku, &one, ab.data(), &ldab, ipiv.data(), r.data(), &n, &info);
      for (int d = 0; d < n; ++d) b[d] = r[pos[d]];
    },
    phi);
  PetscFunctionReturn(0);
}

// The same with a sparse LU of A - sigma I (MUMPS, its fill-reducing ordering and threshold
// pivoting, on PETSC_COMM_SELF): where the band is wide (a string bed's kl is twice its fields
// per node) the band's 4 n kl^2 per mode is what the refinement cost; a 2-D bed's nested
// dissection fills far less. The pattern is analysed once, each mode factors numerically. The
// pivoting of an indefinite A - sigma I can outgrow the analysis' workspace (MUMPS -9): the
// factor is then analysed again with twice the room (ICNTL(14), from 100 %), and a mode it still
// fails falls back to the band (*solved false).
struct SparseShift {
  Mat                    A = nullptr, F = nullptr;
  Vec                    diag = nullptr, b = nullptr, x = nullptr;
  std::vector<PetscReal> a_diag; // A's diagonal (every row has one, a zero row's included)
  bool                   analysed = false;
  PetscInt               room     = 100; // ICNTL(14): % more workspace than the analysis estimates
};

PetscErrorCode SparseShiftCreate(PetscInt n, const std::vector<BandEntry> &entries, SparseShift *sp)
{
  std::vector<PetscInt>                                    nnz(n, 1); // the diagonal
  std::vector<std::vector<std::pair<PetscInt, PetscReal>>> rows(n);

  PetscFunctionBeginUser;
  sp->a_diag.assign(n, 0.0);
  for (const BandEntry &e : entries) {
    if (e.r == e.c) sp->a_diag[e.r] += e.v;
    else rows[e.r].push_back({e.c, e.v});
  }
  for (PetscInt r = 0; r < n; ++r) {
    std::sort(rows[r].begin(), rows[r].end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    PetscInt distinct = 0;
    for (size_t q = 0; q < rows[r].size(); ++q)
      if (q == 0 || rows[r][q].first != rows[r][q - 1].first) distinct++;
    nnz[r] += distinct;
  }
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), &sp->A));
  for (PetscInt r = 0; r < n; ++r) {
    for (const auto &e : rows[r]) PetscCall(MatSetValue(sp->A, r, e.first, e.second, ADD_VALUES));
    PetscCall(MatSetValue(sp->A, r, r, sp->a_diag[r], ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(sp->A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(sp->A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreateVecs(sp->A, &sp->x, &sp->b));
  PetscCall(VecDuplicate(sp->b, &sp->diag));
  PetscFunctionReturn(0);
}

PetscErrorCode SparseShiftDestroy(SparseShift *sp)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&sp->F));
  PetscCall(MatDestroy(&sp->A));
  PetscCall(VecDestroy(&sp->diag));
  PetscCall(VecDestroy(&sp->b));
  PetscCall(VecDestroy(&sp->x));
  PetscFunctionReturn(0);
}

// A fresh factor of A's pattern with the current workspace (analysed on its first numeric use).
static PetscErrorCode SparseShiftFactor(SparseShift *sp)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&sp->F));
  PetscCall(MatGetFactor(sp->A, MATSOLVERMUMPS, MAT_FACTOR_LU, &sp->F));
  PetscCall(MatMumpsSetIcntl(sp->F, 14, (PetscInt)sp->room));
  sp->analysed = false;
  PetscFunctionReturn(0);
}

PetscErrorCode InverseIterateSparse(const ModalSystem &S, bool contact, SparseShift *sp, PetscReal sigma,
                                    PetscReal *phi, bool *solved)
{
  const PetscInt n = S.n;
  MatFactorInfo  info;
  MatFactorError err = MAT_FACTOR_OUTMEMORY;
  PetscScalar   *a;

  PetscFunctionBeginUser;
  *solved = true;
  PetscCall(VecGetArray(sp->diag, &a));
  for (PetscInt d = 0; d < n; ++d) a[d] = sp->a_diag[d] - sigma;
  PetscCall(VecRestoreArray(sp->diag, &a));
  PetscCall(MatDiagonalSet(sp->A, sp->diag, INSERT_VALUES));
  PetscCall(MatFactorInfoInitialize(&info));
  for (int attempt = 0; attempt < 4 && err == MAT_FACTOR_OUTMEMORY; ++attempt) {
    if (!sp->F || attempt > 0) {
      if (attempt > 0) sp->room *= 2;
      PetscCall(SparseShiftFactor(sp));
    }
    if (!sp->analysed) {
      PetscCall(MatLUFactorSymbolic(sp->F, sp->A, NULL, NULL, &info));
      sp->analysed = true;
    }
    PetscCall(MatLUFactorNumeric(sp->F, sp->A, &info));
    PetscCall(MatFactorGetError(sp->F, &err));
  }
  if (err == MAT_FACTOR_NUMERIC_ZEROPIVOT)
    PetscFunctionReturn(0);        // (numerically) singular: the vector is already exact
  if (err != MAT_FACTOR_NOERROR) { // the factor is spoilt for the next modes too
    PetscCall(SparseShiftFactor(sp));
    *solved = false;
    PetscFunctionReturn(0);
  }
  PetscErrorCode ierr = 0;
  InverseSteps(
    S, contact, sigma,
    [&](std::vector<double> &bv) {
      if (ierr) return;
      PetscScalar       *pb;
      const PetscScalar *px;
      ierr = VecGetArray(sp->b, &pb);
      if (ierr) return;
      std::copy(bv.begin(), bv.end(), pb);
      ierr = VecRestoreArray(sp->b, &pb);
      if (!ierr) ierr = MatSolve(sp->F, sp->b, sp->x);
      if (!ierr) ierr = VecGetArrayRead(sp->x, &px);
      if (ierr) return;
      std::copy(px, px + n, bv.begin());
      ierr = VecRestoreArrayRead(sp->x, &px);
    },
    phi);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

// Half-bandwidth of A in the band order: a beam entry straddling the ball is one further
// apart than in K (bw + 1); the ball's own entries reach back over the free dofs between
// the first and the last dof it touches, plus one.
int BandHalfWidth(const ModalSystem &S)
{
  PetscInt first = -1, last = -1;
  for (PetscInt d = 0; d < S.BeamDofs(); ++d)
    if (S.g[d] != 0.0) {
      if (first < 0) first = d;
      last = d;
    }
  return (int)std::max(S.sys->bw, last - first) + 1;
}

// Modified Gram-Schmidt on the columns of Phi (n rows), in order.
void GramSchmidt(PetscInt n, std::vector<PetscReal> &Phi)
{
  const PetscInt count = (PetscInt)(Phi.size() / n);
  for (PetscInt k = 0; k < count; ++k) ModalOrthonormalize(Phi, n, k, 1, &Phi[k * n]);
}

} // namespace

// Which modes are refined. The refinement costs, per mode, a banded LU of A - sigma I and four
// solves with it (ModalRefineModeFlops): nothing next to the decomposition for a beam (kl = 3
// for Euler-Bernoulli, 4 for Timoshenko, 23 with a shell's three harmonics), more than the
// decomposition itself for a string bed, whose half-bandwidth is twice its fields per node
// (kl = 55 to 163 for 25 to 81 nodes across the face). There the modes are refined by
// need: a mode is refined where its residual in the factored form, |A phi - rho phi| with rho
// its Rayleigh quotient, exceeds kRefineResidual rho (ModalRefineResidual). A residual r makes
// (rho, phi) an exact eigenpair of A + E with |E| = |r|: the computed basis propagates a system
// whose mode k is off by |r| / (2 rho) in its frequency, whatever the gap to its neighbours (two
// modes mixed by an angle |r| / gap move apart by that angle times their frequencies'
// difference: |r| t / (omega_k + omega_j) over a time t). dsyevd leaves |r| ~ 1-2 eps lambda_max
// in every mode (measured on the held bed of 61 x 43 nodes), so only the modes with lambda_k <
// ~2 eps lambda_max / kRefineResidual are refined: the beam's h^-4 spread puts most of its low
// modes there (eps lambda_max / lambda_1 ~ 1e-6 at N = 641), the bed's h^-2 spread a handful
// (1.6e-12 at 61 x 43). Where refining every mode costs at most the decomposition's own share per
// mode (4 n^2 flops) or 2e9 flops in all (every beam, shell and hoop of the suite, and the small
// beds), every mode is refined as before: their results are unchanged, bit for bit.
constexpr PetscReal kRefineResidual   = 1e-12;
constexpr double    kRefineEveryFlops = 2e9;

double ModalRefineModeFlops(PetscInt n, PetscInt kl)
{
  return 4.0 * (double)n * (double)kl * (double)kl + 24.0 * (double)n * (double)kl;
}

PetscInt ModalRefineHalfWidth(const ModalSystem &S) { return BandHalfWidth(S); }

bool ModalRefinesEveryMode(PetscInt n, PetscInt kl, PetscInt count)
{
  const double per_mode = ModalRefineModeFlops(n, kl);
  return n <= 64 || per_mode <= 4.0 * (double)n * (double)n || (double)count * per_mode <= kRefineEveryFlops;
}

PetscReal ModalRefineResidual() { return kRefineResidual; }

// |A phi - rho phi| / |rho| of each column of Phi (n x count), rho = phi^T A phi, A in the
// factored form (ModalApply): O(n) per mode.
std::vector<PetscReal> ModalResiduals(const ModalSystem &S, bool contact, const std::vector<PetscReal> &Phi,
                                      PetscInt count, PetscMPIInt rank, PetscMPIInt size)
{
  const PetscInt         n = S.n;
  std::vector<PetscReal> q(S.sys->ndof), f(S.sys->ndof), ax(n), rel(count);
  for (PetscInt k = 0; k < count; ++k) {
    const PetscReal *phi = &Phi[(size_t)k * n];
    PetscReal        rho = 0, r2 = 0, nrm = 0;
    if (k % size != rank) continue; // another rank's: 0 here
    ModalApply(S, contact, phi, q, f, ax.data());
    for (PetscInt d = 0; d < n; ++d) rho += phi[d] * ax[d], nrm += phi[d] * phi[d];
    rho /= nrm;
    for (PetscInt d = 0; d < n; ++d) r2 += (ax[d] - rho * phi[d]) * (ax[d] - rho * phi[d]);
    rel[k] = std::sqrt(r2 / nrm) / std::abs(rho); // inf for a zero mode: refined
  }
  return rel;
}

// Columns of Phi (n each) computed one rank each, column j on rank j % size of comm, handed to
// every rank: each rank's result is the one rank's, bit for bit, whatever the number of ranks.
static PetscErrorCode ShareColumns(MPI_Comm comm, PetscInt n, const std::vector<PetscInt> &cols,
                                   std::vector<PetscReal> &Phi)
{
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size == 1) PetscFunctionReturn(0);
  for (size_t j = 0; j < cols.size(); ++j)
    PetscCallMPI(MPI_Bcast(&Phi[(size_t)cols[j] * n], (PetscMPIInt)n, MPIU_REAL, (PetscMPIInt)(j % size), comm));
  PetscFunctionReturn(0);
}

// The modes `need` refined with the sparse LU of A - sigma I (the band is wide: a string bed), one
// rank each on several (ShareColumns), the banded LU where the sparse one fails.
static PetscErrorCode RefineSparse(const ModalSystem &S, bool contact, const std::vector<BandEntry> &entries,
                                   const std::vector<PetscReal> &lambda, const std::vector<PetscInt> &need,
                                   ModalBasis *B, MPI_Comm comm)
{
  const PetscInt  n     = S.n;
  const int       kl    = BandHalfWidth(S);
  const PetscReal scale = *std::max_element(lambda.begin(), lambda.end());
  PetscMPIInt     rank, size;
  SparseShift     sp;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(SparseShiftCreate(n, entries, &sp));
  for (size_t j = 0; j < need.size(); ++j) {
    const PetscInt k = need[j];
    bool           solved;
    if ((PetscMPIInt)(j % size) != rank) continue; // another rank's
    PetscCall(InverseIterateSparse(S, contact, &sp, lambda[k] - 1e-14 * scale, &B->Phi[k * n], &solved));
    if (!solved)
      PetscCall(InverseIterate(S, contact, entries, BandOrder(S), kl, lambda[k] - 1e-14 * scale, &B->Phi[k * n]));
  }
  PetscCall(SparseShiftDestroy(&sp));
  PetscCall(ShareColumns(comm, n, need, B->Phi));
  PetscFunctionReturn(0);
}

// The dense eigenvectors (dsyevd's or syev's) are accurate only to eps * lambda_max / gap: with the h^-4 spread of
// the beam's spectrum that is ~1e-6 at N = 641. Two steps of inverse iteration per mode,
// shifted by its eigenvalue, with a banded LU of A - sigma I and each solve corrected by its
// residual in the factored form (InverseIterate), then modified Gram-Schmidt (which cleans up
// (near-)degenerate pairs such as the rigid modes), bring each vector to round-off relative
// to its own eigenvalue. Every mode where that is cheap (ModalRefinesEveryMode); elsewhere the
// modes whose residual asks for it, Gram-Schmidt among them in order, and every other mode
// then made orthogonal to them (it was orthogonal to the old vectors to round-off; what the
// refinement moved is ~|r| / gap) and normalised.
static PetscErrorCode RefineBasis(const ModalSystem &S, bool contact, const std::vector<PetscReal> &lambda,
                                  ModalBasis *B, bool refine_all, MPI_Comm comm)
{
  const PetscInt               n       = S.n;
  const int                    kl      = BandHalfWidth(S);
  const std::vector<int>       pos     = BandOrder(S);
  const std::vector<BandEntry> entries = BandEntries(S, contact);
  const PetscReal              scale   = *std::max_element(lambda.begin(), lambda.end());
  const PetscInt               count   = (PetscInt)lambda.size(); // the columns of Phi

  PetscMPIInt rank, size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (refine_all || ModalRefinesEveryMode(n, kl, count)) {
    std::vector<PetscInt> all(count);
    for (PetscInt k = 0; k < count; ++k) {
      all[k] = k;
      if (k % size == rank) // the modes shared over the ranks (ShareColumns)
        PetscCall(InverseIterate(S, contact, entries, pos, kl, lambda[k] - 1e-14 * scale,
                                 &B->Phi[k * n])); // just below: never exactly singular
    }
    PetscCall(ShareColumns(comm, n, all, B->Phi));
    GramSchmidt(n, B->Phi);
    B->refined = count;
    PetscFunctionReturn(0);
  }
  std::vector<PetscReal> rel = ModalResiduals(S, contact, B->Phi, count, rank, size);
  if (size > 1) // each mode's from one rank, the others' 0
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, rel.data(), (PetscMPIInt)count, MPIU_REAL, MPIU_SUM, comm));
  std::vector<PetscInt> need;
  for (PetscInt k = 0; k < count; ++k)
    if (!(rel[k] <= kRefineResidual)) need.push_back(k);
  if (!need.empty()) PetscCall(RefineSparse(S, contact, entries, lambda, need, B, comm));
  std::vector<PetscReal> R((size_t)n *
                           need.size()); // the refined columns, orthonormal (modified Gram-Schmidt in order)
  for (size_t i = 0; i < need.size(); ++i) {
    std::copy_n(&B->Phi[(size_t)need[i] * n], n, &R[i * n]);
    ModalOrthonormalize(R, n, (PetscInt)i, 1, &R[i * n]);
  }
  if (!need.empty()) { // every other column less its projection on R, Phi -= R (R^T Phi), by BLAS 3; then normalised
    PetscBLASInt           bn, bk, bc;
    const PetscScalar      one = 1, zero = 0, minus = -1;
    std::vector<PetscReal> C(need.size() * (size_t)count);
    PetscCall(PetscBLASIntCast(n, &bn));
    PetscCall(PetscBLASIntCast((PetscInt)need.size(), &bk));
    PetscCall(PetscBLASIntCast(count, &bc));
    PetscCallBLAS("BLASgemm",
                  BLASgemm_("T", "N", &bk, &bc, &bn, &one, R.data(), &bn, B->Phi.data(), &bn, &zero, C.data(), &bk));
    for (PetscInt k : need) std::fill_n(&C[(size_t)k * need.size()], need.size(), 0.0); // the refined columns are R's
    PetscCallBLAS("BLASgemm",
                  BLASgemm_("N", "N", &bn, &bc, &bk, &minus, R.data(), &bn, C.data(), &bk, &one, B->Phi.data(), &bn));
    std::vector<char> refined(count, 0);
    for (size_t i = 0; i < need.size(); ++i) {
      refined[need[i]] = 1;
      std::copy_n(&R[i * n], n, &B->Phi[(size_t)need[i] * n]);
    }
    for (PetscInt k = 0; k < count; ++k) {
      if (refined[k]) continue;
      PetscReal *phi = &B->Phi[(size_t)k * n], nrm = 0;
      for (PetscInt d = 0; d < n; ++d) nrm += phi[d] * phi[d];
      nrm = std::sqrt(nrm);
      for (PetscInt d = 0; d < n; ++d) phi[d] /= nrm;
    }
  }
  B->refined = (PetscInt)need.size();
  B->by_need = true;
  PetscCall(PetscInfo(NULL,
                      "modal basis: %" PetscInt_FMT " of %" PetscInt_FMT
                      " modes refined (relative residual above %g in the factored form; half-bandwidth %d)\n",
                      (PetscInt)need.size(), count, (double)kRefineResidual, kl));
  PetscFunctionReturn(0);
}

// The dense A = M^{-1/2} K_p M^{-1/2} (column-major, n x n) of a phase.
static std::vector<PetscReal> ModalMatrix(const ModalSystem &S, bool contact)
{
  const PetscInt         n = S.n;
  std::vector<PetscReal> A(n * n, 0.0);
  std::vector<PetscInt>  cols(2 * S.sys->bw + 1), free_of_dof(S.sys->ndof, -1);
  std::vector<PetscReal> vals(2 * S.sys->bw + 1);
  for (PetscInt d = 0; d < S.BeamDofs(); ++d) free_of_dof[S.dof[d]] = d;
  for (PetscInt d = 0; d < S.BeamDofs(); ++d) {
    const PetscInt nc = BeamSystemStiffnessRow(*S.sys, S.dof[d], cols.data(), vals.data());
    for (PetscInt q = 0; q < nc; ++q) A[d + free_of_dof[cols[q]] * n] += vals[q];
  }
  if (contact)
    for (PetscInt r = 0; r < n; ++r)
      for (PetscInt c = 0; c < n; ++c) A[r + c * n] += S.k * S.g[r] * S.g[c];
  for (PetscInt c = 0; c < n; ++c) // without the contact's term A is sparse: its zeros stay zeros
    for (PetscInt r = 0; r < n; ++r)
      if (contact || A[r + c * n] != 0) A[r + c * n] /= std::sqrt(S.mass[r] * S.mass[c]);
  return A;
}

// Separated and damped: the ball (undamped) must be a mode of its own, not a mix with the
// beam's rigid modes (damped by alpha) that share omega = 0. The ball's row of A is zero, so
// e_ball is an exact eigenvector: it replaces the member of the zero cluster (lambda below
// (1e-3 frequency unit)^2) nearest to it, and the rest of the cluster is made orthogonal to it.
static void IsolateBall(const ModalSystem &S, const std::vector<PetscReal> &lambda, ModalBasis *B)
{
  const PetscInt  n = S.n, ball = n - 1;
  const PetscReal zero = std::pow(1e-3 * S.sys->frequency_unit, 2);
  PetscInt        kb   = -1;
  for (PetscInt k = 0; k < n; ++k)
    if (lambda[k] <= zero && (kb < 0 || std::abs(B->Phi[ball + k * n]) > std::abs(B->Phi[ball + kb * n]))) kb = k;
  if (kb < 0) return;
  for (PetscInt d = 0; d < n; ++d) B->Phi[d + kb * n] = d == ball ? 1.0 : 0.0;
  for (PetscInt k = 0; k < n; ++k) {
    if (k == kb || lambda[k] > zero) continue;
    PetscReal *phi = &B->Phi[k * n], nrm = 0;
    phi[ball] = 0.0;
    for (PetscInt l = 0; l < k; ++l) { // against the cluster's earlier members (Gram-Schmidt)
      if (l == kb || lambda[l] > zero) continue;
      PetscReal dot = 0;
      for (PetscInt d = 0; d < n; ++d) dot += phi[d] * B->Phi[d + l * n];
      for (PetscInt d = 0; d < n; ++d) phi[d] -= dot * B->Phi[d + l * n];
    }
    for (PetscInt d = 0; d < n; ++d) nrm += phi[d] * phi[d];
    nrm = std::sqrt(nrm);
    for (PetscInt d = 0; d < n; ++d) phi[d] /= nrm;
  }
}

// Each mode's omega as its Rayleigh quotient in the energy form (a sum of squares: accurate
// relative to the mode itself, where the dense solver's is only relative to the largest), its share gamma
// of c, and its decay rate sigma = phi^T C phi / 2 (C = alpha M + beta K on the beam dofs:
// alpha/2 + beta omega^2/2 for a beam mode, alpha/2 for its rigid modes, 0 for the ball). Mode k
// on rank k % size of comm, then summed over the ranks (the others' 0): each rank's the one rank's.
static PetscErrorCode ModalQuotients(const ModalSystem &S, bool contact, ModalBasis *B, MPI_Comm comm)
{
  const PetscInt         n   = S.n;
  const BeamSystem      &sys = *S.sys;
  std::vector<PetscReal> shape(sys.ndof);
  PetscReal              alpha, beta;
  PetscMPIInt            rank, size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  S.Rayleigh(&alpha, &beta);
  const bool     damped = alpha != 0 || beta != 0;
  const PetscInt count  = (PetscInt)B->omega.size();
  for (PetscInt k = 0; k < count; ++k) {
    if (k % size != rank) { // another rank's: 0 here
      B->omega[k] = B->gamma[k] = B->rate[k] = 0;
      continue;
    }
    const PetscReal *phi = &B->Phi[k * n];
    std::fill(shape.begin(), shape.end(), 0.0);
    PetscReal norm = 0, c = 0, beam_norm = 0;
    for (PetscInt d = 0; d < n; ++d) {
      const PetscReal q = phi[d] / std::sqrt(S.mass[d]);
      if (d < S.BeamDofs()) shape[S.dof[d]] = q;
      norm += S.mass[d] * q * q;
      c += S.g[d] * q;
      if (d < S.BeamDofs()) beam_norm += S.mass[d] * q * q;
    }
    PetscReal twoU = 2 * BeamSystemStrainEnergy(sys, shape.data(), sys.fields, 0, sys.ndof);
    B->rate[k]     = damped ? 0.5 * (alpha * beam_norm + beta * twoU) / norm : 0.0;
    if (contact) twoU += S.k * c * c;
    B->omega[k] = std::sqrt(std::max<PetscReal>(0.0, twoU / norm));
    B->gamma[k] = c;
  }
  if (size > 1) { // one reduction of the three
    std::vector<PetscReal> all(B->omega);
    all.insert(all.end(), B->gamma.begin(), B->gamma.end());
    all.insert(all.end(), B->rate.begin(), B->rate.end());
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, all.data(), (PetscMPIInt)all.size(), MPIU_REAL, MPIU_SUM, comm));
    std::copy_n(all.begin(), count, B->omega.begin());
    std::copy_n(all.begin() + count, count, B->gamma.begin());
    std::copy_n(all.begin() + 2 * count, count, B->rate.begin());
  }
  PetscFunctionReturn(0);
}

// Every eigenpair of the symmetric n x n A (column-major; its upper triangle): LAPACK dsyevd,
// the tridiagonal reduction, divide and conquer on it (its merges BLAS 3) and the
// back-transformation, in place of syev's QR iteration, whose rotations on the eigenvectors
// are BLAS 1. R161 at N = 641 (n = 1282), the whole run's CPU time: 6.95 s with syev, 6.19 s
// with dsyevr (MRRR), 5.66 s with dsyevd (reference BLAS; docs/convergence.md). Eigenvalues
// ascending in w, the eigenvectors overwrite A. *ok false if it did not converge (info > 0):
// the caller falls back to syev.
static PetscErrorCode SymmetricEigenDC(PetscInt n, std::vector<PetscReal> &A, std::vector<PetscReal> *w, bool *ok)
{
  PetscBLASInt bn, info = 0, lwork = -1, liwork = -1, iq = 0;
  PetscReal    wq = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscBLASIntCast(n, &bn));
  w->assign(n, 0.0);
  dsyevd_("V", "U", &bn, A.data(), &bn, w->data(), &wq, &lwork, &iq, &liwork, &info); // workspace query
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK dsyevd's workspace query failed (info %d)", (int)info);
  lwork  = (PetscBLASInt)wq;
  liwork = iq;
  std::vector<PetscReal>    work(lwork);
  std::vector<PetscBLASInt> iwork(liwork);
  dsyevd_("V", "U", &bn, A.data(), &bn, w->data(), work.data(), &lwork, iwork.data(), &liwork, &info);
  PetscCheck(info >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK dsyevd: argument %d was wrong", (int)-info);
  *ok = info == 0;
  PetscFunctionReturn(0);
}

// The same by LAPACK syev (QR iteration): w ascending, the eigenvectors overwrite A.
static PetscErrorCode SymmetricEigenQR(PetscInt n, std::vector<PetscReal> &A, std::vector<PetscReal> *w)
{
  PetscBLASInt bn, lwork, info;

  PetscFunctionBeginUser;
  PetscCall(PetscBLASIntCast(n, &bn));
  PetscCall(PetscBLASIntCast(std::max<PetscInt>(1, 8 * n), &lwork));
  std::vector<PetscReal> work(lwork);
  w->assign(n, 0.0);
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "U", &bn, A.data(), &bn, w->data(), work.data(), &lwork, &info));
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK syev failed (info %d)", (int)info);
  PetscFunctionReturn(0);
}

// The structure's mirror across the face, z -> -z (a racket's bed about its frame's axis; the
// frame's roll changes sign): R, a signed permutation of the free dofs, dof (node i, z) to the dof
// of the same node at -z (DofZ), the roll field (RollField) to itself with sign -1, every other
// dof (the beam's fields, the wall's, an absorber's, the ball) to itself. False where a dof has
// no partner (a held one, a grid that is not symmetric) or R is the identity (nothing to split).
bool ModalMirrorOf(const ModalSystem &S, ModalMirror *m)
{
  const BeamSystem     &sys = *S.sys;
  const PetscInt        n = S.n, F = sys.fields, roll = sys.RollField();
  std::vector<PetscInt> free_of(sys.ndof, -1);
  for (PetscInt d = 0; d < S.BeamDofs(); ++d) free_of[S.dof[d]] = d;
  m->to.assign(n, -1);
  m->sign.assign(n, 1);
  bool moves = false;
  for (PetscInt r = 0; r < n; ++r) {
    const PetscInt d = S.dof[r];
    if (d < 0) { // the ball
      m->to[r] = r;
      continue;
    }
    const PetscReal z     = sys.DofZ(d);
    PetscInt        image = z == 0 ? d : -1;
    for (PetscInt f = 0; f < F && image < 0; ++f) {
      const PetscInt e = (d / F) * F + f;
      if (std::abs(sys.DofZ(e) + z) <= 1e-9 * std::abs(z)) image = e;
    }
    if (image < 0 || free_of[image] < 0) return false;
    m->to[r]   = free_of[image];
    m->sign[r] = roll >= 0 && d % F == roll ? -1 : 1;
    moves      = moves || m->to[r] != r || m->sign[r] < 0;
  }
  return moves;
}

// The even and odd bases of R (columns with at most two entries: e_r, or (e_r +- s e_t)/sqrt(2)
// for a pair r < t = R r, s its sign), and whether A commutes with R, R A R = A, to within n eps
// of A's largest entry (the racket's grid is mirrored to 4e-15 of it at 73 nodes, 1.3e-14 at
// 145: the bed's masses and strings summed in another order). Then A is block-diagonal in them:
// its even and odd blocks are decomposed apart (an eighth of the cost each at half the size).
// What A and R A R differ by is left out, below dsyevd's own backward error (~n eps |A|), and
// the refinement (RefineBasis, on K and M themselves) takes each mode whose residual asks for it
// to round-off relative to its own eigenvalue, as it does dsyevd's.
struct MirrorColumn {
  PetscInt  r = 0, t = -1;  // its entries' rows (t < 0: one entry)
  PetscReal cr = 1, ct = 0; // and values
};
static bool MirrorBases(const std::vector<PetscReal> &A, PetscInt n, const ModalMirror &m,
                        std::vector<MirrorColumn> *even, std::vector<MirrorColumn> *odd)
{
  PetscReal big = 0, gap = 0;
  for (PetscInt c = 0; c < n; ++c)
    for (PetscInt r = 0; r < n; ++r) {
      const PetscReal a = A[r + c * n];
      big               = std::max(big, std::abs(a));
      gap               = std::max(gap, std::abs(a - m.sign[r] * m.sign[c] * A[m.to[r] + m.to[c] * n]));
    }
  if (!(gap <= n * std::numeric_limits<PetscReal>::epsilon() * big)) return false;
  const PetscReal h = 1 / std::sqrt(2.0);
  for (PetscInt r = 0; r < n; ++r) {
    const PetscInt t = m.to[r], s = m.sign[r];
    if (m.to[t] != r || m.sign[t] != s) return false; // not an involution
    if (t == r) (s > 0 ? even : odd)->push_back({r, -1, 1, 0});
    else if (r < t) {
      even->push_back({r, t, h, s * h});
      odd->push_back({r, t, h, -s * h});
    }
  }
  return !even->empty() && !odd->empty();
}

// The block Q^T A Q of A in the columns Q (dense, column-major).
static std::vector<PetscReal> MirrorBlock(const std::vector<PetscReal> &A, PetscInt n,
                                          const std::vector<MirrorColumn> &Q)
{
  const PetscInt         k = (PetscInt)Q.size();
  std::vector<PetscReal> B((size_t)k * k);
  auto                   at = [&](PetscInt r, const MirrorColumn &q) { // (A q)_r
    return q.t < 0 ? q.cr * A[r + q.r * n] : q.cr * A[r + q.r * n] + q.ct * A[r + q.t * n];
  };
  for (PetscInt c = 0; c < k; ++c)
    for (PetscInt p = 0; p < k; ++p) {
      const MirrorColumn &q = Q[p];
      B[p + c * k]          = q.cr * at(q.r, Q[c]) + (q.t < 0 ? 0.0 : q.ct * at(q.t, Q[c]));
    }
  return B;
}

// Every eigenpair of the symmetric A (ascending in w, the eigenvectors overwrite A), by dsyevd
// (syev where it does not converge).
static PetscErrorCode SymmetricEigen(PetscInt n, std::vector<PetscReal> &A, std::vector<PetscReal> *w,
                                     const std::function<std::vector<PetscReal>()> &again)
{
  bool dc = false;

  PetscFunctionBeginUser;
  PetscCall(SymmetricEigenDC(n, A, w, &dc));
  if (!dc) { // divide and conquer did not converge (rare): QR iteration on a fresh copy
    A = again();
    PetscCall(SymmetricEigenQR(n, A, w));
  }
  PetscFunctionReturn(0);
}

// Every eigenpair of A from its even and odd blocks under the structure's mirror (ModalMirrorOf,
// MirrorBases), merged in ascending order (even first at a tie); *done false where there is no
// mirror A commutes with (then A is untouched).
static PetscErrorCode MirrorEigen(const ModalSystem &S, std::vector<PetscReal> &A, std::vector<PetscReal> *w,
                                  bool *done, MPI_Comm comm)
{
  const PetscInt            n = S.n;
  ModalMirror               m;
  std::vector<MirrorColumn> Q[2];
  PetscMPIInt               rank, size;

  PetscFunctionBeginUser;
  *done = false;
  if (!S.mirror || !ModalMirrorOf(S, &m) || !MirrorBases(A, n, m, &Q[0], &Q[1])) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscReal> V[2], lam[2];
  for (int b = 0; b < 2; ++b) { // on several ranks, block b on rank b % size, at once; then handed out
    const PetscInt k = (PetscInt)Q[b].size();
    if (b % size == rank) {
      V[b] = MirrorBlock(A, n, Q[b]);
      PetscCall(SymmetricEigen(k, V[b], &lam[b], [&] { return MirrorBlock(A, n, Q[b]); }));
    } else V[b].resize((size_t)k * k), lam[b].resize(k);
  }
  for (int b = 0; b < 2 && size > 1; ++b) { // after both: a broadcast between them would hold the second back
    const PetscInt k = (PetscInt)Q[b].size();
    PetscCallMPI(MPI_Bcast(lam[b].data(), (PetscMPIInt)k, MPIU_REAL, b % size, comm));
    PetscCallMPI(MPI_Bcast(V[b].data(), (PetscMPIInt)(k * k), MPIU_REAL, b % size, comm));
  }
  std::fill(A.begin(), A.end(), 0.0);
  w->assign(n, 0.0);
  size_t i[2] = {0, 0};
  for (PetscInt k = 0; k < n; ++k) {
    const int        b  = i[1] >= lam[1].size() || (i[0] < lam[0].size() && lam[0][i[0]] <= lam[1][i[1]]) ? 0 : 1;
    const size_t     kb = Q[b].size(), j = i[b]++;
    const PetscReal *v   = &V[b][j * kb];
    PetscReal       *phi = &A[(size_t)k * n];
    (*w)[k]              = lam[b][j];
    for (size_t p = 0; p < kb; ++p) {
      const MirrorColumn &q = Q[b][p];
      phi[q.r] += q.cr * v[p];
      if (q.t >= 0) phi[q.t] += q.ct * v[p];
    }
  }
  PetscCall(PetscInfo(NULL,
                      "modal basis: the mirror z -> -z splits the %" PetscInt_FMT
                      " free dofs into %zu even and %zu odd\n",
                      n, Q[0].size(), Q[1].size()));
  *done = true;
  PetscFunctionReturn(0);
}

PetscErrorCode ModalBasisBuild(const ModalSystem &S, bool contact, ModalBasis *B, bool refine_all, MPI_Comm comm)
{
  const PetscInt         n = S.n;
  std::vector<PetscReal> A, w(n);
  PetscReal              alpha, beta;
  std::string            why;

  PetscFunctionBeginUser;
  PetscCheck(S.Rayleigh(&alpha, &beta, &why), PETSC_COMM_SELF, PETSC_ERR_SUP, "the modes of the beam: %s", why.c_str());
  const bool damped = alpha != 0 || beta != 0;
  PetscCheck(!(contact && damped), PETSC_COMM_SELF, PETSC_ERR_SUP,
             "-beam_damping_mass %g and -beam_damping_stiffness %g: in contact the damping is not proportional (the "
             "ball and the contact spring carry none), so the coupled "
             "modes have no closed form; the exact modal solution needs both 0 (use a tight TS run as the reference)",
             (double)alpha, (double)beta);
  PetscCall(PetscLogEventBegin(ModalEvent(kModalMatrix), 0, 0, 0, 0));
  A = ModalMatrix(S, contact);
  PetscCall(PetscLogEventEnd(ModalEvent(kModalMatrix), 0, 0, 0, 0));
  bool mirrored = false;
  PetscCall(PetscLogEventBegin(ModalEvent(kModalEigen), 0, 0, 0, 0));
  PetscCall(MirrorEigen(S, A, &w, &mirrored, comm));
  B->mirrored = mirrored;
  if (!mirrored) PetscCall(SymmetricEigen(n, A, &w, [&] { return ModalMatrix(S, contact); }));
  PetscCall(PetscLogEventEnd(ModalEvent(kModalEigen), 0, 0, 0, 0));
  B->Phi = std::move(A);
  B->omega.assign(n, 0.0);
  B->gamma.assign(n, 0.0);
  B->rate.assign(n, 0.0);
  PetscCall(PetscLogEventBegin(ModalEvent(kModalRefine), 0, 0, 0, 0));
  PetscCall(RefineBasis(S, contact, w, B, refine_all, comm));
  PetscCall(PetscLogEventEnd(ModalEvent(kModalRefine), 0, 0, 0, 0));
  if (!contact && damped && S.ball) IsolateBall(S, w, B);
  PetscCall(PetscLogEventBegin(ModalEvent(kModalQuotients), 0, 0, 0, 0));
  PetscCall(ModalQuotients(S, contact, B, comm));
  PetscCall(PetscLogEventEnd(ModalEvent(kModalQuotients), 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalBasisFromModes(const ModalSystem &S, const std::vector<PetscReal> &lambda,
                                   std::vector<PetscReal> &&Phi, ModalBasis *B, bool refine, bool refine_all)
{
  const PetscInt count = (PetscInt)lambda.size();

  PetscFunctionBeginUser;
  PetscCheck(!S.ball && (PetscInt)Phi.size() == S.n * count, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "ModalBasisFromModes: the beam's free dofs (%" PetscInt_FMT ") times %" PetscInt_FMT " modes", S.n, count);
  B->Phi = std::move(Phi);
  B->omega.assign(count, 0.0);
  B->gamma.assign(count, 0.0);
  B->rate.assign(count, 0.0);
  if (refine) PetscCall(RefineBasis(S, false, lambda, B, refine_all, PETSC_COMM_SELF));
  PetscCall(ModalQuotients(S, false, B, PETSC_COMM_SELF));
  PetscFunctionReturn(0);
}

// Mode k of a phase: q'' + 2 sigma q' + w^2 q = 0 from (z, zd) at s = 0, in closed form
//   q(s) = E(s) [z (c + sigma S) + zd S],  q'(s) = E(s) [zd (c - sigma S) - w^2 z S],
// E = exp(-sigma s); with w_d = sqrt(w^2 - sigma^2) (underdamped) c = cos(w_d s), S =
// sin(w_d s)/w_d; critically damped c = 1, S = s; with mu = sqrt(sigma^2 - w^2) (overdamped,
// and rigid modes with alpha) c = cosh(mu s), S = sinh(mu s)/mu, in exponentials that neither
// overflow nor cancel.
void ModalModeAt(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, PetscReal s, PetscReal *q, PetscReal *qd)
{
  PetscReal Ec, ES; // E c and E S
  if (w > sigma) {
    const PetscReal wd = std::sqrt((w - sigma) * (w + sigma)), E = std::exp(-sigma * s);
    Ec = E * std::cos(wd * s);
    ES = E * std::sin(wd * s) / wd;
  } else if (w == sigma) {
    Ec = std::exp(-sigma * s);
    ES = s * Ec;
  } else {
    const PetscReal mu   = std::sqrt((sigma - w) * (sigma + w)),
                    slow = std::exp(-w * w / (sigma + mu) * s); // exp((mu - sigma) s)
    Ec                   = 0.5 * (slow + std::exp(-(sigma + mu) * s));
    ES                   = -slow * std::expm1(-2 * mu * s) / (2 * mu);
  }
  *q  = z * (Ec + sigma * ES) + zd * ES;
  *qd = zd * (Ec - sigma * ES) - w * w * z * ES;
}

// Bound on |q^(p)(s)| over s >= 0 for mode k above. The energy q'^2 + w^2 q^2 never grows
// (its rate is -4 sigma q'^2), so with u = (w q, q'), |u| <= R = hypot(w z, zd), and q^(p) =
// l_p . u with l_0 = (1/w, 0), l_1 = (0, 1), l_{p+2} = -2 sigma l_{p+1} - w^2 l_p. A rigid
// mode (w = 0) has q' = zd exp(-2 sigma s): |q^(p)| <= |zd| (2 sigma)^(p-1), p >= 1.
PetscReal ModalModeBound(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, int p)
{
  if (w == 0.0)
    return p == 0 ? std::abs(z) + (sigma > 0 ? std::abs(zd) / (2 * sigma) : PETSC_INFINITY)
                  : std::abs(zd) * std::pow(2 * sigma, p - 1);
  PetscReal l[2] = {1 / w, 0}, m[2] = {0, 1};
  for (int i = 0; i < p; ++i) {
    const PetscReal n0 = -2 * sigma * m[0] - w * w * l[0], n1 = -2 * sigma * m[1] - w * w * l[1];
    l[0] = m[0], l[1] = m[1], m[0] = n0, m[1] = n1;
  }
  return std::hypot(l[0], l[1]) * std::hypot(w * z, zd);
}

} // namespace beamimpact

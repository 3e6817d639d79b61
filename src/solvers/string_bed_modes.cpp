// The string bed on a 2-D DMDA: K and M, its modes (SLEPc) and its static deflection. See
// string_bed_modes.hpp.
#include "solvers/string_bed_modes.hpp"
#include "solvers/modes.hpp"

#include "system/string_bed_operator.hpp"

#include <petscksp.h>
#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace beamimpact {

PetscInt StringBedFreeCount(const BedGrid &g)
{
  PetscInt n = 0;
  for (PetscInt j = 0; j < g.nz; ++j)
    for (PetscInt i = 0; i < g.nx; ++i) n += BedNodeFree(g, i, j);
  return n;
}

namespace {

// Deterministic number in [-1, 1) from an index (splitmix64): the Krylov start vector, the same
// whatever the number of ranks.
PetscReal HashUniform(PetscInt i)
{
  std::uint64_t z = static_cast<std::uint64_t>(i) + 0x9e3779b97f4a7c15ULL;
  z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z               = z ^ (z >> 31);
  return 2.0 * static_cast<PetscReal>(z >> 11) / 9007199254740992.0 - 1.0; // 2^53
}

// The largest diagonal of K over the free nodes of every rank (the held rows' scale).
PetscErrorCode LargestFreeDiagonal(MPI_Comm comm, const BedGrid &g, const Membrane &m, const DMDALocalInfo &info,
                                   PetscReal *dmax)
{
  PetscReal local = 0;
  PetscFunctionBeginUser;
  for (PetscInt j = info.ys; j < info.ys + info.ym; ++j)
    for (PetscInt i = info.xs; i < info.xs + info.xm; ++i) local = std::max(local, BedStiffnessRow(g, m, i, j).diag);
  PetscCallMPI(MPI_Allreduce(&local, dmax, 1, MPIU_REAL, MPIU_MAX, comm));
  PetscFunctionReturn(0);
}

// A global vector of the DMDA to natural order (x fastest) on every rank.
PetscErrorCode GatherNatural(DM da, Vec x, std::vector<PetscReal> *out)
{
  Vec                nat, all;
  VecScatter         sc;
  const PetscScalar *a;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(DMDACreateNaturalVector(da, &nat));
  PetscCall(DMDAGlobalToNaturalBegin(da, x, INSERT_VALUES, nat));
  PetscCall(DMDAGlobalToNaturalEnd(da, x, INSERT_VALUES, nat));
  PetscCall(VecScatterCreateToAll(nat, &sc, &all));
  PetscCall(VecScatterBegin(sc, nat, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, nat, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetSize(all, &n));
  PetscCall(VecGetArrayRead(all, &a));
  out->assign(a, a + n);
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&nat));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode StringBedOperatorCreate(MPI_Comm comm, const BedGrid &g, const Membrane &m, DM *da, Mat *K, Mat *M)
{
  DMDALocalInfo info;
  PetscReal     dmax;
  PetscFunctionBeginUser;
  // No DMSetFromOptions: the grid is -strings_nodes's, not -da_grid_x's.
  PetscCall(DMDACreate2d(comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, g.nx, g.nz, PETSC_DECIDE,
                         PETSC_DECIDE, 1, 1, NULL, NULL, da));
  PetscCall(DMSetUp(*da));
  PetscCall(DMCreateMatrix(*da, K));
  PetscCall(DMCreateMatrix(*da, M));
  PetscCall(DMDAGetLocalInfo(*da, &info));
  PetscCall(LargestFreeDiagonal(comm, g, m, info, &dmax));
  const PetscInt di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
  for (PetscInt j = info.ys; j < info.ys + info.ym; ++j)
    for (PetscInt i = info.xs; i < info.xs + info.xm; ++i) {
      const BedRow r   = BedStiffnessRow(g, m, i, j);
      MatStencil   row = {0, 0, 0, 0}, cols[5];
      PetscScalar  vals[5];
      PetscInt     n = 1;
      row.i = i, row.j = j;
      cols[0] = row, vals[0] = r.held ? kHeldScale * dmax : r.diag;
      for (int d = 0; d < 4; ++d)
        if (r.off[d] != 0) {
          cols[n]   = row;
          cols[n].i = i + di[d], cols[n].j = j + dj[d];
          vals[n++] = r.off[d];
        }
      const PetscScalar mass = r.held ? m.sigma * g.hx * g.hz
                                      : r.mass; // a held node's: its eigenvalue kHeldScale dmax / (sigma h_x h_z)
      PetscCall(MatSetValuesStencil(*K, 1, &row, n, cols, vals, INSERT_VALUES));
      PetscCall(MatSetValuesStencil(*M, 1, &row, 1, &row, &mass, INSERT_VALUES));
    }
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyBegin(*M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(*K, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(*K, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  PetscCall(MatSetOption(*M, MAT_SPD, PETSC_TRUE));
  PetscFunctionReturn(0);
}

namespace {

// Krylov-Schur, shift-and-invert at 0 (K is positive definite: every free node is tied to the
// held edge), the start vector a hash of the natural index on the free nodes.
PetscErrorCode BedSolverCreate(MPI_Comm comm, const BedGrid &g, DM da, Mat K, Mat M, PetscInt count, EPS *eps)
{
  ST            st;
  KSP           ksp;
  Vec           x0;
  PetscScalar **a;
  DMDALocalInfo info;
  PetscFunctionBeginUser;
  PetscCall(EPSCreate(comm, eps));
  PetscCall(EPSSetOptionsPrefix(*eps, "strings_modes_"));
  PetscCall(EPSSetOperators(*eps, K, M));
  PetscCall(EPSSetProblemType(*eps, EPS_GHEP));
  PetscCall(EPSSetType(*eps, EPSKRYLOVSCHUR));
  PetscCall(EPSSetDimensions(*eps, count, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSetWhichEigenpairs(*eps, EPS_TARGET_MAGNITUDE));
  PetscCall(EPSSetTarget(*eps, 0.0));
  PetscCall(EPSSetTolerances(*eps, 1e-12, 1000));
  PetscCall(EPSGetST(*eps, &st));
  PetscCall(STSetType(st, STSINVERT));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(ModesDirectSolver(comm, ksp));
  PetscCall(DMCreateGlobalVector(da, &x0));
  PetscCall(DMDAGetLocalInfo(da, &info));
  PetscCall(DMDAVecGetArray(da, x0, &a));
  for (PetscInt j = info.ys; j < info.ys + info.ym; ++j)
    for (PetscInt i = info.xs; i < info.xs + info.xm; ++i)
      a[j][i] = BedNodeFree(g, i, j) ? 1.0 + 0.5 * HashUniform(j * g.nx + i) : 0.0;
  PetscCall(DMDAVecRestoreArray(da, x0, &a));
  PetscCall(EPSSetInitialSpace(*eps, 1, &x0));
  PetscCall(VecDestroy(&x0));
  PetscCall(EPSSetFromOptions(*eps));
  PetscFunctionReturn(0);
}

// Mode q of the solved EPS: omega^2 as the Rayleigh quotient (x, K x) / (x, M x), the shape in
// natural order, mass-normalised, 0 at held nodes, its sign fixed.
PetscErrorCode BedModeExtract(EPS eps, DM da, Mat K, Mat M, const BedGrid &g, const Membrane &m, PetscInt q,
                              PetscReal *omega2, std::vector<PetscReal> *shape)
{
  Vec         x, y;
  PetscScalar xKx, xMx;
  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(K, &x, &y));
  PetscCall(EPSGetEigenpair(eps, q, NULL, NULL, x, NULL));
  PetscCall(MatMult(K, x, y));
  PetscCall(VecDot(x, y, &xKx));
  PetscCall(MatMult(M, x, y));
  PetscCall(VecDot(x, y, &xMx));
  *omega2 = PetscRealPart(xKx) / PetscRealPart(xMx);
  PetscCall(GatherNatural(da, x, shape));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscReal norm = 0, amax = 0;
  for (PetscInt j = 0; j < g.nz; ++j)
    for (PetscInt i = 0; i < g.nx; ++i) {
      PetscReal &v = (*shape)[j * g.nx + i];
      if (!BedNodeFree(g, i, j)) v = 0;
      else norm += BedStiffnessRow(g, m, i, j).mass * v * v;
      amax = std::max(amax, std::abs(v));
    }
  norm         = std::sqrt(norm);
  size_t first = 0;
  while (first < shape->size() && std::abs((*shape)[first]) <= 1e-3 * amax) ++first;
  const PetscReal s = (first < shape->size() && (*shape)[first] < 0 ? -1 : 1) / norm;
  for (PetscReal &v : *shape) v *= s;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode StringBedModesCompute(MPI_Comm comm, const BedGrid &g, const Membrane &m, PetscInt count,
                                     StringBedModes *out)
{
  DM       da;
  Mat      K, M;
  EPS      eps;
  PetscInt nconv;
  PetscFunctionBeginUser;
  PetscCall(ModesEnsureSlepc());
  out->free_nodes = StringBedFreeCount(g);
  PetscCheck(count >= 1 && count <= out->free_nodes, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-modes_count %" PetscInt_FMT " is not allowed: the string bed has %" PetscInt_FMT
             " free nodes, so 1..%" PetscInt_FMT " modes exist (more -strings_nodes for more)",
             count, out->free_nodes, out->free_nodes);
  PetscCall(StringBedOperatorCreate(comm, g, m, &da, &K, &M));
  PetscCall(BedSolverCreate(comm, g, da, K, M, count, &eps));
  PetscCall(EPSSolve(eps));
  PetscCall(EPSGetConverged(eps, &nconv));
  PetscCall(EPSGetIterationNumber(eps, &out->iterations));
  PetscCheck(nconv >= count, comm, PETSC_ERR_NOT_CONVERGED,
             "the string bed's eigensolver found %" PetscInt_FMT " of the %" PetscInt_FMT
             " modes asked (-modes_count); raise -strings_modes_eps_max_it or -strings_modes_eps_ncv",
             nconv, count);
  out->omega.assign(count, 0);
  out->frequency.assign(count, 0);
  out->shape.assign(count, {});
  for (PetscInt q = 0; q < count; ++q) {
    PetscReal w2 = 0;
    PetscCall(BedModeExtract(eps, da, K, M, g, m, q, &w2, &out->shape[q]));
    out->omega[q]     = std::sqrt(std::max<PetscReal>(w2, 0));
    out->frequency[q] = out->omega[q] / (2 * M_PI);
  }
  PetscCall(EPSDestroy(&eps));
  PetscCall(MatDestroy(&K));
  PetscCall(MatDestroy(&M));
  PetscCall(DMDestroy(&da));
  PetscFunctionReturn(0);
}

PetscErrorCode StringBedStaticSolve(MPI_Comm comm, const BedGrid &g, const Membrane &m, const std::vector<PetscReal> &f,
                                    std::vector<PetscReal> *w)
{
  DM            da;
  Mat           K, M;
  KSP           ksp;
  Vec           b, x;
  PetscScalar **a;
  DMDALocalInfo info;
  PetscFunctionBeginUser;
  PetscCheck((PetscInt)f.size() == g.nx * g.nz, comm, PETSC_ERR_ARG_SIZ,
             "StringBedStaticSolve: %zu forces for %" PetscInt_FMT " nodes", f.size(), g.nx * g.nz);
  PetscCall(StringBedOperatorCreate(comm, g, m, &da, &K, &M));
  PetscCall(DMCreateGlobalVector(da, &b));
  PetscCall(VecDuplicate(b, &x));
  PetscCall(DMDAGetLocalInfo(da, &info));
  PetscCall(DMDAVecGetArray(da, b, &a));
  for (PetscInt j = info.ys; j < info.ys + info.ym; ++j)
    for (PetscInt i = info.xs; i < info.xs + info.xm; ++i) a[j][i] = BedNodeFree(g, i, j) ? f[j * g.nx + i] : 0.0;
  PetscCall(DMDAVecRestoreArray(da, b, &a));
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOperators(ksp, K, K));
  PetscCall(ModesDirectSolver(comm, ksp));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(GatherNatural(da, x, w));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&x));
  PetscCall(MatDestroy(&K));
  PetscCall(MatDestroy(&M));
  PetscCall(DMDestroy(&da));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

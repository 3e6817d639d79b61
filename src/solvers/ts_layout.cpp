// The TS stepper's DM layout (DMComposite of a DMDA beam and a DMRedundant ball), its index
// maps and array access. See ts_problem.hpp.
#include "solvers/ts_problem.hpp"

#include <petscdmcomposite.h>
#include <petscdmda.h>
#include <petscdmredundant.h>

#include <algorithm>

namespace beamimpact {

PetscInt TSLayout::NodeIndex(PetscInt i, PetscInt d) const
{
  const auto     it = std::upper_bound(node_owner_start.begin(), node_owner_start.end(), i);
  const PetscInt r  = static_cast<PetscInt>(it - node_owner_start.begin()) - 1;
  return rstart[r] + (i - node_owner_start[r]) * dof + d;
}

PetscInt TSLayout::BallIndex(PetscInt d) const
{
  const PetscInt nodes0 = node_owner_start.size() > 1 ? node_owner_start[1] : nodes; // nodes on rank 0
  return rstart[0] + nodes0 * dof + d;
}

// Checks the index formulas against the composite's own numbering.
static PetscErrorCode TSLayoutVerify(const TSLayout &L)
{
  IS *is;

  PetscFunctionBeginUser;
  PetscCall(DMCompositeGetGlobalISs(L.pack, &is));
  if (L.rank == 0) {
    const PetscInt *idx;
    PetscCall(ISGetIndices(is[1], &idx));
    PetscCheck(idx[0] == L.BallIndex(0), L.comm, PETSC_ERR_PLIB,
               "composite numbering of the ball (%" PetscInt_FMT ") differs from the assumed %" PetscInt_FMT, idx[0],
               L.BallIndex(0));
    PetscCall(ISRestoreIndices(is[1], &idx));
  }
  const PetscInt *idx;
  PetscInt        n;
  PetscCall(ISGetLocalSize(is[0], &n));
  PetscCall(ISGetIndices(is[0], &idx));
  PetscCheck(n == 0 || idx[0] == L.NodeIndex(L.xs, 0), L.comm, PETSC_ERR_PLIB,
             "composite numbering of the beam differs from the assumed one");
  PetscCall(ISRestoreIndices(is[0], &idx));
  PetscCall(ISDestroy(&is[0]));
  PetscCall(ISDestroy(&is[1]));
  PetscCall(PetscFree(is));
  PetscFunctionReturn(0);
}

PetscErrorCode TSLayoutCreate(MPI_Comm comm, PetscInt nodes, PetscInt fields, PetscInt ghost_nodes, bool first_order,
                              TSLayout *L)
{
  PetscFunctionBeginUser;
  L->comm = comm;
  PetscCallMPI(MPI_Comm_size(comm, &L->size));
  PetscCallMPI(MPI_Comm_rank(comm, &L->rank));
  L->fields = fields;
  L->nodes  = nodes;
  L->dof    = first_order ? 2 * fields : fields;
  PetscCall(DMDACreate1d(comm, DM_BOUNDARY_NONE, nodes, L->dof, ghost_nodes, NULL, &L->da));
  PetscCall(DMSetUp(L->da));
  if (fields == 1) {
    PetscCall(DMDASetFieldName(L->da, 0, "y"));
    if (first_order) PetscCall(DMDASetFieldName(L->da, 1, "v"));
  }
  PetscCall(DMRedundantCreate(comm, 0, first_order ? 2 : 1, &L->red));
  PetscCall(DMCompositeCreate(comm, &L->pack));
  PetscCall(DMCompositeAddDM(L->pack, L->da));
  PetscCall(DMCompositeAddDM(L->pack, L->red));
  PetscCall(DMSetUp(L->pack));
  PetscInt xs, xm;
  PetscCall(DMDAGetCorners(L->da, &xs, NULL, NULL, &xm, NULL, NULL));
  L->xs = xs;
  L->xe = xs + xm;
  const PetscInt *lx;
  PetscCall(DMDAGetOwnershipRanges(L->da, &lx, NULL, NULL));
  L->node_owner_start.assign(L->size, 0);
  for (PetscMPIInt r = 1; r < L->size; ++r) L->node_owner_start[r] = L->node_owner_start[r - 1] + lx[r - 1];
  Vec             U;
  const PetscInt *ranges;
  PetscCall(DMCreateGlobalVector(L->pack, &U));
  PetscCall(VecGetOwnershipRanges(U, &ranges));
  L->rstart.assign(ranges, ranges + L->size);
  PetscCall(VecDestroy(&U));
  PetscCall(TSLayoutVerify(*L));
  PetscFunctionReturn(0);
}

PetscErrorCode TSLayoutDestroy(TSLayout *L)
{
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&L->pack));
  PetscCall(DMDestroy(&L->da));
  PetscCall(DMDestroy(&L->red));
  PetscFunctionReturn(0);
}

PetscErrorCode TSStateReadBegin(const TSLayout &L, Vec U, TSStateRead *s)
{
  const PetscInt     nball = L.dof == L.fields ? 1 : 2;
  const PetscScalar *r;

  PetscFunctionBeginUser;
  if (L.size == 1) {
    PetscCall(DMCompositeGetAccess(L.pack, U, &s->Ub, &s->Ur));
    PetscCall(VecGetArrayRead(s->Ub, &s->arr));
    s->beam = s->arr;
  } else { // ghosted: the stencil reaches the neighbours' nodes
    PetscInt gxs;
    s->local = true;
    PetscCall(DMCompositeGetLocalVectors(L.pack, &s->Ub, &s->Ur));
    PetscCall(DMCompositeScatter(L.pack, U, s->Ub, s->Ur));
    PetscCall(DMDAGetGhostCorners(L.da, &gxs, NULL, NULL, NULL, NULL, NULL));
    PetscCall(VecGetArrayRead(s->Ub, &s->arr));
    s->beam = s->arr - gxs * L.dof;
  }
  PetscCall(VecGetArrayRead(s->Ur, &r));
  for (PetscInt d = 0; d < nball; ++d) s->ball[d] = r[d];
  PetscCall(VecRestoreArrayRead(s->Ur, &r));
  PetscFunctionReturn(0);
}

PetscErrorCode TSStateReadEnd(const TSLayout &L, Vec U, TSStateRead *s)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(s->Ub, &s->arr));
  if (s->local) PetscCall(DMCompositeRestoreLocalVectors(L.pack, &s->Ub, &s->Ur));
  else PetscCall(DMCompositeRestoreAccess(L.pack, U, &s->Ub, &s->Ur));
  PetscFunctionReturn(0);
}

PetscErrorCode TSStateWriteBegin(const TSLayout &L, Vec F, TSStateWrite *o)
{
  PetscFunctionBeginUser;
  PetscCall(DMCompositeGetAccess(L.pack, F, &o->Fb, &o->Fr));
  PetscCall(VecGetArray(o->Fb, &o->arr));
  PetscCall(VecGetArray(o->Fr, &o->rarr));
  o->beam = o->arr - L.xs * L.dof;
  o->ball = L.rank == 0 ? o->rarr : nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode TSStateWriteEnd(const TSLayout &L, Vec F, TSStateWrite *o)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArray(o->Fr, &o->rarr));
  PetscCall(VecRestoreArray(o->Fb, &o->arr));
  PetscCall(DMCompositeRestoreAccess(L.pack, F, &o->Fb, &o->Fr));
  PetscFunctionReturn(0);
}

PetscErrorCode TSCompression(const TSProblem &P, const PetscScalar *beam, PetscInt stride, PetscScalar ball_value,
                             PetscReal *c)
{
  const TSLayout &L = P.L;
  PetscReal       v = L.rank == 0 ? ball_value : 0.0;

  PetscFunctionBeginUser;
  for (PetscInt q = 0; q < P.g.n; ++q) {
    const PetscInt d = P.g.dof[q], node = d / L.fields;
    if (node >= L.xs && node < L.xe) v -= P.g.w[q] * beam[node * stride + d % L.fields];
  }
  if (L.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPIU_REAL, MPIU_SUM, L.comm));
  *c = v;
  PetscFunctionReturn(0);
}

const char *FormulationName(Formulation f)
{
  switch (f) {
  case Formulation::Explicit:
    return "explicit";
  case Formulation::IMEX:
    return "imex";
  case Formulation::Implicit:
    return "implicit";
  default:
    return "second-order";
  }
}

Formulation FormulationOfType(const char *type)
{
  auto is = [&](const char *t) { return std::string(type) == t; };
  if (is(TSALPHA2)) return Formulation::SecondOrder;
  if (is(TSRK) || is(TSEULER) || is(TSSSP) || is(TSGLEE) || is(TSMPRK) || is(TSBASICSYMPLECTIC) || is("modal"))
    return Formulation::Explicit;
  if (is(TSARKIMEX) || is(TSEIMEX) || is(TSMIMEX)) return Formulation::IMEX;
  return Formulation::Implicit;
}

} // namespace beamimpact

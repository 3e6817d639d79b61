// The string bed in a held frame on a 2-D DMDA (docs/model.md, "The string bed"): its stiffness K
// and lumped mass M assembled as PETSc matrices over the head's bounding box, distributed over
// the ranks of the communicator (PETSc chooses the split), its lowest modes by SLEPc and its
// static deflection under nodal forces.
//
// Every node of the box is a row. A free node's row is system/string_bed_operator.hpp's; a held
// node (outside or on the outline) is decoupled, with K = kHeldScale times the largest free
// diagonal and M its lumped mass, so its eigenvalue lies far above every wanted one and the
// wanted modes are exactly 0 there.
//
// Modes: K phi = omega^2 M phi, generalized Hermitian (K symmetric, M diagonal > 0),
// Krylov-Schur with shift-and-invert at 0 by the LU factorization of K (PETSc's LU on one rank,
// MUMPS on more), tolerance 1e-12; the Krylov start vector a hash of the node's natural index,
// so the result does not depend on the number of ranks. The EPS takes options with the prefix
// "strings_modes_" (-strings_modes_eps_view, ...).
#pragma once

#include "model/string_bed.hpp"

#include <petscdmda.h>

#include <vector>

namespace beamimpact {

constexpr PetscReal kHeldScale = 1e6;

// The DMDA over the grid (1 dof per node, star stencil of width 1) and K (N/m) and M (kg) on it
// (DMCreateMatrix, MatSetValuesStencil).
PetscErrorCode StringBedOperatorCreate(MPI_Comm comm, const BedGrid &g, const Membrane &m, DM *da, Mat *K, Mat *M);

// The number of free nodes: the unknowns of the bed.
PetscInt StringBedFreeCount(const BedGrid &g);

struct StringBedModes {
  std::vector<PetscReal> omega;     // rad/s, ascending
  std::vector<PetscReal> frequency; // Hz
  // shape[q][j * nx + i]: the deflection of mode q at node (i, j) (natural order: x fastest),
  // mass-normalised (sum sigma h_x h_z phi^2 = 1, kg^-1/2), 0 at held nodes; sign: the first
  // node above 1e-3 of the largest |phi| positive. On every rank.
  std::vector<std::vector<PetscReal>> shape;
  PetscInt                            free_nodes = 0;
  PetscInt                            iterations = 0; // the eigensolver's restarts
};

// The `count` lowest modes (1 <= count <= StringBedFreeCount(g)).
PetscErrorCode StringBedModesCompute(MPI_Comm comm, const BedGrid &g, const Membrane &m, PetscInt count,
                                     StringBedModes *out);

// The static deflection K w = f (m) under nodal forces f (N, natural order, the same on every
// rank; forces on held nodes are ignored), by the same LU; w in natural order on every rank.
PetscErrorCode StringBedStaticSolve(MPI_Comm comm, const BedGrid &g, const Membrane &m, const std::vector<PetscReal> &f,
                                    std::vector<PetscReal> *w);

} // namespace beamimpact

// The preconditioner of -ts_type irk's stage system (PETSc's TSIRK, Gauss-Legendre).
//
// TSIRK solves its s stages at once: the SNES unknown Z interleaves them (Z[r s + i] = Y_i[r])
// and its Jacobian is a MATKAIJ, I_n x S + J x T with S = A^-1/dt (A the method's s x s
// tableau), T = I_s and J = dG/dU of the IFunction at shift 0 (ts_jacobian.cpp: the assembled
// J, the contact's block included, at the last stage). PETSc 3.18 can neither factor a KAIJ
// matrix nor convert it cheaply, and GMRES without a preconditioner stalls or breaks down on
// a stiff beam (a swinging bat, the barrel shell).
//
// This PC (a PCSHELL, the irk branch's default; -pc_type none restores the old solve) is the
// exact inverse: the (s n) x (s n) stage matrix assembled as AIJ from J's rows and the KAIJ's
// S and T, row r s + i holding J[r][c] T[i][j] at column c s + j and S[i][j] at r s + j, then
// LU-factored (PETSc's own LU on one rank, MUMPS on more, as the other implicit types). It is
// refactored only when J or S changed (a new Jacobian: each Newton iteration in contact, where
// the contact stiffness moves, and a new step size); GMRES then converges in one iteration.
// Cost: s^2 x J's nonzeros stored and factored, for a banded beam s^2 times a band LU.
#pragma once

#include "solvers/ts_problem.hpp"

#include <petscksp.h>
#include <petscts.h>

namespace beamimpact {

// Make pc the stage-system LU for the TS whose callbacks' context is P (its assembled J,
// P.jac.J, is what the stage matrix is built from: the KAIJ's own AIJ is the same matrix on a
// fresh context, and a stale one after a reused context's new point).
PetscErrorCode IrkStagePCSet(TSProblem &P, PC pc);

// A reused context's new point rebuilds the assembled J (its pattern holds the contact point)
// and sets it on the TS, whose TSSetIJacobian hands J itself to the SNES in place of TSIRK's
// KAIJ (made once, at TSSetUp): the next step failed ("Matrix passed in is not of type KAIJ").
// This gives the SNES a KAIJ over the new J, as TSSetUp_IRK does; nothing for another type.
PetscErrorCode IrkStageNewJacobian(TS ts, Mat J);

// Before TSSetUp, on more than one rank: TSIRK (PETSc 3.18) makes its stage vector Z with
// PETSc's own split of s N entries (PETSC_DECIDE), which is not s times the state's split
// (the ball's dofs live on rank 0, and the beam's nodes split unevenly), so its first step
// failed ("Subvector length * blocksize ... not correct for scatter to multicomponent
// vector"). This gives TSIRK a Z laid out as s times the DM's global vector, per rank; the one
// use of TSIRK's private data (its leading members, checked against TSIRKGetNumStages and
// TSIRKGetType first). Nothing on one rank or for another type.
PetscErrorCode IrkStageLayout(TS ts, DM dm);

// After TSSetUp: TSIRK's Jacobian callback wrapped so that, on more than one rank, a new step
// size reaches the KAIJ's per-rank blocks (PETSc 3.18's MPIKAIJ copies S into them and renews
// the copies only when J's state changes; see irk_stage_pc.cpp). Nothing for another type.
PetscErrorCode IrkStageAfterSetUp(TS ts);

// Factorizations of the stage matrix done since the start (all contexts): for tests and -info.
PetscInt IrkStagePCFactorizations();

// The stage matrix's entries in one row block: for the KAIJ I_n x S + J x T (S, T s x s,
// column-major as MatKAIJGetS gives them; T null: the identity), the values of stage row
// r s + i at columns c s + j are J_rc T[i + s j] + (r == c) S[i + s j]. Plain, for the test.
PetscScalar IrkStageEntry(PetscInt s, const PetscScalar *S, const PetscScalar *T, PetscInt i, PetscInt j,
                          PetscScalar Jrc, bool diagonal);

} // namespace beamimpact

// Mode frequencies of the beam: the discrete modes from an eigen-solve of the
// semi-discrete operator (docs/model.md), and the continuum reference from
// the beta-L tables (docs/model.md).
//
// Discrete:   K phi = omega^2 M phi   over the free (not held) dofs, any number of fields
//   per node, K the stiffness of the system (system/beam_system.hpp), M = diag(mass) the
//   lumped mass per dof, omega in rad/s. Held dofs (clamped/pinned ends, clamped region)
//   are Dirichlet y = 0 and are not unknowns. Solved with SLEPc (GHEP, Krylov-Schur,
//   shift-and-invert at a small negative target so the rigid modes, omega = 0,
//   are found), on the communicator passed in; the result is replicated on
//   every rank. Each omega^2 is then the Rayleigh quotient 2 U(phi)/(phi^T M phi)
//   with U the strain energy (a sum of squared strains), which stays accurate
//   where eps ||M^-1 K|| would blur the solver's own eigenvalue (fine grids).
// Continuum:  omega_n = (beta_n L)^2 sqrt(EI / (mu L^4))  for the n-th flexural
//   mode of a uniform Euler-Bernoulli beam with the given end supports.
//
// Units: SI (m, kg, s, N); omega in rad/s, frequency in Hz, period in s.
#pragma once

#include "base/option_table.hpp"
#include "system/beam_system.hpp"

#include <petscksp.h>
#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

struct ModesParams {
  PetscInt count = 4; // number of modes to report, rigid ones included (-modes_count)
};

// SLEPc initialised on first use (a program that called only PetscInitialize: the tests);
// SlepcFinalize then runs with PetscFinalize.
PetscErrorCode ModesEnsureSlepc();
// A KSP (an ST's, a static solve's) as a direct solve: PETSc's LU on one rank, MUMPS on more.
PetscErrorCode ModesDirectSolver(MPI_Comm comm, KSP ksp);

// -modes_count: the modes module's table (registered by app/registry.cpp).
const OptionModule &ModesOptionTable();

// Reads -modes_count (one PetscOptionsBegin block, no prefix; >= 1 by its row) and checks,
// when op is given, that it is <= the number of free dofs of op.
// BeamModesCompute checks the upper bound again (with the same message).
PetscErrorCode ModesParamsFromOptions(MPI_Comm comm, ModesParams *p, const BeamSystem *op = nullptr);

// Nodes of a mode (m): the points strictly between free nodes where its deflection shape
// (one value per node, spacing h) changes sign, by linear interpolation. A tap test finds them.
std::vector<PetscReal> ModeNodes(const std::vector<PetscReal> &shape, PetscReal h);

struct ModesResult {
  std::vector<PetscReal> omega;           // rad/s, angular frequencies, ascending; rigid modes exactly 0
  std::vector<PetscReal> frequency;       // Hz, omega / (2 pi)
  std::vector<PetscReal> period;          // s, 2 pi / omega (0 for rigid modes)
  PetscInt               rigid_count = 0; // number of rigid modes among the reported ones
  // With a barrel wall (-beam_shell, -barrel_hoop_frequency): each mode's family, the group of
  // fields holding most of its kinetic energy: 0 the beam's bending, n a shell harmonic's, 2 the
  // hoop oscillator; empty without a wall. detail_account: the energy account of the part whose
  // details they are (StructureAccountOf: the wall's).
  std::vector<PetscInt> shell_n;
  PetscInt              detail_account = 0;
  // With a roll field or a string bed (-beam_torsion, -strings_frame): each mode's part
  // (its energy account, StructureAccountOf: the beam's bending 0, the roll, the bed) holding most of its
  // kinetic energy, and that part's share of it (a coupled mode has none near 1); the bed's
  // deflection of each mode on its grid, [z][x] (mass-normalised, 0 where not an unknown; with
  // the shapes only). Empty without them.
  std::vector<PetscInt>               part;
  std::vector<PetscReal>              part_share;
  std::vector<std::vector<PetscReal>> bed_shape;
  // How they were found: "shift-and-invert on K" (SLEPc on the stiffness), or "factored form"
  // (a fine grid of a statically determinate beam: BeamModesFactoredForm, beam_modes.hpp).
  std::string method;
};

// Relative threshold for rigid modes: a computed mode is rigid (reported as
// omega = 0) when omega < kModesRigidThreshold * sqrt(EI/mu) / L^2. The lowest
// flexural mode of a beam of length L with end supports or a clamped region is
// at least that of the clamped-free beam, 1.87510^2 = 3.5 sqrt(EI/mu)/L^2, so the
// gap is > 3000x. The rigid omega evaluated as a Rayleigh quotient of the strain
// energy is < 1e-4 of that unit up to N = 4001 (measured: 4e-5 at N = 4001, 1e-7
// at N = 641).
constexpr PetscReal kModesRigidThreshold = 1e-3;

// Number of free (not held) dofs: the size of the eigenproblem.
PetscInt BeamFreeDofCount(const BeamSystem &op);

// The first `count` modes (rigid ones included, counted from omega = 0 upward)
// of the discrete beam op, on communicator comm (any number of ranks; the
// result is the same on every rank). 1 <= count <= BeamFreeDofCount(op).
// shapes (optional): shapes[m][i] is the deflection (field 0) of mode m at node i (0 at
// held dofs), for all N nodes on every rank; the mode is mass-normalised over all its dofs
// (sum_d m_d phi_d^2 = 1, units kg^-1/2 for a deflection), sign fixed so that the first node
// with |phi_i| > 1e-3 max_d |phi_d| is positive.
// Degenerate modes (the two free-free rigid modes) are an arbitrary
// M-orthonormal basis of their space.
// The EPS takes options with the prefix "modes_" (e.g. -modes_eps_view). On a fine grid of a
// statically determinate beam (BeamModesFactoredForm: N > ~4000 for the paper's free beam) the
// modes come from the factored form instead (BeamModesLowestFactored, distributed over comm; the
// -modes_eps_* options are not read), as the modal engine's do: shift-and-invert on K loses them
// to round-off there (out->method says which).
PetscErrorCode BeamModesCompute(MPI_Comm comm, const BeamSystem &op, PetscInt count, ModesResult *out,
                                std::vector<std::vector<PetscReal>> *shapes = nullptr);

// The `count` lowest modes of op for the modal engine (solvers/beam_modes.hpp): the same
// shift-and-invert Krylov-Schur solve (SLEPc, on comm, the factorization of K + unit^2 M by
// PETSc's LU, MUMPS on more ranks), ascending, each omega^2 the Rayleigh quotient of the strain
// energy, each vector over all dofs, mass-normalised (0 at held dofs; signs as the solver's).
// progress > 0: a line every `progress` seconds while the solver runs (checked at each restart and each
// application of its operator; the converged count capped at `count`). mpd > 0: Krylov-Schur's
// largest projected dimension (EPSSetDimensions; 0: SLEPc's default, ncv = 2 count, whose
// orthogonalisation and projected problem grow as count^2 and count^3 per restart).
PetscErrorCode BeamModesLowest(MPI_Comm comm, const BeamSystem &op, PetscInt count, PetscReal progress,
                               std::vector<PetscReal> *lambda, std::vector<std::vector<PetscReal>> *phis,
                               PetscInt mpd = 0);

// The same from the factored form F of a statically determinate beam (BeamFactorCreate,
// solvers/beam_flexibility.hpp), for grids where shift-and-invert on K loses the low modes to
// eps cond(K) ~ eps 16 (L/h)^4 (the paper's beam at N = 40961): the rigid modes exactly
// (F.rigid, omega = 0), then the largest eigenvalues 1/omega^2 of M^{1/2} K^+ M^{1/2} by
// Krylov-Schur (SLEPc, a shell operator: two banded solves with S's LU per product), exact to
// eps (L/h)^2, each omega^2 the Rayleigh quotient of the strain energy. Collective on comm: the
// EPS's vectors are split over its ranks by rows (PETSC_DECIDE), so that the Krylov basis and
// its orthogonalisation are distributed; each product gathers z whole on every rank and does
// the two banded solves redundantly (O(n)); the eigenvectors are gathered whole to every rank.
// On P ranks the result agrees with one rank's to round-off (the reductions' order); on one
// rank it is the serial solve's, bit for bit. Ascending, as BeamModesLowest.
struct BeamFactor;
PetscErrorCode BeamModesLowestFactored(MPI_Comm comm, const BeamSystem &op, const BeamFactor &F, PetscInt count,
                                       PetscReal progress, std::vector<PetscReal> *lambda,
                                       std::vector<std::vector<PetscReal>> *phis);

// Rigid modes the held dofs allow, for any supports, clamped region or pivot: the number of
// BeamSystemRigidMotions (w = a + b x + c z, psi = b for a second field, the roll c with one;
// those that vanish on every held dof and strain nothing).
PetscInt BeamSystemRigidCount(const BeamSystem &op);

// BeamModesCompute checks that its lowest min(count, BeamSystemRigidCount(op)) modes are rigid
// (below kModesRigidThreshold): on very fine grids (measured for the paper's free-free and
// pinned-free beams: resolved at N = 15001, not at N >= 17001; docs/model.md) the round-off of the stiffness, whose
// largest eigenvalue is ~N^4 times the fundamental's, turns them into modes at a fraction of a hertz or loses them; the
// run is then refused (PETSC_ERR_NOT_CONVERGED) naming N, the expected count and the frequencies found, instead of
// reporting them as flexural modes.

// Rigid modes of a uniform beam with these end supports and no clamped region, from what the
// supports hold (SupportRigidModes, model/support.hpp): 2 for free-free (translation, rotation),
// 1 for pinned-free (rotation about the pin), 0 for the other built-in pairs.
PetscInt BeamModesRigidCount(Support left, Support right);

// Continuum reference: omega[n-1] = (beta_n L)^2 sqrt(EI/(mu L^4)) (rad/s) for the
// flexural modes n = 1..n_flexural (rigid modes not included) of a uniform beam
// of length L (m), EI (N m^2), mu (kg/m), with these end supports (order of
// left/right does not matter; no clamped region).
// beta_n L starts from the tables of docs/model.md and, beyond them, from the asymptotic
// formulas
//   free-free, clamped-clamped:  (2n+1) pi/2   (table 4.73004, 7.85320, 10.99561, 14.13717)
//   clamped-free:                (2n-1) pi/2   (table 1.87510, 4.69409, 7.85476, 10.99554)
//   pinned-free, clamped-pinned: (4n+1) pi/4   (table 3.92660, 7.06858, 10.21018)
//   pinned-pinned:                n pi         (exact)
// and is then polished by Newton's method on the characteristic equation
//   cos(bL) cosh(bL) = 1, cos(bL) cosh(bL) = -1, tan(bL) = tanh(bL)
// respectively, to full double precision. Returns PETSC_ERR_SUP for supports
// outside these combinations and PETSC_ERR_ARG_OUTOFRANGE for bad arguments.
PetscErrorCode BeamModesAnalytic(Support left, Support right, PetscReal L, PetscReal EI, PetscReal mu,
                                 PetscInt n_flexural, std::vector<PetscReal> *omega);

} // namespace beamimpact

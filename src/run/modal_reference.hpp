// The exact reference for the linear spring: the same semi-discrete impact solved in
// closed form between events with the modal tools (solvers/modal_basis.hpp), no time step,
// no tolerance, only round-off. The eigenvectors are refined by inverse iteration, so the
// reference stays exact as the h^-4 spectrum widens (each solve corrected by its residual in
// the factored form of K, so the modes are the system's, not those of the rounded band):
// against an independent eigen-solution (one-sided Jacobi SVD, tests/test_modal_reference.cpp)
// ACOR agrees to 2e-13 / 1.3e-10 at N = 161 / 641; measured against a 5(4) run at rtol
// 1e-12, ACOR agrees to 2e-14 / 6e-11 / 6e-9 and energy is conserved to 1e-14 / 4e-11 /
// 3e-9 at N = 41 / 161 / 641.
#pragma once

#include "run/impact.hpp"
#include "solvers/beam_modes.hpp"
#include "system/beam_system.hpp"

#include <string>

namespace beamimpact {

struct Scenario;

// Fills the outcome fields of an ImpactResult (acor, acor_corrected, contact_time(_total),
// peak_force, max_compression, contacts, events, ball_final_velocity, final_time,
// energy_error, beam energies at the end) for the linear law; the same window and cap
// rules as ImpactRun, so both see the same contacts. ts_type is "modal".
// PETSC_ERR_SUP for the hysteretic law. A damped beam (-beam_damping_mass,
// -beam_damping_stiffness): the separated phases are damped exactly, mode by mode
// (solvers/modal_basis.hpp); in contact, where the ball and the spring carry no damping and
// it is not proportional, the damped first-order modes of solvers/modal_damped.hpp (refused,
// PETSC_ERR_NOT_CONVERGED, if their eigenvectors are too ill-conditioned); the dissipated
// energy is beam_dissipated_end and is in energy_error.
PetscErrorCode ModalReferenceRun(const Scenario &scenario, ImpactResult *res);

// The same on the modes a truncation keeps (-modal_modes, -modal_tolerance; docs/model.md §12):
// when it keeps fewer than every mode, the kept beam modes and the ball with the contact spring
// in series with the static flexibility G_r of the modes left out, k' = k / (1 + k G_r), solved
// exactly (the reference of the truncated model, formulation "exact, truncated"; no memory
// limit: O(n k)). All, a truncation that keeps every mode, or a damped beam: the dense reference
// above, bit for bit. T (truncation.contact_time) defaults to the contact's time scale.
// The forms with comm are collective on it: a truncated basis (and an oblique impact's second
// plane) come from BeamModesShared on comm, the run's communicator when the reference is run
// by the ranks of a run (-reference modal, a study's reference); every rank then solves the
// same exact reference redundantly. The forms without comm run on PETSC_COMM_SELF: for a caller
// on one rank alone (a test, a rank-local study).
PetscErrorCode ModalReferenceRun(const Scenario &scenario, const ModalTruncation &truncation, ImpactResult *res);
PetscErrorCode ModalReferenceRun(MPI_Comm comm, const Scenario &scenario, const ModalTruncation &truncation,
                                 ImpactResult *res);
PetscErrorCode ModalReferenceRunSystem(const Scenario &scenario, const BeamSystem &sys,
                                       const ModalTruncation &truncation, ImpactResult *res);
PetscErrorCode ModalReferenceRunSystem(MPI_Comm comm, const Scenario &scenario, const BeamSystem &sys,
                                       const ModalTruncation &truncation, ImpactResult *res);

// Whether it can solve the scenario: the linear law, no grip; *why (may be null) says why not,
// naming the options, as "-reference modal <why>" reads. (The memory limit is checked when it
// runs, on the built system.)
bool ModalReferenceApplies(const Scenario &scenario, std::string *why);

// The same on a system already built (any number of fields per node); the scenario gives the
// ball, the impact rules and the time scales (its beam is not rebuilt).
PetscErrorCode ModalReferenceRunSystem(const Scenario &scenario, const BeamSystem &sys, ImpactResult *res);

// Memory (bytes) the modal reference's dense matrices need on a system: n = free beam dofs + 1
// (the ball); undamped 4 n^2 doubles (the contact and separated bases, the dense matrix and its
// copy), damped 32 n^2 (the first-order state matrices of size 2n and their inverses on top).
double ModalReferenceMemory(const BeamSystem &sys);

// The limit (bytes) ModalReferenceRunSystem refuses beyond: -reference_max_memory (GB, 1e9
// bytes) if given, else the run's limit (base/memory.hpp: -max_memory, default half of the
// physical memory).
double ModalReferenceMemoryLimit();

} // namespace beamimpact

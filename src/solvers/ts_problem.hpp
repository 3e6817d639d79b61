// Internal to the PETSc TS stepper (solvers/ts_*.cpp): the formulation chosen from the TS
// type, the DM layout of the state, the Jacobian cache and the callback counters. The
// physics comes from the system (system/beam_system.hpp: its force operator, with the swing's
// frame passed in) and the ball's contact law.
//
// State on a DMComposite of a 1-D DMDA (the beam: per node the deflection fields, then,
// in first-order form, their velocities) and a DMRedundant on rank 0 (the ball: y_b, then
// v_b in first-order form).
#pragma once

#include "model/contact.hpp"
#include "solvers/beam_modes.hpp"
#include "system/beam_system.hpp"

#include <petscts.h>

#include <cstdint>
#include <vector>

namespace beamimpact {

enum class Formulation {
  Explicit,
  IMEX,
  Implicit,
  SecondOrder
};
const char *FormulationName(Formulation f);
Formulation FormulationOfType(const char *ts_type);

// Where every unknown lives.
struct TSLayout {
  MPI_Comm              comm = MPI_COMM_NULL;
  PetscMPIInt           size = 1, rank = 0;
  PetscInt              nodes  = 0;
  PetscInt              fields = 1; // beam dofs per node
  PetscInt              dof    = 2; // DMDA components per node: fields (second-order form) or 2 fields
  DM                    pack = nullptr, da = nullptr, red = nullptr;
  PetscInt              xs = 0, xe = 0;   // owned nodes
  std::vector<PetscInt> node_owner_start; // first node of each rank
  std::vector<PetscInt> rstart;           // first composite global index of each rank

  PetscInt NodeIndex(PetscInt node, PetscInt comp) const; // composite global index
  PetscInt BallIndex(PetscInt comp) const;
  PetscInt DofIndex(PetscInt d, bool velocity) const
  {
    return NodeIndex(d / fields, (velocity ? fields : 0) + d % fields);
  }
  PetscInt D0() const { return xs * fields; } // owned beam dofs [D0, D1)
  PetscInt D1() const { return xe * fields; }
};
PetscErrorCode TSLayoutCreate(MPI_Comm comm, PetscInt nodes, PetscInt fields, PetscInt ghost_nodes, bool first_order,
                              TSLayout *L);
PetscErrorCode TSLayoutDestroy(TSLayout *L);

// The Jacobian J = shift I + d(rhs)/du, reassembled only when the shift or the contact
// stiffness changes; J0 (no shift, no contact) is assembled once and copied. K = df/dy and
// C = df/dv come from the force operator (BeamSystemStiffnessRow, BeamSystemDampingRow).
// With damping, the first-order J0 holds C/m in the velocity columns too; the second-order
// form adds shift_V Jd with Jd = C/m on J0's pattern (shift_V = dV/dX of the method).
//
// The program's default solve (-pc_type not given: PCSHELL "rank-one") never assembles or
// factors J: J = B + kc u v^T, B = B0 + shift I (+ shift_V Jd) the beam and the ball without
// the contact (a pattern that does not hold the contact point), u = D^-1 g on the rows of the
// coupled dofs and the ball, v = g on their position columns. B is LU-factored once per
// shift and kept (BeamFactor, a few shifts, the context's lifetime: every point of a sweep),
// J is a shell (B x + kc u v^T x) and the preconditioner is its exact inverse by
// Sherman-Morrison, J^-1 b = z - kc w (v^T z) / (1 + kc v^T w), z = B^-1 b, w = B^-1 u (one
// solve per point and shift). -pc_type lu (or any other) assembles and factors J as before.
struct BeamFactor {
  PetscReal shift = -1, shiftV = -1; // the shift it holds
  Mat       B      = nullptr;        // B0 + shift I (+ shift_V Jd)
  KSP       ksp    = nullptr;        // preonly + LU of B (MUMPS on more than one rank)
  Vec       w      = nullptr;        // B^-1 u for the point of generation `point`
  PetscReal vw     = 0;              // v^T w
  bool      finite = true;           // every entry of w is finite
  PetscInt  point  = -1;
  PetscInt  used   = 0; // uses, halved at each new point (the least used is replaced)
};
// The assembled J of the rank-one path's fallback (RankOneApply): created at the first solve
// whose Sherman-Morrison step is not finite or cancels, refactored when (shift, kc) changed,
// dropped at a new point (its pattern holds the contact point).
struct AssembledFallback {
  Mat       J = nullptr, J0 = nullptr, Jd = nullptr;
  KSP       ksp   = nullptr;                  // preonly + LU (MUMPS on more than one rank), as -pc_type lu
  PetscReal shift = -1, shiftV = -1, kc = -1; // what J holds
};
struct JacobianCache {
  Mat       J = nullptr, J0 = nullptr, Jd = nullptr;
  PetscReal shift = -1, kc = -1, shiftV = -1;
  bool      contact = false; // the contact force is in the implicit part
  // The rank-one path (rank_one): B0 and Jd without the coupling entries (kept with the
  // context), the factors per shift, u and v of the current point.
  bool                    rank_one = false;
  Mat                     B0 = nullptr, Bd = nullptr;
  std::vector<BeamFactor> factors;
  BeamFactor             *current = nullptr; // the factor of the current shift
  Vec                     u = nullptr, v = nullptr;
  std::vector<PetscInt>   v_idx; // v's owned nonzeros: local offsets in a global vector's array
  std::vector<PetscReal>  v_val;
  PetscInt                point = 0, factored = 0; // the point's generation; factorizations done (all runs)
  AssembledFallback       fallback;                // the solves the rank-one formula could not do
  PetscInt                fallbacks = 0;           // solves done by it (this context)
  std::uint64_t           structure = 0;           // the fingerprint of the structure B0 was built from
};
struct TSCounters {
  PetscInt func = 0, jac = 0, assembled = 0;
};

// Everything the TS callbacks need.
struct TSProblem {
  const BeamSystem      *sys   = nullptr;
  const FrameMotion     *frame = nullptr; // the swing's frame (owned by the run driver)
  ContactCoupling        g;
  BallParams             ball;
  ModalTruncation        truncation;        // -ts_type modal's modes (StepperProblem: read once by the run's set-up)
  ContactState          *contact = nullptr; // owned by the run driver
  Formulation            form    = Formulation::Explicit;
  TSLayout               L;
  JacobianCache          jac;
  TSCounters             count;
  std::vector<PetscReal> rate_acc,
    rate_cv; // TSDissipationRate: -a and C v of the owned dofs (kept: it runs every step)
};

// Read access to a composite vector: beam values by global node (ghosted by the system's
// width), the ball's values on every rank.
struct TSStateRead {
  const PetscScalar *beam    = nullptr; // beam[node * dof + comp]
  PetscScalar        ball[2] = {0, 0};
  Vec                Ub = nullptr, Ur = nullptr;
  const PetscScalar *arr   = nullptr;
  bool               local = false;
};
PetscErrorCode TSStateReadBegin(const TSLayout &L, Vec U, TSStateRead *s);
PetscErrorCode TSStateReadEnd(const TSLayout &L, Vec U, TSStateRead *s);

// Write access to the owned part of a composite vector.
struct TSStateWrite {
  PetscScalar *beam = nullptr; // beam[node * dof + comp] for owned nodes
  PetscScalar *ball = nullptr; // nullptr on ranks other than 0
  Vec          Fb = nullptr, Fr = nullptr;
  PetscScalar *arr = nullptr, *rarr = nullptr;
};
PetscErrorCode TSStateWriteBegin(const TSLayout &L, Vec F, TSStateWrite *o);
PetscErrorCode TSStateWriteEnd(const TSLayout &L, Vec F, TSStateWrite *o);

// c = y_b - g^T y (comp 0 of each field block: the deflection) or its rate (the velocity
// block), from a beam array with node stride `stride` starting at the block; summed over ranks.
PetscErrorCode TSCompression(const TSProblem &P, const PetscScalar *beam, PetscInt stride, PetscScalar ball_value,
                             PetscReal *c);

// The residuals (ts_residuals.cpp) and Jacobians (ts_jacobian.cpp) for each formulation.
PetscErrorCode TSRHSExplicit(TS ts, PetscReal t, Vec U, Vec G, void *ctx);
PetscErrorCode TSRHSContact(TS ts, PetscReal t, Vec U, Vec G, void *ctx);
PetscErrorCode TSIFunctionBeam(TS ts, PetscReal t, Vec U, Vec Udot, Vec G, void *ctx);
PetscErrorCode TSI2FunctionBeam(TS ts, PetscReal t, Vec X, Vec V, Vec A, Vec G, void *ctx);
PetscErrorCode TSIJacobianBeam(TS ts, PetscReal t, Vec U, Vec Udot, PetscReal shift, Mat A, Mat B, void *ctx);
PetscErrorCode TSI2JacobianBeam(TS ts, PetscReal t, Vec X, Vec V, Vec A, PetscReal shiftV, PetscReal shiftA, Mat J,
                                Mat B, void *ctx);
// Damped beam: the dissipation rate P = v^T C v (W) and its time derivative dP/dt = 2 a^T C v
// (W/s) at the state (X, and V for the second-order form, else nullptr), a the acceleration of
// the residual (contact force of the current phase); summed over ranks. For the dissipation
// rule (system/dissipation.hpp).
PetscErrorCode TSDissipationRate(TSProblem &P, PetscReal t, Vec X, Vec V, PetscReal *rate, PetscReal *rate_dot);
PetscErrorCode TSJacobianCreate(TSProblem &P);
PetscErrorCode TSJacobianDestroy(TSProblem &P);
// The rank-one path: the preconditioner set before the options (PCSHELL, the program's
// default), then, after them, the matrices of whichever solve the options chose (the shell J
// if the preconditioner is still the program's, else the assembled J), set on the TS.
// TSJacobianNewPoint: a reused context's next point (u, v anew; the factors kept).
PetscErrorCode TSJacobianSetDefaultPC(TSProblem &P, PC pc);
PetscErrorCode TSJacobianInstall(TSProblem &P, TS ts);
PetscErrorCode TSJacobianNewPoint(TSProblem &P, TS ts);
PetscInt       TSJacobianFactorizations(); // all contexts, since the start
// The Sherman-Morrison step of the rank-one solve, J^-1 b = z - kc w (v^T z) / (1 + kc v^T w):
// its denominator 1 + kc v^T w, or false where the step cannot be trusted: kc or the
// denominator not finite, or the denominator within kRankOneCancellation (1 + |kc v^T w|) of
// zero (the step would lose more than half the digits: J is singular to that accuracy, or
// v^T w = v^T B^-1 u is wrong; for a contact, kc >= 0 and v^T w > 0 make it >= 1). Then
// RankOneApply solves with the assembled J instead (its LU, PETSc's own path, as -pc_type lu),
// as it does when B^-1 b or w is not finite.
constexpr PetscReal kRankOneCancellation = 1.5e-8; // sqrt(eps)
bool                RankOneDenominator(PetscReal kc, PetscReal vw, PetscReal *den);

// Diagnostics (ts_diagnostics.cpp): a Newton convergence test that accepts the residual's
// round-off floor, and the explanation of a failed step.
struct NewtonFloor {
  TSProblem *P      = nullptr;
  TS         ts     = nullptr;
  PetscReal  omega2 = 0; // (rad/s)^2, bound on omega_max^2
};
PetscErrorCode TSConvergedWithRoundoffFloor(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm,
                                            SNESConvergedReason *reason, void *ctx);
PetscErrorCode TSCheckStep(const TSProblem &P, TS ts, const char *ts_type, PetscReal omega_max);

} // namespace beamimpact

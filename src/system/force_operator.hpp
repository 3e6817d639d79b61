// The forces of the semi-discrete beam (system/beam_system.hpp) as one operator: a short list
// of force terms, one file each, registered in the table kForceTerms of force_operator.cpp and
// summed by every function here. The equations of motion are
//
//   M a = -f(y, v, t; frame) + g F(c),        f = sum over the terms,
//
// f (N) the internal force of the state (y, v) at time t; `frame` the motion of the swing's
// rigid frame that the grip ties the handle to, passed in by the run and never stored in the
// system. The terms today, all affine in (y, v) with constant Jacobians:
//
//   elastic       (force_elastic.cpp)       B^T W B (y + beta v): the theory's strain terms, and
//                                           their viscous (Kelvin-Voigt) part, the stiffness
//                                           part beta K of Rayleigh damping, in one product
//   mass damping  (force_mass_damping.cpp)  alpha M v: the mass part of Rayleigh damping
//
// and after them the structure parts' terms (system/structure_part.hpp), in registry order: the
// hands' k_i (y_i - v_f,i t) + c_i (v_i - v_f,i) on the handle's dofs, tied to the frame (the
// hands' part in system/parts/), the absorber's dashpot;
//
// so K = df/dy, C = df/dv (Rayleigh: C = alpha M + beta K_elastic, plus the grip's c_i) and the
// drive f(0, 0, t). Every consumer calls this operator: the TS residuals of every formulation
// and their Jacobians (K and C as bands), the leapfrog (the bands and the drive), the modal
// tools (K, M and the proportional damping), the dissipation rule (system/dissipation.hpp) and
// the measures (energies, dissipation rate, the hands' force and work). A new term (a shell in
// series on extra fields per node, a string bed) is one new file with a ForceTerm and one line
// in kForceTerms. Plain arrays only, no PETSc objects.
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

namespace beamimpact {

struct BeamSystem;
struct ContactCoupling;

// The swing's rigid frame (model/swing.hpp): the hands hold the handle to it. Built by the run's
// set-up from the swing and the body (run/impact_driver.cpp); a bat at rest has a frame at rest.
struct FrameMotion {
  std::vector<PetscReal>
    v; // m/s (rad/s for rotation dofs), the frame's velocity per dof, a rigid motion of the free beam; empty: at rest
  PetscReal q0 = 0; // J, the frame's momentum term Q (ForceOperatorFrameMomentum plus the ball's) at t = 0: the hands'
                    // work is Q(t) - q0
  bool      Moves() const { return !v.empty(); }
  PetscReal At(PetscInt d) const { return v.empty() ? 0.0 : v[d]; }
};
// The frame's velocity at the ball's impact point, sum_q w_q v_f[dof_q] (m/s; 0 at rest).
PetscReal FrameMotionAt(const FrameMotion &frame, const ContactCoupling &g);

// A state as the terms read it: dof d of y at y[(d / fields) * ys + d % fields] (an array by
// global node, valid within the system's ghost width of the range asked for:
// BeamSystem::GhostNodes), v likewise.
struct ForceState {
  const PetscReal *y  = nullptr; // m (rad)
  PetscInt         ys = 1;       // node stride of y
  const PetscReal *v  = nullptr; // m/s (rad/s); nullptr: the velocity-dependent parts left out (callers pass none only
                                 // when no term damps)
  PetscInt           vs    = 1;  // node stride of v
  PetscReal          t     = 0;  // s
  const FrameMotion *frame = nullptr; // nullptr: the frame at rest
};

// How strong the damping is, for the explicit stability bounds: C <= rate M + stiffness K.
struct DampingScales {
  PetscReal mass_rate = 0; // 1/s, the diagonal (mass-like) damping over the mass: alpha, plus max c_i/m_i of a grip
  PetscReal stiffness = 0; // s, the stiffness-proportional factor beta
};

// One force term. Every function adds the term's share for the dofs [d0, d1) (or returns its
// partial sum over the dofs, and the terms they own): sums over a partition of the dofs add up
// to the whole, as over the ranks. Arrays f are indexed like y with node stride fs.
class ForceTerm {
public:
  virtual ~ForceTerm()             = default;
  virtual const char *Name() const = 0;
  // f += the term's force (N).
  virtual void AddForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                        PetscInt fs) const = 0;
  // f += its damping force C_term (v - v_ref) (N), v_ref the velocity the damper resists
  // relative to (the frame's for the grip, 0 otherwise): P' = 2 a^T (C v) of the dissipation rule.
  virtual void AddDampingForce(const BeamSystem &, const ForceState &, PetscInt, PetscInt, PetscReal *, PetscInt) const
  {
  }
  // f += its drive f(0, 0, t) (N): the force at zero deflection and velocity (a forcing in time).
  virtual void AddDrive(const BeamSystem &, PetscReal, const FrameMotion *, PetscInt, PetscInt, PetscReal *,
                        PetscInt) const
  {
  }
  // The constant Jacobians: K += df/dy and C += df/dv (N/m, N s/m; bands of half-width sys.bw:
  // entry (i, i + o - bw) at [(2 bw + 1) i + o]), or C's diagonal Cdiag += (N s/m per dof).
  // Rows and columns of held dofs are left out by the caller.
  virtual void AddJacobian(const BeamSystem &, PetscReal *K, PetscReal *C, PetscReal *Cdiag) const = 0;
  // Half-bandwidth (dofs) of its Jacobian, and how far beyond the range AddForce reads (dofs:
  // the ghost width of a distributed state, BeamSystem::GhostNodes).
  virtual PetscInt HalfWidth(const BeamSystem &) const { return 0; }
  virtual PetscInt Reach(const BeamSystem &) const { return 0; }
  // Energy stored in the term (J), a sum of squares.
  virtual PetscReal Energy(const BeamSystem &, const ForceState &, PetscInt, PetscInt) const { return 0; }
  // Dissipation rate (v - v_ref)^T C_term (v - v_ref) (W), a sum of squares: never negative.
  virtual PetscReal DissipationRate(const BeamSystem &, const ForceState &, PetscInt, PetscInt) const { return 0; }
  // A term tying the beam to the frame (TiesToFrame): the force of the beam on the frame (N) and
  // its moment about x = 0 (N m), added; and the power the frame puts in, sum v_f . (-f) (W).
  virtual bool TiesToFrame() const { return false; }
  virtual void AddFrameReaction(const BeamSystem &, const ForceState &, PetscInt, PetscInt, PetscReal *,
                                PetscReal *) const
  {
  }
  virtual PetscReal DrivePower(const BeamSystem &, const ForceState &, PetscInt, PetscInt) const { return 0; }
  // A term not tied to the frame: G(y, v) with dG/dt = v_f^T f along any motion (N m/s x s: J),
  // in closed form (0 when v_f^T f = 0, as for forces without resultant and moment).
  virtual PetscReal     FrameImpulse(const BeamSystem &, const ForceState &, PetscInt, PetscInt) const { return 0; }
  virtual bool          Damps() const { return false; }
  virtual DampingScales Scales(const BeamSystem &) const { return DampingScales(); }
  // Whether the beam's free-vibration modes (solvers/beam_modes.hpp) can carry the term: it
  // is constant in time and its damping is proportional, added to *alpha (C = alpha M) or
  // *beta (C = beta K); else false and why not.
  virtual bool Modal(PetscReal *, PetscReal *, std::string *) const { return true; }
};

// The force terms of a system and their assembled damping (the stiffness band K is the
// system's: BeamSystem::band).
struct ForceOperator {
  std::vector<std::shared_ptr<const ForceTerm>> terms; // in the registration order
  std::vector<PetscReal>
    damping_band; // N s/m: C less its diagonal part, in the layout of BeamSystem::band (empty: none)
  std::vector<PetscReal> damping_diag;   // N s/m: the diagonal part of C per dof (empty: none)
  bool                   damped = false; // a term damps
  bool                   framed = false; // a term ties the beam to the swing's frame (the frame's motion matters)
  PetscInt               reach  = 0;     // dofs: how far beyond a range the terms read (ForceTerm::Reach)

  const ForceTerm *Find(const char *name) const;
};

// The registry: creates the terms of the beam (those it has: no damping term for an undamped
// beam, no grip without one) in the order of kForceTerms. A term may add to sys->mass (the
// hands' mass) when created; ForceOperatorAssemble then builds the Jacobians.
void ForceOperatorCreate(const BeamParams &p, BeamSystem *sys);
// K (BeamSystem::band; bw widened to the terms' half-widths) and C from the terms, held rows
// and columns left out (called by BeamSystemAssemble, once the strain terms are indexed).
void ForceOperatorAssemble(BeamSystem *sys);

// f = the internal force of s (N) on the dofs [d0, d1): every term; rows of held dofs 0.
void ForceOperatorApply(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                        PetscInt fs);
// f = C (v - v_ref) (N): the damping forces of every term (0 rows for held dofs).
void ForceOperatorDampingApply(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                               PetscInt fs);
// f = f(0, 0, t) (N): the drives of every term (0 without one).
void ForceOperatorDrive(const BeamSystem &sys, PetscReal t, const FrameMotion *frame, PetscInt d0, PetscInt d1,
                        PetscReal *f, PetscInt fs);
// Energy stored in the terms (J): the elastic one (the strain energy) and the others (a grip's
// springs, ...).
void ForceOperatorEnergy(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *elastic,
                         PetscReal *others);
// Dissipation rate sum of the terms' (v - v_ref)^T C (v - v_ref) (W), >= 0 by construction.
PetscReal ForceOperatorDissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1);
// The force of the beam on the frame (N) and its moment about x = 0 (N m), added to *force, *moment.
void ForceOperatorFrameReaction(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *force,
                                PetscReal *moment);
// The power the frame puts into the beam (W).
PetscReal ForceOperatorDrivePower(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1);
// Whether the frame's motion enters the forces (a term ties the beam to it) and it moves.
bool ForceOperatorDriven(const BeamSystem &sys, const FrameMotion *frame);
// The beam's share of the frame's momentum term Q = v_f^T M v + sum of the terms' FrameImpulse
// (J). With the ball's m_b v_f(x) v_b, dQ/dt = -v_f^T f_frame-terms = the power the frame puts
// in (for a rigid v_f of a free beam, as the grip requires), so the hands' work since t = 0 is
// Q(t) - Q(0) in closed form (docs/model.md, "The hands"). Needs s.y and s.v; 0 unless
// ForceOperatorDriven.
PetscReal ForceOperatorFrameMomentum(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1);
// The damping scales summed over the terms.
DampingScales ForceOperatorDampingScales(const BeamSystem &sys);
// Whether every term is modal (see ForceTerm::Modal); *alpha and *beta then give C = alpha M + beta K.
bool ForceOperatorModal(const BeamSystem &sys, PetscReal *alpha, PetscReal *beta, std::string *why);

} // namespace beamimpact

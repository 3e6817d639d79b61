// The semi-discrete system of one scenario, built once and consumed by every solver (the
// PETSc TS residuals and Jacobians, the leapfrog baseline, the modal reference, the modes
// solver): none of them assembles anything of its own.
//
//   M y'' = -K y + g F(c),   m_b y_b'' = -F(c),   c = y_b - g_beam^T y,
//
// M the lumped masses (diagonal, per dof), K = B^T W B the stiffness from the theory's
// strain terms (banded: half-bandwidth bw dofs), held dofs (rows and columns of K zero, no
// force), and the contact coupling g: the hat-function share of the impact point between
// its two neighbouring nodes (held dofs get no share). Dofs are node-major: dof = node x
// fields + field; field 0 is the transverse deflection (m). Plain arrays only.
#pragma once

#include "model/beam_theory.hpp"
#include "model/contact.hpp"
#include "model/swing.hpp"

#include <petscsys.h>

#include <algorithm>
#include <string>
#include <vector>

namespace beamimpact {

struct BeamSystem {
  PetscInt  nodes = 0, fields = 1, ndof = 0;
  PetscReal L = 0, h = 0;                  // m, length and node spacing
  std::vector<PetscReal>  mass;            // kg (or kg m^2), per dof
  std::vector<char>       held;            // 1 where the dof is held at 0
  std::vector<StrainTerm> strain;          // U = 1/2 sum weight (b . y)^2, sorted by owner dof
  std::vector<PetscInt>   strain_begin;    // terms owned by dof d: [strain_begin[d], strain_begin[d+1])
  PetscInt                bw = 0;          // half-bandwidth of K (dofs)
  PetscInt                reach = 0;       // max |dof - owner| over the strain terms
  std::vector<PetscReal>  band;            // N/m: K(i, i+o-bw) = band[(2 bw + 1) i + o]
  PetscReal               frequency_unit = 0; // rad/s, sqrt(EI/mu)/L^2
  PetscReal               damping_mass = 0;      // 1/s, alpha: C = alpha M + beta K (Rayleigh)
  PetscReal               damping_stiffness = 0; // s,   beta
  // The hands (BeamParams::grip; empty vectors without a grip): per dof the grip's spring k_i
  // (N/m, also on the diagonal of band and in K y), damper c_i (N s/m, in C v beside the
  // Rayleigh terms) and the velocity of the swing's rigid frame v_f,i (m/s, set by the driver:
  // zero for a bat at rest). The force of the hands on dof i is
  //   -k_i (y_i - v_f,i t) - c_i (v_i - v_f,i).
  // grip_drive0: r^T M v + m_b r_b v_b + alpha r^T M y at t = 0 (r = v_f; the hands' work is its
  // change, BeamSystemGripDrive).
  std::vector<PetscReal>  grip_k, grip_c, grip_v;
  PetscReal               grip_damping = 0;      // N s/m, sum of c_i (> 0: the grip damps)
  PetscReal               grip_drive0 = 0;       // kg m^2/s^2

  bool      Gripped() const { return !grip_k.empty(); }

  PetscInt  Dof(PetscInt node, PetscInt field = 0) const { return node * fields + field; }
  PetscReal NodeX(PetscInt node) const { return node * h; }
  // Ghost width (nodes) a distributed state needs for K y and the strain energy.
  bool      Damped() const { return damping_mass > 0 || damping_stiffness > 0 || grip_damping > 0; }
  PetscInt  GhostNodes() const { return (std::max(bw, 2 * reach) + fields - 1) / fields; }
};

// Builds the system of the beam with its theory (BeamParams::theory). Returns false with
// *why when the theory is unknown.
bool BeamSystemBuild(const BeamParams &p, BeamSystem *sys, std::string *why);

// The ball's coupling to the beam: c = y_b - (w[0] y[dof[0]] + w[1] y[dof[1]]); the force F
// acts as +w[q] F on dof[q] and -F on the ball. Weights of held dofs are 0.
struct ContactCoupling {
  PetscInt  dof[2] = {0, 0};
  PetscReal w[2]   = {0, 0};
  PetscReal x      = 0; // m, the impact point
};
ContactCoupling BeamSystemCoupling(const BeamSystem &sys, PetscReal x_imp);

// f_i = (K y)_i (N) for dofs i in [d0, d1), in the factored form B^T W B y. y holds dof d at
// y[(d / fields) * node_stride + d % fields], valid for d within 2 reach of [d0, d1) (a ghosted
// array indexed by global node); f likewise with out_stride. Rows of held dofs are 0.
void BeamSystemStiffnessApply(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt out_stride);

// The nonzeros of row i of K (at most 2 bw + 1; columns of held dofs left out); returns the count.
PetscInt BeamSystemStiffnessRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals);

// Strain energy (J) of the terms owned by dofs [d0, d1) (a sum of squares); y as above.
PetscReal BeamSystemStrainEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0, PetscInt d1);

// Kinetic energy (J) of dofs [d0, d1); v as y above.
PetscReal BeamSystemKineticEnergy(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0, PetscInt d1);

// Velocities (per dof) of the rigid motion with deflection velocity v0 + slope x (m/s) and,
// for a beam with rotation dofs, section spin `slope` (rad/s): a free motion (K annihilates
// it). Held dofs get 0.
std::vector<PetscReal> BeamSystemRigidVelocity(const BeamSystem &sys, PetscReal v0, PetscReal slope);
// The swinging bat's velocities at contact (model/swing.hpp): V(x) toward the ball, i.e. -y.
std::vector<PetscReal> BeamSystemSwingVelocity(const BeamSystem &sys, const SwingParams &swing, const BeamRigidBody &body);

// Mass (kg) of the translational dofs that are not held.
PetscReal BeamSystemFreeMass(const BeamSystem &sys);

// Upper bound (Gershgorin) on the largest angular frequency (rad/s) of M^{-1} K plus a
// contact stiffness k_extra (N/m) through the coupling to a ball of mass m_extra (kg).
PetscReal BeamSystemMaxFrequencyBound(const BeamSystem &sys, const ContactCoupling &g, PetscReal k_extra, PetscReal m_extra);

// Rayleigh damping C = alpha M + beta K (BeamSystem::damping_mass, damping_stiffness).
// f_i = (C v)_i (N) for dofs i in [d0, d1): alpha m_i v_i + beta (K v)_i with K v in the factored
// form of BeamSystemStiffnessApply (so C annihilates rigid motion when alpha = 0); v and f as
// y and f there (v valid within 2 reach of [d0, d1) when beta != 0). Rows of held dofs are 0.
void BeamSystemDampingApply(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt out_stride);

// Dissipation rate v^T C v (W) of the dofs [d0, d1) and the strain terms they own: alpha sum m v^2
// + beta sum_k weight_k (b_k . v)^2, a sum of squares (>= 0 by construction, no cancellation);
// sums over a partition of the dofs add up to the whole. v as y of BeamSystemStrainEnergy.
PetscReal BeamSystemDissipationRate(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0, PetscInt d1);

// The grip (BeamSystem::grip_*), for dofs [d0, d1); y, v as for BeamSystemStrainEnergy.
// Stored energy 1/2 sum k_i (y_i - v_f,i t)^2 (J).
PetscReal BeamSystemGripEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0, PetscInt d1, PetscReal t);
// The force of the beam on the hands, sum k_i (y_i - v_f,i t) + c_i (v_i - v_f,i) (N), and its
// moment about x = 0, sum x_i (...) (N m), added to *force and *moment.
void BeamSystemGripForce(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs, PetscInt d0, PetscInt d1, PetscReal t, PetscReal *force, PetscReal *moment);
// The beam's share of the hands' drive Q = r^T M v + alpha r^T M y (r = v_f), whose change
// (with the ball's m_b r_b v_b) is the work the hands do on the bat: for a free beam K r = 0,
// so dQ/dt = r^T F_hands (docs/model.md, "The hands").
PetscReal BeamSystemGripDrive(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs, PetscInt d0, PetscInt d1);
// The frame's velocity at the ball's impact point, r_b = g^T v_f (m/s; 0 without a grip).
PetscReal BeamSystemGripFrameAt(const BeamSystem &sys, const ContactCoupling &g);
// Largest c_i/m_i (1/s) over the grip (0 without one): the stability bounds treat it as alpha.
PetscReal BeamSystemGripRate(const BeamSystem &sys);

} // namespace beamimpact

namespace beamimpact {

// Scales of the contact against this beam, shared by every solver's defaults and checks.
struct ContactScales {
  PetscReal time        = 0; // s, contact time T_r against the beam's free mass (the ball's mass reduced with the beam's)
  PetscReal compression = 0; // m, v_i sqrt(m_b / k_eff)
  PetscReal speed       = 0; // m/s, the incident speed
  PetscReal stiffness   = 0; // N/m, bound on dF/dc over the contact (stability bounds)
};
ContactScales ContactScalesOf(const BeamSystem &sys, const BallParams &ball);

} // namespace beamimpact

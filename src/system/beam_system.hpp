// The semi-discrete system of one scenario, built once and consumed by every solver (the
// PETSc TS residuals and Jacobians, the leapfrog baseline, the modal reference, the modes
// solver): none of them assembles anything of its own.
//
//   M y'' = -f(y, y', t; frame) + g F(c),   m_b y_b'' = -F(c),   c = y_b - g^T y,
//
// M the lumped masses (diagonal, per dof), f the internal forces of the force operator
// (system/force_operator.hpp: the elastic strain terms K = B^T W B of the theory, damping, the
// grip, ...; K = df/dy banded, half-bandwidth bw dofs), held dofs (rows and columns of K zero,
// no force), and the contact coupling g: a short list of (dof, weight), today the hat-function
// share of the impact point between its two neighbouring nodes (held dofs get no share). Dofs
// are node-major: dof = node x fields + field; field 0 is the transverse deflection (m). The
// motion of the swing's frame is the run's (FrameMotion), passed to the operator, never stored
// here. A barrel's hoop oscillator (-barrel_hoop_frequency, model/barrel.hpp) is one more field
// per node, free only at node 0 (wall_dof), a coupled dof of weight 1. Plain arrays only.
#pragma once

#include "model/beam_theory.hpp"
#include "model/contact.hpp"
#include "model/swing.hpp"
#include "system/force_operator.hpp"

#include <petscsys.h>

#include <algorithm>
#include <string>
#include <vector>

namespace beamimpact {

struct BeamSystem {
  PetscInt  nodes = 0, fields = 1, ndof = 0;
  PetscInt  beam_fields = 1;               // the theory's fields per node (1, or 2 with a rotation); fields after them are the barrel wall's
  PetscInt  wall_dof    = -1;              // the hoop oscillator's dof (model/barrel.hpp), -1 without
  PetscReal wall_stiffness = 0;            // N/m, its spring k_h
  PetscInt  shell_first = -1;              // the shell's first field (-beam_shell, model/shell.hpp): harmonic k's W_n is field shell_first + 3 k + 2
  std::vector<PetscInt> shell_harmonics;   // n of each harmonic
  PetscReal shell_contact_radius = 0;      // m, the ball's load patch a on the wall (model/shell.hpp; 0: a point load)
  std::vector<PetscReal> shell_radius;     // m, the wall's midsurface radius R per node (0 where solid)
  PetscReal L = 0, h = 0;                  // m, length and node spacing
  std::vector<PetscReal>  mass;            // kg (or kg m^2), per dof (with a grip's hands)
  std::vector<char>       held;            // 1 where the dof is held at 0
  std::vector<StrainTerm> strain;          // U = 1/2 sum weight (b . y)^2, sorted by owner dof
  std::vector<PetscInt>   strain_begin;    // terms owned by dof d: [strain_begin[d], strain_begin[d+1])
  PetscInt                bw = 0;          // half-bandwidth of K and C (dofs)
  PetscInt                reach = 0;       // max |dof - owner| over the strain terms
  std::vector<PetscReal>  band;            // N/m: K = df/dy of every force term, K(i, i+o-bw) = band[(2 bw + 1) i + o]
  PetscReal               frequency_unit = 0; // rad/s, sqrt(EI/mu)/L^2
  ForceOperator           forces;          // the force terms, and C = df/dv

  PetscInt  Dof(PetscInt node, PetscInt field = 0) const { return node * fields + field; }
  PetscReal NodeX(PetscInt node) const { return node * h; }
  bool      Damped() const { return forces.damped; }
  bool      Gripped() const { return forces.Find("grip") != nullptr; }
  // Whether field f is a section rotation (Timoshenko's field 1), which a rigid rotation turns.
  bool      Rotation(PetscInt f) const { return f == 1 && beam_fields > 1; }
  // Ghost width (nodes) a distributed state needs for the forces and the strain energy.
  PetscInt  GhostNodes() const { return (std::max({bw, 2 * reach, forces.reach}) + fields - 1) / fields; }
};

// Builds the system of the beam with its theory (BeamParams::theory). Returns false with
// *why when the theory is unknown.
bool BeamSystemBuild(const BeamParams &p, BeamSystem *sys, std::string *why);
// Indexes the strain terms (strain_begin, reach, bw) and assembles K and C from the force
// terms (ForceOperatorAssemble): part of BeamSystemBuild, and again after a system's layout was
// changed by hand (tests).
void BeamSystemAssemble(BeamSystem *sys);

// The ball's coupling to the beam: c = y_b - sum_q w[q] y[dof[q]] over the n entries; the
// force F acts as +w[q] F on dof[q] and -F on the ball. Today the two hat entries of the
// impact point's nodes (weights of held dofs 0); a shell's radial dofs under the ball or a
// second bending plane would be more entries. Every consumer loops over the n entries.
struct ContactCoupling {
  static constexpr PetscInt kMaxEntries = 64; // a shell's patch: up to 20 nodes per harmonic
  PetscInt  n = 0;                  // entries used
  PetscInt  dof[kMaxEntries] = {};  // coupled dofs
  PetscReal w[kMaxEntries]   = {};  // their weights (1)
  PetscReal x                = 0;   // m, the impact point
  // Whether dof d is coupled, and its weight (the sum over its entries; 0 if not coupled).
  bool Couples(PetscInt d) const
  {
    for (PetscInt q = 0; q < n; ++q)
      if (dof[q] == d) return true;
    return false;
  }
  PetscReal WeightOf(PetscInt d) const
  {
    PetscReal s   = 0.0;
    bool      hit = false;
    for (PetscInt q = 0; q < n; ++q)
      if (dof[q] == d) s = hit ? s + w[q] : w[q], hit = true;
    return s;
  }
};
ContactCoupling BeamSystemCoupling(const BeamSystem &sys, PetscReal x_imp);

// f_i = (K y)_i (N) for dofs i in [d0, d1), K = df/dy of every force term (the elastic
// strain terms in the factored form B^T W B y, a grip's springs): the force of the deflection y
// at rest. y holds dof d at y[(d / fields) * node_stride + d % fields], valid for d within the
// ghost width of [d0, d1) (a ghosted array indexed by global node); f likewise with
// out_stride. Rows of held dofs are 0.
void BeamSystemStiffnessApply(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt out_stride);

// The nonzeros of row i of K (at most 2 bw + 1; columns of held dofs left out); returns the count.
PetscInt BeamSystemStiffnessRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals);
// The nonzeros of row i of C = df/dv (the damping band and its diagonal part), likewise.
PetscInt BeamSystemDampingRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals);

// Strain energy (J) of the terms owned by dofs [d0, d1) (a sum of squares); y as above.
PetscReal BeamSystemStrainEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0, PetscInt d1);

// The barrel wall's energies (J) over the dofs [d0, d1): *stored (its strain terms: 1/2 k_h w^2 of
// the hoop oscillator, the shell's) and *kinetic, its shares of BeamSystemStrainEnergy and
// BeamSystemKineticEnergy (the fields after the beam's); 0 without a wall. y, v as y above.
void BeamSystemWallEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt y_stride, const PetscReal *v, PetscInt v_stride, PetscInt d0, PetscInt d1, PetscReal *stored, PetscReal *kinetic);

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

// f_i = (C v)_i (N) for dofs i in [d0, d1), C = df/dv of every force term (Rayleigh: alpha m_i v_i
// + beta (K v)_i, K v of the strain terms in the factored form, so C annihilates rigid motion
// when alpha = 0; a grip's dampers), the frame at rest; v and f as y and f of
// BeamSystemStiffnessApply. Rows of held dofs are 0. (ForceOperatorDampingApply with a frame.)
void BeamSystemDampingApply(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt out_stride);

// Dissipation rate v^T C v (W) of the dofs [d0, d1) and the strain terms they own, the frame at
// rest: alpha sum m v^2 + beta sum_k weight_k (b_k . v)^2 (+ a grip's sum c v^2), a sum of squares
// (>= 0 by construction, no cancellation); sums over a partition of the dofs add up to the
// whole. v as y of BeamSystemStrainEnergy. (ForceOperatorDissipationRate with a frame.)
PetscReal BeamSystemDissipationRate(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0, PetscInt d1);

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

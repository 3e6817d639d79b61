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
// here. The registered structure parts (system/structure_part.hpp: the frame's roll, the barrel
// wall, a racket's string bed, ...) append their fields after the theory's (the bed one field per
// node of its column across the face, the ball's coupling its nodes under the ball's patch).
// Plain arrays only.
#pragma once

#include "model/beam_theory.hpp"
#include "model/contact.hpp"
#include "model/swing.hpp"
#include "system/force_operator.hpp"
#include "system/structure_part.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace beamimpact {

struct BeamSystem {
  PetscInt nodes = 0, fields = 1, ndof = 0;
  PetscInt
    beam_fields = 1; // the theory's fields per node (1, or 2 with a rotation); fields after them are the barrel wall's
  std::vector<PetscInt>   field_account; // each field's energy account (StructureAccountOf: 0 the beam's)
  std::vector<PetscReal>  field_z; // m, per field: a deflection at z across the axis (StructurePart::FieldZ), or NaN
  std::vector<PetscInt>   face_fields;  // the fields with a z (ascending; none without a string bed)
  PetscReal               L = 0, h = 0; // m, length and node spacing
  std::vector<PetscReal>  mass;         // kg (or kg m^2), per dof (with a grip's hands)
  std::vector<char>       held;         // 1 where the dof is held at 0
  std::vector<StrainTerm> strain;       // U = 1/2 sum weight (b . y)^2, sorted by owner dof
  std::vector<PetscInt>   strain_begin; // terms owned by dof d: [strain_begin[d], strain_begin[d+1])
  PetscInt                bw    = 0;    // half-bandwidth of K and C (dofs)
  PetscInt                reach = 0;    // max |dof - owner| over the strain terms
  std::vector<PetscReal>  band;         // N/m: K = df/dy of every force term, K(i, i+o-bw) = band[(2 bw + 1) i + o]
  PetscReal               frequency_unit = 0; // rad/s, sqrt(EI/mu)/L^2
  ForceOperator           forces;             // the force terms, and C = df/dv
  // The registered structure parts present (system/structure_part.hpp), in registry order, and
  // their dofs a rigid motion carries as the beam's deflection at a point (none without parts).
  std::vector<PartInstance> parts;
  std::vector<RigidPoint>   rigid_points;

  PetscInt  Dof(PetscInt node, PetscInt field = 0) const { return node * fields + field; }
  PetscReal NodeX(PetscInt node) const { return node * h; }
  bool      Damped() const { return forces.damped; }
  // Whether a force term ties the structure to the swing's frame (ForceTerm::TiesToFrame: the hands).
  bool TiedToFrame() const
  {
    for (const auto &t : forces.terms)
      if (t->TiesToFrame()) return true;
    return false;
  }
  // The field of the frame's roll phi (rad): the first of the part present that rolls
  // (PartParams::Rolls, -beam_torsion); -1 without. A lookup: keep it out of per-dof loops.
  PetscInt RollField() const
  {
    for (const PartInstance &s : parts)
      if (s.params->Rolls()) return s.first;
    return -1;
  }
  // Whether field f is a section rotation (Timoshenko's field 1), which a rigid rotation turns.
  bool Rotation(PetscInt f) const { return f == 1 && beam_fields > 1; }
  // The energy account of field f (a system laid out by hand: the beam's, 0).
  PetscInt AccountOf(PetscInt f) const { return f < (PetscInt)field_account.size() ? field_account[f] : 0; }
  // Whether field f is a part's deflection at z across the axis (StructurePart::FieldZ: a string
  // bed's): anchored on the frame's section, its held dofs move with it.
  bool Face(PetscInt f) const { return f < (PetscInt)field_z.size() && !std::isnan(field_z[f]); }
  // Whether field f is a deflection (m) toward the ball: the beam's (field 0) or a face's. Their
  // masses carry the momentum; a rigid motion y = a + b x + c z moves them all.
  bool Deflection(PetscInt f) const { return f == 0 || Face(f); }
  // The point (x along the beam, z across from its axis; m) of dof d's deflection.
  PetscReal DofZ(PetscInt d) const { return Face(d % fields) ? field_z[d % fields] : 0.0; }
  // Ghost width (nodes) a distributed state needs for the forces and the strain energy.
  PetscInt GhostNodes() const { return (std::max({bw, 2 * reach, forces.reach}) + fields - 1) / fields; }
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
  static constexpr PetscInt kMaxEntries = 256;     // a shell's patch: up to 20 nodes per harmonic; a string bed's patch
  PetscInt                  n           = 0;       // entries used
  PetscInt                  dof[kMaxEntries] = {}; // coupled dofs
  PetscReal                 w[kMaxEntries]   = {}; // their weights (1)
  PetscReal                 x                = 0;  // m, the impact point
  PetscReal                 z                = 0;  // m, across the face from the frame's axis (-impact_z; 0: on it)
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
// The coupling of a ball striking at x_imp along the beam and z_imp across it (m): a part's own
// where the point strikes it (StructurePart::CoupleInstead: a string bed's nodes under the ball's
// disc); elsewhere the hat of the beam's nodes, then each part's entries (StructurePart::Couple:
// with a roll field their roll times z_imp).
ContactCoupling BeamSystemCoupling(const BeamSystem &sys, PetscReal x_imp, PetscReal z_imp = 0);

// f_i = (K y)_i (N) for dofs i in [d0, d1), K = df/dy of every force term (the elastic
// strain terms in the factored form B^T W B y, a grip's springs): the force of the deflection y
// at rest. y holds dof d at y[(d / fields) * node_stride + d % fields], valid for d within the
// ghost width of [d0, d1) (a ghosted array indexed by global node); f likewise with
// out_stride. Rows of held dofs are 0.
void BeamSystemStiffnessApply(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0, PetscInt d1,
                              PetscReal *f, PetscInt out_stride);

// The nonzeros of row i of K (at most 2 bw + 1; columns of held dofs left out); returns the count.
PetscInt BeamSystemStiffnessRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals);
// The nonzeros of row i of C = df/dv (the damping band and its diagonal part), likewise.
PetscInt BeamSystemDampingRow(const BeamSystem &sys, PetscInt i, PetscInt *cols, PetscReal *vals);

// Strain energy (J) of the terms owned by dofs [d0, d1) (a sum of squares); y as above.
PetscReal BeamSystemStrainEnergy(const BeamSystem &sys, const PetscReal *y, PetscInt node_stride, PetscInt d0,
                                 PetscInt d1);

// The energies (J) of each energy account (StructureAccountCount of them: the beam's, then the
// parts' own) over the dofs [d0, d1): stored[a] the strain terms of account a owned there,
// kinetic[a] its dofs'; they sum to BeamSystemStrainEnergy and BeamSystemKineticEnergy. y, v as
// y above.
void BeamSystemAccountEnergies(const BeamSystem &sys, const PetscReal *y, PetscInt y_stride, const PetscReal *v,
                               PetscInt v_stride, PetscInt d0, PetscInt d1, PetscReal *stored, PetscReal *kinetic);

// Kinetic energy (J) of dofs [d0, d1); v as y above.
PetscReal BeamSystemKineticEnergy(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0,
                                  PetscInt d1);

// Velocities (per dof) of the rigid motion with deflection velocity v0 + slope x + roll z (m/s)
// at every deflection (the beam's and a string bed's), section spin `slope` (rad/s) for a beam
// with rotation dofs and `roll` (rad/s) for its roll field: a free motion (K annihilates it).
// Held dofs get 0.
std::vector<PetscReal> BeamSystemRigidVelocity(const BeamSystem &sys, PetscReal v0, PetscReal slope,
                                               PetscReal roll = 0);
// The structure's rigid motions before its holds (translation, pitch about x = 0, and with a roll
// field the roll about the axis), as displacements per dof (held dofs included): v0 = 1, slope =
// 1 (rad), roll = 1 (rad) of BeamSystemRigidVelocity without the holds.
std::vector<std::vector<PetscReal>> BeamSystemRigidCandidates(const BeamSystem &sys);
// The rigid motions the holds leave: the combinations of the candidates that vanish on every
// held dof and that the stiffness annihilates (|K v| <= 1e-9 max|K| max|v|: an Euler-Bernoulli
// clamp holds the rotation through its mirrored curvature, not a held dof), held dofs 0. A string
// bed's held dofs (its nodes outside the head or on its edge) are no supports: nothing of the
// structure is there (the bed's edge moves with its frame section), so they do not count.
std::vector<std::vector<PetscReal>> BeamSystemRigidMotions(const BeamSystem &sys);
// The swinging bat's velocities at contact (model/swing.hpp): V(x) toward the ball, i.e. -y.
std::vector<PetscReal> BeamSystemSwingVelocity(const BeamSystem &sys, const SwingParams &swing,
                                               const BeamRigidBody &body);

// Mass (kg) of the deflection dofs (the beam's, a string bed's, a part's rigid points) that are not held.
PetscReal BeamSystemFreeMass(const BeamSystem &sys);

// Upper bound (Gershgorin) on the largest angular frequency (rad/s) of M^{-1} K plus a
// contact stiffness k_extra (N/m) through the coupling to a ball of mass m_extra (kg).
// With `where`, the dof whose row sets the bound (-1: the ball's own 2 k_extra / m_extra).
PetscReal BeamSystemMaxFrequencyBound(const BeamSystem &sys, const ContactCoupling &g, PetscReal k_extra,
                                      PetscReal m_extra, PetscInt *where = nullptr);

// The energy account holding most of a motion's kinetic energy (-task modes and /modes_energy label
// a mode by its StructureAccountName): e[r] the kinetic energy (any unit) of dof dof[r] (dof ==
// nullptr: of dof r), r < n; *share (if given) its fraction of the sum (0 if the sum is 0).
PetscInt BeamSystemDominantAccount(const BeamSystem &sys, const PetscInt *dof, const PetscReal *e, PetscInt n,
                                   PetscReal *share);

// Words for the part of the structure a dof belongs to ("the beam's bending", "the frame's roll",
// "the barrel wall", "the string bed", a registered part's Words()), for messages.
const char *BeamSystemPartWords(const BeamSystem &sys, PetscInt dof);

// f_i = (C v)_i (N) for dofs i in [d0, d1), C = df/dv of every force term (Rayleigh: alpha m_i v_i
// + beta (K v)_i, K v of the strain terms in the factored form, so C annihilates rigid motion
// when alpha = 0; a grip's dampers), the frame at rest; v and f as y and f of
// BeamSystemStiffnessApply. Rows of held dofs are 0. (ForceOperatorDampingApply with a frame.)
void BeamSystemDampingApply(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0, PetscInt d1,
                            PetscReal *f, PetscInt out_stride);

// Dissipation rate v^T C v (W) of the dofs [d0, d1) and the strain terms they own, the frame at
// rest: alpha sum m v^2 + beta sum_k weight_k (b_k . v)^2 (+ a grip's sum c v^2), a sum of squares
// (>= 0 by construction, no cancellation); sums over a partition of the dofs add up to the
// whole. v as y of BeamSystemStrainEnergy. (ForceOperatorDissipationRate with a frame.)
PetscReal BeamSystemDissipationRate(const BeamSystem &sys, const PetscReal *v, PetscInt node_stride, PetscInt d0,
                                    PetscInt d1);

} // namespace beamimpact

namespace beamimpact {

// Scales of the contact against this beam, shared by every solver's defaults and checks.
struct ContactScales {
  PetscReal time = 0; // s, contact time T_r against the beam's free mass (the ball's mass reduced with the beam's)
  PetscReal compression = 0; // m, v_i sqrt(m_b / k_eff)
  PetscReal speed       = 0; // m/s, the incident speed
  PetscReal stiffness   = 0; // N/m, bound on dF/dc over the contact (stability bounds)
};
ContactScales ContactScalesOf(const BeamSystem &sys, const BallParams &ball);

} // namespace beamimpact

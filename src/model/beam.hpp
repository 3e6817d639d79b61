// The beam as the options describe it (BeamParams): length, nodes, sections (model/section.hpp:
// EI, mu, kappa G A may vary along x), supports and holds (model/support.hpp), the pivot and a
// clamped region; with what every theory needs of it: how each node is held, the rigid body, the
// impact point's hat weights and the fundamental's scale. Units: SI (m, kg, s, N).
//
// The theories build their strain terms from these (model/beam_theory.hpp: Euler-Bernoulli in
// model/euler_bernoulli.cpp, Timoshenko in model/timoshenko.cpp), the system its stiffness and
// forces (system/beam_system.hpp). Everything here is plain numbers and arrays: no PETSc
// objects, so it can be tested against formulas. The -beam_* options are read by
// io/beam_options.hpp.
#pragma once

#include "model/section.hpp"
#include "model/support.hpp"

#include <petscsys.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace beamimpact {

// What the user gave, kept for the record (HDF5 attributes); 0 when not given.
struct BeamMaterialInput {
  PetscReal   youngs_modulus      = 0; // Pa
  PetscReal   density             = 0; // kg/m^3
  PetscReal   width               = 0; // m (b)
  PetscReal   thickness           = 0; // m (a, in the direction of motion)
  PetscReal   mass                = 0; // kg (M)
  PetscReal   youngs_over_density = 0; // N m / kg (E / rho)
  std::string parameter_set;           // "E,rho,a,b" | "M,L,a,E/rho" | "EI,mu" | "profile" | "table"
};

// The hands (-grip x_a,x_b): a spring-damper per unit length over [x_a, x_b] tying the handle's
// deflection to the swing's rigid frame, and an optional hand mass spread over the same span
// (GripNodeWeights: the per-dof weights; the hands' structure part in system/parts/: where it
// enters, held in BeamParams::parts).
struct BeamGrip {
  bool      on  = false;
  PetscReal x_a = 0, x_b = 0;      // m
  PetscReal stiffness         = 0; // N/m per m of handle
  PetscReal damping           = 0; // N s/m per m
  PetscReal mass              = 0; // kg, the hands (added to the translational dofs of the grip)
  PetscReal torsion_stiffness = 0; // N m/rad per m of handle: the hands' hold on the frame's roll (-beam_torsion)
  PetscReal torsion_damping   = 0; // N m s/rad per m
};

// The barrel wall's hoop oscillator in series with the ball (issue 23, MODEL.md section 9, the
// lumped alternative; model/barrel.hpp): a wall mass on a spring k_h = m_h (2 pi f_h)^2 loaded by
// the contact force, its displacement added to the compression. Part of the barrel wall's
// structure part (system/parts/wall.cpp), present in BeamParams::parts with -barrel_hoop_frequency.
struct BarrelHoop {
  PetscReal frequency = 0; // Hz, f_h (a bat lab's tap-test hoop frequency)
  PetscReal mass      = 0; // kg, m_h, the wall's mass in the hoop mode
};

// The barrel wall as a thin cylindrical shell (-beam_shell; model/shell.hpp): Sanders-Koiter
// harmonics on the hollow part of a profile. Part of the barrel wall's structure part
// (system/parts/wall.cpp), present in BeamParams::parts with -beam_shell.
struct BarrelShell {
  std::vector<PetscInt> harmonics = {2, 3, 4}; // circumferential orders n >= 2
  PetscReal contact_radius = -1; // m, the ball's load patch a (-shell_contact_radius; 0: a point load; < 0: not yet
                                 // derived from the ball)
  PetscReal
    youngs_modulus = 0; // Pa, the wall's E in the shell (-shell_youngs_modulus; 0: the profile's, -beam_youngs_modulus)
};

// The frame's twist about its own axis (-beam_torsion; model/torsion.hpp): one more field per
// node, the roll phi (rad), with G J (phi')^2/2 per length and rho J phi_t^2/2. A racket's head
// rolls under an off-axis hit (-impact_z). A structure part (system/parts/roll.cpp), present in
// BeamParams::parts with -beam_torsion.
struct BeamTorsion {
  PetscReal stiffness = 0; // N m^2, G J of a uniform section (-beam_torsion_stiffness; 0: the section's)
  PetscReal inertia   = 0; // kg m, rho J per length of a uniform section (-beam_torsion_inertia; 0: the section's)
};

// A registered structure part's own parameters (system/structure_part.hpp: the registry of
// parts, one file each in system/parts/): each part derives its struct, filled by its option
// module; BeamParams holds those of the parts present, by the part's name. Only the part's own
// file reads its struct; what the model needs of every part is here.
struct BeamParams;
struct PartParams {
  virtual ~PartParams() = default;
  // Its share of the rigid body (BeamRigidBodyOf): m0 kg, m1 kg m, m2 kg m^2 about x = 0, roll
  // kg m^2 about the frame's axis. Nothing by default.
  virtual void AddRigidBody(SectionMoments *) const { }
  // The same with the beam at hand (a part whose share depends on the beam's sections); by default
  // AddRigidBody's.
  virtual void AddRigidBodyOn(const BeamParams &, SectionMoments *m) const { AddRigidBody(m); }
  // Whether it is the frame's roll about its own axis (the roll's part): a hit off the axis
  // (-impact_z) turns it, a rigid motion of the structure includes the roll, a string bed on the
  // frame rolls with it and the hands may hold it (-grip_torsion_*). No by default.
  virtual bool Rolls() const { return false; }
  // The numbers a system built on the beam depends on beyond the options (a value resolved at the
  // impact point: the shell's patch radius a, m): a sweep builds a new system when they change.
  virtual std::vector<PetscReal> SystemKey() const { return {}; }
};
struct PartParamSet {
  std::vector<std::pair<std::string, std::shared_ptr<const PartParams>>> present; // in registry order
  const PartParams      *Find(const char *name) const;                            // nullptr: the part is absent
  bool                   Has(const char *name) const { return Find(name) != nullptr; }
  void                   Set(const char *name, std::shared_ptr<const PartParams> p); // replaces; nullptr removes
  bool                   Rolls() const;     // some part present is the frame's roll (PartParams::Rolls)
  std::vector<PetscReal> SystemKey() const; // every present part's SystemKey, in order
};

struct BeamParams {
  PetscReal         length = 1.1;   // m
  PetscReal         EI     = 0;     // N m^2, bending stiffness (uniform; with a profile or table, its mean)
  PetscReal         mu     = 0;     // kg/m, mass per length (uniform; with a profile or table, mass / L)
  PetscReal         kGA    = 0;     // N, shear stiffness kappa G A of a uniform section (0: unknown)
  PetscReal         rhoI   = 0;     // kg m, rotary inertia per length rho I of a uniform section (0: unknown)
  BeamSection       section;        // where the section varies (profile or table); source Uniform: the scalars above
  PetscInt          nodes     = 41; // number of grid nodes N (>= 5)
  Support           left      = Support::Free;   // support at x = 0 (model/support.hpp registry)
  Support           right     = Support::Free;   // support at x = L
  bool              has_clamp = false;           // a clamped region [clamp_x0, clamp_x1] is held fixed
  PetscReal         clamp_x0 = 0, clamp_x1 = 0;  // m
  bool              has_pivot         = false;   // an interior point pinned (y = 0, free rotation): a test rig's pivot
  PetscReal         pivot_x           = 0;       // m, on a node (BeamPivotNode)
  std::string       theory            = "euler"; // beam theory (model/beam_theory.hpp registry)
  PetscReal         damping_mass      = 0;       // 1/s, alpha of the Rayleigh damping C = alpha M + beta K
  PetscReal         damping_stiffness = 0;       // s,   beta
  PartParamSet      parts;                       // the registered structure parts present (none by default)
  BeamMaterialInput input;
  // The whole beam is a frame held still (a held string bed's, set up by its part: StructurePart::
  // Frame): nothing to grip, pivot, roll or attach.
  bool frame_held = false;
};

// The section at x (m): the uniform scalars or the profile/table rows.
SectionProperties BeamSectionAt(const BeamParams &p, PetscReal x);
// The mean section over [a, b] (m): the uniform scalars, or the cell integrals / (b - a).
SectionProperties BeamSectionMean(const BeamParams &p, PetscReal a, PetscReal b);

// The beam as a rigid body, from its sections (exact integrals): what a scale, a balance point
// and a pendulum measure. The moments of inertia are about a transverse axis; a Timoshenko
// beam's include the sections' own rotary inertia (int rho I), as its dynamics do (for a bat
// about 0.1% of the total).
struct BeamRigidBody {
  PetscReal mass         = 0; // kg
  PetscReal x_cm         = 0; // m, centre of mass from x = 0
  PetscReal inertia_cm   = 0; // kg m^2, about the centre of mass
  PetscReal inertia_end  = 0; // kg m^2, about the x = 0 end (the knob of a bat)
  PetscReal inertia_roll = 0; // kg m^2, about the frame's own axis (int rho J and a string bed's sigma z^2; 0 without
                              // -beam_torsion)
};
BeamRigidBody BeamRigidBodyOf(const BeamParams &p);

// The node of the pivot (has_pivot): the nearest to pivot_x.
PetscInt BeamPivotNode(const BeamParams &p);

// How each node is held (NodeHold of model/support.hpp: its deflection, its rotation, both):
// the end nodes as their supports hold them, the pivot's node pinned (deflection), every node
// of a clamped region clamped (both).
std::vector<NodeHold> BeamNodeHolds(const BeamParams &p);

// Hat-function share of an impact point between its two neighbouring nodes of a grid of N
// nodes over [0, L] (m): the compression uses w*y_j + (1-w)*y_{j+1}.
struct ImpactStencil {
  PetscInt  j = 0; // left node
  PetscReal w = 1; // weight of node j; node j+1 gets 1-w
};
ImpactStencil GridImpactStencil(PetscInt N, PetscReal L, PetscReal x_imp);

// Lowest flexural angular frequency (rad/s) of the continuum beam with these end
// supports (analytic beta L); with a clamped region the free span beyond its
// inner edge is treated as clamped there. Used only to size default windows.
PetscReal BeamFundamentalFrequencyEstimate(const BeamParams &p);

} // namespace beamimpact

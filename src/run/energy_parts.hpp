// Where the structure's energy is at the end of a run, split without overlap (docs/model.md
// section 4, "Where the energy went"): its rigid motions (the M-orthogonal projection of its
// velocities on the rigid motions its holds leave: translation, rotation, roll) and, part by
// part (the beam's bending, the frame's twist, the string bed, the barrel wall), the rest, its
// flexible energy. The parts' flexible energies and the rigid motions' energies add up to the
// structure's kinetic and strain energy exactly (Pythagoras in the mass inner product: the
// rigid motions strain nothing), so that with the ball's, the damping's and the hands' terms the
// outcome's fractions of E_in close to 1 (run/results_table.cpp). The same labels name the modes
// of a modal free flight's /modes_energy, whose per-part sums are the same fractions.
#pragma once

#include "model/beam.hpp"
#include "run/impact.hpp"
#include "run/measures.hpp"
#include "solvers/beam_modes.hpp"
#include "system/beam_system.hpp"

#include <vector>

namespace beamimpact {

// A rigid motion the outcome reports, as a velocity field over the dofs (held dofs 0):
// Translation 1 on every deflection (the beam's and a string bed's); Rotation x - x_axis on the
// deflections and 1 on a Timoshenko section's rotation; Roll z on a string bed's deflections and 1
// on the frame's roll.
enum class RigidKind : int {
  Translation = 0,
  Rotation    = 1,
  Roll        = 2
};
constexpr int kRigidKinds = 3;
const char   *RigidKindName(RigidKind k); // "translation", "rotation", "roll"

struct RigidMotion {
  RigidKind kind   = RigidKind::Translation;
  PetscReal x_axis = 0; // m, a rotation's axis along the beam
};

// The rigid motions the holds of `beam` leave, in the order they are orthogonalised: a structure
// with no held dof (free, gripped or swinging): translation, rotation (about x = 0, which the
// orthogonalisation against the translation moves to the centre of mass), and the roll with
// -beam_torsion; held at one pin only (-beam_pivot or one pinned end, no clamp): the rotation about
// it, and the roll with -beam_torsion; two pins or more: the roll with -beam_torsion; a clamp
// (a clamped end, -beam_clamp, a held string bed's frame): none.
std::vector<RigidMotion> ReportedRigidMotions(const BeamParams &beam);
// Whether `beam` has a rigid motion of kind k (the results table's predicates).
bool HasRigidMotion(const BeamParams &beam, RigidKind k);

// The split at the end of a run (J): rigid[k] the energy of the rigid motion of kind k after the
// orthogonalisation (NaN where the structure has none), flexible[a] the rest of energy account a's
// energy (system/structure_part.hpp: StructureAccountCount of them, 0 the beam's; the wall's is all
// flexible: rigid motions do not move it).
struct EnergySplit {
  PetscReal rigid[kRigidKinds];
  PetscReal flexible[kMaxAccounts];
};
EnergySplit EnergySplitOf(const BeamParams &beam, const BeamSystem &sys, const StateMeasures &m);

// Labels the modes of a modal free flight's energies (ModeEnergy::part): a rigid mode by the
// reported rigid motion it is (the largest overlap in the mass inner product), a flexible one by the
// account holding most of its kinetic energy, as -task modes names them (StructureAccountName).
void ModeEnergiesLabel(const BeamParams &beam, const BeamModes &modes, std::vector<ModeEnergy> *energies);

} // namespace beamimpact

// A beam theory turns the beam's parameters into its discrete mechanics, as plain arrays:
// the lumped mass of every degree of freedom, which ones are held, and the strain energy as
// a sum of squares
//
//   U = 1/2 sum_k weight_k (sum_q b_kq y_{dof_kq})^2      (J; y in m, or rad for rotations)
//
// from which the stiffness K = B^T W B follows (system/beam_system.hpp assembles it once).
// Writing U as squares keeps energies free of cancellation and makes K symmetric positive
// semi-definite by construction, with the rigid motions in its null space whenever every
// term annihilates them. A theory is a function registered by name (BeamTheoryFind):
// Euler-Bernoulli is model/euler_bernoulli.cpp, Timoshenko (two fields per node, bending and
// shear terms) model/timoshenko.cpp: a new theory is one more file and one more line in the
// registry (kTheories in model/beam_theory.cpp).
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

#include <vector>

namespace beamimpact {

// One term of the strain energy: weight (b . y)^2 / 2 over at most six dofs (the beams use up to
// four; a shell's membrane strain ex + nu et six, a string bed's link along the frame six).
struct StrainTerm {
  PetscInt  n       = 0; // entries used
  PetscInt  dof[6]  = {0, 0, 0, 0, 0, 0};
  PetscReal b[6]    = {0, 0, 0, 0, 0, 0}; // 1/m^2 (curvature), 1/m or 1 (shear, strain)
  PetscReal weight  = 0;                  // N m^2 x m (EI h), or N x m (kappa G A h)
  PetscInt  owner   = 0;                  // the dof whose rank evaluates this term (sums over ranks partition U)
  PetscInt  account = 0; // its energy account: 0 the beam's; a structure part's own (system/structure_part.hpp)
};

// The discrete beam of a theory (every array over dofs = nodes x fields, node-major).
struct BeamDiscretization {
  PetscInt                fields = 1;         // dofs per node (1: deflection; 2: deflection, rotation)
  std::vector<PetscReal>  mass;               // kg (translation) or kg m^2 (rotation), lumped, per dof
  std::vector<char>       held;               // 1 where the dof is held at 0
  std::vector<StrainTerm> strain;             // sorted by owner
  PetscReal               frequency_unit = 0; // rad/s, sqrt(EI/mu)/L^2: the scale of the flexural modes
};

using BeamTheoryBuild = void (*)(const BeamParams &, BeamDiscretization *);

// Widens a discretization to G >= d->fields fields per node: the dofs renumbered node-major
// (dof = node G + field), the strain terms with them; the new dofs held, of mass `mass` (a held
// dof's mass is never used, but none is 0). How a part on fields of its own joins the beam.
void BeamDiscretizationWiden(BeamDiscretization *d, PetscInt G, PetscReal mass);

// The registered theories by name ("euler"); nullptr if unknown.
BeamTheoryBuild BeamTheoryFind(const char *name);
// Names of all registered theories, for messages and -help.
std::vector<const char *> BeamTheoryNames();

// Euler-Bernoulli (model/euler_bernoulli.cpp): one field, the curvature terms of beam.hpp.
void EulerBernoulliBuild(const BeamParams &p, BeamDiscretization *d);
// Timoshenko (model/timoshenko.cpp): deflection and rotation per node, bending and shear terms.
void TimoshenkoBuild(const BeamParams &p, BeamDiscretization *d);

} // namespace beamimpact

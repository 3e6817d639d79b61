// The frame's twist about its own axis (-beam_torsion; MODEL.md section 11, docs/model.md
// section 16): the roll phi(x, t) (rad) of each section, a second-order field
//
//   rho J phi_tt = (G J phi_x)_x + m(x, t),       G J phi_x = 0 at a free end, phi = 0 where held,
//
// m the torque per length of the loads off the axis (a ball at z from the axis: F z; a string
// bed's edge). Discrete: one more field per node after the theory's, lumped rho J h (half at the
// ends) and one term per cell, U = 1/2 sum_cells G J h ((phi_k+1 - phi_k)/h)^2, the cell means
// of the section (model/section.hpp: a round section's J = 2 I; a table's columns GJ, rhoJ; or
// the uniform -beam_torsion_stiffness, -beam_torsion_inertia: BeamTorsion). A node whose bending rotation is
// held (a clamp) holds its roll too; a free or pinned end leaves it free, so that a free frame
// has the rigid roll phi = const among its rigid motions. Units: SI.
#pragma once

#include "model/beam_theory.hpp"

namespace beamimpact {

// G J (N m^2) and rho J (kg m) over [a, b] (m): the uniform options where given, else the
// section's cell means (0 where the section has none).
void TorsionSectionMean(const BeamTorsion &t, const BeamParams &p, PetscReal a, PetscReal b, PetscReal *GJ,
                        PetscReal *rhoJ);

// Appends the roll field to a theory's discretization (dofs renumbered node-major). Returns the
// roll's field index.
PetscInt TorsionAppend(const BeamTorsion &t, const BeamParams &p, BeamDiscretization *d);

// The free-free shaft's twisting frequencies (Hz) of a uniform section: f_n = n/(2 L)
// sqrt(G J / rho J), n = 1, 2, ... (the reference of the discrete field).
PetscReal TorsionFreeFrequency(PetscReal GJ, PetscReal rhoJ, PetscReal L, PetscInt n);

} // namespace beamimpact

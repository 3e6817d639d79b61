// The barrel wall's hoop oscillator in series with the ball (issue 23; MODEL.md section 9, the
// lumped alternative): the wall's displacement w (m, toward the bat's inside under the ball) is
// the n = 2 ovaling of the barrel as one mass m_h on a spring k_h = m_h (2 pi f_h)^2,
//
//   m_h w'' = -k_h w + F,    c = y_b - y(x_c) - w,
//
// the contact force F loading the beam (as without the wall) and the wall alike: a harmonic of
// the barrel's wall, orthogonal to the beam's bending (n = 1), carries no resultant on the
// section, so its spring ties the wall to nothing but its own rest shape and w adds no momentum.
// In the system it is one more field per node (held at every node but node 0, whose dof is w),
// with the mass m_h and the strain term 1/2 k_h w^2, and one more entry of weight 1 in the
// ball's coupling: every integrator, the leapfrog and the modal tools take it as they take the
// beam (the wall is one more mode, at f_h).
#pragma once

#include "model/beam_theory.hpp"

#include <string>
#include <vector>

namespace beamimpact {

// k_h = m_h (2 pi f_h)^2 (N/m).
PetscReal BarrelHoopStiffness(const BarrelHoop &hoop);

// Appends the wall's field to a theory's discretization (fields + 1, dofs renumbered node-major;
// the new field held at nodes 1..N-1, mass m_h everywhere so that no held dof has zero mass).
// Returns the wall's dof (node 0's new field).
PetscInt BarrelHoopAppend(const BarrelHoop &hoop, BeamDiscretization *d);

// -barrel_wall_thickness t (m): the profile's rows at its largest outer diameter D (the barrel,
// to 1e-9 relative) get the inner diameter d = D - 2 t; the diameters stay linear between rows,
// so a taper into the barrel follows. False (with the reason in *why) where such a row is solid
// (no wall to change) or t is not in (0, D/2) (t >= D/2: a solid section).
bool BarrelWallThicknessApply(PetscReal t, std::vector<ProfileRow> *rows, std::string *why);

// Restitution of a linear ball (e0 on a rigid wall) on a rigid target through a massless wall
// spring, r = k_b / k_h: e^2 = (e0^2 + r) / (1 + r) (MODEL.md section 9; the ball and the wall
// carry the same force, the wall returns all of its share).
PetscReal SeriesSpringRestitution(PetscReal e0, PetscReal r);

} // namespace beamimpact

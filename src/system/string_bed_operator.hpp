// The string bed's semi-discrete membrane (docs/model.md, "The string bed"): the stiffness row
// and lumped mass of each node of the head's grid (model/string_bed.hpp), plain numbers that
// solvers/string_bed_modes.cpp assembles on a 2-D DMDA. The discrete equations of the free nodes
// are  M w_tt = -K w + f  with M = sigma h_x h_z per node, K below, f the nodal forces (N).
#pragma once

#include "model/string_bed.hpp"

namespace beamimpact {

// One row of the membrane's stiffness K (N/m) at node (i, j): K w = sum over the four arms of
// the link's conductance times (w_P - w_Q), the x arms N_x h_z / l, the z arms N_z h_x / l, with
// l = h (a neighbour inside) or l = d < h (the arm cut by the outline at distance d: its end
// held, w = 0 there, so the link adds only to the diagonal). The cut arm is Shortley and
// Weller's distance; the mass is the lumped sigma h_x h_z of every free node, which keeps K
// symmetric (Gibou, Fedkiw, Cheng, Kang, J. Comput. Phys. 176 (2002) 205: second order for the
// Dirichlet problem; docs/model.md says why not Shortley-Weller's own (h + d)/2 weight).
// A node is held (not an unknown) when it is outside or on the outline, or when an arm is cut
// closer than d_min = h^2 / (2 a) (Gibou et al.'s rule: moving the edge by less than h^2 keeps
// the order; it avoids conductances ~ 1/d without bound).
struct BedRow {
  bool      held = true;
  PetscReal diag = 0;        // N/m
  PetscReal off[4] = {0};    // N/m, the coefficient of the neighbour in direction 0..3 (+x, -x, +z, -z); 0 when cut
  PetscReal mass = 0;        // kg, sigma h_x h_z for a free node
};
BedRow BedStiffnessRow(const BedGrid &g, const Membrane &m, PetscInt i, PetscInt j);
// Whether node (i, j) is an unknown (the first condition of BedStiffnessRow).
bool   BedNodeFree(const BedGrid &g, PetscInt i, PetscInt j);

} // namespace beamimpact

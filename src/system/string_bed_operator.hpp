// The string bed's semi-discrete membrane (docs/model.md, "The string bed"): the stiffness row
// and lumped mass of each node of the head's grid (model/string_bed.hpp), plain numbers that
// solvers/string_bed_modes.cpp assembles on a 2-D DMDA for the bed in a held frame; and the bed
// on a beam frame as fields of the beam's nodes (StringBedAppend), which every solver of the
// system takes. The discrete equations of the free nodes are  M w_tt = -K w + f  with M =
// sigma |cell ∩ head| per node, K below, f the nodal forces (N).
#pragma once

#include "model/beam_theory.hpp"
#include "model/string_bed.hpp"

#include <vector>

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
  bool      held   = true;
  PetscReal diag   = 0;   // N/m
  PetscReal off[4] = {0}; // N/m, the coefficient of the neighbour in direction 0..3 (+x, -x, +z, -z); 0 when cut
  PetscReal mass   = 0;   // kg, sigma |cell ∩ head| for a free node (sigma h_x h_z inside)
};
BedRow BedStiffnessRow(const BedGrid &g, const Membrane &m, PetscInt i, PetscInt j);
// Whether node (i, j) is an unknown (the first condition of BedStiffnessRow).
bool BedNodeFree(const BedGrid &g, PetscInt i, PetscInt j);
// The length (m) of arm dir (0: +x, 1: -x, 2: +z, 3: -z) of the free node (i, j): h when its
// neighbour is inside, else the distance to the outline along it (<= h).
PetscReal BedArmLength(const BedGrid &g, PetscInt i, PetscInt j, int dir);

// The bed on a beam frame (-strings_frame beam, docs/model.md section 16). Its columns are the
// beam's nodes (StringBedFrameGrid) and its nz nodes across the face are nz more fields of each
// node: field first + j is the bed's deflection w at (x_i, z_j) (m, absolute, like the beam's
// y). A node outside the head (or on its edge) holds its field. The strings are anchored on the
// frame, whose section at x_i is at y_i + z phi_i (bending and roll, phi the roll field; 0
// without one): the bed's strain energy is the held-frame membrane's in the deflection relative
// to the frame's sections,
//
//   links along the frame   1/2 (N_x h_z/h_x) (w_i+1,j - w_ij - (y_i+1 - y_i) - z_j (phi_i+1 - phi_i))^2,
//   links across it          1/2 (N_z h_x/h_z) (w_i,j+1 - w_ij - h_z phi_i)^2,
//   arms to the edge         1/2 (N h / l) (w_ij - y_i - z_j phi_i)^2     (l <= h: the cut arm),
//
// so that the frame's rigid motions (translation, pitch, roll) move the bed with it and strain
// nothing: the strings pull on the frame along the outline (N dw/dnu per length, a force on its
// bending and a torque on its roll) through the same terms. The mass sigma |cell ∩ head| of a node
// that is not an unknown but lies in the head moves with the frame: it is added to y_i and, as
// sigma |cell| z_j^2, to phi_i. With the frame held (every y, phi held) this is the held frame's
// bed exactly.
// The ball's load on the bed (docs/model.md section 16): the point (x, z) from the head's centre
// is shared between the four nodes of its cell with the bilinear hat weights, and each node's
// share is spread over the disc of radius a (m) about it with the weights 1 - r^2/a^2 (a parabolic
// pressure, normalised; the node alone when a < h: a point load is the hat weights). The weights
// sum to 1 and their first moments are the point's, sum w x_i = x and sum w z_j = z, on any grid
// and near the rim: a node outside the outline, or past the grid's edge across the face (j < 0 or
// j >= nz), is not dropped but carried by its frame section (y_i + z_j phi_i, z_j = -b + j h_z),
// so the load's resultant and moments about both axes are the ball's. A node past the grid's
// columns (i < 0 or i >= nx: the disc reaches beyond the frame's end) is marked `beyond`.
// Entries in (i, j) order, each node once.
struct BedPatchNode {
  PetscInt  i = 0, j = 0;   // the node (j may lie outside [0, nz): a frame section's point)
  PetscReal w      = 0;     // 1, its share of the load
  bool      free   = false; // an unknown of the bed (else it moves with its frame section)
  bool      beyond = false; // its column lies past the grid's ends: no frame section there
};
std::vector<BedPatchNode> BedPatch(const BedGrid &g, PetscReal x, PetscReal z, PetscReal a);

struct BedLayout {
  PetscInt first = -1; // the bed's first field
  BedGrid  grid;       // its grid (columns: the beam's nodes)
  PetscInt roll = -1;  // the frame's roll field (-1: none)
};
// (Its strain terms are the bed part's energy account: system/structure.cpp sets it.)
BedLayout StringBedAppend(const StringBedParams &p, const BedGrid &g, PetscInt phi_field, BeamDiscretization *d);

} // namespace beamimpact

// The racket's string bed as a membrane (docs/model.md, "The string bed"; MODEL.md section 11):
//
//   sigma w_tt = N_x w_xx + N_z w_zz - p(x, z, t)       on the head's outline,
//   w = 0 on the outline and outside it                  (-strings_frame held: a rigid frame)
//
// x along the frame's axis (the mains' direction), z across the face (the crosses'), both from
// the head's centre. A woven bed of strings of tension T per string, mass lambda per length and
// spacings s_m (between mains) and s_c (between crosses) acts as a membrane of tension per
// length N_x = T_m / s_m, N_z = T_c / s_c (N/m) and areal mass sigma = lambda/s_m + lambda/s_c
// (kg/m^2). The outline is an ellipse or a rectangle of length 2a (along x) and width 2b.
// Plain structs and functions; the options are read in io/string_bed_options.cpp.
// Units: SI (m, kg, N).
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

enum class HeadShape {
  Ellipse,
  Rectangle
};
const char *HeadShapeName(HeadShape s);

struct StringBedParams {
  PetscReal tension         = 250.0;   // N, tension of each main string (-strings_tension)
  PetscReal tension_crosses = 250.0;   // N, of each cross string (-strings_tension_crosses; default the mains')
  PetscReal spacing         = 0.0151;  // m, between neighbouring mains (-strings_spacing)
  PetscReal spacing_crosses = 0.0151;  // m, between neighbouring crosses (-strings_spacing_crosses; default the mains')
  PetscReal linear_density  = 1.51e-3; // kg/m, mass per length of a string (-strings_linear_density)
  HeadShape shape           = HeadShape::Ellipse; // -head_shape
  PetscReal head_length     = 0.34;               // m, the outline's extent along the frame's axis (-head_length)
  PetscReal head_width      = 0.24;               // m, across the face (-head_width)
  PetscReal head_center     = 0.175; // m, the head's centre along the frame's axis from x = 0 (-head_center)
  PetscInt  nodes           = 61;    // grid nodes across the head's length, edges included (-strings_nodes)
  PetscInt  nodes_width     = 0;     // across its width (-strings_nodes_width); 0: from the aspect, h_z ~ h_x
  std::string frame = "none";  // -strings_frame: none (no bed), held (a rigid frame) or beam (the beam is the frame: it
                               // bends and rolls)
  PetscReal patch_radius = -1; // m, the ball's load on the bed spread over a disc of this radius
                               // (-strings_patch_radius; < 0: not yet derived from the ball)
  // The mains under the ball in the bed's plane, for an oblique impact (StringBedInPlaneOf; < 0: from the tension)
  PetscReal inplane_stiffness = -1; // N/m, -strings_inplane_stiffness
  PetscReal inplane_mass      = -1; // kg, -strings_inplane_mass
  bool      On() const { return frame != "none"; }
  bool      Held() const { return frame == "held"; }
};

// The woven bed as a membrane: tension per length and areal mass.
struct Membrane {
  PetscReal N_x   = 0; // N/m, along x (the mains' tension over their spacing)
  PetscReal N_z   = 0; // N/m, along z (the crosses')
  PetscReal sigma = 0; // kg/m^2
};
Membrane StringBedMembrane(const StringBedParams &p);

// The grid of the bed: nx x nz nodes, node (i, j) at x_i = x0 + i h_x, z_j = -b + j h_z from the
// head's centre (a = head_length/2, b = head_width/2). In a held frame the grid spans the head's
// bounding box [-a, a] x [-b, b], edges included (x0 = -a); on a beam frame its columns are the
// beam's nodes (x0 = -head_center, h_x the beam's h), so that each column of the bed moves with
// its section of the frame.
struct BedGrid {
  PetscInt  nx = 0, nz = 0;
  PetscReal a = 0, b = 0;   // m, half-length and half-width
  PetscReal hx = 0, hz = 0; // m
  PetscReal x0    = 0;      // m, x of column 0 from the head's centre
  HeadShape shape = HeadShape::Ellipse;
  PetscReal X(PetscInt i) const { return x0 + i * hx; }
  PetscReal Z(PetscInt j) const { return -b + j * hz; }
};
// The held frame's grid: nx = nodes, nz from the aspect ((nx - 1) width / length + 1, rounded)
// unless nodes_width > 0.
BedGrid StringBedGrid(const StringBedParams &p);
// The grid on a beam frame of `nodes` nodes over [0, length] (m): a column per node, nz =
// nodes_width, or from h_z ~ h_x (width / h_x + 1, rounded).
BedGrid StringBedFrameGrid(const StringBedParams &p, PetscInt nodes, PetscReal length);

// The area (m^2) of node (i, j)'s cell [x_i - h_x/2, x_i + h_x/2] x [z_j - h_z/2, z_j + h_z/2]
// inside the outline: the node's share of the bed's mass sigma |cell ∩ head| (exact for the
// rectangle; the ellipse's by quadrature along x of the chord, to ~1e-9 of the cell).
PetscReal BedCellArea(const BedGrid &g, PetscInt i, PetscInt j);

// The outline's area and second moments (m^2, m^4) about the head's centre: int dA, int x^2 dA
// (along the frame), int z^2 dA (across it). The bed's rigid-body share: sigma times these.
struct HeadMoments {
  PetscReal area = 0, xx = 0, zz = 0;
};
HeadMoments HeadMomentsOf(const StringBedParams &p);

// Whether (x, z) lies strictly inside the outline (a point within 1e-12 of the edge, relative,
// is on it: held).
bool BedInside(const BedGrid &g, PetscReal x, PetscReal z);

// Distance (m) from the inside point (x, z) to the outline along the grid line in direction
// dir (0: +x, 1: -x, 2: +z, 3: -z), exact for both shapes.
PetscReal BedEdgeDistance(const BedGrid &g, PetscReal x, PetscReal z, int dir);

// The bed in its own plane under the ball (MODEL.md section 17; docs/model.md section 13, "On the
// string bed"): the mains under the ball's patch pulled sideways (along z, across their length) by the
// friction force. A main of tension T pulled aside at a point a and b from its ends has the stiffness
// T (1/a + 1/b) and, in the triangle that static pull gives it, the kinetic energy of a point of mass
// lambda (a + b)/3 moving with the point (Rayleigh's lumped mass); the mains under the patch of
// radius r_p (2 r_p / s_m of them, at least one) act together. At (x, z) from the head's centre.
struct StringBedInPlane {
  PetscReal mains     = 0; // 1, the mains under the patch (2 r_p / s_m, at least 1)
  PetscReal to_ends_a = 0; // m, the struck main's length from the point to its end at -x
  PetscReal to_ends_b = 0; // m, to its end at +x
  PetscReal stiffness = 0; // N/m, mains T (1/a + 1/b)
  PetscReal mass      = 0; // kg, mains lambda (a + b) / 3
};
StringBedInPlane StringBedInPlaneOf(const StringBedParams &p, PetscReal x, PetscReal z, PetscReal patch_radius);

// References (scripts/references/membrane.py):
// rectangle 2a x 2b: f_mn = 1/2 sqrt((N_x (m/(2a))^2 + N_z (n/(2b))^2) / sigma) (Hz);
PetscReal MembraneRectangleFrequency(const Membrane &m, PetscReal length, PetscReal width, PetscInt mm, PetscInt nn);
// circle of radius R, N_x = N_z = N: f = j / (2 pi R) sqrt(N/sigma), j a zero of a Bessel function;
PetscReal MembraneCircleFrequency(const Membrane &m, PetscReal R, PetscReal bessel_zero);
// the deflection at the centre of a circular bed of radius R under a total force F spread
// uniformly over the central disc of radius c: F / (2 pi N) (ln(R/c) + 1/2) (m).
PetscReal MembranePatchCentreDeflection(PetscReal N, PetscReal R, PetscReal c, PetscReal F);

} // namespace beamimpact

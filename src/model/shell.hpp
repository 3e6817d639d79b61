// The barrel wall as a thin cylindrical shell (issue 23; MODEL.md section 9): wherever the
// profile's section is hollow (rows 'x D d' with d > 0), the wall of midsurface radius
// R = (D + d)/4 and thickness t = (D - d)/2 (per cell, from its midpoint), material E, rho, nu
// (-beam_youngs_modulus, -beam_density, -beam_poisson), in circumferential harmonics
//
//   u = U_n(x) cos n theta (axial),  v = V_n(x) sin n theta,  w = W_n(x) cos n theta (outward),
//
// n in -shell_harmonics (2, 3, 4 by default; n = 1 is the beam's own bending, n = 0 breathing is
// far stiffer). Each harmonic is three more fields per node (U_n, V_n, W_n; m) on the beam's grid,
// with the Sanders-Koiter energy (scripts/references/shell_modes.py, the same functional)
//
//   U_n = pi R/2 int [ C (ex^2 + et^2 + 2 nu ex et + (1-nu)/2 g^2)
//                      + B (kx^2 + kt^2 + 2 nu kx kt + 2 (1-nu) tw^2) ] dx,
//   T_n = pi R rho t/2 int (U_n'^2 + V_n'^2 + W_n'^2) dx,     C = E t/(1-nu^2), B = E t^3/(12 (1-nu^2)),
//   ex = U', et = (n V + W)/R, g = V' - n U/R, kx = -W'', kt = (n V + n^2 W)/R^2,
//   tw = (n W' + 3/4 V' + n U/(4 R))/R   (Sanders' twist: every rigid motion strain-free),
//
// as sums of squares (ex^2 + et^2 + 2 nu ex et = (ex + nu et)^2 + (1 - nu^2) et^2): the membrane
// and twist terms at each cell's midpoint (linear U, V, W; one point, so that an inextensional
// ovaling is not locked by the membrane), the bending terms at the nodes (kx the second difference,
// as the Euler-Bernoulli beam), masses lumped at the nodes. Second order in h.
//
// Ends: a free end of the wall (a beam end free, or the open end of a hollow part) has no kx
// (M_x = 0, the natural condition); where the beam's deflection is held (a clamped or pinned
// end, a clamped region) the wall is held (U = V = W = 0) and, where the rotation is held too,
// W' = 0 (the mirror term); where the hollow part joins a solid one the wall is clamped-like
// (held, W' = 0). The ball loads each harmonic's W_n at the impact point (hat weights, inward).
#pragma once

#include "model/beam_theory.hpp"
#include "model/contact_law.hpp"

#include <utility>
#include <vector>

namespace beamimpact {

// Where the shell's fields are: harmonic k's U, V, W are fields first + 3 k + 0, 1, 2.
struct ShellLayout {
  PetscInt              first = -1; // first shell field (the theory's fields come before)
  std::vector<PetscInt> harmonics;  // n of each harmonic
  PetscInt              WField(size_t k) const { return first + 3 * (PetscInt)k + 2; }
};

// Appends the shell's fields to a theory's discretization (its dofs renumbered node-major; the
// shell's strain terms and lumped masses; held where no wall is, at a held beam and at a
// junction with a solid part). A Profile section. Returns the layout.
ShellLayout ShellAppend(const BarrelShell &shell, const BeamParams &p, BeamDiscretization *d);

// The wall's midsurface radius R and thickness t (m) of a profile at x (m); false where solid.
bool ShellWallAt(const BeamParams &p, PetscReal x, PetscReal *R, PetscReal *t);
// The barrel's wall (the profile's rows at its largest outer diameter, as -barrel_wall_thickness
// takes them): R and t (m) of the row whose t/R is largest; false when no row there is hollow.
bool ShellBarrelWall(const BeamParams &p, PetscReal *R, PetscReal *t);
// The wall's radius (m) a displacement under the ball at x is judged against: the midsurface
// radius there, else (a hoop oscillator struck where the profile is solid) the barrel's; 0 if
// neither is hollow.
PetscReal ShellRadiusAt(const BeamParams &p, PetscReal x);

// The thin-shell model's range (docs/model.md section 14): Sanders-Koiter, like every thin-shell
// theory of the Kirchhoff-Love kind, drops terms of order t/R against 1; a wall thicker than
// kShellThinLimit R is noted.
constexpr PetscReal kShellThinLimit = 0.1;
// Both wall models are linear (strains and the ring's curvature linear in the displacements,
// taken small against the wall's thickness and radius): a displacement under the ball beyond
// kWallDeflectionLimit R is physically absurd, flagged in the results (wall_deflection_large).
constexpr PetscReal kWallDeflectionLimit = 0.25;

// The ball's load as a patch (issue 23): a nominal contact radius a (m) spreads the load over
// the wall. Around the wall, a uniform pressure over the half-angle phi = a/R: the virtual work
// on W_n cos n theta is the theta-average of cos n theta, sin(n phi)/(n phi) (1 at a = 0). Along
// x, a hat-shaped line load of half-width a, (a - |x - x_c|)/a^2, integrated against each node's
// hat function: w_i = int N_i(x) p(x) dx (exact: Simpson on the pieces between the nodes and
// x_c, x_c +- a), renormalized to sum 1 where the patch passes an end; a = 0 (or a patch within
// one cell, by symmetry) gives the point load's hat weights N_i(x_c) exactly.
PetscReal                                   ShellPatchHarmonicWeight(PetscInt n, PetscReal a, PetscReal R);
std::vector<std::pair<PetscInt, PetscReal>> ShellPatchNodeWeights(PetscInt nodes, PetscReal L, PetscReal x_c,
                                                                  PetscReal a);
// The default a (m): sqrt(R_b delta), delta the ball's peak compression on a rigid wall at the
// approach speed v (its own law, ContactWallMaxCompression): the Hertz contact radius of a
// sphere pressed delta into a flat (a^2 = R_b delta); 0 (the point load) without -ball_radius.
PetscReal ShellContactRadiusDefault(const BallParams &b, PetscReal v);

// The wall's Young's modulus in the shell (Pa): -shell_youngs_modulus, else the profile's E.
PetscReal ShellYoungsModulus(const BarrelShell &shell, const BeamParams &p);

// The lowest frequency (Hz) of the wall's harmonic n alone: its U, V, W fields on the grid with
// the ends, holds and junctions of ShellAppend (the harmonics are uncoupled from the beam and
// from each other in K and M), the lowest eigenvalue of M^-1/2 K M^-1/2 in band form (LAPACK
// dsbevx, O(N)). For n = 2 the barrel's lowest hoop (ovaling) mode: the results column
// hoop_frequency. NaN without a wall (or if LAPACK fails).
PetscReal ShellLowestFrequency(const BarrelShell &shell, const BeamParams &p, PetscInt n);

// Rayleigh's inextensional ring (Hz) of harmonic n: sqrt(E t^2 n^2 (n^2-1)^2 / (12 rho (1-nu^2) R^4 (n^2+1)))/(2 pi).
PetscReal RayleighRingFrequency(PetscReal E, PetscReal rho, PetscReal nu, PetscReal R, PetscReal t, PetscInt n);

} // namespace beamimpact

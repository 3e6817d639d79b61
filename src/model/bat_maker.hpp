// A bat by its maker's numbers (docs/bats.md, "A bat by its maker's numbers"; MODEL.md section 14):
// length, knob, handle and barrel diameters, where the taper starts and ends, an optional narrowing
// of the barrel toward its end (a "torpedo" bat's), the wall thicknesses of a hollow bat, an end
// cap's mass, a cupped end of a wood bat: turned into the profile of round sections the program
// uses for any bat (rows x D d, linear between rows; model/section.hpp). x runs from the knob's
// end (x = 0) to the barrel's end (x = L). Plain numbers: the options are read in
// io/bat_maker_options.cpp.
//
//   knob      [0, k]            D = D_k, solid (a hollow bat: the handle's bore runs through it)
//   flare     [k, k + 4 mm]     D from D_k to D_h (the knob's fillet)
//   handle    [k + 4 mm, x_1]   D = D_h,   wall t_h
//   taper     [x_1, x_2]        D from D_h to D_b and the wall from t_h to t (both linear)
//   barrel    [x_2, x_3]        D = D_b,   wall t
//   end taper [x_3, L]          D from D_b to D_e (x_3 = L: none)
//   end cap   [L - l_c, L]      a hollow bat's wall thickened inward over l_c, adding the cap's mass
//   cup       [L - c, L]        a solid bat's end hollowed to the cup's diameter, depth c
//
// The end cap is a thickened ring, not a disc: the profile is one material and round, and the
// ring keeps the mass, the balance and the moments exact and every number continuous in the cap's
// mass (a design variable); the shell sees a stiff ring at an open end (docs/bats.md says what
// that changes).
#pragma once

#include "model/section.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

struct BatMakerParams {
  PetscReal length                = 0.8382;   // m, L (33 in)
  PetscReal knob_diameter         = 0.046;    // m, D_k
  PetscReal knob_length           = 0.012;    // m, k: the knob's flat part along the axis
  PetscReal handle_diameter       = 0.0254;   // m, D_h
  PetscReal taper_start           = 0.30;     // m, x_1: the handle ends, the taper begins
  PetscReal taper_end             = 0.53;     // m, x_2: the barrel's full diameter is reached
  PetscReal barrel_diameter       = 0.066675; // m, D_b (2 5/8 in)
  PetscReal end_taper_start       = 0;        // m, x_3 (0: no end taper, x_3 = L)
  PetscReal end_diameter          = 0;        // m, D_e at x = L (0: D_b)
  PetscReal wall_thickness        = 0;        // m, t, the barrel's wall (0: a solid bat)
  PetscReal handle_wall_thickness = 0;        // m, t_h (0: t)
  PetscReal end_cap_mass          = 0;        // kg, a hollow bat's end cap
  PetscReal end_cap_length        = 0.02;     // m, l_c, the barrel's end the cap thickens
  PetscReal cup_depth             = 0;        // m, c, a solid bat's cupped end (0: none)
  PetscReal cup_diameter          = 0.0381;   // m, the cup's diameter (1.5 in)
};

// The knob's fillet length (m).
constexpr PetscReal kBatKnobFlare = 0.004;
// The length (m) over which the end cap's or the cup's inner diameter steps in.
constexpr PetscReal kBatEndStep = 0.001;

// The profile of the bat of `b` in a material of density rho (kg/m^3; the end cap's ring needs it).
// False, with the reason in *why naming the option (-bat_taper_end ...) and the value, for numbers
// that describe no bat: positions out of order, a wall too thick for its diameter, an end cap on a
// solid bat or heavier than its ring can hold, a cup on a hollow bat or wider than the end.
bool BatMakerProfile(const BatMakerParams &b, PetscReal rho, std::vector<ProfileRow> *rows, std::string *why);

// A bat's rule numbers: the length in inches minus the weight in ounces (the "drop"; the NCAA and
// NFHS allow at most 3), from the length (m) and the mass (kg).
PetscReal           BatDrop(PetscReal length, PetscReal mass);
constexpr PetscReal kMetresPerInch     = 0.0254;
constexpr PetscReal kKilogramsPerOunce = 0.028349523125;

} // namespace beamimpact

// A racket by its maker's numbers (docs/model.md section 16, "A racket by its maker's numbers"):
// length, strung mass and balance, head size and shape, frame stiffness, the
// roll's stiffness and the twistweight, turned into the frame's table of section properties
// (rows x EI mu kappaGA rhoI GJ rhoJ, linear between rows; model/section.hpp) and the head's
// outline of the string bed (-head_length, -head_width, -head_center). x runs from the butt (x = 0)
// to the tip (x = L). Plain numbers: the options are read in io/racket_maker_options.cpp.
//
//   mu     mu_1 over the handle [0, x_h], mu_2 from x_h + 2 cm to the tip, linear between: the two
//          levels solve the strung mass M and balance x_b with the strings' mass sigma A at the
//          head's centre (the bed's own moments, HeadMomentsOf, counted as the rigid body does);
//   EI     the frame stiffness, uniform; kappaGA = 0.5 (G/rho) mu with G/rho = 3.3e6 m^2/s^2 and
//          rhoI = mu a^2/12 with a = 26 mm (a frame's depth), as racket-pure-drive.properties;
//   GJ     the roll's stiffness, uniform; rhoJ = mu (12.5 mm)^2 in the handle and a head level that
//          gives the strung racket its twistweight (with the strings' sigma int z^2 dA);
//   head   an ellipse (or rectangle) of area A and aspect length/width r: width sqrt(4A/(pi r)) (a
//          rectangle: sqrt(A/r)), length r times it, its tip -racket_head_margin below the frame's.
#pragma once

#include "model/section.hpp"
#include "model/string_bed.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

struct RacketMakerParams {
  PetscReal length          = 0.685;  // m, L (27 in)
  PetscReal mass            = 0.321;  // kg, M, strung (the frame and the strings)
  PetscReal balance         = 0.330;  // m, x_b, the strung racket's centre of mass from the butt
  PetscReal head_size       = 0.0645; // m^2, A, the strung area (645 cm^2 = 100 in^2)
  PetscReal head_aspect     = 1.37;   // 1, r, the head's length over its width
  PetscReal head_margin     = 0.01;   // m, from the head's tip to the frame's
  PetscReal handle_length   = 0.17;   // m, x_h, the handle's level of mass
  PetscReal frame_stiffness = 157;    // N m^2, EI
  PetscReal twist_stiffness = 350;    // N m^2, GJ
  PetscReal twistweight     = 0.0014; // kg m^2, about the axis, strung (14 kg cm^2)
};

// The head's outline of the maker's racket in the bed's parameters (head_length, head_width,
// head_center; the shape as given).
void RacketMakerHead(const RacketMakerParams &r, StringBedParams *bed);

// What a racket's frame carries besides itself (its strings: RacketStrungBy), which the levels of
// mass and of rho J balance; all 0 for a frame with no strings.
struct RacketStrung {
  PetscReal mass        = 0; // kg, the strings' sigma A
  PetscReal moment      = 0; // kg m, their first moment about the butt (x = 0)
  PetscReal roll        = 0; // kg m^2, their moment about the frame's axis, sigma int z^2 dA
  PetscReal head_start  = 0; // m, where the strung head begins along the frame (checked against the handle)
  PetscReal head_length = 0; // m, the head's length along the frame (0: no head)
};
// The bed's share (its own moments, HeadMomentsOf, at its centre -head_center).
RacketStrung RacketStrungBy(const StringBedParams &bed);
// *s plus the bed's share: mass and moments summed, the head's span the bed's.
void RacketStrungAdd(const StringBedParams &bed, RacketStrung *s);

// The frame's table for a racket carrying `strung`. False, with the reason naming the option and
// the value, when the numbers make no racket (a level of mass or of rho J not > 0, a head longer
// than the racket).
bool RacketMakerTable(const RacketMakerParams &r, const RacketStrung &strung, std::vector<PropertiesRow> *rows,
                      std::string *why);

// The ramp (m) between the handle's and the head's levels.
constexpr PetscReal kRacketRamp = 0.02;

} // namespace beamimpact

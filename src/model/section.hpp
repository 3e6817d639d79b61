// Sections of a beam along its length: what a bat, a racket frame or the paper's strip is
// made of at each point, as plain numbers (docs/bats.md).
//
//   round solid    A = pi D^2/4,         I = pi D^4/64
//   round hollow   A = pi (D^2 - d^2)/4, I = pi (D^4 - d^4)/64   (outer D, inner d)
//   EI = E I,  mu = rho A,  kappa G A,  rho I  (the last two for a Timoshenko beam)
//
// A section comes from one of three sources: the uniform options (scalars in BeamParams),
// a profile of round sections (rows x D [d], diameters linear between rows, E, rho, G from
// the material), or a table of properties (rows x EI mu [kappaGA rhoI], each linear between
// rows) for frames that are not round. The files are read by io/section_file.hpp; here the
// rows are only evaluated. The twist (model/torsion.hpp) takes GJ and rho J: a round section's
// J = 2 I = pi (D^4 - d^4)/32, G from the material (or E/(2 (1 + nu))); a table's columns 6 and
// 7 (rows x EI mu kappaGA rhoI GJ rhoJ).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

enum class SectionSource {
  Uniform = 0,
  Profile = 1,
  Table   = 2
};
const char *SectionSourceName(SectionSource s);

// Properties of the section at one point.
struct SectionProperties {
  PetscReal EI   = 0; // N m^2, bending stiffness
  PetscReal mu   = 0; // kg/m, mass per length
  PetscReal kGA  = 0; // N, shear stiffness kappa G A (0: unknown)
  PetscReal rhoI = 0; // kg m, rotary inertia per length rho I (0: unknown)
  PetscReal GJ   = 0; // N m^2, torsional stiffness (0: unknown)
  PetscReal rhoJ = 0; // kg m, polar mass moment per length rho J about the axis (0: unknown)
};

struct ProfileRow {
  PetscReal x = 0, D = 0, d = 0; // m: position, outer and inner diameter (d = 0: solid)
  int       line = 0;            // the row's line in its file (for messages; 0: not from a file)
};
struct PropertiesRow {
  PetscReal         x = 0;
  SectionProperties s;
  int               line = 0; // the row's line in its file (for messages; 0: not from a file)
};

// Material of a round profile. kappa = 0 picks Cowper's coefficient for each section.
struct SectionMaterial {
  PetscReal E = 0, rho = 0; // Pa, kg/m^3
  PetscReal G     = 0;      // Pa, shear modulus (0: not given; Timoshenko needs it)
  PetscReal nu    = 0.3;    // Poisson's ratio (Cowper's formula)
  PetscReal kappa = 0;      // shear coefficient; 0: by section (Cowper)
};

// A section varying along the beam: rows sorted by strictly increasing x, the first at x = 0.
struct BeamSection {
  SectionSource              source = SectionSource::Uniform;
  std::string                file;                      // where the rows came from (for the record)
  std::vector<ProfileRow>    profile;                   // source Profile
  std::vector<PropertiesRow> table;                     // source Table
  bool                       table_has_shear   = false; // the table gives kappaGA and rhoI
  bool                       table_has_torsion = false; // the table gives GJ and rhoJ too (seven columns)
  SectionMaterial            material;                  // source Profile
};

// Round sections (m^2, m^4).
PetscReal RoundArea(PetscReal D, PetscReal d);
PetscReal RoundSecondMoment(PetscReal D, PetscReal d);
// Cowper's shear coefficient of a round tube with inner/outer ratio m = d/D (m = 0: solid,
// 6(1+nu)/(7+6nu)) and of a solid rectangle, 10(1+nu)/(12+11nu).
PetscReal CowperRound(PetscReal nu, PetscReal m);
PetscReal CowperRectangle(PetscReal nu);

// Properties at x (m) of a Profile or Table section (x clamped to the rows' span).
SectionProperties SectionAt(const BeamSection &s, PetscReal x);
// Integrals over [a, b] (m) of each property of a Profile or Table section (EI in N m^3, mu in
// kg, ...): 3-point Gauss on each piece between rows, exact for the polynomial properties of a
// profile (degree <= 4) and a table (degree 1). The discrete beams use cell integrals rather
// than point values, so that steps in the section (a knob, a wall change) keep second order.
SectionProperties SectionIntegral(const BeamSection &s, PetscReal a, PetscReal b);
// Mass moments over [a, b]: m0 = int mu (kg), m1 = int mu x (kg m), m2 = int mu x^2 (kg m^2),
// j = int rho I (kg m^2, the sections' own rotary inertia) and roll = int rho J (kg m^2, about the
// axis); exact as SectionIntegral.
struct SectionMoments {
  PetscReal m0 = 0, m1 = 0, m2 = 0, j = 0, roll = 0;
};
SectionMoments SectionMomentsOf(const BeamSection &s, PetscReal a, PetscReal b);
// The span (m) of the rows: last x minus first x.
PetscReal SectionLength(const BeamSection &s);

} // namespace beamimpact

// The -beam_* options. See beam_options.hpp.
#include "io/beam_options.hpp"

#include "io/bat_maker_options.hpp"
#include "io/racket_maker_options.hpp"
#include "io/section_file.hpp"
#include "io/text.hpp"
#include "model/barrel.hpp"
#include "model/beam_theory.hpp"
#include "system/structure_part.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace beamimpact {

namespace {
std::vector<std::string> TheoryChoices();
std::string              SupportHelp(const char *end);
} // namespace

const OptionModule &BeamOptionTable()
{
  static const OptionModule m = {
    "beam",
    "Beam: geometry, material, section, theory and supports (SI units)",
    {
      OptionNeeds(OptionReal("-beam_length", "m",
                             "Beam length L; not with a profile or table (they span their rows); not with "
                             "-strings_frame held (the frame is the head's length)",
                             "1.1", Positive()),
                  {"-strings_frame=none|-strings_frame=beam"}),
      OptionReal("-beam_thickness", "m", "Thickness a in the direction of motion", "0.006", Positive()),
      OptionReal("-beam_width", "m", "Width b; with E and rho", "0.032", Positive()),
      OptionReal("-beam_youngs_modulus", "Pa", "Young's modulus E; with rho, a, b, or with -beam_profile", "7e10",
                 Positive()),
      OptionReal("-beam_density", "kg/m^3", "Density rho; with E, a, b, or with -beam_profile", "2700", Positive()),
      OptionReal("-beam_mass", "kg", "Total mass M; with -beam_youngs_over_density and a", "", Positive()),
      OptionReal("-beam_youngs_over_density", "N m/kg", "E/rho; with -beam_mass and a", "", Positive()),
      OptionReal("-beam_EI", "N m^2", "Bending stiffness EI; with -beam_mu", "", Positive()),
      OptionReal("-beam_mu", "kg/m", "Mass per length mu; with -beam_EI", "", Positive()),
      OptionFile("-beam_profile", "Round sections along the beam: file of rows 'x D [d]' (m: the outer and an "
                                  "optional inner diameter, linear between rows), with E and rho"),
      OptionFile("-beam_properties", "Section properties along the beam: file of rows 'x EI mu [kappaGA rhoI [GJ "
                                     "rhoJ]]' (SI; linear between rows; GJ, rhoJ for -beam_torsion)"),
      OptionChoice("-beam_theory",
                   "Beam theory (model/beam_theory.hpp): euler (Euler-Bernoulli), timoshenko (shear and rotary "
                   "inertia)",
                   TheoryChoices(), "euler"),
      OptionNeeds(OptionReal("-beam_shear_modulus", "Pa",
                             "Shear modulus G: Timoshenko with E, rho (uniform or profile)", "", Positive()),
                  {"-beam_theory=timoshenko"}),
      [] {
        OptionSpec s = OptionReal("-beam_shear_coefficient", "1",
                                  "Shear coefficient kappa; 0: Cowper's by section (round tube, rectangle)", "0",
                                  Between(0, 1));
        s.range_text = "in (0, 1], or 0: Cowper's by section";
        s.needs      = {"-beam_theory=timoshenko"};
        return s;
      }(),
      OptionNeeds(OptionReal("-beam_poisson", "1",
                             "Poisson's ratio nu (Cowper's shear coefficient; the barrel's shell)", "0.3",
                             Between(-1, 0.5, true, true)),
                  {"-beam_theory=timoshenko|-beam_shell"}),
      OptionNeeds(OptionInt("-beam_nodes",
                            "Number of grid nodes N (not with -strings_frame held: the bed's -strings_nodes)", "41",
                            AtLeast(5)),
                  {"-strings_frame=none|-strings_frame=beam"}),
      OptionChoice("-beam_left", SupportHelp("x = 0").c_str(), SupportNames(), "free"),
      OptionChoice("-beam_right", SupportHelp("x = L").c_str(), SupportNames(), "free"),
      OptionList("-beam_clamp", "m", "Clamped region x0,x1 held fixed (a handle in a vice)", 2, 2, NonNegative()),
      OptionReal("-beam_pivot", "m",
                 "Pivot x_p: an interior point held at y = 0, free to rotate (a test rig; on the nearest node)", ""),
      OptionReal("-beam_damping_mass", "1/s",
                 "Rayleigh damping alpha: C = alpha M + beta K, zeta = alpha/(2 omega) + beta omega/2", "0",
                 NonNegative()),
      OptionReal("-beam_damping_stiffness", "s", "Rayleigh damping beta", "0", NonNegative()),
      OptionNeeds(OptionReal("-barrel_wall_thickness", "m",
                             "The barrel's wall thickness t: the profile's rows at its largest outer diameter D (the "
                             "barrel) get the inner diameter D - 2 t instead of the file's (the taper follows "
                             "linearly); 1e-4 (0.1 mm, a drink can's wall) <= t < D/2; with -bat_length, the maker's "
                             "barrel wall (a hollow bat)",
                             "", AtLeast(1e-4)),
                  {"-beam_profile|-bat_length"}),
    },
  };
  return m;
}

namespace {

// The raw option values and which were given.
struct BeamOptionValues {
  PetscReal E = 7e10, rho = 2700, a = 0.006, b = 0.032, M = 0, Erho = 0, EI = 0, mu = 0; // the paper's aluminium beam
  PetscReal G = 0, kappa = 0, nu = 0.3;
  PetscReal wall    = 0; // m, -barrel_wall_thickness
  PetscBool setwall = PETSC_FALSE;
  PetscBool setE = PETSC_FALSE, setrho = PETSC_FALSE, seta = PETSC_FALSE, setb = PETSC_FALSE, setM = PETSC_FALSE,
            setErho = PETSC_FALSE, setEI = PETSC_FALSE, setmu = PETSC_FALSE;
  PetscBool   setlength = PETSC_FALSE, setprofile = PETSC_FALSE, setproperties = PETSC_FALSE;
  std::string profile, properties, theory                                      = "euler";
};

std::vector<std::string> TheoryChoices()
{
  std::vector<std::string> v;
  for (const char *n : BeamTheoryNames()) v.push_back(n);
  return v;
}

std::string SupportHelp(const char *end)
{
  std::string s = std::string("Support at ") + end + ":";
  for (Support q : Supports()) s += std::string(" ") + q.Name() + " (" + q.Spec().help + ");";
  s.pop_back();
  return s;
}

PetscErrorCode BeamOptionsRead(MPI_Comm comm, BeamParams *p, BeamOptionValues *o)
{
  const OptionModule    &T    = BeamOptionTable();
  std::string            left = p->left.Name(), right = p->right.Name();
  std::vector<PetscReal> clamp;
  PetscBool              setclamp = PETSC_FALSE, setpivot = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_length", &p->length, &o->setlength));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_thickness", &o->a, &o->seta));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_width", &o->b, &o->setb));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_youngs_modulus", &o->E, &o->setE));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_density", &o->rho, &o->setrho));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_mass", &o->M, &o->setM));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_youngs_over_density", &o->Erho, &o->setErho));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_EI", &o->EI, &o->setEI));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_mu", &o->mu, &o->setmu));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_profile", &o->profile, &o->setprofile));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_properties", &o->properties, &o->setproperties));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_theory", &o->theory, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_shear_modulus", &o->G, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_shear_coefficient", &o->kappa, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_poisson", &o->nu, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_nodes", &p->nodes, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_left", &left, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_right", &right, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_clamp", &clamp, &setclamp));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_pivot", &p->pivot_x, &setpivot));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_damping_mass", &p->damping_mass, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-beam_damping_stiffness", &p->damping_stiffness, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-barrel_wall_thickness", &o->wall, &o->setwall));
  PetscOptionsEnd();

  PetscCheck(SupportFind(left, &p->left) && SupportFind(right, &p->right), comm, PETSC_ERR_PLIB,
             "a support the table allows is not registered");
  p->theory    = o->theory;
  p->has_pivot = setpivot;
  if (setclamp) {
    p->has_clamp = true;
    p->clamp_x0  = clamp[0];
    p->clamp_x1  = clamp[1];
  }
  PetscFunctionReturn(0);
}

// The first option of a uniform parameter set that was given, or nullptr.
const char *UniformOptionGiven(const BeamOptionValues &o)
{
  return o.setlength ? "-beam_length"
       : o.seta      ? "-beam_thickness"
       : o.setb      ? "-beam_width"
       : o.setM      ? "-beam_mass"
       : o.setErho   ? "-beam_youngs_over_density"
       : o.setEI     ? "-beam_EI"
       : o.setmu     ? "-beam_mu"
                     : nullptr;
}

// Each profile row's derived properties finite and > 0 (a diameter of 1e300 m gives EI = inf),
// said with the file, the line and the value. A table's are its own numbers, checked on reading.
PetscErrorCode SectionRowsCheck(MPI_Comm comm, const char *option, const BeamSection &s)
{
  PetscFunctionBeginUser;
  const SectionMaterial &m = s.material;
  for (const ProfileRow &r : s.profile) {
    const PetscReal A = RoundArea(r.D, r.d), I = RoundSecondMoment(r.D, r.d),
                    kappa = m.kappa > 0 ? m.kappa : CowperRound(m.nu, r.d / r.D);
    const struct {
      const char *name, *unit;
      PetscReal   value;
      bool        used;
    } derived[] = {
      {"EI", "N m^2", m.E * I, true},
      {"mu", "kg/m", m.rho * A, true},
      {"kappaGA", "N", kappa * m.G * A, m.G > 0},
      {"rhoI", "kg m", m.rho * I, true},
    };
    char row[96]; // as written (PETSc's %g would write 0 as "0.")
    std::snprintf(row, sizeof row, "x %g D %g d %g", (double)r.x, (double)r.D, (double)r.d);
    for (const auto &q : derived)
      PetscCheck(!q.used || (std::isfinite(q.value) && q.value > 0), comm, PETSC_ERR_ARG_OUTOFRANGE,
                 "%s %s:%d: the row '%s' gives %s = %g %s, not a finite number > 0: the diameters are out of range (m, "
                 "with E = %g Pa, rho = %g kg/m^3)",
                 option, s.file.c_str(), r.line, row, q.name, (double)q.value, q.unit, (double)m.E, (double)m.rho);
  }
  PetscFunctionReturn(0);
}

// A file's rows that do not start at x = 0 are shifted so that they do: the beam's x, and with it
// -impact_x, -beam_pivot, -beam_clamp, -grip and the monitors' points, is measured from the first
// row (docs/bats.md). Said once.
PetscErrorCode SectionShiftNote(MPI_Comm comm, const char *option, const std::string &file, PetscReal x0)
{
  char text[1024];
  PetscFunctionBeginUser;
  if (x0 == 0) PetscFunctionReturn(0);
  std::snprintf(text, sizeof text,
                "note: %s %s: its rows start at x = %g m, not 0: the beam's x is measured from its first row (x = 0 "
                "there), so -impact_x, -beam_pivot, -beam_clamp, -grip and the "
                "monitors' points are %g m less than the file's x (-impact_x 0.5 strikes the file's x = %g)\n",
                option, file.c_str(), (double)x0, (double)x0, (double)(0.5 + x0));
  PetscCall(PrintOnce(comm, text));
  PetscFunctionReturn(0);
}

// A section file far outside any bat, racket or test beam (a profile written in centimetres
// gives an 84 m, 130 kg bat): a warning naming the file, the values and the likely cause. Said once.
PetscErrorCode SectionPlausibility(MPI_Comm comm, const char *option, const BeamSection &s, PetscReal length)
{
  const PetscReal mass = SectionMomentsOf(s, 0, length).m0;
  PetscReal       D    = 0;
  for (const ProfileRow &r : s.profile) D = std::max(D, r.D);
  std::string odd;
  char        item[160];
  PetscFunctionBeginUser;
  if (!(length >= 0.1 && length <= 5)) {
    std::snprintf(item, sizeof item, " length %g m (a bat, racket or test beam: 0.1 to 5 m);", (double)length);
    odd += item;
  }
  if (!(mass >= 0.01 && mass <= 10)) {
    std::snprintf(item, sizeof item, " mass %g kg (0.01 to 10 kg);", (double)mass);
    odd += item;
  }
  if (s.source == SectionSource::Profile && !(D >= 0.005 && D <= 0.2)) {
    std::snprintf(item, sizeof item, " largest outer diameter %g m (0.005 to 0.2 m);", (double)D);
    odd += item;
  }
  if (!odd.empty())
    PetscCall(PrintOnce(comm, "WARNING: " + std::string(option) + " " + s.file +
                                " gives a beam far outside any bat, racket or test beam:" + odd +
                                " is the file in centimetres or millimetres, or the material in other units? Section "
                                "files are in SI units (m, kg, N m^2)\n"));
  PetscFunctionReturn(0);
}

// Scales only (default windows, frequency unit): the mean EI and mu over the length of a profile or table.
PetscErrorCode SectionScales(BeamParams *p)
{
  const PetscInt n  = 4096;
  PetscReal      EI = 0, mu = 0;
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < n; ++k) {
    const SectionProperties q = SectionAt(p->section, (k + 0.5) * p->length / n);
    EI += q.EI / n, mu += q.mu / n;
  }
  p->EI = EI, p->mu = mu;
  PetscFunctionReturn(0);
}

// -beam_profile or -beam_properties: the rows, the length, and mean EI and mass per length.
PetscErrorCode BeamSectionFromFile(MPI_Comm comm, const BeamOptionValues &o, BeamParams *p)
{
  BeamSection &s = p->section;
  std::string  why;
  PetscFunctionBeginUser;
  PetscCheck(!(o.setprofile && o.setproperties), comm, PETSC_ERR_ARG_INCOMP,
             "-beam_profile and -beam_properties both describe the section: give one");
  const char *option = o.setprofile ? "-beam_profile" : "-beam_properties";
  const char *other  = UniformOptionGiven(o);
  PetscCheck(!other, comm, PETSC_ERR_ARG_INCOMP, "%s fixes the beam's length and sections: do not also give %s", option,
             other);
  if (o.setprofile) {
    PetscCheck(o.setE && o.setrho, comm, PETSC_ERR_ARG_WRONG,
               "-beam_profile %s needs the material: give -beam_youngs_modulus (Pa) and -beam_density (kg/m^3)",
               o.profile.c_str());
    PetscCheck(ProfileFileRead(o.profile.c_str(), &s.profile, &why), comm, PETSC_ERR_FILE_READ, "-beam_profile: %s",
               why.c_str());
    s.source     = SectionSource::Profile;
    s.file       = o.profile;
    s.material.E = o.E, s.material.rho = o.rho, s.material.G = o.G, s.material.nu = o.nu, s.material.kappa = o.kappa;
    const PetscReal x0 = s.profile.front().x;
    for (ProfileRow &r : s.profile) r.x -= x0;
    PetscCall(SectionShiftNote(comm, option, s.file, x0));
    if (o.setwall)
      PetscCheck(BarrelWallThicknessApply(o.wall, &s.profile, &why), comm, PETSC_ERR_ARG_OUTOFRANGE,
                 "-barrel_wall_thickness %g is not allowed with -beam_profile %s: %s", (double)o.wall, s.file.c_str(),
                 why.c_str());
    PetscCall(SectionRowsCheck(comm, option, s));
    p->input.youngs_modulus = o.E;
    p->input.density        = o.rho;
    p->input.parameter_set  = "profile";
  } else {
    PetscCheck(!(o.setE || o.setrho), comm, PETSC_ERR_ARG_INCOMP,
               "-beam_properties gives EI and mu directly: do not also give %s",
               o.setE ? "-beam_youngs_modulus" : "-beam_density");
    PetscCheck(PropertiesFileRead(o.properties.c_str(), &s.table, &s.table_has_shear, &s.table_has_torsion, &why), comm,
               PETSC_ERR_FILE_READ, "-beam_properties: %s", why.c_str());
    s.source           = SectionSource::Table;
    s.file             = o.properties;
    const PetscReal x0 = s.table.front().x;
    for (PropertiesRow &r : s.table) r.x -= x0;
    PetscCall(SectionShiftNote(comm, option, s.file, x0));
    p->input.parameter_set = "table";
  }
  p->length = SectionLength(s);
  PetscCall(SectionPlausibility(comm, option, s, p->length));
  PetscCall(SectionScales(p));
  PetscFunctionReturn(0);
}

// -bat_length: the profile of a bat by its maker's numbers (model/bat_maker.hpp), hollow with
// -barrel_wall_thickness, in the material of -beam_youngs_modulus and -beam_density.
PetscErrorCode BeamSectionFromMaker(MPI_Comm comm, const BeamOptionValues &o, BeamParams *p)
{
  BeamSection   &s = p->section;
  BatMakerParams b;
  std::string    why;
  PetscFunctionBeginUser;
  const char *other = o.setprofile ? "-beam_profile" : o.setproperties ? "-beam_properties" : UniformOptionGiven(o);
  PetscCheck(!other, comm, PETSC_ERR_ARG_INCOMP,
             "-bat_length (a bat by its maker's numbers) fixes the beam's length and sections: do not also give %s",
             other);
  PetscCheck(o.setE && o.setrho, comm, PETSC_ERR_ARG_WRONG,
             "-bat_length (a bat by its maker's numbers) needs the material: give -beam_youngs_modulus (Pa) and "
             "-beam_density (kg/m^3)");
  PetscCall(BatMakerParamsFromOptions(comm, o.setwall ? o.wall : 0, &b));
  PetscCheck(BatMakerProfile(b, o.rho, &s.profile, &why), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "the bat's maker's numbers describe no bat: %s", why.c_str());
  s.source     = SectionSource::Profile;
  s.file       = "(the bat maker's numbers: -bat_*)";
  s.material.E = o.E, s.material.rho = o.rho, s.material.G = o.G, s.material.nu = o.nu, s.material.kappa = o.kappa;
  PetscCall(SectionRowsCheck(comm, "-bat_length", s));
  p->input.youngs_modulus = o.E;
  p->input.density        = o.rho;
  p->input.parameter_set  = "profile";
  p->length               = SectionLength(s);
  PetscCall(SectionPlausibility(comm, "-bat_length", s, p->length));
  PetscCall(SectionScales(p));
  PetscFunctionReturn(0);
}

// -racket_length: the frame's table of a racket by its maker's numbers (model/racket_maker.hpp),
// strung with the parts that weigh on it (a string bed, its head's outline the maker's). Called
// after the parts that make the frame (StructurePartsFrame).
PetscErrorCode BeamSectionFromRacket(MPI_Comm comm, const BeamOptionValues &o, const RacketMakerParams &r,
                                     BeamParams *p)
{
  BeamSection &s = p->section;
  std::string  why;
  RacketStrung strung; // what the parts present weigh on the frame (a string bed: StructurePart::Strung)
  PetscFunctionBeginUser;
  for (const StructurePart *part : StructureParts())
    if (const PartParams *q = p->parts.Find(part->Name())) part->Strung(*q, &strung);
  PetscCheck(RacketMakerTable(r, strung, &s.table, &why), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "the racket's maker's numbers describe no racket: %s", why.c_str());
  s.source            = SectionSource::Table;
  s.file              = "(the racket maker's numbers: -racket_*)";
  s.table_has_shear   = true;
  s.table_has_torsion = true;
  (void)o;
  p->input.parameter_set = "table";
  p->length              = SectionLength(s);
  PetscCall(SectionScales(p));
  PetscFunctionReturn(0);
}

// The uniform parameter sets: (EI, mu), (M, L, a, E/rho) or (E, rho, a, b), and for the last
// the Timoshenko section of the rectangle (kappa G A, rho I) when G is given.
PetscErrorCode BeamUniformSection(MPI_Comm comm, const BeamOptionValues &o, BeamParams *p)
{
  BeamMaterialInput &in = p->input;
  PetscFunctionBeginUser;
  if (o.setEI || o.setmu) {
    PetscCheck(o.setEI && o.setmu, comm, PETSC_ERR_ARG_WRONG,
               "-beam_EI and -beam_mu go together: give both (got only %s)", o.setEI ? "-beam_EI" : "-beam_mu");
    PetscCheck(!(o.setE || o.setrho || o.seta || o.setb || o.setM || o.setErho), comm, PETSC_ERR_ARG_INCOMP,
               "contradicting beam parameter sets: -beam_EI/-beam_mu fix the beam; do not also give %s",
               o.setE     ? "-beam_youngs_modulus"
               : o.setrho ? "-beam_density"
               : o.seta   ? "-beam_thickness"
               : o.setb   ? "-beam_width"
               : o.setM   ? "-beam_mass"
                          : "-beam_youngs_over_density");
    p->EI = o.EI, p->mu = o.mu;
    in.parameter_set = "EI,mu";
  } else if (o.setM || o.setErho) {
    PetscCheck(o.setM && o.setErho, comm, PETSC_ERR_ARG_WRONG,
               "-beam_mass and -beam_youngs_over_density go together (with -beam_thickness): give both (got only %s)",
               o.setM ? "-beam_mass" : "-beam_youngs_over_density");
    PetscCheck(!(o.setE || o.setrho || o.setb), comm, PETSC_ERR_ARG_INCOMP,
               "contradicting beam parameter sets: -beam_mass with E/rho fixes the beam; do not also give %s",
               o.setE     ? "-beam_youngs_modulus"
               : o.setrho ? "-beam_density"
                          : "-beam_width");
    p->mu                  = o.M / p->length;
    p->EI                  = o.Erho * p->mu * o.a * o.a / 12.0; // E b a^3/12 = (E/rho) (rho a b) a^2/12
    in.mass                = o.M;
    in.youngs_over_density = o.Erho;
    in.thickness           = o.a;
    in.parameter_set       = "M,L,a,E/rho";
  } else {
    p->mu             = o.rho * o.a * o.b;
    p->EI             = o.E * o.b * o.a * o.a * o.a / 12.0;
    p->rhoI           = o.rho * o.b * o.a * o.a * o.a / 12.0;
    p->kGA            = (o.kappa > 0 ? o.kappa : CowperRectangle(o.nu)) * o.G * o.a * o.b;
    in.youngs_modulus = o.E;
    in.density        = o.rho;
    in.thickness      = o.a;
    in.width          = o.b;
    in.parameter_set  = "E,rho,a,b";
  }
  PetscFunctionReturn(0);
}

// What a Timoshenko beam needs: a section with area (shear stiffness and rotary inertia).
PetscErrorCode TimoshenkoCheck(MPI_Comm comm, const BeamOptionValues &o, const BeamParams &p)
{
  const BeamSection &s = p.section;
  PetscFunctionBeginUser;
  if (p.theory != "timoshenko") PetscFunctionReturn(0);
  if (s.source == SectionSource::Table) {
    PetscCheck(s.table_has_shear, comm, PETSC_ERR_ARG_WRONG,
               "-beam_theory timoshenko with -beam_properties %s needs five columns 'x EI mu kappaGA rhoI'; the file "
               "has three",
               s.file.c_str());
    PetscFunctionReturn(0);
  }
  PetscCheck(s.source == SectionSource::Profile || p.input.parameter_set == "E,rho,a,b", comm, PETSC_ERR_ARG_WRONG,
             "-beam_theory timoshenko needs the section's area and material: give -beam_youngs_modulus, -beam_density, "
             "-beam_thickness, -beam_width (or -beam_profile, or a five-column -beam_properties), not the %s set",
             p.input.parameter_set.c_str());
  PetscCheck(o.G > 0, comm, PETSC_ERR_ARG_WRONG, "-beam_theory timoshenko needs -beam_shear_modulus G > 0 (Pa)");
  PetscFunctionReturn(0);
}

// "a clamped end (-beam_left clamped)": the first end whose support holds what `holds` tests;
// "" when neither does.
std::string HeldEnd(const BeamParams &p, bool (*holds)(NodeHold))
{
  for (const char *end : {"left", "right"}) {
    const Support s = *end == 'l' ? p.left : p.right;
    if (holds(s.Holds())) return std::string("a ") + s.Name() + " end (-beam_" + end + " " + s.Name() + ")";
  }
  return "";
}

} // namespace

namespace {

// -beam_pivot: inside the beam, off the grid's end nodes, free ends, not inside a clamp.
PetscErrorCode PivotCheck(MPI_Comm comm, const BeamParams &p)
{
  PetscFunctionBeginUser;
  PetscCheck(p.pivot_x > 0 && p.pivot_x < p.length, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_pivot %g is not allowed: the pivot must be inside the beam, 0 < x_p < L = %g (m)",
             (double)p.pivot_x, (double)p.length);
  const std::string end = HeldEnd(p, HoldsRotation);
  PetscCheck(end.empty(), comm, PETSC_ERR_ARG_INCOMP,
             "-beam_pivot %g with %s is not allowed: a pivoted bat is free at both ends (or pinned)", (double)p.pivot_x,
             end.c_str());
  PetscCheck(!(p.has_clamp && p.pivot_x >= p.clamp_x0 && p.pivot_x <= p.clamp_x1), comm, PETSC_ERR_ARG_INCOMP,
             "-beam_pivot %g is not allowed: it lies inside the clamped region -beam_clamp %g,%g", (double)p.pivot_x,
             (double)p.clamp_x0, (double)p.clamp_x1);
  const PetscInt k = BeamPivotNode(p);
  PetscCheck(k > 0 && k < p.nodes - 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_pivot %g falls on an end node of the grid (h = %g m): move it inward or use more -beam_nodes",
             (double)p.pivot_x, (double)(p.length / (p.nodes - 1)));
  PetscFunctionReturn(0);
}

// -beam_clamp: an interval of the beam that leaves at least 3 nodes free.
PetscErrorCode ClampCheck(MPI_Comm comm, const BeamParams &p)
{
  PetscFunctionBeginUser;
  PetscCheck(p.clamp_x0 >= 0 && p.clamp_x1 <= p.length && p.clamp_x0 < p.clamp_x1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_clamp %g,%g is not allowed: need 0 <= x0 < x1 <= L = %g (m)", (double)p.clamp_x0,
             (double)p.clamp_x1, (double)p.length);
  PetscInt nfree = 0;
  for (NodeHold h : BeamNodeHolds(p)) nfree += !HoldsDeflection(h);
  PetscCheck(nfree >= 3, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_clamp %g,%g holds all but %" PetscInt_FMT " of the %" PetscInt_FMT
             " nodes: at least 3 must stay free",
             (double)p.clamp_x0, (double)p.clamp_x1, nfree, p.nodes);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode BeamParamsCheck(MPI_Comm comm, const BeamParams &p)
{
  PetscFunctionBeginUser;
  PetscCheck(p.length > 0 && std::isfinite(p.length), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_length %g is not allowed: the length must be finite and > 0 (m)", (double)p.length);
  PetscCheck(p.EI > 0 && std::isfinite(p.EI), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "bending stiffness EI = %g is not allowed: it must be > 0 (N m^2)", (double)p.EI);
  PetscCheck(p.mu > 0 && std::isfinite(p.mu), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "mass per length mu = %g is not allowed: it must be > 0 (kg/m)", (double)p.mu);
  PetscCheck(p.damping_mass >= 0 && std::isfinite(p.damping_mass), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_damping_mass %g is not allowed: alpha must be >= 0 (1/s)", (double)p.damping_mass);
  PetscCheck(p.damping_stiffness >= 0 && std::isfinite(p.damping_stiffness), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_damping_stiffness %g is not allowed: beta must be >= 0 (s)", (double)p.damping_stiffness);
  PetscCheck(p.nodes >= 5, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-beam_nodes %" PetscInt_FMT " is not allowed: at least 5 nodes are needed", p.nodes);
  PetscCheck(BeamTheoryFind(p.theory.c_str()), comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-beam_theory %s is not known: %s",
             p.theory.c_str(), BeamOptionTable().Find("-beam_theory")->Allowed().c_str());
  if (p.has_pivot) PetscCall(PivotCheck(comm, p));
  if (p.has_clamp && !p.frame_held) PetscCall(ClampCheck(comm, p)); // a held frame is clamped everywhere
  PetscFunctionReturn(0);
}

// A registered structure part's rows (system/structure_part.hpp), read in its own -help block:
// the given ones into *v (a flag as 1, a number as one value, a list as its values).
PetscErrorCode StructurePartOptionsRead(MPI_Comm comm, const StructurePart &part, PartOptionValues *v)
{
  const OptionModule &T = part.Options();

  PetscFunctionBeginUser;
  v->given.clear();
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  for (const OptionSpec &o : T.options) {
    PetscBool              set = PETSC_FALSE;
    std::vector<PetscReal> values;
    if (o.kind == OptionKind::RealList) PetscCall(OptionsRead(PetscOptionsObject, T, o.name.c_str(), &values, &set));
    else if (o.kind == OptionKind::Real) {
      PetscReal x = part.Unset(o.name.c_str(), *v);
      PetscCall(OptionsRead(PetscOptionsObject, T, o.name.c_str(), &x, &set));
      values = {x};
    } else if (o.kind == OptionKind::Bool) {
      PetscBool b = PETSC_FALSE;
      PetscCall(OptionsRead(PetscOptionsObject, T, o.name.c_str(), &b, &set));
      values = {b ? 1.0 : 0.0};
    } else if (o.kind == OptionKind::Int || o.kind == OptionKind::Choice) { // a whole number, a choice's index
      PetscInt n = (PetscInt)part.Unset(o.name.c_str(), *v);
      if (o.kind == OptionKind::Int) PetscCall(OptionsRead(PetscOptionsObject, T, o.name.c_str(), &n, &set));
      else PetscCall(OptionsReadChoice(PetscOptionsObject, T, o.name.c_str(), &n, &set));
      values = {(PetscReal)n};
    } else
      SETERRQ(comm, PETSC_ERR_PLIB, "%s: the part's reader takes numbers, choices, lists and flags", o.name.c_str());
    if (set) v->given[o.name] = values;
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

// Every registered structure part's options -> its parameters in p->parts (absent when not given),
// once the beam's holds are known; a refusal names the option and its value.
PetscErrorCode StructurePartsFromOptions(MPI_Comm comm, BeamParams *p)
{
  PetscFunctionBeginUser;
  for (const StructurePart *part : StructureParts()) {
    PartOptionValues                  v;
    std::shared_ptr<const PartParams> q;
    std::string                       why;
    if (part->Frames()) continue; // set up with the beam (StructurePartsFrame)
    PetscCall(StructurePartOptionsRead(comm, *part, &v));
    PetscCheck(part->Configure(v, *p, &q, &why), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", why.c_str());
    p->parts.Set(part->Name(), q);
    const std::string note = q ? part->Note(*q, *p) : ""; // beyond the part's range: say so, once
    if (!note.empty()) PetscCall(PrintOnce(comm, ("note: " + note + "\n").c_str()));
  }
  const std::string why = StructurePartsRefusalWith(*p); // the checks of one part against another
  PetscCheck(why.empty(), comm, PETSC_ERR_ARG_INCOMP, "%s", why.c_str());
  PetscFunctionReturn(0);
}

// The parts that make the frame they sit on (StructurePart::Frames: a string bed), on the beam as
// read so far: each may make the beam its frame, and a racket maker's numbers place them.
PetscErrorCode StructurePartsFrame(MPI_Comm comm, const RacketMakerParams *racket, BeamParams *p)
{
  PetscFunctionBeginUser;
  for (const StructurePart *part : StructureParts()) {
    if (!part->Frames()) continue;
    PartOptionValues                  v;
    std::shared_ptr<const PartParams> q;
    std::string                       why;
    PetscBool                         gate = PETSC_TRUE;
    if (part->Gate()) PetscCall(PetscOptionsHasName(NULL, NULL, part->Gate(), &gate));
    if (gate) { // its rows read, checked and recorded only with its gate
      PetscCall(StructurePartOptionsRead(comm, *part, &v));
      const int code = part->Frame(v, racket, p, &q, &why);
      PetscCheck(!code, comm, (PetscErrorCode)code, "%s", why.c_str());
    }
    p->parts.Set(part->Name(), q);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BeamParamsFromOptions(MPI_Comm comm, BeamParams *p)
{
  BeamOptionValues o;
  PetscFunctionBeginUser;
  PetscBool         maker = PETSC_FALSE, racket_on = PETSC_FALSE;
  RacketMakerParams racket;
  PetscCall(BeamOptionsRead(comm, p, &o));
  PetscCall(BatMakerRequested(comm, &maker));
  PetscCall(RacketMakerRequested(comm, &racket_on));
  PetscCheck(!(maker && racket_on), comm, PETSC_ERR_ARG_INCOMP,
             "-bat_length and -racket_length both describe the beam: give one");
  if (racket_on) {
    const char *other = o.setprofile ? "-beam_profile" : o.setproperties ? "-beam_properties" : UniformOptionGiven(o);
    PetscCheck(!other, comm, PETSC_ERR_ARG_INCOMP,
               "-racket_length (a racket by its maker's numbers) fixes the frame's length and sections: do not also "
               "give %s",
               other);
    PetscCall(RacketMakerParamsFromOptions(comm, &racket));
    p->length = racket.length;
    p->EI = racket.frame_stiffness, p->mu = racket.mass / racket.length; // until the table is made
  } else if (maker) PetscCall(BeamSectionFromMaker(comm, o, p));
  else if (o.setprofile || o.setproperties) PetscCall(BeamSectionFromFile(comm, o, p));
  else PetscCall(BeamUniformSection(comm, o, p));
  if (!racket_on) PetscCall(TimoshenkoCheck(comm, o, *p));
  PetscCall(StructurePartsFrame(comm, racket_on ? &racket : nullptr, p));
  if (racket_on && !p->frame_held) { // a held frame is no racket's
    PetscCall(BeamSectionFromRacket(comm, o, racket, p));
    PetscCall(TimoshenkoCheck(comm, o, *p));
  }
  PetscCall(BeamParamsCheck(comm, *p));
  if (p->has_pivot) { // the pivot sits on a node: say where when that moves it
    const PetscReal h = p->length / (p->nodes - 1), xk = BeamPivotNode(*p) * h;
    char            text[256];
    if (std::abs(xk - p->pivot_x) > 1e-9 * h) {
      std::snprintf(text, sizeof text,
                    "note: -beam_pivot %g is placed on the nearest node, x_p = %.6g m (h = %.3g m); choose -beam_nodes "
                    "to put it exactly\n",
                    (double)p->pivot_x, (double)xk, (double)h);
      PetscCall(PrintOnce(comm, text)); // once, also in a sweep
    }
    p->pivot_x = xk;
  }
  if (p->has_clamp) { // the nodes inside [x0, x1] are held: say where the held region ends when an edge falls between
                      // nodes
    const PetscReal h = p->length / (p->nodes - 1), tol = 1e-9 * h;
    const PetscReal a = std::ceil((p->clamp_x0 - tol) / h) * h + 0.0,
                    b = std::floor((p->clamp_x1 + tol) / h) * h; // + 0.0: not -0
    char text[512];
    if (std::abs(a - p->clamp_x0) > tol || std::abs(b - p->clamp_x1) > tol) {
      std::snprintf(text, sizeof text,
                    "note: -beam_clamp %g,%g holds the nodes from x = %.6g to x = %.6g m (h = %.3g m): an edge between "
                    "nodes moves to the node inside the clamp; choose -beam_nodes to put it exactly\n",
                    (double)p->clamp_x0, (double)p->clamp_x1, (double)a, (double)b, (double)h);
      PetscCall(PrintOnce(comm, text));
    }
  }
  PetscCall(StructurePartsFromOptions(comm, p)); // on the beam as held (the pivot on its node)
  PetscFunctionReturn(0);
}

} // namespace beamimpact

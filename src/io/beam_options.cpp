// The -beam_* options. See beam_options.hpp.
#include "io/beam_options.hpp"

#include "io/section_file.hpp"
#include "model/beam_theory.hpp"

#include <cmath>
#include <string>

namespace beamimpact {

namespace {

// The raw option values and which were given.
struct BeamOptionValues {
  PetscReal E = 7e10, rho = 2700, a = 0.006, b = 0.032, M = 0, Erho = 0, EI = 0, mu = 0; // the paper's aluminium beam
  PetscReal G = 0, kappa = 0, nu = 0.3;
  PetscBool setE = PETSC_FALSE, setrho = PETSC_FALSE, seta = PETSC_FALSE, setb = PETSC_FALSE, setM = PETSC_FALSE, setErho = PETSC_FALSE, setEI = PETSC_FALSE, setmu = PETSC_FALSE;
  PetscBool setlength = PETSC_FALSE, setprofile = PETSC_FALSE, setproperties = PETSC_FALSE;
  char      profile[PETSC_MAX_PATH_LEN] = "", properties[PETSC_MAX_PATH_LEN] = "", theory[64] = "euler";
};

std::string TheoryList()
{
  std::string s;
  for (const char *n : BeamTheoryNames()) s += (s.empty() ? "" : "|") + std::string(n);
  return s;
}

PetscErrorCode BeamOptionsRead(MPI_Comm comm, BeamParams *p, BeamOptionValues *o)
{
  PetscEnum left = (PetscEnum)p->left, right = (PetscEnum)p->right;
  PetscReal clamp[2] = {0, 0};
  PetscInt  nclamp   = 2;
  PetscBool setclamp = PETSC_FALSE, setpivot = PETSC_FALSE, setgrip = PETSC_FALSE;
  PetscReal grip[2]  = {0, 0};
  PetscInt  ngrip    = 2;
  const std::string theories = "Beam theory: " + TheoryList();

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Beam: geometry, material, section, theory and supports (SI units)", "beamimpact");
  PetscCall(PetscOptionsReal("-beam_length", "Beam length L (m); not with a profile or table (they span their rows)", "", p->length, &p->length, &o->setlength));
  PetscCall(PetscOptionsReal("-beam_thickness", "Thickness a in the direction of motion (m)", "", o->a, &o->a, &o->seta));
  PetscCall(PetscOptionsReal("-beam_width", "Width b (m); with E and rho", "", o->b, &o->b, &o->setb));
  PetscCall(PetscOptionsReal("-beam_youngs_modulus", "Young's modulus E (Pa); with rho, a, b, or with -beam_profile", "", o->E, &o->E, &o->setE));
  PetscCall(PetscOptionsReal("-beam_density", "Density rho (kg/m^3); with E, a, b, or with -beam_profile", "", o->rho, &o->rho, &o->setrho));
  PetscCall(PetscOptionsReal("-beam_mass", "Total mass M (kg); with -beam_youngs_over_density and a", "", o->M, &o->M, &o->setM));
  PetscCall(PetscOptionsReal("-beam_youngs_over_density", "E/rho (N m/kg); with -beam_mass and a", "", o->Erho, &o->Erho, &o->setErho));
  PetscCall(PetscOptionsReal("-beam_EI", "Bending stiffness EI (N m^2); with -beam_mu", "", o->EI, &o->EI, &o->setEI));
  PetscCall(PetscOptionsReal("-beam_mu", "Mass per length mu (kg/m); with -beam_EI", "", o->mu, &o->mu, &o->setmu));
  PetscCall(PetscOptionsString("-beam_profile", "Round sections along the beam: file of rows 'x D [d]' (m), with E and rho", "", o->profile, o->profile, sizeof o->profile, &o->setprofile));
  PetscCall(PetscOptionsString("-beam_properties", "Section properties along the beam: file of rows 'x EI mu [kappaGA rhoI]' (SI)", "", o->properties, o->properties, sizeof o->properties, &o->setproperties));
  PetscCall(PetscOptionsString("-beam_theory", theories.c_str(), "", o->theory, o->theory, sizeof o->theory, NULL));
  PetscCall(PetscOptionsReal("-beam_shear_modulus", "Shear modulus G (Pa): Timoshenko with E, rho (uniform or profile)", "", o->G, &o->G, NULL));
  PetscCall(PetscOptionsReal("-beam_shear_coefficient", "Shear coefficient kappa; 0: Cowper's by section (round tube, rectangle)", "", o->kappa, &o->kappa, NULL));
  PetscCall(PetscOptionsReal("-beam_poisson", "Poisson's ratio nu (Cowper's shear coefficient)", "", o->nu, &o->nu, NULL));
  PetscCall(PetscOptionsInt("-beam_nodes", "Number of grid nodes N (>= 5)", "", p->nodes, &p->nodes, NULL));
  PetscCall(PetscOptionsEnum("-beam_left", "Support at x = 0", "", SupportNames, left, &left, NULL));
  PetscCall(PetscOptionsEnum("-beam_right", "Support at x = L", "", SupportNames, right, &right, NULL));
  PetscCall(PetscOptionsRealArray("-beam_clamp", "Clamped region x0,x1 (m) held fixed (a handle in a vice)", "", clamp, &nclamp, &setclamp));
  PetscCall(PetscOptionsReal("-beam_pivot", "Pivot x_p (m): an interior point held at y = 0, free to rotate (a test rig; on the nearest node)", "", p->pivot_x, &p->pivot_x, &setpivot));
  PetscCall(PetscOptionsReal("-beam_damping_mass", "Rayleigh damping alpha (1/s): C = alpha M + beta K, zeta = alpha/(2 omega) + beta omega/2", "", p->damping_mass, &p->damping_mass, NULL));
  PetscCall(PetscOptionsReal("-beam_damping_stiffness", "Rayleigh damping beta (s)", "", p->damping_stiffness, &p->damping_stiffness, NULL));
  PetscCall(PetscOptionsRealArray("-grip", "The hands: grip x_a,x_b (m), a spring-damper per metre of handle tying it to the swing's rigid frame (a free beam)", "", grip, &ngrip, &setgrip));
  PetscCall(PetscOptionsReal("-grip_stiffness", "Grip stiffness k' (N/m per m of handle): force -k' (y - v_f t) per metre", "", p->grip.stiffness, &p->grip.stiffness, NULL));
  PetscCall(PetscOptionsReal("-grip_damping", "Grip damping c' (N s/m per m of handle): force -c' (v - v_f) per metre", "", p->grip.damping, &p->grip.damping, NULL));
  PetscCall(PetscOptionsReal("-grip_mass", "Mass of the hands (kg), spread over the grip's translational dofs", "", p->grip.mass, &p->grip.mass, NULL));
  PetscOptionsEnd();

  p->left   = (Support)left;
  p->right  = (Support)right;
  p->theory = o->theory;
  PetscCheck(BeamTheoryFind(o->theory), comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-beam_theory %s is not known: use one of %s", o->theory, TheoryList().c_str());
  p->has_pivot = setpivot;
  if (setgrip) {
    PetscCheck(ngrip == 2, comm, PETSC_ERR_ARG_WRONG, "-grip takes two numbers x_a,x_b (m); got %" PetscInt_FMT, ngrip);
    p->grip.on  = true;
    p->grip.x_a = grip[0];
    p->grip.x_b = grip[1];
  }
  if (setclamp) {
    PetscCheck(nclamp == 2, comm, PETSC_ERR_ARG_WRONG, "-beam_clamp takes two numbers x0,x1 (m); got %" PetscInt_FMT, nclamp);
    p->has_clamp = true;
    p->clamp_x0  = clamp[0];
    p->clamp_x1  = clamp[1];
  }
  PetscFunctionReturn(0);
}

// The first option of a uniform parameter set that was given, or nullptr.
const char *UniformOptionGiven(const BeamOptionValues &o)
{
  return o.setlength ? "-beam_length" : o.seta ? "-beam_thickness" : o.setb ? "-beam_width" : o.setM ? "-beam_mass" : o.setErho ? "-beam_youngs_over_density" : o.setEI ? "-beam_EI" : o.setmu ? "-beam_mu" : nullptr;
}

// -beam_profile or -beam_properties: the rows, the length, and mean EI and mass per length.
PetscErrorCode BeamSectionFromFile(MPI_Comm comm, const BeamOptionValues &o, BeamParams *p)
{
  BeamSection &s = p->section;
  std::string  why;
  PetscFunctionBeginUser;
  PetscCheck(!(o.setprofile && o.setproperties), comm, PETSC_ERR_ARG_INCOMP, "-beam_profile and -beam_properties both describe the section: give one");
  const char *option = o.setprofile ? "-beam_profile" : "-beam_properties";
  const char *other  = UniformOptionGiven(o);
  PetscCheck(!other, comm, PETSC_ERR_ARG_INCOMP, "%s fixes the beam's length and sections: do not also give %s", option, other);
  if (o.setprofile) {
    PetscCheck(o.setE && o.setrho, comm, PETSC_ERR_ARG_WRONG, "-beam_profile %s needs the material: give -beam_youngs_modulus (Pa) and -beam_density (kg/m^3)", o.profile);
    PetscCheck(ProfileFileRead(o.profile, &s.profile, &why), comm, PETSC_ERR_FILE_READ, "-beam_profile: %s", why.c_str());
    s.source     = SectionSource::Profile;
    s.file       = o.profile;
    s.material.E = o.E, s.material.rho = o.rho, s.material.G = o.G, s.material.nu = o.nu, s.material.kappa = o.kappa;
    const PetscReal x0 = s.profile.front().x;
    for (ProfileRow &r : s.profile) r.x -= x0;
    p->input.youngs_modulus = o.E;
    p->input.density        = o.rho;
    p->input.parameter_set  = "profile";
  } else {
    PetscCheck(!(o.setE || o.setrho), comm, PETSC_ERR_ARG_INCOMP, "-beam_properties gives EI and mu directly: do not also give %s", o.setE ? "-beam_youngs_modulus" : "-beam_density");
    PetscCheck(PropertiesFileRead(o.properties, &s.table, &s.table_has_shear, &why), comm, PETSC_ERR_FILE_READ, "-beam_properties: %s", why.c_str());
    s.source           = SectionSource::Table;
    s.file             = o.properties;
    const PetscReal x0 = s.table.front().x;
    for (PropertiesRow &r : s.table) r.x -= x0;
    p->input.parameter_set = "table";
  }
  p->length = SectionLength(s);
  // Scales only (default windows, frequency unit): the mean EI and mu over the length.
  const PetscInt n  = 4096;
  PetscReal      EI = 0, mu = 0;
  for (PetscInt k = 0; k < n; ++k) {
    const SectionProperties q = SectionAt(s, (k + 0.5) * p->length / n);
    EI += q.EI / n, mu += q.mu / n;
  }
  p->EI = EI, p->mu = mu;
  PetscFunctionReturn(0);
}

// The uniform parameter sets: (EI, mu), (M, L, a, E/rho) or (E, rho, a, b), and for the last
// the Timoshenko section of the rectangle (kappa G A, rho I) when G is given.
PetscErrorCode BeamUniformSection(MPI_Comm comm, const BeamOptionValues &o, BeamParams *p)
{
  BeamMaterialInput &in = p->input;
  PetscFunctionBeginUser;
  if (o.setEI || o.setmu) {
    PetscCheck(o.setEI && o.setmu, comm, PETSC_ERR_ARG_WRONG, "-beam_EI and -beam_mu go together: give both (got only %s)", o.setEI ? "-beam_EI" : "-beam_mu");
    PetscCheck(!(o.setE || o.setrho || o.seta || o.setb || o.setM || o.setErho), comm, PETSC_ERR_ARG_INCOMP, "contradicting beam parameter sets: -beam_EI/-beam_mu fix the beam; do not also give %s",
               o.setE ? "-beam_youngs_modulus" : o.setrho ? "-beam_density" : o.seta ? "-beam_thickness" : o.setb ? "-beam_width" : o.setM ? "-beam_mass" : "-beam_youngs_over_density");
    p->EI = o.EI, p->mu = o.mu;
    in.parameter_set = "EI,mu";
  } else if (o.setM || o.setErho) {
    PetscCheck(o.setM && o.setErho, comm, PETSC_ERR_ARG_WRONG, "-beam_mass and -beam_youngs_over_density go together (with -beam_thickness): give both (got only %s)", o.setM ? "-beam_mass" : "-beam_youngs_over_density");
    PetscCheck(!(o.setE || o.setrho || o.setb), comm, PETSC_ERR_ARG_INCOMP, "contradicting beam parameter sets: -beam_mass with E/rho fixes the beam; do not also give %s",
               o.setE ? "-beam_youngs_modulus" : o.setrho ? "-beam_density" : "-beam_width");
    PetscCheck(o.M > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_mass %g is not allowed: it must be > 0 (kg)", (double)o.M);
    PetscCheck(o.Erho > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_youngs_over_density %g is not allowed: it must be > 0 (N m/kg)", (double)o.Erho);
    PetscCheck(o.a > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_thickness %g is not allowed: it must be > 0 (m)", (double)o.a);
    PetscCheck(p->length > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_length %g is not allowed: the length must be > 0 (m)", (double)p->length);
    p->mu                  = o.M / p->length;
    p->EI                  = o.Erho * p->mu * o.a * o.a / 12.0; // E b a^3/12 = (E/rho) (rho a b) a^2/12
    in.mass                = o.M;
    in.youngs_over_density = o.Erho;
    in.thickness           = o.a;
    in.parameter_set       = "M,L,a,E/rho";
  } else {
    PetscCheck(o.E > 0 && std::isfinite(o.E), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_youngs_modulus %g is not allowed: it must be > 0 (Pa)", (double)o.E);
    PetscCheck(o.rho > 0 && std::isfinite(o.rho), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_density %g is not allowed: it must be > 0 (kg/m^3)", (double)o.rho);
    PetscCheck(o.a > 0 && std::isfinite(o.a), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_thickness %g is not allowed: it must be > 0 (m)", (double)o.a);
    PetscCheck(o.b > 0 && std::isfinite(o.b), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_width %g is not allowed: it must be > 0 (m)", (double)o.b);
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
    PetscCheck(s.table_has_shear, comm, PETSC_ERR_ARG_WRONG, "-beam_theory timoshenko with -beam_properties %s needs five columns 'x EI mu kappaGA rhoI'; the file has three", s.file.c_str());
    PetscFunctionReturn(0);
  }
  PetscCheck(s.source == SectionSource::Profile || p.input.parameter_set == "E,rho,a,b", comm, PETSC_ERR_ARG_WRONG,
             "-beam_theory timoshenko needs the section's area and material: give -beam_youngs_modulus, -beam_density, -beam_thickness, -beam_width (or -beam_profile, or a five-column -beam_properties), not the %s set",
             p.input.parameter_set.c_str());
  PetscCheck(o.G > 0, comm, PETSC_ERR_ARG_WRONG, "-beam_theory timoshenko needs -beam_shear_modulus G > 0 (Pa); got %g", (double)o.G);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode BeamParamsCheck(MPI_Comm comm, const BeamParams &p)
{
  PetscFunctionBeginUser;
  PetscCheck(p.length > 0 && std::isfinite(p.length), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_length %g is not allowed: the length must be finite and > 0 (m)", (double)p.length);
  PetscCheck(p.EI > 0 && std::isfinite(p.EI), comm, PETSC_ERR_ARG_OUTOFRANGE, "bending stiffness EI = %g is not allowed: it must be > 0 (N m^2)", (double)p.EI);
  PetscCheck(p.mu > 0 && std::isfinite(p.mu), comm, PETSC_ERR_ARG_OUTOFRANGE, "mass per length mu = %g is not allowed: it must be > 0 (kg/m)", (double)p.mu);
  PetscCheck(p.damping_mass >= 0 && std::isfinite(p.damping_mass), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_damping_mass %g is not allowed: alpha must be >= 0 (1/s)", (double)p.damping_mass);
  PetscCheck(p.damping_stiffness >= 0 && std::isfinite(p.damping_stiffness), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_damping_stiffness %g is not allowed: beta must be >= 0 (s)", (double)p.damping_stiffness);
  PetscCheck(p.nodes >= 5, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_nodes %" PetscInt_FMT " is not allowed: at least 5 nodes are needed", p.nodes);
  PetscCheck(BeamTheoryFind(p.theory.c_str()), comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-beam_theory %s is not known: use one of %s", p.theory.c_str(), TheoryList().c_str());
  if (p.has_pivot) {
    PetscCheck(p.pivot_x > 0 && p.pivot_x < p.length, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_pivot %g is not allowed: the pivot must be inside the beam, 0 < x_p < L = %g (m)", (double)p.pivot_x,
               (double)p.length);
    PetscCheck(p.left != Support::Clamped && p.right != Support::Clamped, comm, PETSC_ERR_ARG_INCOMP,
               "-beam_pivot %g with a clamped end (-beam_%s clamped) is not allowed: a pivoted bat is free at both ends (or pinned)", (double)p.pivot_x, p.left == Support::Clamped ? "left" : "right");
    PetscCheck(!(p.has_clamp && p.pivot_x >= p.clamp_x0 && p.pivot_x <= p.clamp_x1), comm, PETSC_ERR_ARG_INCOMP, "-beam_pivot %g is not allowed: it lies inside the clamped region -beam_clamp %g,%g",
               (double)p.pivot_x, (double)p.clamp_x0, (double)p.clamp_x1);
    const PetscInt k = BeamPivotNode(p);
    PetscCheck(k > 0 && k < p.nodes - 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_pivot %g falls on an end node of the grid (h = %g m): move it inward or use more -beam_nodes", (double)p.pivot_x,
               (double)(p.length / (p.nodes - 1)));
  }
  if (p.grip.on) {
    const BeamGrip &g = p.grip;
    PetscCheck(g.x_a >= 0 && g.x_b <= p.length && g.x_a < g.x_b, comm, PETSC_ERR_ARG_OUTOFRANGE, "-grip %g,%g is not allowed: the grip must be a non-empty interval of the beam, 0 <= x_a < x_b <= L = %g (m)",
               (double)g.x_a, (double)g.x_b, (double)p.length);
    PetscCheck(g.stiffness >= 0 && std::isfinite(g.stiffness), comm, PETSC_ERR_ARG_OUTOFRANGE, "-grip_stiffness %g is not allowed: it must be >= 0 (N/m per m)", (double)g.stiffness);
    PetscCheck(g.damping >= 0 && std::isfinite(g.damping), comm, PETSC_ERR_ARG_OUTOFRANGE, "-grip_damping %g is not allowed: it must be >= 0 (N s/m per m)", (double)g.damping);
    PetscCheck(g.mass >= 0 && std::isfinite(g.mass), comm, PETSC_ERR_ARG_OUTOFRANGE, "-grip_mass %g is not allowed: it must be >= 0 (kg)", (double)g.mass);
    PetscCheck(p.left != Support::Clamped && p.right != Support::Clamped, comm, PETSC_ERR_ARG_INCOMP, "-grip %g,%g with a clamped end (-beam_%s clamped) is not allowed: the hands hold a free bat",
               (double)g.x_a, (double)g.x_b, p.left == Support::Clamped ? "left" : "right");
    PetscCheck(p.left != Support::Pinned && p.right != Support::Pinned, comm, PETSC_ERR_ARG_INCOMP, "-grip %g,%g with a pinned end (-beam_%s pinned) is not allowed: the hands hold a free bat",
               (double)g.x_a, (double)g.x_b, p.left == Support::Pinned ? "left" : "right");
    PetscCheck(!p.has_clamp, comm, PETSC_ERR_ARG_INCOMP, "-grip %g,%g with a clamped region (-beam_clamp %g,%g) is not allowed: the hands hold a free bat", (double)g.x_a, (double)g.x_b, (double)p.clamp_x0,
               (double)p.clamp_x1);
    PetscCheck(!p.has_pivot, comm, PETSC_ERR_ARG_INCOMP, "-grip %g,%g with a pivot (-beam_pivot %g) is not allowed: the hands hold a free bat (the pivot is the certification rig's)", (double)g.x_a,
               (double)g.x_b, (double)p.pivot_x);
  }
  if (p.has_clamp) {
    PetscCheck(p.clamp_x0 >= 0 && p.clamp_x1 <= p.length && p.clamp_x0 < p.clamp_x1, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-beam_clamp %g,%g is not allowed: need 0 <= x0 < x1 <= L = %g (m)", (double)p.clamp_x0, (double)p.clamp_x1, (double)p.length);
    PetscInt nfree = 0;
    for (NodeHold h : BeamNodeHolds(p)) nfree += h == NodeHold::None;
    PetscCheck(nfree >= 3, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_clamp %g,%g holds all but %" PetscInt_FMT " of the %" PetscInt_FMT " nodes: at least 3 must stay free", (double)p.clamp_x0,
               (double)p.clamp_x1, nfree, p.nodes);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BeamParamsFromOptions(MPI_Comm comm, BeamParams *p)
{
  BeamOptionValues o;
  PetscFunctionBeginUser;
  PetscCall(BeamOptionsRead(comm, p, &o));
  PetscCheck(o.nu > -1 && o.nu < 0.5, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_poisson %g is not allowed: need -1 < nu < 0.5", (double)o.nu);
  PetscCheck(o.kappa >= 0 && o.kappa <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_shear_coefficient %g is not allowed: need 0 < kappa <= 1 (or 0: Cowper's by section)", (double)o.kappa);
  PetscCheck(o.G >= 0 && std::isfinite(o.G), comm, PETSC_ERR_ARG_OUTOFRANGE, "-beam_shear_modulus %g is not allowed: it must be > 0 (Pa)", (double)o.G);
  if (o.setprofile || o.setproperties) PetscCall(BeamSectionFromFile(comm, o, p));
  else PetscCall(BeamUniformSection(comm, o, p));
  PetscCall(TimoshenkoCheck(comm, o, *p));
  PetscCall(BeamParamsCheck(comm, *p));
  if (p->has_pivot) { // the pivot sits on a node: say where when that moves it
    const PetscReal h = p->length / (p->nodes - 1), xk = BeamPivotNode(*p) * h;
    if (std::abs(xk - p->pivot_x) > 1e-9 * h)
      PetscCall(PetscPrintf(comm, "note: -beam_pivot %g is placed on the nearest node, x_p = %.6g m (h = %.3g m); choose -beam_nodes to put it exactly\n", (double)p->pivot_x, (double)xk, (double)h));
    p->pivot_x = xk;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

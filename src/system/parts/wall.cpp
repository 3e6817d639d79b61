// The barrel wall (docs/model.md section 14): a hollow bat's barrel deforms under the ball, in
// series with it, either as the lumped hoop oscillator (-barrel_hoop_frequency, -barrel_hoop_mass;
// model/barrel.hpp: one more field per node, free only at node 0, a coupled dof of weight 1) or
// as a thin cylindrical shell (-beam_shell; model/shell.hpp: three fields U_n, V_n, W_n per
// harmonic n where the profile is hollow, the ball's load a patch of radius a on each W_n). They
// exclude each other and share the wall's columns and its energy account ("wall", kept apart from
// the beam's: AccountApart). A structure part (system/structure_part.hpp): its option rows and checks,
// the patch radius at the impact point, its fields, coupling, -task modes' family detail (the harmonic
// n; the hoop counts as n = 2), the shell's snapshots, its columns (shell_energy_end, wall_fraction,
// shell_energy_peak, wall_deflection_peak, wall_deflection_large, hoop_frequency: after the hands')
// and the summary's warning on a displacement beyond the linear range are this file. Units: SI.
#include "model/barrel.hpp"
#include "model/shell.hpp"
#include "system/beam_system.hpp"
#include "system/structure_part.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace beamimpact {

namespace {

struct WallParams : PartParams {
  bool                   shell_on = false; // the shell (-beam_shell), else the hoop oscillator
  BarrelHoop             hoop;
  BarrelShell            shell;
  std::vector<PetscReal> SystemKey() const override // the patch radius a (m) as resolved at the point
  {
    return shell_on ? std::vector<PetscReal>{shell.contact_radius} : std::vector<PetscReal>{};
  }
};
struct WallBuilt : PartBuilt {
  PetscInt               hoop_dof = -1;      // the hoop oscillator's dof, -1 for the shell
  ShellLayout            shell;              // the shell's fields (first -1 for the hoop)
  PetscReal              contact_radius = 0; // m, the ball's load patch a on the shell (0: a point load)
  std::vector<PetscReal> radius;             // m, the shell's midsurface radius R per node (0 where solid)
};
const WallParams &P(const PartParams &q) { return static_cast<const WallParams &>(q); }
const WallBuilt  &B(const PartInstance &s) { return static_cast<const WallBuilt &>(*s.built); }

const OptionModule &WallOptions()
{
  static const OptionModule m = {
    "wall",
    "The barrel wall: the hoop oscillator or the shell (docs/model.md section 14)",
    {
      OptionFlag("-beam_shell",
                 "The barrel wall as a thin cylindrical shell (Sanders-Koiter harmonics) where the profile is hollow, "
                 "in series with the ball (-beam_profile with inner diameters); a barrel wall thicker than 0.1 of its "
                 "radius is noted (the thin-shell model drops terms of order t/R)"),
      OptionNeeds(OptionList("-shell_harmonics", "1",
                             "Circumferential orders n of the shell's harmonics (n >= 2, at most 3; default 2,3,4)", 1,
                             3, AtLeast(2)),
                  {"-beam_shell"}),
      OptionNeeds(OptionReal("-shell_contact_radius", "m",
                             "The ball's load on the shell as a patch of radius a: sin(n a/R)/(n a/R) per harmonic, a "
                             "hat of half-width a along x (0: a point load; default sqrt(R_b delta), delta the ball's "
                             "peak compression on a rigid wall at the approach speed, with -ball_radius); at most the "
                             "ball's radius and the wall's midsurface radius at the impact point",
                             "", NonNegative()),
                  {"-beam_shell"}),
      OptionNeeds(OptionReal("-shell_youngs_modulus", "Pa",
                             "The wall's Young's modulus in the shell (its ovaling stiffness: a composite layup or "
                             "another alloy moves the hoop frequency as sqrt(E)); the beam's bending keeps "
                             "-beam_youngs_modulus (default: that); 1e8 (a soft polymer) to 1e12 (stiffer than any "
                             "bat's wall)",
                             "", Between(1e8, 1e12)),
                  {"-beam_shell"}),
      OptionReal("-barrel_hoop_frequency", "Hz",
                 "The barrel wall's hoop frequency f_h: a wall mass on a spring m_h (2 pi f_h)^2 in series with the "
                 "ball at the impact point (with -barrel_hoop_mass); a hollow barrel's: needs -beam_profile with inner "
                 "diameters or a hollow -bat_length bat",
                 "", Positive()),
      OptionNeeds(OptionReal("-barrel_hoop_mass", "kg",
                             "The barrel wall's mass m_h in its hoop mode (with -barrel_hoop_frequency)", "",
                             Positive()),
                  {"-barrel_hoop_frequency"}),
    },
  };
  return m;
}

// -shell_harmonics: whole, distinct circumferential orders (the table's row checks n >= 2).
std::string HarmonicsSet(const std::vector<PetscReal> &harmonics, BarrelShell *shell)
{
  shell->harmonics.clear();
  for (PetscReal n : harmonics) {
    if (n != std::floor(n))
      return Fmt("-shell_harmonics %g is not allowed: the circumferential orders are whole numbers n >= 2", (double)n);
    for (PetscInt q : shell->harmonics)
      if (q == (PetscInt)n) return Fmt("-shell_harmonics: %g is given twice", (double)n);
    shell->harmonics.push_back((PetscInt)n);
  }
  return "";
}

bool HollowProfile(const BeamParams &beam)
{
  bool hollow = false;
  for (const ProfileRow &r : beam.section.profile)
    hollow = hollow || (beam.section.source == SectionSource::Profile && r.d > 0);
  return hollow;
}

// The barrel's wall: the shell on a round hollow profile, the hoop on a hollow one, not both, not
// on a racket's frame: "" or the refusal.
std::string WallRefusal(const WallParams &w, bool hoop, const BeamParams &beam)
{
  if (StructurePartsHaveFace(beam)) // a racket's string bed (set up with the frame, before the wall)
    return Fmt("-strings_frame %s with a barrel wall (%s) is not allowed: a racket has no barrel",
               beam.frame_held ? "held" : "beam", w.shell_on ? "-beam_shell" : "-barrel_hoop_frequency");
  if (w.shell_on) {
    if (beam.section.source != SectionSource::Profile)
      return "-beam_shell needs a round hollow section: -beam_profile with rows 'x D d' (a uniform beam or "
             "-beam_properties has no wall)";
    if (!HollowProfile(beam))
      return "-beam_shell with a solid profile is not allowed: no row of -beam_profile has an inner diameter d > 0";
    if (hoop)
      return "-beam_shell with -barrel_hoop_frequency is not allowed: the wall is either the shell or the lumped hoop "
             "oscillator";
  } else if (!HollowProfile(beam)) // the hoop is a hollow barrel's wall, as the shell is
    return Fmt("-barrel_hoop_frequency %g is not allowed on %s: the hoop oscillator is a hollow barrel's wall; give "
               "-beam_profile with rows 'x D d', d > 0",
               (double)w.hoop.frequency,
               beam.section.source == SectionSource::Profile
                 ? "a solid profile (no row of -beam_profile has an inner diameter d > 0)"
                 : "a beam with no round hollow section (a uniform beam or -beam_properties has no wall)");
  return "";
}

class Wall : public StructurePart {
public:
  const char         *Name() const override { return "wall"; }
  const char         *Presence() const override { return "with -barrel_hoop_frequency or -beam_shell"; }
  const char         *Words() const override { return "the barrel wall"; }
  const OptionModule &Options() const override { return WallOptions(); }
  PetscReal           Unset(const char *name, const PartOptionValues &) const override
  {
    return std::strcmp(name, "-shell_contact_radius") ? 0 : BarrelShell().contact_radius;
  }
  bool Configure(const PartOptionValues &v, const BeamParams &beam, std::shared_ptr<const PartParams> *out,
                 std::string *why) const override
  {
    *out             = nullptr;
    const bool shell = v.Given("-beam_shell") && v.given.at("-beam_shell")[0] != 0;
    const bool hoop = v.Given("-barrel_hoop_frequency"), hoop_mass = v.Given("-barrel_hoop_mass");
    auto       w     = std::make_shared<WallParams>();
    w->shell_on      = shell;
    const auto value = [&](const char *name, PetscReal *x) {
      if (v.Given(name)) *x = v.given.at(name)[0];
    };
    value("-barrel_hoop_frequency", &w->hoop.frequency);
    value("-barrel_hoop_mass", &w->hoop.mass);
    if (hoop != hoop_mass) {
      *why = Fmt("%s %g without %s is not allowed: the hoop oscillator needs its frequency (Hz) and its mass (kg)",
                 hoop ? "-barrel_hoop_frequency" : "-barrel_hoop_mass",
                 (double)(hoop ? w->hoop.frequency : w->hoop.mass),
                 hoop ? "-barrel_hoop_mass" : "-barrel_hoop_frequency");
      return false;
    }
    if (!shell && !hoop) return true;
    value("-shell_contact_radius", &w->shell.contact_radius);
    value("-shell_youngs_modulus", &w->shell.youngs_modulus);
    if (v.Given("-shell_harmonics") && !(*why = HarmonicsSet(v.given.at("-shell_harmonics"), &w->shell)).empty())
      return false;
    if (!(*why = WallRefusal(*w, hoop, beam)).empty()) return false;
    *out = w;
    return true;
  }
  std::string Note(const PartParams &q, const BeamParams &beam) const override
  {
    PetscReal R, t;
    if (!P(q).shell_on || !ShellBarrelWall(beam, &R, &t) || !(t > kShellThinLimit * R)) return "";
    return Fmt("-beam_shell on a thick wall: the barrel's wall is t = %.4g m on a midsurface radius R = %.4g m (t/R = "
               "%.2f, above %g): the thin-shell model (Sanders-Koiter) drops terms of order t/R against 1, so the "
               "wall's frequencies and compliance are rough here (docs/model.md section 14)",
               (double)t, (double)R, (double)(t / R), (double)kShellThinLimit);
  }
  bool Resolve(const PartParams &q, const BeamParams &beam, const PartPoint &at, std::shared_ptr<const PartParams> *out,
               std::string *why) const override;
  PetscInt Build(const PartParams &q, const BeamParams &beam, BeamDiscretization *d,
                 std::shared_ptr<const PartBuilt> *out) const override
  {
    const PetscInt first = d->fields;
    auto           w     = std::make_shared<WallBuilt>();
    if (!P(q).shell_on) w->hoop_dof = BarrelHoopAppend(P(q).hoop, d);
    else {
      w->shell          = ShellAppend(P(q).shell, beam, d);
      w->contact_radius = std::max<PetscReal>(0, P(q).shell.contact_radius);
      w->radius.assign(beam.nodes, 0.0);
      for (PetscInt i = 0; i < beam.nodes; ++i) {
        PetscReal t;
        ShellWallAt(beam, beam.length * i / (beam.nodes - 1), &w->radius[i], &t);
      }
    }
    *out = w;
    return d->fields - first;
  }
  const char *AccountName() const override { return "wall"; }
  const char *AccountSeries() const override { return "shell_energy"; } // -monitor_energy's
  bool        AccountApart() const override { return true; }
  void        Couple(const PartInstance &s, const BeamSystem &sys, const ImpactStencil &st, PetscReal,
                     ContactCoupling *g) const override;
  PetscInt    FamilyDetail(const PartInstance &s, PetscInt f) const override
  {
    const WallBuilt &w = B(s);
    return w.hoop_dof >= 0 ? 2 : w.shell.harmonics[(f - w.shell.first) / 3];
  }
  bool Peaks() const override { return true; }
  bool Snapshot(const PartInstance &s, const BeamSystem &sys, const std::vector<PetscReal> &u,
                std::vector<PetscReal> *values, std::vector<PetscInt> *labels, PartSnapshotSpec *spec) const override
  {
    const WallBuilt &w = B(s); // the wall's W_n of each harmonic k (field shell.WField(k)), [k][node] flattened
    if (w.shell.first < 0) return false;
    spec->name = "wall", spec->attribute = "W", spec->labels = "wall_n";
    spec->description = "m, the barrel wall's radial displacement W_n (outward; w = sum_n W_n cos n theta, theta = 0 "
                        "under the ball), [time][wall_n][node] (NaN where solid)";
    spec->labels_description = "1 (the harmonic n of the wall's cos n theta)";
    const size_t H           = w.shell.harmonics.size();
    values->assign(H * (size_t)sys.nodes, 0.0);
    for (PetscInt i = 0; i < sys.nodes && !u.empty(); ++i)
      for (size_t k = 0; k < H; ++k)
        (*values)[k * sys.nodes + i] = w.radius[i] > 0 ? u[(size_t)i * sys.fields + w.shell.WField(k)] : NAN;
    *labels = w.shell.harmonics;
    return true;
  }
  // Its columns where the table had them (after the hands', before the roll's).
  const char             *ColumnsAfter() const override { return "hands_fraction"; }
  std::vector<PartColumn> Columns() const override
  {
    return {
      {"shell_energy_end", "J", "the barrel wall's energy at the end (stored and kinetic): what it did not give back",
       [](const PartOutputFacts &f) -> double { return f.account_end; }},
      {"wall_fraction", "1", "shell_energy_end / E_in",
       [](const PartOutputFacts &f) -> double { return f.account_flexible / f.E_in; }, "wall"},
      {"shell_energy_peak", "J", "the barrel wall's largest energy over the steps (NaN from the modal reference)",
       [](const PartOutputFacts &f) -> double { return f.account_peak; }},
      {"wall_deflection_peak", "m",
       "the barrel wall's largest displacement under the ball over the steps (NaN from the modal reference)",
       [](const PartOutputFacts &f) -> double { return f.apart_deflection_peak; }},
      {"wall_deflection_large", "1",
       "1 if wall_deflection_peak exceeds a quarter of the wall's midsurface radius at the impact point: the linear "
       "wall far outside its range, physically absurd",
       [](const PartOutputFacts &f) -> double {
         const PetscReal R = ShellRadiusAt(*f.beam, f.impact_x);
         return R > 0 && f.apart_deflection_peak > kWallDeflectionLimit * R ? 1 : 0;
       },
       nullptr, true},
      {"hoop_frequency", "Hz",
       "the barrel wall's lowest hoop (n = 2, ovaling) frequency: the shell's harmonic alone, or the given f_h",
       [](const PartOutputFacts &f) -> double {
         const WallParams &w = P(*f.params);
         return w.shell_on ? ShellLowestFrequency(w.shell, *f.beam, 2) : w.hoop.frequency;
       }},
    };
  }
  std::string Warning(const PartParams &q, const BeamParams &beam, const std::vector<double> &c,
                      const PartPoint &at) const override;
};

// -shell_contact_radius: its default from the ball (model/shell.hpp) at the approach speed at the
// impact point, and the patch's entries within the contact coupling's room.
bool Wall::Resolve(const PartParams &q, const BeamParams &beam, const PartPoint &at,
                   std::shared_ptr<const PartParams> *out, std::string *why) const
{
  if (!P(q).shell_on) return true;
  auto         w     = std::make_shared<WallParams>(P(q));
  BarrelShell &shell = w->shell;
  if (shell.contact_radius >= 0) { // given: a patch wider than the ball or the wall spreads the load off the wall
    const PetscReal R = ShellRadiusAt(beam, at.x), Rb = at.ball->radius;
    PetscReal       limit = PETSC_INFINITY;
    const char     *what  = "";
    if (Rb > 0) limit = Rb, what = "the ball's radius (-ball_radius)";
    if (R > 0 && R < limit) limit = R, what = "the barrel wall's midsurface radius at the impact point";
    if (shell.contact_radius > limit) {
      *why = Fmt("-shell_contact_radius %g m is not allowed: the ball's patch on the wall can be no wider than %s, %g "
                 "m; allowed 0 <= a <= %g m (a wider patch spreads the load off the wall)",
                 (double)shell.contact_radius, what, (double)limit, (double)limit);
      return false;
    }
  }
  if (shell.contact_radius < 0) shell.contact_radius = ShellContactRadiusDefault(*at.ball, at.approach);
  const size_t   per   = ShellPatchNodeWeights(beam.nodes, beam.length, at.x, shell.contact_radius).size();
  const PetscInt total = 2 + (PetscInt)(per * shell.harmonics.size());
  if (total > ContactCoupling::kMaxEntries) {
    *why = Fmt("-shell_contact_radius %g m is not allowed with -beam_nodes %" PetscInt_FMT
               ": the patch covers %zu nodes per harmonic, %" PetscInt_FMT
               " coupled dofs in all (at most %" PetscInt_FMT "); give a smaller radius or fewer -shell_harmonics",
               (double)shell.contact_radius, beam.nodes, per, total, ContactCoupling::kMaxEntries);
    return false;
  }
  *out = w;
  return true;
}

// c: shell_energy_end, wall_fraction, shell_energy_peak, wall_deflection_peak, wall_deflection_large, hoop_frequency.
// The flag set: the displacement under the ball beyond kWallDeflectionLimit of the wall's midsurface radius at
// the point, and the options that set the wall's stiffness.
std::string Wall::Warning(const PartParams &q, const BeamParams &beam, const std::vector<double> &c,
                          const PartPoint &at) const
{
  if (c[4] == 0) return "";
  const PetscReal R = ShellRadiusAt(beam, at.x), peak = c[3];
  return Fmt("warning: the barrel wall's largest displacement under the ball, %.4g m, is %.3g times its midsurface "
             "radius (R = %.4g m at x = %g m), beyond %g of it: physically absurd, the wall's model is linear (its "
             "displacements small against its thickness and radius); check %s and -ball_speed %g m/s",
             peak, (double)(peak / R), (double)R, (double)at.x, (double)kWallDeflectionLimit,
             P(q).shell_on ? "-shell_youngs_modulus, -barrel_wall_thickness, -shell_contact_radius"
                           : "-barrel_hoop_frequency and -barrel_hoop_mass",
             (double)at.ball->speed);
}

// The hoop: the wall under the ball, in series (weight 1). The shell: each harmonic's W_n under
// the ball's patch (outward: the inward displacement is -W_n).
void Wall::Couple(const PartInstance &s, const BeamSystem &sys, const ImpactStencil &st, PetscReal,
                  ContactCoupling *g) const
{
  const WallBuilt &w = B(s);
  if (w.hoop_dof >= 0) g->dof[g->n] = w.hoop_dof, g->w[g->n++] = 1.0;
  if (w.shell.harmonics.empty()) return;
  const PetscReal a = w.contact_radius, R = st.w * w.radius[st.j] + (1 - st.w) * w.radius[st.j + 1];
  const std::vector<std::pair<PetscInt, PetscReal>> nodes = ShellPatchNodeWeights(sys.nodes, sys.L, g->x, a);
  for (size_t k = 0; k < w.shell.harmonics.size(); ++k) {
    const PetscReal wn = ShellPatchHarmonicWeight(w.shell.harmonics[k], a, R);
    for (const auto &[i, wi] : nodes) {
      if (g->n == ContactCoupling::kMaxEntries) return; // refused before: Resolve
      const PetscInt d = sys.Dof(i, w.shell.WField(k));
      g->dof[g->n]     = d;
      g->w[g->n++]     = sys.held[d] ? 0.0 : -(wn * wi);
    }
  }
}

} // namespace

const StructurePart &WallPart()
{
  static const Wall part;
  return part;
}

} // namespace beamimpact

// The frame's roll about its own axis (-beam_torsion; docs/model.md section 16, the physics in
// model/torsion.hpp): one more field per node after the beam's theory, the roll phi (rad), with
// G J (phi')^2/2 per length (its strain terms, in its energy account "roll") and rho J phi_t^2/2
// (its lumped masses, kg m^2). A racket's head rolls under a hit off the axis (-impact_z): the ball
// couples to the sections' roll times z at the point's two nodes. A rigid roll about the axis turns
// the field at the roll's rate (PartParams::Rolls: BeamSystem::RollField, the rigid motions, the
// roll momentum); the rigid body's roll inertia is int rho J (and a string bed's sigma z^2 on the
// frame, which rolls with it). A structure part (system/structure_part.hpp): its option rows,
// checks, fields, coupling, energy account (its columns twist_energy_end and twist_fraction, its
// series twist_energy), run-record entries, summary line and description are this file. (Its rigid
// roll's columns and the roll momentum are still the outcome's: run/results_table.cpp,
// run/measures.cpp.) Units: SI.
#include "model/torsion.hpp"
#include "system/beam_system.hpp"
#include "system/structure_part.hpp"

#include <cmath>

namespace beamimpact {

namespace {

struct RollParams : PartParams {
  BeamTorsion torsion; // the uniform options (0: the section's)
  bool        Rolls() const override { return true; }
  // int rho J about the axis (the uniform -beam_torsion_inertia where given, else the sections'),
  // added to the bed's sigma z^2 already in m->roll.
  void AddRigidBodyOn(const BeamParams &p, SectionMoments *m) const override
  {
    PetscReal roll = 0; // kg m^2
    if (torsion.inertia > 0) roll = torsion.inertia * p.length;
    else if (p.section.source != SectionSource::Uniform) roll = SectionMomentsOf(p.section, 0, p.length).roll;
    m->roll = roll + m->roll;
  }
};
const RollParams &P(const PartParams &q) { return static_cast<const RollParams &>(q); }

const OptionModule &RollOptions()
{
  static const OptionModule m =
    {"roll",
     "The frame's roll about its own axis (docs/model.md section 16)",
     {
       OptionNeeds(OptionFlag("-beam_torsion", "The frame's twist about its own axis: one more field per node, the "
                                               "roll "
                                               "phi (G J phi'^2/2 per length, rho J per length), so that a hit off the "
                                               "axis (-impact_z) rolls it (a racket's head; docs/model.md section 16; "
                                               "not with -strings_frame held: the frame is held)"),
                   {"-strings_frame=none|-strings_frame=beam"}),
       OptionNeeds(OptionReal("-beam_torsion_stiffness", "N m^2",
                              "Torsional stiffness G J of a uniform section (default: the section's: a round profile's "
                              "G pi (D^4 - d^4)/32, a seven-column -beam_properties' GJ)",
                              "", Positive()),
                   {"-beam_torsion", "-strings_frame=none|-strings_frame=beam"}),
       OptionNeeds(OptionReal("-beam_torsion_inertia", "kg m",
                              "Polar mass moment per length rho J of a uniform section about its axis (default: the "
                              "section's: a round profile's rho pi (D^4 - d^4)/32, a seven-column -beam_properties' "
                              "rhoJ)",
                              "", Positive()),
                   {"-beam_torsion", "-strings_frame=none|-strings_frame=beam"}),
     }};
  return m;
}

// G J and rho J > 0 over the whole beam, from the uniform options or the section: "" or the refusal.
std::string TorsionRefusal(const BeamTorsion &t, const BeamParams &p)
{
  const PetscInt n = 64;
  for (PetscInt k = 0; k < n; ++k) {
    PetscReal GJ, rhoJ;
    TorsionSectionMean(t, p, k * p.length / n, (k + 1) * p.length / n, &GJ, &rhoJ);
    if (!(GJ > 0 && std::isfinite(GJ) && rhoJ > 0 && std::isfinite(rhoJ)))
      return Fmt("-beam_torsion needs the section's G J and rho J: give -beam_torsion_stiffness (N m^2) and "
                 "-beam_torsion_inertia (kg m), or a round -beam_profile, or a seven-column -beam_properties 'x EI mu "
                 "kappaGA rhoI GJ rhoJ' (%s gives G J = %g, rho J = %g near x = %g m)",
                 p.section.source == SectionSource::Uniform ? "the uniform section" : p.section.file.c_str(),
                 (double)GJ, (double)rhoJ, (double)((k + 0.5) * p.length / n));
  }
  return "";
}

class Roll : public StructurePart {
public:
  const char         *Name() const override { return "roll"; }
  const char         *Presence() const override { return "with -beam_torsion"; }
  const char         *Words() const override { return "the frame's roll"; }
  const OptionModule &Options() const override { return RollOptions(); }
  // Present with -beam_torsion, but not in a held string bed's frame (held: it does not roll).
  bool Configure(const PartOptionValues &v, const BeamParams &beam, std::shared_ptr<const PartParams> *out,
                 std::string *why) const override
  {
    *out = nullptr;
    if (!v.Given("-beam_torsion") || v.given.at("-beam_torsion")[0] == 0 || beam.frame_held) return true;
    auto p = std::make_shared<RollParams>();
    if (v.Given("-beam_torsion_stiffness")) p->torsion.stiffness = v.given.at("-beam_torsion_stiffness")[0];
    if (v.Given("-beam_torsion_inertia")) p->torsion.inertia = v.given.at("-beam_torsion_inertia")[0];
    if (!(*why = TorsionRefusal(p->torsion, beam)).empty()) return false;
    *out = p;
    return true;
  }
  PetscInt Build(const PartParams &q, const BeamParams &beam, BeamDiscretization *d,
                 std::shared_ptr<const PartBuilt> *) const override
  {
    TorsionAppend(P(q).torsion, beam, d);
    return 1;
  }
  const char *AccountName() const override { return "roll"; }
  const char *AccountSeries() const override { return "twist_energy"; }
  // Off the axis (z != 0): the sections' roll at the point's two nodes times z (held: weight 0).
  void Couple(const PartInstance &s, const BeamSystem &sys, const ImpactStencil &st, PetscReal z,
              ContactCoupling *g) const override
  {
    if (z == 0.0) return;
    g->dof[g->n] = sys.Dof(st.j, s.first), g->w[g->n] = sys.held[g->dof[g->n]] ? 0.0 : st.w * z, g->n++;
    g->dof[g->n] = sys.Dof(st.j + 1, s.first), g->w[g->n] = sys.held[g->dof[g->n]] ? 0.0 : (1.0 - st.w) * z, g->n++;
  }
  // Its energy account's columns, where the table had them: after the hands' (the wall's and the bed's,
  // registered after it, go between).
  const char             *ColumnsAfter() const override { return "hands_fraction"; }
  std::vector<PartColumn> Columns() const override
  {
    return {
      {"twist_energy_end", "J",
       "the frame's roll energy at the end: the twist's strain and the sections' spin rho J phi_t^2/2 (a string "
       "bed's roll is in bed_energy_end)",
       [](const PartOutputFacts &f) -> double { return f.account_end; }},
      {"twist_fraction", "1",
       "the frame's twisting at the end / E_in: twist_energy_end less its share of the rigid roll",
       [](const PartOutputFacts &f) -> double { return f.account_flexible / f.E_in; }, "twist"},
    };
  }
  std::vector<const char *> SummaryColumns() const override { return {"roll_rate_end", "roll_fraction"}; }
  // After a hit on a structure free to roll (roll_rate_end applies: no held dof, a moving ball): c is
  // twist_energy_end, twist_fraction, roll_rate_end, roll_fraction.
  std::string Summary(const PartParams &, const std::vector<double> &c) const override
  {
    if (std::isnan(c[2])) return "";
    return Fmt("roll: the frame rolls at %.4f rad/s about its axis after the hit, %.4f of E_in; its twist and spin "
               "hold %.4e J at the end",
               Shown(c[2], 4), Shown(c[3], 4), c[0]);
  }
  void Record(const PartParams &q, const BeamParams &beam,
              std::vector<std::pair<const char *, PetscReal>> *out) const override
  {
    out->push_back({"beam_torsion_stiffness", P(q).torsion.stiffness}); // 0: the section's
    out->push_back({"beam_torsion_inertia", P(q).torsion.inertia});
    out->push_back({"beam_inertia_roll", BeamRigidBodyOf(beam).inertia_roll});
  }
  std::string Describe(const PartParams &, const BeamRigidBody &b) const override
  {
    return Fmt(", %.6f kg m^2 about its axis", (double)b.inertia_roll);
  }
};

} // namespace

const StructurePart &RollPart()
{
  static const Roll part;
  return part;
}

} // namespace beamimpact

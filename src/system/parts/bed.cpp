// A racket's string bed (-strings_frame beam or held; docs/model.md section 16, the membrane in
// model/string_bed.hpp, its semi-discrete operator in system/string_bed_operator.hpp): nz more
// fields per node, the bed's deflection w at (x_i, z_j) across the face (FieldZ: a rigid motion
// moves them as y + z phi, their masses carry momentum as the beam's deflection, their held dofs
// move with the frame), its links and edge arms strain terms in the deflection relative to the
// frame's sections y + z phi (phi the roll's field: the bed rolls with the frame), the strings'
// mass sigma |cell ∩ head| per node (on the frame's section where the frame holds the node). The
// ball inside the head's outline strikes the bed: its disc of nodes (BedPatch) in place of the
// beam's hat. Its energy account is "strings". A structure part (system/structure_part.hpp): its
// option rows (the module 'strings'), parameters, rigid-body share, the refusal without the roll,
// the impact point's checks on the head, the patch radius at the point (the sweep's system key),
// its fields, coupling, in-plane mains for an oblique impact, its heading and summary lines and its
// run-record entries are this file. It makes its frame (Frames): its rows are read with the
// beam's, since a held bed's frame is the head's outline held whole (the beam's length, nodes and
// holds) and a racket maker's numbers place its head and weigh its strings on the frame. Its columns
// (bed_energy_end, bed_fraction, bed_energy_peak, bed_deflection_peak) and its account's series
// (bed_energy) and its snapshot (Snapshot: w - y - z phi on its face's grid) are this file; the
// measure of its deflection from the frame (StateMeasures::face_deflection) is still the
// outcome's, found through its fields (BeamSystem::face_fields). Units: SI.
#include "system/parts/bed.hpp"

#include "model/racket_maker.hpp"
#include "model/shell.hpp"
#include "system/beam_system.hpp"
#include "system/string_bed_operator.hpp"
#include "system/structure_part.hpp"

#include <algorithm>
#include <cstdarg>
#include <set>

namespace beamimpact {

// The rows given in v -> *p, over its values (no checks; the -help defaults and StringBedParamsFrom).
void StringBedParamsFill(const PartOptionValues &v, StringBedParams *p);

namespace {

struct BedParams : PartParams {
  StringBedParams bed; // the options as read (Frame: the head placed), the patch radius as resolved at the point
  // sigma over the head's outline at its centre c: sigma A, sigma A c, sigma (I_xx + A c^2); sigma I_zz
  // about the frame's axis (the roll's part adds its own to it). None in a held frame (not a body).
  void AddRigidBody(SectionMoments *m) const override
  {
    if (bed.Held()) return;
    const PetscReal   sigma = StringBedMembrane(bed).sigma, c = bed.head_center;
    const HeadMoments h = HeadMomentsOf(bed);
    m->m0 += sigma * h.area, m->m1 += sigma * h.area * c, m->m2 += sigma * (h.xx + h.area * c * c);
    m->roll += sigma * h.zz;
  }
  // The ball's disc (m) as resolved: a new one is a new system (the coupling's room, its nodes).
  std::vector<PetscReal> SystemKey() const override { return {bed.patch_radius}; }
};
struct BedBuilt : PartBuilt {
  BedLayout layout;           // its first field, its grid (columns: the beam's nodes), the roll's field
  PetscReal head_center  = 0; // m, the head's centre along the frame
  PetscReal patch_radius = 0; // m, the ball's load disc on the bed (0: the hat weights)
};
const BedParams &P(const PartParams &q) { return static_cast<const BedParams &>(q); }
const BedBuilt  &B(const PartInstance &s) { return static_cast<const BedBuilt &>(*s.built); }

// Adds weight w on dof d to g (merging a dof already there; a held dof's share is 0); false when
// g is full.
bool CouplingAdd(const BeamSystem &sys, PetscInt d, PetscReal w, ContactCoupling *g)
{
  if (sys.held[d] || w == 0.0) return true;
  for (PetscInt q = 0; q < g->n; ++q)
    if (g->dof[q] == d) return g->w[q] += w, true;
  if (g->n == ContactCoupling::kMaxEntries) return false;
  g->dof[g->n] = d, g->w[g->n++] = w;
  return true;
}

// printf's text as PETSc's PetscPrintf writes it (a whole %g as "0."): the bed's lines and
// refusals read as they did when run/ and app/ printed them.
std::string PetscFmt(const char *format, ...)
{
  char    text[1024];
  size_t  full = 0;
  va_list ap;
  va_start(ap, format);
  const PetscErrorCode ierr = PetscVSNPrintf(text, sizeof text, format, &full, ap);
  va_end(ap);
  return ierr ? std::string(format) : std::string(text);
}

BedGrid Outline(const StringBedParams &s) // the head's outline alone (its shape and half-axes)
{
  BedGrid g;
  g.shape = s.shape, g.a = 0.5 * s.head_length, g.b = 0.5 * s.head_width;
  return g;
}

class Bed : public StructurePart {
public:
  const char         *Name() const override { return "bed"; }
  const char         *Presence() const override { return "with a string bed (-strings_frame held or beam)"; }
  const char         *Words() const override { return "the string bed"; }
  const OptionModule &Options() const override { return BedOptions(); }
  bool                Frames() const override { return true; }
  PetscReal           Unset(const char *name, const PartOptionValues &before) const override;
  const char         *Gate() const override { return "-strings_frame"; }
  int                 Frame(const PartOptionValues &v, const RacketMakerParams *racket, BeamParams *beam,
                            std::shared_ptr<const PartParams> *out, std::string *why) const override;
  void                Strung(const PartParams &q, RacketStrung *s) const override { RacketStrungAdd(P(q).bed, s); }
  bool                FaceGrid(const PartParams &q, const BeamParams &beam, BedGrid *g) const override
  {
    *g = StringBedFrameGrid(P(q).bed, beam.nodes, beam.length);
    return true;
  }
  bool Resolve(const PartParams &q, const BeamParams &beam, const PartPoint &at, std::shared_ptr<const PartParams> *out,
               std::string *why) const override;
  // A bed on the frame needs the frame's roll (the head rolls under an off-centre hit).
  std::string RefusalWith(const PartParams &q, const BeamParams &beam) const override
  {
    if (P(q).bed.Held() || beam.parts.Rolls()) return "";
    return "-strings_frame beam needs the frame's roll: give -beam_torsion (with its G J and rho J) so that the head "
           "can roll under an off-centre hit";
  }
  bool Strikes(const PartParams &q, PetscReal x, PetscReal z) const override
  {
    return BedInside(Outline(P(q).bed), x - P(q).bed.head_center, z);
  }
  bool HasFace(const PartParams &) const override { return true; }
  // The mains under the ball's disc (-strings_inplane_*, else from the tension: StringBedInPlaneOf).
  bool InPlane(const PartParams &q, PetscReal x, PetscReal z, PetscReal *stiffness, PetscReal *mass) const override
  {
    const StringBedParams &s = P(q).bed;
    const StringBedInPlane d = StringBedInPlaneOf(s, x - s.head_center, z, s.patch_radius);
    *stiffness               = s.inplane_stiffness > 0 ? s.inplane_stiffness : d.stiffness;
    *mass                    = s.inplane_mass > 0 ? s.inplane_mass : d.mass;
    return true;
  }
  std::string PointRefusal(const PartParams &q, const char *what, PetscReal z, bool held) const override
  {
    const StringBedParams &s = P(q).bed;
    if (!held)
      return PetscFmt("%s with -impact_z %g is not allowed: off the frame's axis the ball must strike the string bed, "
                      "inside the head's outline (centre x = %g m, %g x %g m, -head_*)",
                      what, (double)z, (double)s.head_center, (double)s.head_length, (double)s.head_width);
    if (!s.Held()) return "";
    return PetscFmt("%s is not allowed: -strings_frame held holds the whole frame, so the ball must strike the bed, "
                    "inside the head's outline (x from 0 to -head_length %g m, the head's centre at %g m)",
                    what, (double)s.head_length, (double)(0.5 * s.head_length));
  }
  PetscInt BuildAfter(const PartParams &q, const BeamParams &beam, const std::vector<PartInstance> &before,
                      BeamDiscretization *d, std::shared_ptr<const PartBuilt> *out) const override
  {
    const StringBedParams &s     = P(q).bed;
    const PetscInt         first = d->fields;
    PetscInt               roll  = -1; // the frame's roll field, which the bed is anchored on
    for (const PartInstance &p : before)
      if (roll < 0 && p.params->Rolls()) roll = p.first;
    auto b          = std::make_shared<BedBuilt>();
    b->layout       = StringBedAppend(s, StringBedFrameGrid(s, beam.nodes, beam.length), roll, d);
    b->head_center  = s.head_center;
    b->patch_radius = std::max<PetscReal>(0, s.patch_radius);
    *out            = b;
    return d->fields - first;
  }
  PetscInt Build(const PartParams &q, const BeamParams &beam, BeamDiscretization *d,
                 std::shared_ptr<const PartBuilt> *out) const override
  {
    return BuildAfter(q, beam, {}, d, out);
  }
  PetscReal FieldZ(const PartInstance &s, PetscInt f) const override { return B(s).layout.grid.Z(f - s.first); }
  // Its deflection from its frame, w - y - z phi, [z][x] flattened on its face's grid (NaN where held).
  bool Snapshot(const PartInstance &s, const BeamSystem &sys, const std::vector<PetscReal> &u,
                std::vector<PetscReal> *values, std::vector<PetscInt> *, PartSnapshotSpec *spec) const override
  {
    spec->name = "bed", spec->attribute = "w", spec->face_x = "bed_x", spec->face_z = "bed_z";
    spec->face_point  = "bed_point";
    spec->description = "m, the string bed's deflection from its frame w - y - z phi, [time][z * len(bed_x) + x] (NaN "
                        "off the bed)";
    values->assign((size_t)s.count * sys.nodes, 0.0);
    const PetscInt roll = sys.RollField();
    for (PetscInt i = 0; i < sys.nodes && !u.empty(); ++i) {
      const PetscReal *node = &u[(size_t)i * sys.fields], phi = roll >= 0 ? node[roll] : 0.0;
      for (PetscInt j = 0, f = s.first; j < s.count; ++j, ++f)
        (*values)[j * sys.nodes + i] = sys.held[sys.Dof(i, f)] ? NAN : node[f] - node[0] - sys.field_z[f] * phi;
    }
    return true;
  }
  const char *AccountName() const override { return "strings"; }
  const char *AccountSeries() const override { return "bed_energy"; }
  bool        CoupleInstead(const PartInstance &s, const BeamSystem &sys, PetscReal x, PetscReal z,
                            ContactCoupling *g) const override;

  // Its columns, where the table had them (after the wall's).
  const char             *ColumnsAfter() const override { return "hoop_frequency"; }
  std::vector<PartColumn> Columns() const override
  {
    return {
      {"bed_energy_end", "J",
       "the string bed's energy at the end (its strain relative to the frame and its strings' kinetic energy)",
       [](const PartOutputFacts &f) -> double { return f.account_end; }},
      {"bed_fraction", "1",
       "the string bed's vibration at the end / E_in: bed_energy_end less its share of the rigid motions",
       [](const PartOutputFacts &f) -> double { return f.account_flexible / f.E_in; }, "strings"},
      {"bed_energy_peak", "J", "the string bed's largest energy over the steps (NaN from the modal reference)",
       [](const PartOutputFacts &f) -> double { return f.account_peak; }},
      {"bed_deflection_peak", "m",
       "the string bed's largest deflection from its frame, max |w - y - z phi| over its nodes and the steps (NaN "
       "from the modal reference)",
       [](const PartOutputFacts &f) -> double { return f.face_deflection_peak; }},
    };
  }
  // c: bed_energy_end, bed_fraction, bed_energy_peak, bed_deflection_peak.
  std::string SummaryAt(const PartParams &, const std::vector<double> &c, const PartPoint &at) const override
  {
    return PetscFmt("strings: struck at x %g m, z %g m; the bed's largest deflection from its frame %.4e m, its "
                    "energy %.4e J at most, %.4e J at the end (its vibration %.4f of E_in)",
                    (double)at.x, (double)at.z, c[3], c[2], c[0], c[1]);
  }
  bool SummaryFirst() const override { return true; }
  void Record(const PartParams                                &q, const BeamParams &,
              std::vector<std::pair<const char *, PetscReal>> *out) const override;
  void RecordWords(const PartParams &q, const BeamParams &beam,
                   std::vector<std::pair<const char *, std::string>> *words,
                   std::vector<std::pair<const char *, long long>>   *whole) const override
  {
    words->push_back({"strings_frame", P(q).bed.frame});
    words->push_back({"head_shape", HeadShapeName(P(q).bed.shape)});
    whole->push_back({"strings_nodes_width", StringBedFrameGrid(P(q).bed, beam.nodes, beam.length).nz});
  }
  std::string Heading(const PartParams &q, bool *body) const override
  {
    const StringBedParams &s = P(q).bed;
    const Membrane         m = StringBedMembrane(s);
    *body                    = !s.Held(); // a held frame is not a body
    return PetscFmt("strings: %s %g x %g m, N_x %.6g N/m, N_z %.6g N/m, sigma %.4g kg/m^2, the ball's disc %.4g m, %s",
                    HeadShapeName(s.shape), (double)s.head_length, (double)s.head_width, (double)m.N_x, (double)m.N_z,
                    (double)m.sigma, (double)s.patch_radius, s.Held() ? "in a held frame" : "on the beam's frame");
  }

private:
  static const OptionModule &BedOptions();
};

// The bed's rows, the module 'strings' (-help's block; read with the beam's: io/string_bed_options.cpp).
const OptionModule &Bed::BedOptions()
{
  static const OptionModule m = {
    "strings",
    "The racket's string bed: a membrane on the head's outline (-strings_frame held -task modes: its modes in a held "
    "frame)",
    {
      OptionChoice("-strings_frame",
                   "The frame holding the bed: none (no string bed; the racket is the beam), held (a rigid frame, w = "
                   "0 on the outline; -impact_x from the head's end, -task modes the bed's modes on a 2-D DMDA) or "
                   "beam (the beam is the frame: the bed on its nodes, the head bending and rolling with it; needs "
                   "-beam_torsion)",
                   {"none", "held", "beam"}, "none"),
      OptionNeeds(OptionReal("-strings_patch_radius", "m",
                             "The ball's load on the bed: the point's bilinear hat weights on its cell's four nodes, "
                             "each node's share spread over a disc of this radius about it with the weights 1 - "
                             "r^2/a^2, so that the load's resultant and moments are the point's (0: the hat weights "
                             "alone; default sqrt(R_b delta), delta the ball's peak compression on a rigid wall at the "
                             "approach speed, with -ball_radius)",
                             "", NonNegative()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_tension", "N", "Tension of each main string (along the frame's axis)", "250",
                             Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_tension_crosses", "N",
                             "Tension of each cross string (default: -strings_tension)", "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_spacing", "m",
                             "Spacing of the mains (centre to centre, across the face; < -head_width)", "0.0151",
                             Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_spacing_crosses", "m",
                             "Spacing of the crosses (along the frame's axis; default: -strings_spacing; < "
                             "-head_length)",
                             "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_linear_density", "kg/m", "Mass per length of a string (nylon 1.30 mm: 1.51e-3)",
                             "1.51e-3", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionChoice("-head_shape", "Outline of the head", {"ellipse", "rectangle"}, "ellipse"),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-head_length", "m",
                             "Length of the head's outline along the frame's axis (the ellipse's major axis)", "0.34",
                             Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-head_width", "m", "Width of the head's outline across the face", "0.24", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-head_center", "m",
                             "Centre of the head along the frame's axis, from x = 0 (-strings_frame beam; held: the "
                             "head's middle)",
                             "0.175", NonNegative()),
                  {"-strings_frame=beam"}),
      OptionNeeds(OptionInt("-strings_nodes",
                            "Grid nodes across the head's length, edges included (-strings_frame held; on a beam frame "
                            "the bed's columns are the beam's nodes, -beam_nodes)",
                            "61", AtLeast(5)),
                  {"-strings_frame=held"}),
      OptionNeeds(OptionInt("-strings_nodes_width",
                            "Grid nodes across the head's width (default: from the aspect, so that h_z ~ h_x)", "",
                            AtLeast(5)),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_inplane_stiffness", "N/m",
                             "An oblique impact on the bed: the stiffness of the mains under the ball against their "
                             "sideways slide (across their length, the friction force's direction; docs/model.md "
                             "section 13); default n T (1/a + 1/b), n = 2 r_p / s_m mains under the ball's patch, T "
                             "-strings_tension, a and b the struck main's lengths to its two ends",
                             "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam", "-impact_angle!=0|-ball_spin!=0|-bat_speed_face!=0",
                   "-ball_friction!=0"}),
      OptionNeeds(OptionReal("-strings_inplane_mass", "kg",
                             "An oblique impact on the bed: the mass of the mains under the ball in that slide; "
                             "default n lambda (a + b) / 3 (the triangle of a string pulled aside at a point)",
                             "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam", "-impact_angle!=0|-ball_spin!=0|-bat_speed_face!=0",
                   "-ball_friction!=0"}),
    },
  };
  return m;
}

// The value -help and /options_used show for a row not given: StringBedParams' own default (-1:
// derived later); the width's nodes from the aspect of the head as read before it.
PetscReal Bed::Unset(const char *name, const PartOptionValues &before) const
{
  StringBedParams d;
  StringBedParamsFill(before, &d);
  const std::map<std::string, PetscReal> unset = {
    {"-strings_patch_radius", d.patch_radius},
    {"-strings_tension", d.tension},
    {"-strings_tension_crosses", d.tension_crosses},
    {"-strings_spacing", d.spacing},
    {"-strings_spacing_crosses", d.spacing_crosses},
    {"-strings_linear_density", d.linear_density},
    {"-head_length", d.head_length},
    {"-head_width", d.head_width},
    {"-head_center", d.head_center},
    {"-strings_nodes", (PetscReal)d.nodes},
    {"-strings_nodes_width", (PetscReal)StringBedGrid(d).nz}, // the aspect's count
    {"-strings_inplane_stiffness", d.inplane_stiffness},
    {"-strings_inplane_mass", d.inplane_mass},
  };
  const auto it = unset.find(name);
  return it == unset.end() ? 0 : it->second; // the choices' first: none, ellipse
}

// Set up with the beam (Frames): the bed's options, its head placed by a racket maker's numbers;
// held, the beam becomes its frame: the head's length on the bed's columns, held everywhere.
int Bed::Frame(const PartOptionValues &v, const RacketMakerParams *racket, BeamParams *beam,
               std::shared_ptr<const PartParams> *out, std::string *why) const
{
  auto             p = std::make_shared<BedParams>();
  StringBedParams &s = p->bed;
  *out               = nullptr;
  if (!StringBedParamsFrom(v, &s, why)) return PETSC_ERR_ARG_OUTOFRANGE;
  if (!s.On()) return 0;
  if (racket) { // the maker's head
    for (const char *o : {"-head_length", "-head_width", "-head_center"})
      if (v.Given(o))
        return *why = PetscFmt("%s with -racket_length is not allowed: the racket's maker's numbers place the head "
                               "(-racket_head_size, -racket_head_aspect, -racket_head_margin)",
                               o),
               PETSC_ERR_ARG_INCOMP;
    RacketMakerHead(*racket, &s);
  }
  *out = p;
  if (s.Held()) {
    if (beam->has_pivot) // -grip, -beam_torsion, -absorber: their parts refuse a held frame
      return *why = "-strings_frame held holds the whole frame: -beam_pivot has nothing to hold", PETSC_ERR_ARG_INCOMP;
    beam->length     = s.head_length; // the frame: the head's length on the bed's columns, held everywhere
    beam->nodes      = s.nodes;
    beam->has_clamp  = true;
    beam->frame_held = true;
    beam->clamp_x0 = 0, beam->clamp_x1 = beam->length;
    s.head_center = 0.5 * s.head_length;
    beam->section = BeamSection(); // a held frame's section (and roll: the part is absent) are never used
    return 0;
  }
  const PetscReal a = 0.5 * s.head_length, h = beam->length / (beam->nodes - 1);
  if (!(s.head_center - a > 0 && s.head_center + a < beam->length))
    *why = PetscFmt("-head_center %g with -head_length %g is not allowed on this %g m frame: the head (%g to %g m) "
                    "must lie inside the beam, 0 < x < L",
                    (double)s.head_center, (double)s.head_length, (double)beam->length, (double)(s.head_center - a),
                    (double)(s.head_center + a));
  else if (!(s.head_length >= 4 * h))
    *why = PetscFmt("-strings_frame beam: the head (-head_length %g m) spans fewer than 4 of the frame's cells (h = "
                    "%g m): give more -beam_nodes",
                    (double)s.head_length, (double)h);
  else if (const BedGrid g = StringBedFrameGrid(s, beam->nodes, beam->length); g.nz < 5)
    *why = PetscFmt("-strings_frame beam: %" PetscInt_FMT " nodes across the head's width (h_x %g m from -beam_nodes): "
                    "at least 5 are needed (more -beam_nodes, or -strings_nodes_width)",
                    g.nz, (double)h);
  return why->empty() ? 0 : PETSC_ERR_ARG_OUTOFRANGE;
}

// -strings_patch_radius: its default from the ball as the shell's (ShellContactRadiusDefault: the
// Hertz radius on a rigid flat at the approach speed); the load's nodes (BedPatch) within the
// frame's ends on a beam frame, and its coupled dofs within the contact coupling's room.
bool Bed::Resolve(const PartParams &q, const BeamParams &beam, const PartPoint &at,
                  std::shared_ptr<const PartParams> *out, std::string *why) const
{
  auto             p   = std::make_shared<BedParams>(P(q));
  StringBedParams &bed = p->bed;
  if (bed.patch_radius < 0) bed.patch_radius = ShellContactRadiusDefault(*at.ball, at.approach);
  const BedGrid      g = StringBedFrameGrid(bed, beam.nodes, beam.length);
  const PetscReal    a = bed.patch_radius;
  std::set<PetscInt> dofs; // the coupling's entries: a free node's own, or its frame section's deflection and roll
  bool               beyond = false;
  for (const BedPatchNode &e : BedPatch(g, at.x - bed.head_center, at.z, a)) {
    beyond = beyond || e.beyond;
    if (e.free) dofs.insert(e.i * (g.nz + 2) + 2 + e.j);
    else if (!bed.Held()) dofs.insert(e.i * (g.nz + 2)), dofs.insert(e.i * (g.nz + 2) + 1); // a held frame's dofs: none
  }
  if (beyond && !bed.Held())
    *why = PetscFmt("-impact_x %g with -strings_patch_radius %g m is not allowed: the ball's load on the bed (its "
                    "disc, "
                    "spread over the nodes around the point, h_x %g m) reaches past the frame's end (0 <= x <= L = %g "
                    "m); strike further from the end or give a smaller -strings_patch_radius",
                    (double)at.x, (double)a, (double)g.hx, (double)beam.length);
  else if ((PetscInt)dofs.size() > ContactCoupling::kMaxEntries)
    *why = PetscFmt("-strings_patch_radius %g m is not allowed with this grid (h_x %g, h_z %g m): the ball's disc "
                    "covers "
                    "%zu coupled dofs of the bed (at most %" PetscInt_FMT "); give a smaller radius or a coarser grid",
                    (double)a, (double)g.hx, (double)g.hz, dofs.size(), ContactCoupling::kMaxEntries);
  if (!why->empty()) return false;
  if (a != P(q).bed.patch_radius) *out = p;
  return true;
}

// The bed's numbers in the run record: its head, strings, membrane, the ball's disc as used (< 0
// in a sweep's structure record: each point's from its ball) and the grid's steps.
void Bed::Record(const PartParams &q, const BeamParams &beam,
                 std::vector<std::pair<const char *, PetscReal>> *out) const
{
  const StringBedParams &b = P(q).bed;
  const Membrane         m = StringBedMembrane(b);
  const BedGrid          g = StringBedFrameGrid(b, beam.nodes, beam.length);
  for (const auto &e : std::vector<std::pair<const char *, PetscReal>>{{"head_length", b.head_length},
                                                                       {"head_width", b.head_width},
                                                                       {"head_center", b.head_center},
                                                                       {"strings_tension", b.tension},
                                                                       {"strings_tension_crosses", b.tension_crosses},
                                                                       {"strings_spacing", b.spacing},
                                                                       {"strings_spacing_crosses", b.spacing_crosses},
                                                                       {"strings_linear_density", b.linear_density},
                                                                       {"membrane_N_x", m.N_x},
                                                                       {"membrane_N_z", m.N_z},
                                                                       {"membrane_sigma", m.sigma},
                                                                       {"strings_patch_radius", b.patch_radius},
                                                                       {"strings_h_x", g.hx},
                                                                       {"strings_h_z", g.hz}})
    out->push_back(e);
}

// Strictly inside the head's outline: the bed under the ball's disc; a node the frame holds moves
// with its section (its deflection and roll times z).
bool Bed::CoupleInstead(const PartInstance &s, const BeamSystem &sys, PetscReal x, PetscReal z,
                        ContactCoupling *g) const
{
  const BedBuilt &b = B(s);
  if (!BedInside(b.layout.grid, x - b.head_center, z)) return false;
  const PetscInt roll = sys.RollField(); // the bed's frame rolls with it
  for (const BedPatchNode &e : BedPatch(b.layout.grid, x - b.head_center, z, b.patch_radius)) {
    if (e.beyond) continue; // past a held frame's end (refused on a beam frame: Resolve)
    if (e.free) {
      if (!CouplingAdd(sys, sys.Dof(e.i, s.first + e.j), e.w, g)) return true; // refused before: the scenario's check
      continue;
    }
    if (!CouplingAdd(sys, sys.Dof(e.i), e.w, g)) return true;
    if (roll >= 0 && !CouplingAdd(sys, sys.Dof(e.i, roll), e.w * b.layout.grid.Z(e.j), g)) return true;
  }
  return true;
}

} // namespace

// The rows given in v -> *p, over its values; the crosses' tension and spacing default to the
// mains'.
void StringBedParamsFill(const PartOptionValues &v, StringBedParams *p)
{
  const auto real = [&](const char *name, PetscReal *x) {
    if (v.Given(name)) *x = v.given.at(name)[0];
  };
  const auto whole = [&](const char *name, PetscInt *n) {
    if (v.Given(name)) *n = (PetscInt)v.given.at(name)[0];
  };
  PetscInt frame = 0, shape = p->shape == HeadShape::Ellipse ? 0 : 1, nw = 0;
  whole("-strings_frame", &frame);
  real("-strings_tension", &p->tension);
  p->tension_crosses = p->tension; // the default is the mains'
  real("-strings_tension_crosses", &p->tension_crosses);
  real("-strings_spacing", &p->spacing);
  p->spacing_crosses = p->spacing;
  real("-strings_spacing_crosses", &p->spacing_crosses);
  real("-strings_linear_density", &p->linear_density);
  whole("-head_shape", &shape);
  real("-head_length", &p->head_length);
  real("-head_width", &p->head_width);
  real("-head_center", &p->head_center);
  whole("-strings_nodes", &p->nodes);
  real("-strings_patch_radius", &p->patch_radius);
  real("-strings_inplane_stiffness", &p->inplane_stiffness);
  real("-strings_inplane_mass", &p->inplane_mass);
  whole("-strings_nodes_width", &nw);
  p->shape       = shape == 0 ? HeadShape::Ellipse : HeadShape::Rectangle;
  p->frame       = frame == 1 ? "held" : frame == 2 ? "beam" : "none";
  p->nodes_width = nw;
}

// The rows as read -> the bed's parameters; checks across options: at least one string of each
// kind across the head, 5 nodes across a held bed's width.
bool StringBedParamsFrom(const PartOptionValues &v, StringBedParams *p, std::string *why)
{
  StringBedParamsFill(v, p);
  if (!p->On()) return true;           // no bed: its options have no effect (a note)
  const BedGrid g = StringBedGrid(*p); // the held frame's grid (a beam frame's: Frame)
  if (!(p->spacing < p->head_width))
    *why = PetscFmt("-strings_spacing %g m is not allowed with -head_width %g m: the mains, %g m apart across the "
                    "face, leave no string on the head; it must be < -head_width (m)",
                    (double)p->spacing, (double)p->head_width, (double)p->spacing);
  else if (!(p->spacing_crosses < p->head_length))
    *why = PetscFmt("%s %g m is not allowed with -head_length %g m: the crosses, %g m apart along the frame, leave no "
                    "string on the head; it must be < -head_length (m)",
                    v.Given("-strings_spacing_crosses") ? "-strings_spacing_crosses"
                                                        : "-strings_spacing (the crosses' default)",
                    (double)p->spacing_crosses, (double)p->head_length, (double)p->spacing_crosses);
  else if (p->Held() && g.nz < 5)
    *why = PetscFmt("-strings_nodes %" PetscInt_FMT " with -head_length %g and -head_width %g puts %" PetscInt_FMT
                    " nodes across the width: at least 5 are needed (more -strings_nodes, or -strings_nodes_width)",
                    p->nodes, (double)p->head_length, (double)p->head_width, g.nz);
  return why->empty();
}

const StringBedParams *StringBedOf(const BeamParams &beam)
{
  const PartParams *q = beam.parts.Find(BedPart().Name());
  return q ? &P(*q).bed : nullptr;
}

void StringBedSet(BeamParams *beam, const StringBedParams &bed)
{
  auto p = std::make_shared<BedParams>();
  p->bed = bed;
  beam->parts.Set(BedPart().Name(), bed.On() ? p : nullptr);
}

const StructurePart &BedPart()
{
  static const Bed part;
  return part;
}

} // namespace beamimpact

// The hands on the handle (-grip x_a,x_b; docs/model.md, "The hands"; model/grip.hpp for the
// weights): a structure part without fields. A spring-damper over [x_a, x_b] ties the handle's
// deflection to the swing's rigid frame, which moves with the velocity v_f (FrameMotion; zero for
// a bat at rest): on the deflection dof d of node i, with the share w_i of the span,
//
//   f_d = k_i (y_d - v_f,d t) + c_i (v_d - v_f,d),   k_i = k' w_i (N/m),  c_i = c' w_i (N s/m),
//
// and the hands' mass m_hand w_i / (x_b - x_a) added to m_d (AddMasses, before the force terms);
// with -beam_torsion and -grip_torsion_stiffness/-grip_torsion_damping the same on the node's
// roll (k_phi' w_i in N m/rad, c_phi' w_i in N m s/rad, the frame's roll rate 0). Stored energy
// 1/2 sum k_i (y_d - v_f,d t)^2, dissipation rate sum c_i (v_d - v_f,d)^2 >= 0, the force of the
// beam on the hands sum f_d (and its moment about x = 0), the power the frame puts in -sum v_f,d
// f_d; the drive f(0, 0, t) = -k_i v_f,d t - c_i v_f,d. It ties the structure to the frame
// (momentum is not an invariant); the free-vibration modes do not carry it (a forcing in time,
// and a damper not proportional to M or K). A structure part (system/structure_part.hpp): its
// option rows (with -monitor_grip), checks, force term, the hands' mass, its measures (the force
// operator's frame terms: the force on the hands, its moment, the stored energy, the hands'
// work), results columns, series and summary line are this file. Units: SI.
#include "model/grip.hpp"
#include "system/beam_system.hpp"
#include "system/structure_part.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

namespace {

struct GripParams : PartParams {
  BeamGrip grip;            // the physics inputs (model/beam.hpp)
  bool     monitor = false; // -monitor_grip: its series per step
};
const GripParams &P(const PartParams &q) { return static_cast<const GripParams &>(q); }

// The force term "grip": the hands' spring-dampers, one per gripped dof.
class GripTerm : public ForceTerm {
public:
  // One spring-damper of the hands: on field f (the deflection, or the roll) of a node.
  struct Hold {
    PetscInt  node, field;
    PetscReal k, c; // N/m and N s/m on a deflection; N m/rad and N m s/rad on the roll
  };
  explicit GripTerm(std::vector<Hold> holds) : holds_(std::move(holds))
  {
    for (const Hold &h : holds_) damping_ += h.c;
  }
  const char *Name() const override { return "grip"; }
  bool        Damps() const override { return damping_ > 0; }
  bool        TiesToFrame() const override { return true; }

  void AddForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                PetscInt fs) const override
  {
    ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) { f[h.node * fs + h.field] += Force(s, h, d); });
  }
  void AddDampingForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                       PetscInt fs) const override
  {
    if (s.v)
      ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) {
        f[h.node * fs + h.field] += h.c * (s.v[h.node * s.vs + h.field] - Frame(s.frame, d));
      });
  }
  void AddDrive(const BeamSystem &sys, PetscReal t, const FrameMotion *frame, PetscInt d0, PetscInt d1, PetscReal *f,
                PetscInt fs) const override
  {
    ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) {
      f[h.node * fs + h.field] -= h.k * Frame(frame, d) * t + h.c * Frame(frame, d);
    });
  }
  void AddJacobian(const BeamSystem &sys, PetscReal *K, PetscReal *, PetscReal *Cdiag) const override
  {
    const PetscInt width = 2 * sys.bw + 1;
    ForEach(sys, 0, sys.ndof, [&](const Hold &h, PetscInt d) {
      K[(size_t)width * d + sys.bw] += h.k;
      Cdiag[d] += h.c;
    });
  }
  PetscReal Energy(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    PetscReal U = 0.0;
    ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) {
      const PetscReal u = s.y[h.node * s.ys + h.field] - Frame(s.frame, d) * s.t;
      U += h.k * u * u;
    });
    return 0.5 * U;
  }
  PetscReal DissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    PetscReal r = 0.0;
    if (s.v)
      ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) {
        const PetscReal u = s.v[h.node * s.vs + h.field] - Frame(s.frame, d);
        r += h.c * u * u;
      });
    return r;
  }
  void AddFrameReaction(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *force,
                        PetscReal *moment) const override
  {
    ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) {
      if (h.field != 0) return; // a torque about the frame's axis: no force, no moment about x = 0
      const PetscReal fd = Force(s, h, d);
      *force += fd;
      *moment += sys.NodeX(h.node) * fd;
    });
  }
  PetscReal DrivePower(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    PetscReal P = 0.0;
    ForEach(sys, d0, d1, [&](const Hold &h, PetscInt d) { P -= Frame(s.frame, d) * Force(s, h, d); });
    return P;
  }
  DampingScales Scales(const BeamSystem &sys) const override
  {
    DampingScales s;
    ForEach(sys, 0, sys.ndof,
            [&](const Hold &h, PetscInt d) { s.mass_rate = std::max(s.mass_rate, h.c / sys.mass[d]); });
    return s;
  }
  bool Modal(PetscReal *, PetscReal *, std::string *why) const override
  {
    if (why)
      *why = "the beam is held by the hands (-grip: a time-dependent drive of the swing's frame and a non-proportional "
             "damper), which the free-vibration modes do not include";
    return false;
  }

private:
  std::vector<Hold> holds_;       // the gripped nodes' deflections, then their rolls
  PetscReal         damping_ = 0; // sum of the dampers' c

  static PetscReal Frame(const FrameMotion *frame, PetscInt d) { return frame ? frame->At(d) : 0.0; }
  // The generalized force (N, or N m on the roll) of hold h on its dof d (arrays by node: node * stride is its field
  // 0).
  PetscReal Force(const ForceState &s, const Hold &h, PetscInt d) const
  {
    const PetscReal vf = Frame(s.frame, d);
    PetscReal       fd = h.k * (s.y[h.node * s.ys + h.field] - vf * s.t);
    if (s.v) fd += h.c * (s.v[h.node * s.vs + h.field] - vf);
    return fd;
  }
  // fn(hold, dof) for the holds whose dof is in [d0, d1) and not held.
  template <class Fn>
  void ForEach(const BeamSystem &sys, PetscInt d0, PetscInt d1, Fn fn) const
  {
    for (const Hold &h : holds_) {
      const PetscInt d = sys.Dof(h.node, h.field);
      if (d >= d0 && d < d1 && !sys.held[d]) fn(h, d);
    }
  }
};

// The hands' holds on the free gripped dofs of S: the deflections, then the rolls.
std::vector<GripTerm::Hold> GripHolds(const BeamGrip &g, const BeamSystem &S)
{
  const std::vector<PetscReal> w = GripNodeWeights(g, S.nodes, S.L);
  std::vector<GripTerm::Hold>  holds;
  for (PetscInt i = 0; i < S.nodes; ++i)
    if (!S.held[S.Dof(i)] && w[i] != 0.0) holds.push_back({i, 0, g.stiffness * w[i], g.damping * w[i]});
  const PetscInt phi  = S.RollField(); // the hands' hold on the frame's roll
  const bool     roll = phi >= 0 && (g.torsion_stiffness > 0 || g.torsion_damping > 0);
  for (PetscInt i = 0; roll && i < S.nodes; ++i)
    if (w[i] != 0.0 && !S.held[S.Dof(i, phi)])
      holds.push_back({i, phi, g.torsion_stiffness * w[i], g.torsion_damping * w[i]});
  return holds;
}

const OptionModule &GripOptions()
{
  static const OptionModule m =
    {"grip",
     "The hands on the handle (docs/model.md, \"The hands\")",
     {
       OptionList("-grip", "m",
                  "The hands: grip x_a,x_b, a spring-damper per metre of handle tying it to the swing's rigid frame (a "
                  "free beam)",
                  2, 2, NonNegative()),
       OptionNeeds(OptionReal("-grip_stiffness", "N/m^2",
                              "Grip stiffness k' per metre of handle: force -k' (y - v_f t) per metre", "0",
                              NonNegative()),
                   {"-grip"}),
       OptionNeeds(OptionReal("-grip_damping", "N s/m^2",
                              "Grip damping c' per metre of handle: force -c' (v - v_f) per metre", "0", NonNegative()),
                   {"-grip"}),
       OptionNeeds(OptionReal("-grip_mass", "kg", "Mass of the hands, spread over the grip's translational dofs", "0",
                              NonNegative()),
                   {"-grip"}),
       OptionNeeds(OptionReal("-grip_torsion_stiffness", "N m/rad/m",
                              "The hands' hold on the frame's roll (-beam_torsion): torque -k'_phi phi per metre of "
                              "handle",
                              "0", NonNegative()),
                   {"-grip"}),
       OptionNeeds(OptionReal("-grip_torsion_damping", "N m s/rad/m",
                              "The hands' damping of the frame's roll: torque -c'_phi phi_t per metre of handle", "0",
                              NonNegative()),
                   {"-grip"}),
       OptionNeeds(OptionFlag("-monitor_grip", "With -grip: record the force of the bat on the hands (total, and its "
                                               "moment about x = 0), the grip's stored energy and the hands' work at "
                                               "every step"),
                   {"-grip"}),
     }};
  return m;
}

// -grip and its stiffnesses on this beam: an interval of a free bat, non-negative numbers; "" or
// the refusal, naming the option and its value.
std::string GripRefusal(const BeamGrip &g, const BeamParams &p)
{
  const double a = g.x_a, b = g.x_b;
  if (p.frame_held) return "-strings_frame held holds the whole frame: -grip has nothing to hold";
  if (!(g.x_a >= 0 && g.x_b <= p.length && g.x_a < g.x_b))
    return Fmt("-grip %g,%g is not allowed: the grip must be a non-empty interval of the beam, 0 <= x_a < x_b <= L = "
               "%g (m)",
               a, b, (double)p.length);
  const struct {
    const char *name, *unit;
    PetscReal   value;
  } rows[] = {{"-grip_stiffness", "N/m^2", g.stiffness},
              {"-grip_damping", "N s/m^2", g.damping},
              {"-grip_mass", "kg", g.mass},
              {"-grip_torsion_stiffness", "N m/rad per m", g.torsion_stiffness},
              {"-grip_torsion_damping", "N m s/rad per m", g.torsion_damping}};
  for (const auto &r : rows)
    if (!(r.value >= 0 && std::isfinite(r.value)))
      return Fmt("%s %g is not allowed: it must be >= 0 (%s)", r.name, (double)r.value, r.unit);
  for (const char *end : {"left", "right"}) { // the first end held in any way (io/beam_options.cpp's words)
    const Support s = *end == 'l' ? p.left : p.right;
    if (s.Holds() != NodeHold::None)
      return Fmt("-grip %g,%g with a %s end (-beam_%s %s) is not allowed: the hands hold a free bat", a, b, s.Name(),
                 end, s.Name());
  }
  if (p.has_clamp)
    return Fmt("-grip %g,%g with a clamped region (-beam_clamp %g,%g) is not allowed: the hands hold a free bat", a, b,
               (double)p.clamp_x0, (double)p.clamp_x1);
  if (p.has_pivot) // as written (p.pivot_x is on its node by now)
    return Fmt("-grip %g,%g with a pivot (-beam_pivot %s) is not allowed: the hands hold a free bat (the pivot is the "
               "certification rig's)",
               a, b, OptionWritten("-beam_pivot").c_str());
  return "";
}

// The slots: the force operator's frame terms, in MeasureFrame's order.
enum Slot {
  kForce,
  kMoment,
  kStored,
  kWork
};

class Grip : public StructurePart {
public:
  const char         *Name() const override { return "grip"; }
  const char         *Presence() const override { return "with -grip"; }
  const char         *Words() const override { return "the hands (-grip)"; }
  const OptionModule &Options() const override { return GripOptions(); }
  bool Configure(const PartOptionValues &v, const BeamParams &beam, std::shared_ptr<const PartParams> *out,
                 std::string *why) const override
  {
    *out = nullptr;
    if (!v.Given("-grip")) return true;
    auto      p   = std::make_shared<GripParams>();
    BeamGrip &g   = p->grip;
    auto      get = [&](const char *name, PetscReal *x) {
      if (v.Given(name)) *x = v.given.at(name)[0];
    };
    g.on = true, g.x_a = v.given.at("-grip")[0], g.x_b = v.given.at("-grip")[1];
    get("-grip_stiffness", &g.stiffness);
    get("-grip_damping", &g.damping);
    get("-grip_mass", &g.mass);
    get("-grip_torsion_stiffness", &g.torsion_stiffness);
    get("-grip_torsion_damping", &g.torsion_damping);
    p->monitor = v.Given("-monitor_grip") && v.given.at("-monitor_grip")[0] != 0;
    if (!(*why = GripRefusal(g, beam)).empty()) return false;
    *out = p;
    return true;
  }
  // The hands' hold on the roll needs the frame's roll (another part).
  std::string RefusalWith(const PartParams &q, const BeamParams &beam) const override
  {
    const BeamGrip &g = P(q).grip;
    if (beam.parts.Rolls() || (g.torsion_stiffness == 0 && g.torsion_damping == 0)) return "";
    return Fmt("%s %g without -beam_torsion is not allowed: the hands hold the frame's roll, which only -beam_torsion "
               "gives it",
               g.torsion_stiffness != 0 ? "-grip_torsion_stiffness" : "-grip_torsion_damping",
               (double)(g.torsion_stiffness != 0 ? g.torsion_stiffness : g.torsion_damping));
  }
  const char *ModalRefusal(const PartParams &) const override
  {
    return "with -grip is not possible: the hands' frame drive (a forcing in time) and damper are not in the modal "
           "reference; use a tight TS run as the reference";
  }
  bool TiesToFrame(const PartParams &) const override { return true; }
  bool Monitors(const PartParams &q) const override { return P(q).monitor; }
  // The hands: m_hand w_i / (x_b - x_a) on each free gripped deflection.
  void AddMasses(const PartInstance &s, BeamSystem *sys) const override
  {
    BeamSystem                  &S = *sys;
    const BeamGrip              &g = P(*s.params).grip;
    const std::vector<PetscReal> w = GripNodeWeights(g, S.nodes, S.L);
    for (PetscInt i = 0; i < S.nodes; ++i)
      if (!S.held[S.Dof(i)] && w[i] != 0.0) S.mass[S.Dof(i)] += g.mass * w[i] / (g.x_b - g.x_a);
  }
  void ForceTerms(const PartInstance &s, const BeamSystem &sys,
                  std::vector<std::shared_ptr<const ForceTerm>> *t) const override
  {
    t->push_back(std::make_shared<GripTerm>(GripHolds(P(*s.params).grip, sys)));
  }
  std::vector<PartSlot> Slots() const override
  {
    return {{"grip_force", "N", false, true, true},
            {"grip_moment", "N m", false, true, true},
            {"grip_stored", "J", false, true, true},
            {"hand_work", "J", false, true, true}};
  }
  void MeasureFrame(const PartInstance &, const FrameMeasures &fm, PetscReal *slot) const override
  {
    slot[kForce] = fm.force, slot[kMoment] = fm.moment, slot[kStored] = fm.stored, slot[kWork] = fm.work;
  }
  const char             *ColumnsAfter() const override { return "bbcor"; }
  std::vector<PartColumn> Columns() const override
  {
    return {
      {"grip_force_peak", "N", "largest |force of the bat on the hands| over the steps",
       [](const PartOutputFacts &f) -> double { return f.frame_force_peak; }},
      {"grip_force_peak_time", "s", "when", [](const PartOutputFacts &f) -> double { return f.frame_force_peak_time; }},
      {"grip_stored_end", "J", "the grip's stored energy at the end",
       [](const PartOutputFacts &f) -> double { return f.end[kStored]; }},
      {"hand_work_end", "J", "work the hands did on the bat by the end",
       [](const PartOutputFacts &f) -> double { return f.end[kWork]; }},
      {"grip_fraction", "1", "grip_stored_end / E_in",
       [](const PartOutputFacts &f) -> double { return f.end[kStored] / f.E_in; }, "grip"},
      {"hands_fraction", "1", "the energy the bat gave the hands, -hand_work_end / E_in (< 0: the hands gave energy)",
       [](const PartOutputFacts &f) -> double { return -f.end[kWork] / f.E_in; }, "to the hands"},
    };
  }
  std::string Summary(const PartParams &q, const std::vector<double> &c) const override
  {
    return Fmt("hands on %g-%g m: peak force on the hands %.4e N at %.4e s; grip energy stored at the end %.4e J; "
               "work done by the hands %.4e J",
               (double)P(q).grip.x_a, (double)P(q).grip.x_b, c[0], c[1], c[2], c[3]);
  }
};

} // namespace

const StructurePart &GripPart()
{
  static const Grip part;
  return part;
}

} // namespace beamimpact

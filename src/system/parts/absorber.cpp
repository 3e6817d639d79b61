// A tuned vibration absorber on the beam (docs/model.md, "A tuned vibration absorber"): the damper
// bat makers fit in the knob to cut the sting. A mass m_a on a spring k_a = m_a (2 pi f_a)^2 and
// a dashpot c_a = 2 zeta m_a (2 pi f_a) attached to the beam at x_a (-absorber x_a,m_a,f_a,zeta):
//
//   m_a u'' = -k_a (u - y(x_a)) - c_a (u' - y'(x_a)),    y(x_a) = w y_j + (1 - w) y_j+1,
//
// u (m) the mass's displacement: one more field per node, free only at node j (the left node of
// x_a's hat, GridImpactStencil); the spring a strain term, the dashpot a force term (not
// proportional damping: the modal tools refuse zeta > 0), both internal (the beam feels -k_a
// (u - y) - c_a (u' - y') back through the hat weights), so a free beam's momentum is kept. A
// rigid motion carries u with the beam at x_a: m_a is in the momenta, the free mass and the
// rigid body; its energy is in the beam's (beam_kinetic, beam_strain), the dashpot's work in
// beam_dissipated. A structure part (system/structure_part.hpp): this file and its line in
// system/structure.cpp are all of it. Units: SI.
#include "system/beam_system.hpp"
#include "system/structure_part.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beamimpact {

namespace {

struct AbsorberParams : PartParams {
  PetscReal x = 0, mass = 0, frequency = 0, zeta = 0;              // m, kg, Hz, 1
  PetscReal Omega() const { return 2 * PETSC_PI * frequency; }     // rad/s
  PetscReal Stiffness() const { return mass * Omega() * Omega(); } // N/m, k_a
  PetscReal Damping() const { return 2 * zeta * mass * Omega(); }  // N s/m, c_a
  void      AddRigidBody(SectionMoments *m) const override         // a point mass at x_a
  {
    m->m0 += mass, m->m1 += mass * x, m->m2 += mass * x * x;
  }
};
struct AbsorberBuilt : PartBuilt {
  PetscInt  dof[3] = {0, 0, 0}; // u, y_j, y_j+1
  PetscReal b[3]   = {1, 0, 0}; // the stroke u - y(x_a) = b . (u, y_j, y_j+1)
};
const AbsorberParams &P(const PartInstance &s) { return static_cast<const AbsorberParams &>(*s.params); }
const AbsorberBuilt  &B(const PartInstance &s) { return static_cast<const AbsorberBuilt &>(*s.built); }

// A state's dof d (ForceState's and PartState's layout).
inline PetscReal At(const PetscReal *a, PetscInt stride, PetscInt d, PetscInt F) { return a[(d / F) * stride + d % F]; }

// The dashpot: r = c b . v (N), +c b_k (b . v) on each of its three dofs; C = c b b^T.
class AbsorberDashpot : public ForceTerm {
public:
  AbsorberDashpot(const AbsorberBuilt &a, PetscReal c) : a_(a), c_(c) { }
  const char *Name() const override { return "absorber"; }
  void        AddForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                       PetscInt fs) const override
  {
    if (s.v) Add(sys, s, d0, d1, f, fs);
  }
  void AddDampingForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                       PetscInt fs) const override
  {
    Add(sys, s, d0, d1, f, fs);
  }
  void AddJacobian(const BeamSystem &sys, PetscReal *, PetscReal *C, PetscReal *) const override
  {
    const PetscInt w = 2 * sys.bw + 1;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) C[(size_t)w * a_.dof[p] + (a_.dof[q] - a_.dof[p] + sys.bw)] += c_ * a_.b[p] * a_.b[q];
  }
  PetscInt  HalfWidth(const BeamSystem &) const override { return a_.dof[2] - a_.dof[1]; } // the widest pair
  PetscInt  Reach(const BeamSystem &) const override { return a_.dof[2] - a_.dof[1]; }
  PetscReal DissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    if (a_.dof[0] < d0 || a_.dof[0] >= d1) return 0; // u's owner
    const PetscReal r = Rate(sys, s);
    return c_ * r * r;
  }
  bool          Damps() const override { return true; }
  DampingScales Scales(const BeamSystem &sys) const override
  {
    DampingScales s; // C's row k sums to c |b_k| sum |b| = 2 c |b_k| (Gershgorin), over its mass
    for (int k = 0; k < 3; ++k) s.mass_rate = std::max(s.mass_rate, 2 * c_ * std::abs(a_.b[k]) / sys.mass[a_.dof[k]]);
    return s;
  }
  bool Modal(PetscReal *, PetscReal *, std::string *why) const override
  {
    if (why)
      *why = "the absorber's dashpot (-absorber with zeta > 0) is not proportional damping: give zeta 0 for the "
             "modes, or a time-stepping run";
    return false;
  }

private:
  PetscReal Rate(const BeamSystem &sys, const ForceState &s) const
  {
    PetscReal r = 0;
    for (int k = 0; k < 3; ++k) r += a_.b[k] * At(s.v, s.vs, a_.dof[k], sys.fields);
    return r;
  }
  void Add(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt fs) const
  {
    const PetscReal r = c_ * Rate(sys, s);
    const PetscInt  F = sys.fields;
    for (int k = 0; k < 3; ++k)
      if (a_.dof[k] >= d0 && a_.dof[k] < d1) f[(a_.dof[k] / F) * fs + a_.dof[k] % F] += a_.b[k] * r;
  }
  AbsorberBuilt a_;
  PetscReal     c_; // N s/m
};

const OptionModule &AbsorberOptions()
{
  static const OptionModule m =
    {"absorber",
     "Tuned vibration absorber on the beam (the knob's damper; docs/model.md)",
     {OptionList("-absorber", "m,kg,Hz,1",
                 "x_a,m_a,f_a,zeta: a mass m_a (kg) on a spring tuned to f_a (Hz) with damping ratio zeta, attached "
                 "at x_a (m) along the beam; Den Hartog's optimum for a mode f of modal mass M at x_a: mu = m_a/M, f_a "
                 "= f/(1 + mu), zeta = sqrt(3 mu/(8 (1 + mu)^3))",
                 4, 4)}};
  return m;
}

// The refusal of -absorber's values, naming them: "" when they are allowed on this beam.
std::string AbsorberRefusal(const std::vector<PetscReal> &v, const BeamParams &beam)
{
  const PetscReal x = v[0], m = v[1], f = v[2], zeta = v[3];
  std::string     why;
  if (!(x >= 0 && x <= beam.length))
    why = Fmt("its x_a = %g m is off the beam: it must be in [0, %g] m (-beam_length)", (double)x, (double)beam.length);
  else if (!(m > 0)) why = Fmt("its mass m_a = %g kg must be > 0", (double)m);
  else if (!(f > 0)) why = Fmt("its frequency f_a = %g Hz must be > 0", (double)f);
  else if (!(zeta >= 0)) why = Fmt("its damping ratio zeta = %g must be >= 0", (double)zeta);
  else if (beam.frame_held) why = "a held string bed (-strings_frame held) has no frame to attach it to";
  else {
    const ImpactStencil         st    = GridImpactStencil(beam.nodes, beam.length, x);
    const std::vector<NodeHold> hold  = BeamNodeHolds(beam);
    const bool                  left  = st.w > 0 && !HoldsDeflection(hold[st.j]);
    const bool                  right = st.w < 1 && !HoldsDeflection(hold[st.j + 1]);
    if (!left && !right)
      why = Fmt("x_a = %g m is on a held node (a support, -beam_clamp or -beam_pivot holds the deflection there): the "
                "absorber would not move; put it where the beam moves",
                (double)x);
  }
  return why.empty() ? "" : "-absorber " + OptionWritten("-absorber") + " is not allowed: " + why;
}

std::string AbsorberSummary(const PartParams &q, const std::vector<double> &c)
{
  const auto &p = static_cast<const AbsorberParams &>(q);
  char        line[400];
  std::snprintf(line, sizeof line,
                "absorber at x %g m: %g kg tuned to %g Hz, zeta %g (k_a %.4g N/m, c_a %.4g N s/m); its largest "
                "stroke %.4e m, its energy %.4e J at most, %.4e J at the end",
                (double)p.x, (double)p.mass, (double)p.frequency, (double)p.zeta, (double)p.Stiffness(),
                (double)p.Damping(), c[2], c[1], c[0]);
  return line;
}

class Absorber : public StructurePart {
public:
  const char         *Name() const override { return "absorber"; }
  const char         *Presence() const override { return "with -absorber"; }
  const char         *Words() const override { return "the absorber's spring and mass (-absorber)"; }
  const OptionModule &Options() const override { return AbsorberOptions(); }
  bool Configure(const PartOptionValues &v, const BeamParams &beam, std::shared_ptr<const PartParams> *out,
                 std::string *why) const override
  {
    *out = nullptr;
    if (!v.Given("-absorber")) return true;
    const std::vector<PetscReal> &x = v.given.at("-absorber");
    if (!(*why = AbsorberRefusal(x, beam)).empty()) return false;
    auto p = std::make_shared<AbsorberParams>();
    p->x = x[0], p->mass = x[1], p->frequency = x[2], p->zeta = x[3];
    *out = p;
    return true;
  }
  const char *ModalRefusal(const PartParams &q) const override
  {
    return static_cast<const AbsorberParams &>(q).zeta > 0
           ? "with -absorber's zeta > 0 is not possible: the absorber's dashpot is not proportional damping, which "
             "the modes cannot carry; use a tight TS run as the reference"
           : nullptr;
  }
  PetscInt Build(const PartParams &q, const BeamParams &beam, BeamDiscretization *d,
                 std::shared_ptr<const PartBuilt> *out) const override
  {
    const auto         &p  = static_cast<const AbsorberParams &>(q);
    const ImpactStencil st = GridImpactStencil(beam.nodes, beam.length, p.x);
    const PetscInt      F  = d->fields + 1;
    BeamDiscretizationWiden(d, F, p.mass); // the new field, held everywhere but at node j; its mass m_a
    auto a    = std::make_shared<AbsorberBuilt>();
    a->dof[0] = st.j * F + F - 1, a->dof[1] = st.j * F, a->dof[2] = (st.j + 1) * F;
    a->b[0] = 1, a->b[1] = -st.w, a->b[2] = -(1 - st.w);
    d->held[a->dof[0]] = 0;
    StrainTerm t; // 1/2 k_a (u - y(x_a))^2, owned by u
    t.n = 3, t.owner = a->dof[0], t.weight = p.Stiffness();
    for (int k = 0; k < 3; ++k) t.dof[k] = a->dof[k], t.b[k] = a->b[k];
    d->strain.push_back(t);
    *out = a;
    return 1;
  }
  void RigidPoints(const PartInstance &s, std::vector<RigidPoint> *r) const override
  {
    RigidPoint pt;
    pt.dof = B(s).dof[0], pt.x = P(s).x;
    r->push_back(pt);
  }
  void ForceTerms(const PartInstance                            &s, const BeamSystem &,
                  std::vector<std::shared_ptr<const ForceTerm>> *t) const override
  {
    if (P(s).Damping() > 0) t->push_back(std::make_shared<AbsorberDashpot>(B(s), P(s).Damping()));
  }
  std::vector<PartSlot> Slots() const override
  {
    return {{"absorber_energy", "J", true, true}, {"absorber_stroke", "m", true, true}};
  }
  void Measure(const PartInstance &s, const BeamSystem &sys, const PartState &st, PetscReal *slot) const override
  {
    const AbsorberBuilt &a = B(s); // by u's owner (the others add 0)
    if (a.dof[0] < st.d0 || a.dof[0] >= st.d1) return;
    PetscReal stroke = 0;
    for (int k = 0; k < 3; ++k) stroke += a.b[k] * At(st.y, st.ys, a.dof[k], sys.fields);
    const PetscReal u_t = At(st.v, st.vs, a.dof[0], sys.fields);
    slot[0] += 0.5 * P(s).mass * u_t * u_t + 0.5 * P(s).Stiffness() * stroke * stroke;
    slot[1] += stroke;
  }
  std::vector<PartColumn> Columns() const override
  {
    return {
      {"absorber_energy_end", "J",
       "the absorber's energy at the end, 1/2 m_a u_t^2 + 1/2 k_a (u - y(x_a))^2 (in beam_kinetic and beam_strain)",
       [](const PartOutputFacts &f) -> double { return f.end[0]; }},
      {"absorber_energy_peak", "J", "the absorber's largest energy over the steps (NaN from the modal reference)",
       [](const PartOutputFacts &f) -> double { return f.peak[0]; }},
      {"absorber_stroke_peak", "m",
       "the absorber's largest stroke |u - y(x_a)| over the steps (NaN from the modal reference)",
       [](const PartOutputFacts &f) -> double { return f.peak[1]; }},
    };
  }
  std::string Summary(const PartParams &q, const std::vector<double> &c) const override
  {
    return AbsorberSummary(q, c);
  }
};

} // namespace

const StructurePart &AbsorberPart()
{
  static const Absorber part;
  return part;
}

} // namespace beamimpact

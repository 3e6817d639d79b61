// Force term "grip": the hands (docs/model.md, "The hands"; model/grip.hpp for the weights). A
// spring-damper over [x_a, x_b] ties the handle's deflection to the swing's rigid frame, which
// moves with the velocity v_f (FrameMotion; zero for a bat at rest): on the deflection dof d of
// node i, with the share w_i of the span,
//
//   f_d = k_i (y_d - v_f,d t) + c_i (v_d - v_f,d),   k_i = k' w_i (N/m),  c_i = c' w_i (N s/m),
//
// and the hands' mass m_hand w_i / (x_b - x_a) added to m_d when the term is created; with
// -beam_torsion and -grip_torsion_stiffness/-grip_torsion_damping the same on the node's roll
// (k_phi' w_i in N m/rad, c_phi' w_i in N m s/rad, the frame's roll rate 0). Stored
// energy 1/2 sum k_i (y_d - v_f,d t)^2, dissipation rate sum c_i (v_d - v_f,d)^2 >= 0, the force
// of the beam on the hands sum f_d (and its moment about x = 0), the power the frame puts in
// -sum v_f,d f_d; the drive f(0, 0, t) = -k_i v_f,d t - c_i v_f,d. The free-vibration modes do
// not carry it (a forcing in time, and a damper not proportional to M or K).
#include "model/grip.hpp"
#include "system/beam_system.hpp"

#include <algorithm>

namespace beamimpact {

namespace {

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

} // namespace

std::shared_ptr<const ForceTerm> GripTermCreate(const BeamParams &p, BeamSystem *sys)
{
  if (!p.grip.on) return nullptr;
  BeamSystem                  &S    = *sys;
  const std::vector<PetscReal> w    = GripNodeWeights(p.grip, S.nodes, S.L);
  const PetscReal              span = p.grip.x_b - p.grip.x_a;
  std::vector<GripTerm::Hold>  holds;
  for (PetscInt i = 0; i < S.nodes; ++i) {
    const PetscInt d = S.Dof(i);
    if (S.held[d] || w[i] == 0.0) continue;
    holds.push_back({i, 0, p.grip.stiffness * w[i], p.grip.damping * w[i]});
    S.mass[d] += p.grip.mass * w[i] / span; // the hands
  }
  const PetscInt phi  = S.RollField(); // the hands' hold on the frame's roll
  const bool     roll = phi >= 0 && (p.grip.torsion_stiffness > 0 || p.grip.torsion_damping > 0);
  for (PetscInt i = 0; roll && i < S.nodes; ++i)
    if (w[i] != 0.0 && !S.held[S.Dof(i, phi)])
      holds.push_back({i, phi, p.grip.torsion_stiffness * w[i], p.grip.torsion_damping * w[i]});
  return std::make_shared<GripTerm>(std::move(holds));
}

} // namespace beamimpact

// Force term "grip": the hands (docs/model.md, "The hands"; model/grip.hpp for the weights). A
// spring-damper over [x_a, x_b] ties the handle's deflection to the swing's rigid frame, which
// moves with the velocity v_f (FrameMotion; zero for a bat at rest): on the deflection dof d of
// node i, with the share w_i of the span,
//
//   f_d = k_i (y_d - v_f,d t) + c_i (v_d - v_f,d),   k_i = k' w_i (N/m),  c_i = c' w_i (N s/m),
//
// and the hands' mass m_hand w_i / (x_b - x_a) added to m_d when the term is created. Stored
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
  GripTerm(std::vector<PetscReal> k, std::vector<PetscReal> c) : k_(std::move(k)), c_(std::move(c))
  {
    for (size_t i = 0; i < k_.size(); ++i)
      if (k_[i] != 0.0 || c_[i] != 0.0) nodes_.push_back((PetscInt)i);
    for (PetscReal ci : c_) damping_ += ci;
  }
  const char *Name() const override { return "grip"; }
  bool        Damps() const override { return damping_ > 0; }
  bool        TiesToFrame() const override { return true; }

  void AddForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt fs) const override
  {
    ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) { f[i * fs] += Force(s, i, d); });
  }
  void AddDampingForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt fs) const override
  {
    if (s.v) ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) { f[i * fs] += c_[i] * (s.v[i * s.vs] - Frame(s.frame, d)); });
  }
  void AddDrive(const BeamSystem &sys, PetscReal t, const FrameMotion *frame, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt fs) const override
  {
    ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) { f[i * fs] -= k_[i] * Frame(frame, d) * t + c_[i] * Frame(frame, d); });
  }
  void AddJacobian(const BeamSystem &sys, PetscReal *K, PetscReal *, PetscReal *Cdiag) const override
  {
    const PetscInt width = 2 * sys.bw + 1;
    ForEach(sys, 0, sys.ndof, [&](PetscInt i, PetscInt d) {
      K[(size_t)width * d + sys.bw] += k_[i];
      Cdiag[d] += c_[i];
    });
  }
  PetscReal Energy(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    PetscReal U = 0.0;
    ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) {
      const PetscReal u = s.y[i * s.ys] - Frame(s.frame, d) * s.t;
      U += k_[i] * u * u;
    });
    return 0.5 * U;
  }
  PetscReal DissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    PetscReal r = 0.0;
    if (s.v) ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) {
        const PetscReal u = s.v[i * s.vs] - Frame(s.frame, d);
        r += c_[i] * u * u;
      });
    return r;
  }
  void AddFrameReaction(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *force, PetscReal *moment) const override
  {
    ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) {
      const PetscReal fd = Force(s, i, d);
      *force += fd;
      *moment += sys.NodeX(i) * fd;
    });
  }
  PetscReal DrivePower(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    PetscReal P = 0.0;
    ForEach(sys, d0, d1, [&](PetscInt i, PetscInt d) { P -= Frame(s.frame, d) * Force(s, i, d); });
    return P;
  }
  DampingScales Scales(const BeamSystem &sys) const override
  {
    DampingScales s;
    ForEach(sys, 0, sys.ndof, [&](PetscInt i, PetscInt d) { s.mass_rate = std::max(s.mass_rate, c_[i] / sys.mass[d]); });
    return s;
  }
  bool Modal(PetscReal *, PetscReal *, std::string *why) const override
  {
    if (why) *why = "the beam is held by the hands (-grip: a time-dependent drive of the swing's frame and a non-proportional damper), which the free-vibration modes do not include";
    return false;
  }

private:
  std::vector<PetscReal> k_, c_;     // N/m, N s/m per node
  std::vector<PetscInt>  nodes_;     // the nodes with a spring or a damper
  PetscReal              damping_ = 0; // N s/m, sum of c_i

  static PetscReal Frame(const FrameMotion *frame, PetscInt d) { return frame ? frame->At(d) : 0.0; }
  // The force on the deflection dof d of node i (arrays by node: i * stride is its field 0).
  PetscReal Force(const ForceState &s, PetscInt i, PetscInt d) const
  {
    const PetscReal vf = Frame(s.frame, d);
    PetscReal       fd = k_[i] * (s.y[i * s.ys] - vf * s.t);
    if (s.v) fd += c_[i] * (s.v[i * s.vs] - vf);
    return fd;
  }
  // fn(node, dof) for the gripped nodes whose deflection dof is in [d0, d1) and not held.
  template <class Fn>
  void ForEach(const BeamSystem &sys, PetscInt d0, PetscInt d1, Fn fn) const
  {
    for (PetscInt i : nodes_) {
      const PetscInt d = sys.Dof(i);
      if (d >= d0 && d < d1 && !sys.held[d]) fn(i, d);
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
  std::vector<PetscReal>       k(S.nodes, 0.0), c(S.nodes, 0.0);
  for (PetscInt i = 0; i < S.nodes; ++i) {
    const PetscInt d = S.Dof(i);
    if (S.held[d] || w[i] == 0.0) continue;
    k[i] = p.grip.stiffness * w[i];
    c[i] = p.grip.damping * w[i];
    S.mass[d] += p.grip.mass * w[i] / span; // the hands
  }
  return std::make_shared<GripTerm>(std::move(k), std::move(c));
}

} // namespace beamimpact

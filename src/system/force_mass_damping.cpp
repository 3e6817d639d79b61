// Force term "mass-damping": the mass part of Rayleigh damping, a drag on every dof in
// proportion to its mass,
//
//   f_d = alpha m_d v_d   (N),   P = alpha sum_d m_d v_d^2 >= 0   (W),
//
// alpha = -beam_damping_mass (1/s). It damps the rigid motion too (against the ground, not the
// swing's frame), so along the frame's velocity v_f its force integrates in closed form to
// alpha v_f^T M y (FrameImpulse: the hands' work, ForceOperatorFrameMomentum).
#include "system/beam_system.hpp"

namespace beamimpact {

namespace {

class MassDampingTerm : public ForceTerm {
public:
  explicit MassDampingTerm(PetscReal alpha) : alpha_(alpha) { }
  const char *Name() const override { return "mass-damping"; }
  bool        Damps() const override { return true; }

  void AddForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                PetscInt fs) const override
  {
    AddDampingForce(sys, s, d0, d1, f, fs);
  }
  void AddDampingForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                       PetscInt fs) const override
  {
    const PetscInt F = sys.fields;
    if (!s.v) return;
    for (PetscInt d = d0; d < d1; ++d) f[(d / F) * fs + d % F] += alpha_ * sys.mass[d] * s.v[(d / F) * s.vs + d % F];
  }
  void AddJacobian(const BeamSystem &sys, PetscReal *, PetscReal *, PetscReal *Cdiag) const override
  {
    for (PetscInt d = 0; d < sys.ndof; ++d) Cdiag[d] += alpha_ * sys.mass[d];
  }
  PetscReal DissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    return s.v ? 2 * alpha_ * BeamSystemKineticEnergy(sys, s.v, s.vs, d0, d1) : 0.0;
  }
  PetscReal FrameImpulse(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    const PetscInt F = sys.fields;
    PetscReal      G = 0.0;
    if (!s.frame || !s.frame->Moves()) return G;
    for (PetscInt d = d0; d < d1; ++d) G += s.frame->v[d] * sys.mass[d] * s.y[(d / F) * s.ys + d % F];
    return alpha_ * G;
  }
  DampingScales Scales(const BeamSystem &) const override
  {
    DampingScales s;
    s.mass_rate = alpha_;
    return s;
  }
  bool Modal(PetscReal *alpha, PetscReal *, std::string *) const override
  {
    *alpha += alpha_;
    return true;
  }

private:
  PetscReal alpha_; // 1/s
};

} // namespace

std::shared_ptr<const ForceTerm> MassDampingTermCreate(const BeamParams &p, BeamSystem *)
{
  return p.damping_mass > 0 ? std::make_shared<MassDampingTerm>(p.damping_mass) : nullptr;
}

} // namespace beamimpact

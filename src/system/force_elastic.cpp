// Force term "elastic": the beam's strain terms (model/beam_theory.hpp) with their viscous
// (Kelvin-Voigt) part, the stiffness part of Rayleigh damping,
//
//   U = 1/2 sum_k weight_k (b_k . y)^2,   f = B^T W B (y + beta v) = K y + beta K v   (N),
//
// beta = -beam_damping_stiffness (s). The force is formed in the factored form: each strain
// b_k . (y + beta v) first, then spread back, one product for both parts. A rigid motion then
// gives exactly what its strains give (round-off relative to K y, not to |K| |y|), so the
// momenta of a free beam are conserved to round-off; the band form would lose
// eps |K| |y| ~ eps omega_max^2 m |y| per evaluation. The dissipation rate is the same sum of
// squares on the velocities, beta sum_k weight_k (b_k . v)^2 >= 0.
#include "system/beam_system.hpp"

#include <algorithm>

namespace beamimpact {

namespace {

class ElasticTerm : public ForceTerm {
public:
  explicit ElasticTerm(PetscReal beta) : beta_(beta) { }
  const char *Name() const override { return "elastic"; }
  bool        Damps() const override { return beta_ > 0; }

  void AddForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                PetscInt fs) const override
  {
    if (beta_ != 0.0 && s.v) Spread<true, false>(sys, s.y, s.ys, s.v, s.vs, d0, d1, f, fs);
    else Spread<false, false>(sys, s.y, s.ys, nullptr, 0, d0, d1, f, fs);
  }
  void AddDampingForce(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                       PetscInt fs) const override
  {
    if (beta_ != 0.0 && s.v) Spread<false, true>(sys, s.v, s.vs, nullptr, 0, d0, d1, f, fs); // beta K v
  }
  void AddJacobian(const BeamSystem &sys, PetscReal *K, PetscReal *C, PetscReal *) const override
  {
    const PetscInt width = 2 * sys.bw + 1;
    for (const StrainTerm &t : sys.strain)
      for (PetscInt a = 0; a < t.n; ++a) {
        const PetscInt i = t.dof[a];
        if (sys.held[i]) continue;
        for (PetscInt b = 0; b < t.n; ++b) {
          const PetscInt j = t.dof[b];
          if (sys.held[j]) continue;
          const PetscReal kij = t.weight * (t.b[a] * t.b[b]); // symmetric to the bit
          K[(size_t)width * i + (j - i + sys.bw)] += kij;
          if (beta_ != 0.0) C[(size_t)width * i + (j - i + sys.bw)] += beta_ * kij;
        }
      }
  }
  PetscInt  HalfWidth(const BeamSystem &sys) const override { return sys.bw; }
  PetscInt  Reach(const BeamSystem &sys) const override { return 2 * sys.reach; }
  PetscReal Energy(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    return BeamSystemStrainEnergy(sys, s.y, s.ys, d0, d1);
  }
  PetscReal DissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1) const override
  {
    return beta_ != 0.0 && s.v ? 2 * beta_ * BeamSystemStrainEnergy(sys, s.v, s.vs, d0, d1) : 0.0;
  }
  DampingScales Scales(const BeamSystem &) const override
  {
    DampingScales s;
    s.stiffness = beta_;
    return s;
  }
  bool Modal(PetscReal *, PetscReal *beta, std::string *) const override
  {
    *beta += beta_;
    return true;
  }

private:
  PetscReal beta_; // s

  // f_d += B^T W B (y + beta v) for d in [d0, d1) (viscous: with the v part; scaled: beta B^T W B y),
  // reading the strain terms owned within the strain reach of the range.
  template <bool viscous, bool scaled>
  void Spread(const BeamSystem &sys, const PetscReal *y, PetscInt ys, const PetscReal *v, PetscInt vs, PetscInt d0,
              PetscInt d1, PetscReal *f, PetscInt fs) const
  {
    const PetscInt F  = sys.fields;
    auto           yi = [&](PetscInt d) {
      if (F == 1) return viscous ? y[d * ys] + beta_ * v[d * vs] : y[d * ys];
      return viscous ? y[(d / F) * ys + d % F] + beta_ * v[(d / F) * vs + d % F] : y[(d / F) * ys + d % F];
    };
    auto           fi = [&](PetscInt d) { return F == 1 ? f + d * fs : f + (d / F) * fs + d % F; };
    const PetscInt k0 = sys.strain_begin[std::max<PetscInt>(0, d0 - sys.reach)],
                   k1 = sys.strain_begin[std::min<PetscInt>(sys.ndof, d1 + sys.reach)];
    for (PetscInt k = k0; k < k1; ++k) {
      const StrainTerm &t = sys.strain[k];
      PetscReal         e = 0.0;
      for (PetscInt q = 0; q < t.n; ++q) e += t.b[q] * yi(t.dof[q]);
      e *= scaled ? beta_ * t.weight : t.weight;
      for (PetscInt q = 0; q < t.n; ++q)
        if (t.dof[q] >= d0 && t.dof[q] < d1) *fi(t.dof[q]) += t.b[q] * e;
    }
  }
};

} // namespace

std::shared_ptr<const ForceTerm> ElasticTermCreate(const BeamParams &p, BeamSystem *)
{
  return std::make_shared<ElasticTerm>(p.damping_stiffness);
}

} // namespace beamimpact

// The force operator: the registry of force terms and the sums over them. See force_operator.hpp.
#include "system/force_operator.hpp"

#include "system/beam_system.hpp"

#include <algorithm>
#include <cstring>

namespace beamimpact {

// The terms, one file each: the term for these parameters, or nullptr when the beam does not
// have it. (A structure part's terms, the hands', come from its part: StructurePartsFinish.)
std::shared_ptr<const ForceTerm> ElasticTermCreate(const BeamParams &p, BeamSystem *sys);     // force_elastic.cpp
std::shared_ptr<const ForceTerm> MassDampingTermCreate(const BeamParams &p, BeamSystem *sys); // force_mass_damping.cpp

namespace {

using ForceTermCreateFn = std::shared_ptr<const ForceTerm> (*)(const BeamParams &, BeamSystem *);
struct ForceTermEntry {
  const char       *name;
  ForceTermCreateFn create;
};
// The registry: one line per force term, in the order their forces are summed.
const ForceTermEntry kForceTerms[] = {
  {"elastic", ElasticTermCreate},
  {"mass-damping", MassDampingTermCreate},
};

inline PetscReal &At(PetscReal *a, PetscInt d, PetscInt F, PetscInt stride)
{
  return F == 1 ? a[d * stride] : a[(d / F) * stride + d % F];
}

// f = 0 on [d0, d1), then add(term) adds each term's share, then the rows of held dofs are 0.
template <class Add>
void SumOverTerms(const BeamSystem &sys, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt fs, Add add)
{
  const PetscInt F = sys.fields;
  if (F == 1)
    for (PetscInt d = d0; d < d1; ++d) f[d * fs] = 0.0;
  else
    for (PetscInt d = d0; d < d1; ++d) At(f, d, F, fs) = 0.0;
  for (const auto &t : sys.forces.terms) add(*t);
  for (PetscInt d = d0; d < d1; ++d)
    if (sys.held[d]) At(f, d, F, fs) = 0.0;
}

} // namespace

const ForceTerm *ForceOperator::Find(const char *name) const
{
  for (const auto &t : terms)
    if (!std::strcmp(t->Name(), name)) return t.get();
  return nullptr;
}

PetscReal FrameMotionAt(const FrameMotion &frame, const ContactCoupling &g)
{
  PetscReal r = 0.0;
  if (!frame.Moves()) return r;
  for (PetscInt q = 0; q < g.n; ++q) r += g.w[q] * frame.v[g.dof[q]];
  return r;
}

void ForceOperatorCreate(const BeamParams &p, BeamSystem *sys)
{
  sys->forces = ForceOperator();
  for (const ForceTermEntry &e : kForceTerms)
    if (auto t = e.create(p, sys)) sys->forces.terms.push_back(t);
}

void ForceOperatorAssemble(BeamSystem *sys)
{
  BeamSystem    &S  = *sys;
  ForceOperator &op = S.forces;
  for (const auto &t : op.terms) S.bw = std::max(S.bw, t->HalfWidth(S));
  const size_t size = (size_t)(2 * S.bw + 1) * S.ndof;
  S.band.assign(size, 0.0);
  op.damping_band.assign(size, 0.0);
  op.damping_diag.assign(S.ndof, 0.0);
  op.damped = op.framed = false;
  op.reach              = 0;
  for (const auto &t : op.terms) {
    op.reach = std::max(op.reach, t->Reach(S));
    t->AddJacobian(S, S.band.data(), op.damping_band.data(), op.damping_diag.data());
    op.damped = op.damped || t->Damps();
    op.framed = op.framed || t->TiesToFrame();
  }
  const PetscInt width = 2 * S.bw + 1; // leave the held rows and columns out
  for (PetscInt i = 0; i < S.ndof; ++i)
    for (PetscInt o = 0; o < width; ++o) {
      const PetscInt j = i + o - S.bw;
      if (S.held[i] || (j >= 0 && j < S.ndof && S.held[j]))
        S.band[(size_t)width * i + o] = op.damping_band[(size_t)width * i + o] = 0.0;
    }
  for (PetscInt i = 0; i < S.ndof; ++i)
    if (S.held[i]) op.damping_diag[i] = 0.0;
  auto nonzero = [](const std::vector<PetscReal> &a) {
    return std::any_of(a.begin(), a.end(), [](PetscReal x) { return x != 0.0; });
  };
  if (!nonzero(op.damping_band)) op.damping_band.clear();
  if (!nonzero(op.damping_diag)) op.damping_diag.clear();
}

void ForceOperatorApply(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f, PetscInt fs)
{
  SumOverTerms(sys, d0, d1, f, fs, [&](const ForceTerm &t) { t.AddForce(sys, s, d0, d1, f, fs); });
}

void ForceOperatorDampingApply(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *f,
                               PetscInt fs)
{
  SumOverTerms(sys, d0, d1, f, fs, [&](const ForceTerm &t) { t.AddDampingForce(sys, s, d0, d1, f, fs); });
}

void ForceOperatorDrive(const BeamSystem &sys, PetscReal t, const FrameMotion *frame, PetscInt d0, PetscInt d1,
                        PetscReal *f, PetscInt fs)
{
  SumOverTerms(sys, d0, d1, f, fs, [&](const ForceTerm &term) { term.AddDrive(sys, t, frame, d0, d1, f, fs); });
}

void ForceOperatorEnergy(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *elastic,
                         PetscReal *others)
{
  *elastic = *others = 0.0;
  for (const auto &t : sys.forces.terms) {
    if (!std::strcmp(t->Name(), "elastic")) *elastic = t->Energy(sys, s, d0, d1);
    else *others += t->Energy(sys, s, d0, d1);
  }
}

PetscReal ForceOperatorDissipationRate(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1)
{
  PetscReal r = 0.0;
  for (const auto &t : sys.forces.terms)
    if (t->Damps()) r += t->DissipationRate(sys, s, d0, d1);
  return r;
}

void ForceOperatorFrameReaction(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1, PetscReal *force,
                                PetscReal *moment)
{
  for (const auto &t : sys.forces.terms) t->AddFrameReaction(sys, s, d0, d1, force, moment);
}

PetscReal ForceOperatorDrivePower(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1)
{
  PetscReal P = 0.0;
  for (const auto &t : sys.forces.terms) P += t->DrivePower(sys, s, d0, d1);
  return P;
}

bool ForceOperatorDriven(const BeamSystem &sys, const FrameMotion *frame)
{
  return sys.forces.framed && frame && frame->Moves();
}

PetscReal ForceOperatorFrameMomentum(const BeamSystem &sys, const ForceState &s, PetscInt d0, PetscInt d1)
{
  const PetscInt F = sys.fields;
  PetscReal      Q = 0.0;
  if (!ForceOperatorDriven(sys, s.frame)) return Q;
  for (PetscInt d = d0; d < d1; ++d) Q += s.frame->v[d] * sys.mass[d] * s.v[(d / F) * s.vs + d % F];
  for (const auto &t : sys.forces.terms) Q += t->FrameImpulse(sys, s, d0, d1);
  return Q;
}

DampingScales ForceOperatorDampingScales(const BeamSystem &sys)
{
  DampingScales sum;
  for (const auto &t : sys.forces.terms) {
    const DampingScales s = t->Scales(sys);
    sum.mass_rate += s.mass_rate;
    sum.stiffness += s.stiffness;
  }
  return sum;
}

bool ForceOperatorModal(const BeamSystem &sys, PetscReal *alpha, PetscReal *beta, std::string *why)
{
  PetscReal a = 0, b = 0;
  for (const auto &t : sys.forces.terms)
    if (!t->Modal(&a, &b, why)) return false;
  if (alpha) *alpha = a;
  if (beta) *beta = b;
  return true;
}

} // namespace beamimpact

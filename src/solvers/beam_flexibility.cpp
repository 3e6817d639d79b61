// The beam's static flexibility in factored form. See beam_flexibility.hpp.
#include "solvers/beam_flexibility.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

extern "C" void dgbtrf_(const int *m, const int *n, const int *kl, const int *ku, double *ab, const int *ldab,
                        int *ipiv, int *info);
extern "C" void dgbtrs_(const char *trans, const int *n, const int *kl, const int *ku, const int *nrhs,
                        const double *ab, const int *ldab, const int *ipiv, double *b, const int *ldb, int *info);

namespace beamimpact {

std::vector<PetscInt> BeamTemporarySupports(const BeamSystem &sys, const std::vector<PetscInt> &dof,
                                            const std::vector<std::vector<PetscReal>> &R)
{
  const PetscInt                      n = (PetscInt)dof.size();
  std::vector<PetscInt>               sup;
  std::vector<std::vector<PetscReal>> r = R;
  for (size_t i = 0; i < r.size(); ++i) {
    PetscInt  best = -1, any = 0;
    PetscReal rmax = 0;
    for (PetscInt d = 0; d < n; ++d) {
      if (std::abs(r[i][d]) > std::abs(r[i][any])) any = d;
      if (dof[d] % sys.fields == 0 && (best < 0 || std::abs(r[i][d]) > std::abs(r[i][best]))) best = d;
      rmax = std::max(rmax, std::abs(r[i][d]));
    }
    if (best < 0 || std::abs(r[i][best]) <= 1e-12 * rmax) best = any; // a motion no deflection takes: the roll
    sup.push_back(best);
    for (size_t j = i + 1; j < r.size(); ++j) { // eliminate the chosen dof from the later modes
      const PetscReal f = r[j][best] / r[i][best];
      for (PetscInt d = 0; d < n; ++d) r[j][d] -= f * r[i][d];
    }
  }
  return sup;
}

namespace {

bool Refuse(std::string *why, const char *text)
{
  if (why) *why = text;
  return false;
}

// The rigid motions on the free dofs, M-orthonormal (modified Gram-Schmidt in the mass, twice).
std::vector<std::vector<PetscReal>> RigidModesOnFree(const BeamSystem &sys, const BeamFactor &F)
{
  std::vector<std::vector<PetscReal>> R;
  for (const auto &v : BeamSystemRigidMotions(sys)) {
    std::vector<PetscReal> r(F.n);
    for (PetscInt d = 0; d < F.n; ++d) r[d] = v[F.dof[d]];
    for (int pass = 0; pass < 2; ++pass) {
      for (const auto &q : R) {
        PetscReal a = 0;
        for (PetscInt d = 0; d < F.n; ++d) a += q[d] * F.mass[d] * r[d];
        for (PetscInt d = 0; d < F.n; ++d) r[d] -= a * q[d];
      }
      PetscReal nrm = 0;
      for (PetscInt d = 0; d < F.n; ++d) nrm += F.mass[d] * r[d] * r[d];
      nrm = std::sqrt(nrm);
      for (PetscInt d = 0; d < F.n; ++d) r[d] /= nrm;
    }
    R.push_back(r);
  }
  return R;
}

// One nonzero of S = B^T W^{1/2} (row: a free dof that is not a support; column: a strain).
struct SEntry {
  int       r, c;
  PetscReal v;
};

} // namespace

bool BeamFactorCreate(const BeamSystem &sys, BeamFactor *F, std::string *why)
{
  std::vector<PetscInt> free_of(sys.ndof, -1);
  *F = BeamFactor();
  for (PetscInt d = 0; d < sys.ndof; ++d)
    if (!sys.held[d]) {
      free_of[d] = F->n++;
      F->dof.push_back(d);
      F->mass.push_back(sys.mass[d]);
    }
  if (sys.TiedToFrame()) return Refuse(why, "the hands' springs are not strain terms");
  std::vector<SEntry> entries;
  for (const StrainTerm &t : sys.strain) {
    bool touches = false;
    for (PetscInt q = 0; q < t.n; ++q) touches = touches || free_of[t.dof[q]] >= 0;
    if (!touches || t.weight == 0) continue;
    if (!(t.weight > 0)) return Refuse(why, "a strain term of negative weight (a shell)");
    for (PetscInt q = 0; q < t.n; ++q)
      if (free_of[t.dof[q]] >= 0) entries.push_back({(int)free_of[t.dof[q]], F->m, std::sqrt(t.weight) * t.b[q]});
    F->m++;
  }
  F->rigid = RigidModesOnFree(sys, *F);
  if (F->n - F->m != (PetscInt)F->rigid.size()) {
    if (why) {
      char text[200];
      std::snprintf(text, sizeof text, "not statically determinate: %d free dofs, %d strains, %d rigid motions",
                    (int)F->n, F->m, (int)F->rigid.size());
      *why = text;
    }
    return false;
  }
  F->support = BeamTemporarySupports(sys, F->dof, F->rigid);
  F->row.assign(F->n, 0);
  for (PetscInt s : F->support) F->row[s] = -1;
  for (PetscInt d = 0, r = 0; d < F->n; ++d)
    if (F->row[d] >= 0) F->row[d] = r++;
  std::vector<SEntry> S; // the rows of the supports dropped
  for (const SEntry &e : entries)
    if (F->row[e.r] >= 0) {
      S.push_back({(int)F->row[e.r], e.c, e.v});
      F->kl = std::max(F->kl, S.back().r - e.c);
      F->ku = std::max(F->ku, e.c - S.back().r);
    }
  if (F->kl + F->ku > 64) return Refuse(why, "the equilibrium's band is wider than 64");
  const int m = F->m, ldab = 2 * F->kl + F->ku + 1;
  F->lu.assign((size_t)ldab * m, 0.0);
  F->ipiv.assign(m, 0);
  for (const SEntry &e : S) F->lu[(size_t)(F->kl + F->ku + e.r - e.c) + (size_t)e.c * ldab] += e.v;
  int info = 0;
  if (m > 0) dgbtrf_(&m, &m, &F->kl, &F->ku, F->lu.data(), &ldab, F->ipiv.data(), &info);
  if (info != 0) return Refuse(why, "the equilibrium is singular (LAPACK dgbtrf)");
  // How far from singular: the ratio of the smallest pivot to the largest (LAPACK's dgbcon
  // would be the estimate, but its scaled triangular solves are O(m^2) on a band this long).
  double umin = m > 0 ? std::abs(F->lu[(size_t)(F->kl + F->ku)]) : 1.0, umax = umin;
  for (int i = 0; i < m; ++i) {
    const double u = std::abs(F->lu[(size_t)(F->kl + F->ku) + (size_t)i * ldab]);
    umin = std::min(umin, u), umax = std::max(umax, u);
  }
  F->rcond = umax > 0 ? umin / umax : 0.0;
  if (!(F->rcond > 100 * std::numeric_limits<double>::epsilon()))
    return Refuse(why, "the equilibrium is conditioned beyond double precision");
  return true;
}

void BeamFactorFlexibility(const BeamFactor &F, const PetscReal *f, PetscReal *u, PetscReal *G)
{
  const int              m = F.m, ldab = 2 * F.kl + F.ku + 1, one = 1;
  std::vector<PetscReal> load(f, f + F.n), x(m);
  int                    info;
  for (const auto &r : F.rigid) { // less its rigid-body inertia: f - M R R^T f
    PetscReal a = 0;
    for (PetscInt d = 0; d < F.n; ++d) a += r[d] * f[d];
    for (PetscInt d = 0; d < F.n; ++d) load[d] -= F.mass[d] * r[d] * a;
  }
  for (PetscInt d = 0; d < F.n; ++d)
    if (F.row[d] >= 0) x[F.row[d]] = load[d];
  if (m > 0)
    dgbtrs_("N", &m, &F.kl, &F.ku, &one, F.lu.data(), &ldab, F.ipiv.data(), x.data(), &m,
            &info); // equilibrium: S m' = f
  if (G) {
    PetscReal g = 0;
    for (PetscReal v : x) g += v * v;
    *G = g;
  }
  if (!u) return;
  if (m > 0)
    dgbtrs_("T", &m, &F.kl, &F.ku, &one, F.lu.data(), &ldab, F.ipiv.data(), x.data(), &m,
            &info); // compatibility: S^T u = m'
  for (PetscInt d = 0; d < F.n; ++d) u[d] = F.row[d] >= 0 ? x[F.row[d]] : 0.0;
  for (const auto &r : F.rigid) { // M-orthogonal to the rigid modes
    PetscReal a = 0;
    for (PetscInt d = 0; d < F.n; ++d) a += r[d] * F.mass[d] * u[d];
    for (PetscInt d = 0; d < F.n; ++d) u[d] -= r[d] * a;
  }
}

} // namespace beamimpact

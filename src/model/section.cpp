// Section properties along the beam. See section.hpp.
#include "model/section.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

const char *SectionSourceName(SectionSource s)
{
  switch (s) {
  case SectionSource::Profile:
    return "profile";
  case SectionSource::Table:
    return "table";
  default:
    return "uniform";
  }
}

PetscReal RoundArea(PetscReal D, PetscReal d) { return M_PI * (D * D - d * d) / 4.0; }
PetscReal RoundSecondMoment(PetscReal D, PetscReal d) { return M_PI * (D * D * D * D - d * d * d * d) / 64.0; }

PetscReal CowperRound(PetscReal nu, PetscReal m)
{
  const PetscReal q = (1 + m * m) * (1 + m * m);
  return 6 * (1 + nu) * q / ((7 + 6 * nu) * q + (20 + 12 * nu) * m * m);
}

PetscReal CowperRectangle(PetscReal nu) { return 10 * (1 + nu) / (12 + 11 * nu); }

// Index j of the row interval [x_j, x_{j+1}] holding x, and the fraction t in it.
template <class Row>
static void Locate(const std::vector<Row> &rows, PetscReal x, size_t *j, PetscReal *t)
{
  const size_t n = rows.size();
  if (n == 1 || x <= rows.front().x) {
    *j = 0, *t = 0;
    return;
  }
  if (x >= rows.back().x) {
    *j = n - 2, *t = 1;
    return;
  }
  const auto it = std::upper_bound(rows.begin(), rows.end(), x, [](PetscReal v, const Row &r) { return v < r.x; });
  *j            = (size_t)(it - rows.begin()) - 1;
  *t            = (x - rows[*j].x) / (rows[*j + 1].x - rows[*j].x);
}

static SectionProperties RoundProperties(const SectionMaterial &m, PetscReal D, PetscReal d)
{
  SectionProperties p;
  const PetscReal   A = RoundArea(D, d), I = RoundSecondMoment(D, d);
  p.EI              = m.E * I;
  p.mu              = m.rho * A;
  p.rhoI            = m.rho * I;
  const PetscReal k = m.kappa > 0 ? m.kappa : CowperRound(m.nu, d / D);
  p.kGA             = k * m.G * A;
  const PetscReal G = m.G > 0 ? m.G : m.E / (2 * (1 + m.nu)); // the twist's: an isotropic wall's G when none is given
  p.GJ              = G * 2 * I;
  p.rhoJ            = m.rho * 2 * I;
  return p;
}

SectionProperties SectionAt(const BeamSection &s, PetscReal x)
{
  size_t    j;
  PetscReal t;
  if (s.source == SectionSource::Profile) {
    Locate(s.profile, x, &j, &t);
    const ProfileRow &a = s.profile[j], &b = s.profile[std::min(j + 1, s.profile.size() - 1)];
    return RoundProperties(s.material, (1 - t) * a.D + t * b.D, (1 - t) * a.d + t * b.d);
  }
  Locate(s.table, x, &j, &t);
  const SectionProperties &a = s.table[j].s, &b = s.table[std::min(j + 1, s.table.size() - 1)].s;
  SectionProperties        p;
  p.EI   = (1 - t) * a.EI + t * b.EI;
  p.mu   = (1 - t) * a.mu + t * b.mu;
  p.kGA  = (1 - t) * a.kGA + t * b.kGA;
  p.rhoI = (1 - t) * a.rhoI + t * b.rhoI;
  p.GJ   = (1 - t) * a.GJ + t * b.GJ;
  p.rhoJ = (1 - t) * a.rhoJ + t * b.rhoJ;
  return p;
}

// 3-point Gauss on each piece of [a, b] between rows: f(x, properties at x, weight).
template <class F>
static void SectionQuadrature(const BeamSection &s, PetscReal a, PetscReal b, F f)
{
  std::vector<PetscReal> cuts{a};
  auto                   add_knot = [&](PetscReal x) {
    if (x > a && x < b) cuts.push_back(x);
  };
  if (s.source == SectionSource::Profile)
    for (const ProfileRow &r : s.profile) add_knot(r.x);
  else
    for (const PropertiesRow &r : s.table) add_knot(r.x);
  cuts.push_back(b);
  static const PetscReal gx[3] = {-0.7745966692414834, 0.0, 0.7745966692414834},
                         gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  for (size_t j = 0; j + 1 < cuts.size(); ++j) {
    const PetscReal c = 0.5 * (cuts[j] + cuts[j + 1]), r = 0.5 * (cuts[j + 1] - cuts[j]);
    for (int g = 0; g < 3; ++g) f(c + r * gx[g], SectionAt(s, c + r * gx[g]), r * gw[g]);
  }
}

SectionProperties SectionIntegral(const BeamSection &s, PetscReal a, PetscReal b)
{
  SectionProperties sum;
  SectionQuadrature(s, a, b, [&](PetscReal, const SectionProperties &q, PetscReal w) {
    sum.EI += w * q.EI, sum.mu += w * q.mu, sum.kGA += w * q.kGA, sum.rhoI += w * q.rhoI, sum.GJ += w * q.GJ,
      sum.rhoJ += w * q.rhoJ;
  });
  return sum;
}

SectionMoments SectionMomentsOf(const BeamSection &s, PetscReal a, PetscReal b)
{
  SectionMoments m;
  SectionQuadrature(s, a, b, [&](PetscReal x, const SectionProperties &q, PetscReal w) {
    m.m0 += w * q.mu, m.m1 += w * q.mu * x, m.m2 += w * q.mu * x * x, m.j += w * q.rhoI, m.roll += w * q.rhoJ;
  });
  return m;
}

PetscReal SectionLength(const BeamSection &s)
{
  if (s.source == SectionSource::Profile) return s.profile.back().x - s.profile.front().x;
  if (s.source == SectionSource::Table) return s.table.back().x - s.table.front().x;
  return 0;
}

} // namespace beamimpact

// The barrel wall as a thin cylindrical shell appended to a theory's discretization. See shell.hpp.
#include "model/shell.hpp"

#include "model/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

extern "C" void dsbevx_(const char *jobz, const char *range, const char *uplo, const int *n, const int *kd, double *ab,
                        const int *ldab, double *q, const int *ldq, const double *vl, const double *vu, const int *il,
                        const int *iu, const double *abstol, int *m, double *w, double *z, const int *ldz, double *work,
                        int *iwork, int *ifail, int *info);

namespace beamimpact {

bool ShellWallAt(const BeamParams &p, PetscReal x, PetscReal *R, PetscReal *t)
{
  const std::vector<ProfileRow> &rows = p.section.profile;
  *R = *t = 0;
  if (p.section.source != SectionSource::Profile || rows.empty()) return false;
  const PetscReal xs = std::min(std::max(x + rows.front().x, rows.front().x),
                                rows.back().x); // the beam's x = 0 is the first row
  size_t          k  = 0;
  while (k + 2 < rows.size() && rows[k + 1].x < xs) ++k;
  const ProfileRow &a = rows[k], &b = rows[std::min(k + 1, rows.size() - 1)];
  const PetscReal   s = b.x > a.x ? (xs - a.x) / (b.x - a.x) : 0.0;
  const PetscReal   D = a.D + s * (b.D - a.D), d = a.d + s * (b.d - a.d);
  if (!(d > 0)) return false;
  *R = (D + d) / 4;
  *t = (D - d) / 2;
  return true;
}

bool ShellBarrelWall(const BeamParams &p, PetscReal *R, PetscReal *t)
{
  const std::vector<ProfileRow> &rows = p.section.profile;
  PetscReal                      D    = 0;
  bool                           any  = false;
  *R = *t = 0;
  if (p.section.source != SectionSource::Profile) return false;
  for (const ProfileRow &r : rows) D = std::max(D, r.D);
  for (const ProfileRow &r : rows) {
    if (r.D < D * (1 - 1e-9) || !(r.d > 0)) continue;
    const PetscReal Rr = (r.D + r.d) / 4, tr = (r.D - r.d) / 2;
    if (!any || tr / Rr > *t / *R) *R = Rr, *t = tr;
    any = true;
  }
  return any;
}

PetscReal ShellRadiusAt(const BeamParams &p, PetscReal x)
{
  PetscReal R, t;
  if (ShellWallAt(p, x, &R, &t) || ShellBarrelWall(p, &R, &t)) return R;
  return 0;
}

PetscReal ShellYoungsModulus(const BarrelShell &shell, const BeamParams &p)
{
  return shell.youngs_modulus > 0 ? shell.youngs_modulus : p.section.material.E;
}

PetscReal RayleighRingFrequency(PetscReal E, PetscReal rho, PetscReal nu, PetscReal R, PetscReal t, PetscInt n)
{
  const PetscReal n2 = (PetscReal)(n * n);
  return std::sqrt(E * t * t * n2 * (n2 - 1) * (n2 - 1) / (12 * rho * (1 - nu * nu) * std::pow(R, 4) * (n2 + 1))) /
         (2 * PETSC_PI);
}

namespace {

StrainTerm Term(PetscInt owner, PetscReal weight, std::initializer_list<std::pair<PetscInt, PetscReal>> entries)
{
  StrainTerm t;
  t.owner  = owner;
  t.weight = weight;
  for (const auto &e : entries)
    if (e.second != 0.0) t.dof[t.n] = e.first, t.b[t.n++] = e.second;
  return t;
}

// The wall of each cell: hollow, R, t (m) at its midpoint.
struct ShellCells {
  std::vector<char>      hollow;
  std::vector<PetscReal> R, t;
};

ShellCells CellsOf(const BeamParams &p)
{
  const PetscInt  N = p.nodes;
  const PetscReal h = p.length / (N - 1);
  ShellCells      c;
  c.hollow.assign(N - 1, 0), c.R.assign(N - 1, 0), c.t.assign(N - 1, 0);
  for (PetscInt k = 0; k < N - 1; ++k) c.hollow[k] = ShellWallAt(p, (k + 0.5) * h, &c.R[k], &c.t[k]);
  return c;
}

} // namespace

namespace {

// What the shell's two loops read: the grid, the wall's material and cells, the dof numbering.
struct ShellGrid {
  PetscInt              F = 0, N = 0, G = 0, nh = 0;   // the fields before, nodes, fields after, harmonics
  PetscInt              first = 0;                     // the shell's first field
  PetscReal             h = 0, E = 0, rho = 0, nu = 0; // m, Pa, kg/m^3, 1
  ShellCells            c;
  std::vector<PetscInt> harmonics;
  PetscInt  Dof(PetscInt node, size_t k, PetscInt comp) const { return node * G + first + 3 * (PetscInt)k + comp; }
  PetscReal Cm(PetscInt k) const { return E * c.t[k] / (1 - nu * nu); }                     // N/m
  PetscReal Bb(PetscInt k) const { return E * std::pow(c.t[k], 3) / (12 * (1 - nu * nu)); } // N m
};

// Each node's wall dofs: mass, held, and the bending terms (kx, and the mirror at held ends).
void ShellAppendNodes(const ShellGrid &s, const std::vector<NodeHold> &hold, BeamDiscretization *d)
{
  const PetscInt          F = s.F, N = s.N, G = s.G, nh = s.nh;
  const PetscReal         h = s.h, rho = s.rho, nu = s.nu;
  const ShellCells       &c        = s.c;
  const auto              renumber = [&](PetscInt dof) { return (dof / F) * G + dof % F; };
  const auto              dof      = [&](PetscInt node, size_t k, PetscInt comp) { return s.Dof(node, k, comp); };
  const auto              Bb       = [&](PetscInt k) { return s.Bb(k); };
  std::vector<PetscReal> &mass     = d->mass;
  std::vector<char>      &held     = d->held;
  std::vector<char>       wall_held(N);
  for (PetscInt i = 0; i < N; ++i) {
    const bool left = i > 0 && c.hollow[i - 1], right = i < N - 1 && c.hollow[i];
    wall_held[i] = !(left || right) || ((left != right) && i > 0 && i < N - 1) || HoldsDeflection(hold[i]);
  }
  for (PetscInt i = 0; i < N; ++i) {
    const bool left = i > 0 && c.hollow[i - 1], right = i < N - 1 && c.hollow[i], wall = left || right;
    const bool junction = wall && !(left && right) && i > 0 &&
                          i < N - 1; // a hollow part meets a solid one: clamped-like
    const bool wheld = wall_held[i], mirror = wall && (junction || HoldsRotation(hold[i]));
    PetscReal  m = 0, PB = 0, Rn = 0, len = 0; // the node's half cells: mass, pi R B h, mean R
    for (PetscInt k : {i - 1, i}) {
      if (k < 0 || k >= N - 1 || !c.hollow[k]) continue;
      m += PETSC_PI * c.R[k] * rho * c.t[k] * h / 2;
      PB += PETSC_PI * c.R[k] * Bb(k) * h / 2;
      Rn += c.R[k] * h / 2, len += h / 2;
    }
    for (size_t k = 0; k < (size_t)nh; ++k) {
      const PetscReal n = (PetscReal)s.harmonics[k];
      for (PetscInt comp = 0; comp < 3; ++comp) {
        mass[dof(i, k, comp)] = wall ? m : mass[renumber(i * F)]; // a held dof's mass is never used
        held[dof(i, k, comp)] = wheld;
      }
      if (!wall) continue;
      if (wheld) { // W' = 0 across a held rotation or a junction: the mirror kx = -2 (W_j - W_i)/h^2 toward each hollow
                   // side
        if (!mirror) continue;
        for (PetscInt j : {i - 1, i + 1}) {
          const PetscInt cell = std::min(i, j);
          if (j < 0 || j >= N || !c.hollow[cell] || wall_held[j]) continue;
          d->strain.push_back(
            Term(dof(i, k, 2), PETSC_PI * c.R[cell] * Bb(cell) * h / 2, {{dof(j, k, 2), -2 / (h * h)}}));
        }
        continue;
      }
      const PetscReal R = Rn / len, kv = n / (R * R), kw = n * n / (R * R); // kt = kv V + kw W
      if (left && right) // kx = -W'': the moment (kx + nu kt) and (1 - nu^2) kt^2
        d->strain.push_back(Term(dof(i, k, 2), PB,
                                 {{dof(i - 1, k, 2), -1 / (h * h)},
                                  {dof(i, k, 2), 2 / (h * h) + nu * kw},
                                  {dof(i + 1, k, 2), -1 / (h * h)},
                                  {dof(i, k, 1), nu * kv}}));
      d->strain.push_back(
        Term(dof(i, k, 2), PB * (1 - nu * nu),
             {{dof(i, k, 1), kv}, {dof(i, k, 2), kw}})); // alone at a free end: M_x = 0, kx + nu kt = 0
    }
  }
}

// Each hollow cell's membrane and twist terms, at its midpoint.
void ShellAppendCells(const ShellGrid &s, BeamDiscretization *d)
{
  const PetscInt    N = s.N, nh = s.nh;
  const PetscReal   h = s.h, nu = s.nu;
  const ShellCells &c   = s.c;
  const auto        dof = [&](PetscInt node, size_t k, PetscInt comp) { return s.Dof(node, k, comp); };
  const auto        Cm  = [&](PetscInt k) { return s.Cm(k); };
  const auto        Bb  = [&](PetscInt k) { return s.Bb(k); };
  for (PetscInt cell = 0; cell < N - 1; ++cell) { // membrane and twist at the midpoint
    if (!c.hollow[cell]) continue;
    const PetscInt  a = cell, b = cell + 1;
    const PetscReal R = c.R[cell], w = PETSC_PI * R * h, ih = 1 / h;
    for (size_t k = 0; k < (size_t)nh; ++k) {
      const PetscReal n = (PetscReal)s.harmonics[k], C = Cm(cell), B = Bb(cell);
      const PetscInt  Ua = dof(a, k, 0), Ub = dof(b, k, 0), Va = dof(a, k, 1), Vb = dof(b, k, 1), Wa = dof(a, k, 2),
                     Wb    = dof(b, k, 2);
      const PetscReal et_v = n / (2 * R), et_w = 1 / (2 * R); // et = (n V + W)/R at the midpoint
      d->strain.push_back(
        Term(Wa, w * C,
             {{Ua, -ih}, {Ub, ih}, {Va, nu * et_v}, {Vb, nu * et_v}, {Wa, nu * et_w}, {Wb, nu * et_w}})); // ex + nu et
      d->strain.push_back(Term(Wa, w * C * (1 - nu * nu), {{Va, et_v}, {Vb, et_v}, {Wa, et_w}, {Wb, et_w}})); // et
      d->strain.push_back(Term(Wa, w * C * (1 - nu) / 2,
                               {{Va, -ih}, {Vb, ih}, {Ua, -n / (2 * R)}, {Ub, -n / (2 * R)}})); // g = V' - n U/R
      d->strain.push_back(Term(Wa, w * 2 * (1 - nu) * B,
                               {{Wa, -n * ih / R},
                                {Wb, n * ih / R},
                                {Va, -0.75 * ih / R},
                                {Vb, 0.75 * ih / R},
                                {Ua, n / (8 * R * R)},
                                {Ub, n / (8 * R * R)}})); // tw
    }
  }
}

} // namespace

ShellLayout ShellAppend(const BarrelShell &shell, const BeamParams &p, BeamDiscretization *d)
{
  ShellGrid s;
  s.F = d->fields, s.N = p.nodes, s.nh = (PetscInt)shell.harmonics.size(), s.G = s.F + 3 * s.nh;
  s.h = p.length / (s.N - 1), s.E = ShellYoungsModulus(shell, p), s.rho = p.section.material.rho;
  s.nu = p.section.material.nu, s.c = CellsOf(p), s.first = s.F, s.harmonics = shell.harmonics;
  const std::vector<NodeHold> hold = BeamNodeHolds(p);
  ShellLayout                 out;
  out.first     = s.first;
  out.harmonics = shell.harmonics;
  BeamDiscretizationWiden(d, s.G, 0.0); // every new dof's mass is set below
  ShellAppendNodes(s, hold, d);
  ShellAppendCells(s, d);
  return out;
}

} // namespace beamimpact

namespace beamimpact {

PetscReal ShellPatchHarmonicWeight(PetscInt n, PetscReal a, PetscReal R)
{
  const PetscReal phi = R > 0 ? std::min(a / R, PETSC_PI) : 0.0; // the patch's half-angle
  const PetscReal z   = (PetscReal)n * phi;
  return z > 0 ? std::sin(z) / z : 1.0;
}

std::vector<std::pair<PetscInt, PetscReal>> ShellPatchNodeWeights(PetscInt nodes, PetscReal L, PetscReal x_c,
                                                                  PetscReal a)
{
  std::vector<std::pair<PetscInt, PetscReal>> w;
  const ImpactStencil                         st = GridImpactStencil(nodes, L, x_c);
  if (!(a > 0)) return {{st.j, st.w}, {st.j + 1, 1.0 - st.w}}; // the point load
  const PetscReal h  = L / (nodes - 1);
  const PetscReal x0 = std::max<PetscReal>(0, x_c - a), x1 = std::min(L, x_c + a);
  const PetscInt  i0         = std::max<PetscInt>(0, (PetscInt)std::floor(x0 / h)),
                 i1          = std::min<PetscInt>(nodes - 1, (PetscInt)std::ceil(x1 / h));
  std::vector<PetscReal> cut = {x0, x1}; // the pieces where N_i p is one quadratic
  if (x_c > x0 && x_c < x1) cut.push_back(x_c);
  for (PetscInt i = i0; i <= i1; ++i)
    if (i * h > x0 && i * h < x1) cut.push_back(i * h);
  std::sort(cut.begin(), cut.end());
  auto      p   = [&](PetscReal x) { return std::max<PetscReal>(0, a - std::abs(x - x_c)) / (a * a); };
  auto      hat = [&](PetscInt i, PetscReal x) { return std::max<PetscReal>(0, 1 - std::abs(x - i * h) / h); };
  PetscReal sum = 0;
  for (PetscInt i = i0; i <= i1; ++i) {
    PetscReal wi = 0;
    for (size_t k = 0; k + 1 < cut.size(); ++k) {
      const PetscReal l = cut[k], r = cut[k + 1], m = (l + r) / 2;
      wi += (r - l) / 6 * (hat(i, l) * p(l) + 4 * hat(i, m) * p(m) + hat(i, r) * p(r));
    }
    if (wi > 0) w.push_back({i, wi}), sum += wi;
  }
  for (auto &e : w) e.second /= sum; // the whole load on the wall where the patch passes an end
  return w;
}

PetscReal ShellContactRadiusDefault(const BallParams &b, PetscReal v)
{
  if (!(b.radius > 0) || !(v > 0)) return 0.0;
  return std::sqrt(b.radius * ContactWallMaxCompression(b, v));
}

} // namespace beamimpact

namespace beamimpact {

PetscReal ShellLowestFrequency(const BarrelShell &shell, const BeamParams &p, PetscInt n)
{
  const PetscReal nan = std::numeric_limits<PetscReal>::quiet_NaN();
  BarrelShell     q   = shell;
  q.harmonics         = {n};
  BeamDiscretization d; // a placeholder field per node, held: the harmonic's fields alone
  d.fields = 1;
  d.mass.assign(p.nodes, 1.0);
  d.held.assign(p.nodes, 1);
  ShellAppend(q, p, &d);
  std::vector<PetscInt> index(d.mass.size(), -1);
  PetscInt              size = 0;
  for (size_t i = 0; i < d.mass.size(); ++i)
    if (!d.held[i]) index[i] = size++;
  if (size == 0) return nan;
  int kd = 0; // the band of K over the free dofs (node-major: a few nodes' fields)
  for (const StrainTerm &t : d.strain)
    for (PetscInt a = 0; a < t.n; ++a)
      for (PetscInt b = 0; b < t.n; ++b)
        if (index[t.dof[a]] >= 0 && index[t.dof[b]] >= 0)
          kd = std::max(kd, (int)std::abs(index[t.dof[a]] - index[t.dof[b]]));
  const int           ldab = kd + 1, nn = (int)size;
  std::vector<double> ab((size_t)ldab * nn, 0.0), scale(nn); // lower band: ab[(i - j) + j ldab] = A(i, j), i >= j
  for (size_t i = 0; i < d.mass.size(); ++i)
    if (index[i] >= 0) scale[index[i]] = 1 / std::sqrt(d.mass[i]);
  for (const StrainTerm &t : d.strain)
    for (PetscInt a = 0; a < t.n; ++a)
      for (PetscInt b = 0; b < t.n; ++b) {
        const PetscInt i = index[t.dof[a]], j = index[t.dof[b]];
        if (i >= 0 && j >= i)
          ab[(size_t)(j - i) + (size_t)i * ldab] += t.weight * t.b[a] * t.b[b] * scale[i] * scale[j];
      }
  int                 il = 1, iu = 1, found = 0, info = 0, ldq = 1, ldz = 1;
  double              vl = 0, vu = 0, abstol = 0, qd = 0, z = 0;
  std::vector<double> work(7 * (size_t)nn), lam(nn);
  std::vector<int>    iwork(5 * (size_t)nn), ifail(nn);
  dsbevx_("N", "I", "L", &nn, &kd, ab.data(), &ldab, &qd, &ldq, &vl, &vu, &il, &iu, &abstol, &found, lam.data(), &z,
          &ldz, work.data(), iwork.data(), ifail.data(), &info);
  if (info != 0 || found < 1 || !(lam[0] >= 0)) return nan;
  return std::sqrt(lam[0]) / (2 * PETSC_PI);
}

} // namespace beamimpact

// The string bed's stiffness rows. See string_bed_operator.hpp.
#include "system/string_bed_operator.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace beamimpact {

namespace {
// The arms of node (i, j): the neighbour's indices, the grid step and whether it is an x arm.
struct Arm {
  PetscInt di, dj;
};
const Arm kArms[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// The length of arm dir of the inside node (i, j): h when the neighbour is inside, else the
// distance to the outline along it (<= h).
PetscReal ArmLength(const BedGrid &g, PetscInt i, PetscInt j, int dir, bool *cut)
{
  const PetscInt  in = i + kArms[dir].di, jn = j + kArms[dir].dj;
  const PetscReal h = dir < 2 ? g.hx : g.hz;
  *cut              = !(in > 0 && in < g.nx - 1 && jn > 0 && jn < g.nz - 1 && BedInside(g, g.X(in), g.Z(jn)));
  if (!*cut) return h;
  return std::min(h, BedEdgeDistance(g, g.X(i), g.Z(j), dir));
}
} // namespace

PetscReal BedArmLength(const BedGrid &g, PetscInt i, PetscInt j, int dir)
{
  bool cut;
  return ArmLength(g, i, j, dir, &cut);
}

bool BedNodeFree(const BedGrid &g, PetscInt i, PetscInt j)
{
  if (i <= 0 || i >= g.nx - 1 || j <= 0 || j >= g.nz - 1 || !BedInside(g, g.X(i), g.Z(j))) return false;
  for (int dir = 0; dir < 4; ++dir) {
    bool            cut;
    const PetscReal l = ArmLength(g, i, j, dir, &cut);
    const PetscReal h = dir < 2 ? g.hx : g.hz;
    if (cut && l < h * h / (2 * (dir < 2 ? g.a : g.b))) return false; // Gibou et al.'s rule: on the edge
  }
  return true;
}

BedRow BedStiffnessRow(const BedGrid &g, const Membrane &m, PetscInt i, PetscInt j)
{
  BedRow r;
  if (!BedNodeFree(g, i, j)) return r;
  r.held = false;
  r.mass = m.sigma * BedCellArea(g, i, j);
  for (int dir = 0; dir < 4; ++dir) {
    bool            cut;
    const PetscReal l = ArmLength(g, i, j, dir, &cut);
    PetscReal       c = dir < 2 ? m.N_x * g.hz / l : m.N_z * g.hx / l;
    // a neighbour that is inside but held by the d_min rule is an edge at distance h
    if (!cut && !BedNodeFree(g, i + kArms[dir].di, j + kArms[dir].dj)) cut = true;
    r.diag += c;
    if (!cut) r.off[dir] = -c;
  }
  return r;
}

namespace {

// Adds the disc of radius a (m) about node (ic, jc), its weights 1 - r^2/a^2 normalised and
// scaled by share, to *w (keyed by node). The node alone when the disc covers no other (a < h).
// The offsets are taken from the centre node ((i - ic) h_x, (j - jc) h_z), so the disc is
// symmetric about it to the last bit and its first moments are those of the node.
void BedDiscAdd(const BedGrid &g, PetscInt ic, PetscInt jc, PetscReal a, PetscReal share,
                std::map<std::pair<PetscInt, PetscInt>, PetscReal> *w)
{
  const PetscInt ri = a > 0 ? (PetscInt)std::ceil(a / g.hx) : 0, rj = a > 0 ? (PetscInt)std::ceil(a / g.hz) : 0;
  std::vector<std::pair<std::pair<PetscInt, PetscInt>, PetscReal>> disc;
  PetscReal                                                        sum = 0;
  for (PetscInt di = -ri; di <= ri; ++di)
    for (PetscInt dj = -rj; dj <= rj; ++dj) {
      const PetscReal dx = di * g.hx, dz = dj * g.hz, r2 = di == 0 && dj == 0 ? 0.0 : (dx * dx + dz * dz) / (a * a);
      if (r2 >= 1) continue;
      disc.push_back({{ic + di, jc + dj}, 1 - r2});
      sum += 1 - r2;
    }
  for (const auto &e : disc) (*w)[e.first] += share * e.second / sum;
}

// The cell coordinate s of a point (s = (x - x_0)/h): its lower node and the fraction t in [0, 1)
// beyond it; a point within 1e-9 of a node is on it (t = 0), as the beam's hat
// (GridImpactStencil).
PetscInt CellOf(PetscReal s, PetscReal *t)
{
  const PetscReal sr = std::round(s);
  if (std::abs(s - sr) < 1e-9) return *t = 0.0, (PetscInt)sr;
  const PetscReal sf = std::floor(s);
  *t                 = s - sf;
  return (PetscInt)sf;
}

} // namespace

std::vector<BedPatchNode> BedPatch(const BedGrid &g, PetscReal x, PetscReal z, PetscReal a)
{
  PetscReal      tx, tz;
  const PetscInt i = CellOf((x - g.x0) / g.hx, &tx), j = CellOf((z + g.b) / g.hz, &tz);
  // the bilinear hat weights of the point on its cell's four corners, each spreading its share
  // over the disc about it
  std::map<std::pair<PetscInt, PetscInt>, PetscReal> w;
  const PetscReal                                    wx[2] = {1 - tx, tx}, wz[2] = {1 - tz, tz};
  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2; ++q)
      if (wx[p] * wz[q] != 0.0) BedDiscAdd(g, i + p, j + q, a, wx[p] * wz[q], &w);
  std::vector<BedPatchNode> out;
  for (const auto &e : w) {
    BedPatchNode n;
    n.i = e.first.first, n.j = e.first.second, n.w = e.second;
    n.beyond = n.i < 0 || n.i >= g.nx;
    n.free   = !n.beyond && BedNodeFree(g, n.i, n.j);
    out.push_back(n);
  }
  return out;
}

BedLayout StringBedAppend(const StringBedParams &p, const BedGrid &g, PetscInt phi_field, BeamDiscretization *d)
{
  const Membrane m = StringBedMembrane(p);
  const PetscInt F = d->fields, N = g.nx, G = F + g.nz;
  BedLayout      out;
  out.first = F;
  out.grid  = g;
  out.roll  = phi_field;
  BeamDiscretizationWiden(d, G, m.sigma * g.hx * g.hz);
  const auto w   = [&](PetscInt i, PetscInt j) { return i * G + F + j; };
  const auto y   = [&](PetscInt i) { return i * G; };
  const auto phi = [&](PetscInt i) { return i * G + phi_field; };
  // a term over (dof, b) entries, the roll's entries left out without a roll field or when 0
  const auto term = [&](PetscInt owner, PetscReal weight, std::initializer_list<std::pair<PetscInt, PetscReal>> e,
                        std::initializer_list<std::pair<PetscInt, PetscReal>> roll) {
    StrainTerm t;
    t.owner = owner, t.weight = weight;
    for (const auto &q : e) t.dof[t.n] = q.first, t.b[t.n++] = q.second;
    if (phi_field >= 0)
      for (const auto &q : roll)
        if (q.second != 0.0) t.dof[t.n] = q.first, t.b[t.n++] = q.second;
    d->strain.push_back(t);
  };
  for (PetscInt i = 0; i < N; ++i)
    for (PetscInt j = 0; j < g.nz; ++j) {
      const PetscReal area = BedCellArea(g, i, j), z = g.Z(j);
      if (!BedNodeFree(g, i, j)) { // in the head but not an unknown: its strings' mass moves with the frame
        if (area > 0) {
          d->mass[y(i)] += m.sigma * area;
          if (phi_field >= 0) d->mass[phi(i)] += m.sigma * area * z * z;
        }
        continue;
      }
      d->held[w(i, j)] = 0;
      d->mass[w(i, j)] = m.sigma * area;
      const BedRow r   = BedStiffnessRow(g, m, i, j);
      for (int dir = 0; dir < 4; ++dir) {
        const PetscReal c = dir < 2 ? m.N_x * g.hz : m.N_z * g.hx; // times 1/l
        if (r.off[dir] != 0.0) { // a link to a free neighbour: once, from its lower end
          if (dir == 0)
            term(w(i, j), -r.off[dir], {{w(i + 1, j), 1}, {w(i, j), -1}, {y(i + 1), -1}, {y(i), 1}},
                 {{phi(i + 1), -z}, {phi(i), z}});
          if (dir == 2) term(w(i, j), -r.off[dir], {{w(i, j + 1), 1}, {w(i, j), -1}}, {{phi(i), -g.hz}});
          continue;
        }
        // an arm to the edge, or to a node held by the d_min rule: the frame's section at x_i
        const PetscReal l = BedArmLength(g, i, j, dir);
        term(w(i, j), c / l, {{w(i, j), 1}, {y(i), -1}}, {{phi(i), -z}});
      }
    }
  return out;
}

} // namespace beamimpact

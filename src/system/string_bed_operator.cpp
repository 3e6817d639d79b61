// The string bed's stiffness rows. See string_bed_operator.hpp.
#include "system/string_bed_operator.hpp"

#include <algorithm>
#include <cmath>

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
  const PetscReal h  = dir < 2 ? g.hx : g.hz;
  *cut               = !(in > 0 && in < g.nx - 1 && jn > 0 && jn < g.nz - 1 && BedInside(g, g.X(in), g.Z(jn)));
  if (!*cut) return h;
  return std::min(h, BedEdgeDistance(g, g.X(i), g.Z(j), dir));
}
} // namespace

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
  r.mass = m.sigma * g.hx * g.hz;
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

} // namespace beamimpact

// The string bed as a membrane: its coefficients, outline, grid and stiffness rows. See
// string_bed.hpp.
#include "model/string_bed.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

const char *HeadShapeName(HeadShape s) { return s == HeadShape::Ellipse ? "ellipse" : "rectangle"; }

Membrane StringBedMembrane(const StringBedParams &p)
{
  Membrane m;
  m.N_x   = p.tension / p.spacing;
  m.N_z   = p.tension_crosses / p.spacing_crosses;
  m.sigma = p.linear_density / p.spacing + p.linear_density / p.spacing_crosses;
  return m;
}

BedGrid StringBedGrid(const StringBedParams &p)
{
  BedGrid g;
  g.shape = p.shape;
  g.a     = 0.5 * p.head_length;
  g.b     = 0.5 * p.head_width;
  g.nx    = p.nodes;
  g.nz    = p.nodes_width > 0 ? p.nodes_width : (PetscInt)std::lround((p.nodes - 1) * p.head_width / p.head_length) + 1;
  g.hx    = 2 * g.a / (g.nx - 1);
  g.hz    = 2 * g.b / (g.nz - 1);
  g.x0    = -g.a;
  return g;
}

BedGrid StringBedFrameGrid(const StringBedParams &p, PetscInt nodes, PetscReal length)
{
  BedGrid g;
  g.shape = p.shape;
  g.a     = 0.5 * p.head_length;
  g.b     = 0.5 * p.head_width;
  g.nx    = nodes;
  g.hx    = length / (nodes - 1);
  g.x0    = -p.head_center;
  g.nz    = p.nodes_width > 0 ? p.nodes_width : (PetscInt)std::lround(p.head_width / g.hx) + 1;
  g.hz    = 2 * g.b / (g.nz - 1);
  return g;
}

PetscReal BedCellArea(const BedGrid &g, PetscInt i, PetscInt j)
{
  const PetscReal x0 = g.X(i) - 0.5 * g.hx, x1 = g.X(i) + 0.5 * g.hx, z0 = g.Z(j) - 0.5 * g.hz,
                  z1 = g.Z(j) + 0.5 * g.hz;
  const auto overlap = [](PetscReal a0, PetscReal a1, PetscReal b0, PetscReal b1) {
    return std::max<PetscReal>(0, std::min(a1, b1) - std::max(a0, b0));
  };
  if (g.shape == HeadShape::Rectangle) return overlap(x0, x1, -g.a, g.a) * overlap(z0, z1, -g.b, g.b);
  const auto inside = [&](PetscReal x, PetscReal z) { return (x / g.a) * (x / g.a) + (z / g.b) * (z / g.b) <= 1; };
  bool       all    = true;
  for (PetscReal x : {x0, x1})
    for (PetscReal z : {z0, z1}) all = all && inside(x, z);
  if (all) return g.hx * g.hz;
  // the chord's half-height at x, clipped to the cell: the cell's area as an integral along x
  const auto chord = [&](PetscReal x) {
    const PetscReal u = x / g.a;
    if (std::abs(u) >= 1) return PetscReal(0);
    const PetscReal zb = g.b * std::sqrt(1 - u * u);
    return overlap(z0, z1, -zb, zb);
  };
  const PetscReal xa = std::max(x0, -g.a), xb = std::min(x1, g.a);
  if (!(xb > xa)) return 0;
  bool           none = true;
  const PetscInt n    = 4096; // midpoints: the chord has a kink where it meets z0 or z1 and a square root at x = +-a
  PetscReal      s    = 0;
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal c = chord(xa + (k + 0.5) * (xb - xa) / n);
    s += c, none = none && c == 0;
  }
  return none ? 0 : s * (xb - xa) / n;
}

HeadMoments HeadMomentsOf(const StringBedParams &p)
{
  const PetscReal a = 0.5 * p.head_length, b = 0.5 * p.head_width;
  HeadMoments     m;
  if (p.shape == HeadShape::Rectangle) m.area = 4 * a * b, m.xx = 4 * a * a * a * b / 3, m.zz = 4 * a * b * b * b / 3;
  else m.area = M_PI * a * b, m.xx = M_PI * a * a * a * b / 4, m.zz = M_PI * a * b * b * b / 4;
  return m;
}

bool BedInside(const BedGrid &g, PetscReal x, PetscReal z)
{
  const PetscReal tol = 1e-12;
  if (g.shape == HeadShape::Rectangle) return std::abs(x) < g.a * (1 - tol) && std::abs(z) < g.b * (1 - tol);
  const PetscReal u = x / g.a, v = z / g.b;
  return u * u + v * v < 1 - tol;
}

PetscReal BedEdgeDistance(const BedGrid &g, PetscReal x, PetscReal z, int dir)
{
  if (dir < 2) { // along x at height z: the edge at x_e = +-a (rectangle) or +-a sqrt(1 - (z/b)^2)
    const PetscReal v  = z / g.b;
    const PetscReal xe = g.shape == HeadShape::Rectangle ? g.a : g.a * std::sqrt(std::max<PetscReal>(0, 1 - v * v));
    return dir == 0 ? xe - x : x + xe;
  }
  const PetscReal u  = x / g.a;
  const PetscReal ze = g.shape == HeadShape::Rectangle ? g.b : g.b * std::sqrt(std::max<PetscReal>(0, 1 - u * u));
  return dir == 2 ? ze - z : z + ze;
}

PetscReal MembraneRectangleFrequency(const Membrane &m, PetscReal length, PetscReal width, PetscInt mm, PetscInt nn)
{
  const PetscReal km = mm / length, kn = nn / width;
  return 0.5 * std::sqrt((m.N_x * km * km + m.N_z * kn * kn) / m.sigma);
}

PetscReal MembraneCircleFrequency(const Membrane &m, PetscReal R, PetscReal bessel_zero)
{
  return bessel_zero / (2 * M_PI * R) * std::sqrt(m.N_x / m.sigma);
}

PetscReal MembranePatchCentreDeflection(PetscReal N, PetscReal R, PetscReal c, PetscReal F)
{
  return F / (2 * M_PI * N) * (std::log(R / c) + 0.5);
}

StringBedInPlane StringBedInPlaneOf(const StringBedParams &p, PetscReal x, PetscReal z, PetscReal patch_radius)
{
  StringBedInPlane s;
  BedGrid          g; // the outline alone
  g.shape = p.shape, g.a = 0.5 * p.head_length, g.b = 0.5 * p.head_width;
  s.mains     = std::max<PetscReal>(1, 2 * patch_radius / p.spacing);
  s.to_ends_a = BedEdgeDistance(g, x, z, 1);
  s.to_ends_b = BedEdgeDistance(g, x, z, 0);
  s.stiffness = s.mains * p.tension * (1 / s.to_ends_a + 1 / s.to_ends_b);
  s.mass      = s.mains * p.linear_density * (s.to_ends_a + s.to_ends_b) / 3;
  return s;
}

} // namespace beamimpact

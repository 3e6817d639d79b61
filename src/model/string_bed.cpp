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
  return g;
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

PetscReal MembraneCircleFrequency(const Membrane &m, PetscReal R, PetscReal bessel_zero) { return bessel_zero / (2 * M_PI * R) * std::sqrt(m.N_x / m.sigma); }

PetscReal MembranePatchCentreDeflection(PetscReal N, PetscReal R, PetscReal c, PetscReal F) { return F / (2 * M_PI * N) * (std::log(R / c) + 0.5); }

} // namespace beamimpact

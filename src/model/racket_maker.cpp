// A racket by its maker's numbers turned into its frame's table. See racket_maker.hpp.
#include "model/racket_maker.hpp"

#include <cmath>
#include <cstdio>

namespace beamimpact {

namespace {

const PetscReal kShearSpeed2 = 3.3e6;  // m^2/s^2, G/rho of the frame's layup
const PetscReal kDepth       = 0.026;  // m, the frame's depth a (rho I = mu a^2/12)
const PetscReal kHandleGyr   = 0.0125; // m, the handle's radius of gyration about the axis

// Integrals over [0, L] of the handle's shape phi (1 on [0, x_h], linear to 0 over the ramp) and
// of x phi; the head's shape is 1 - phi.
void ShapeIntegrals(PetscReal xh, PetscReal L, PetscReal *i0, PetscReal *i1, PetscReal *j0, PetscReal *j1)
{
  const PetscReal r = kRacketRamp;
  *i0 = xh + r / 2, *i1 = xh * xh / 2 + r * xh / 2 + r * r / 6;
  *j0 = L - *i0, *j1 = L * L / 2 - *i1;
}

PropertiesRow Row(PetscReal x, PetscReal EI, PetscReal mu, PetscReal GJ, PetscReal rhoJ)
{
  PropertiesRow q;
  q.x = x, q.s.EI = EI, q.s.mu = mu, q.s.kGA = 0.5 * kShearSpeed2 * mu, q.s.rhoI = mu * kDepth * kDepth / 12,
  q.s.GJ = GJ, q.s.rhoJ = rhoJ;
  return q;
}

} // namespace

void RacketMakerHead(const RacketMakerParams &r, StringBedParams *bed)
{
  const PetscReal w = bed->shape == HeadShape::Ellipse ? std::sqrt(4 * r.head_size / (PETSC_PI * r.head_aspect))
                                                       : std::sqrt(r.head_size / r.head_aspect);
  bed->head_width   = w;
  bed->head_length  = r.head_aspect * w;
  bed->head_center  = r.length - r.head_margin - bed->head_length / 2;
}

RacketStrung RacketStrungBy(const StringBedParams &bed)
{
  RacketStrung      q;
  const HeadMoments h = HeadMomentsOf(bed);
  const PetscReal   s = StringBedMembrane(bed).sigma;
  q.mass = s * h.area, q.moment = q.mass * bed.head_center, q.roll = s * h.zz;
  q.head_start = bed.head_center - bed.head_length / 2, q.head_length = bed.head_length;
  return q;
}

void RacketStrungAdd(const StringBedParams &bed, RacketStrung *s)
{
  const RacketStrung b = RacketStrungBy(bed);
  s->mass += b.mass, s->moment += b.moment, s->roll += b.roll;
  s->head_start = b.head_start, s->head_length = b.head_length;
}

bool RacketMakerTable(const RacketMakerParams &r, const RacketStrung &strung, std::vector<PropertiesRow> *rows,
                      std::string *why)
{
  char            text[512];
  const PetscReal L = r.length, xh = r.handle_length;
  const PetscReal ms = strung.mass, mx = strung.moment, mzz = strung.roll; // the strings' mass and moments
  if (strung.head_length > 0 && !(strung.head_start > xh + kRacketRamp)) {
    std::snprintf(text, sizeof text,
                  "the head (%g m long, -racket_head_size %g m^2) reaches into the handle (-racket_handle_length %g "
                  "m): a longer -racket_length or a smaller head",
                  (double)strung.head_length, (double)r.head_size, (double)xh);
    *why = text;
    return false;
  }
  if (!(xh > 0 && xh + kRacketRamp < L)) {
    std::snprintf(text, sizeof text,
                  "-racket_handle_length %g m must lie within the racket (-racket_length %g m) with the %g m ramp to "
                  "the head",
                  (double)xh, (double)L, (double)kRacketRamp);
    *why = text;
    return false;
  }
  PetscReal i0, i1, j0, j1;
  ShapeIntegrals(xh, L, &i0, &i1, &j0, &j1);
  const PetscReal M = r.mass - ms, F = r.mass * r.balance - mx, det = i0 * j1 - j0 * i1;
  const PetscReal mu1 = (M * j1 - F * j0) / det, mu2 = (i0 * F - i1 * M) / det;
  if (!(mu1 > 0 && mu2 > 0)) {
    std::snprintf(text, sizeof text,
                  "-racket_mass %g kg with -racket_balance %g m makes no racket: the handle's and the head's mass per "
                  "length would be %g and %g kg/m (both must be > 0: at this mass the balance lies between %g and %g "
                  "m)",
                  (double)r.mass, (double)r.balance, (double)mu1, (double)mu2, (double)((mx + M * i1 / i0) / r.mass),
                  (double)((mx + M * j1 / j0) / r.mass));
    *why = text;
    return false;
  }
  const PetscReal j_handle = mu1 * kHandleGyr * kHandleGyr, rhoJ2 = (r.twistweight - mzz - j_handle * i0) / j0;
  if (!(rhoJ2 > 0)) {
    std::snprintf(text, sizeof text,
                  "-racket_twistweight %g kg m^2 is less than the strings' and the handle's own (%g kg m^2)",
                  (double)r.twistweight, (double)(mzz + j_handle * i0));
    *why = text;
    return false;
  }
  rows->clear();
  rows->push_back(Row(0, r.frame_stiffness, mu1, r.twist_stiffness, j_handle));
  rows->push_back(Row(xh, r.frame_stiffness, mu1, r.twist_stiffness, j_handle));
  rows->push_back(Row(xh + kRacketRamp, r.frame_stiffness, mu2, r.twist_stiffness, rhoJ2));
  rows->push_back(Row(L, r.frame_stiffness, mu2, r.twist_stiffness, rhoJ2));
  return true;
}

} // namespace beamimpact

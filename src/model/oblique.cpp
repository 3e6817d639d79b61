// The oblique impact's geometry and tangential contact. See oblique.hpp.
#include "model/oblique.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

ObliqueGeometry ObliqueGeometryOf(PetscReal offset, PetscReal ball_radius, PetscReal bat_radius)
{
  ObliqueGeometry g;
  g.offset     = offset;
  g.radius_sum = ball_radius + bat_radius;
  g.sin_theta  = offset / g.radius_sum;
  g.theta      = std::asin(g.sin_theta);
  g.cos_theta  = offset == 0 ? 1.0 : std::cos(g.theta); // exactly 1 head-on
  return g;
}

PetscReal RoundSectionRadiusAt(const BeamSection &s, PetscReal x)
{
  const std::vector<ProfileRow> &r = s.profile;
  if (s.source != SectionSource::Profile || r.empty()) return 0;
  if (x <= r.front().x) return 0.5 * r.front().D;
  for (size_t i = 0; i + 1 < r.size(); ++i)
    if (x <= r[i + 1].x) return 0.5 * (r[i].D + (r[i + 1].D - r[i].D) * (x - r[i].x) / (r[i + 1].x - r[i].x));
  return 0.5 * r.back().D;
}

PetscReal TangentialModel::EffectiveMass() const
{
  PetscReal inv = 1 / ball_mass + ball_radius * ball_radius / ball_inertia;
  if (std::isfinite(bat_mass)) inv += 1 / bat_mass;
  if (std::isfinite(bat_roll_inertia)) inv += bat_radius * bat_radius / bat_roll_inertia;
  return 1 / inv;
}

PetscReal TangentialStiffnessFromCor(PetscReal ball_mass, PetscReal alpha, PetscReal e_T, PetscReal tau)
{
  const PetscReal m_e0 = ball_mass * alpha / (1 + alpha);
  const PetscReal w    = std::acos(-e_T) / tau;
  return m_e0 * w * w;
}

TangentialState TangentialStart(PetscReal u0)
{
  TangentialState s;
  s.u         = u0;
  s.phase     = u0 == 0 ? TangentialPhase::Grip : TangentialPhase::Slip;
  s.slip_sign = u0 > 0 ? 1 : u0 < 0 ? -1 : 0;
  return s;
}

namespace {

// The first point of (0, b] where f > 0, given f(0) <= 0: sampled at n points, then bisected to
// round-off; -1 when f stays <= 0 at every sample.
template <class F>
PetscReal FirstPositive(F f, PetscReal b, PetscInt n)
{
  PetscReal a = 0;
  for (PetscInt k = 1; k <= n; ++k) {
    const PetscReal x = b * k / n;
    if (f(x) > 0) {
      PetscReal lo = a, hi = x;
      for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        const PetscReal mid = 0.5 * (lo + hi);
        if (f(mid) > 0) hi = mid;
        else lo = mid;
      }
      return hi;
    }
    a = x;
  }
  return -1;
}

// One stretch of slip from sigma = 0 (force F_a, slope dF) for at most sigma_max: how long it
// lasts (sigma_max if it does not end), and the state moved to its end.
PetscReal SlipStretch(const TangentialModel &m, PetscReal m_e, PetscReal Fa, PetscReal dF, PetscReal sigma_max, TangentialState *s)
{
  const PetscReal mu = m.friction, k = m.stiffness, sg = (PetscReal)s->slip_sign, ua = s->u;
  auto            F     = [&](PetscReal x) { return Fa + dF * x; };
  auto            u     = [&](PetscReal x) { return ua - sg * mu / m_e * (Fa * x + 0.5 * dF * x * x); };
  auto            srate = [&](PetscReal x) { return sg * (u(x) - (k > 0 ? sg * mu * dF / k : 0)); }; // s (u - xi')
  PetscReal       end   = srate(0) <= 0 ? 0 : FirstPositive([&](PetscReal x) { return -srate(x); }, sigma_max, 16);
  const bool      grips = end >= 0;
  if (!grips) end = sigma_max;
  // mu F s (u - xi') is a cubic in sigma: Simpson's rule is exact.
  auto rate = [&](PetscReal x) { return mu * F(x) * std::max<PetscReal>(srate(x), 0); };
  s->dissipated += end / 6 * (rate(0) + 4 * rate(0.5 * end) + rate(end));
  s->impulse += -sg * mu * (Fa * end + 0.5 * dF * end * end);
  s->u  = u(end);
  s->xi = k > 0 ? sg * mu * F(end) / k : 0;
  if (grips) {
    s->phase = TangentialPhase::Grip;
    if (k == 0) s->u = 0; // a rigid grip: the surfaces move together
  }
  return end;
}

// One stretch of grip from sigma = 0: the spring's harmonic motion (k > 0) until k |xi| reaches
// mu F; a rigid grip (k = 0) keeps u = 0 and F_t = 0 to the end.
PetscReal GripStretch(const TangentialModel &m, PetscReal m_e, PetscReal Fa, PetscReal dF, PetscReal sigma_max, TangentialState *s)
{
  const PetscReal mu = m.friction, k = m.stiffness;
  if (k == 0) {
    s->u = 0;
    return sigma_max;
  }
  const PetscReal w = std::sqrt(k / m_e), ua = s->u, xa = s->xi;
  auto            xi    = [&](PetscReal x) { return xa * std::cos(w * x) + ua / w * std::sin(w * x); };
  auto            u     = [&](PetscReal x) { return ua * std::cos(w * x) - xa * w * std::sin(w * x); };
  const PetscReal scale = mu * std::max(std::abs(Fa), std::abs(Fa + dF * sigma_max)) + k * std::abs(xa) + k * std::abs(ua) / w;
  auto            over  = [&](PetscReal x) { return k * std::abs(xi(x)) - mu * (Fa + dF * x) - 1e-12 * scale; };
  const PetscInt  n     = std::max<PetscInt>(16, (PetscInt)std::ceil(w * sigma_max / 0.2));
  PetscReal       end   = FirstPositive(over, sigma_max, n);
  const bool      slips = end >= 0;
  if (!slips) end = sigma_max;
  s->u = u(end);
  s->xi = xi(end);
  s->impulse += m_e * (s->u - ua);
  if (slips) {
    s->phase     = TangentialPhase::Slip;
    s->slip_sign = s->xi > 0 ? 1 : -1;
    s->xi        = s->slip_sign * mu * (Fa + dF * end) / k;
  }
  return end;
}

} // namespace

void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1, TangentialState *s)
{
  const PetscReal h = t1 - t0;
  if (!(h > 0)) return;
  s->normal_impulse += 0.5 * h * (F0 + F1);
  if (F0 == 0 && F1 == 0) { // not touching: no tangential force, the spring relaxed
    s->xi = 0;
    return;
  }
  const PetscReal m_e = m.EffectiveMass(), dF = (F1 - F0) / h;
  PetscReal       tau = 0;
  for (int it = 0; it < 200 && tau < h; ++it) {
    const TangentialPhase before = s->phase;
    const PetscReal       Fa     = F0 + dF * tau;
    if (s->phase == TangentialPhase::Slip && s->slip_sign == 0) { // no slip yet: grip
      s->phase = TangentialPhase::Grip;
      continue;
    }
    const PetscReal d = s->phase == TangentialPhase::Slip ? SlipStretch(m, m_e, Fa, dF, h - tau, s) : GripStretch(m, m_e, Fa, dF, h - tau, s);
    tau += d;
    if (s->phase != before) {
      TangentialSwitch sw;
      sw.time = t0 + tau;
      sw.to   = s->phase;
      s->switches.push_back(sw);
    }
  }
  if (tau < h) { // a grip/slip chatter at one instant (a degenerate touch): the rest of the piece in the phase reached
    const PetscReal Fa = F0 + dF * tau;
    if (s->phase == TangentialPhase::Slip) (void)SlipStretch(m, m_e, Fa, dF, h - tau, s);
    else (void)GripStretch(m, m_e, Fa, dF, h - tau, s);
  }
}

TangentialBodies TangentialBodiesAfter(const TangentialModel &m, const TangentialBodies &b0, PetscReal J)
{
  TangentialBodies b;
  b.v_ball = b0.v_ball + J / m.ball_mass;
  b.spin   = b0.spin - m.ball_radius * J / m.ball_inertia;
  b.v_bat  = std::isfinite(m.bat_mass) ? b0.v_bat - J / m.bat_mass : b0.v_bat;
  b.roll   = std::isfinite(m.bat_roll_inertia) ? b0.roll - m.bat_radius * J / m.bat_roll_inertia : b0.roll;
  return b;
}

PetscReal TangentialKineticEnergy(const TangentialModel &m, const TangentialBodies &b)
{
  PetscReal E = 0.5 * m.ball_mass * b.v_ball * b.v_ball + 0.5 * m.ball_inertia * b.spin * b.spin;
  if (std::isfinite(m.bat_mass)) E += 0.5 * m.bat_mass * b.v_bat * b.v_bat;
  if (std::isfinite(m.bat_roll_inertia)) E += 0.5 * m.bat_roll_inertia * b.roll * b.roll;
  return E;
}

ObliqueExit ObliqueExitOf(const ObliqueGeometry &g, PetscReal u_n, PetscReal v_t)
{
  ObliqueExit e;
  e.vy           = u_n * g.cos_theta - v_t * g.sin_theta;
  e.vz           = u_n * g.sin_theta + v_t * g.cos_theta;
  e.speed        = std::hypot(e.vy, e.vz);
  e.launch_angle = std::atan2(e.vz, e.vy) * 180 / M_PI;
  return e;
}

} // namespace beamimpact

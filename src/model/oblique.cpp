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

TangentialState TangentialStart(const TangentialModel &m, PetscReal u0)
{
  TangentialState s;
  s.u         = u0;
  s.phase     = u0 == 0 || m.compliance_length > 0 ? TangentialPhase::Grip : TangentialPhase::Slip;
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
// lasts (sigma_max if it does not end), and the state moved to its end. The spring, if any, is
// held at its limit, xi = s mu l (k_t |xi| = mu F_n), so the sliding rate is u itself.
PetscReal SlipStretch(const TangentialModel &m, PetscReal m_e, PetscReal Fa, PetscReal dF, PetscReal sigma_max, TangentialState *s)
{
  const PetscReal mu = m.friction, l = m.compliance_length, sg = (PetscReal)s->slip_sign, ua = s->u;
  auto            F     = [&](PetscReal x) { return Fa + dF * x; };
  auto            u     = [&](PetscReal x) { return ua - sg * mu / m_e * (Fa * x + 0.5 * dF * x * x); };
  auto            srate = [&](PetscReal x) { return sg * u(x); };
  PetscReal       end   = srate(0) <= 0 ? 0 : FirstPositive([&](PetscReal x) { return -srate(x); }, sigma_max, 16);
  const bool      grips = end >= 0;
  if (!grips) end = sigma_max;
  // mu F s u is a cubic in sigma: Simpson's rule is exact.
  auto rate = [&](PetscReal x) { return mu * F(x) * std::max<PetscReal>(srate(x), 0); };
  s->dissipated += end / 6 * (rate(0) + 4 * rate(0.5 * end) + rate(end));
  s->impulse += -sg * mu * (Fa * end + 0.5 * dF * end * end);
  s->u = u(end);
  if (l > 0) {
    s->xi = sg * mu * l;
    s->stiffness_work += 0.5 * dF / l * s->xi * s->xi * end; // the spring's stiffness F_n/l changes under a fixed stretch
  }
  if (grips) {
    s->phase = TangentialPhase::Grip;
    if (l == 0) s->u = 0; // a rigid grip: the surfaces move together
  }
  return end;
}

// The grip of a compliant contact on [0, sigma]: xi' = u, u' = -F(t) xi / (l m_e), with the
// integral of xi^2 (for the stiffness's work), by classical Runge-Kutta in n steps.
struct GripState {
  PetscReal xi = 0, u = 0, xi2 = 0;
};
GripState GripIntegrate(PetscReal l_me, PetscReal Fa, PetscReal dF, GripState y, PetscReal sigma, PetscInt n)
{
  const PetscReal h = sigma / n;
  auto            f = [&](PetscReal x, const GripState &z) {
    GripState d;
    d.xi  = z.u;
    d.u   = -(Fa + dF * x) / l_me * z.xi;
    d.xi2 = z.xi * z.xi;
    return d;
  };
  auto axpy = [](const GripState &z, PetscReal a, const GripState &d) {
    GripState r;
    r.xi = z.xi + a * d.xi, r.u = z.u + a * d.u, r.xi2 = z.xi2 + a * d.xi2;
    return r;
  };
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal x = k * h;
    const GripState k1 = f(x, y), k2 = f(x + h / 2, axpy(y, h / 2, k1)), k3 = f(x + h / 2, axpy(y, h / 2, k2)), k4 = f(x + h, axpy(y, h, k3));
    y.xi += h / 6 * (k1.xi + 2 * k2.xi + 2 * k3.xi + k4.xi);
    y.u += h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u);
    y.xi2 += h / 6 * (k1.xi2 + 2 * k2.xi2 + 2 * k3.xi2 + k4.xi2);
  }
  return y;
}

// Steps for a grip over sigma: 40 per radian of the fastest tangential oscillation, at least 4.
PetscInt GripSteps(PetscReal l_me, PetscReal Fa, PetscReal dF, PetscReal sigma)
{
  const PetscReal w = std::sqrt(std::max<PetscReal>(std::max(Fa, Fa + dF * sigma), 0) / l_me);
  return std::max<PetscInt>(4, (PetscInt)std::ceil(40 * w * sigma));
}

// One stretch of grip from sigma = 0. A compliant contact (l > 0): the spring k_t = F_n / l takes
// the surfaces' relative motion until its stretch reaches the Coulomb limit |xi| = mu l; a rigid
// grip (l = 0) keeps u = 0 and F_t = 0 to the end.
PetscReal GripStretch(const TangentialModel &m, PetscReal m_e, PetscReal Fa, PetscReal dF, PetscReal sigma_max, TangentialState *s)
{
  const PetscReal mu = m.friction, l = m.compliance_length, l_me = l * m_e;
  if (l == 0) {
    s->u = 0;
    return sigma_max;
  }
  const PetscReal limit = mu * l;
  const PetscInt  n     = GripSteps(l_me, Fa, dF, sigma_max);
  const PetscReal h     = sigma_max / n;
  GripState       y;
  y.xi = s->xi, y.u = s->u;
  PetscReal end = sigma_max;
  bool      slips = false;
  for (PetscInt k = 0; k < n; ++k) { // step by step, so that the first crossing of the limit is found
    const GripState z = GripIntegrate(l_me, Fa + dF * k * h, dF, y, h, 1);
    if (std::abs(z.xi) > limit) {
      PetscReal lo = 0, hi = h; // bisect the step's length onto the limit
      for (int it = 0; it < 200 && hi - lo > 1e-15 * h; ++it) {
        const PetscReal mid = 0.5 * (lo + hi);
        if (std::abs(GripIntegrate(l_me, Fa + dF * k * h, dF, y, mid, 1).xi) > limit) hi = mid;
        else lo = mid;
      }
      y     = GripIntegrate(l_me, Fa + dF * k * h, dF, y, hi, 1);
      end   = k * h + hi;
      slips = true;
      break;
    }
    y = z;
  }
  s->impulse += m_e * (y.u - s->u);
  s->stiffness_work += 0.5 * dF / l * y.xi2;
  s->u  = y.u;
  s->xi = y.xi;
  if (slips) {
    s->phase     = TangentialPhase::Slip;
    s->slip_sign = s->xi > 0 ? 1 : -1;
    s->xi        = s->slip_sign * limit;
  }
  return end;
}

} // namespace

PetscReal TangentialComplianceLength(PetscReal m_e, PetscReal e_T, const std::vector<PetscReal> &t, const std::vector<PetscReal> &F)
{
  const size_t n = std::min(t.size(), F.size());
  // The grip throughout from xi = 0, u = 1: -u at the end.
  auto reversal = [&](PetscReal l) {
    GripState y;
    y.u = 1;
    for (size_t k = 0; k + 1 < n; ++k) {
      const PetscReal h = t[k + 1] - t[k];
      if (!(h > 0)) continue;
      const PetscReal F0 = std::max<PetscReal>(F[k], 0), F1 = std::max<PetscReal>(F[k + 1], 0), dF = (F1 - F0) / h;
      y = GripIntegrate(l * m_e, F0, dF, y, h, GripSteps(l * m_e, F0, dF, h));
    }
    return -y.u;
  };
  // The phase of the tangential oscillation, integral sqrt(F / (l m_e)) dt = arccos(-e_T) in the
  // slowly varying limit, gives the first guess; then bisection on log l.
  PetscReal root = 0;
  for (size_t k = 0; k + 1 < n; ++k) root += 0.5 * (t[k + 1] - t[k]) * (std::sqrt(std::max<PetscReal>(F[k], 0) / m_e) + std::sqrt(std::max<PetscReal>(F[k + 1], 0) / m_e));
  if (!(root > 0)) return 0;
  const PetscReal l0 = std::pow(root / std::acos(-e_T), 2);
  PetscReal       lo = l0 / 64, hi = l0 * 64; // reversal(lo) > e_T > reversal(hi) on the first branch
  for (int it = 0; it < 40 && reversal(lo) <= e_T; ++it) lo *= 1.5;
  for (int it = 0; it < 200 && hi / lo > 1 + 1e-13; ++it) {
    const PetscReal mid = std::sqrt(lo * hi);
    if (reversal(mid) > e_T) lo = mid;
    else hi = mid;
  }
  return std::sqrt(lo * hi);
}

void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1, TangentialState *s)
{
  const PetscReal h = t1 - t0;
  if (!(h > 0)) return;
  s->normal_impulse += 0.5 * h * (F0 + F1);
  if (F0 == 0 && F1 == 0) { // not touching: no tangential force, the spring (stiffness F_n / l) relaxed
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

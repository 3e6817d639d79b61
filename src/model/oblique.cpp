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

// One stretch of slip from sigma = 0 (F_n the cubic F from there) for at most sigma_max: how long
// it lasts (sigma_max if it does not end), and the state moved to its end. The spring, if any,
// is held at its limit, xi = s mu l (k_t |xi| = mu F_n), so the sliding rate is u itself.
PetscReal SlipStretch(const TangentialModel &m, PetscReal m_e, const ForceCubic &F, PetscReal sigma_max,
                      TangentialState *s)
{
  const PetscReal mu = m.friction, l = m.compliance_length, sg = (PetscReal)s->slip_sign, ua = s->u;
  auto            u     = [&](PetscReal x) { return ua - sg * mu / m_e * F.Integral(x); };
  auto            srate = [&](PetscReal x) { return sg * u(x); };
  PetscReal       end   = srate(0) <= 0 ? 0 : FirstPositive([&](PetscReal x) { return -srate(x); }, sigma_max, 16);
  const bool      grips = end >= 0;
  if (!grips) end = sigma_max;
  // mu F s u is a polynomial of degree 7 in sigma: 4-point Gauss is exact.
  static const PetscReal gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const PetscReal gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  auto                   rate  = [&](PetscReal x) { return mu * F(x) * std::max<PetscReal>(srate(x), 0); };
  for (int i = 0; i < 4; ++i) s->dissipated += 0.5 * end * gw[i] * rate(0.5 * end * (1 + gx[i]));
  s->impulse += -sg * mu * F.Integral(end);
  s->u = u(end);
  if (l > 0) {
    s->xi = sg * mu * l;
    s->stiffness_work += 0.5 * (F(end) - F(0)) / l * s->xi *
                         s->xi; // the spring's stiffness F_n/l changes under a fixed stretch
  }
  if (grips) {
    s->phase = TangentialPhase::Grip;
    if (l == 0) s->u = 0; // a rigid grip: the surfaces move together
  }
  return end;
}

// The grip of a compliant contact on [0, sigma] (F_n the cubic F): xi' = u, u' = -F(t) xi /
// (l m_e), with the integral of dF/dt xi^2 (for the stiffness's work), by classical Runge-Kutta
// in n steps.
struct GripState {
  PetscReal xi = 0, u = 0, fxi2 = 0;
};
GripState GripIntegrate(PetscReal l_me, const ForceCubic &F, GripState y, PetscReal sigma, PetscInt n)
{
  const PetscReal h = sigma / n;
  auto            f = [&](PetscReal x, const GripState &z) {
    GripState d;
    d.xi   = z.u;
    d.u    = -F(x) / l_me * z.xi;
    d.fxi2 = F.Rate(x) * z.xi * z.xi;
    return d;
  };
  auto axpy = [](const GripState &z, PetscReal a, const GripState &d) {
    GripState r;
    r.xi = z.xi + a * d.xi, r.u = z.u + a * d.u, r.fxi2 = z.fxi2 + a * d.fxi2;
    return r;
  };
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal x  = k * h;
    const GripState k1 = f(x, y), k2 = f(x + h / 2, axpy(y, h / 2, k1)), k3 = f(x + h / 2, axpy(y, h / 2, k2)),
                    k4 = f(x + h, axpy(y, h, k3));
    y.xi += h / 6 * (k1.xi + 2 * k2.xi + 2 * k3.xi + k4.xi);
    y.u += h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u);
    y.fxi2 += h / 6 * (k1.fxi2 + 2 * k2.fxi2 + 2 * k3.fxi2 + k4.fxi2);
  }
  return y;
}

// Steps for a grip over sigma: 40 per radian of the fastest tangential oscillation, at least 4.
PetscInt GripSteps(PetscReal l_me, const ForceCubic &F, PetscReal sigma)
{
  const PetscReal w = std::sqrt(std::max<PetscReal>(std::max(F(0), F(sigma)), 0) / l_me);
  return std::max<PetscInt>(4, (PetscInt)std::ceil(40 * w * sigma));
}

// One stretch of grip from sigma = 0. A compliant contact (l > 0): the spring k_t = F_n / l takes
// the surfaces' relative motion until its stretch reaches the Coulomb limit |xi| = mu l; a rigid
// grip (l = 0) keeps u = 0 and F_t = 0 to the end.
PetscReal GripStretch(const TangentialModel &m, PetscReal m_e, const ForceCubic &F, PetscReal sigma_max,
                      TangentialState *s)
{
  const PetscReal mu = m.friction, l = m.compliance_length, l_me = l * m_e;
  if (l == 0) {
    s->u = 0;
    return sigma_max;
  }
  const PetscReal limit = mu * l;
  const PetscInt  n     = GripSteps(l_me, F, sigma_max);
  const PetscReal h     = sigma_max / n;
  GripState       y;
  y.xi = s->xi, y.u = s->u;
  PetscReal end   = sigma_max;
  bool      slips = false;
  for (PetscInt k = 0; k < n; ++k) { // step by step, so that the first crossing of the limit is found
    const ForceCubic Fk = F.Shift(k * h);
    const GripState  z  = GripIntegrate(l_me, Fk, y, h, 1);
    if (std::abs(z.xi) > limit) {
      PetscReal lo = 0, hi = h; // bisect the step's length onto the limit
      for (int it = 0; it < 200 && hi - lo > 1e-15 * h; ++it) {
        const PetscReal mid = 0.5 * (lo + hi);
        if (std::abs(GripIntegrate(l_me, Fk, y, mid, 1).xi) > limit) hi = mid;
        else lo = mid;
      }
      y     = GripIntegrate(l_me, Fk, y, hi, 1);
      end   = k * h + hi;
      slips = true;
      break;
    }
    y = z;
  }
  s->impulse += m_e * (y.u - s->u);
  s->stiffness_work += 0.5 / l * y.fxi2;
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

ForceCubic ForceCubic::Shift(PetscReal a) const
{
  ForceCubic r;
  r.c[0] = (*this)(a);
  r.c[1] = Rate(a);
  r.c[2] = c[2] + 3 * c[3] * a;
  r.c[3] = c[3];
  return r;
}

ForceCubic ForceCubic::Scaled(PetscReal k) const
{
  ForceCubic r;
  for (int i = 0; i < 4; ++i) r.c[i] = k * c[i];
  return r;
}

ForceCubic ForceCubic::Hermite(PetscReal h, PetscReal F0, PetscReal F1, PetscReal dF0, PetscReal dF1)
{
  const PetscReal d = (F1 - F0) / h;
  ForceCubic      r;
  r.c[0] = F0;
  r.c[1] = dF0;
  r.c[2] = (3 * d - 2 * dF0 - dF1) / h;
  r.c[3] = (dF0 + dF1 - 2 * d) / (h * h);
  return r;
}

namespace {

// The root of g (decreasing through it) in [lo, hi] to 1e-13 relative, on log l: bisection
// until the bracket is within 25 % (g oscillates with the phase of the tangential oscillation,
// ~ l^-1/2, so a wide bracket holds other branches' roots; within 25 % the phase varies by 12 %,
// one root: the one the bisection converges to), then Illinois' regula falsi (the end kept twice
// has its value halved), a bisection wherever two steps did not halve the bracket: ~13
// evaluations of g (each a grip over the whole contact) where the bisection took 47, a sixth of
// a sweep point's time (issue 38). g_lo > 0 > g_hi, else the bisection throughout.
template <class G>
PetscReal ComplianceRoot(PetscReal lo, PetscReal hi, PetscReal g_lo, PetscReal g_hi, const G &g)
{
  PetscReal  a = std::log(lo), b = std::log(hi), w1 = b - a, w2 = 2 * (b - a); // widths one and two steps ago
  const bool bracketed = g_lo > 0 && g_hi < 0;
  int        kept      = 0; // the end kept by the last step: -1 a, +1 b
  for (int it = 0; it < 200 && b - a > 1e-13; ++it) {
    const bool      bisect = !bracketed || b - a > 0.25 || b - a > 0.5 * w2;
    const PetscReal x      = bisect ? 0.5 * (a + b)
                                    : std::min(std::max((a * g_hi - b * g_lo) / (g_hi - g_lo), a + 0.01 * (b - a)),
                                               b - 0.01 * (b - a));
    const PetscReal gx     = g(std::exp(x));
    w2 = w1, w1 = b - a;
    if (gx == 0) return std::exp(x);
    if (gx > 0) {
      a = x, g_lo = gx;
      if (kept == 1 && !bisect) g_hi *= 0.5;
      kept = 1;
    } else {
      b = x, g_hi = gx;
      if (kept == -1 && !bisect) g_lo *= 0.5;
      kept = -1;
    }
  }
  return std::exp(0.5 * (a + b));
}

} // namespace

PetscReal TangentialComplianceLength(PetscReal m_e, PetscReal e_T, const std::vector<PetscReal> &t,
                                     const std::vector<PetscReal> &F, const std::vector<PetscReal> &dF)
{
  const size_t n     = std::min(t.size(), F.size());
  const bool   rates = dF.size() >= n;
  // The grip throughout from xi = 0, u = 1: -u at the end.
  auto reversal = [&](PetscReal l) {
    GripState y;
    y.u = 1;
    for (size_t k = 0; k + 1 < n; ++k) {
      const PetscReal h = t[k + 1] - t[k];
      if (!(h > 0)) continue;
      const PetscReal  F0 = std::max<PetscReal>(F[k], 0), F1 = std::max<PetscReal>(F[k + 1], 0), d = (F1 - F0) / h;
      const ForceCubic Fk = F0 == 0 && F1 == 0
                            ? ForceCubic()
                            : ForceCubic::Hermite(h, F0, F1, rates ? dF[k] : d, rates ? dF[k + 1] : d);
      y                   = GripIntegrate(l * m_e, Fk, y, h, GripSteps(l * m_e, Fk, h));
    }
    return -y.u;
  };
  // The phase of the tangential oscillation, integral sqrt(F / (l m_e)) dt = arccos(-e_T) in the
  // slowly varying limit, gives the first guess; then the root on log l in its bracket.
  PetscReal root = 0;
  for (size_t k = 0; k + 1 < n; ++k)
    root += 0.5 * (t[k + 1] - t[k]) *
            (std::sqrt(std::max<PetscReal>(F[k], 0) / m_e) + std::sqrt(std::max<PetscReal>(F[k + 1], 0) / m_e));
  if (!(root > 0)) return 0;
  const PetscReal l0 = std::pow(root / std::acos(-e_T), 2);
  PetscReal       lo = l0 / 64, hi = l0 * 64, g_lo = 0; // reversal(lo) > e_T > reversal(hi) on the first branch
  for (int it = 0; it < 40 && (g_lo = reversal(lo) - e_T) <= 0; ++it) lo *= 1.5;
  return ComplianceRoot(lo, hi, g_lo, reversal(hi) - e_T, [&](PetscReal l) { return reversal(l) - e_T; });
}

void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1,
                       TangentialState *s)
{
  const PetscReal d = t1 > t0 ? (F1 - F0) / (t1 - t0) : 0;
  TangentialAdvance(m, t0, t1, F0, F1, d, d, s);
}

void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1, PetscReal dF0,
                       PetscReal dF1, TangentialState *s)
{
  const PetscReal h = t1 - t0;
  if (!(h > 0)) return;
  if (F0 == 0 && F1 == 0) { // not touching: no tangential force, the spring (stiffness F_n / l) relaxed
    s->xi = 0;
    return;
  }
  const ForceCubic Fn = ForceCubic::Hermite(h, F0, F1, dF0, dF1);
  s->normal_impulse += Fn.Integral(h);
  const PetscReal m_e = m.EffectiveMass();
  PetscReal       tau = 0;
  for (int it = 0; it < 200 && tau < h; ++it) {
    const TangentialPhase before = s->phase;
    if (s->phase == TangentialPhase::Slip && s->slip_sign == 0) { // no slip yet: grip
      s->phase = TangentialPhase::Grip;
      continue;
    }
    const ForceCubic Fa = Fn.Shift(tau);
    const PetscReal  d  = s->phase == TangentialPhase::Slip ? SlipStretch(m, m_e, Fa, h - tau, s)
                                                            : GripStretch(m, m_e, Fa, h - tau, s);
    tau += d;
    if (s->phase != before) {
      TangentialSwitch sw;
      sw.time = t0 + tau;
      sw.to   = s->phase;
      s->switches.push_back(sw);
    }
  }
  if (tau < h) { // a grip/slip chatter at one instant (a degenerate touch): the rest of the piece in the phase reached
    const ForceCubic Fa = Fn.Shift(tau);
    if (s->phase == TangentialPhase::Slip) (void)SlipStretch(m, m_e, Fa, h - tau, s);
    else (void)GripStretch(m, m_e, Fa, h - tau, s);
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

// ---- The bat flexible in its second plane (oblique.hpp, TangentialPlane) ----

namespace beamimpact {

PetscReal TangentialPlane::PointVelocity() const
{
  PetscReal v = 0;
  for (size_t k = 0; k < gamma.size(); ++k) v += gamma[k] * zd[k];
  return v;
}

PetscReal TangentialPlane::ModeEnergy() const
{
  PetscReal E = 0.5 * flexibility * force * force;
  for (size_t k = 0; k < omega.size(); ++k) E += 0.5 * (zd[k] * zd[k] + omega[k] * omega[k] * z[k] * z[k]);
  return E;
}

void TangentialModeForced(PetscReal w, PetscReal z, PetscReal zd, PetscReal f0, PetscReal f1, PetscReal tau,
                          PetscReal *q, PetscReal *qd)
{
  // z(tau) = z cos + zd S1 + f0 C1 + f1 D1,  S1 = sin(w tau)/w, C1 = (1 - cos(w tau))/w^2,
  // D1 = (w tau - sin(w tau))/w^3 (its series below w tau = 0.2, where the difference cancels).
  PetscReal c = 1, S1 = tau, C1 = 0.5 * tau * tau, D1 = tau * tau * tau / 6;
  if (w != 0) {
    const PetscReal x = w * tau, sh = std::sin(0.5 * x);
    c  = std::cos(x);
    S1 = std::sin(x) / w;
    C1 = 2 * sh * sh / (w * w);
    if (x < 0.2) {
      const PetscReal x2 = x * x;
      D1                 = tau * tau * tau * (1.0 / 6 - x2 / 120 * (1 - x2 / 42 * (1 - x2 / 72 * (1 - x2 / 110))));
    } else D1 = (x - std::sin(x)) / (w * w * w);
  }
  *q  = z * c + zd * S1 + f0 * C1 + f1 * D1;
  *qd = -z * w * w * S1 + zd * c + f0 * S1 + f1 * C1;
}

namespace {

// phi_k(x) = sum_j x^j / (j + k)!, k >= 0 (phi_0 = e^x): the series below |x| = 0.5, else the
// recurrence phi_k = (phi_k-1 - 1/(k-1)!) / x from e^x.
PetscReal PhiScalar(int k, PetscReal x)
{
  if (std::abs(x) < 0.5) {
    PetscReal term = 1, sum = 0;
    for (int j = 1; j <= k; ++j) term /= j;
    for (int j = 0; j < 30; ++j) {
      sum += term;
      term *= x / (j + k + 1);
    }
    return sum;
  }
  PetscReal r = std::exp(x), fact = 1;
  for (int j = 1; j <= k; ++j) {
    r = (r - 1 / fact) / x;
    fact *= j;
  }
  return r;
}

// A 2 x 2 matrix [[a, b], [c, d]].
struct Mat2 {
  PetscReal a = 0, b = 0, c = 0, d = 0;
};
Mat2 operator*(const Mat2 &x, const Mat2 &y)
{
  return {x.a * y.a + x.b * y.c, x.a * y.b + x.b * y.d, x.c * y.a + x.d * y.c, x.c * y.b + x.d * y.d};
}

// E = e^X, P1 = phi_1(X), P2 = phi_2(X) of X = tau [[0, w], [-w, -2 sigma]] (the mode in the
// scaled state (w z, z')): the series where |X| < 0.5; else E in closed form,
// e^{-sigma tau} (c I + s Y) with Y = [[sigma, w], [-w, -sigma]] (Y^2 = (sigma^2 - w^2) I), and
// X P1 = E - I, X P2 = P1 - I.
void ModeExponential(PetscReal w, PetscReal sigma, PetscReal tau, Mat2 *E, Mat2 *P1, Mat2 *P2)
{
  const Mat2 X{0, w * tau, -w * tau, -2 * sigma * tau};
  if (tau * (w + 2 * sigma) < 0.5) {
    Mat2      pw{1, 0, 0, 1};           // X^j
    PetscReal f0 = 1, f1 = 1, f2 = 0.5; // 1/j!, 1/(j+1)!, 1/(j+2)!
    *E = *P1 = *P2 = Mat2();
    for (int j = 0; j < 30; ++j) {
      E->a += f0 * pw.a, E->b += f0 * pw.b, E->c += f0 * pw.c, E->d += f0 * pw.d;
      P1->a += f1 * pw.a, P1->b += f1 * pw.b, P1->c += f1 * pw.c, P1->d += f1 * pw.d;
      P2->a += f2 * pw.a, P2->b += f2 * pw.b, P2->c += f2 * pw.c, P2->d += f2 * pw.d;
      pw = pw * X;
      f0 /= j + 1, f1 /= j + 2, f2 /= j + 3;
    }
    return;
  }
  const PetscReal d2 = sigma * sigma - w * w;
  PetscReal       ec, es; // e^{-sigma tau} c and e^{-sigma tau} s
  if (d2 < 0) {
    const PetscReal wd = std::sqrt(-d2), x = wd * tau, decay = std::exp(-sigma * tau);
    ec = decay * std::cos(x);
    es = decay * (x < 1e-4 ? tau * (1 - x * x / 6) : std::sin(x) / wd);
  } else {
    const PetscReal k = std::sqrt(d2), x = k * tau;
    const PetscReal up = std::exp((k - sigma) * tau), down = std::exp(-(k + sigma) * tau);
    ec = 0.5 * (up + down);
    es = x < 1e-4 ? std::exp(-sigma * tau) * tau * (1 + x * x / 6) : 0.5 * (up - down) / k;
  }
  *E = {ec + es * sigma, es * w, -es * w, ec - es * sigma};
  // X^-1 = [[-2 sigma, -w], [w, 0]] / (w^2 tau)
  const PetscReal inv   = 1 / (w * w * tau);
  const auto      solve = [&](const Mat2 &r) {
    return Mat2{inv * (-2 * sigma * r.a - w * r.c), inv * ((-2 * sigma) * r.b - w * r.d), inv * (w * r.a),
                inv * (w * r.b)};
  };
  *P1 = solve({E->a - 1, E->b, E->c, E->d - 1});
  *P2 = solve({P1->a - 1, P1->b, P1->c, P1->d - 1});
}

} // namespace

void TangentialModeForced(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, PetscReal f0, PetscReal f1,
                          PetscReal tau, PetscReal *q, PetscReal *qd)
{
  if (!(sigma > 0)) {
    TangentialModeForced(w, z, zd, f0, f1, tau, q, qd);
    return;
  }
  if (w == 0) { // z'' + 2 sigma z' = f0 + f1 s
    const PetscReal x = -2 * sigma * tau;
    *qd               = PhiScalar(0, x) * zd + tau * PhiScalar(1, x) * f0 + tau * tau * PhiScalar(2, x) * f1;
    *q = z + tau * PhiScalar(1, x) * zd + tau * tau * PhiScalar(2, x) * f0 + tau * tau * tau * PhiScalar(3, x) * f1;
    return;
  }
  Mat2 E, P1, P2;
  ModeExponential(w, sigma, tau, &E, &P1, &P2);
  // (w z, z')(tau) = E (w z, z') + tau P1 (0, f0) + tau^2 P2 (0, f1)
  const PetscReal y0 = w * z, y1 = zd;
  *q  = (E.a * y0 + E.b * y1 + tau * P1.b * f0 + tau * tau * P2.b * f1) / w;
  *qd = E.c * y0 + E.d * y1 + tau * P1.d * f0 + tau * tau * P2.d * f1;
}

namespace {

// The response of a mode over tau (ModeKernelOf): (z, z')(tau) = [[zz, zv], [vz, vv]] (z, z')(0)
// plus sum_k c_k (gz[k], gv[k]) under the force sum_k c_k s^k.
struct ModeKernel {
  PetscReal zz = 1, zv = 0, vz = 0, vv = 1;
  PetscReal gz[4] = {0, 0, 0, 0}, gv[4] = {0, 0, 0, 0};
  void      Apply(PetscReal z, PetscReal zd, const ForceCubic &f, PetscReal *q, PetscReal *qd) const
  {
    PetscReal fz = 0, fv = 0;
    for (int k = 0; k < 4; ++k) fz += f.c[k] * gz[k], fv += f.c[k] * gv[k];
    *q  = zz * z + zv * zd + fz;
    *qd = vz * z + vv * zd + fv;
  }
};

// P[j] = phi_j(X), j = 0..4, of X = tau [[0, w], [-w, -2 sigma]] (w > 0): the series where
// |X| < 1; else e^X in closed form (ModeExponential) and phi_j = X^-1 (phi_(j-1) - I/(j-1)!).
void ModePhi4(PetscReal w, PetscReal sigma, PetscReal tau, Mat2 P[5])
{
  const Mat2      X{0, w * tau, -w * tau, -2 * sigma * tau};
  const PetscReal norm = tau * (w + 2 * sigma);
  if (norm < 1) { // phi_4 by its series (to a term below 1e-18 of it), then phi_(j-1) = I/(j-1)! + X phi_j
    Mat2      pw{1, 0, 0, 1};
    PetscReal f = 1.0 / 24, size = 1; // 1/(i + 4)!, a bound on |X^i|
    P[4] = Mat2();
    for (int i = 0; i < 30 && f * size > 1e-18 / 24; ++i) {
      P[4].a += f * pw.a, P[4].b += f * pw.b, P[4].c += f * pw.c, P[4].d += f * pw.d;
      pw = pw * X;
      f /= i + 5;
      size *= 2 * norm;
    }
    const PetscReal inv_fact[4] = {1, 1, 0.5, 1.0 / 6};
    for (int j = 4; j > 0; --j) {
      const Mat2 xp = X * P[j];
      P[j - 1]      = {inv_fact[j - 1] + xp.a, xp.b, xp.c, inv_fact[j - 1] + xp.d};
    }
    return;
  }
  ModeExponential(w, sigma, tau, &P[0], &P[1], &P[2]);
  const PetscReal inv   = 1 / (w * w * tau);
  const auto      solve = [&](const Mat2 &r) {
    return Mat2{inv * (-2 * sigma * r.a - w * r.c), inv * (-2 * sigma * r.b - w * r.d), inv * (w * r.a),
                inv * (w * r.b)};
  };
  P[3] = solve({P[2].a - 0.5, P[2].b, P[2].c, P[2].d - 0.5});
  P[4] = solve({P[3].a - 1.0 / 6, P[3].b, P[3].c, P[3].d - 1.0 / 6});
}

// The mode (w, sigma) over tau: its response to the state and to s^k, k = 0..3, exact: k! tau^(k+1)
// phi_(k+1)(X) applied to (0, 1) in the scaled state (w z, z'); a rigid mode (w = 0) in closed form.
ModeKernel ModeKernelOf(PetscReal w, PetscReal sigma, PetscReal tau)
{
  ModeKernel K;
  PetscReal  fact[4] = {1, 1, 2, 6}, tk = tau; // k!, tau^(k+1)
  if (w == 0 && !(sigma > 0)) {                // z'' = f
    K.zv = tau;
    for (int k = 0; k < 4; ++k, tk *= tau) K.gv[k] = tk / (k + 1), K.gz[k] = tk * tau / ((k + 1) * (k + 2));
    return K;
  }
  if (w == 0) { // z'' + 2 sigma z' = f: z' through phi_j(-2 sigma tau)
    const PetscReal x = -2 * sigma * tau;
    K.vv              = PhiScalar(0, x);
    K.zv              = tau * PhiScalar(1, x);
    for (int k = 0; k < 4; ++k, tk *= tau)
      K.gv[k] = fact[k] * tk * PhiScalar(k + 1, x), K.gz[k] = fact[k] * tk * tau * PhiScalar(k + 2, x);
    return K;
  }
  Mat2 P[5];
  ModePhi4(w, sigma, tau, P);
  K.zz = P[0].a, K.zv = P[0].b / w, K.vz = P[0].c * w, K.vv = P[0].d;
  for (int k = 0; k < 4; ++k, tk *= tau) K.gz[k] = fact[k] * tk * P[k + 1].b / w, K.gv[k] = fact[k] * tk * P[k + 1].d;
  return K;
}

} // namespace

void TangentialModeForced(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, const ForceCubic &f, PetscReal tau,
                          PetscReal *q, PetscReal *qd)
{
  ModeKernelOf(w, std::max<PetscReal>(sigma, 0), tau).Apply(z, zd, f, q, qd);
}

TangentialState TangentialFlexibleStart(const TangentialModel &m, const TangentialPlane &p)
{
  return TangentialStart(m, p.ball_side - p.PointVelocity());
}

namespace {

// The plane's modes over one length tau, and the point's response to the force s^j from rest
// summed over them (the plane's gamma: a trial is the state's drift plus these, PlaneTry).
struct PlaneKernels {
  PetscReal               tau = 0;
  std::vector<ModeKernel> mode;
  PetscReal               fz[4] = {0, 0, 0, 0}, fv[4] = {0, 0, 0, 0}; // sum_k gamma_k^2 gz[j], gamma_k^2 gv[j]
};

} // namespace

// The kernels of the last sub-step lengths (a fixed-step run's steps repeat the rest length and
// its Gauss points), for the omega, sigma and gamma they were made for.
struct TangentialKernelCache {
  std::vector<PetscReal>                           omega, sigma, gamma;
  std::vector<std::shared_ptr<const PlaneKernels>> entry; // at most kSize, replaced in turn
  size_t                                           next  = 0;
  static constexpr size_t                          kSize = 8;
};

namespace {

// The kernels over exactly tau, not kept (a bisection's trial lengths: each is used once, and a
// kept length within 1e-12 would stand in for it and stall the bisection at that resolution).
std::shared_ptr<const PlaneKernels> PlaneKernelsExact(const TangentialPlane &p, PetscReal tau)
{
  auto K = std::make_shared<PlaneKernels>();
  K->tau = tau;
  K->mode.resize(p.omega.size());
  for (size_t k = 0; k < p.omega.size(); ++k) {
    const ModeKernel &Kk = K->mode[k] = ModeKernelOf(p.omega[k], p.Sigma(k), tau);
    const PetscReal   g2              = p.gamma[k] * p.gamma[k];
    for (int j = 0; j < 4; ++j) K->fz[j] += g2 * Kk.gz[j], K->fv[j] += g2 * Kk.gv[j];
  }
  return K;
}

// The plane's kernel cache emptied unless it was made for its omega, sigma and gamma (checked
// once per piece of F_n: PlaneKernelsOf, four times a sub-step, trusts it).
void PlaneKernelCacheCheck(const TangentialPlane &p)
{
  if (!p.cache || p.cache->omega != p.omega || p.cache->sigma != p.sigma || p.cache->gamma != p.gamma) {
    p.cache        = std::make_shared<TangentialKernelCache>();
    p.cache->omega = p.omega;
    p.cache->sigma = p.sigma;
    p.cache->gamma = p.gamma;
  }
}

// The kernels over tau: from the cache where a length equal to tau to 1e-12 (the steps' lengths
// are differences of times that carry that round-off) is kept, else computed and kept.
std::shared_ptr<const PlaneKernels> PlaneKernelsOf(const TangentialPlane &p, PetscReal tau)
{
  if (!p.cache) PlaneKernelCacheCheck(p);
  TangentialKernelCache &C = *p.cache;
  for (const auto &e : C.entry)
    if (std::abs(e->tau - tau) <= 1e-12 * tau) return e;
  auto K = PlaneKernelsExact(p, tau);
  if (C.entry.size() < TangentialKernelCache::kSize) C.entry.push_back(K);
  else C.entry[C.next++ % TangentialKernelCache::kSize] = K;
  return K;
}

// A trial sub-step of length K.tau from the plane's state with the cubic F_t = f(s): the point's
// displacement change and end velocity, the ball side at the end and its integral.
struct PlaneTrial {
  PetscReal disp = 0, vel = 0, ws = 0, ws_int = 0;
  PetscReal U() const { return ws - vel; }
};

// The point's motion over K.tau that the plane's state gives with no force: its displacement
// change and end velocity (the one pass over the modes of a trial; PlaneTry adds the force's part).
struct PlaneDrift {
  PetscReal disp = 0, vel = 0;
};
PlaneDrift PlaneDriftOf(const TangentialPlane &p, const PlaneKernels &K)
{
  PlaneDrift d;
  for (size_t k = 0; k < p.omega.size(); ++k) {
    const ModeKernel &Kk = K.mode[k];
    d.disp += p.gamma[k] * ((Kk.zz - 1) * p.z[k] + Kk.zv * p.zd[k]);
    d.vel += p.gamma[k] * (Kk.vz * p.z[k] + Kk.vv * p.zd[k]);
  }
  return d;
}
// Its velocity alone (disp 0: for a trial's U() only).
PlaneDrift PlaneDriftVelocityOf(const TangentialPlane &p, const PlaneKernels &K)
{
  PlaneDrift d;
  for (size_t k = 0; k < p.omega.size(); ++k) d.vel += p.gamma[k] * (K.mode[k].vz * p.z[k] + K.mode[k].vv * p.zd[k]);
  return d;
}

// drift: the state's (PlaneDriftOf over the same K), or null: from rest (the state left out), for
// the responses to a unit force. Linear in f: the force's part from K's sums over the modes.
PlaneTrial PlaneTry(const TangentialPlane &p, const PlaneKernels &K, PetscReal inv_me, const ForceCubic &f,
                    const PlaneDrift *drift)
{
  const PetscReal tau = K.tau;
  PlaneTrial      t;
  if (drift) t.disp = drift->disp, t.vel = drift->vel;
  for (int j = 0; j < 4; ++j) t.disp -= f.c[j] * K.fz[j], t.vel -= f.c[j] * K.fv[j];
  t.disp -= p.flexibility * (f(tau) - f(0)); // the modes left out: the point at -G_r F_t
  t.vel -= p.flexibility * f.Rate(tau);
  const PetscReal w0 = drift ? p.ball_side : 0;
  const PetscReal ff = tau * tau *
                       (f.c[0] / 2 +
                        tau * (f.c[1] / 6 + tau * (f.c[2] / 12 + tau * f.c[3] / 20))); // the double integral
  t.ws     = w0 + f.Integral(tau) * inv_me;
  t.ws_int = w0 * tau + ff * inv_me;
  return t;
}

// Whether a rigid grip (l = 0) on p takes the cubic of RigidGripForce: a plane with modes and no
// static flexibility (a string bed's mains, a bat's plane with every mode kept). With G_r > 0 the
// grip's force has its own dynamics (u = 0 fixes its rate): a constant force that ends u at 0.
bool RigidGripCubic(const TangentialPlane &p) { return p.flexibility == 0 && !p.omega.empty(); }

// A rigid grip's force on a plane without static flexibility. u = w - V stays 0, so u' = 0 gives
// F_t from the state, F = -sum g (w^2 z + 2 sigma z') / (1/m_e + sum g^2), and u'' = 0 its rate;
// the cubic Hermite from those and, at the end, u(tau) and the integral of u over the sub-step as
// if u stayed at its start (a constant force that only ends u at 0, as with G_r > 0, makes every
// tangential output converge at order 2 in the step whatever the integrator: docs/convergence.md).
ForceCubic RigidGripForce(PetscReal inv_me, const TangentialPlane &p, const PlaneKernels &K, const PlaneDrift &d)
{
  PetscReal g2 = 0, a = 0;
  for (size_t k = 0; k < p.omega.size(); ++k) {
    const PetscReal g = p.gamma[k];
    g2 += g * g, a += g * (p.omega[k] * p.omega[k] * p.z[k] + 2 * p.Sigma(k) * p.zd[k]);
  }
  const PetscReal den = inv_me + g2, F0 = -a / den;
  PetscReal       b = 0;
  for (size_t k = 0; k < p.omega.size(); ++k) {
    const PetscReal w2 = p.omega[k] * p.omega[k], zdd = -w2 * p.z[k] - 2 * p.Sigma(k) * p.zd[k] - p.gamma[k] * F0;
    b += p.gamma[k] * (w2 * p.zd[k] + 2 * p.Sigma(k) * zdd);
  }
  const PetscReal D0 = -b / den, tau = K.tau;
  PetscReal       w = 0; // rad/s, the plane's fastest mode: within 1e-6 rad of it (a switch's bisection)
  for (PetscReal wk : p.omega) w = std::max(w, wk); // the line from F0, D0 is exact to round-off, and
  if (w * tau < 1e-6) return ForceCubic::Hermite(tau, F0, F0 + D0 * tau, D0, D0); // the 2 x 2 below is not
  const PlaneTrial A = PlaneTry(p, K, inv_me, ForceCubic::Hermite(tau, F0, 0, D0, 0), &d);
  const PlaneTrial B = PlaneTry(p, K, inv_me, ForceCubic::Hermite(tau, 0, 1, 0, 0), nullptr);
  const PlaneTrial C = PlaneTry(p, K, inv_me, ForceCubic::Hermite(tau, 0, 0, 0, 1), nullptr);
  // u(tau) = A.U + Fe B.U + De C.U = u0, its integral A.X + Fe B.X + De C.X = u0 tau (X = ws_int -
  // disp): u keeps the start's residual u0 (a switch's, to the bisection's resolution), which a
  // correction to 0 would turn into a force ~ u0/tau on the switch's sub-step of ~1e-15 of a step
  const PetscReal u0  = p.ball_side - p.PointVelocity();
  const PetscReal a11 = B.U(), a12 = C.U(), a21 = B.ws_int - B.disp, a22 = C.ws_int - C.disp;
  const PetscReal r1 = u0 - A.U(), r2 = u0 * tau - (A.ws_int - A.disp), det = a11 * a22 - a12 * a21;
  return ForceCubic::Hermite(tau, F0, (r1 * a22 - a12 * r2) / det, D0, (a11 * r2 - a21 * r1) / det);
}

// The force over a sub-step of length K.tau the current phase gives (F_n = Fn(s); d: the state's drift over K).
ForceCubic PhaseForce(const TangentialModel &m, PetscReal inv_me, const TangentialPlane &p, const PlaneKernels &K,
                      const PlaneDrift &d, const TangentialState &s, const ForceCubic &Fn)
{
  const PetscReal mu = m.friction, l = m.compliance_length, tau = K.tau;
  if (s.phase == TangentialPhase::Slip) return Fn.Scaled(-s.slip_sign * mu);
  if (l > 0) { // Hermite: F_t and dF_t/dt at the start and (unknown: Fe, De) at the end, the law's
    const PetscReal  D0 = -(Fn.Rate(0) * s.xi + Fn(0) * s.u) / l;
    const PlaneTrial a  = PlaneTry(p, K, inv_me, ForceCubic::Hermite(tau, p.force, 0, D0, 0), &d);
    const PlaneTrial b  = PlaneTry(p, K, inv_me, ForceCubic::Hermite(tau, 0, 1, 0, 0), nullptr);
    const PlaneTrial c  = PlaneTry(p, K, inv_me, ForceCubic::Hermite(tau, 0, 0, 0, 1), nullptr);
    // xi(tau) = X0 + Fe Xb + De Xc, u(tau) = U0 + Fe Ub + De Uc; Fe = -P xi, De = -(Q xi + P u)
    const PetscReal X0 = s.xi + a.ws_int - a.disp, Xb = b.ws_int - b.disp, Xc = c.ws_int - c.disp;
    const PetscReal P = Fn(tau) / l, Q = Fn.Rate(tau) / l;
    const PetscReal a11 = 1 + P * Xb, a12 = P * Xc, r1 = -P * X0;
    const PetscReal a21 = Q * Xb + P * b.U(), a22 = 1 + Q * Xc + P * c.U(), r2 = -(Q * X0 + P * a.U());
    const PetscReal det = a11 * a22 - a12 * a21;
    return ForceCubic::Hermite(tau, p.force, (r1 * a22 - a12 * r2) / det, D0, (a11 * r2 - a21 * r1) / det);
  }
  if (RigidGripCubic(p)) return RigidGripForce(inv_me, p, K, d);
  // rigid grip with G_r > 0: a constant force over the sub-step that ends it at u = 0
  ForceCubic unit, f;
  unit.c[0] = 1;
  f.c[0]    = -PlaneTry(p, K, inv_me, ForceCubic(), &d).U() / PlaneTry(p, K, inv_me, unit, nullptr).U();
  return f;
}

// Whether the current phase ends within the sub-step tried.
bool PhaseEnds(const TangentialModel &m, const TangentialPlane &p, const TangentialState &s, const PlaneTrial &t,
               const ForceCubic &f, PetscReal tau, const ForceCubic &Fn)
{
  const PetscReal mu = m.friction, l = m.compliance_length;
  // (margins of round-off: a slip that starts from a rigid grip starts at u = 0)
  if (s.phase == TangentialPhase::Slip) return s.slip_sign * t.U() < -1e-13 * (std::abs(t.ws) + std::abs(t.vel));
  if (l > 0) return std::abs(s.xi + t.ws_int - t.disp) > mu * l;
  if (RigidGripCubic(p)) { // the cubic force within the cone at its ends and three points between
    for (int i = 0; i <= 4; ++i)
      if (std::abs(f(tau * i / 4)) > (1 + 1e-12) * mu * Fn(tau * i / 4)) return true;
    return false;
  }
  return std::abs(f(0)) > (1 + 1e-12) * mu * std::min(Fn(0), Fn(tau));
}

// Moves the plane and the contact's state over K.tau with F_t = f(s) (t: its trial from the
// state); the energy taken, integral -F_t u, and the modes' damping loss by 3-point Gauss from
// the exact u and z'.
void PlaneCommit(const TangentialModel &m, PetscReal inv_me, const PlaneKernels &K, const ForceCubic &f,
                 const PlaneTrial &t, TangentialPlane *p, TangentialState *s)
{
  static const PetscReal gx[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const PetscReal        tau = K.tau;
  for (int i = 0; i < 3; ++i) {
    const PetscReal     si = 0.5 * tau * (1 + gx[i]);
    const auto          Kp = PlaneKernelsOf(*p, si); // held: a later insertion may replace it in the cache
    const PlaneKernels &Ki = *Kp;
    const PlaneDrift    di = PlaneDriftVelocityOf(*p, Ki); // u = w - V_c: the trial's velocity alone
    s->dissipated += 0.5 * tau * gw[i] * (-f(si) * PlaneTry(*p, Ki, inv_me, f, &di).U());
    for (size_t k = 0; k < p->sigma.size(); ++k) { // the modes' damping: integral 2 sigma z'^2
      if (!(p->sigma[k] > 0)) continue;
      PetscReal q, qd;
      Ki.mode[k].Apply(p->z[k], p->zd[k], f.Scaled(-p->gamma[k]), &q, &qd);
      p->damped += 0.5 * tau * gw[i] * 2 * p->sigma[k] * qd * qd;
    }
  }
  for (size_t k = 0; k < p->omega.size(); ++k)
    K.mode[k].Apply(p->z[k], p->zd[k], f.Scaled(-p->gamma[k]), &p->z[k], &p->zd[k]);
  if (s->phase == TangentialPhase::Grip && m.compliance_length > 0) s->xi += t.ws_int - t.disp;
  p->ball_side = t.ws;
  p->force     = f(tau);
  p->time += tau;
  p->substeps++;
  s->impulse += f.Integral(tau);
  s->u = t.U();
}

// The phase switch at the end of a committed sub-step whose phase ended.
void PhaseSwitch(const TangentialModel &m, TangentialPlane *p, TangentialState *s)
{
  const PetscReal  mu = m.friction, l = m.compliance_length;
  TangentialSwitch sw;
  sw.time = p->time;
  if (s->phase == TangentialPhase::Slip) {
    s->phase = TangentialPhase::Grip;
  } else {
    s->phase     = TangentialPhase::Slip;
    s->slip_sign = l > 0 ? (s->xi > 0 ? 1 : -1) : (p->force > 0 ? -1 : 1); // F_t = -s mu F_n opposes the slip
    if (l > 0) s->xi = s->slip_sign * mu * l;
  }
  sw.to = s->phase;
  s->switches.push_back(sw);
}

// One sub-step of length h with F_n = Fn(s): the phase's force, its end located by bisection of
// the length where it ends, the switch, and the rest in the new phase.
void PlaneSubStep(const TangentialModel &m, PetscReal inv_me, PetscReal h, const ForceCubic &Fn, TangentialPlane *p,
                  TangentialState *s)
{
  PetscReal tau = 0;
  for (int it = 0; it < 16 && tau < (1 - 1e-12) * h; ++it) {
    if (s->phase == TangentialPhase::Slip && s->slip_sign == 0) s->phase = TangentialPhase::Grip;
    const PetscReal     rest = h - tau;
    const ForceCubic    Fb   = Fn.Shift(tau);
    const auto          Kp   = PlaneKernelsOf(*p, rest);
    const PlaneKernels &K    = *Kp;
    const PlaneDrift    d    = PlaneDriftOf(*p, K);
    ForceCubic          f    = PhaseForce(m, inv_me, *p, K, d, *s, Fb);
    if (s->phase == TangentialPhase::Slip) p->force = f(0); // continuous into a slip: -s mu F_n
    const PlaneTrial t = PlaneTry(*p, K, inv_me, f, &d);
    if (!PhaseEnds(m, *p, *s, t, f, rest, Fb) || it == 15) {
      PlaneCommit(m, inv_me, K, f, t, p, s);
      return;
    }
    PetscReal lo = 0, hi = rest;
    for (int b = 0; b < 200 && hi - lo > 1e-15 * rest; ++b) {
      const PetscReal  mid = 0.5 * (lo + hi);
      const auto       Km  = PlaneKernelsExact(*p, mid);
      const PlaneDrift dm  = PlaneDriftOf(*p, *Km);
      f                    = PhaseForce(m, inv_me, *p, *Km, dm, *s, Fb);
      if (PhaseEnds(m, *p, *s, PlaneTry(*p, *Km, inv_me, f, &dm), f, mid, Fb)) hi = mid;
      else lo = mid;
    }
    const auto       Kh = PlaneKernelsExact(*p, hi); // the switch at exactly hi (tau += hi below)
    const PlaneDrift dh = PlaneDriftOf(*p, *Kh);
    const ForceCubic fh = PhaseForce(m, inv_me, *p, *Kh, dh, *s, Fb);
    PlaneCommit(m, inv_me, *Kh, fh, PlaneTry(*p, *Kh, inv_me, fh, &dh), p, s);
    PhaseSwitch(m, p, s);
    tau += hi;
  }
}

// The plane free (F_t = 0) over h: each mode exactly; a damped mode's loss is its energy's drop.
void PlaneFree(PetscReal h, TangentialPlane *p)
{
  for (size_t k = 0; k < p->omega.size(); ++k) {
    const PetscReal w = p->omega[k], E0 = 0.5 * (p->zd[k] * p->zd[k] + w * w * p->z[k] * p->z[k]);
    TangentialModeForced(w, p->Sigma(k), p->z[k], p->zd[k], 0, 0, h, &p->z[k], &p->zd[k]);
    if (p->Sigma(k) > 0) p->damped += E0 - 0.5 * (p->zd[k] * p->zd[k] + w * w * p->z[k] * p->z[k]);
  }
}

} // namespace

void TangentialAdvanceFlexible(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1,
                               TangentialPlane *p, TangentialState *s)
{
  const PetscReal d = t1 > t0 ? (F1 - F0) / (t1 - t0) : 0;
  TangentialAdvanceFlexible(m, t0, t1, F0, F1, d, d, p, s);
}

void TangentialAdvanceFlexible(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1,
                               PetscReal dF0, PetscReal dF1, TangentialPlane *p, TangentialState *s)
{
  const PetscReal h = t1 - t0;
  if (!(h > 0)) return;
  TangentialModel ball   = m;
  ball.bat_mass          = PETSC_INFINITY; // the plane is the bat's translation
  const PetscReal inv_me = 1 / ball.EffectiveMass();
  PlaneKernelCacheCheck(*p);
  if (t0 > p->time) { // free since the plane's time: F_t = 0
    PlaneFree(t0 - p->time, p);
    p->force = 0;
    p->time  = t0;
  }
  if (F0 == 0 && F1 == 0) { // not touching: no tangential force, the spring relaxed
    PlaneFree(h, p);
    p->force = 0;
    p->time  = t1;
    s->xi    = 0;
    s->u     = p->ball_side - p->PointVelocity();
    return;
  }
  const ForceCubic Fn = ForceCubic::Hermite(h, F0, F1, dF0, dF1);
  s->normal_impulse += Fn.Integral(h);
  // Sub-steps: 100 per radian of the compliant grip's fastest oscillation, at least one.
  PetscReal G = p->flexibility;
  for (PetscReal g : p->gamma) G += g * g;
  // A rigid grip's cubic (RigidGripForce): 10 per radian of the plane's fastest mode (the ball's
  // mass at the point only lowers the gripped plane's frequencies; 100 gave the same errors to 3
  // digits in study-racket-oblique and cost a bat's plane of every mode 4 times its run).
  const PetscReal l = m.compliance_length;
  PetscReal       w = l > 0 ? std::sqrt(std::max(F0, F1) / l * (inv_me + G)) : 0;
  if (!(l > 0) && RigidGripCubic(*p))
    for (PetscReal wk : p->omega) w = std::max(w, 0.1 * wk);
  const PetscInt n = std::max<PetscInt>(1, (PetscInt)std::ceil(100 * w * h));
  for (PetscInt k = 0; k < n; ++k) {
    const PetscReal a = h * k / n, b = h * (k + 1) / n;
    PlaneSubStep(ball, inv_me, b - a, Fn.Shift(a), p, s);
  }
  p->time = t1; // the sub-steps' sum, to round-off
}

TangentialPlane BedInPlaneOf(const BedInPlaneModel &b, PetscInt *rigid)
{
  TangentialPlane p;
  const bool      held = !(b.frame_mass < PETSC_INFINITY); // PETSC_INFINITY is finite
  const PetscReal M = b.frame_mass, m = b.strings_mass;
  *rigid = held ? 0 : 1;
  if (!held) p.omega.push_back(0), p.gamma.push_back(1 / std::sqrt(M + m));
  p.omega.push_back(std::sqrt(b.stiffness * (1 / m + (held ? 0 : 1 / M))));
  p.gamma.push_back(held ? 1 / std::sqrt(m) : std::sqrt(M / (m * (M + m))));
  p.z.assign(p.omega.size(), 0.0);
  p.zd.assign(p.omega.size(), 0.0);
  return p;
}

PetscReal BedInPlaneSlide(const BedInPlaneModel &b, const TangentialPlane &p)
{
  const size_t k = p.omega.size() - 1; // the flexible mode, the last
  return (b.frame_mass < PETSC_INFINITY ? 1 + b.strings_mass / b.frame_mass : 1) * p.gamma[k] * p.z[k];
}

PetscReal BedInPlaneEnergy(const TangentialPlane &p, PetscInt rigid)
{
  PetscReal E = 0;
  for (size_t k = (size_t)rigid; k < p.omega.size(); ++k)
    E += 0.5 * (p.zd[k] * p.zd[k] + p.omega[k] * p.omega[k] * p.z[k] * p.z[k]);
  return E;
}

} // namespace beamimpact

// A ball against a rigid, fixed wall, integrated apart from the program (RK4 with bisected
// roots), for tests of the contact laws against their closed forms and presets. Any force law:
// the caller passes the force and what happens at the maximum compression.
#pragma once

#include <functional>

namespace beamimpact::test {

struct WallBounce {
  double cor = 0, contact_time = 0, max_compression = 0, loading_time = 0;
};

// A ball of mass m against a rigid, fixed wall at speed v: m c'' = -force(c), at_max(c) called
// at the maximum compression (dc/dt = 0: the switch to unloading), until the separation at
// c = 0. RK4 at step h; each root is bisected by re-stepping from the step's start.
inline WallBounce Bounce(const std::function<double(double)> &force, const std::function<void(double)> &at_max, double mass, double v, double h)
{
  auto rk4 = [&](double &c, double &u, double dt) {
    const double c1 = u, u1 = -force(c) / mass;
    const double c2 = u + 0.5 * dt * u1, u2 = -force(c + 0.5 * dt * c1) / mass;
    const double c3 = u + 0.5 * dt * u2, u3 = -force(c + 0.5 * dt * c2) / mass;
    const double c4 = u + dt * u3, u4 = -force(c + dt * c3) / mass;
    c += dt / 6 * (c1 + 2 * c2 + 2 * c3 + c4);
    u += dt / 6 * (u1 + 2 * u2 + 2 * u3 + u4);
  };
  double     t = 0, c = 0, u = v;
  WallBounce w;
  for (int phase = 0; phase < 2; ++phase) {
    const bool loading = phase == 0;
    for (long it = 0; it < 10000000L; ++it) {
      double cn = c, un = u;
      rk4(cn, un, h);
      if (!(loading ? un <= 0 : cn <= 0)) {
        c = cn, u = un, t += h;
        continue;
      }
      double lo = 0, hi = h;
      for (int k = 0; k < 200 && hi - lo > 1e-16 * h; ++k) {
        const double mid = 0.5 * (lo + hi);
        double       cm = c, um = u;
        rk4(cm, um, mid);
        if (loading ? um <= 0 : cm <= 0) hi = mid;
        else lo = mid;
      }
      rk4(c, u, hi);
      t += hi;
      break;
    }
    if (loading) {
      w.max_compression = c;
      w.loading_time    = t;
      at_max(c);
    }
  }
  w.cor          = -u / v;
  w.contact_time = t;
  return w;
}

} // namespace beamimpact::test

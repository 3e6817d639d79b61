// Contact laws of the ball: force, stiffness, energy and phase switches. See contact.hpp.
#include "model/contact.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

const char *const ContactLawNames[] = {"linear", "hysteresis", "ContactLawKind", "BALL_LAW_", nullptr};
static const char *const PhaseNames[] = {"separated", "loading", "unloading"};

const char *ContactLawName(ContactLawKind k) { return ContactLawNames[static_cast<int>(k)]; }
const char *ContactPhaseName(ContactPhase p) { return PhaseNames[static_cast<int>(p)]; }

// Odd power sgn(c)|c|^p and its even antiderivative |c|^(p+1)/(p+1).
static inline PetscReal OddPow(PetscReal c, PetscReal p) { return std::copysign(std::pow(std::abs(c), p), c); }
static inline PetscReal PowAntiderivative(PetscReal c, PetscReal p) { return std::pow(std::abs(c), p + 1) / (p + 1); }

bool ContactHasHysteresis(const BallParams &b) { return b.law == ContactLawKind::Hysteresis && (b.m != b.n || !b.cor_table.empty()); }

PetscReal ContactUnloadingExponent(const BallParams &b, const ContactState &s) { return s.n > 0 ? s.n : b.n; }

PetscReal ContactForce(const BallParams &b, const ContactState &s, PetscReal c)
{
  switch (s.phase) {
  case ContactPhase::Separated: return 0.0;
  case ContactPhase::Loading: return b.law == ContactLawKind::Linear ? b.k * c : b.k1 * OddPow(c, b.m);
  case ContactPhase::Unloading: return b.law == ContactLawKind::Linear ? b.k * c : s.k2 * OddPow(c, ContactUnloadingExponent(b, s));
  }
  return 0.0;
}

PetscReal ContactStiffness(const BallParams &b, const ContactState &s, PetscReal c)
{
  if (s.phase == ContactPhase::Separated) return 0.0;
  if (b.law == ContactLawKind::Linear) return b.k;
  const PetscReal p    = s.phase == ContactPhase::Loading ? b.m : ContactUnloadingExponent(b, s);
  const PetscReal coef = s.phase == ContactPhase::Loading ? b.k1 : s.k2;
  if (p == 1.0) return coef;
  return coef * p * std::pow(std::abs(c), p - 1);
}

PetscReal ContactStoredEnergy(const BallParams &b, const ContactState &s, PetscReal c)
{
  switch (s.phase) {
  case ContactPhase::Separated: return 0.0;
  case ContactPhase::Loading: return b.law == ContactLawKind::Linear ? 0.5 * b.k * c * c : b.k1 * PowAntiderivative(c, b.m);
  case ContactPhase::Unloading: return b.law == ContactLawKind::Linear ? 0.5 * b.k * c * c : s.k2 * PowAntiderivative(c, ContactUnloadingExponent(b, s));
  }
  return 0.0;
}

PetscReal ContactWork(const BallParams &b, const ContactState &s, PetscReal c) { return s.work_offset + ContactStoredEnergy(b, s, c); }

void ContactSwitch(const BallParams &b, ContactState *s, ContactPhase to, PetscReal c)
{
  const PetscReal before = ContactStoredEnergy(b, *s, c);
  if (to == ContactPhase::Unloading) {
    s->c_max = c;
    s->k2    = b.law == ContactLawKind::Hysteresis ? b.k1 * std::pow(std::abs(c), b.m - ContactUnloadingExponent(b, *s)) : b.k;
  }
  s->phase = to;
  s->work_offset += before - ContactStoredEnergy(b, *s, c);
}

PetscReal ContactWallTimeLinear(const BallParams &b) { return M_PI * std::sqrt(b.mass / b.k); }
PetscReal ContactWallRestitution(const BallParams &b) { return b.law == ContactLawKind::Linear ? 1.0 : std::sqrt((b.m + 1) / (b.n + 1)); }
PetscReal ContactCycleLoss(const BallParams &b, PetscReal c_max) { return (b.n - b.m) * b.k1 * std::pow(c_max, b.m + 1) / ((b.m + 1) * (b.n + 1)); }

PetscReal ContactCompressionScale(const BallParams &b)
{
  if (b.law == ContactLawKind::Linear) return b.speed * std::sqrt(b.mass / b.k);
  // Wall loading: 1/2 m v^2 = k1 c^(m+1)/(m+1).
  return std::pow(0.5 * b.mass * b.speed * b.speed * (b.m + 1) / b.k1, 1.0 / (b.m + 1));
}

PetscReal ContactTimeScale(const BallParams &b)
{
  if (b.law == ContactLawKind::Linear) return ContactWallTimeLinear(b);
  const PetscReal c    = ContactCompressionScale(b);
  const PetscReal keff = b.k1 * std::pow(c, b.m - 1); // secant stiffness at c_max
  return M_PI * std::sqrt(b.mass / keff);
}

PetscReal PowerLawWallIntegral(PetscReal p)
{
  // B(1/p, 1/2) / p with B(a, b) = Gamma(a) Gamma(b) / Gamma(a + b), through lgamma (finite for any p >= 1).
  const PetscReal a = 1.0 / p;
  return std::exp(std::lgamma(a) + std::lgamma(0.5) - std::lgamma(a + 0.5)) / p;
}

PetscReal BallExponentFromCor(PetscReal m, PetscReal e) { return std::max(m, (m + 1) / (e * e) - 1); } // e = 1: exactly m, not m - ulp

PetscReal BallCorAt(const BallParams &b, PetscReal v)
{
  if (b.law == ContactLawKind::Linear) return 1.0;
  if (!b.cor_table.empty()) return b.cor_table(v);
  return std::sqrt((b.m + 1) / (b.n + 1));
}

PetscReal BallExponentAt(const BallParams &b, PetscReal v) { return b.cor_table.empty() ? b.n : BallExponentFromCor(b.m, b.cor_table(v)); }

PetscReal ContactWallMaxCompression(const BallParams &b, PetscReal v)
{
  if (b.law == ContactLawKind::Linear) return v * std::sqrt(b.mass / b.k);
  return std::pow(0.5 * (b.m + 1) * b.mass * v * v / b.k1, 1.0 / (b.m + 1));
}

PetscReal ContactWallLoadingTime(const BallParams &b, PetscReal v)
{
  if (b.law == ContactLawKind::Linear) return 0.5 * ContactWallTimeLinear(b);
  return ContactWallMaxCompression(b, v) / v * PowerLawWallIntegral(b.m + 1);
}

PetscReal ContactWallUnloadingTime(const BallParams &b, PetscReal v)
{
  if (b.law == ContactLawKind::Linear) return 0.5 * ContactWallTimeLinear(b);
  const PetscReal e = BallCorAt(b, v), n = BallExponentAt(b, v);
  return ContactWallMaxCompression(b, v) / (e * v) * PowerLawWallIntegral(n + 1);
}

PetscReal ContactWallTime(const BallParams &b, PetscReal v) { return ContactWallLoadingTime(b, v) + ContactWallUnloadingTime(b, v); }

PetscReal BallK1FromContactTime(PetscReal mass, PetscReal m, PetscReal e, PetscReal tau, PetscReal v)
{
  const PetscReal n    = BallExponentFromCor(m, e);
  const PetscReal tau1 = (PowerLawWallIntegral(m + 1) + PowerLawWallIntegral(n + 1) / e) / v; // tau at k1 = A, in units where c_max = 1
  return 0.5 * (m + 1) * mass * v * v * std::pow(tau1 / tau, m + 1);
}

} // namespace beamimpact

// Contact laws of the ball: force, stiffness, energy and phase switches. See contact.hpp.
#include "model/contact.hpp"

#include <cmath>

namespace beamimpact {

static const char *const LawNames[]   = {"linear", "hysteresis", "ContactLawKind", "BALL_LAW_", nullptr};
static const char *const PhaseNames[] = {"separated", "loading", "unloading"};

const char *ContactLawName(ContactLawKind k) { return LawNames[static_cast<int>(k)]; }
const char *ContactPhaseName(ContactPhase p) { return PhaseNames[static_cast<int>(p)]; }

// Odd power sgn(c)|c|^p and its even antiderivative |c|^(p+1)/(p+1).
static inline PetscReal OddPow(PetscReal c, PetscReal p) { return std::copysign(std::pow(std::abs(c), p), c); }
static inline PetscReal PowAntiderivative(PetscReal c, PetscReal p) { return std::pow(std::abs(c), p + 1) / (p + 1); }

bool ContactHasHysteresis(const BallParams &b) { return b.law == ContactLawKind::Hysteresis && b.m != b.n; }

PetscReal ContactForce(const BallParams &b, const ContactState &s, PetscReal c)
{
  switch (s.phase) {
  case ContactPhase::Separated: return 0.0;
  case ContactPhase::Loading: return b.law == ContactLawKind::Linear ? b.k * c : b.k1 * OddPow(c, b.m);
  case ContactPhase::Unloading: return b.law == ContactLawKind::Linear ? b.k * c : s.k2 * OddPow(c, b.n);
  }
  return 0.0;
}

PetscReal ContactStiffness(const BallParams &b, const ContactState &s, PetscReal c)
{
  if (s.phase == ContactPhase::Separated) return 0.0;
  if (b.law == ContactLawKind::Linear) return b.k;
  const PetscReal p    = s.phase == ContactPhase::Loading ? b.m : b.n;
  const PetscReal coef = s.phase == ContactPhase::Loading ? b.k1 : s.k2;
  if (p == 1.0) return coef;
  return coef * p * std::pow(std::abs(c), p - 1);
}

PetscReal ContactStoredEnergy(const BallParams &b, const ContactState &s, PetscReal c)
{
  switch (s.phase) {
  case ContactPhase::Separated: return 0.0;
  case ContactPhase::Loading: return b.law == ContactLawKind::Linear ? 0.5 * b.k * c * c : b.k1 * PowAntiderivative(c, b.m);
  case ContactPhase::Unloading: return b.law == ContactLawKind::Linear ? 0.5 * b.k * c * c : s.k2 * PowAntiderivative(c, b.n);
  }
  return 0.0;
}

PetscReal ContactWork(const BallParams &b, const ContactState &s, PetscReal c) { return s.work_offset + ContactStoredEnergy(b, s, c); }

void ContactSwitch(const BallParams &b, ContactState *s, ContactPhase to, PetscReal c)
{
  const PetscReal before = ContactStoredEnergy(b, *s, c);
  if (to == ContactPhase::Unloading) {
    s->c_max = c;
    s->k2    = b.law == ContactLawKind::Hysteresis ? b.k1 * std::pow(std::abs(c), b.m - b.n) : b.k;
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

PetscErrorCode BallParamsFromOptions(MPI_Comm comm, BallParams *b)
{
  PetscEnum law = (PetscEnum)b->law;
  PetscBool setk = PETSC_FALSE, setk1 = PETSC_FALSE, setm = PETSC_FALSE, setn = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Ball: mass, speed and contact law (SI units)", "beamimpact");
  PetscCall(PetscOptionsReal("-ball_mass", "Ball mass m_b (kg)", "", b->mass, &b->mass, NULL));
  PetscCall(PetscOptionsReal("-ball_speed", "Incident speed v_i (m/s)", "", b->speed, &b->speed, NULL));
  PetscCall(PetscOptionsEnum("-ball_law", "Contact law", "", LawNames, law, &law, NULL));
  PetscCall(PetscOptionsReal("-ball_k", "Linear spring stiffness k (N/m); -ball_law linear", "", b->k, &b->k, &setk));
  PetscCall(PetscOptionsReal("-ball_k1", "Hysteresis loading coefficient k1 (N/m^m); -ball_law hysteresis", "", b->k1, &b->k1, &setk1));
  PetscCall(PetscOptionsReal("-ball_m", "Hysteresis loading exponent m; -ball_law hysteresis", "", b->m, &b->m, &setm));
  PetscCall(PetscOptionsReal("-ball_n", "Hysteresis unloading exponent n; -ball_law hysteresis", "", b->n, &b->n, &setn));
  PetscCall(PetscOptionsReal("-ball_loss_factor", "Factor applied to the ACOR for ball losses (reported as acor_corrected)", "", b->loss_factor, &b->loss_factor, NULL));
  PetscOptionsEnd();
  b->law = (ContactLawKind)law;

  PetscCheck(b->mass > 0 && std::isfinite(b->mass), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_mass %g is not allowed: it must be > 0 (kg)", (double)b->mass);
  PetscCheck(b->speed > 0 && std::isfinite(b->speed), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_speed %g is not allowed: it must be > 0 (m/s)", (double)b->speed);
  PetscCheck(b->loss_factor > 0 && b->loss_factor <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_loss_factor %g is not allowed: it must be in (0, 1]", (double)b->loss_factor);
  if (b->law == ContactLawKind::Linear) {
    PetscCheck(!(setk1 || setm || setn), comm, PETSC_ERR_ARG_INCOMP, "%s is a hysteresis parameter but -ball_law is linear: use -ball_k, or -ball_law hysteresis", setk1 ? "-ball_k1" : setm ? "-ball_m" : "-ball_n");
    PetscCheck(b->k > 0 && std::isfinite(b->k), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_k %g is not allowed: it must be > 0 (N/m)", (double)b->k);
  } else {
    PetscCheck(!setk, comm, PETSC_ERR_ARG_INCOMP, "-ball_k is the linear spring stiffness but -ball_law is hysteresis: use -ball_k1, -ball_m, -ball_n");
    PetscCheck(b->k1 > 0 && std::isfinite(b->k1), comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_k1 %g is not allowed: it must be > 0", (double)b->k1);
    PetscCheck(b->m >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_m %g is not allowed: the loading exponent must be >= 1", (double)b->m);
    PetscCheck(b->n >= b->m, comm, PETSC_ERR_ARG_OUTOFRANGE, "-ball_n %g is not allowed: the unloading exponent must be >= m = %g (energy can only be lost)", (double)b->n, (double)b->m);
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

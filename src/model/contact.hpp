// Ball-beam contact laws (MODEL.md section 1), as plain functions of the
// compression c = y_ball - y_beam(x_imp) (m). Force F (N) acts only in contact:
//   linear      F = k c
//   hysteresis  F = k1 c^m while compressing, F = k2 c^n while expanding,
//               k2 = k1 c_max^(m-n) (continuous at maximum compression).
// Inside a contact phase the laws are extended oddly to c < 0 (F = k sgn(c)|c|^p)
// so that the right-hand side is smooth up to the located separation event.
// Energy: W = integral F dc is the work done on the ball (stored + dissipated);
// with W the total energy KE_ball + KE_beam + U_beam + W is exactly conserved.
#pragma once

#include <petscsys.h>

namespace beamimpact {

enum class ContactLawKind { Linear = 0, Hysteresis = 1 };
const char *ContactLawName(ContactLawKind k);

struct BallParams {
  PetscReal      mass        = 0.042; // kg
  PetscReal      speed       = 1.0;   // m/s, incident speed v_i (moving in +y)
  ContactLawKind law         = ContactLawKind::Linear;
  PetscReal      k           = 2e4;   // N/m, linear spring
  PetscReal      k1          = 2e4;   // N/m^m, hysteresis loading coefficient
  PetscReal      m           = 1.0;   // loading exponent
  PetscReal      n           = 1.768; // unloading exponent
  PetscReal      loss_factor = 0.85;  // ACOR correction for ball losses (linear spring)
};

// Which branch of the law is active: the phase of the event-driven model.
enum class ContactPhase { Separated = 0, Loading = 1, Unloading = 2 };
const char *ContactPhaseName(ContactPhase p);

struct ContactState {
  ContactPhase phase   = ContactPhase::Loading; // the ball starts touching, moving in
  PetscReal    c_max   = 0;   // m, compression at the last loading->unloading switch
  PetscReal    k2      = 0;   // N/m^n, unloading coefficient for that c_max
  PetscReal    work_offset = 0; // J, W minus the active branch's antiderivative
};

// Contact force F(c) (N) in the current phase (0 when separated).
PetscReal ContactForce(const BallParams &b, const ContactState &s, PetscReal c);
// dF/dc (N/m) in the current phase.
PetscReal ContactStiffness(const BallParams &b, const ContactState &s, PetscReal c);
// Energy stored in the ball (J): the active branch's antiderivative at c.
PetscReal ContactStoredEnergy(const BallParams &b, const ContactState &s, PetscReal c);
// W = stored + dissipated (J), continuous in time.
PetscReal ContactWork(const BallParams &b, const ContactState &s, PetscReal c);
// Phase switches at compression c, keeping W continuous.
void ContactSwitch(const BallParams &b, ContactState *s, ContactPhase to, PetscReal c);
// Whether the law's force changes formula at the loading<->unloading switch.
bool ContactHasHysteresis(const BallParams &b);

// Closed forms on a rigid, fixed wall (tests and diagnostics):
// linear spring contact time pi sqrt(m/k); hysteresis e^2 = (m+1)/(n+1);
// energy lost in one cycle (n-m) k1 c_max^(m+1) / ((m+1)(n+1)).
PetscReal ContactWallTimeLinear(const BallParams &b);
PetscReal ContactWallRestitution(const BallParams &b);
PetscReal ContactCycleLoss(const BallParams &b, PetscReal c_max);
// A contact-time scale (s) for either law: pi sqrt(m/k) with k (linear) or an
// equivalent stiffness at the wall maximum compression (hysteresis).
PetscReal ContactTimeScale(const BallParams &b);
// Compression scale (m): v_i sqrt(m_b/k_eff).
PetscReal ContactCompressionScale(const BallParams &b);

// Reads -ball_* options; checks ranges with messages naming option and value.
PetscErrorCode BallParamsFromOptions(MPI_Comm comm, BallParams *b);

} // namespace beamimpact

// Ball-beam contact laws (docs/model.md), as plain functions of the
// compression c = y_ball - y_beam(x_imp) (m). Force F (N) acts only in contact:
//   linear      F = k c
//   hysteresis  F = k1 c^m while compressing, F = k2 c^n while expanding,
//               k2 = k1 c_max^(m-n) (continuous at maximum compression).
// Inside a contact phase the laws are extended oddly to c < 0 (F = k sgn(c)|c|^p)
// so that the right-hand side is smooth up to the located separation event.
// Energy: W = integral F dc is the work done on the ball (stored + dissipated);
// with W the total energy KE_ball + KE_beam + U_beam + W is exactly conserved.
//
// A real ball (MODEL section 6, docs/model.md section 2): the hysteretic law characterised the
// way a ball is tested, by its rigid-wall coefficient of restitution e and contact time tau
// at a test speed (-ball_cor, -ball_contact_time, -ball_test_speed with -ball_m), which give
// n and k1 in closed form; optionally e follows a table e(v) of the approach speed
// (-ball_cor_table), and then n is set at the start of each contact.
#pragma once

#include "model/cor_table.hpp"

#include <petscsys.h>

namespace beamimpact {

enum class ContactLawKind { Linear = 0, Hysteresis = 1 };
const char *ContactLawName(ContactLawKind k);
extern const char *const ContactLawNames[]; // PETSc enum list: names, type, prefix, nullptr

struct BallParams {
  PetscReal      mass        = 0.042; // kg
  PetscReal      speed       = 1.0;   // m/s, incident speed v_i (moving in +y)
  ContactLawKind law         = ContactLawKind::Linear;
  PetscReal      k           = 2e4;   // N/m, linear spring
  PetscReal      k1          = 2e4;   // N/m^m, hysteresis loading coefficient
  PetscReal      m           = 1.0;   // loading exponent
  PetscReal      n           = 1.768; // unloading exponent
  PetscReal      loss_factor = 0.85;  // ACOR correction for ball losses (linear spring)
  PetscReal      radius      = 0;     // m, -ball_radius: a compression beyond it is flagged (0: not given, no check)
  // The characterisation k1 and n were derived from (0: not given): the rigid-wall
  // coefficient of restitution e and contact time tau (s, contact to separation) at the test
  // speed (m/s). With a table, cor is the table's e at the test speed.
  PetscReal      cor = 0, contact_time = 0, test_speed = 0;
  // -ball_cor_table: e(v) of the approach speed (empty: n is fixed). With it, n above is
  // the exponent at the incident speed, and each contact sets its own from e(v_approach).
  CorTable       cor_table;
};

// Which branch of the law is active: the phase of the event-driven model.
enum class ContactPhase { Separated = 0, Loading = 1, Unloading = 2 };
const char *ContactPhaseName(ContactPhase p);

struct ContactState {
  ContactPhase phase   = ContactPhase::Loading; // the ball starts touching, moving in
  PetscReal    c_max   = 0;   // m, compression at the last loading->unloading switch
  PetscReal    k2      = 0;   // N/m^n, unloading coefficient for that c_max
  PetscReal    work_offset = 0; // J, W minus the active branch's antiderivative
  PetscReal    n       = 0;   // unloading exponent of this contact (0: the ball's n); set from e(v) with a table
};

// The unloading exponent in force in state s.
PetscReal ContactUnloadingExponent(const BallParams &b, const ContactState &s);

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

// The power-law ball on a rigid wall, arriving at speed v (MODEL section 6). Loading from
// 1/2 m_b v^2 - 1/2 m_b cdot^2 = k1 c^(m+1)/(m+1): c_max = ((m+1) m_b v^2 / (2 k1))^(1/(m+1)),
// t_load = (c_max/v) I(m+1); unloading from k2 c_max^(n+1)/(n+1) = e^2 1/2 m_b v^2: the ball
// leaves at e v and t_unload = (c_max/(e v)) I(n+1), with
//   I(p) = integral_0^1 ds / sqrt(1 - s^p) = B(1/p, 1/2) / p.
// The contact time is tau = t_load + t_unload (first touch to separation). e and n are the
// ball's at v (the table's with -ball_cor_table). The linear law: pi sqrt(m_b/k), e = 1.
PetscReal PowerLawWallIntegral(PetscReal p);
PetscReal BallExponentFromCor(PetscReal m, PetscReal e); // n = (m+1)/e^2 - 1
PetscReal BallCorAt(const BallParams &b, PetscReal v);      // e at approach speed v
PetscReal BallExponentAt(const BallParams &b, PetscReal v); // n at approach speed v
PetscReal ContactWallMaxCompression(const BallParams &b, PetscReal v);
PetscReal ContactWallLoadingTime(const BallParams &b, PetscReal v);
PetscReal ContactWallUnloadingTime(const BallParams &b, PetscReal v);
PetscReal ContactWallTime(const BallParams &b, PetscReal v);
// k1 (N/m^m) that gives the wall contact time tau (s) at speed v (m/s) for a ball of mass
// m_b (kg), loading exponent m and restitution e: tau is proportional to k1^(-1/(m+1)), so
//   k1 = (m+1)/2 m_b v^2 (tau_1 / tau)^(m+1),  tau_1 = (I(m+1) + I(n+1)/e) / v.
PetscReal BallK1FromContactTime(PetscReal mass, PetscReal m, PetscReal e, PetscReal tau, PetscReal v);


} // namespace beamimpact

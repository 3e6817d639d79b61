// The ball-beam contact as the solvers, events and measures see it (docs/model.md section 2):
// plain functions of the ball (BallParams: mass, speed, its registered law and the law's
// parameters), the contact's state and the compression c = y_ball - y_beam(x_imp) (m). Each
// asks the ball's law (model/contact_law.hpp; the laws are model/contact_laws/*.cpp):
//   linear      F = k c
//   hysteresis  F = k1 c^m while compressing, F = k2 c^n while expanding,
//               k2 = k1 c_max^(m-n) (continuous at maximum compression).
// Energy: W = integral F dc is the work done on the ball (stored + dissipated);
// with W the total energy KE_ball + KE_beam + U_beam + W is exactly conserved.
//
// A real ball (MODEL section 6, docs/model.md section 2): the hysteretic law characterised the
// way a ball is tested, by its rigid-wall coefficient of restitution e and contact time tau
// at a test speed (-ball_cor, -ball_contact_time, -ball_test_speed with -ball_m), which give
// n and k1 in closed form; optionally e follows a table e(v) of the approach speed
// (-ball_cor_table), and then n is set at the start of each contact.
#pragma once

#include "model/contact_law.hpp"

#include <petscsys.h>

namespace beamimpact {

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
// A contact starts at approach speed v (m/s): the law sets what it keeps for this contact (the
// hysteretic law with -ball_cor_table: n from e(v)). Before the switch to loading.
void ContactBegin(const BallParams &b, ContactState *s, PetscReal v);

// Questions the law answers.
// Whether the law's force changes formula at the loading<->unloading switch.
bool ContactHasHysteresis(const BallParams &b);
// Whether the law loses nothing (linear): -ball_loss_factor corrects its ACOR for the ball's losses.
bool ContactElastic(const BallParams &b);
// Whether F = k c in every phase (the exact modal reference applies), and that k (N/m; NaN if not).
bool      ContactLinear(const BallParams &b);
PetscReal ContactLinearStiffness(const BallParams &b);
// The unloading exponent in force in state s (0 for a law without one).
PetscReal ContactUnloadingExponent(const BallParams &b, const ContactState &s);

// Scales at the incident speed: a contact time (s; linear pi sqrt(m/k), hysteresis the same with
// the secant stiffness at the wall's maximum compression), the compression (m; v_i sqrt(m_b/k_eff))
// and a bound on dF/dc over the contact (N/m) for explicit stability limits.
PetscReal ContactTimeScale(const BallParams &b);
// The same at the ball's and the beam's approach speed (m/s): a ball at rest struck by a
// swinging bat has the bat's speed as its approach, and a speed-dependent law's scale at
// -ball_speed 0 would be infinite (approach <= 0: the ball's own speed).
PetscReal ContactTimeScale(const BallParams &b, PetscReal approach);
PetscReal ContactCompressionScale(const BallParams &b);
PetscReal ContactStiffnessBound(const BallParams &b);
// The exponent p of the force at the first touch, F ~ c^p (1 for the linear law and a hysteretic
// law of -ball_m 1, 1.5 for Hertz), measured on the loading branch at 1e-6 and 2e-6 of the
// compression scale (approach: as ContactTimeScale). The modal engine's share weight
// (solvers/beam_modes.hpp): a mode left out responds to the force's start by (pi/(w T))^min(p, 2).
PetscReal ContactStartExponent(const BallParams &b, PetscReal approach);

// Closed forms on a rigid, fixed wall, arriving at speed v (m/s): the coefficient of
// restitution (the table's with -ball_cor_table), the maximum compression (m), the loading and
// unloading times and the contact time (s, first touch to separation). A power-law ball
// F = k c^p (MODEL section 6): from 1/2 m_b v^2 - 1/2 m_b cdot^2 = k c^(p+1)/(p+1),
// c_max = ((p+1) m_b v^2 / (2 k))^(1/(p+1)) and t_load = (c_max/v) I(p+1) (PowerLawWallIntegral).
PetscReal BallCorAt(const BallParams &b, PetscReal v);
PetscReal ContactWallMaxCompression(const BallParams &b, PetscReal v);
PetscReal ContactWallLoadingTime(const BallParams &b, PetscReal v);
PetscReal ContactWallUnloadingTime(const BallParams &b, PetscReal v);
PetscReal ContactWallTime(const BallParams &b, PetscReal v);

// The hysteretic law's closed forms (model/contact_laws/hysteresis.cpp). Unloading from
// k2 c_max^(n+1)/(n+1) = e^2 1/2 m_b v^2: the ball leaves at e v with e^2 = (m+1)/(n+1) and
// t_unload = (c_max/(e v)) I(n+1); one cycle loses (n-m) k1 c_max^(m+1) / ((m+1)(n+1)).
PetscReal ContactCycleLoss(const BallParams &b, PetscReal c_max);
PetscReal BallExponentFromCor(PetscReal m, PetscReal e);    // n = (m+1)/e^2 - 1
PetscReal BallExponentAt(const BallParams &b, PetscReal v); // n at approach speed v
// k1 (N/m^m) that gives the wall contact time tau (s) at speed v (m/s) for a ball of mass
// m_b (kg), loading exponent m and restitution e: tau is proportional to k1^(-1/(m+1)), so
//   k1 = (m+1)/2 m_b v^2 (tau_1 / tau)^(m+1),  tau_1 = (I(m+1) + I(n+1)/e) / v.
PetscReal BallK1FromContactTime(PetscReal mass, PetscReal m, PetscReal e, PetscReal tau, PetscReal v);

} // namespace beamimpact

// The oblique impact (MODEL section 10, docs/model.md "Oblique impacts"): the ball's line of
// flight offset D from the bat's axis, friction and tangential compliance at the contact, the
// ball's spin. Plain numbers; the run's set-up (run/oblique.cpp) decomposes the impact and calls
// these.
//
// Frame: the plane across the bat at the impact point, y along the reversed incoming direction
// (from the bat toward where the ball came from), z up; the bat's axis at the origin. The ball
// comes in at speed v along -y with its centre at height D; at first touch the line of centres
// makes the angle theta with y,
//
//   sin theta = D / (R_b + R_bat),    n = (cos theta, sin theta),    t = (-sin theta, cos theta),
//
// and the contact's normal n and tangent t are kept for the whole contact (the contact lasts
// about 1 ms; the line of centres turns by about v_t T_c / (R_b + R_bat) over it, a few degrees:
// the assumption of Sawicki et al. 2003, Cross & Nathan 2006 and Nathan et al. 2012). The
// normal force F_n(t) along n is the existing contact (any law, the flexible bat); along t the
// friction force F_t acts on four rigid motions: the ball's tangential speed v_b and its spin
// w (counter-clockwise in (y, z), which is backspin of the batted ball), the bat's tangential
// speed V at the impact point (its rigid effective mass M_t there; infinite for a held bat) and
// its roll w_a about its own axis (inertia I_a; infinite for a held bat). Each is linear in the
// tangential impulse J = integral F_t dt:
//
//   v_b = v_b0 + J/m,  w = w0 - R_b J / I_b,  V = V0 - J/M_t,  w_a = w_a0 - R_bat J / I_a,
//
// so the slip speed of the surfaces u = (v_b - R_b w) - (V + R_bat w_a) obeys u' = F_t / m_e,
//
//   1/m_e = 1/m + R_b^2/I_b + 1/M_t + R_bat^2/I_a          (I_b = alpha m R_b^2).
//
// Tangential force: Coulomb friction |F_t| <= mu F_n with grip and slip, and optionally a
// tangential spring k_t (the contact's tangential compliance; F_t = -k_t xi, xi its stretch):
//   slip:  F_t = -s mu F_n (s the slip's sign), xi = s mu F_n / k_t; it grips when the sliding
//          rate u - xi' changes sign;
//   grip:  xi' = u (the spring takes the surfaces' relative motion), F_t = -k_t xi; it slips when
//          k_t |xi| reaches mu F_n.
// Without compliance (k_t = 0 here: none) the grip is rigid: u stays 0 and, since nothing else
// moves the surfaces apart tangentially, F_t = 0 from then on. The spring is set from a
// measured tangential restitution e_T (the reversal -u'/u of the surfaces' tangential speed):
// a ball that grips throughout on a massive fixed target oscillates at w_t = sqrt(k_t/m_e0),
// m_e0 = m alpha / (1 + alpha), and leaves after the wall contact time tau with u = u0 cos(w_t tau),
//
//   k_t = m_e0 (arccos(-e_T) / tau)^2                       (e_T = 0: w_t tau = pi/2).
//
// F_n is given as samples (t_k, F_k), linear between them (the stepper's steps); on each piece
// grip is solved in closed form (a harmonic oscillator), slip too (u quadratic in t), and each
// switch between them is located by bisection to round-off; the frictional dissipation
// integral mu F_n |u - xi'| dt is exact (Simpson on a cubic).
#pragma once

#include "model/section.hpp"

#include <petscsys.h>

#include <vector>

namespace beamimpact {

// The contact's geometry at first touch (m; angle in rad). Valid when |D| < R_b + R_bat.
struct ObliqueGeometry {
  PetscReal offset = 0, radius_sum = 0, theta = 0, cos_theta = 1, sin_theta = 0;
};
ObliqueGeometry ObliqueGeometryOf(PetscReal offset, PetscReal ball_radius, PetscReal bat_radius);

// The outer radius (m) of a round profile at x (its diameter linear between rows; x clamped to
// the rows); 0 for a section that is not a profile (a strip, a table: no radius).
PetscReal RoundSectionRadiusAt(const BeamSection &s, PetscReal x);

// The four tangential motions and the contact's parameters.
struct TangentialModel {
  PetscReal ball_mass = 0, ball_radius = 0, ball_inertia = 0; // kg, m, kg m^2 (alpha m R_b^2)
  PetscReal bat_mass = PETSC_INFINITY;                       // kg, M_t: the bat's effective mass at the impact point (inf: fixed)
  PetscReal bat_roll_inertia = PETSC_INFINITY;               // kg m^2, I_a about the bat's axis (inf: held)
  PetscReal bat_radius = 0;                                  // m, R_bat at the impact point
  PetscReal friction   = 0;                                  // mu
  PetscReal stiffness  = 0;                                  // N/m, k_t (0: no tangential compliance)
  PetscReal EffectiveMass() const;                           // m_e (kg)
};

// k_t (N/m) for the tangential restitution e_T in [0, 1), the ball (mass m, alpha) gripping
// throughout a contact of duration tau (s) on a massive fixed target.
PetscReal TangentialStiffnessFromCor(PetscReal ball_mass, PetscReal alpha, PetscReal e_T, PetscReal tau);

enum class TangentialPhase { Slip = 0, Grip = 1 };

struct TangentialSwitch {
  PetscReal       time = 0; // s
  TangentialPhase to   = TangentialPhase::Slip;
};

// The state of the tangential contact.
struct TangentialState {
  PetscReal       u           = 0; // m/s, slip speed of the surfaces (ball minus bat, along t)
  PetscReal       xi          = 0; // m, stretch of the tangential spring
  PetscReal       impulse     = 0; // N s, J = integral F_t dt (on the ball, along t)
  PetscReal       dissipated  = 0; // J, by friction (integral mu F_n |u - xi'| dt over the slips)
  PetscReal       normal_impulse = 0; // N s, integral F_n dt
  TangentialPhase phase       = TangentialPhase::Slip;
  PetscInt        slip_sign   = 0; // s: +1, -1 (0: not yet known)
  std::vector<TangentialSwitch> switches; // located grip/slip changes, in time order
};

// The state at the first touch with slip speed u0 (m/s).
TangentialState TangentialStart(PetscReal u0);

// Advances the tangential contact over [t0, t1] with F_n linear from F0 to F1 (N, >= 0).
void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1, TangentialState *s);

// The four motions after an impulse J, from their values at the first touch.
struct TangentialBodies {
  PetscReal v_ball = 0, spin = 0, v_bat = 0, roll = 0; // m/s, rad/s (counter-clockwise), m/s, rad/s
};
TangentialBodies TangentialBodiesAfter(const TangentialModel &m, const TangentialBodies &b0, PetscReal J);
// Their kinetic energy (J; the infinite bodies' terms are left out: they do not move).
PetscReal TangentialKineticEnergy(const TangentialModel &m, const TangentialBodies &b);

// The batted ball in the frame (y, z) from its normal speed away from the bat u_n (m/s) and its
// tangential speed v_t: exit speed (m/s) and launch angle (deg, from +y, positive up).
struct ObliqueExit {
  PetscReal vy = 0, vz = 0, speed = 0, launch_angle = 0;
};
ObliqueExit ObliqueExitOf(const ObliqueGeometry &g, PetscReal u_n, PetscReal v_t);

} // namespace beamimpact

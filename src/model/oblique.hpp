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
// tangential spring at the contact (its compliance), whose stiffness follows the normal force,
// k_t = F_n / l (the contact patch grows and shrinks with the normal load, Mindlin's k_t
// proportional to k_n; l a length), F_t = -k_t xi with xi its stretch. Then the Coulomb limit
// k_t |xi| <= mu F_n is |xi| <= mu l, a fixed stretch:
//   slip:  F_t = -s mu F_n (s the slip's sign), xi = s mu l; it grips when u changes sign;
//   grip:  xi' = u (the spring takes the surfaces' relative motion), F_t = -F_n xi / l; it slips
//          when |xi| reaches mu l.
// Without compliance (l = 0: none) the grip is rigid: u stays 0 and, since nothing else moves
// the surfaces apart tangentially, F_t = 0 from then on: the ball leaves rolling on a massive
// fixed target, v_t' = v_t / (1 + alpha). The length l is set from the tangential restitution
// e_T (the reversal -u'/u of the surfaces' tangential speed, Cross & Nathan 2006) on the normal
// force of the contact itself: gripping throughout it, the contact would reverse u by e_T
// (TangentialComplianceLength). The spring's energy F_n xi^2 / (2 l) is not conserved while
// F_n changes (the stiffness's work, 1/2 (dF_n/dt / l) xi^2, kept apart from friction's
// dissipation); it is 0 before the first touch and after the separation.
//
// F_n is given as samples (t_k, F_k) with its rates dF_k/dt (the stepper's steps; the rate is the
// contact law's dF/dc times the compression rate), the cubic Hermite of both on each piece (exact
// to O(h^4), so the tangential outputs keep the normal run's order up to 4; without rates, the
// secant: F_n linear, order 2). On each piece slip is solved in closed form (u a quartic in t),
// grip by classical Runge-Kutta (40 steps per radian of the tangential oscillation, at least 4),
// and each switch between them is located by bisection to round-off; the frictional dissipation
// integral mu F_n |u| dt over the slips is exact (4-point Gauss).
#pragma once

#include "model/section.hpp"

#include <petscsys.h>

#include <memory>
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
  PetscReal bat_mass          = PETSC_INFINITY; // kg, M_t: the bat's effective mass at the impact point (inf: fixed)
  PetscReal bat_roll_inertia  = PETSC_INFINITY; // kg m^2, I_a about the bat's axis (inf: held)
  PetscReal bat_radius        = 0;              // m, R_bat at the impact point
  PetscReal friction          = 0;              // mu
  PetscReal compliance_length = 0;              // m, l of k_t = F_n / l (0: no tangential compliance, a rigid grip)
  PetscReal EffectiveMass() const;              // m_e (kg)
};

// A cubic in the time s (s) from the start of a piece: c[0] + c[1] s + c[2] s^2 + c[3] s^3 (N).
struct ForceCubic {
  PetscReal c[4] = {0, 0, 0, 0};
  PetscReal operator()(PetscReal s) const { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); }
  PetscReal Rate(PetscReal s) const { return c[1] + s * (2 * c[2] + s * 3 * c[3]); }
  PetscReal Integral(PetscReal s) const
  {
    return s * (c[0] + s * (c[1] / 2 + s * (c[2] / 3 + s * c[3] / 4)));
  }                                     // from 0 to s
  ForceCubic Shift(PetscReal a) const;  // the same cubic in s - a (from s = a)
  ForceCubic Scaled(PetscReal k) const; // k times it
  // The cubic Hermite on [0, h] of the values F0, F1 and rates dF0, dF1 at its ends.
  static ForceCubic Hermite(PetscReal h, PetscReal F0, PetscReal F1, PetscReal dF0, PetscReal dF1);
};

// The length l (m) of k_t = F_n / l for which a contact of effective mass m_e (kg) gripping
// throughout the normal force F(t) (samples with their rates dF, the cubic Hermite between them;
// dF empty: linear between them) reverses the surfaces' tangential speed by e_T in [0, 1):
// bisection on the first branch (the tangential oscillation's phase below pi); 0 when F is 0
// throughout.
PetscReal TangentialComplianceLength(PetscReal m_e, PetscReal e_T, const std::vector<PetscReal> &t,
                                     const std::vector<PetscReal> &F, const std::vector<PetscReal> &dF = {});

enum class TangentialPhase {
  Slip = 0,
  Grip = 1
};

struct TangentialSwitch {
  PetscReal       time = 0; // s
  TangentialPhase to   = TangentialPhase::Slip;
};

// The state of the tangential contact.
struct TangentialState {
  PetscReal u              = 0; // m/s, slip speed of the surfaces (ball minus bat, along t)
  PetscReal xi             = 0; // m, stretch of the tangential spring
  PetscReal impulse        = 0; // N s, J = integral F_t dt (on the ball, along t)
  PetscReal dissipated     = 0; // J, by friction (integral mu F_n |u| dt over the slips)
  PetscReal stiffness_work = 0; // J, done on the spring by its changing stiffness (integral 1/2 (dF_n/dt / l) xi^2 dt)
  PetscReal normal_impulse = 0; // N s, integral F_n dt
  TangentialPhase               phase     = TangentialPhase::Slip;
  PetscInt                      slip_sign = 0; // s: +1, -1 (0: not yet known)
  std::vector<TangentialSwitch> switches;      // located grip/slip changes, in time order
};

// The state at the first touch with slip speed u0 (m/s): a compliant contact grips (its spring
// unstretched takes the motion), a rigid one slides (unless u0 = 0).
TangentialState TangentialStart(const TangentialModel &m, PetscReal u0);

// Advances the tangential contact over [t0, t1] with F_n the cubic Hermite of F0, F1 (N, >= 0) and
// the rates dF0, dF1 (N/s) at the ends; without rates, linear from F0 to F1.
void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1, PetscReal dF0,
                       PetscReal dF1, TangentialState *s);
void TangentialAdvance(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1,
                       TangentialState *s);

// The bat flexible in its second plane (docs/model.md "Oblique impacts"): a round, straight bat
// bends alike and independently in both planes, so along t it is the same beam, in the same
// modes, driven at the impact point by -F_t (and moving with the swing's component along t).
// Each mode k (frequency w_k, share gamma_k of the point's deflection; rigid modes w_k = 0
// included) obeys z_k'' + w_k^2 z_k = -gamma_k F_t; the modes a truncated basis leaves out move
// the point quasi-statically by -G_r F_t (the static correction). The ball's side of the slip
// speed, w = v_b - R_b w_b - R_bat w_a (translation, spin, the bat's roll), obeys w' = F_t / m*
// (1/m* = 1/m + R_b^2/I_b + R_bat^2/I_a), and the slip speed is u = w - V_c with the point's
// velocity V_c = sum gamma_k z_k' - G_r dF_t/dt.
//
// The force is a cubic on sub-steps (at least one per piece of F_n, more where the tangential
// oscillation is fast: 100 per radian of sqrt(k_t (1/m* + G)), G = sum gamma_k^2 + G_r the
// point's flexibility in mass); on each the modes and w are exact for the cubic force (the
// phi-functions phi_1 ... phi_4 of the sub-step), and the force is what the contact's law gives:
// slip: -s mu F_n, the cubic of F_n itself; a compliant grip: the cubic Hermite whose value and
// rate at the sub-step's end are the law's there, F_t = -F_n xi / l and dF_t/dt =
// -(dF_n/dt xi + F_n u) / l, with xi = xi0 + integral u and u affine in the two unknowns (a 2 x 2
// linear solve: Hermite collocation, local error O(tau^5), so order 4); a rigid grip: a constant
// force that ends the sub-step at u = 0 (order 1: give e_T for the higher orders). So the stiff
// modes never limit the sub-step. Switches (slip ends
// where u changes sign; a compliant grip slips where |xi| reaches mu l, a rigid one where
// |F_t| reaches mu F_n) are located by bisection of the sub-step. The energy the tangential
// contact takes, integral -F_t u dt, is summed by 3-point Gauss on each sub-step from the exact
// u into TangentialState::dissipated (an independent check of the balance against the bodies'
// and the modes' energies; stiffness_work stays 0: the spring's part is in it).
// Damped modes (Rayleigh damping: sigma) decay exactly in the same way; their loss is summed into
// TangentialPlane::damped (Gauss on each sub-step, the energy drop in free vibration).
struct TangentialKernelCache; // the modes' responses over the sub-step lengths last used (model/oblique.cpp)
struct TangentialPlane {
  std::vector<PetscReal> omega, gamma; // rad/s, m/(N s^2)^(1/2): per mode
  std::vector<PetscReal>
            sigma; // 1/s, each mode's decay rate (z'' + 2 sigma z' + w^2 z = f; Rayleigh damping); empty: undamped
  PetscReal damped      = 0;            // J, the energy the modes' damping took up to the plane's time
  PetscReal flexibility = 0;            // m/N, G_r: the point's static flexibility in the modes left out
  std::vector<PetscReal> z, zd;         // the modes' coordinates and velocities now
  PetscReal              ball_side = 0; // m/s, w now
  PetscReal              force     = 0; // N, F_t now (on the ball, along t)
  PetscReal              time      = 0; // s, the time the state is at
  PetscInt               substeps  = 0; // sub-steps taken
  PetscReal              Sigma(size_t k) const { return sigma.empty() ? 0 : sigma[k]; }
  // The modes' responses over the last sub-step lengths (a fixed-step run repeats them), kept with
  // the omega and sigma they were made for; made on first use.
  mutable std::shared_ptr<TangentialKernelCache> cache;
  PetscReal PointVelocity() const; // m/s, sum gamma_k z_k' (the static correction's rate left out)
  PetscReal ModeEnergy() const;    // J, 1/2 sum (z_k'^2 + w_k^2 z_k^2) + 1/2 G_r F_t^2
};

// The slip speed u0 of the first touch from the plane's state and the ball side: the state of the
// tangential contact as TangentialStart gives it.
TangentialState TangentialFlexibleStart(const TangentialModel &m, const TangentialPlane &p);

// Advances the tangential contact and the plane over [t0, t1] with F_n the cubic Hermite of F0,
// F1 (N, >= 0) and the rates dF0, dF1 (N/s) at the ends (without rates: linear); a piece with
// F_n = 0 at both ends is free, and a gap since the plane's time is free vibration (F_t = 0).
// m: the ball, the roll and the contact (bat_mass is ignored: the plane is the bat's translation).
void TangentialAdvanceFlexible(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1,
                               PetscReal dF0, PetscReal dF1, TangentialPlane *p, TangentialState *s);
void TangentialAdvanceFlexible(const TangentialModel &m, PetscReal t0, PetscReal t1, PetscReal F0, PetscReal F1,
                               TangentialPlane *p, TangentialState *s);

// Mode w from z, zd under the force f0 + f1 s over [0, tau]: z and z' at tau, exact (w = 0: a
// rigid mode).
void TangentialModeForced(PetscReal w, PetscReal z, PetscReal zd, PetscReal f0, PetscReal f1, PetscReal tau,
                          PetscReal *q, PetscReal *qd);
// The same with damping, z'' + 2 sigma z' + w^2 z = f0 + f1 s (sigma >= 0): exact for every
// damping (under-, critically and over-damped, a damped rigid mode), through the exponential of
// the mode's 2 x 2 matrix and its phi-functions (a series where their argument is small).
void TangentialModeForced(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, PetscReal f0, PetscReal f1,
                          PetscReal tau, PetscReal *q, PetscReal *qd);
// The same under a cubic force f(s), z'' + 2 sigma z' + w^2 z = f(s): the response to s^k is
// k! tau^(k+1) phi_(k+1)(tau A) of the mode's 2 x 2 matrix A (a series where |tau A| < 1, else
// from e^(tau A) by phi_k = (phi_(k-1) - I/(k-1)!) (tau A)^-1); a rigid mode in closed form.
void TangentialModeForced(PetscReal w, PetscReal sigma, PetscReal z, PetscReal zd, const ForceCubic &f, PetscReal tau,
                          PetscReal *q, PetscReal *qd);

// The string bed in its own plane (docs/model.md section 13, "On the string bed"; MODEL.md section
// 17): the frame's rigid motion along t at the point (its effective mass M_t; infinite: a held
// frame) and the mains under the ball (model/string_bed.hpp, StringBedInPlane: k_s, m_s) on it,
// the friction force acting on the mains. The two points, frame F and strings S (M = diag(M_t,
// m_s), K = k_s [1 -1; -1 1], the force on S), in their modes: a held frame one mode, omega^2 =
// k_s / m_s, gamma = 1/sqrt(m_s); a free one the rigid mode (1, 1)/sqrt(M_t + m_s) and the mode
// omega^2 = k_s (1/m_s + 1/M_t) of shape b (-m_s/M_t, 1), b^2 = M_t / (m_s (M_t + m_s)); gamma is
// a mode's value at S. The strings' slide from the frame (S less F) is the flexible mode's
// (1 + m_s/M_t) b z.
struct BedInPlaneModel {
  PetscReal frame_mass   = PETSC_INFINITY; // kg, M_t (inf: a held frame)
  PetscReal strings_mass = 0;              // kg, m_s
  PetscReal stiffness    = 0;              // N/m, k_s
};
// The plane at rest; *rigid: its rigid modes (0 or 1, the first).
TangentialPlane BedInPlaneOf(const BedInPlaneModel &b, PetscInt *rigid);
// The strings' slide from the frame (m, along t) and the energy of the strings' vibration against
// the frame (J, the flexible mode's) in the plane's state.
PetscReal BedInPlaneSlide(const BedInPlaneModel &b, const TangentialPlane &p);
PetscReal BedInPlaneEnergy(const TangentialPlane &p, PetscInt rigid);

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

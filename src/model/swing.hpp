// A swinging bat (docs/bats.md, "The bat in play"): before the impact the bat moves rigidly
// toward the ball, its centre of mass at V_cm and turning at Omega about it (positive when the
// larger-x end, the barrel, moves faster toward the ball):
//
//   V(x) = V_cm + Omega (x - x_cm)                       (m/s, toward the ball)
//
// A rigid motion is a free motion of the beam (K annihilates it), so with the ball coming at
// v_ball the contact starts at the approach speed v_ball + V(x_imp) and, for a free bat, the
// batted-ball speed obeys BBS = e_A v_ball + (1 + e_A) V(x), e_A the ACOR of the bat at rest
// hit at the approach speed: a test of the run, which integrates the swinging state itself.
// Plain numbers: the options are read in io/, the state is set by the steppers.
#pragma once

#include "model/beam.hpp"

#include <petscsys.h>

namespace beamimpact {

struct SwingParams {
  PetscReal bat_speed            = 0; // m/s, V_cm toward the ball
  PetscReal bat_angular_velocity = 0; // rad/s, Omega about the centre of mass
  PetscReal face_speed = 0; // m/s, a racket's speed along its face's +z at the impact point (a brush; -bat_speed_face)
  bool      Swings() const { return bat_speed != 0 || bat_angular_velocity != 0; } // toward the ball (the brush apart)
};

// The batter's swing as a law (MODEL.md section 14; Cross & Bower, J. Sports Sci. 24 (2006) 23-30:
// the speed at which a batter swings an implement of swing-weight I falls as V = C I^(-n), n = 0.27
// for their rods above 0.03 kg m^2, 0.25 for softball bats, 0.26 for golf clubs): the bat turns at
// omega about the point x_s (the hands) moving at v_s, both scaled by (I_s/I_0)^(-n) with I_s the
// bat's moment of inertia about x_s,
//
//   V(x) = s (v_s + omega_0 (x - x_s)),   s = (I_s / I_0)^(-n)   (s = 1 without I_0),
//
// so a heavier (or barrel-heavier) bat is swung slower. As a free bat's rigid motion: Omega = s
// omega_0 and V_cm = V(x_cm).
struct SwingLaw {
  bool      on                = false; // the law gives the swing (-bat_swing_angular_velocity given)
  PetscReal pivot             = 0;     // m, x_s from x = 0
  PetscReal pivot_speed       = 0;     // m/s, v_s toward the ball
  PetscReal angular_velocity  = 0;     // rad/s, omega_0 (at I_0)
  PetscReal exponent          = 0.26;  // n (1)
  PetscReal reference_inertia = 0;     // kg m^2, I_0 about x_s (0: no dependence, s = 1)
};
// I_s of a body about x_s (kg m^2) and the factor s (1).
PetscReal   SwingLawInertia(const SwingLaw &law, const BeamRigidBody &body);
PetscReal   SwingLawFactor(const SwingLaw &law, const BeamRigidBody &body);
SwingParams SwingFromLaw(const SwingLaw &law, const BeamRigidBody &body);

// The bat's speed toward the ball at x (m/s).
PetscReal SwingSpeedAt(const SwingParams &s, const BeamRigidBody &body, PetscReal x);

// The collision efficiency q = (BBS - V(x)) / (v_ball + V(x)) (the ACOR of the bat at rest).
PetscReal SwingCollisionEfficiency(PetscReal bbs, PetscReal v_ball, PetscReal V_x);

// The rigid pivoted bat (a certification rig): I_p about the pivot (kg m^2), the recoil factor
// r = m_b (x - x_p)^2 / I_p, and the bat-ball COR of the measured e_A, BBCOR = e_A (1 + r) + r.
struct PivotRig {
  PetscReal inertia_pivot = 0, recoil_factor = 0;
};
PivotRig  PivotRigOf(const BeamRigidBody &body, PetscReal x_pivot, PetscReal ball_mass, PetscReal x_imp);
PetscReal PivotBBCOR(const PivotRig &rig, PetscReal e_A);

} // namespace beamimpact

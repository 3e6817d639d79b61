// The outcome of a run from its first and last states: ACOR, invariants, and where the
// incident energy went (ball loss, the beam's rigid translation and rotation about its
// centre of mass, vibration).
#pragma once

#include "run/measures.hpp"
#include "run/scenario.hpp"

namespace beamimpact {

// Fills the outcome fields of *res (final_time, ball_final_velocity, acor(_corrected),
// energy and momentum errors, end energies, energy partition) from the measures m0 at
// t = 0 and m1 at the end time t (s).
void ImpactOutcomeFinish(const MeasureContext &ctx, const StateMeasures &m0, const StateMeasures &m1, PetscReal t, ImpactResult *res);

// The bat in play, from the ball's final velocity: the batted-ball speed, the collision
// efficiency (V_x: the bat's speed toward the ball at the impact point before the impact) and,
// with a pivot, the rig's recoil factor and BBCOR.
void ImpactBatOutcome(const Scenario &sc, PetscReal V_x, ImpactResult *res);

} // namespace beamimpact

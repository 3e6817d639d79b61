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

// Flags of physically absurd outcomes: compression_beyond_radius (max_compression beyond
// -ball_radius, when given). CompressionBeyondRadiusText: the summary's warning line (empty if
// not flagged), naming both values.
void        ImpactPlausibility(const Scenario &sc, ImpactResult *res);
std::string CompressionBeyondRadiusText(const Scenario &sc, const ImpactResult &r);

// A run that reached its cap on the simulated time (-impact_max_time, or its default) while
// the ball was still in contact has no outcome (its ACOR, peak force and compression are of a
// contact cut short): the message naming the option, the time reached, when the contact began
// and what to raise; empty if the run ended with the ball separated.
std::string ImpactCutOffReason(const Scenario &sc, const ImpactResult &r);

} // namespace beamimpact

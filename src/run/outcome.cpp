// The outcome of a run. See outcome.hpp.
#include "run/outcome.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace beamimpact {

void ImpactOutcomeFinish(const MeasureContext &ctx, const StateMeasures &m0, const StateMeasures &m1, PetscReal t, ImpactResult *res)
{
  const BallParams &ball = *ctx.ball;
  const BeamSystem &S    = *ctx.sys;
  res->final_time             = t;
  res->ball_final_velocity    = m1.ball_v;
  // A ball at rest (struck by a swinging bat): no ACOR and no fractions of the ball's incident
  // energy (NaN: they do not apply); the momenta relative to the bat's.
  const PetscReal nan   = std::numeric_limits<PetscReal>::quiet_NaN();
  const PetscReal p_ref = ball.speed > 0 ? ball.mass * ball.speed : std::abs(m0.momentum);
  res->acor                   = ball.speed > 0 ? -m1.ball_v / ball.speed : nan;
  res->acor_corrected         = ContactElastic(ball) ? res->acor * ball.loss_factor : res->acor;
  res->energy_error           = (m1.total() - m0.total()) / m0.total();
  res->linear_momentum_error  = (m1.momentum - m0.momentum) / p_ref;
  res->angular_momentum_error = (m1.angular_momentum - m0.angular_momentum) / (p_ref * S.L);
  res->beam_kinetic_end       = m1.beam_kinetic;
  res->beam_strain_end        = m1.beam_strain;
  res->ball_dissipated_end    = m1.ball_work - m1.ball_stored;
  // Rigid-body part of the beam's motion about its centre of mass (held nodes never move); a
  // rigid rotation of a Timoshenko beam also turns its sections (psi = theta).
  PetscReal M = 0, Mx = 0, Mxx = 0;
  for (PetscInt i = 0; i < S.nodes; ++i) {
    const PetscInt d = S.Dof(i);
    if (S.held[d]) continue;
    const PetscReal x = S.NodeX(i);
    M += S.mass[d];
    Mx += S.mass[d] * x;
    Mxx += S.mass[d] * x * x;
    if (S.fields > 1 && !S.held[S.Dof(i, 1)]) Mxx += S.mass[S.Dof(i, 1)]; // rotary inertia of a Timoshenko section
  }
  const PetscReal x_cm = Mx / M, I_cm = Mxx - M * x_cm * x_cm;
  const PetscReal L_cm = m1.beam_moment - x_cm * m1.beam_momentum;
  const PetscReal Ein  = ball.speed > 0 ? 0.5 * ball.mass * ball.speed * ball.speed : nan;
  const PetscReal Etr = m1.beam_momentum * m1.beam_momentum / (2 * M), Erot = I_cm > 0 ? L_cm * L_cm / (2 * I_cm) : 0;
  const PetscReal ball_loss = ContactElastic(ball) ? (1 - ball.loss_factor * ball.loss_factor) * m1.ball_kinetic : res->ball_dissipated_end;
  res->ball_loss_fraction   = ball_loss / Ein;
  res->translation_fraction = Etr / Ein;
  res->rotation_fraction    = Erot / Ein;
  res->vibration_fraction   = (m1.beam_kinetic + m1.beam_strain - Etr - Erot) / Ein;
  res->bat_speed_end            = -m1.beam_momentum / M; // toward the ball (-y)
  res->bat_angular_velocity_end = I_cm > 0 ? -L_cm / I_cm : 0;
  res->grip_stored_end = m1.grip_stored;
  res->hand_work_end   = m1.hand_work;
  if (S.Damped()) {
    res->beam_dissipated_end = m1.beam_dissipated;
    res->damping_fraction    = m1.beam_dissipated / Ein;
  }
}

void ImpactBatOutcome(const Scenario &sc, PetscReal V_x, ImpactResult *res)
{
  res->bbs                  = -res->ball_final_velocity;
  res->collision_efficiency = SwingCollisionEfficiency(res->bbs, sc.ball.speed, V_x);
  if (sc.beam.has_pivot) {
    const PivotRig rig = PivotRigOf(BeamRigidBodyOf(sc.beam), sc.beam.pivot_x, sc.ball.mass, res->x);
    res->recoil_factor = rig.recoil_factor;
    res->bbcor         = PivotBBCOR(rig, res->collision_efficiency);
  }
}

void ImpactPlausibility(const Scenario &sc, ImpactResult *res)
{
  res->compression_beyond_radius = sc.ball.radius > 0 && res->max_compression > sc.ball.radius ? PETSC_TRUE : PETSC_FALSE;
}

std::string CompressionBeyondRadiusText(const Scenario &sc, const ImpactResult &r)
{
  if (!r.compression_beyond_radius) return "";
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "warning: the maximum compression %.4g m is beyond the ball's radius (-ball_radius %g m, %.3g times it): physically absurd, the contact law is used far outside its range "
                "(check -ball_speed %g m/s and the stiffness)",
                (double)r.max_compression, (double)sc.ball.radius, (double)(r.max_compression / sc.ball.radius), (double)sc.ball.speed);
  return msg;
}

std::string ImpactCutOffReason(const Scenario &sc, const ImpactResult &r)
{
  if (!r.ended_in_contact) return "";
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);
  PetscReal         start = 0;
  for (const ContactEvent &e : r.events)
    if (e.kind == ContactEventKind::ContactStart) start = e.time;
  char cap[160], msg[640];
  if (sc.impact.max_time > 0) std::snprintf(cap, sizeof cap, "-impact_max_time %g s", (double)sc.impact.max_time);
  else std::snprintf(cap, sizeof cap, "the default cap on the simulated time (%g s: 4 windows + 100 contact times)", (double)times.max_time);
  std::snprintf(msg, sizeof msg,
                "the run was cut off in contact: %s ended it at t = %g s while the ball was still touching the beam (contact %d began at t = %g s), so it has no ACOR, "
                "peak force or compression; raise -impact_max_time (the run needs the contact's end plus -impact_window %g s: more than %g s), or leave it unset",
                cap, (double)r.final_time, (int)r.contacts, (double)start, (double)times.window, (double)(r.final_time + times.window));
  return msg;
}

} // namespace beamimpact

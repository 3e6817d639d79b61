// The oblique impact in a run. See oblique.hpp.
#include "run/oblique.hpp"

#include "base/option_table.hpp"
#include "model/rigid.hpp"
#include "run/results_table.hpp"
#include "run/scenario.hpp"

#include <cmath>

namespace beamimpact {

bool ObliqueImpact(const Scenario &sc) { return sc.impact.offset != 0 || sc.ball.spin != 0 || sc.flight.on; }

PetscErrorCode ObliqueNormalScenario(MPI_Comm comm, const Scenario &sc, Scenario *normal)
{
  const PetscReal D = sc.impact.offset, R_b = sc.ball.radius;
  const PetscReal R = RoundSectionRadiusAt(sc.beam.section, sc.impact.x);

  PetscFunctionBeginUser;
  if (D != 0 || sc.ball.spin != 0) {
    const char *what = D != 0 ? "-impact_offset" : "-ball_spin";
    PetscCheck(R > 0, comm, PETSC_ERR_ARG_INCOMP,
               "%s %s: an oblique impact needs the bat's radius at the impact point, which only a round profile gives (-beam_profile); this beam's section is %s, which has no radius (a strip or a "
               "table of properties is not round)",
               what, OptionWritten(what).c_str(), SectionSourceName(sc.beam.section.source));
    PetscCheck(R_b > 0, comm, PETSC_ERR_ARG_INCOMP, "%s %s: an oblique impact needs the ball's radius: give -ball_radius (m)", what, OptionWritten(what).c_str());
    PetscCheck(std::abs(D) < R_b + R, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-impact_offset %s misses the bat: |D| must be < R_b + R_bat = %g m (-ball_radius %g m plus the bat's radius %g m at -impact_x %g m)", OptionWritten("-impact_offset").c_str(),
               (double)(R_b + R), (double)R_b, (double)R, (double)sc.impact.x);
  }
  *normal                     = sc;
  ObliqueIncoming &in         = normal->oblique;
  in.on                       = true;
  in.ball_speed               = sc.ball.speed;
  in.swing                    = sc.swing;
  in.bat_radius               = R;
  in.ball_series_asked        = sc.monitor.ball;
  in.series_asked             = sc.monitor.any();
  if (D != 0) in.geometry = ObliqueGeometryOf(D, R_b, R); // head-on: theta = 0, cos theta = 1 exactly
  const PetscReal c           = in.geometry.cos_theta;
  normal->ball.speed          = c * sc.ball.speed;
  normal->swing.bat_speed     = c * sc.swing.bat_speed;
  normal->swing.bat_angular_velocity = c * sc.swing.bat_angular_velocity;
  normal->monitor.ball        = PETSC_TRUE; // F_n(t) for the tangential contact
  PetscFunctionReturn(0);
}

namespace {

// The bat's rigid second plane at the impact point: its effective mass and roll inertia.
void TangentialBat(const Scenario &sc, TangentialModel *m)
{
  const BeamParams   &b    = sc.beam;
  const BeamRigidBody body = BeamRigidBodyOf(b);
  const bool          ends_free = b.left == Support::Free && b.right == Support::Free && !b.has_clamp;
  if (ends_free && !b.has_pivot) {
    m->bat_mass         = RigidEffectiveMass(body.mass, body.inertia_cm, std::abs(sc.impact.x - body.x_cm));
    m->bat_roll_inertia = b.section.source == SectionSource::Profile ? 2 * SectionMomentsOf(b.section, 0, SectionLength(b.section)).j : PETSC_INFINITY;
  } else if (ends_free && sc.impact.x != b.pivot_x) {
    m->bat_mass = PivotRigOf(body, b.pivot_x, sc.ball.mass, sc.impact.x).inertia_pivot / ((sc.impact.x - b.pivot_x) * (sc.impact.x - b.pivot_x));
  }
}

} // namespace

PetscErrorCode ObliqueFinish(const Scenario &sc, const ImpactSeries &series, PetscReal u_n, ObliqueRecord *rec)
{
  const ObliqueIncoming &in = sc.oblique;
  const BallParams      &ball = sc.ball;
  TangentialModel        m;

  PetscFunctionBeginUser;
  rec->on       = true;
  rec->geometry = in.geometry;
  m.ball_mass   = ball.mass;
  m.ball_radius = ball.radius;
  m.ball_inertia = ball.inertia_factor * ball.mass * ball.radius * ball.radius;
  m.bat_radius  = in.bat_radius;
  m.friction    = ball.friction;
  TangentialBat(sc, &m);
  const BeamRigidBody body    = BeamRigidBodyOf(sc.beam);
  const PetscReal     V_in    = SwingSpeedAt(in.swing, body, sc.impact.x); // toward the ball, as given
  const PetscReal     s       = in.geometry.sin_theta;
  if (ball.tangential_cor >= 0 && ball.radius > 0 && ball.inertia_factor > 0) m.compliance_length = TangentialComplianceLength(m.EffectiveMass(), ball.tangential_cor, series.time, series.force);
  rec->model          = m;
  rec->before.v_ball  = in.ball_speed * s;
  rec->before.spin    = -ball.spin; // counter-clockwise in (y, z): the incoming backspin turns clockwise
  rec->before.v_bat   = -V_in * s;
  rec->before.roll    = 0;
  const PetscReal u0  = (rec->before.v_ball - m.ball_radius * rec->before.spin) - rec->before.v_bat;
  rec->contact        = TangentialStart(m, u0);
  const bool touches  = m.ball_radius > 0 && m.ball_inertia > 0;
  if (touches && u0 != 0)
    for (size_t k = 0; k + 1 < series.time.size() && k + 1 < series.force.size(); ++k)
      TangentialAdvance(m, series.time[k], series.time[k + 1], std::max<PetscReal>(series.force[k], 0), std::max<PetscReal>(series.force[k + 1], 0), &rec->contact);
  rec->after = touches ? TangentialBodiesAfter(m, rec->before, rec->contact.impulse) : rec->before;
  rec->exit  = ObliqueExitOf(in.geometry, u_n, rec->after.v_ball);
  if (sc.flight.on) {
    FlightParams p    = sc.flight.params;
    p.launch.speed    = rec->exit.speed;
    p.launch.angle    = rec->exit.launch_angle;
    p.launch.backspin = rec->after.spin;
    PetscReal u[6];
    FlightInitialState(p.launch, u);
    PetscCheck(p.launch.height > 0 || p.launch.angle > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
               "-flight with -flight_height 0: the batted ball leaves at %g deg, downward, from the ground; give -flight_height > 0", (double)p.launch.angle);
    PetscCall(FlightSolve(FlightModelOf(p), u, sc.flight.solve, &rec->flight));
    rec->flew = true;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

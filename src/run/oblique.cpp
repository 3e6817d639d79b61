// The oblique impact in a run. See oblique.hpp.
#include "run/oblique.hpp"

#include "base/option_table.hpp"
#include "model/rigid.hpp"
#include "run/impact.hpp"
#include "run/results_table.hpp"
#include "run/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

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
               "%s %s: an oblique impact needs the bat's radius at the impact point, which only a round profile gives "
               "(-beam_profile); this beam's section is %s, which has no radius (a strip or a "
               "table of properties is not round)",
               what, OptionWritten(what).c_str(), SectionSourceName(sc.beam.section.source));
    PetscCheck(R_b > 0, comm, PETSC_ERR_ARG_INCOMP,
               "%s %s: an oblique impact needs the ball's radius: give -ball_radius (m)", what,
               OptionWritten(what).c_str());
    PetscCheck(std::abs(sc.ball.spin) < FlightSpinMax(R_b), comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-ball_spin %s is not allowed: it moves the ball's surface at %g m/s (-ball_radius %g m), beyond the "
               "speed of sound in air (%g m/s), where neither the contact nor the flight "
               "models hold; |spin| must be below %g rad/s",
               OptionWritten("-ball_spin").c_str(), (double)(std::abs(sc.ball.spin) * R_b), (double)R_b,
               (double)kSpeedOfSound, (double)FlightSpinMax(R_b));
    PetscCheck(std::abs(D) < R_b + R, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-impact_offset %s misses the bat: |D| must be < R_b + R_bat = %g m (-ball_radius %g m plus the bat's "
               "radius %g m at -impact_x %g m)",
               OptionWritten("-impact_offset").c_str(), (double)(R_b + R), (double)R_b, (double)R, (double)sc.impact.x);
  }
  *normal              = sc;
  ObliqueIncoming &in  = normal->oblique;
  in.on                = true;
  in.ball_speed        = sc.ball.speed;
  in.swing             = sc.swing;
  in.bat_radius        = R;
  in.ball_series_asked = sc.monitor.ball;
  in.series_asked      = sc.monitor.any();
  if (D != 0) in.geometry = ObliqueGeometryOf(D, R_b, R); // head-on: theta = 0, cos theta = 1 exactly
  const PetscReal c                  = in.geometry.cos_theta;
  normal->ball.speed                 = c * sc.ball.speed;
  normal->swing.bat_speed            = c * sc.swing.bat_speed;
  normal->swing.bat_angular_velocity = c * sc.swing.bat_angular_velocity;
  normal->monitor.ball               = PETSC_TRUE; // F_n(t) for the tangential contact
  PetscFunctionReturn(0);
}

namespace {

// The bat's rigid second plane at the impact point: its effective mass and roll inertia.
void TangentialBat(const Scenario &sc, TangentialModel *m)
{
  const BeamParams   &b         = sc.beam;
  const BeamRigidBody body      = BeamRigidBodyOf(b);
  const bool          ends_free = b.left == Support::Free && b.right == Support::Free && !b.has_clamp;
  if (ends_free && !b.has_pivot) {
    m->bat_mass         = RigidEffectiveMass(body.mass, body.inertia_cm, std::abs(sc.impact.x - body.x_cm));
    m->bat_roll_inertia = b.section.source == SectionSource::Profile
                          ? 2 * SectionMomentsOf(b.section, 0, SectionLength(b.section)).j
                          : PETSC_INFINITY;
  } else if (ends_free && sc.impact.x != b.pivot_x) {
    m->bat_mass = PivotRigOf(body, b.pivot_x, sc.ball.mass, sc.impact.x).inertia_pivot /
                  ((sc.impact.x - b.pivot_x) * (sc.impact.x - b.pivot_x));
  }
}

} // namespace

PetscErrorCode ObliquePlaneBuild(const ObliqueBeam &beam, const std::vector<PetscReal> &velocity, TangentialPlane *p,
                                 PetscInt *rigid)
{
  std::shared_ptr<const BeamModes> modes;
  std::string                      why;

  PetscFunctionBeginUser;
  PetscCheck(BeamModesAvailable(*beam.sys, &why), beam.comm, PETSC_ERR_SUP,
             "-impact_tangential_plane flexible: the bat's second plane is solved in the beam's modes, which cannot "
             "carry this beam (%s); give -impact_tangential_plane rigid (the bat rigid in "
             "that plane, its effective mass at the impact point), or no friction (-ball_friction 0)",
             why.c_str());
  PetscCall(BeamModesShared(beam.comm, *beam.sys, beam.truncation, &modes));
  const BeamModes       &M = *modes;
  const PetscInt         n = M.S.n, nm = M.Count();
  std::vector<PetscReal> sv(n), gw(n, 0.0);
  for (PetscInt d = 0; d < n; ++d) {
    const PetscReal sm = std::sqrt(M.S.mass[d]);
    sv[d]              = velocity.empty() ? 0.0 : sm * velocity[M.S.dof[d]];
    for (PetscInt q = 0; q < beam.g->n; ++q)
      if (M.S.dof[d] == beam.g->dof[q]) gw[d] += beam.g->w[q] / sm;
  }
  *p       = TangentialPlane();
  p->omega = M.B.omega;
  for (PetscReal r : M.B.rate)
    if (r > 0) p->sigma = M.B.rate; // Rayleigh damping (proportional): the same modes, each decaying
  p->gamma.assign(nm, 0.0);
  p->z.assign(nm, 0.0);
  p->zd.assign(nm, 0.0);
  for (PetscInt k = 0; k < nm; ++k) { // zd = Phi^T M^{1/2} v, gamma = Phi^T M^{-1/2} g
    const PetscReal *phi = &M.B.Phi[(size_t)k * n];
    PetscReal        a = 0, c = 0;
    for (PetscInt d = 0; d < n; ++d) a += phi[d] * sv[d], c += phi[d] * gw[d];
    p->zd[k]    = a;
    p->gamma[k] = c;
  }
  if (M.truncated) {
    const ModalCorrection *corr = nullptr;
    PetscCall(M.StaticCorrection(*beam.g, &corr));
    p->flexibility = corr->Gr;
  }
  *rigid = M.rigid;
  PetscFunctionReturn(0);
}

PetscErrorCode ObliquePlaneMomenta(const ObliqueBeam &beam, const TangentialPlane &p, PetscReal *P, PetscReal *L)
{
  std::shared_ptr<const BeamModes> modes;

  PetscFunctionBeginUser;
  PetscCall(BeamModesShared(beam.comm, *beam.sys, beam.truncation, &modes)); // from the cache
  const PetscInt n = modes->S.n, f = beam.sys->fields;
  *P = 0, *L = 0;
  for (size_t k = 0; k < p.zd.size(); ++k) {
    const PetscReal *phi = &modes->B.Phi[k * n];
    PetscReal        r   = 0,
              x = 0; // sum m_d v_d and m_d x_d v_d per unit zd_k, over the translational dofs: v = M^{-1/2} phi zd
    for (PetscInt d = 0; d < n; ++d) {
      const PetscInt dof = modes->S.dof[d];
      if (dof % f) continue;
      r += phi[d] * std::sqrt(modes->S.mass[d]);
      x += phi[d] * std::sqrt(modes->S.mass[d]) * beam.sys->NodeX(dof / f);
    }
    *P += r * p.zd[k];
    *L += x * p.zd[k];
  }
  PetscFunctionReturn(0);
}

namespace {

// The plane after the contact: its flexible modes' energy and its momentum along t.
PetscErrorCode TangentialPlaneFinish(const ObliqueBeam &beam, ObliqueRecord *rec)
{
  const TangentialPlane &p = rec->plane;
  PetscReal              L;

  PetscFunctionBeginUser;
  rec->plane_damped    = p.damped;
  rec->plane_vibration = 0.5 * p.flexibility * p.force * p.force;
  for (size_t k = (size_t)rec->plane_rigid_modes; k < p.omega.size(); ++k)
    rec->plane_vibration += 0.5 * (p.zd[k] * p.zd[k] + p.omega[k] * p.omega[k] * p.z[k] * p.z[k]);
  PetscCall(ObliquePlaneMomenta(beam, p, &rec->plane_momentum, &L));
  PetscFunctionReturn(0);
}

} // namespace

namespace {

// The normal force on the piece [t_k, t_k+1] of the run's steps: its values (the odd extension's
// round-off below 0 at a separation clipped) and rates at the ends, the rates the secant's where
// the series has none (F_n linear).
struct NormalPiece {
  PetscReal F0 = 0, F1 = 0, dF0 = 0, dF1 = 0;
};
NormalPiece NormalPieceOf(const ImpactSeries &S, size_t k)
{
  NormalPiece f;
  f.F0 = std::max<PetscReal>(S.force[k], 0);
  f.F1 = std::max<PetscReal>(S.force[k + 1], 0);
  if (S.force_rate.size() > k + 1) f.dF0 = S.force_rate[k], f.dF1 = S.force_rate[k + 1];
  else f.dF0 = f.dF1 = (f.F1 - f.F0) / (S.time[k + 1] - S.time[k]);
  return f;
}

// The batted ball's flight from the exit velocity and spin (-flight): rec->flight.
PetscErrorCode ObliqueFlight(const Scenario &sc, ObliqueRecord *rec)
{
  PetscFunctionBeginUser;
  FlightParams p    = sc.flight.params;
  p.ball.mass       = sc.ball.mass; // the impact's own ball (its radius is required with -flight: FlightBallResolve)
  p.ball.radius     = sc.ball.radius > 0 ? sc.ball.radius : p.ball.radius;
  p.launch.speed    = rec->exit.speed;
  p.launch.angle    = rec->exit.launch_angle;
  p.launch.backspin = rec->after.spin;
  PetscReal u[6];
  FlightInitialState(p.launch, u);
  PetscCheck(p.launch.height > 0 || p.launch.angle > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
             "-flight with -flight_height 0: the batted ball leaves at %g deg, downward, from the ground; give "
             "-flight_height > 0",
             (double)p.launch.angle);
  PetscCheck(std::abs(p.launch.backspin) < FlightSpinMax(p.ball.radius), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "-flight: the batted ball leaves spinning at %g rad/s, its surface at %g m/s (-flight_ball_radius %g "
             "m), beyond the speed of sound in air (%g m/s), where the flight's drag and "
             "lift do not hold (check -ball_speed, -ball_spin and the swing)",
             (double)p.launch.backspin, (double)(std::abs(p.launch.backspin) * p.ball.radius), (double)p.ball.radius,
             (double)kSpeedOfSound);
  PetscCall(FlightSolve(FlightModelOf(p), u, sc.flight.solve, &rec->flight));
  rec->flew = true;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ObliqueFinish(const Scenario &sc, const ImpactSeries &series, PetscReal u_n, const ObliqueBeam &beam,
                             ObliqueRecord *rec)
{
  const ObliqueIncoming &in   = sc.oblique;
  const BallParams      &ball = sc.ball;
  TangentialModel        m;

  PetscFunctionBeginUser;
  ImpactStageScope stage(ImpactStage::Tangential); // -log_view
  rec->on        = true;
  rec->geometry  = in.geometry;
  m.ball_mass    = ball.mass;
  m.ball_radius  = ball.radius;
  m.ball_inertia = ball.inertia_factor * ball.mass * ball.radius * ball.radius;
  m.bat_radius   = in.bat_radius;
  m.friction     = ball.friction;
  TangentialBat(sc, &m);
  const BeamRigidBody body = BeamRigidBodyOf(sc.beam);
  const PetscReal     V_in = SwingSpeedAt(in.swing, body, sc.impact.x); // toward the ball, as given
  const PetscReal     s    = in.geometry.sin_theta;
  // l from e_T on the rigid bat's effective mass (the ball's property, the same for both planes' models);
  // without friction the spring carries no force: none (its zero-force steps left -6e-71 J of round-off)
  if (ball.tangential_cor >= 0 && ball.radius > 0 && ball.inertia_factor > 0 && ball.friction > 0)
    m.compliance_length = TangentialComplianceLength(m.EffectiveMass(), ball.tangential_cor, series.time, series.force,
                                                     series.force_rate);
  rec->model            = m;
  rec->before.v_ball    = in.ball_speed * s;
  rec->before.spin      = -ball.spin; // counter-clockwise in (y, z): the incoming backspin turns clockwise
  rec->before.v_bat     = -V_in * s;
  rec->before.roll      = 0;
  const PetscReal u0    = (rec->before.v_ball - m.ball_radius * rec->before.spin) - rec->before.v_bat;
  rec->contact          = TangentialStart(m, u0);
  const bool   touches  = m.ball_radius > 0 && m.ball_inertia > 0;
  const bool   flexible = touches && u0 != 0 && m.friction > 0 && !sc.impact.tangential_rigid;
  const size_t n        = std::min(series.time.size(), series.force.size());
  if (flexible) { // the swing's -V(x) per dof times sin theta: its component along t
    std::vector<PetscReal> v;
    PetscReal              L;
    if (in.swing.Swings()) v = BeamSystemSwingVelocity(*beam.sys, in.swing, body);
    for (PetscReal &x : v) x *= s;
    PetscCall(ObliquePlaneBuild(beam, v, &rec->plane, &rec->plane_rigid_modes));
    PetscCall(ObliquePlaneMomenta(beam, rec->plane, &rec->plane_momentum0, &L));
    rec->plane.ball_side = (rec->before.v_ball - m.ball_radius * rec->before.spin) - m.bat_radius * rec->before.roll;
    rec->flexible        = true;
    rec->contact         = TangentialFlexibleStart(m, rec->plane);
    for (size_t k = 0; k + 1 < n; ++k) {
      const NormalPiece f = NormalPieceOf(series, k);
      TangentialAdvanceFlexible(m, series.time[k], series.time[k + 1], f.F0, f.F1, f.dF0, f.dF1, &rec->plane,
                                &rec->contact);
    }
    PetscCall(TangentialPlaneFinish(beam, rec));
    rec->model.bat_mass = PETSC_INFINITY; // the bat's translation is the plane's: the ball and the roll from J
  } else if (touches && u0 != 0)
    for (size_t k = 0; k + 1 < n; ++k) {
      const NormalPiece f = NormalPieceOf(series, k);
      TangentialAdvance(m, series.time[k], series.time[k + 1], f.F0, f.F1, f.dF0, f.dF1, &rec->contact);
    }
  rec->after = touches ? TangentialBodiesAfter(rec->model, rec->before, rec->contact.impulse) : rec->before;
  if (flexible) rec->after.v_bat = rec->plane.PointVelocity();
  rec->exit = ObliqueExitOf(in.geometry, u_n, rec->after.v_ball);
  if (sc.flight.on) {
    stage.Switch(ImpactStage::Flight);
    PetscCall(ObliqueFlight(sc, rec));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

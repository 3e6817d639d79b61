// The oblique impact in a run. See oblique.hpp.
#include "run/oblique.hpp"

#include "base/option_table.hpp"
#include "model/rigid.hpp"
#include "run/impact.hpp"
#include "run/impact_point.hpp"
#include "run/results_table.hpp"
#include "run/scenario.hpp"
#include "system/structure_part.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace beamimpact {

bool ObliqueImpact(const Scenario &sc)
{
  return sc.impact.offset != 0 || sc.impact.angle != 0 || sc.ball.spin != 0 || sc.swing.face_speed != 0 || sc.flight.on;
}

namespace {

// The incoming spin's bound: the ball's surface below the speed of sound.
PetscErrorCode ObliqueSpinCheck(MPI_Comm comm, const BallParams &ball)
{
  PetscFunctionBeginUser;
  PetscCheck(std::abs(ball.spin) < FlightSpinMax(ball.radius), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-ball_spin %s is not allowed: it moves the ball's surface at %g m/s (-ball_radius %g m), beyond the "
             "speed of sound in air (%g m/s), where neither the contact nor the flight "
             "models hold; |spin| must be below %g rad/s",
             OptionWritten("-ball_spin").c_str(), (double)(std::abs(ball.spin) * ball.radius), (double)ball.radius,
             (double)kSpeedOfSound, (double)FlightSpinMax(ball.radius));
  PetscFunctionReturn(0);
}

// A bat's oblique impact: a round section at the point, the ball's radius, an offset that hits.
PetscErrorCode ObliqueBatCheck(MPI_Comm comm, const Scenario &sc, PetscReal R)
{
  const PetscReal D = sc.impact.offset, R_b = sc.ball.radius;

  PetscFunctionBeginUser;
  PetscCheck(sc.impact.angle == 0, comm, PETSC_ERR_ARG_INCOMP,
             "-impact_angle %s is not allowed here: the angle to the face's normal is a string bed's oblique impact, "
             "which needs a racket's bed struck inside its head's outline (-strings_frame held or beam, -impact_x "
             "and -impact_z on the head); this point (-impact_x %g m, -impact_z %g m) %s; a round bat's oblique "
             "impact is -impact_offset",
             OptionWritten("-impact_angle").c_str(), (double)sc.impact.x, (double)sc.impact.z,
             StructurePartsHaveFace(sc.beam) ? "is off the head's outline" : "is on a beam without a string bed");
  PetscCheck(sc.swing.face_speed == 0, comm, PETSC_ERR_ARG_INCOMP,
             "-bat_speed_face %s is not allowed here: it is a racket's brush along its face, for an impact on a string "
             "bed inside its head's outline; this point (-impact_x %g m, -impact_z %g m) %s",
             OptionWritten("-bat_speed_face").c_str(), (double)sc.impact.x, (double)sc.impact.z,
             StructurePartsHaveFace(sc.beam) ? "is off the head's outline" : "is on a beam without a string bed");
  if (D == 0 && sc.ball.spin == 0) PetscFunctionReturn(0);
  const char *what = D != 0 ? "-impact_offset" : "-ball_spin";
  PetscCheck(R > 0, comm, PETSC_ERR_ARG_INCOMP,
             "%s %s: an oblique impact needs the bat's radius at the impact point, which only a round profile gives "
             "(-beam_profile); this beam's section is %s, which has no radius (a strip or a "
             "table of properties is not round)",
             what, OptionWritten(what).c_str(), SectionSourceName(sc.beam.section.source));
  PetscCheck(R_b > 0, comm, PETSC_ERR_ARG_INCOMP,
             "%s %s: an oblique impact needs the ball's radius: give -ball_radius (m)", what,
             OptionWritten(what).c_str());
  PetscCall(ObliqueSpinCheck(comm, sc.ball));
  PetscCheck(std::abs(D) < R_b + R, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-impact_offset %s misses the bat: |D| must be < R_b + R_bat = %g m (-ball_radius %g m plus the bat's "
             "radius %g m at -impact_x %g m)",
             OptionWritten("-impact_offset").c_str(), (double)(R_b + R), (double)R_b, (double)R, (double)sc.impact.x);
  PetscFunctionReturn(0);
}

// A string bed's oblique impact: the ball's radius, no bat's offset.
PetscErrorCode ObliqueBedCheck(MPI_Comm comm, const Scenario &sc)
{
  PetscFunctionBeginUser;
  PetscCheck(sc.impact.offset == 0, comm, PETSC_ERR_ARG_INCOMP,
             "-impact_offset %s is not allowed on a string bed: it is a round bat's (the ball's line off the bat's "
             "axis); the bed's face is flat: give the ball's path from its normal, -impact_angle (deg)",
             OptionWritten("-impact_offset").c_str());
  if (sc.impact.angle == 0 && sc.ball.spin == 0 && sc.swing.face_speed == 0) PetscFunctionReturn(0);
  const char *what = sc.impact.angle != 0 ? "-impact_angle" : sc.ball.spin != 0 ? "-ball_spin" : "-bat_speed_face";
  PetscCheck(sc.ball.radius > 0, comm, PETSC_ERR_ARG_INCOMP,
             "%s %s: an oblique impact on the strings needs the ball's radius: give -ball_radius (m)", what,
             OptionWritten(what).c_str());
  PetscCall(ObliqueSpinCheck(comm, sc.ball));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ObliqueNormalScenario(MPI_Comm comm, const Scenario &sc, Scenario *normal)
{
  const PetscReal D   = sc.impact.offset;
  const PetscReal R   = RoundSectionRadiusAt(sc.beam.section, sc.impact.x);
  const bool      bed = ImpactOnBed(sc.beam, sc.impact.x, sc.impact.z);

  PetscFunctionBeginUser;
  if (bed) PetscCall(ObliqueBedCheck(comm, sc));
  else PetscCall(ObliqueBatCheck(comm, sc, R));
  *normal             = sc;
  ObliqueIncoming &in = normal->oblique;
  in.on               = true;
  in.ball_speed       = sc.ball.speed;
  in.swing            = sc.swing;
  in.bat_radius       = bed ? 0 : R;
  in.bed              = bed;
  if (bed) { // the bed's frame: theta 0; the swing is along the bed's normal already
    in.angle           = sc.impact.angle * M_PI / 180;
    normal->ball.speed = std::cos(in.angle) * sc.ball.speed;
    PetscFunctionReturn(0);
  }
  if (D != 0) in.geometry = ObliqueGeometryOf(D, sc.ball.radius, R); // head-on: theta = 0, cos theta = 1 exactly
  const PetscReal c                  = in.geometry.cos_theta;
  normal->ball.speed                 = c * sc.ball.speed;
  normal->swing.bat_speed            = c * sc.swing.bat_speed;
  normal->swing.bat_angular_velocity = c * sc.swing.bat_angular_velocity;
  PetscFunctionReturn(0);
}

namespace {

// The bat's rigid second plane at the impact point: its effective mass and roll inertia. On a
// string bed (face) the plane is the face's: the frame turns in it about the normal with about its
// pitch and roll inertias together (sum m ((x - x_cm)^2 + z^2), the frame thin along the normal).
void TangentialBat(const Scenario &sc, bool face, TangentialModel *m)
{
  const BeamParams   &b         = sc.beam;
  const BeamRigidBody body      = BeamRigidBodyOf(b);
  const bool          ends_free = b.left == Support::Free && b.right == Support::Free && !b.has_clamp;
  const PetscReal     yaw       = face ? body.inertia_roll : 0;
  if (ends_free && !b.has_pivot) {
    m->bat_mass         = RigidEffectiveMass(body.mass, body.inertia_cm + yaw, std::abs(sc.impact.x - body.x_cm));
    m->bat_roll_inertia = b.section.source == SectionSource::Profile && !face
                          ? 2 * SectionMomentsOf(b.section, 0, SectionLength(b.section)).j
                          : PETSC_INFINITY;
  } else if (ends_free && sc.impact.x != b.pivot_x) {
    m->bat_mass = (PivotRigOf(body, b.pivot_x, sc.ball.mass, sc.impact.x).inertia_pivot + yaw) /
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
  const BeamSystem      &S = *beam.sys;
  const PetscInt         n = modes->S.n, f = S.fields;
  std::vector<PetscReal> at(S.ndof, std::nan("")); // m: the point each translational dof moves with (NaN: none)
  for (PetscInt dof = 0; dof < S.ndof; dof += f) at[dof] = S.NodeX(dof / f);
  for (const RigidPoint &r : S.rigid_points) at[r.dof] = r.x; // a registered part's point masses (an absorber)
  *P = 0, *L = 0;
  for (size_t k = 0; k < p.zd.size(); ++k) {
    const PetscReal *phi = &modes->B.Phi[k * n];
    PetscReal        r   = 0,
              x = 0; // sum m_d v_d and m_d x_d v_d per unit zd_k, over the translational dofs: v = M^{-1/2} phi zd
    for (PetscInt d = 0; d < n; ++d) {
      const PetscReal xd = at[modes->S.dof[d]];
      if (std::isnan(xd)) continue;
      r += phi[d] * std::sqrt(modes->S.mass[d]);
      x += phi[d] * std::sqrt(modes->S.mass[d]) * xd;
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

} // namespace

namespace {

// The ball's side of the tangential model, and l from e_T on the model's rigid effective mass (the
// ball's property, the same for both planes' models); without friction the spring carries no
// force: none (its zero-force steps left -6e-71 J of round-off). The bat's side: m->bat_* first.
void TangentialBallSet(const BallParams &ball, const ImpactSeries &series, TangentialModel *m)
{
  m->ball_mass    = ball.mass;
  m->ball_radius  = ball.radius;
  m->ball_inertia = ball.inertia_factor * ball.mass * ball.radius * ball.radius;
  m->friction     = ball.friction;
  if (ball.tangential_cor >= 0 && ball.radius > 0 && ball.inertia_factor > 0 && ball.friction > 0)
    m->compliance_length = TangentialComplianceLength(m->EffectiveMass(), ball.tangential_cor, series.time,
                                                      series.force, series.force_rate);
}

size_t SeriesPieces(const ImpactSeries &S) { return std::min(S.time.size(), S.force.size()); }

// The tangential contact on the rigid model over the run's F_n series.
void TangentialRigidRun(const TangentialModel &m, const ImpactSeries &series, TangentialState *c)
{
  for (size_t k = 0; k + 1 < SeriesPieces(series); ++k) {
    const NormalPiece f = NormalPieceOf(series, k);
    TangentialAdvance(m, series.time[k], series.time[k + 1], f.F0, f.F1, f.dF0, f.dF1, c);
  }
}

// The tangential contact on the flexible plane rec->plane over the run's F_n series; after each
// step, watch(rec) (may be empty).
template <class Watch>
void TangentialFlexibleRun(const TangentialModel &m, const ImpactSeries &series, ObliqueRecord *rec, Watch watch)
{
  for (size_t k = 0; k + 1 < SeriesPieces(series); ++k) {
    const NormalPiece f = NormalPieceOf(series, k);
    TangentialAdvanceFlexible(m, series.time[k], series.time[k + 1], f.F0, f.F1, f.dF0, f.dF1, &rec->plane,
                              &rec->contact);
    watch(rec);
  }
}

// The exit from the normal speed and the tangential contact's impulse.
void ExitOf(PetscReal u_n, ObliqueRecord *rec)
{
  const bool touches = rec->model.ball_radius > 0 && rec->model.ball_inertia > 0;
  rec->after         = touches ? TangentialBodiesAfter(rec->model, rec->before, rec->contact.impulse) : rec->before;
  if (rec->flexible) rec->after.v_bat = rec->plane.PointVelocity();
  rec->exit = ObliqueExitOf(rec->geometry, u_n, rec->after.v_ball);
}

// The string bed in its own plane (model/oblique.hpp, BedInPlaneModel): the mains under the ball
// (-strings_inplane_*, else from the tension: StringBedInPlaneOf) on the frame's rigid motion
// along t, driven by the friction force; their slide and energy watched at the run's steps.
void BedInPlaneRun(const Scenario &sc, const ImpactSeries &series, ObliqueRecord *rec)
{
  BedInPlaneModel &b = rec->bed_plane;
  b.frame_mass       = rec->model.bat_mass;
  StructurePartsInPlane(sc.beam, sc.impact.x, sc.impact.z, &b.stiffness, &b.strings_mass); // the bed part's mains
  rec->plane           = BedInPlaneOf(b, &rec->plane_rigid_modes);
  rec->plane.ball_side = rec->before.v_ball - rec->before.v_bat - rec->model.ball_radius * rec->before.spin;
  rec->flexible        = true;
  rec->contact         = TangentialFlexibleStart(rec->model, rec->plane);
  TangentialFlexibleRun(rec->model, series, rec, [](ObliqueRecord *r) {
    r->bed_slide_peak  = std::max(r->bed_slide_peak, std::abs(BedInPlaneSlide(r->bed_plane, r->plane)));
    r->bed_energy_peak = std::max(r->bed_energy_peak, BedInPlaneEnergy(r->plane, r->plane_rigid_modes));
  });
  const TangentialPlane &p = rec->plane;
  rec->plane_vibration     = BedInPlaneEnergy(p, rec->plane_rigid_modes);
  rec->plane_momentum      = rec->plane_rigid_modes ? p.zd[0] / p.gamma[0] : 0; // sqrt(M_t + m_s) zd_0; held: 0
  rec->model.bat_mass      = PETSC_INFINITY; // the frame's motion is the plane's: the ball from J
}

// An oblique impact on a string bed (oblique.hpp): the bed's frame, a flat face (no radius, no
// roll), the ball's path at -impact_angle from the normal, the swing along the normal.
PetscErrorCode ObliqueBedFinish(const Scenario &sc, const ImpactSeries &series, PetscReal u_n, ObliqueRecord *rec)
{
  const ObliqueIncoming &in = sc.oblique;
  TangentialModel        m;

  PetscFunctionBeginUser;
  rec->on = rec->bed = true;
  rec->geometry      = in.geometry; // theta 0: n the bed's normal
  TangentialBat(sc, true, &m);      // the frame's effective mass along t at the point (held: infinite)
  m.bat_roll_inertia = PETSC_INFINITY;
  TangentialBallSet(sc.ball, series, &m);
  rec->model         = m;
  rec->before.v_ball = in.ball_speed * std::sin(in.angle);
  rec->before.spin   = 0 - sc.ball.spin;    // counter-clockwise in (n, t), as the bat's (0 - s: no spin is +0, not -0)
  rec->before.v_bat  = sc.swing.face_speed; // the brush; the plane moves relative to it (Galilean along t)
  const PetscReal u0 = rec->before.v_ball - m.ball_radius * rec->before.spin - rec->before.v_bat;
  rec->contact       = TangentialStart(m, u0);
  if (u0 != 0 && m.friction > 0 && m.ball_radius > 0 && m.ball_inertia > 0) {
    if (sc.impact.tangential_rigid) TangentialRigidRun(m, series, &rec->contact);
    else BedInPlaneRun(sc, series, rec);
  }
  ExitOf(u_n, rec);
  if (rec->flexible) rec->after.v_bat += rec->before.v_bat; // the plane's point relative to the brush
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ObliqueFinish(const Scenario &sc, const ImpactSeries &series, PetscReal u_n, const ObliqueBeam &beam,
                             ObliqueRecord *rec)
{
  const ObliqueIncoming &in = sc.oblique;
  TangentialModel        m;

  PetscFunctionBeginUser;
  if (in.bed) {
    PetscCall(ObliqueBedFinish(sc, series, u_n, rec));
    PetscFunctionReturn(0);
  }
  rec->on       = true;
  rec->geometry = in.geometry;
  m.bat_radius  = in.bat_radius;
  TangentialBat(sc, false, &m);
  TangentialBallSet(sc.ball, series, &m);
  const BeamRigidBody body = BeamRigidBodyOf(sc.beam);
  const PetscReal     V_in = SwingSpeedAt(in.swing, body, sc.impact.x); // toward the ball, as given
  const PetscReal     s    = in.geometry.sin_theta;
  rec->model               = m;
  rec->before.v_ball       = in.ball_speed * s;
  rec->before.spin         = -sc.ball.spin; // counter-clockwise in (y, z): the incoming backspin turns clockwise
  rec->before.v_bat        = -V_in * s;
  rec->before.roll         = 0;
  const PetscReal u0       = (rec->before.v_ball - m.ball_radius * rec->before.spin) - rec->before.v_bat;
  rec->contact             = TangentialStart(m, u0);
  const bool touches       = m.ball_radius > 0 && m.ball_inertia > 0;
  const bool flexible      = touches && u0 != 0 && m.friction > 0 && !sc.impact.tangential_rigid;
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
    TangentialFlexibleRun(m, series, rec, [](ObliqueRecord *) {});
    PetscCall(TangentialPlaneFinish(beam, rec));
    rec->model.bat_mass = PETSC_INFINITY; // the bat's translation is the plane's: the ball and the roll from J
  } else if (touches && u0 != 0) TangentialRigidRun(m, series, &rec->contact);
  ExitOf(u_n, rec);
  if (rec->flexible) rec->after.v_bat += rec->before.v_bat; // the plane's point relative to the brush
  PetscFunctionReturn(0);
}

} // namespace beamimpact

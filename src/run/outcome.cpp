// The outcome of a run. See outcome.hpp.
#include "run/outcome.hpp"

#include "system/structure_part.hpp"

#include <cstdio>
#include <limits>
#include <utility>

namespace beamimpact {

namespace {

// The beam's rigid-body part at the end over the dofs that can move (held dofs never move); a
// rigid rotation of a Timoshenko beam also turns its sections (psi = theta).
void RigidPartAtEnd(const BeamSystem &S, OutcomeFacts *f)
{
  PetscReal      M = 0, Mx = 0, Mxx = 0, Izz = 0;
  const PetscInt roll = S.RollField();
  for (PetscInt d = 0; d < S.ndof; ++d) {
    if (S.held[d]) continue;
    const PetscInt  fld = d % S.fields;
    const PetscReal x = S.NodeX(d / S.fields), m = S.mass[d];
    if (S.Deflection(fld)) { // the beam's and a string bed's deflections
      const PetscReal z = S.DofZ(d);
      M += m, Mx += m * x, Mxx += m * x * x, Izz += m * z * z;
    } else if (S.Rotation(fld)) Mxx += m; // rotary inertia of a Timoshenko section
    else if (fld == roll) Izz += m;       // the sections' rho J
  }
  for (const RigidPoint &r : S.rigid_points) { // a registered part's point masses
    if (S.held[r.dof]) continue;
    const PetscReal m = S.mass[r.dof];
    M += m, Mx += m * r.x, Mxx += m * r.x * r.x;
  }
  const PetscReal x_cm = Mx / M, I_cm = Mxx - M * x_cm * x_cm;
  f->beam_mass  = M;
  f->inertia_cm = I_cm;
  f->moment_cm  = f->end.beam_moment - x_cm * f->end.beam_momentum;
  if (roll < 0) return;
  f->inertia_roll = Izz; // about the axis z = 0: the bed is symmetric across it, its centre of mass on the axis
  f->moment_roll  = f->end.beam_roll;
}

// A registered part's column: computed from its slots and its account's energies where the part is
// in the system, else NaN (a flag 0).
double PartColumnValue(const ResultColumn &c, const BeamSystem &sys, const OutcomeFacts &f)
{
  for (const PartInstance &p : sys.parts) {
    if (p.part != c.owner) continue;
    PartOutputFacts pf;
    pf.start                 = f.start.part_slot + p.slot0;
    pf.end                   = f.end.part_slot + p.slot0;
    pf.peak                  = f.peaks->part_peak + p.slot0;
    const PetscInt a         = StructureAccountOf(*p.part); // its own energy account (0: none)
    pf.account_end           = a > 0 ? f.end.account_energy[a] : 0;
    pf.account_peak          = a > 0 ? f.peaks->account_energy[a] : 0;
    pf.account_flexible      = a > 0 ? f.split.flexible[a] : 0;
    pf.apart_deflection_peak = f.peaks->apart_deflection;
    pf.face_deflection_peak  = f.peaks->face_deflection;
    pf.impact_x              = f.sc->impact.x;
    pf.E_in                  = f.E_in;
    pf.params                = p.params.get();
    pf.beam                  = &f.sc->beam;
    pf.frame_force_peak      = f.peaks->frame_force;
    pf.frame_force_peak_time = f.peaks->frame_force_time;
    return c.part_compute(pf);
  }
  return c.integer ? 0 : std::numeric_limits<double>::quiet_NaN(); // a flag always applies
}

} // namespace

ImpactScales ImpactScalesOf(const ContactScales &scales)
{
  ImpactScales s;
  s.contact_time_scale = scales.time;
  s.compression_scale  = scales.compression;
  return s;
}

void ImpactOutcomeFinish(const Scenario &sc, const BeamSystem &sys, ImpactRecord &&rec, ImpactResult *res)
{
  const PetscReal nan = std::numeric_limits<PetscReal>::quiet_NaN();
  OutcomeFacts    f;

  f.sc         = &sc;
  f.contact    = &rec.contact;
  f.peaks      = &rec.peaks;
  f.start      = rec.start;
  f.end        = rec.end;
  f.energy_in  = rec.energy_in;
  f.energy_end = rec.energy_end;
  f.final_time = rec.final_time;
  f.V_x        = rec.V_x;
  f.E_in       = 0.5 * sc.ball.mass * sc.ball.speed * sc.ball.speed + rec.start.beam_kinetic; // a swinging bat's too
  f.oblique    = &rec.oblique;
  RigidPartAtEnd(sys, &f);
  f.split = EnergySplitOf(sc.beam, sys, f.end);
  for (const ResultColumn &c : ImpactResultColumns())
    if (c.compute) c.Set(res, c.applies(sc) ? c.compute(f) : nan);
    else if (c.part_compute) c.Set(res, PartColumnValue(c, sys, f));
    else if (c.stage_compute)
      c.Set(res, c.applies(sc) ? StageColumnValue(c.stage_compute, (size_t)c.stage, sc, rec.oblique) : nan);
  res->events = std::move(rec.contact.events);
  res->series = std::move(rec.series);
  RunStagesSeries(rec.oblique, &res->series); // a stage's own series (the flight's)
  res->after_used    = rec.after_used;
  res->mode_energies = std::move(rec.mode_energies);
  res->modal         = rec.modal;
  for (ModeEnergy &e : res->mode_energies) e.fraction = f.E_in > 0 ? e.energy / f.E_in : nan;
  res->scales = ImpactScalesOf(rec.scales);
}

std::string CompressionBeyondRadiusText(const Scenario &sc, const ImpactResult &r)
{
  if (!r.compression_beyond_radius) return "";
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "warning: the maximum compression %.4g m is beyond the ball's radius (-ball_radius %g m, %.3g times "
                "it): physically absurd, the contact law is used far outside its range "
                "(check -ball_speed %g m/s and the stiffness)",
                (double)r.max_compression, (double)sc.ball.radius, (double)(r.max_compression / sc.ball.radius),
                (double)sc.ball.speed);
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
  else
    std::snprintf(cap, sizeof cap, "the default cap on the simulated time (%g s: 4 windows + 100 contact times)",
                  (double)times.max_time);
  std::snprintf(msg, sizeof msg,
                "the run was cut off in contact: %s ended it at t = %g s while the ball was still touching the beam "
                "(contact %d began at t = %g s), so it has no ACOR, "
                "peak force or compression; raise -impact_max_time (the run needs the contact's end plus "
                "-impact_window %g s: more than %g s), or leave it unset",
                cap, (double)r.final_time, (int)r.contacts, (double)start, (double)times.window,
                (double)(r.final_time + times.window));
  return msg;
}

} // namespace beamimpact

// The results table. See results_table.hpp; docs/results.md lists it for readers (beamimpact -help_markdown results).
#include "run/results_table.hpp"

#include "model/rigid.hpp"
#include "run/impact_point.hpp"
#include "run/stage.hpp"
#include "run/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace beamimpact {

bool ResultAlways(const Scenario &) { return true; }

bool ResultNoHeldDof(const Scenario &sc)
{
  const BeamParams &b = sc.beam;
  return b.left == Support::Free && b.right == Support::Free && !b.has_clamp && !b.has_pivot;
}

bool ResultMomentumInvariant(const Scenario &sc)
{
  return ResultNoHeldDof(sc) && !StructurePartsTieToFrame(sc.beam) && sc.beam.damping_mass == 0;
}

bool ResultFreeBeamAtRest(const Scenario &sc)
{
  return ResultNoHeldDof(sc) && !StructurePartsTieToFrame(sc.beam) && !sc.swing.Swings();
}

bool ResultFreePivot(const Scenario &sc) { return sc.beam.has_pivot && PivotHeldText(sc).empty(); }

bool ResultSegment(const Scenario &sc) { return sc.monitor.segment; }
bool ResultTwist(const Scenario &sc) { return sc.beam.parts.Rolls(); }
bool ResultTwistInvariant(const Scenario &sc) { return ResultTwist(sc) && ResultMomentumInvariant(sc); }
bool ResultTwistNoHeld(const Scenario &sc) { return ResultTwist(sc) && ResultNoHeldDof(sc) && sc.ball.speed > 0; }

std::string PivotHeldText(const Scenario &sc)
{
  const BeamParams &b = sc.beam;
  std::string       held;
  auto              add = [&](const std::string &what) { held += (held.empty() ? "" : ", ") + what; };
  if (!b.has_pivot) return "";
  if (b.left != Support::Free) add(std::string("-beam_left ") + SupportName(b.left));
  if (b.right != Support::Free) add(std::string("-beam_right ") + SupportName(b.right));
  if (b.has_clamp) add("-beam_clamp"); // (the hands and a pivot: refused)
  return held;
}

bool ResultColumn::Applies(const Scenario &sc) const
{
  return owner && !integer ? sc.beam.parts.Has(owner->Name()) : applies(sc);
}

double ResultColumn::Get(const ImpactResult &r) const
{
  if (keyed >= 0) return keyed < (PetscInt)r.keyed.size() ? r.keyed[keyed] : std::numeric_limits<double>::quiet_NaN();
  if (real) return r.*real;
  if (count) return (double)(r.*count);
  return (double)(r.*flag);
}

void ResultColumn::Set(ImpactResult *r, double v) const
{
  if (keyed >= 0) {
    if (keyed >= (PetscInt)r->keyed.size()) r->keyed.resize(keyed + 1, std::numeric_limits<double>::quiet_NaN());
    r->keyed[keyed] = v;
  } else if (real) r->*real = v;
  else if (count) r->*count = (PetscInt)v;
  else r->*flag = v != 0 ? PETSC_TRUE : PETSC_FALSE;
}

namespace {

using Compute = double (*)(const OutcomeFacts &);

ResultColumn Real(const char *name, const char *unit, PetscReal ImpactResult::*field, ResultApplies applies,
                  const char *applies_text, Compute compute, const char *description)
{
  ResultColumn c{name, unit, description, applies, applies_text};
  c.compute = compute;
  c.real    = field;
  return c;
}

// A share of E_in (ResultColumn::share).
ResultColumn Share(ResultColumn c, const char *label)
{
  c.share = label;
  return c;
}

ResultColumn Count(const char *name, PetscInt ImpactResult::*field, Compute compute, const char *description)
{
  ResultColumn c{name, "1", description, ResultAlways, "always"};
  c.integer = true;
  c.compute = compute;
  c.count   = field;
  return c;
}

ResultColumn Flag(const char *name, PetscBool ImpactResult::*field, Compute compute, const char *description)
{
  ResultColumn c{name, "1", description, ResultAlways, "always"};
  c.integer = true;
  c.compute = compute;
  c.flag    = field;
  return c;
}

const char *const kAlways  = "always";
const char *const kStrings = "with a string bed (-strings_frame held or beam)";
const char *const kNoHeld  = "a beam with no held dof (both ends free, no -beam_clamp, no -beam_pivot)";
// A ball at rest (-ball_speed 0, struck by a swinging bat) has no ACOR.
bool              BallMoves(const Scenario &sc) { return sc.ball.speed > 0; }
const char *const kBallMoves = "a moving ball (-ball_speed > 0; a ball at rest has no ACOR)";
// The fractions of the energy brought in, E_in (the ball's and a swinging bat's kinetic energy):
// always (a ball at rest is refused without a swing), each where its energy is tracked. Together
// they close to 1 (run/energy_parts.hpp, docs/model.md section 4).
bool EnergyIn(const Scenario &sc) { return sc.ball.speed > 0 || sc.swing.Swings(); }
bool EnergyInTranslation(const Scenario &sc) { return EnergyIn(sc) && HasRigidMotion(sc.beam, RigidKind::Translation); }
bool EnergyInRotation(const Scenario &sc) { return EnergyIn(sc) && HasRigidMotion(sc.beam, RigidKind::Rotation); }
bool EnergyInRoll(const Scenario &sc) { return EnergyIn(sc) && HasRigidMotion(sc.beam, RigidKind::Roll); }
const char *const kEnergyIn    = "always (E_in > 0: a moving ball or a swinging bat)";
const char *const kTranslation = "a structure with no held dof (both ends free, no -beam_clamp, no -beam_pivot)";
const char *const kRotation = "a structure with no held dof, or held at one pin only (-beam_pivot or one pinned end, "
                              "no clamp): its rigid rotation about the centre of mass, or about the pin";
const char *const kRoll     = "with -beam_torsion and no clamp (a clamped end or -beam_clamp holds the roll)";
// The momenta's reference: the ball's, or a ball at rest's swinging bat's.
PetscReal MomentumScale(const OutcomeFacts &f)
{
  return f.sc->ball.speed > 0 ? f.sc->ball.mass * f.sc->ball.speed : std::abs(f.start.momentum);
}

// The ball's quantities that depend on its law: an elastic law keeps all the work done on it,
// so the paper corrects its ACOR (and the ball's loss) by -ball_loss_factor.

PetscReal Acor(const OutcomeFacts &f) { return -f.end.ball_v / f.sc->ball.speed; }
PetscReal AcorCorrected(const OutcomeFacts &f)
{
  return ContactElastic(f.sc->ball) ? Acor(f) * f.sc->ball.loss_factor : Acor(f);
}
PetscReal BallDissipated(const OutcomeFacts &f) { return f.end.ball_work - f.end.ball_stored; }
PetscReal CollisionEfficiency(const OutcomeFacts &f)
{
  return SwingCollisionEfficiency(-f.end.ball_v, f.sc->ball.speed, f.V_x);
}
PivotRig RigOf(const OutcomeFacts &f)
{
  return PivotRigOf(BeamRigidBodyOf(f.sc->beam), f.sc->beam.pivot_x, f.sc->ball.mass, f.sc->impact.x);
}
// Eq. (11) with the beam's own mass, centre of mass and inertia (for the paper's uniform beam
// M = mu L, I_cm = M L^2/12 about its centre), struck at x.
PetscReal RigidMassAt(const OutcomeFacts &f)
{
  const BeamRigidBody body = BeamRigidBodyOf(f.sc->beam);
  const PetscReal     M_e  = RigidEffectiveMass(body.mass, body.inertia_cm, std::abs(f.sc->impact.x - body.x_cm));
  const PetscReal     z    = f.sc->impact.z; // off the axis: the roll adds z^2 / I_x to 1/M_e
  return z != 0 && body.inertia_roll > 0 ? 1 / (1 / M_e + z * z / body.inertia_roll) : M_e;
}

using R = ImpactResult;
using F = const OutcomeFacts &;

// The impact, the energies and the bat (the hands' columns follow bbcor: their part's).
std::vector<ResultColumn> OutcomeColumns()
{
  return {
    Real(
      "x", "m", &R::x, ResultAlways, kAlways, [](F f) -> double { return f.sc->impact.x; }, "impact point x_imp"),
    Real(
      "acor", "1", &R::acor, BallMoves, kBallMoves, [](F f) -> double { return Acor(f); },
      "apparent coefficient of restitution -v_b,final / v_i"),
    Real(
      "acor_corrected", "1", &R::acor_corrected, BallMoves, kBallMoves, [](F f) -> double { return AcorCorrected(f); },
      "an elastic law (linear, hertz): acor x -ball_loss_factor; otherwise acor"),
    Real(
      "contact_time", "s", &R::contact_time, ResultAlways, kAlways,
      [](F f) -> double { return f.contact->contact_time; },
      "duration of the first contact (its start to the first separation)"),
    Real(
      "contact_time_total", "s", &R::contact_time_total, ResultAlways, kAlways,
      [](F f) -> double { return f.contact->contact_time_total; }, "contact time summed over all contacts"),
    Real(
      "peak_force", "N", &R::peak_force, ResultAlways, kAlways, [](F f) -> double { return f.contact->peak_force; },
      "largest force at a maximum-compression event"),
    Real(
      "max_compression", "m", &R::max_compression, ResultAlways, kAlways,
      [](F f) -> double { return f.contact->max_compression; }, "largest compression at a maximum-compression event"),
    Count(
      "contacts", &R::contacts, [](F f) -> double { return (double)f.contact->contacts; },
      "separate contacts (1: a single impact)"),
    Flag(
      "ended_in_contact", &R::ended_in_contact, [](F f) -> double { return f.contact->touching ? 1 : 0; },
      "1 if the run reached -impact_max_time while touching"),
    Flag(
      "compression_beyond_radius", &R::compression_beyond_radius,
      [](F f) -> double { return f.sc->ball.radius > 0 && f.contact->max_compression > f.sc->ball.radius ? 1 : 0; },
      "1 if max_compression exceeds -ball_radius (given): physically absurd (a sweep's summary counts such rows)"),
    Real(
      "ball_final_velocity", "m/s", &R::ball_final_velocity, ResultAlways, kAlways,
      [](F f) -> double { return f.end.ball_v; }, "the ball's velocity at the end (negative: rebound)"),
    Real(
      "final_time", "s", &R::final_time, ResultAlways, kAlways, [](F f) -> double { return f.final_time; },
      "simulated time at the end"),
    Real(
      "energy_in", "J", &R::energy_in, ResultAlways, kAlways, [](F f) -> double { return f.E_in; },
      "E_in, the energy brought in: the ball's 1/2 m_b v_i^2 and a swinging bat's kinetic energy (lab frame); the "
      "*_fraction columns' denominator"),
    Real(
      "energy_error", "1", &R::energy_error, ResultAlways, kAlways,
      [](F f) -> double { return (f.energy_end - f.energy_in) / f.energy_in; },
      "(E_end - E_0) / E_0 of the conserved total (ball work and dissipated energy included)"),
    Real(
      "linear_momentum_error", "1", &R::linear_momentum_error, ResultMomentumInvariant,
      "where momentum is an invariant: no held dof, no -grip, -beam_damping_mass 0",
      [](F f) -> double { return (f.end.momentum - f.start.momentum) / MomentumScale(f); },
      "change of the total linear momentum / (m_b v_i) (a ball at rest: / the bat's)"),
    Real(
      "angular_momentum_error", "1", &R::angular_momentum_error, ResultMomentumInvariant,
      "where momentum is an invariant: no held dof, no -grip, -beam_damping_mass 0",
      [](F f) -> double {
        return (f.end.angular_momentum - f.start.angular_momentum) / (MomentumScale(f) * f.sc->beam.length);
      },
      "change of the angular momentum about x = 0 / (m_b v_i L) (a ball at rest: the bat's momentum for m_b v_i)"),
    Real(
      "beam_kinetic_end", "J", &R::beam_kinetic_end, ResultAlways, kAlways,
      [](F f) -> double { return f.end.beam_kinetic; }, "the beam's kinetic energy at the end"),
    Real(
      "beam_strain_end", "J", &R::beam_strain_end, ResultAlways, kAlways,
      [](F f) -> double { return f.end.beam_strain; }, "the beam's strain energy at the end"),
    Real(
      "ball_kinetic_end", "J", &R::ball_kinetic_end, ResultAlways, kAlways,
      [](F f) -> double { return f.end.ball_kinetic; }, "the ball's kinetic energy at the end (its rebound)"),
    Real(
      "ball_dissipated_end", "J", &R::ball_dissipated_end, ResultAlways, kAlways,
      [](F f) -> double { return BallDissipated(f); }, "energy dissipated in the ball (0 for an elastic law)"),
    Share(Real(
            "ball_loss_fraction", "1", &R::ball_loss_fraction, EnergyIn, kEnergyIn,
            [](F f) -> double {
              const BallParams &b = f.sc->ball;
              return (ContactElastic(b) ? (1 - b.loss_factor * b.loss_factor) * f.end.ball_kinetic
                                        : BallDissipated(f)) /
                     f.E_in;
            },
            "the ball's loss / E_in: dissipated (hysteresis); (1 - loss_factor^2) of its rebound energy (elastic)"),
          "ball loss"),
    Share(Real(
            "rebound_fraction", "1", &R::rebound_fraction, EnergyIn, kEnergyIn,
            [](F f) -> double {
              return (ContactElastic(f.sc->ball) ? f.sc->ball.loss_factor * f.sc->ball.loss_factor : 1) *
                     f.end.ball_kinetic / f.E_in;
            },
            "the ball's rebound energy 1/2 m_b v_b,final^2 / E_in (lab frame; elastic laws: times loss_factor^2); a "
            "bat at rest: acor_corrected^2"),
          "ball rebound"),
    Share(Real(
            "translation_fraction", "1", &R::translation_fraction, EnergyInTranslation, kTranslation,
            [](F f) -> double { return f.split.rigid[(int)RigidKind::Translation] / f.E_in; },
            "the structure's rigid translation P^2/2M at the end / E_in"),
          "translation"),
    Share(Real(
            "rotation_fraction", "1", &R::rotation_fraction, EnergyInRotation, kRotation,
            [](F f) -> double { return f.split.rigid[(int)RigidKind::Rotation] / f.E_in; },
            "the structure's rigid rotation at the end / E_in: L_cm^2/2I_cm about its centre of mass (no held dof), "
            "L_p^2/2I_p about its pin"),
          "rotation"),
    Share(Real(
            "vibration_fraction", "1", &R::vibration_fraction, EnergyIn, kEnergyIn,
            [](F f) -> double { return f.split.flexible[0] / f.E_in; },
            "the beam's bending (and shear) at the end / E_in: its kinetic and strain energy less its share of the "
            "rigid motions"),
          "bending"),
    Real(
      "bbs", "m/s", &R::bbs, ResultAlways, kAlways, [](F f) -> double { return -f.end.ball_v; },
      "batted-ball speed, away from the bat (lab frame; a bat at rest: acor v_i)"),
    Real(
      "collision_efficiency", "1", &R::collision_efficiency, ResultAlways, kAlways,
      [](F f) -> double { return CollisionEfficiency(f); },
      "q = (bbs - V(x)) / (v_ball + V(x)), the ACOR in the bat's frame (a bat at rest: acor)"),
    Real(
      "bat_speed_end", "m/s", &R::bat_speed_end, ResultNoHeldDof, kNoHeld,
      [](F f) -> double { return -f.end.beam_momentum / f.beam_mass; },
      "the bat's centre-of-mass speed toward the ball at the end"),
    Real(
      "bat_angular_velocity_end", "rad/s", &R::bat_angular_velocity_end, ResultNoHeldDof, kNoHeld,
      [](F f) -> double { return f.inertia_cm > 0 ? -f.moment_cm / f.inertia_cm : 0; },
      "the bat's angular velocity about its centre of mass at the end"),
    Real(
      "recoil_factor", "1", &R::recoil_factor, ResultFreePivot,
      "with -beam_pivot and no other support or grip (a rig free to turn about its pivot)",
      [](F f) -> double { return RigOf(f).recoil_factor; }, "r = m_b (x - x_p)^2 / I_p of the rigid pivoted rig"),
    Real(
      "bbcor", "1", &R::bbcor, ResultFreePivot,
      "with -beam_pivot and no other support or grip (a rig free to turn about its pivot)",
      [](F f) -> double { return PivotBBCOR(RigOf(f), CollisionEfficiency(f)); },
      "bat-ball COR e_A (1 + r) + r of the pivoted rig"),
    Real(
      "roll_rate_end", "rad/s", &R::roll_rate_end, ResultTwistNoHeld,
      "with -beam_torsion, a moving ball and no held dof",
      [](F f) -> double { return f.inertia_roll > 0 ? f.moment_roll / f.inertia_roll : 0; },
      "the frame's rigid roll rate about its axis at the end (> 0: the +z side moves toward +y, away from the ball's "
      "approach)"),
    Share(Real(
            "roll_fraction", "1", &R::roll_fraction, EnergyInRoll, kRoll,
            [](F f) -> double { return f.split.rigid[(int)RigidKind::Roll] / f.E_in; },
            "the structure's rigid roll L_x^2/2I_x about the frame's axis at the end / E_in (not in twist_fraction or "
            "bed_fraction)"),
          "roll"),
    Real(
      "roll_momentum_error", "1", &R::roll_momentum_error, ResultTwistInvariant,
      "with -beam_torsion where momentum is an invariant",
      [](F f) -> double {
        return (f.end.roll_momentum - f.start.roll_momentum) / (MomentumScale(f) * f.sc->beam.length);
      },
      "change of the angular momentum about the frame's axis / (m_b v_i L)"),
    Real(
      "segment_kinetic_peak", "J", &R::segment_kinetic_peak, ResultSegment, "with -monitor_segment",
      [](F f) -> double { return f.peaks->segment_kinetic; }, "peak kinetic energy of the monitored segment"),
    Real(
      "segment_kinetic_peak_time", "s", &R::segment_kinetic_peak_time, ResultSegment, "with -monitor_segment",
      [](F f) -> double { return f.peaks->segment_kinetic_time; }, "when"),
  };
}

// What the run cost (the stepper's and the driver's counts), the dissipated energy, Eq. (11).
std::vector<ResultColumn> CostAndLaterColumns()
{
  return {
    Count("failed_solves", &R::failed_solves, nullptr, "nonlinear solves that failed (the step was retried smaller)"),
    Count("steps", &R::steps, nullptr, "accepted steps"),
    Count("rejected_steps", &R::rejected_steps, nullptr, "steps rejected by the error controller"),
    Count("event_steps", &R::event_steps, nullptr, "extra steps to locate events"),
    Count("function_evals", &R::function_evals, nullptr, "residual evaluations"),
    Count("jacobian_evals", &R::jacobian_evals, nullptr, "Jacobian requests"),
    Count("jacobian_assemblies", &R::jacobian_assemblies, nullptr, "Jacobian re-assemblies"),
    Count("nonlinear_its", &R::nonlinear_its, nullptr, "Newton iterations"),
    Count("linear_its", &R::linear_its, nullptr, "Krylov iterations (preonly LU: one per solve)"),
    Real("wall_time", "s", &R::wall_time, ResultAlways, kAlways, nullptr, "wall-clock time of the time stepping"),
    Real("dt_nominal", "s", &R::dt_nominal, ResultAlways, kAlways, nullptr,
         "the fixed step, or the first step of an adaptive run (0 for modal)"),
    Real("dt_stable", "s", &R::dt_stable, ResultAlways, kAlways, nullptr,
         "explicit stability limit y*/omega_max (0: not explicit)"),
    Real(
      "beam_dissipated_end", "J", &R::beam_dissipated_end, ResultAlways, kAlways,
      [](F f) -> double { return f.end.beam_dissipated; },
      "energy the beam's damping (and a grip's damper) dissipated by the end (0 undamped)"),
    Share(Real(
            "damping_fraction", "1", &R::damping_fraction, EnergyIn, kEnergyIn,
            [](F f) -> double { return f.end.beam_dissipated / f.E_in; }, "beam_dissipated_end / E_in"),
          "damping"),
    Real(
      "rigid_acor", "1", &R::rigid_acor, ResultFreeBeamAtRest, "a free beam at rest: no held dof, no -grip, no swing",
      [](F f) -> double { return RigidACOR(f.sc->ball.mass, RigidMassAt(f), f.sc->impact.rigid_loss_fraction); },
      "Eq. (11) with the loss fraction f (a sweep's -rigid_loss_fraction; 0 for -task impact)"),
    Real(
      "rigid_forced_loss_fraction", "1", &R::rigid_forced_loss_fraction, ResultFreeBeamAtRest,
      "a free beam at rest: no held dof, no -grip, no swing",
      [](F f) -> double { return RigidForcedLossFraction(f.sc->ball.mass, RigidMassAt(f), AcorCorrected(f)); },
      "the f for which Eq. (11) gives acor_corrected"),
  };
}

std::vector<ResultColumn> BuildTable()
{
  std::vector<ResultColumn> t = OutcomeColumns(), more = CostAndLaterColumns();
  t.insert(t.end(), more.begin(), more.end());
  PetscInt keyed = 0; // the stages' columns after the contact (along the line of centres the columns
                      // above are the run's: acor, bbs the normal components), then the parts', last (or
                      // after the column they name)
  for (size_t k = 0; k < RunStages().size(); ++k)
    for (const StageColumn &sc : RunStages()[k]->Columns()) {
      ResultColumn c{sc.name, sc.unit, sc.description, sc.applies, sc.applies_text};
      c.stage         = (PetscInt)k;
      c.stage_compute = sc.compute;
      c.keyed         = keyed++;
      t.push_back(c);
    }
  for (const StructurePart *p : StructureParts()) {
    auto at = t.end();
    if (const char *after = p->ColumnsAfter())
      at = std::find_if(t.begin(), t.end(), [&](const ResultColumn &c) { return !std::strcmp(c.name, after); }) + 1;
    for (const PartColumn &pc : p->Columns()) { // after the part's previous one
      ResultColumn c{pc.name, pc.unit, pc.description, nullptr, p->Presence()};
      if (pc.integer) c.applies = ResultAlways, c.applies_text = kAlways, c.integer = true; // a flag: always
      c.owner        = p;
      c.part_compute = pc.compute;
      c.keyed        = keyed++;
      c.share        = pc.share;
      at             = t.insert(at, c) + 1;
    }
  }
  return t;
}

} // namespace

std::string ImpactEnergyShareText(const Scenario &sc, const ImpactResult &r)
{
  std::string text;
  PetscReal   sum = 0;
  char        item[96];
  for (const ResultColumn &c : ImpactResultColumns()) {
    if (!c.share || !c.Applies(sc)) continue;
    std::snprintf(item, sizeof item, "%s%s %.4g", text.empty() ? "" : ", ", c.share, c.Get(r));
    text += item;
    sum += c.Get(r);
  }
  if (text.empty()) return "";
  char head[96], tail[96];
  std::snprintf(head, sizeof head, "energy: fractions of E_in = %.5g J: ", (double)r.energy_in);
  std::snprintf(tail, sizeof tail, "; their sum 1 %c %.2g (the energy error)", sum - 1 < 0 ? '-' : '+',
                (double)std::abs(sum - 1));
  return head + text + tail;
}

const std::vector<ResultColumn> &ImpactResultColumns()
{
  static const std::vector<ResultColumn> table = BuildTable();
  return table;
}

const ResultColumn *ImpactResultColumn(const std::string &name)
{
  for (const ResultColumn &c : ImpactResultColumns())
    if (name == c.name) return &c;
  return nullptr;
}

std::string ImpactResultColumnNames()
{
  std::string s;
  for (const ResultColumn &c : ImpactResultColumns()) s += (s.empty() ? "" : ",") + std::string(c.name);
  return s;
}

} // namespace beamimpact

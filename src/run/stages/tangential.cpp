// An oblique impact's tangential contact and the ball's exit (docs/model.md "Oblique impacts",
// MODEL sections 10 and 17; the physics in run/oblique.hpp and model/oblique.hpp): the first
// stage after the contact (run/stage.hpp), driven by the run along the normal's F_n(t). On a bat:
// friction on the ball and the bat's roll and second plane; on a string bed: the mains sliding
// on the frame in the face's plane. Its results columns (the exit, the spin, the friction's and
// the second plane's energies, the mains' slide) and its summary lines are this file. Units: SI.
#include "run/stage.hpp"

#include "base/option_table.hpp"
#include "run/impact_point.hpp"

#include <cmath>

namespace beamimpact {

namespace {

// Asked of the scenario as given (the run record, a file's `applies`, the summary) and of the
// run's projected one (the outcome): ObliqueImpact answers the same for both.
bool Oblique(const Scenario &sc) { return sc.oblique.on || ObliqueImpact(sc); }
bool Flexible(const Scenario &sc) { return Oblique(sc) && !sc.impact.tangential_rigid; }
bool OnBed(const Scenario &sc) { return Flexible(sc) && ImpactOnBed(sc.beam, sc.impact.x, sc.impact.z); }

const char *const kOblique  = "an oblique impact: -impact_offset, -impact_angle or -ball_spin not 0, or -flight (a "
                              "head-on hit: exit_speed = bbs, launch_angle 0, no spin)";
const char *const kFlexible = "an oblique impact with -impact_tangential_plane flexible (the default; 0 where no "
                              "friction force acts)";
const char *const kOnBed    = "an oblique impact on a string bed (-impact_angle, -ball_spin) with "
                              "-impact_tangential_plane flexible (0 where no friction force acts)";

// The columns in Columns()'s order (the summary's values).
enum Column {
  ExitSpeed,
  LaunchAngle,
  Spin,
  SpinRpm,
  Friction,
  Vibration,
  Damping,
  Slide,
  InPlanePeak,
  Returned
};

class Tangential final : public RunStage {
public:
  const char *Name() const override { return "tangential"; }
  bool        Applies(const Scenario &sc) const override { return Oblique(sc); }
  bool        NeedsForce() const override { return true; } // the friction's drive: F_n(t), dF_n/dt at each step

  PetscErrorCode Run(const StageInput &in, ObliqueRecord *rec, std::shared_ptr<const StageResult> *) const override
  {
    PetscFunctionBeginUser;
    PetscCall(ObliqueFinish(*in.sc, *in.series, in.u_n, in.beam, rec));
    PetscFunctionReturn(0);
  }

  std::vector<StageColumn> Columns() const override;

  std::string Summary(const Scenario &sc, const std::vector<double> &v) const override
  {
    std::string s;
    if (ImpactOnBed(sc.beam, sc.impact.x, sc.impact.z)) {
      s = Fmt("oblique on the strings: %g deg from the normal; the ball leaves at %.4f m/s, %.3f deg from the normal "
              "(> 0 toward +z), spin %.2f rad/s (%.0f rpm); friction dissipated %.4e J\n",
              (double)sc.impact.angle, v[ExitSpeed], Shown(v[LaunchAngle], 3), Shown(v[Spin], 2), Shown(v[SpinRpm], 0),
              v[Friction]);
      if (OnBed(sc) && v[InPlanePeak] > 0)
        s += Fmt("oblique on the strings: the mains slid %.4e m on the frame, held %.4e J at most and gave %.4e J "
                 "back (snapback), %.4e J left in their vibration\n",
                 v[Slide], v[InPlanePeak], v[Returned], v[Vibration]);
      return s;
    }
    s = Fmt("oblique: offset %g m, batted ball %.4f m/s at %.3f deg, spin %.2f rad/s (%.0f rpm, > 0 backspin); "
            "friction dissipated %.4e J (along the line of centres: acor and bbs above)\n",
            (double)sc.impact.offset, v[ExitSpeed], Shown(v[LaunchAngle], 3), Shown(v[Spin], 2), Shown(v[SpinRpm], 0),
            v[Friction]);
    if (v[Vibration] > 0)
      s += Fmt("oblique: the bat's vibration in its second plane took %.4e J (-impact_tangential_plane flexible)\n",
               v[Vibration]);
    return s;
  }
};

std::vector<StageColumn> Tangential::Columns() const
{
  using F = const StageFacts &;
  return {
    {"exit_speed", "m/s", "the batted ball's speed, normal and tangential parts together (lab frame)", Oblique,
     kOblique, [](F f) -> double { return f.oblique->exit.speed; }},
    {"launch_angle", "deg",
     "the batted ball's direction from the reversed incoming direction, > 0 upward (on a string bed: from the bed's "
     "normal, > 0 toward +z)",
     Oblique, kOblique, [](F f) -> double { return f.oblique->exit.launch_angle; }},
    {"spin", "rad/s",
     "the batted ball's spin, > 0 backspin (on a string bed: about x, the sense of a ball leaving toward +z rolling "
     "on the bed)",
     Oblique, kOblique, [](F f) -> double { return f.oblique->after.spin; }},
    {"spin_rpm", "rpm", "the same in revolutions per minute", Oblique, kOblique,
     [](F f) -> double { return f.oblique->after.spin * 30 / M_PI; }},
    {"friction_dissipated", "J",
     "energy the tangential contact took from the motions: friction's sliding, and the tangential spring's (its "
     "stiffness follows F_n); its own term, not in energy_error's E (the normal run's)",
     Oblique, kOblique,
     [](F f) -> double { return f.oblique->contact.dissipated - f.oblique->contact.stiffness_work; }},
    {"bat_vibration_tangential", "J",
     "energy left in the bat's vibration in its second plane (across the line of centres) by the friction force; its "
     "own term, beside friction_dissipated",
     Flexible, kFlexible, [](F f) -> double { return f.oblique->plane_vibration; }},
    {"bat_damping_tangential", "J",
     "energy the bat's damping (-beam_damping_*) took in its second plane up to the end of the contact; 0 for an "
     "undamped bat; its own term, beside bat_vibration_tangential",
     Flexible, kFlexible, [](F f) -> double { return f.oblique->plane_damped; }},
    {"strings_slide_peak", "m",
     "the largest sideways slide of the mains under the ball from the frame (in the face's plane, across the mains; "
     "at the run's steps)",
     OnBed, kOnBed, [](F f) -> double { return f.oblique->bed_slide_peak; }},
    {"strings_inplane_energy_peak", "J",
     "the largest energy of the mains' vibration in the face's plane (their slide's strain and motion on the frame) "
     "during the contact",
     OnBed, kOnBed, [](F f) -> double { return f.oblique->bed_energy_peak; }},
    {"strings_inplane_energy_returned", "J",
     "what of that peak the mains gave back by the separation (snapback): the peak less the energy left in their "
     "vibration (bat_vibration_tangential)",
     OnBed, kOnBed, [](F f) -> double { return f.oblique->bed_energy_peak - f.oblique->plane_vibration; }},
  };
}

} // namespace

const RunStage &TangentialStage()
{
  static const Tangential s;
  return s;
}

} // namespace beamimpact

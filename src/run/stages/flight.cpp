// The batted ball's flight after an oblique impact (-flight; docs/flight.md, MODEL section 10):
// the second stage after the contact (run/stage.hpp), from the tangential stage's exit speed,
// launch angle and spin, integrated by the flight's TS (solvers/flight_ts.hpp) to the ground.
// Its columns (distance, apex, hang_time), its series (/series/flight_*, on their own time axis
// flight_time from the launch) and its summary line are this file. Units: SI.
#include "run/stage.hpp"

#include "base/option_table.hpp"

#include <cmath>

namespace beamimpact {

namespace {

struct FlightStageResult : StageResult {
  FlightResult flight;
};
const FlightResult *Own(const StageFacts &f)
{
  return f.own ? &static_cast<const FlightStageResult *>(f.own)->flight : nullptr;
}
double Landing(const StageFacts &f, PetscReal FlightLanding::*m)
{
  const FlightResult *r = Own(f);
  return r ? r->landing.*m : std::nan("");
}
bool Flies(const Scenario &sc) { return sc.flight.on; }

class Flight final : public RunStage {
public:
  const char *Name() const override { return "flight"; }
  bool        Applies(const Scenario &sc) const override { return Flies(sc); }

  // The flight from the exit velocity and spin (the impact's own ball; its radius is required with
  // -flight: FlightBallResolve).
  PetscErrorCode Run(const StageInput &in, ObliqueRecord *rec, std::shared_ptr<const StageResult> *own) const override
  {
    const Scenario &sc = *in.sc;
    auto            r  = std::make_shared<FlightStageResult>();

    PetscFunctionBeginUser;
    FlightParams p    = sc.flight.params;
    p.ball.mass       = sc.ball.mass;
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
    PetscCall(FlightSolve(FlightModelOf(p), u, sc.flight.solve, &r->flight));
    *own = r;
    PetscFunctionReturn(0);
  }

  std::vector<StageColumn> Columns() const override
  {
    const char *const when = "with -flight";
    return {
      {"distance", "m", "the batted ball's carry: launch point to landing, horizontal", Flies, when,
       [](const StageFacts &f) -> double { return Landing(f, &FlightLanding::distance); }},
      {"apex", "m", "the flight's highest point above the ground", Flies, when,
       [](const StageFacts &f) -> double { return Own(f) ? Own(f)->apex : std::nan(""); }},
      {"hang_time", "s", "the flight's time from launch to landing", Flies, when,
       [](const StageFacts &f) -> double { return Landing(f, &FlightLanding::hang_time); }},
    };
  }

  // /series/flight_time (s, from the launch) and the ball's x, y, z (m, the flight's frame: y down
  // the field, z up) and spin (rad/s) on it, when the flight recorded them (-monitor_* asked).
  void Series(const StageResult &own, ImpactSeries *S) const override
  {
    const FlightSeries &F = static_cast<const FlightStageResult &>(own).flight.series;
    if (F.t.empty()) return;
    S->keyed.push_back({"flight_time", "s", F.t, ""});
    S->keyed.push_back({"flight_x", "m, across the field", F.x, "flight_time"});
    S->keyed.push_back({"flight_y", "m, down the field", F.y, "flight_time"});
    S->keyed.push_back({"flight_z", "m, height above the ground", F.z, "flight_time"});
    S->keyed.push_back({"flight_spin", "rad/s", F.spin, "flight_time"});
  }

  std::string Summary(const Scenario &, const std::vector<double> &v) const override
  {
    return Fmt("flight: distance %.2f m (%.1f ft), apex %.2f m, hang time %.2f s\n", v[0], v[0] / 0.3048, v[1], v[2]);
  }
};

} // namespace

const RunStage &FlightStage()
{
  static const Flight s;
  return s;
}

} // namespace beamimpact

// The scenario of one impact: what is struck (beam), by what (ball), how the run is
// followed (impact rules) and what is recorded (monitors). Read once from the options
// (io/scenario_options.hpp) and handed to every task, solver and study; a study varies
// a copy of it per point.
#pragma once

#include "model/beam.hpp"
#include "model/contact.hpp"
#include "model/swing.hpp"
#include "run/impact.hpp"
#include "run/oblique.hpp"

namespace beamimpact {

struct Scenario {
  Scenario() = default;
  Scenario(BeamParams b, BallParams l, ImpactParams i, MonitorRequest m = MonitorRequest(),
           SwingParams s = SwingParams()) :
    beam(b), ball(l), impact(i), monitor(m), swing(s)
  {
  }

  BeamParams        beam;    // -beam_*
  BallParams        ball;    // -ball_*
  ImpactParams      impact;  // -impact_*
  MonitorRequest    monitor; // -monitor_*, -snapshot_times (nothing by default)
  SwingParams       swing;   // -bat_speed, -bat_angular_velocity (a bat at rest by default)
  FlightAfterImpact flight;  // -flight: the batted ball's flight after the impact (-flight_*, -air_*)
  ObliqueIncoming   oblique; // set by run/oblique.cpp on the run along the normal of an oblique impact
};

} // namespace beamimpact

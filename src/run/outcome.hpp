// The outcome of a run: the only writer of its results. The driver (and the modal reference)
// hand it a record: the small records of the events (ContactTally: contact times, peak force,
// maximum compression, contacts) and of the monitors (MonitorPeaks), the measures of the
// first and last states, the series; the outcome computes every column of the results table
// (run/results_table.hpp) where it applies and puts NaN where it does not, and the impact's
// scales. The cost (steps, counts, wall time) and the integrator's settings are the stepper's
// and the driver's, and stay as they wrote them.
#pragma once

#include "run/measures.hpp"
#include "run/results_table.hpp"
#include "run/scenario.hpp"
#include "system/beam_system.hpp"

#include <string>

namespace beamimpact {

// What a run hands its outcome.
struct ImpactRecord {
  ContactTally contact; // run/events.cpp
  MonitorPeaks peaks;   // run/monitors.cpp
  ImpactSeries series;  // run/monitors.cpp (only what was asked)
  // The run's F_n(t) for the stages after it (run/stage.hpp; time, force and force_rate at every
  // record, ball_y, ball_v, compression beside them): only when a stage needs it, never written.
  ImpactSeries  drive;
  StateMeasures start, end;     // the measures at t = 0 and at the end
  PetscReal     energy_in  = 0; // J, the conserved total at t = 0 (start.total() for a stepper)
  PetscReal     energy_end = 0; // J, the same at the end
  PetscReal     final_time = 0; // s
  PetscReal     V_x        = 0; // m/s, the swinging bat's speed toward the ball at the impact point
  ContactScales scales;         // of the contact, at the first contact's approach speed (v_ball + V_x)
  std::string   after_used;     // -impact_after as the run resolved it
  ObliqueRecord oblique; // run/oblique.cpp: an oblique impact's tangential contact, exit and flight (on: oblique)
  std::vector<ModeEnergy> mode_energies; // J per kept mode at the end (a modal free flight's last; fraction unset)
  ModalEngineUse          modal;         // the modal engine the run used (none: kept = 0)
};

// Fills the outcome, the events, the series, the scales, after_used and the mode energies (with
// their fractions of E_in) of *res from the
// record (moved from); sys: the scenario's system (which dofs can move, their masses).
void ImpactOutcomeFinish(const Scenario &sc, const BeamSystem &sys, ImpactRecord &&rec, ImpactResult *res);

// The scales of an impact from the contact's scales: T_r and the compression scale.
ImpactScales ImpactScalesOf(const ContactScales &scales);

// The summary's warning line for compression_beyond_radius (empty if not flagged), naming both values.
std::string CompressionBeyondRadiusText(const Scenario &sc, const ImpactResult &r);

// A run that reached its cap on the simulated time (-impact_max_time, or its default) while
// the ball was still in contact has no outcome (its ACOR, peak force and compression are of a
// contact cut short): the message naming the option, the time reached, when the contact began
// and what to raise; empty if the run ended with the ball separated.
std::string ImpactCutOffReason(const Scenario &sc, const ImpactResult &r);

} // namespace beamimpact

// The results table of an impact: every column of /results defined once, with its name, unit,
// description, when it applies (a predicate of the scenario: the value is NaN in the rows where
// it does not, never a number a reader could take for one) and how it is computed from the
// run's measures (run/outcome.cpp applies the table: it is the only writer of ImpactOutcome).
// Everything that shows a result reads this table: the summary line of -task impact, the
// /results datasets of an impact file (their units, and the order in the root attribute
// results_columns that scripts/h5_to_csv.py follows), a sweep's columns.
//
// The results reference docs/results.md is printed from this table (-help_markdown results;
// `cmake --build --preset dev --target docs` rewrites it, the test docs_generated checks it).
// The columns of the stages after the contact (run/stage.hpp: the oblique impact's exit and
// spin, the flight's carry) and then a registered structure part's (system/structure_part.hpp)
// follow the table, in registry order, each applying by its stage's predicate or where its part
// is present (its applies_text the part's Presence()), stored in ImpactResult::keyed: a stage or
// a part adds its columns in its own file (a part after the column its ColumnsAfter names, if
// any: the hands' follow bbcor, their place before).
// A new column is one row in results_table.cpp and its field in ImpactOutcome (run/impact.hpp);
// a quantity the measures do not hold yet needs it in the record the driver hands the outcome
// (run/outcome.hpp), from the events (ContactTally) or the monitors (MonitorPeaks).
#pragma once

#include "run/energy_parts.hpp"
#include "run/impact.hpp"
#include "run/measures.hpp"
#include "run/scenario.hpp"
#include "run/stage.hpp"

#include <string>
#include <vector>

namespace beamimpact {

// What the outcome knows when it computes a column: the scenario, the records of the events
// and monitors, the measures of the first and last states, and the few numbers derived from
// them once (the beam's rigid-body part at the end).
struct OutcomeFacts {
  const Scenario     *sc      = nullptr;
  const ContactTally *contact = nullptr;
  const MonitorPeaks *peaks   = nullptr;
  StateMeasures       start, end;     // at t = 0 and at the end of the run
  PetscReal           energy_in  = 0; // J, the conserved total at t = 0 (StateMeasures::total)
  PetscReal           energy_end = 0; // J, the same at the end
  PetscReal           final_time = 0; // s
  PetscReal           V_x        = 0; // m/s, the swinging bat's speed toward the ball at the impact point (0 at rest)
  // J, the energy brought into the impact: the ball's incident kinetic energy 1/2 m_b v_i^2 and a
  // swinging bat's kinetic energy at t = 0 (lab frame; 0 for a bat at rest). The fractions'
  // denominator (0: a ball at rest and a bat at rest, which -ball_speed refuses).
  PetscReal E_in = 0;
  // The beam's rigid-body part at the end, over the dofs that can move: mass (kg), moment of
  // inertia about its centre of mass (kg m^2, with a Timoshenko section's rotary inertia),
  // angular momentum about the centre of mass (kg m^2/s).
  PetscReal beam_mass = 0, inertia_cm = 0, moment_cm = 0;
  // With a roll field (-beam_torsion): the moment of inertia about the frame's axis (kg m^2: the
  // sections' rho J and a string bed's m z^2) and the structure's angular momentum about it
  // (kg m^2/s); 0 without.
  PetscReal inertia_roll = 0, moment_roll = 0;
  // The structure's energy at the end in its rigid motions and, part by part, the rest (J;
  // run/energy_parts.hpp): the fraction columns' numerators.
  EnergySplit          split;
  const ObliqueRecord *oblique = nullptr; // an oblique impact's tangential contact, exit and flight
};

// When a column applies: a predicate of the scenario.
using ResultApplies = bool (*)(const Scenario &sc);

// The predicates of the table (also for messages and tests).
bool ResultAlways(const Scenario &sc);
bool ResultNoHeldDof(const Scenario &sc);         // no end clamped or pinned, no clamped region, no pivot
bool ResultMomentumInvariant(const Scenario &sc); // no held dof, no grip, no mass-proportional damping
bool ResultFreeBeamAtRest(const Scenario &sc);    // no held dof, no grip, no swing (Eq. 11)
bool ResultFreePivot(const Scenario &sc);         // -beam_pivot and no other support or grip: the rig turns freely
bool ResultTwist(const Scenario &sc);             // -beam_torsion
bool ResultSegment(const Scenario &sc);           // -monitor_segment

// Why a pivoted rig does not turn freely about its pivot (the supports and grip that also hold
// it, as options), or "" when it does or has no pivot.
std::string PivotHeldText(const Scenario &sc);

struct ResultColumn {
  const char   *name;
  const char   *unit;            // never empty ("1": dimensionless)
  const char   *description;     // one line: what it is
  ResultApplies applies;         // false: NaN in this row (nullptr for a part's column: Applies)
  const char   *applies_text;    // the same in words ("always", "with -grip")
  bool          integer = false; // a count: an integer dataset in an impact file (a count always applies)
  // A share of the energy brought in (the fractions that close to 1: docs/model.md section 4): its
  // short name in the summary's energy line ("ball rebound", "wall", ...); nullptr for the rest.
  const char *share = nullptr;
  // How the outcome computes it (nullptr: the stepper's own counts and settings, written by the
  // driver and the stepper: the cost and integrator columns).
  double (*compute)(const OutcomeFacts &f) = nullptr;
  // Where ImpactResult holds it: exactly one of the three.
  PetscReal ImpactResult::*real = nullptr;
  PetscInt ImpactResult::*count = nullptr;
  PetscBool ImpactResult::*flag = nullptr;
  // A registered structure part's column: its part and how it is computed; a stage's after the
  // contact (run/stage.hpp): its index in the stages' registry and how it is computed; either's
  // index in ImpactResult::keyed (-1 for the rest).
  const StructurePart *owner                       = nullptr;
  double (*part_compute)(const PartOutputFacts &f) = nullptr;
  PetscInt stage                                   = -1;
  double (*stage_compute)(const StageFacts &f)     = nullptr;
  PetscInt keyed                                   = -1;

  bool   Applies(const Scenario &sc) const;    // applies(sc), or the owner present in sc.beam (a flag: always)
  double Get(const ImpactResult &r) const;     // the value as a double
  void   Set(ImpactResult *r, double v) const; // (the outcome's writes)
};

// The energy line of the summary: every share of E_in that applies, "energy: E_in 116 J: ball
// rebound 0.055, ...; their sum 1 - 8.8e-09 (the energy error)" (empty when none applies).
std::string ImpactEnergyShareText(const Scenario &sc, const ImpactResult &r);

// The table, in the order of the files (a sweep adds its own columns before it).
const std::vector<ResultColumn> &ImpactResultColumns();
// The column `name`, or nullptr.
const ResultColumn *ImpactResultColumn(const std::string &name);
// The table's names in order, comma-separated (the impact file's root attribute results_columns).
std::string ImpactResultColumnNames();

} // namespace beamimpact

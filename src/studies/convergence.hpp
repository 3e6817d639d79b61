// -task convergence: which time integrator reaches a given accuracy of the ACOR
// fastest, and at which order it converges through the contact events; and, as
// a separate study, the spatial (grid) error and the continuum limit.
//
//   beamimpact -task convergence -options_file options/convergence/study-default.opts
//              -beam_nodes 161 -output conv161.h5
//   scripts/plot_convergence.py conv161.h5 -o conv161
//
// Temporal study (one scene, one impact point, -beam_nodes fixed): every
// configuration (an options file, -convergence_configs a.opts,b.opts,...) is run
// over its own sequence of steps or tolerances, and each run is compared with
// the reference:
//   * linear spring: the exact modal reference (modal_reference.hpp): no step, no
//     tolerance, only round-off (-convergence_reference modal, the default);
//   * hysteretic ball (or -convergence_reference run): the configuration
//     -convergence_reference_config at its own sequence; the finest level is the
//     reference and its error is estimated by Richardson extrapolation from the
//     last three levels (reported with the results).
// Spatial study (-convergence_spatial_nodes 41,81,161,...): the reference at each
// N, Richardson extrapolation to the continuum limit and the observed order in h.
//
// A configuration file holds its PETSc options (all -ts_, -snes_, -ksp_, -pc_
// options), or -convergence_method leapfrog for the hand-written Stormer-Verlet
// baseline (leapfrog.hpp), plus exactly one sequence:
//   -convergence_dt first,divisor,count         fixed steps first/divisor^k (s): sets -ts_dt
//                                                (-leapfrog_dt for the baseline)
//   -convergence_dt_stable first,divisor,count  the same as fractions of the explicit
//                                                stability limit (rk and leapfrog only)
//   -convergence_tol first,divisor,count        adaptive: -ts_rtol first/divisor^k and
//                                                -ts_atol = atol_factor x rtol
// and optionally -convergence_order p (the theoretical order: reference slope in
// the diagram, and the order the tests expect), -convergence_atol_factor f (m or
// m/s per unit rtol: the state holds displacements ~1e-3 m; default 1e-3), and
// -convergence_name (default: the file name without .opts).
// Each run gets a fresh options database (PetscOptionsCreate + the file +
// its step/tolerance, after the options of -convergence_common_options FILE; made the default database with
// PetscOptionsPush for the run and popped and destroyed afterwards), so nothing of
// one configuration leaks into the next, and an option of the file that the run
// does not use is an error (a typo).
#pragma once

#include "model/beam.hpp"
#include "model/contact.hpp"
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// How a configuration's runs are refined.
enum class ConvergenceSequenceKind { Step = 0, StableFraction = 1, Tolerance = 2 };
const char *ConvergenceSequenceName(ConvergenceSequenceKind k); // "dt", "dt_stable", "tol"

struct ConvergenceSequence {
  ConvergenceSequenceKind kind    = ConvergenceSequenceKind::Step;
  PetscReal               first   = 0; // s (dt), fraction of dt_max (dt_stable), or rtol (tol)
  PetscReal               divisor = 2; // > 1
  PetscInt                count   = 0; // levels
  PetscReal value(PetscInt level) const; // first / divisor^level
};

// One integrator configuration (an options file, or options text in tests).
struct ConvergenceConfig {
  std::string         name;        // label (file name without .opts, or -convergence_name)
  std::string         file;        // options file ("" when given as text)
  std::string         text;        // options text, inserted after the file
  std::string         description; // the file's first comment line
  std::string         method = "ts"; // "ts" (ImpactRun) or "leapfrog" (LeapfrogRun)
  ConvergenceSequence seq;
  PetscReal           expected_order = 0;    // theoretical order (0: not given)
  PetscReal           atol_factor    = 1e-3; // -ts_atol = atol_factor x -ts_rtol (tol sequences)
  std::string         options;               // the configuration's own options, for the record
};

enum class ConvergenceReferenceKind { Modal = 0, Run = 1 };

// -convergence_* options of the study.
struct ConvergencePlan {
  std::vector<ConvergenceConfig> configs;
  PetscInt                 repeats = 3;      // runs per level (interleaved); the wall time is the minimum
  PetscReal                repeat_budget = 2; // s: no further repeat of a level once its runs took this long
  ConvergenceReferenceKind reference = ConvergenceReferenceKind::Modal; // default: modal (linear), run (hysteresis)
  std::string              reference_file = "options/convergence/reference.opts";
  std::vector<PetscInt>    spatial_nodes;    // N of the spatial study (empty: none)
  PetscReal                target = 1e-6;    // ACOR error of the cost summary (and the targets)
  PetscReal                error_floor = 1e-12; // errors below this are round-off: left out of order fits
  std::string              common_file;      // options file inserted into every run (-convergence_common_options)
  PetscBool                quiet = PETSC_FALSE;
};

// Reads the plan's options and loads every configuration file.
PetscErrorCode ConvergencePlanFromOptions(MPI_Comm comm, const BallParams &ball, ConvergencePlan *plan);

// Loads a configuration from a file and/or options text (its -convergence_* keys).
PetscErrorCode ConvergenceConfigLoad(MPI_Comm comm, const std::string &file, const std::string &text, ConvergenceConfig *cfg);

// The reference the runs are measured against.
struct ConvergenceReference {
  ImpactResult result;
  std::string  method;            // "modal" or the reference configuration's name
  // Estimated error of the reference itself (0 for modal: round-off only).
  PetscReal    acor_error = 0;         // absolute
  PetscReal    contact_time_error = 0; // relative
  PetscReal    peak_force_error = 0;   // relative
  PetscReal    observed_order = 0;     // of the reference configuration, from its last three levels (ACOR)
  PetscReal    wall_time = 0;          // s, to compute the reference
};

// One level of one configuration.
struct ConvergenceRun {
  PetscInt     level = 0;
  PetscReal    dt = 0;          // s, the fixed step (tol runs: the initial step)
  PetscReal    rtol = 0, atol = 0; // tol runs
  PetscReal    mean_step = 0;   // s, simulated time / accepted steps
  ImpactResult result;          // the outcome and cost (wall_time: minimum of the repeats)
  PetscReal    wall_time_max = 0; // s, maximum of the repeats
  PetscReal    acor_error = 0;         // |acor - acor_ref|
  PetscReal    contact_time_error = 0; // relative
  PetscReal    peak_force_error = 0;   // relative
  PetscReal    max_compression_error = 0; // relative
  PetscReal    energy_error = 0;       // |E_end - E_0| / E_0 (the run's own invariant)
  bool         failed = false;
  std::string  message;          // why it failed
};

// Observed order of e(h) ~ C h^p: pairwise between consecutive levels and a
// least-squares fit of log e against log h over the levels with e > floor.
// Levels at or below the floor (or not finite) give NaN pairwise orders; the
// fit is NaN with fewer than two usable levels.
struct ConvergenceOrder {
  std::vector<PetscReal> pairwise; // pairwise[k]: between levels k-1 and k (pairwise[0] = NaN)
  PetscReal              lsq = 0;
  PetscInt               used = 0; // levels in the fit
};
ConvergenceOrder ConvergenceObservedOrder(const std::vector<PetscReal> &h, const std::vector<PetscReal> &e, PetscReal floor);

// Richardson extrapolation of A(h) = A0 + C h^p from three levels with a common
// ratio r = h1/h2 = h2/h3: p = log(|A1-A2| / |A2-A3|) / log r and A0 = A3 + (A3-A2)/(r^p - 1).
// Returns false when the differences do not decrease (no asymptotic behaviour).
bool ConvergenceRichardson(PetscReal A1, PetscReal A2, PetscReal A3, PetscReal r, PetscReal *p, PetscReal *A0);

// Computes the reference for the scenario (modal or a run of the reference configuration).
// Here and below the scenario's monitors are not used: the runs record no time series.
PetscErrorCode ConvergenceReferenceCompute(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &sc, ConvergenceReference *ref);

// Runs every level of every configuration plan.repeats times (interleaved: all levels
// once, then again; a level is not repeated once its runs took plan.repeat_budget),
// keeps the minimum wall time, and measures each run against ref. A failing level is
// recorded (failed, message) and the others run. all[c][k]: configuration c, level k.
PetscErrorCode ConvergenceRunConfigs(MPI_Comm comm, const ConvergencePlan &plan, const std::vector<ConvergenceConfig> &cfgs, const Scenario &sc, const ConvergenceReference &ref,
                                     std::vector<std::vector<ConvergenceRun>> *all);
// The same for one configuration.
PetscErrorCode ConvergenceRunConfig(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceConfig &cfg, const Scenario &sc, const ConvergenceReference &ref, std::vector<ConvergenceRun> *runs);

// Observed order of one configuration's runs for one error (e.g. &ConvergenceRun::acor_error)
// against ConvergenceStepOf; failed runs are left out.
ConvergenceOrder ConvergenceOrderOf(const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs, PetscReal floor, PetscReal ConvergenceRun::*err);

// The step measure of a run for order fits: the fixed step, or the mean step of an adaptive run.
PetscReal ConvergenceStepOf(const ConvergenceConfig &cfg, const ConvergenceRun &run);

// The spatial study: the reference outcome at each N, Richardson extrapolation.
struct ConvergenceSpatial {
  std::vector<PetscInt>  nodes;
  std::vector<PetscReal> h;                                // m
  std::vector<PetscReal> acor, contact_time, peak_force;   // at each N
  std::vector<PetscReal> acor_order, contact_time_order, peak_force_order; // from the triple ending at N (NaN for the first two)
  PetscReal acor_limit = 0, contact_time_limit = 0, peak_force_limit = 0;   // extrapolated from the last three
  PetscReal acor_order_lsq = 0, contact_time_order_lsq = 0, peak_force_order_lsq = 0; // fit of |A(h) - limit|
};
PetscErrorCode ConvergenceSpatialStudy(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &sc, ConvergenceSpatial *sp);

// -task convergence: reads the options, runs the study, prints the tables and the
// cost at -convergence_target against the leapfrog baseline, writes -output.
PetscErrorCode TaskConvergence(MPI_Comm comm, const std::string &output);

} // namespace beamimpact

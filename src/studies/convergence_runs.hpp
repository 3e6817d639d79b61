// -task convergence, the execution: the reference, the runs of every configuration's levels and
// the references of the spatial study. Each run gets a fresh options database
// (PetscOptionsCreate + the common options file + the configuration's file and its level's step
// or tolerance, made the default database with PetscOptionsPush for the run and popped and
// destroyed afterwards), so nothing of one configuration leaks into the next, and an option of
// the file that the run does not use is an error (a typo): the level is recorded as failed.
#pragma once

#include "run/impact.hpp"
#include "run/reference.hpp"
#include "run/scenario.hpp"
#include "studies/convergence_plan.hpp"

#include <functional>
#include <string>
#include <vector>

namespace beamimpact {

// The reference the runs are measured against: a method of the reference registry
// (run/reference.hpp) and its own estimated error (0 for an exact one).
using ConvergenceReference = ReferenceSolution;

// One level of one configuration.
struct ConvergenceRun {
  PetscInt     level = 0;
  PetscReal    dt    = 0;                 // s, the fixed step (tol runs: the initial step)
  PetscReal    rtol = 0, atol = 0;        // tol runs
  PetscReal    mean_step = 0;             // s, simulated time / accepted steps
  ImpactResult result;                    // the outcome and cost (wall_time: minimum of the repeats)
  PetscReal    wall_time_max         = 0; // s, maximum of the repeats
  PetscReal    acor_error            = 0; // |acor - acor_ref|
  PetscReal    contact_time_error    = 0; // relative
  PetscReal    peak_force_error      = 0; // relative
  PetscReal    max_compression_error = 0; // relative
  PetscReal    energy_error          = 0; // |E_end - E_0| / E_0 (the run's own invariant)
  // An oblique impact (-impact_offset, -ball_spin): the batted ball's (NaN otherwise)
  PetscReal   exit_speed_error   = 0; // relative
  PetscReal   launch_angle_error = 0; // deg, absolute
  PetscReal   spin_error         = 0; // relative
  bool        failed             = false;
  std::string message; // why it failed
};

// The reference for the scenario by the plan's method (-convergence_reference); its wall time.
// Here and below the scenario's monitors are not used: the runs record no time series.
PetscErrorCode ConvergenceReferenceCompute(MPI_Comm comm, const ConvergencePlan &plan, const Scenario &sc,
                                           ConvergenceReference *ref);

// The reference method "run" (registered in app/registry.cpp): the configuration
// -convergence_reference_config at its own sequence; its finest level is the reference, its
// error estimated by Richardson extrapolation from the last three levels.
extern const ReferenceMethod kReferenceRun;

// Runs every level of every configuration plan.repeats times (interleaved: all levels
// once, then again; a level is not repeated once its runs took plan.repeat_budget),
// keeps the minimum wall time, and measures each run against ref. A failing level is
// recorded (failed, message) and the others run. all[c][k]: configuration c, level k.
PetscErrorCode ConvergenceRunConfigs(MPI_Comm comm, const ConvergencePlan &plan,
                                     const std::vector<ConvergenceConfig> &cfgs, const Scenario &sc,
                                     const ConvergenceReference &ref, std::vector<std::vector<ConvergenceRun>> *all);
// The same for one configuration.
PetscErrorCode ConvergenceRunConfig(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceConfig &cfg,
                                    const Scenario &sc, const ConvergenceReference &ref,
                                    std::vector<ConvergenceRun> *runs);

// The spatial study: the reference outcome at each N (the analysis fills the orders and limits).
struct ConvergenceSpatial {
  std::vector<PetscInt>  nodes;
  std::vector<PetscReal> h;                              // m
  std::vector<PetscReal> acor, contact_time, peak_force; // at each N
  std::vector<PetscReal> acor_order, contact_time_order,
    peak_force_order; // from the triple ending at N (NaN for the first two)
  PetscReal acor_limit = 0, contact_time_limit = 0, peak_force_limit = 0; // extrapolated from the last three
  PetscReal acor_order_lsq = 0, contact_time_order_lsq = 0, peak_force_order_lsq = 0; // fit of |A(h) - limit|
};
// The reference at each N of plan.spatial_nodes; done(N, ref) after each (for progress lines).
PetscErrorCode ConvergenceSpatialRuns(
  MPI_Comm comm, const ConvergencePlan &plan, const Scenario &sc, ConvergenceSpatial *sp,
  const std::function<PetscErrorCode(PetscInt, const ConvergenceReference &)> &done);

} // namespace beamimpact

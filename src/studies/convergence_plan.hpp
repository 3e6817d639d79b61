// -task convergence, the plan: the study's options (-convergence_*, one option table) and its
// integrator configurations, each an options file with its sequence of steps or tolerances.
//
// A configuration file holds its PETSc options (all -ts_, -snes_, -ksp_, -pc_ options), or
// -convergence_method leapfrog for the hand-written Stormer-Verlet baseline (leapfrog.hpp),
// plus exactly one sequence:
//   -convergence_dt first,divisor,count         fixed steps first/divisor^k (s): sets -ts_dt
//                                                (-leapfrog_dt for the baseline)
//   -convergence_dt_stable first,divisor,count  the same as fractions of the explicit
//                                                stability limit (rk and leapfrog only)
//   -convergence_tol first,divisor,count        adaptive: -ts_rtol first/divisor^k and
//                                                -ts_atol = atol_factor x rtol
// and optionally -convergence_order p (the theoretical order: reference slope in the diagram,
// and the order the tests expect), -convergence_atol_factor f (m or m/s per unit rtol: the state
// holds displacements ~1e-3 m; default 1e-3), and -convergence_name (default: the file name
// without .opts). These keys belong to the configuration's own options database (each run gets
// a fresh one: convergence_runs.hpp), not to the command line.
#pragma once

#include "base/option_table.hpp"
#include "run/reference.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// How a configuration's runs are refined.
enum class ConvergenceSequenceKind {
  Step           = 0,
  StableFraction = 1,
  Tolerance      = 2
};
const char *ConvergenceSequenceName(ConvergenceSequenceKind k); // "dt", "dt_stable", "tol"

struct ConvergenceSequence {
  ConvergenceSequenceKind kind    = ConvergenceSequenceKind::Step;
  PetscReal               first   = 0;                 // s (dt), fraction of dt_max (dt_stable), or rtol (tol)
  PetscReal               divisor = 2;                 // > 1
  PetscInt                count   = 0;                 // levels
  PetscReal               value(PetscInt level) const; // first / divisor^level
};

// One integrator configuration (an options file, or options text in tests).
struct ConvergenceConfig {
  std::string         name;          // label (file name without .opts, or -convergence_name)
  std::string         file;          // options file ("" when given as text)
  std::string         text;          // options text, inserted after the file
  std::string         description;   // the file's first comment line
  std::string         method = "ts"; // "ts" (ImpactRun) or "leapfrog" (LeapfrogRun)
  ConvergenceSequence seq;
  PetscReal           expected_order = 0;    // theoretical order (0: not given)
  PetscReal           atol_factor    = 1e-3; // -ts_atol = atol_factor x -ts_rtol (tol sequences)
  std::string         options;               // the configuration's own options, for the record
};

// -convergence_* options of the study.
struct ConvergencePlan {
  std::vector<ConvergenceConfig> configs;
  PetscInt                       repeats       = 3; // runs per level (interleaved); the wall time is the minimum
  PetscReal                      repeat_budget = 2; // s: no further repeat of a level once its runs took this long
  std::string
    reference = "modal"; // a study method of the reference registry (run/reference.hpp); read: the first that applies
  std::string           reference_file = "options/convergence/reference.opts"; // the run reference's configuration
  std::vector<PetscInt> spatial_nodes;                                         // N of the spatial study (empty: none)
  PetscReal             target      = 1e-6;  // ACOR error of the cost summary (and the targets)
  PetscReal             error_floor = 1e-12; // errors below this are round-off: left out of order fits
  std::string           common_file;         // options file inserted into every run (-convergence_common_options)
  PetscBool             quiet = PETSC_FALSE;
};

// The study's option table (built on first use from the reference registry: register the
// methods first) and its reader: the plan's options, every configuration file loaded; the
// reference checked against the scenario (the default: the first study method that applies).
const OptionModule &ConvergenceOptionModule();
PetscErrorCode      ConvergencePlanFromOptions(MPI_Comm comm, const Scenario &sc, ConvergencePlan *plan);

// What the reference method needs from the plan, and what the file calls it ("modal", or the
// run reference's configuration file).
ReferenceSettings ConvergenceReferenceSettings(const ConvergencePlan &plan);
std::string       ConvergenceReferenceLabel(const ConvergencePlan &plan);

// Loads a configuration from a file and/or options text (its -convergence_* keys).
PetscErrorCode ConvergenceConfigLoad(MPI_Comm comm, const std::string &file, const std::string &text,
                                     ConvergenceConfig *cfg);

// A fresh options database holding a configuration: the common options file (if any) first,
// then the configuration's file and text, which win over it. The common options are marked
// used: they apply to the runs where they mean something (a factorization ordering means
// nothing to an explicit method).
PetscErrorCode ConvergenceConfigOptionsCreate(MPI_Comm comm, const ConvergenceConfig &cfg,
                                              const std::string &common_file, PetscOptions *o);

// The -convergence_* keys a configuration file may hold (removed from a run's database).
const std::vector<const char *> &ConvergenceConfigKeys();

// printf of one number into a string (the study's messages and options).
std::string ConvergenceFormat(const char *fmt, double v);

} // namespace beamimpact

// The plan of a sweep (-sweep, -sweep_x and the other -sweep_* options): which cases
// exist, as the product of axes, each varying one option of the program (numbers, or text:
// -sweep "ts_type=rk;cn;modal,impact_x=0.4:0.9:6"), and the scenario of each case, read from
// the options with the case's values set.
#pragma once

#include "base/option_table.hpp"
#include "run/scenario.hpp"
#include "studies/sweep_sampling.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// One swept option: its name, its unit (when known), its text as given and its values. An
// axis is numeric (values are numbers) or text, categorical (labels are the values as written:
// "rk", "cn"; values then number them 0, 1, ... so that a case's row stays numbers).
struct SweepAxis {
  std::string              name;              // the option without its dash ("impact_x"); also its column
  std::string              unit;              // of its values ("m"; "" when not known or text)
  std::string              spec;              // the SPEC as given (start:stop:count[:log] or a list)
  std::vector<PetscReal>   values;            // in the given order; a text axis: the index of each label
  std::vector<std::string> labels;            // a text axis: its values as written, in order (empty: numeric)
  bool                     overrides = false; // -NAME was also given (options file or command line): the axis wins
  std::string              given;             // its value there, restored after each case
  bool sampled = false;    // a distribution (SPEC normal:..., uniform:..., V@W;..., csv:...): values are its samples
  SampleDistribution dist; // a sampled axis's distribution (studies/sweep_sampling.hpp)

  bool Text() const { return !labels.empty(); }
  // Value v of this axis (an entry of values) as the options database gets it: the label, or
  // the number exactly, in its shortest text (ShortestText: -0.06, not -0.059999999999999998).
  std::string OptionValue(PetscReal v) const;
  // As a person reads it: the label, or %g with the unit ("0.3 m").
  std::string Display(PetscReal v) const;
};

// What became of a case: 0 ok, else a documented code (docs/sweep.md).
enum SweepStatus {
  SweepOk           = 0,
  SweepFailedOther  = 1, // the run returned an error not listed below
  SweepOffBeam      = 2, // the impact point is off the beam
  SweepHeldPoint    = 3, // the impact point is held fixed (clamped/pinned end, -beam_clamp)
  SweepRefused      = 4, // the run's set-up refused the values (e.g. an explicit step above its stability limit)
  SweepNotConverged = 5, // the run stopped: a solve or event location failed, energy grew, the ball chattered
  SweepNotFinite    = 6, // the solution became NaN/Inf (an unstable step)
  SweepCutInContact = 7, // the run reached -impact_max_time with the ball still in contact
  SweepOffFace = 8, // not failed: the point is off a racket's face (outside the head's outline, off the frame's axis;
                    // without a bed, beyond the section's half-width): no impact there
};
const char *SweepStatusName(int status);
// Whether a row's status is a failure (not ok, and not a point that has no impact by design: off a racket's face).
inline bool SweepFailed(double status) { return status != SweepOk && status != SweepOffFace; }

// The option table of the sweep (module "sweep": -sweep, -sweep_x, -sweep_ranks_per_case,
// -rigid_loss_fraction, -sweep_quiet, ...), registered by app/registry.cpp.
extern const OptionModule kSweepOptions;

// -sweep, -sweep_x, -sweep_ranks_per_case, -rigid_loss_fraction and the farm's options.
// The cases are the product of the axes in the order written (-sweep_x first), the first
// varying slowest and the last fastest; case indices number them from 0.
struct SweepPlan {
  std::vector<SweepAxis> axes;
  std::string            sweep;                   // -sweep as given ("" if not)
  std::string            sweep_x;                 // -sweep_x as given ("" if not)
  PetscInt               ranks_per_case      = 1; // ranks solving one impact together (DMDA distributed over them)
  PetscReal              rigid_loss_fraction = 0; // f of Eq. (11) for the rigid_acor column (dimensionless)
  PetscBool              quiet               = PETSC_FALSE; // no progress or summary lines
  PetscBool              restart             = PETSC_FALSE; // discard an existing -output file and its journal
  PetscBool              retry_failed        = PETSC_FALSE; // a resume computes failed cases again
  PetscReal              progress_interval   = 2;           // s, at most one progress line per interval
  PetscReal              write_interval      = 5;           // s, minimum time between live rewrites of the file
  PetscReal cost_warn = 30; // s, -impact_cost_warn: the expected time of the remaining points is said above this
  // Sampled axes (docs/uncertainty.md): the cases are every point of the grid axes (the others)
  // times the sample's rows, the rows varying fastest (the same rows at every grid point).
  PetscInt            samples   = 0;                    // -sweep_samples N: points of the design (0: not given)
  SampleDesign        design    = SampleDesign::Random; // -sweep_sampling
  PetscInt            seed      = 0;                    // -sweep_seed
  PetscBool           sobol     = PETSC_FALSE;          // -sweep_sobol: Saltelli's design, N (d + 2) rows
  PetscInt            bootstrap = 200;                  // -sweep_bootstrap: resamples of the intervals
  std::string         exceedance;                       // -sweep_exceedance as given
  std::vector<size_t> sampled;                          // the sampled axes (indices into axes), in order
  std::vector<double> sample_rows;                      // the sample: rows of one value per sampled axis (option units)

  PetscInt SampleRows() const { return sampled.empty() ? 0 : (PetscInt)(sample_rows.size() / sampled.size()); }
  PetscInt cases() const;
  // The value of every axis for case `index` (axis order).
  std::vector<PetscReal> CaseValues(PetscInt index) const;
};

// The unit of an option's values ("m" for impact_x), "" when not known.
std::string SweepOptionUnit(const std::string &name);

// Parses the values of one axis: "start:stop:count" (count points from start to stop, both
// included, like numpy.linspace), "start:stop:count:log" (geometric: equal ratios, start and
// stop of one sign, not 0) or a list separated by any of `separators`. Values are rounded to
// 15 significant digits. Returns false with a reason in *why (which names the unit).
bool SweepParsePoints(const std::string &spec, std::vector<PetscReal> *values, std::string *why,
                      const std::string &unit = "m", const std::string &separators = ",;");

// Parses -sweep "NAME=SPEC[,NAME=SPEC...]" into axes (lists in SPEC separated by ';'). An axis
// is text (categorical) when its option is text in its module's table (a Choice, Text or File
// row), when a value is quoted ('4';'5dp': numbers kept as text; a quoted value may hold ',' ';'
// ':'), or when a list's values are not all numbers (ts_type=rk;cn); it is numeric when its
// option has a unit (SweepOptionUnit), for a range start:stop:count and for a list of numbers.
bool SweepParseAxes(const std::string &text, std::vector<SweepAxis> *axes, std::string *why);

// Draws the sample of the plan's sampled axes (plan->sample_rows and each sampled axis's values)
// from -sweep_samples, -sweep_sampling, -sweep_seed and -sweep_sobol. False with a reason.
bool SweepPlanSample(SweepPlan *plan, std::string *why);

// Checks the values of a text axis where the program knows the choices: a Choice row of its
// module's table (beam_theory, beam_left, ball_law, ...) and -ts_type (PETSc's registry of TS
// types, with this program's alpha2 and modal). *why: a reason naming the first bad value and
// the allowed ones ("" when they are all known, or the program does not know the choices: the
// run then decides, and a value it refuses is a failed point).
PetscErrorCode SweepCheckTextAxis(const SweepAxis &a, std::string *why);

// Reads the -sweep* options and -rigid_loss_fraction, and checks their form (no scenario yet).
PetscErrorCode SweepPlanFromOptions(MPI_Comm comm, SweepPlan *plan);

// Sets the options of case `index` in the options database (-NAME value for every axis),
// and puts back what was there before (nothing, or the value an options file gave).
PetscErrorCode SweepCaseOptionsSet(const SweepPlan &plan, PetscInt index);
PetscErrorCode SweepCaseOptionsClear(const SweepPlan &plan);

// What the points of one structure share: the scenario as read at the structure's first point.
// The structure is the values of the axes that are not one part of the scenario alone
// (ScenarioPartOf: a beam_* axis, beam_nodes, ts_type, ...); the other axes (impact_x,
// ball_speed, ball_mass, bat_speed, impact_offset, ...) are the point's, and a point on the
// structure of the one before reads only their parts again (io/scenario_options.hpp).
struct SweepScenarioCache {
  bool                   valid    = false;
  bool                   monitors = true;       // the reading's (a key too)
  std::vector<PetscReal> key;                   // the structure axes' values
  Scenario               base;                  // as read (ScenarioReading::read_as)
  std::vector<unsigned>  axis_part;             // ScenarioPartOf of each axis (ScenarioAll: a structure axis)
  PetscInt               full = 0, partial = 0; // readings of the whole scenario, of the point's parts only
  bool                   last_partial = false;  // the last reading was on the cached structure
};

// The scenario of case `index`: the options read as -task impact reads them, with the
// case's values set (and left set: the run reads the integrator's from the database; clear
// them with SweepCaseOptionsClear). An impact point off the beam or held fixed is not an
// error: *status says so (SweepOffBeam, SweepHeldPoint) and *reason has the option's message;
// any other error is returned. monitors: read the -monitor_* options too. cache (may be NULL):
// the structure's scenario, reused when this case is on it (only the point's parts are read),
// else replaced by this case's.
PetscErrorCode SweepCaseScenario(MPI_Comm comm, const SweepPlan &plan, PetscInt index, bool monitors, Scenario *sc,
                                 int *status, std::string *reason, SweepScenarioCache *cache = nullptr);

// The values of case `index`, "impact_x = 0.3 m, ts_type = cn", formatted as C's printf
// does (petsc_format false) or as PETSc's messages do (true: 1 reads "1.").
std::string SweepCaseText(const SweepPlan &plan, PetscInt index, bool petsc_format);

// The first line of the message of the error just raised (LastErrorMessage), for `reason`.
std::string SweepErrorReason(PetscErrorCode ierr);

} // namespace beamimpact

// -task fit's inputs: its options (-fit_*), the parameters (-fit_parameters: bounds, start, the
// scale TAO sees) and the table of measurements (-fit_data: a CSV file, one row per run of the
// program). docs/fit.md describes them; docs/model.md section 17 the method.
//
// The table: `#` comment lines, a header of names, one row per run. A column named as an option
// (without its dash) sets that option for the row's run, as a sweep point does; a column named as
// a column of the rows' task (-fit_task: an impact's results table, the modes' frequency_K, mass,
// ..., the flight's distance, ...) is a measured value (an empty cell: not measured in that row);
// a column <name>_sigma is its standard deviation. Errors name the file, the line and the column.
#pragma once

#include "base/option_table.hpp"
#include "studies/case_batch.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// The option table of -task fit (module "fit") and of TAO's options the program advertises
// (module "tao", a PETSc table), registered by app/registry.cpp.
const OptionModule &FitOptionTable();
const OptionModule &TaoOptionTable();

struct FitSettings {
  std::string     data;                // -fit_data: the CSV file
  std::string     parameters;          // -fit_parameters as given
  std::string     sigma;               // -fit_sigma as given ("" none)
  const CaseTask *task      = nullptr; // -fit_task
  bool            central   = false;   // -fit_differences central (else forward) for TAO's Jacobian
  PetscReal       step      = 1e-6;    // -fit_difference_step: relative step of TAO's Jacobian (1)
  PetscReal covariance_step = 1e-4; // -fit_covariance_step: relative step of the central differences at the optimum (1)
  PetscReal xtol            = 1e-8; // -fit_xtol: brgn stops when no scaled parameter moves more than this (1)
  PetscReal ftol            = 1e-10; // -fit_ftol: brgn stops when chi^2 changes by less than this, relative (1)
  PetscReal identifiability = 1e-8;  // -fit_identifiability_tol: a singular value below this times the largest is not
                                     // determined (1)
  std::string options_output;        // -fit_options_output ("" with -output none and not given)
  PetscBool   quiet      = PETSC_FALSE; // -fit_quiet: no iteration lines
  PetscBool   restart    = PETSC_FALSE; // -fit_restart: forget the runs of an earlier fit into -output
  PetscInt    stop_after = 0;           // -fit_stop_after: stop after this many runs (tests of the resume)
};

// Reads the -fit_* options (one PetscOptionsBegin block); output is -output ("" for none): the
// default -fit_options_output is its name with .opts.
PetscErrorCode FitSettingsFromOptions(MPI_Comm comm, const std::string &output, FitSettings *s);

// One fitted parameter: an option of the program, its bounds and start, and the scale TAO sees:
// u in [0, 1], p = lo + u (hi - lo), or p = lo (hi/lo)^u when the bounds are both positive and
// span a decade or more (hi/lo >= 10: log-scaled).
struct FitParameter {
  std::string name;           // the option without its dash
  std::string unit;           // of its values ("" when not known)
  PetscReal   lo = 0, hi = 0; // the bounds (the option's unit)
  PetscReal   start = 0;      // the start: NAME=LO:HI:START, else the option's given value, else the middle
  std::string start_from;     // "given as NAME=LO:HI:START", "the option's value", "the middle of the bounds"
  bool        log = false;    // log-scaled

  PetscReal ToInternal(PetscReal p) const;   // u of p
  PetscReal FromInternal(PetscReal u) const; // p of u
};

// Parses "NAME=LO:HI[:START][,NAME=LO:HI[:START]...]" (the start, when not given, from the options
// database or the middle: the geometric mean when log-scaled). *why: the reason it is refused.
bool FitParseParameters(const std::string &text, std::vector<FitParameter> *p, std::string *why);

// One measured value: its row, column, value and standard deviation.
struct FitMeasurement {
  size_t    row    = 0; // index of the data row (0-based)
  size_t    column = 0; // index into FitData::measured
  PetscReal y      = 0; // the measured value (the column's unit)
  PetscReal sigma  = 1; // its standard deviation (absolute) or relative weight (the column's unit)
};

struct FitData {
  std::string                 file, sha256;     // -fit_data and the SHA-256 of its contents
  std::vector<std::string>    option_columns;   // the columns that set options
  std::vector<std::string>    measured;         // the measured columns (the task's), in the file's order
  std::vector<std::string>    units;            // of each measured column
  std::vector<CaseOptions>    rows;             // each row's settings (an empty cell: not set)
  std::vector<int>            line;             // each row's line in the file (1-based)
  std::vector<FitMeasurement> values;           // every measured value, row by row
  bool                        absolute = false; // every value has a standard deviation (a _sigma column or -fit_sigma)
  std::string                 sigma_text;       // how the weights were chosen, in words
};

// Parses the CSV `text` of file `file` for the task's columns, with -fit_sigma's per-column
// standard deviations, against the parameters (none of them may be a column). *why: the error,
// naming the file, the line and the column.
bool FitParseData(const std::string &file, const std::string &text, const CaseTask &task, const std::string &sigma,
                  const std::vector<FitParameter> &params, FitData *d, std::string *why);

// A row as people read it: "row 3 (line 7: impact_x=0.3, ball_speed=20)".
std::string FitRowText(const FitData &d, size_t row);

} // namespace beamimpact

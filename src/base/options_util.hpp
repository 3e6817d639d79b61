// The options database as a record and as a check: all options as one string (stored with
// results), and the options set but never read turned into an error (a typo) or a note.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// Every option set (command line and files), as "-name value" pairs.
PetscErrorCode OptionsAsString(std::string *all);

// Checks the options that were set but never read, as PETSc's -options_left lists them, against
// the registered option tables (base/option_table.hpp):
//  * a program option that is no row of any table (a typo) is an error that names it and
//    suggests the closest known name; -allow_unused_options turns the error into a warning;
//  * a row this task does not read (-sweep_x under -task impact) is a one-line note;
//  * a row that was read but has no effect in this run (its `needs` fail: -grip_stiffness
//    without -grip, -beam_shear_modulus under -beam_theory euler) is a one-line note;
//  * a PETSc option (under a prefix of the PETSc table: -ts_, -snes_, -ksp_, -pc_, -modes_eps_,
//    ...) left over is a one-line note when it is a row (a scene's -ts_rk_type under a later
//    -ts_type cn) or close to no known name; one close to a known name (-ts_dtt, -ts_rk_tpye) is
//    a typo: an error with the suggestion. Under strict_solver_options (a convergence
//    configuration must run as written) every unread PETSc option is an error.
// Options whose names start with one of ignore_prefixes (without the dash, e.g. "ts_") are not
// reported: a task that legitimately does not use them says so itself. An option without effect
// whose condition names one of `varied` (with the dash: a sweep's axes) is not reported either:
// it acts at other points.
PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes = {},
                                  bool strict_solver_options = false, const std::vector<std::string> &varied = {});

// The known name closest to `name` (optimal string alignment distance: insertions, deletions,
// substitutions, swaps of neighbours), "" when none is within max(2, length/5) edits.
std::string OptionsClosest(const std::string &name, const std::vector<std::string> &known);

} // namespace beamimpact

// The options database as a record and as a check: all options as one string
// (stored with results), and unused options (typos) turned into an error.
#pragma once

#include <petscsys.h>

#include <functional>
#include <string>
#include <vector>

namespace beamimpact {

// Every option set (command line and files), as "-name value" pairs.
PetscErrorCode OptionsAsString(std::string *all);

// The number of comma-separated values given to option `name` (0 when it is not given): the
// size to allocate before PetscOptionsRealArray, so that lists have no fixed limit.
PetscErrorCode OptionsListLength(const char *name, PetscInt *n);

// Checks the options that were set but never read, as PETSc's -options_left lists them:
//  * an option of the program's own that it does not know (a typo) is an error that names it
//    and suggests the closest known option (OptionsSetCatalog); -allow_unused_options turns
//    the error into a warning;
//  * a known option this task does not use (-sweep_x under -task impact) is a one-line note;
//  * PETSc's solver options left over (-ts_*, -snes_*, ...: a scene's -ts_rk_type under a
//    later -ts_type cn) are a one-line note, unless strict_solver_options (a convergence
//    configuration must run as written: there they are errors too).
// Options whose names start with one of ignore_prefixes (without the dash, e.g. "ts_") are not
// reported: a task that legitimately does not use them says so itself. Without a catalog every
// unused option of the program's own is an error.
PetscErrorCode OptionsCheckUnused(MPI_Comm comm, const std::vector<std::string> &ignore_prefixes = {}, bool strict_solver_options = false);

// The program's known options, for OptionsCheckUnused: a function filling the names (with the
// dash) of every option any task reads. The application sets it once (app/tasks.cpp).
using OptionsCatalog = std::function<PetscErrorCode(MPI_Comm, std::vector<std::string> *)>;
void OptionsSetCatalog(OptionsCatalog catalog);

// The option names `readers` would print under -help (each PetscOptionsBegin block's lines
// "  -name <default>: text"), captured instead of printed. Blocks that were already read in this
// run are printed again: PETSc's record of printed blocks is set aside meanwhile. Errors of
// the readers are theirs to ignore.
PetscErrorCode OptionsHelpNames(const std::function<PetscErrorCode()> &readers, std::vector<std::string> *names);

// The known name closest to `name` (optimal string alignment distance: insertions, deletions,
// substitutions, swaps of neighbours), "" when none is within max(2, length/5) edits.
std::string OptionsClosest(const std::string &name, const std::vector<std::string> &known);

} // namespace beamimpact

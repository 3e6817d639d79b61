// Small text helpers of the tasks: trimmed option values and comment lines, and the
// message of a PETSc error as the program reports it.
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// s without leading and trailing blanks (space, tab, CR, LF).
std::string Trim(const std::string &s);

// The text of a comment line: without its leading '#' marks and blanks, nor trailing blanks.
std::string CommentText(const std::string &line);

// The message of the PETSc error ierr just raised: its specific text (what PetscCheck or
// SETERRQ said), else PETSc's generic text for the code; values as the user wrote them (without
// the dot PETSc's %g puts after a whole number, inf or nan).
std::string LastErrorMessage(PetscErrorCode ierr);

// Prints `text` (a whole line, with its newline) on comm's rank 0 the first time this process
// is asked to, and never again: a note about the input is said once per run, also in a sweep
// or a study that reads the same options for every point.
PetscErrorCode PrintOnce(MPI_Comm comm, const std::string &text);

} // namespace beamimpact

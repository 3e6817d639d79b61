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

} // namespace beamimpact

// Small text helpers of the tasks: trimmed option values and comment lines, and the
// message of a PETSc error as the program reports it.
#pragma once

#include <petscsys.h>

#include <istream>
#include <string>
#include <vector>

namespace beamimpact {

// s without leading and trailing blanks (space, tab, CR, LF).
std::string Trim(const std::string &s);
// The whole of text (blanks around it apart) as a finite number; false for anything else (empty,
// trailing characters, out of range, inf, nan).
bool TextFiniteNumber(const std::string &text, double *v);

// The text of a comment line: without its leading '#' marks and blanks, nor trailing blanks.
std::string CommentText(const std::string &line);

// The lines of a text file's contents as an editor shows them: a UTF-8 byte order mark at the
// start skipped (Windows editors write one; kept, it made the first option unknown under an
// invisible name), each line ended by LF, CR LF or a lone CR (classic Mac files: read by LF alone
// the whole file was one line), the ends not kept. False with *why when the contents start with
// a UTF-16 or UTF-32 byte order mark ("the file is UTF-16 text (it starts with the bytes FF FE):
// save it as UTF-8 or plain ASCII"); *why names no file: the caller adds it.
bool TextLines(std::istream &in, std::vector<std::string> *lines, std::string *why);

// The message of the PETSc error ierr just raised: its specific text (what PetscCheck or
// SETERRQ said), else PETSc's generic text for the code; values as the user wrote them (without
// the dot PETSc's %g puts after a whole number, inf or nan).
std::string LastErrorMessage(PetscErrorCode ierr);

// Prints `text` (a whole line, with its newline) on comm's rank 0 the first time this process
// is asked to, and never again: a note about the input is said once per run, also in a sweep
// or a study that reads the same options for every point.
PetscErrorCode PrintOnce(MPI_Comm comm, const std::string &text);

} // namespace beamimpact

// Reading a ball's e(v) table (model/cor_table.hpp) from a file: rows "v e" (m/s, 1), '#'
// comments, blank lines skipped; every bad row refused with the file and line named.
#pragma once

#include "model/cor_table.hpp"

#include <istream>
#include <string>

namespace beamimpact {

// Parses the rows of `in` (named `name` in messages). On a bad row returns false with *why
// naming the file, the line and what is allowed.
bool CorTableParse(std::istream &in, const std::string &name, CorTable *t, std::string *why);
// Reads the file at `path` (false with *why if it cannot be opened or a row is bad).
bool CorTableRead(const std::string &path, CorTable *t, std::string *why);

} // namespace beamimpact

// Reading section files: a profile of round sections (rows "x D [d]") and a table of section
// properties (rows "x EI mu [kappaGA rhoI]"), whitespace separated, SI units, '#' comments and
// blank lines ignored (docs/bats.md). Every fault is refused with the file and line named.
#pragma once

#include "model/section.hpp"

#include <string>
#include <vector>

namespace beamimpact {

// Rows of a profile file: at least two, x strictly increasing, D > 0, 0 <= d < D, all finite.
// Returns false with *why ("FILE:LINE: what is wrong") on any fault.
bool ProfileFileRead(const std::string &path, std::vector<ProfileRow> *rows, std::string *why);

// Rows of a properties file: at least two, 3, 5 or 7 numbers per row (the same on every row),
// x strictly increasing, every property > 0 and finite. *has_shear: rows carry kappaGA, rhoI;
// *has_torsion: and GJ, rhoJ (the twist, model/torsion.hpp).
bool PropertiesFileRead(const std::string &path, std::vector<PropertiesRow> *rows, bool *has_shear, bool *has_torsion,
                        std::string *why);

} // namespace beamimpact

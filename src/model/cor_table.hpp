// A ball's coefficient of restitution as a table of the approach speed, e(v): rows
// "v e" (m/s, 1), '#' starts a comment, blank lines are skipped. Linear interpolation
// between rows, constant beyond the first and last row. Read by -ball_cor_table
// (io/ball_options.cpp, file read by io/cor_table_file.cpp); the hysteretic law takes its unloading exponent n from e
// at the start of each contact (docs/model.md, section 2).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

struct CorTable {
  std::string            file; // where it was read from (for messages and the run record)
  std::vector<PetscReal> v;    // m/s, strictly increasing, >= 0
  std::vector<PetscReal> e;    // 1, each in (0, 1]
  bool                   empty() const { return v.empty(); }
  PetscReal              operator()(PetscReal speed) const; // e at this approach speed
};

} // namespace beamimpact

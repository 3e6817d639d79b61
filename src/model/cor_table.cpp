// The e(v) table of a ball. See cor_table.hpp.
#include "model/cor_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace beamimpact {

PetscReal CorTable::operator()(PetscReal speed) const
{
  if (v.empty()) return 1.0;
  if (speed <= v.front()) return e.front();
  if (speed >= v.back()) return e.back();
  const size_t    i = static_cast<size_t>(std::upper_bound(v.begin(), v.end(), speed) -
                                       v.begin()); // v[i-1] <= speed < v[i]
  const PetscReal s = (speed - v[i - 1]) / (v[i] - v[i - 1]);
  return e[i - 1] + s * (e[i] - e[i - 1]);
}

} // namespace beamimpact

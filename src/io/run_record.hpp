// The record kept with every results file, as root attributes: program and PETSc versions,
// the full options, every parameter of the scenario and the integrator of its first run.
#pragma once

#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace beamimpact {

// Named numbers, whole numbers and strings, in the order they were added. Whole numbers (counts,
// ranks, flags: any integral type given to add) become HDF5 integer attributes (64-bit), the
// others double ones.
struct RunRecord {
  std::vector<std::pair<std::string, double>>      numbers;
  std::vector<std::pair<std::string, long long>>   integers;
  std::vector<std::pair<std::string, std::string>> strings;
  void add(const std::string &k, double v) { numbers.emplace_back(k, v); }
  template <class T, std::enable_if_t<std::is_integral<T>::value, int> = 0>
  void add(const std::string &k, T v)
  {
    integers.emplace_back(k, (long long)v);
  }
  void add(const std::string &k, const std::string &v) { strings.emplace_back(k, v); }
  void add(const std::string &k, const char *v) { strings.emplace_back(k, v); }
};

// Program, its provenance, PETSc version and the options (a task with no beam: -task flight).
PetscErrorCode RunRecordProgram(RunRecord *rec);

// The same and the beam's parameters (a task on the beam alone).
PetscErrorCode RunRecordBuild(const BeamParams &beam, RunRecord *rec);

// The same plus the ball, the impact rules and, given a first result, its integrator.
PetscErrorCode RunRecordBuild(const Scenario &sc, const ImpactResult *first, RunRecord *rec);

} // namespace beamimpact

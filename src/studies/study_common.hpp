// What the studies that drive TAO over the case batch share (-task fit, -task design): the ranks
// other than 0 kept quiet while TAO runs redundantly on each of them, and the study's options file
// of the optimum, written whole or not at all and never over a file it did not write.
#pragma once

#include <petscvec.h>

#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

namespace beamimpact {

// While it lives, on a rank other than 0, PETSc's printing to stdout is dropped (TAO's monitors
// and views would print once per rank).
struct QuietRanks {
  bool on = false; // this object silenced the rank
  explicit QuietRanks(PetscMPIInt rank);
  ~QuietRanks();
  QuietRanks(const QuietRanks &)            = delete;
  QuietRanks &operator=(const QuietRanks &) = delete;
};

// Inside a TAO callback: the printer as it was (the cases' notes go through the sweep's filter).
struct LoudScope {
  PetscErrorCode (*quiet)(FILE *, const char[], va_list) = nullptr; // the quiet printer to put back
  LoudScope();
  ~LoudScope();
  LoudScope(const LoudScope &)            = delete;
  LoudScope &operator=(const LoudScope &) = delete;
};

// Rank 0: text put at path whole or not at all (a temporary file beside it, fsync'ed, renamed);
// errors name `option`.
PetscErrorCode StudyWriteAtomically(const std::string &path, const std::string &text, const char *option);

// Collective: path (the study's options file, "" none) may be written: not -output, its directory
// writable, not an input of the run, and an existing file there one the study wrote (its first
// line starts with `marker`). Errors name `option`; `who` ("a fit") says whose file it would be.
PetscErrorCode StudyCheckOptionsOutput(MPI_Comm comm, const std::string &path, const std::string &output,
                                       const char *option, const char *marker, const char *who);

// Collective: the study's check of unused options, once TAO and the first runs have read theirs.
// TAO's -tao_test_gradient, -tao_test_hessian and their _view are read only when TAO computes
// a gradient or Hessian (after the first runs): they count as read here.
PetscErrorCode StudyOptionsCheckUnused(MPI_Comm comm);

// A TAO vector's local entries as a std::vector, and back (the studies run TAO on one rank's data).
std::vector<double> FromVec(Vec x);
PetscErrorCode      ToVec(const std::vector<double> &v, Vec x);

// A unit as it follows a number in a line: " m/s", nothing for "" or "1".
std::string UnitText(const std::string &unit);

} // namespace beamimpact

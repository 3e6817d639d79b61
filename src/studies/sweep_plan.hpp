// The plan of a sweep (-sweep_* options): which cases exist, as the product of named axes
// taken from a registry, each varying one parameter of the scenario.
#pragma once

#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// A parameter a sweep can vary: one entry of SweepAxisTypes(). A new axis is one entry there.
struct SweepAxisType {
  const char *name;   // the option it varies, without the dash ("impact_x"); refused in a sweep
  const char *column; // its column in /results and /sweep; its points come from -sweep_<column> ("x")
  const char *unit;   // of its values ("m")
  const char *points; // what its values are called in messages ("impact points")
  void (*set)(Scenario &sc, PetscReal value); // sets the value in a case's scenario
  // Errors out when the value (the index-th of -sweep_<column>, from 0) is not allowed in sc.
  PetscErrorCode (*check)(MPI_Comm comm, const Scenario &sc, PetscReal value, PetscInt index);
  std::string (*example)(const Scenario &sc); // a typical -sweep_<column> value, for messages
};
const std::vector<SweepAxisType> &SweepAxisTypes();

// One swept parameter: its type, its option as given and its values.
struct SweepAxis {
  const SweepAxisType   *type = nullptr;
  std::string            spec;   // -sweep_<column> as given (recorded in the file)
  std::vector<PetscReal> values; // in the given order
};

// -sweep_* options and -rigid_loss_fraction. The cases are the product of the
// axes with the last axis varying fastest; case indices number them from 0.
struct SweepPlan {
  std::vector<SweepAxis> axes;                     // those given, in registry order (now: x)
  PetscInt               ranks_per_case = 1;       // ranks solving one impact together (DMDA distributed over them)
  PetscReal              rigid_loss_fraction = 0;  // f of Eq. (11) for the rigid_acor column (dimensionless)
  PetscBool              quiet = PETSC_FALSE;      // no progress or summary lines
  PetscBool              restart = PETSC_FALSE;    // discard an existing -output file and its journal
  PetscReal              progress_interval = 2;    // s, at most one progress line per interval
  PetscReal              write_interval = 5;       // s, minimum time between live rewrites of the file

  PetscInt cases() const;
  // The value of every axis for case `index` (axis order).
  std::vector<PetscReal> CaseValues(PetscInt index) const;
};

// Parses a list of points: "start:stop:count" (count points from start to stop,
// both included, like numpy.linspace) or "x1,x2,...". Returns false with a
// reason in *why (which names the unit) when the text is not of either form.
bool SweepParsePoints(const std::string &spec, std::vector<PetscReal> *values, std::string *why, const std::string &unit = "m");

// Reads -sweep_<column> of every registered axis, -sweep_ranks_per_case, -sweep_quiet,
// -sweep_restart, -sweep_progress_interval, -sweep_write_interval and -rigid_loss_fraction;
// checks every point against the base scenario (the impact point: on the beam, not held).
PetscErrorCode SweepPlanFromOptions(MPI_Comm comm, const Scenario &base, SweepPlan *plan);

// The scenario of case `index`: the base with the plan's axis values set.
Scenario SweepCaseFor(const SweepPlan &plan, const Scenario &base, PetscInt index);

// The values of case `index`, "x = 0.3 m" (axes separated by ", "), formatted as C's printf
// does (petsc_format false) or as PETSc's messages do (true: 1 reads "1.").
std::string SweepCaseText(const SweepPlan &plan, PetscInt index, bool petsc_format);

} // namespace beamimpact

// The methods that solve one impact, as one registry (as PETSc's ts/tutorials/ex9.c registers
// its physics with PetscFunctionListAdd and libCEED's examples/fluids its problems): the time
// integrator configured by -ts_* (ts), the exact modal solution (modal), and the references a
// study measures integrators against (modal; run: a tight run of a configuration, its own error
// estimated, defined by the convergence study). -reference (-task impact) and
// -convergence_reference (-task convergence) choose from it by name; -help lists every method
// with its help. A method says when it applies (the modal solution needs the linear law and no
// grip) and how it runs.
//
// A new method is one ReferenceMethod (in its own file, or beside the code it runs) and one line
// in app/registry.cpp; its own options go in its module's option table.
#pragma once

#include "base/option_table.hpp"
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// What a method gives: the impact's result, and for a method that is not exact, its own error
// estimated (a study reports it beside the errors it measures).
struct ReferenceSolution {
  ImpactResult result;
  std::string  method;                 // what solved it, for the record: "ts", "modal", a configuration's name
  PetscReal    acor_error         = 0; // its own estimated error: absolute
  PetscReal    contact_time_error = 0; // relative
  PetscReal    peak_force_error   = 0; // relative
  PetscReal    observed_order     = 0; // of the configuration's last levels (ACOR); 0 for an exact method
  PetscReal    wall_time          = 0; // s, to compute it (set by the caller)
};

// What a method may need besides the scenario (a study's settings).
struct ReferenceSettings {
  std::string config_file; // run: the configuration whose finest level is the reference (-convergence_reference_config)
  std::string common_file; // run: an options file inserted into each of its runs (-convergence_common_options)
};

struct ReferenceMethod {
  const char *name;           // as -reference / -convergence_reference take it
  const char *help;           // one line for -help
  bool        impact = false; // offered by -reference (-task impact)
  bool        study  = false; // offered by -convergence_reference (a reference for a study)
  bool        exact  = false; // no step, no tolerance: only round-off (else its own error is estimated)
  // Whether it can solve sc; *why (may be null): why not, naming the options, as
  // "-reference <name> <why>" reads.
  bool (*applies)(const Scenario &sc, std::string *why) = nullptr;
  // Solves sc on comm. With sc.impact.check_unused_options and report_setup (-task impact)
  // it checks the options it leaves unused and prints its set-up, as ImpactRun does.
  PetscErrorCode (*run)(MPI_Comm comm, const Scenario &sc, const ReferenceSettings &settings,
                        ReferenceSolution *sol) = nullptr;
  // What a study's file calls it: its name, or what it depends on (the configuration file).
  std::string (*label)(const ReferenceSettings &settings) = nullptr;
};

// The registry (app/registry.cpp registers the methods once per process, in the order -help
// lists them: the first impact method is -reference's default; a second registration of the
// same name is ignored).
void                                        ReferenceMethodRegister(const ReferenceMethod *m);
const std::vector<const ReferenceMethod *> &ReferenceMethods();
const ReferenceMethod                      *ReferenceMethodFind(const std::string &name); // nullptr if none
// The names offered by -reference (impact) or -convergence_reference (study), in order.
std::vector<std::string> ReferenceMethodNames(bool study);
// "name: help; name: help" of those methods, for -help.
std::string ReferenceMethodHelp(bool study);
// A study's default reference for sc: the first study method that applies (modal for the linear
// law, run otherwise).
const ReferenceMethod *ReferenceMethodDefault(const Scenario &sc);

// The methods of the run layer.
extern const ReferenceMethod kReferenceTimeStepping; // "ts": ImpactRun with the -ts_* options
extern const ReferenceMethod kReferenceModal;        // "modal": the exact modal solution (run/modal_reference.hpp)

// -reference and the modal solution's -reference_max_memory (GB): the option table (built from
// the registry, so register the methods first) and its reader (-task impact).
const OptionModule &ReferenceOptionModule();
PetscErrorCode      ReferenceMethodFromOptions(MPI_Comm comm, const ReferenceMethod **method);

} // namespace beamimpact

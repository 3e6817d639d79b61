// -task convergence: which time integrator reaches a given accuracy of the ACOR
// fastest, and at which order it converges through the contact events; and, as
// a separate study, the spatial (grid) error and the continuum limit.
//
//   beamimpact -task convergence -options_file options/convergence/study-default.opts
//              -beam_nodes 161 -output conv161.h5
//   scripts/plot_convergence.py conv161.h5 -o conv161
//
// Temporal study (one scene, one impact point, -beam_nodes fixed): every
// configuration (an options file, -convergence_configs a.opts,b.opts,...) is run
// over its own sequence of steps or tolerances, and each run is compared with
// the reference, a study method of the reference registry (run/reference.hpp):
//   * modal, for the linear spring (the default there): the exact modal solution, no step, no
//     tolerance, only round-off;
//   * run, for the hysteretic ball (the default there): the configuration
//     -convergence_reference_config at its own sequence; the finest level is the reference and
//     its error is estimated by Richardson extrapolation from the last three levels (reported
//     with the results).
// Spatial study (-convergence_spatial_nodes 41,81,161,...): the reference at each
// N, Richardson extrapolation to the continuum limit and the observed order in h.
//
// In four parts, as the sweep:
//   * the plan (convergence_plan.hpp): the -convergence_* options (one option table), the
//     configurations and their sequences;
//   * the execution (convergence_runs.hpp): the reference, each configuration's levels in a
//     fresh options database each, the spatial study's references;
//   * the analysis (convergence_analysis.hpp): errors against the reference, observed orders
//     above the error floor, Richardson extrapolation, the cost at the target;
//   * the output (convergence_output.hpp): the HDF5 file and the printed tables;
// and the task (here), which reads the options and runs them in order.
#pragma once

#include "studies/convergence_analysis.hpp"
#include "studies/convergence_output.hpp"
#include "studies/convergence_plan.hpp"
#include "studies/convergence_runs.hpp"

#include <petscsys.h>

#include <string>

namespace beamimpact {

// -task convergence: reads the options, runs the study, prints the tables and the
// cost at -convergence_target against the leapfrog baseline, writes -output.
PetscErrorCode TaskConvergence(MPI_Comm comm, const std::string &output);

} // namespace beamimpact

// -task fit: least-squares calibration of options of the program (the parameters) against a table
// of measurements, each row one run (an impact, the modes, a flight), by TAO (brgn: Gauss-Newton
// with bounds; pounders: derivative-free; -tao_type and every -tao_* option), with the standard
// errors, correlations and identifiability of the fitted numbers at the optimum (docs/fit.md,
// docs/model.md section 17). The runs go through the case batch (studies/case_batch.hpp): farmed
// over the MPI ranks, journaled, never computed twice; a killed fit rerun resumes.
//
//   beamimpact -task fit -fit_data wall.csv -fit_parameters "ball_k1=1e7:1e10,ball_m=1.2:2.4" -output wall-fit.h5
//   mpirun -n 2 beamimpact -options_file options/fits/baseball-wall.opts
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// Reads the -fit_* options and the data, fits, prints the summary and writes -output (/fit, the
// runs in /case_batch) and -fit_options_output (the fitted values as an options file).
PetscErrorCode TaskFit(MPI_Comm comm, const std::string &output);

// Under -help: the -fit_* block and TAO's -tao_* options.
PetscErrorCode FitHelpOptions(MPI_Comm comm);

} // namespace beamimpact

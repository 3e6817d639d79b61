// -task design: the best design a rulebook allows. Bounded numeric options of the program are the
// design variables (-design_variables, log-scaled where their bounds span a decade); the objective
// and the constraints are reductions (max, min, mean over its points) of a results column of a
// small study of each design (-design_studies: an impact, or a few impacts over impact_x, in the
// rig or in the game swing), or numbers of the bat itself (mass, drop, moments of inertia,
// diameter). TAO searches (bqnls without constraints, almm with them; -tao_type and every -tao_*
// option), its gradients by differences of the scaled variables farmed over the ranks as one case
// batch (studies/case_batch.hpp: journaled, a killed design resumes). docs/design-studies.md.
//
//   beamimpact -task design -options_file options/designs/bbcor-bat.opts -output bbcor.h5
#pragma once

#include "base/option_table.hpp"

#include <petscsys.h>

#include <string>

namespace beamimpact {

// The option table of -task design (module "design"), registered by app/registry.cpp.
const OptionModule &DesignOptionTable();

// Reads the -design_* options, optimises, prints the summary and writes -output (/design, the
// runs in /case_batch) and -design_options_output (the optimum as an options file).
PetscErrorCode TaskDesign(MPI_Comm comm, const std::string &output);

// The program's exit status after TaskDesign: 0, or kDesignInfeasibleStatus (3) when the design it returned violates
// a constraint beyond -tao_catol (every output written, each saying so).
constexpr int kDesignInfeasibleStatus = 3;
int           DesignExitStatus();

// Under -help: the -design_* block.
PetscErrorCode DesignHelpOptions(MPI_Comm comm);

} // namespace beamimpact

// The references generated from the program's tables, as Markdown (-help_markdown): the options
// reference (every registered option table: base/option_table.hpp) and the results reference
// (every task's columns: run/results_table.hpp, the sweep's, the convergence study's and the
// flight's). docs/options.md and docs/results.md are this output, committed; the CTest test
// docs_generated fails while they differ, and `cmake --build --preset dev --target docs`
// (scripts/make_docs.sh) rewrites them. The output depends on the tables alone (their order,
// not the run's options or ranks), so it is the same on every machine.
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// The options reference: one section per registered module, in the registry's order, a row per
// option (unit, default, what is allowed, when it acts, its help).
std::string DocsOptionsMarkdown();

// The results reference: the columns of -task impact, sweep, convergence and flight.
std::string DocsResultsMarkdown();

// Prints the reference `which` ("options" or "results") on rank 0 of comm.
PetscErrorCode DocsPrintMarkdown(MPI_Comm comm, const std::string &which);

} // namespace beamimpact

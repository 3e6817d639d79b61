// The string bed's options (-strings_*, -head_*; docs/model.md "The string bed", README's table):
// one table, the module `strings`, registered in app/registry.cpp and read by the checked
// readers of base/option_table.hpp. -strings_frame held makes -task modes compute the bed's
// modes in a held frame (this slice); none, the default, leaves the racket a beam.
#pragma once

#include "base/option_table.hpp"
#include "model/string_bed.hpp"

#include <petscsys.h>

namespace beamimpact {

const OptionModule &StringBedOptionTable();

// Whether -strings_frame asks for the string bed (held), read through its row.
PetscErrorCode StringBedRequested(MPI_Comm comm, PetscBool *on);

// Every -strings_* and -head_* option; the crosses' tension and spacing default to the mains'.
// Checks across options: the grid must put at least 5 nodes across the width (-strings_nodes_width
// or the aspect's count).
PetscErrorCode StringBedParamsFromOptions(MPI_Comm comm, StringBedParams *p);

} // namespace beamimpact

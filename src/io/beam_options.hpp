// The -beam_* options: geometry, material, section (uniform, profile or table), theory,
// supports, damping, the hands (-grip*). Each option is a row of BeamOptionTable (name, unit,
// help, default, range), read in one PetscOptionsBegin block through base/option_table.hpp;
// the checks across options (parameter sets, pivot and grip against the supports, files) are
// here, with messages naming the options (or the file and line) and the values.
#pragma once

#include "base/option_table.hpp"
#include "model/beam.hpp"

#include <petscsys.h>

namespace beamimpact {

struct PartOptionValues;
class StructurePart;

// The -beam_* and -grip* options: the beam module's table (registered by app/registry.cpp).
const OptionModule &BeamOptionTable();

// Reads the options, converts the parameter set to sections, checks every range.
PetscErrorCode BeamParamsFromOptions(MPI_Comm comm, BeamParams *p);

// A registered structure part's rows (system/structure_part.hpp), read in its own -help block:
// the given ones into *v (a flag as 1, a number as one value, a choice as its index, a list as its
// values).
PetscErrorCode StructurePartOptionsRead(MPI_Comm comm, const StructurePart &part, PartOptionValues *v);

// Range and consistency checks, with messages naming the option and the value.
PetscErrorCode BeamParamsCheck(MPI_Comm comm, const BeamParams &p);

} // namespace beamimpact

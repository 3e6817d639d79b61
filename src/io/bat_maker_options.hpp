// The options of a bat by its maker's numbers (-bat_length, -bat_knob_diameter, ...; the module
// `batmaker`, docs/bats.md "A bat by its maker's numbers"): read when -bat_length is given, they
// replace -beam_profile: the profile is model/bat_maker.hpp's, in the material of
// -beam_youngs_modulus and -beam_density, hollow with -barrel_wall_thickness.
#pragma once

#include "base/option_table.hpp"
#include "model/bat_maker.hpp"

#include <petscsys.h>

namespace beamimpact {

const OptionModule &BatMakerOptionTable();

// Whether -bat_length is given (the bat is then the maker's).
PetscErrorCode BatMakerRequested(MPI_Comm comm, PetscBool *on);

// Every -bat_* number of the maker (the barrel's wall is -barrel_wall_thickness, read with the beam's
// options and passed in: wall, 0 for a solid bat).
PetscErrorCode BatMakerParamsFromOptions(MPI_Comm comm, PetscReal wall, BatMakerParams *b);

// Under -help: the block.
PetscErrorCode BatMakerHelpOptions(MPI_Comm comm);

} // namespace beamimpact

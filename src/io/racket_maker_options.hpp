// The options of a racket by its maker's numbers (-racket_length, -racket_mass, -racket_balance, ...;
// the module `racket`, docs/model.md section 16): read when -racket_length is given, they replace
// -beam_properties and the head's outline (-head_length, -head_width, -head_center): the frame's
// table and the head are model/racket_maker.hpp's; the strings stay the -strings_* options.
#pragma once

#include "base/option_table.hpp"
#include "model/racket_maker.hpp"

#include <petscsys.h>

namespace beamimpact {

const OptionModule &RacketMakerOptionTable();

// Whether -racket_length is given (the racket is then the maker's).
PetscErrorCode RacketMakerRequested(MPI_Comm comm, PetscBool *on);

// Every -racket_* number.
PetscErrorCode RacketMakerParamsFromOptions(MPI_Comm comm, RacketMakerParams *r);

// Under -help: the block.
PetscErrorCode RacketMakerHelpOptions(MPI_Comm comm);

} // namespace beamimpact

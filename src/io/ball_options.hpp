// The -ball_* options: mass, speed, the contact law (-ball_law, from the registry of
// model/contact_law.hpp) and that law's own options (its rows: for the hysteretic law the
// characterisation of a ball as it is tested, rigid-wall COR and contact time at a test speed,
// an e(v) table). One option table (the common rows and every law's), one PetscOptionsBegin
// block; every value checked against its row, then the law's checks across options, each with a
// message naming the option. An option of another law than the one chosen is refused.
#pragma once

#include "base/option_table.hpp"
#include "model/contact.hpp"

#include <petscsys.h>

namespace beamimpact {

// The option table of the ball: -ball_mass, -ball_speed, -ball_law, -ball_radius,
// -ball_loss_factor and every registered law's rows (registered by app/registry.cpp).
const OptionModule &BallOptionModule();

// Reads -ball_* options; checks ranges with messages naming option and value. Under -help every
// law's options are listed (read into a scratch ball).
PetscErrorCode BallParamsFromOptions(MPI_Comm comm, BallParams *b);

} // namespace beamimpact

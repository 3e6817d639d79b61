// The PETSc and SLEPc options the program advertises: the integrators (-ts_type and the options
// of the types in options/integrators and options/convergence), their steps and tolerances, the
// nonlinear and linear solvers of the implicit types, the modes' eigensolver (-modes_eps_*,
// -modes_st_*). PETSc's own objects read them (TSSetFromOptions, ...); the table lists them so
// that -help shows them with their units (also -ts_modal_order, read only under -ts_type
// modal), the unknown-option check tells a typo of one of them (-ts_dtt) from a leftover of
// another integrator (a note), and a sweep knows the unit of a -ts_dt axis.
#pragma once

#include "base/option_table.hpp"

namespace beamimpact {

const OptionModule &PetscSolverOptionTable();

} // namespace beamimpact

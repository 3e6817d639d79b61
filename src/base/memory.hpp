// The memory a run may take, and the check of an estimate against it: -max_memory (GB; default
// half of the physical memory) bounds the largest allocations a run makes (the flight's series,
// a grid's state and its modes), each estimated before it is made and refused beyond the limit
// with the estimate and the option in the message, as -reference_max_memory does for
// -reference modal (run/reference.hpp).
#pragma once

#include <petscsys.h>

#include <string>

namespace beamimpact {

// The machine's physical memory (bytes; 0 when the system does not say).
double MemoryPhysical();
// The limit (bytes): -max_memory GB as given (the task table checks it is > 0), else half of the
// physical memory (8 GB when that is unknown).
double MemoryLimit();
// Refuses `need` bytes above MemoryLimit(): "<what> would need about X GB, above the limit of
// Y GB (-max_memory, default half of the physical memory): <remedy>, or raise -max_memory".
PetscErrorCode MemoryCheck(MPI_Comm comm, double need, const std::string &what, const std::string &remedy);

} // namespace beamimpact

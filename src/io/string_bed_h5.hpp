// The results file of -strings_frame held -task modes (docs/model.md, "The string bed"): the run
// record as root attributes (program, provenance, /options_used, the bed's parameters and the
// membrane's N_x, N_z, sigma and grid), /modes/frequency (Hz), /modes/omega (rad/s), the node
// coordinates /modes/x and /modes/z (m, from the head's centre; x along the frame's axis) and one
// dataset per mode /modes/shape_1, shape_2, ... of dims [z][x] (the mass-normalised deflection,
// kg^-1/2; 0 at held nodes). Written by rank 0.
#pragma once

#include "io/run_record.hpp"
#include "model/string_bed.hpp"
#include "solvers/string_bed_modes.hpp"

#include <string>

namespace beamimpact {

PetscErrorCode StringBedRunRecordBuild(const StringBedParams &p, const StringBedModes &modes, RunRecord *rec);
PetscErrorCode ResultsWriteStringBedModesFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                              const StringBedParams &p, const StringBedModes &modes);

} // namespace beamimpact

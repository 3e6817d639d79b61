// The notes of a sweep's points said once per sweep. A note ("note: -beam_pivot 0.5 is placed
// on the nearest node ...") that every point's set-up prints would otherwise print once per
// point (43 times in a 21-point sweep). While the sweep runs, every line its process prints
// through PETSc that starts with "note: " passes a filter (PetscVFPrintf): during the set-up
// (options of every point, probe) each note prints once and is remembered; during the points they are counted,
// each text once per point; at the end rank 0 prints each note not already said, once, with
// the number of points it applies to: "note (on 21 of 21 points): ...".
#pragma once

#include <petscsys.h>

namespace beamimpact {

// From the sweep's start: notes print and are remembered.
PetscErrorCode SweepNotesBegin();
// From the first point: notes are counted, not printed.
void SweepNotesCollect();
// After a point on this process (leader: whether it counts the point's notes; a group's other
// ranks print nothing through PetscPrintf on the group, so they count nothing).
void SweepNotesPointDone(bool leader);
// At the end, on every rank of world: the counts summed on rank 0, which prints each note not
// said during the set-up, once, with "of npoints points"; the filter removed.
PetscErrorCode SweepNotesEnd(MPI_Comm world, PetscInt npoints);

// A sweep stopped by an error: the filter removed, nothing printed.
void SweepNotesAbandon();

} // namespace beamimpact

// The string bed part's parameters for the bed's own tasks (-task modes of a held bed, its -help
// block) and for tests: the part itself is system/parts/bed.cpp, registered in
// system/structure.cpp like every part; nothing else reads its parameters.
#pragma once

#include "model/beam.hpp"
#include "model/string_bed.hpp"
#include "system/structure_part.hpp"

#include <string>

namespace beamimpact {

const StructurePart &BedPart();

// Its rows as read (StructurePart::Options, the module 'strings') -> *p, from StringBedParams'
// defaults; false with *why naming the options and values when the strings do not fit the head.
bool StringBedParamsFrom(const PartOptionValues &v, StringBedParams *p, std::string *why);
// The bed present in beam (nullptr: none).
const StringBedParams *StringBedOf(const BeamParams &beam);
// Puts `bed` in beam as its part (a bed with -strings_frame none removes it); the beam's frame is
// left as it is.
void StringBedSet(BeamParams *beam, const StringBedParams &bed);

} // namespace beamimpact

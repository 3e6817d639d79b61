// The -strings_* and -head_* options. See string_bed_options.hpp.
#include "io/string_bed_options.hpp"

#include "io/beam_options.hpp"
#include "system/parts/bed.hpp"

namespace beamimpact {

// The rows are the bed part's (system/parts/bed.cpp).
const OptionModule &StringBedOptionTable() { return BedPart().Options(); }

PetscErrorCode StringBedRequested(MPI_Comm comm, PetscBool *on)
{
  const OptionModule &t     = StringBedOptionTable();
  PetscInt            frame = 0;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, t.title.c_str(), "beamimpact");
  PetscCall(OptionsReadChoice(PetscOptionsObject, t, "-strings_frame", &frame, NULL));
  PetscOptionsEnd();
  *on = frame == 1 ? PETSC_TRUE : PETSC_FALSE; // held: the bed's own modes
  PetscFunctionReturn(0);
}

PetscErrorCode StringBedParamsFromOptions(MPI_Comm comm, StringBedParams *p)
{
  PartOptionValues v;
  std::string      why;
  PetscFunctionBeginUser;
  PetscCall(StructurePartOptionsRead(comm, BedPart(), &v));
  PetscCheck(StringBedParamsFrom(v, p, &why), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", why.c_str());
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The -strings_* and -head_* options. See string_bed_options.hpp.
#include "io/string_bed_options.hpp"

#include "system/structure_part.hpp"

namespace beamimpact {

// The rows are the bed part's (system/parts/bed.cpp).
const OptionModule &StringBedOptionTable() { return StructurePartFind("bed")->Options(); }

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
  const OptionModule &t     = StringBedOptionTable();
  PetscInt            shape = p->shape == HeadShape::Ellipse ? 0 : 1, frame = 0;
  PetscBool           set_tc, set_sc, set_nw;
  PetscInt            nw = 0;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, t.title.c_str(), "beamimpact");
  PetscCall(OptionsReadChoice(PetscOptionsObject, t, "-strings_frame", &frame, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_tension", &p->tension, NULL));
  p->tension_crosses = p->tension; // the default shown by -help is the mains'
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_tension_crosses", &p->tension_crosses, &set_tc));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_spacing", &p->spacing, NULL));
  p->spacing_crosses = p->spacing;
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_spacing_crosses", &p->spacing_crosses, &set_sc));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_linear_density", &p->linear_density, NULL));
  PetscCall(OptionsReadChoice(PetscOptionsObject, t, "-head_shape", &shape, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-head_length", &p->head_length, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-head_width", &p->head_width, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-head_center", &p->head_center, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_nodes", &p->nodes, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_patch_radius", &p->patch_radius, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_inplane_stiffness", &p->inplane_stiffness, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_inplane_mass", &p->inplane_mass, NULL));
  nw = StringBedGrid(*p).nz; // -help shows the aspect's count
  PetscCall(OptionsRead(PetscOptionsObject, t, "-strings_nodes_width", &nw, &set_nw));
  PetscOptionsEnd();
  p->shape       = shape == 0 ? HeadShape::Ellipse : HeadShape::Rectangle;
  p->frame       = frame == 1 ? "held" : frame == 2 ? "beam" : "none";
  p->nodes_width = set_nw ? nw : 0;
  if (!p->On()) PetscFunctionReturn(0); // no bed: its options have no effect (a note)
  // the membrane stands for a woven bed: at least one string of each kind across the head
  PetscCheck(p->spacing < p->head_width, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-strings_spacing %g m is not allowed with -head_width %g m: the mains, %g m apart across the face, leave "
             "no string on the head; it must be < -head_width (m)",
             (double)p->spacing, (double)p->head_width, (double)p->spacing);
  PetscCheck(p->spacing_crosses < p->head_length, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s %g m is not allowed with -head_length %g m: the crosses, %g m apart along the frame, leave no string "
             "on the head; it must be < -head_length (m)",
             set_sc ? "-strings_spacing_crosses" : "-strings_spacing (the crosses' default)",
             (double)p->spacing_crosses, (double)p->head_length, (double)p->spacing_crosses);
  const BedGrid g = StringBedGrid(*p); // the held frame's grid (a beam frame's: StringBedOnFrame)
  PetscCheck(!p->Held() || g.nz >= 5, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-strings_nodes %" PetscInt_FMT " with -head_length %g and -head_width %g puts %" PetscInt_FMT
             " nodes across the width: at least 5 are needed (more -strings_nodes, or -strings_nodes_width)",
             p->nodes, (double)p->head_length, (double)p->head_width, g.nz);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

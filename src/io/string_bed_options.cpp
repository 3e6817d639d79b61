// The -strings_* and -head_* options. See string_bed_options.hpp.
#include "io/string_bed_options.hpp"

namespace beamimpact {

const OptionModule &StringBedOptionTable()
{
  static const OptionModule m = {
    "strings",
    "The racket's string bed: a membrane on the head's outline (-strings_frame held -task modes: its modes in a held "
    "frame)",
    {
      OptionChoice("-strings_frame",
                   "The frame holding the bed: none (no string bed; the racket is the beam), held (a rigid frame, w = "
                   "0 on the outline; -impact_x from the head's end, -task modes the bed's modes on a 2-D DMDA) or "
                   "beam (the beam is the frame: the bed on its nodes, the head bending and rolling with it; needs "
                   "-beam_torsion)",
                   {"none", "held", "beam"}, "none"),
      OptionNeeds(OptionReal("-strings_patch_radius", "m",
                             "The ball's load on the bed: the point's bilinear hat weights on its cell's four nodes, "
                             "each node's share spread over a disc of this radius about it with the weights 1 - "
                             "r^2/a^2, so that the load's resultant and moments are the point's (0: the hat weights "
                             "alone; default sqrt(R_b delta), delta the ball's peak compression on a rigid wall at the "
                             "approach speed, with -ball_radius)",
                             "", NonNegative()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_tension", "N", "Tension of each main string (along the frame's axis)", "250",
                             Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_tension_crosses", "N",
                             "Tension of each cross string (default: -strings_tension)", "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_spacing", "m",
                             "Spacing of the mains (centre to centre, across the face; < -head_width)", "0.0151",
                             Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_spacing_crosses", "m",
                             "Spacing of the crosses (along the frame's axis; default: -strings_spacing; < "
                             "-head_length)",
                             "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_linear_density", "kg/m", "Mass per length of a string (nylon 1.30 mm: 1.51e-3)",
                             "1.51e-3", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionChoice("-head_shape", "Outline of the head", {"ellipse", "rectangle"}, "ellipse"),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-head_length", "m",
                             "Length of the head's outline along the frame's axis (the ellipse's major axis)", "0.34",
                             Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-head_width", "m", "Width of the head's outline across the face", "0.24", Positive()),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-head_center", "m",
                             "Centre of the head along the frame's axis, from x = 0 (-strings_frame beam; held: the "
                             "head's middle)",
                             "0.175", NonNegative()),
                  {"-strings_frame=beam"}),
      OptionNeeds(OptionInt("-strings_nodes",
                            "Grid nodes across the head's length, edges included (-strings_frame held; on a beam frame "
                            "the bed's columns are the beam's nodes, -beam_nodes)",
                            "61", AtLeast(5)),
                  {"-strings_frame=held"}),
      OptionNeeds(OptionInt("-strings_nodes_width",
                            "Grid nodes across the head's width (default: from the aspect, so that h_z ~ h_x)", "",
                            AtLeast(5)),
                  {"-strings_frame=held|-strings_frame=beam"}),
      OptionNeeds(OptionReal("-strings_inplane_stiffness", "N/m",
                             "An oblique impact on the bed: the stiffness of the mains under the ball against their "
                             "sideways slide (across their length, the friction force's direction; docs/model.md "
                             "section 13); default n T (1/a + 1/b), n = 2 r_p / s_m mains under the ball's patch, T "
                             "-strings_tension, a and b the struck main's lengths to its two ends",
                             "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam", "-impact_angle!=0|-ball_spin!=0|-bat_speed_face!=0",
                   "-ball_friction!=0"}),
      OptionNeeds(OptionReal("-strings_inplane_mass", "kg",
                             "An oblique impact on the bed: the mass of the mains under the ball in that slide; "
                             "default n lambda (a + b) / 3 (the triangle of a string pulled aside at a point)",
                             "", Positive()),
                  {"-strings_frame=held|-strings_frame=beam", "-impact_angle!=0|-ball_spin!=0|-bat_speed_face!=0",
                   "-ball_friction!=0"}),
    },
  };
  return m;
}

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

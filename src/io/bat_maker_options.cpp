// The options of a bat by its maker's numbers. See bat_maker_options.hpp.
#include "io/bat_maker_options.hpp"

namespace beamimpact {

const OptionModule &BatMakerOptionTable()
{
  static const OptionModule m = {
    "batmaker",
    "A bat by its maker's numbers (instead of -beam_profile): x from the knob's end; hollow with "
    "-barrel_wall_thickness (docs/bats.md)",
    {
      OptionReal("-bat_length", "m",
                 "The bat's length L, knob end to barrel end: a bat by its maker's numbers (the -bat_* rows below), in "
                 "the material of -beam_youngs_modulus and -beam_density; not with -beam_profile",
                 "", Positive()),
      OptionNeeds(OptionReal("-bat_knob_diameter", "m", "The knob's diameter D_k", "0.046", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_knob_length", "m",
                             "The knob's flat part along the axis (a 4 mm fillet joins it to the handle)", "0.012",
                             Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_handle_diameter", "m", "The handle's diameter D_h", "0.0254", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_taper_start", "m", "Where the handle ends and the taper toward the barrel starts",
                             "0.30", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_taper_end", "m",
                             "Where the taper ends: the barrel's full diameter (diameter and wall linear along the "
                             "taper)",
                             "0.53", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_barrel_diameter", "m",
                             "The barrel's diameter D_b (NCAA/NFHS: at most 2 5/8 in = 0.066675 m; MLB: 2.61 in = "
                             "0.066294 m)",
                             "0.066675", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_end_taper_start", "m",
                             "Where the barrel starts narrowing toward -bat_end_diameter at the end (a torpedo bat's "
                             "barrel; default: no narrowing)",
                             "", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_end_diameter", "m",
                             "The diameter at the barrel's end, reached linearly from -bat_end_taper_start (default: "
                             "the barrel's)",
                             "", Positive()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_handle_wall_thickness", "m",
                             "A hollow bat's wall in the handle and the knob (default: -barrel_wall_thickness; linear "
                             "along the taper)",
                             "", Positive()),
                  {"-barrel_wall_thickness"}),
      OptionNeeds(OptionReal("-bat_end_cap_mass", "kg",
                             "A hollow bat's end cap: its mass added by thickening the wall inward over the barrel's "
                             "last -bat_end_cap_length",
                             "0", NonNegative()),
                  {"-barrel_wall_thickness"}),
      OptionNeeds(OptionReal("-bat_end_cap_length", "m", "The length of the barrel's end the end cap thickens", "0.02",
                             Positive()),
                  {"-bat_end_cap_mass"}),
      OptionNeeds(OptionReal("-bat_cup_depth", "m",
                             "A solid bat's cupped end: a bore of -bat_cup_diameter this deep (MLB rule 3.02: at most "
                             "1 1/4 in)",
                             "0", NonNegative()),
                  {"-bat_length"}),
      OptionNeeds(OptionReal("-bat_cup_diameter", "m", "The cup's diameter (MLB: 1 to 2 in)", "0.0381", Positive()),
                  {"-bat_cup_depth"}),
    },
  };
  return m;
}

PetscErrorCode BatMakerRequested(MPI_Comm, PetscBool *on)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-bat_length", on));
  PetscFunctionReturn(0);
}

PetscErrorCode BatMakerParamsFromOptions(MPI_Comm comm, PetscReal wall, BatMakerParams *b)
{
  const OptionModule &T = BatMakerOptionTable();

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_length", &b->length, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_knob_diameter", &b->knob_diameter, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_knob_length", &b->knob_length, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_handle_diameter", &b->handle_diameter, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_taper_start", &b->taper_start, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_taper_end", &b->taper_end, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_barrel_diameter", &b->barrel_diameter, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_end_taper_start", &b->end_taper_start, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_end_diameter", &b->end_diameter, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_handle_wall_thickness", &b->handle_wall_thickness, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_end_cap_mass", &b->end_cap_mass, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_end_cap_length", &b->end_cap_length, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_cup_depth", &b->cup_depth, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-bat_cup_diameter", &b->cup_diameter, NULL));
  PetscOptionsEnd();
  b->wall_thickness = wall;
  PetscFunctionReturn(0);
}

PetscErrorCode BatMakerHelpOptions(MPI_Comm comm)
{
  BatMakerParams b;
  PetscFunctionBeginUser;
  PetscCall(BatMakerParamsFromOptions(comm, 0, &b));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The options of a racket by its maker's numbers. See racket_maker_options.hpp.
#include "io/racket_maker_options.hpp"

namespace beamimpact {

const OptionModule &RacketMakerOptionTable()
{
  static const OptionModule m = {
    "racket",
    "A racket by its maker's numbers (instead of -beam_properties and -head_length, -head_width, -head_center): x from "
    "the butt (docs/model.md section 16)",
    {
      OptionReal("-racket_length", "m",
                 "The racket's length L, butt to tip: a racket by its maker's numbers (the -racket_* rows below; the "
                 "strings stay -strings_*); not with -beam_properties",
                 "", Positive()),
      OptionNeeds(OptionReal("-racket_mass", "kg",
                             "The strung racket's mass M (the frame's two levels of mass per length and the strings')",
                             "0.321", Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_balance", "m",
                             "The strung racket's balance point x_b from the butt (its centre of mass)", "0.330",
                             Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_head_size", "m^2", "The head's strung area A (645 cm^2 = 100 in^2)", "0.0645",
                             Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_head_aspect", "1", "The head's length over its width", "1.37", Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_head_margin", "m", "From the head's tip (its strung area's) to the frame's tip",
                             "0.01", NonNegative()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_handle_length", "m",
                             "The handle's level of mass per length ends here (a 2 cm ramp to the head's level)",
                             "0.17", Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_frame_stiffness", "N m^2",
                             "The frame's bending stiffness EI, uniform (a free frame's first mode near 150 Hz for the "
                             "defaults)",
                             "157", Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_twist_stiffness", "N m^2",
                             "The frame's torsional stiffness G J, uniform (-beam_torsion)", "350", Positive()),
                  {"-racket_length"}),
      OptionNeeds(OptionReal("-racket_twistweight", "kg m^2",
                             "The strung racket's moment of inertia about its axis (14 kg cm^2 typical)", "0.0014",
                             Positive()),
                  {"-racket_length"}),
    },
  };
  return m;
}

PetscErrorCode RacketMakerRequested(MPI_Comm, PetscBool *on)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-racket_length", on));
  PetscFunctionReturn(0);
}

PetscErrorCode RacketMakerParamsFromOptions(MPI_Comm comm, RacketMakerParams *r)
{
  const OptionModule &T = RacketMakerOptionTable();

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_length", &r->length, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_mass", &r->mass, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_balance", &r->balance, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_head_size", &r->head_size, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_head_aspect", &r->head_aspect, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_head_margin", &r->head_margin, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_handle_length", &r->handle_length, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_frame_stiffness", &r->frame_stiffness, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_twist_stiffness", &r->twist_stiffness, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-racket_twistweight", &r->twistweight, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode RacketMakerHelpOptions(MPI_Comm comm)
{
  RacketMakerParams r;
  PetscFunctionBeginUser;
  PetscCall(RacketMakerParamsFromOptions(comm, &r));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

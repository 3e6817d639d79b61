// The -ball_* options. See ball_options.hpp.
#include "io/ball_options.hpp"

#include "io/cor_table_file.hpp"

#include <string>

namespace beamimpact {

namespace {

// -ball_law's help: every registered law with its formula.
std::string LawHelp()
{
  std::string s = "Contact law:";
  for (const ContactLaw *law : ContactLaws())
    s += std::string(s.back() == ':' ? " " : "; ") + law->Name() + " (" + law->Summary() + ")";
  return s;
}

// -ball_loss_factor's help: the laws it applies to (the elastic ones).
std::string LossFactorHelp()
{
  std::string elastic;
  for (const ContactLaw *law : ContactLaws())
    if (law->Elastic()) elastic += (elastic.empty() ? "" : ", ") + std::string(law->Name());
  return "Factor applied to the ACOR of an elastic law (" + elastic +
         ") for the ball's losses (reported as acor_corrected; a lossy law's acor_corrected is its acor)";
}

// The condition of an oblique impact's tangential options (OptionSpec::needs).
const char *const kOblique = "-impact_offset!=0|-ball_spin!=0|-impact_angle!=0|-bat_speed_face!=0";

OptionModule BuildBallOptions()
{
  OptionModule m;
  m.name    = "ball";
  m.title   = "Ball: mass, speed and contact law (SI units)";
  m.options = {
    OptionReal("-ball_mass", "kg", "Ball mass m_b", "0.042", Positive()),
    OptionReal("-ball_speed", "m/s", "Incident speed v_i (0: a ball at rest, struck by a swinging bat: -bat_speed)",
               "1", NonNegative()),
    OptionChoice("-ball_law", LawHelp().c_str(), ContactLawNames(), ContactLaws().front()->Name()),
    OptionReal("-ball_radius", "m",
               "Ball radius: a compression beyond it is flagged as physically absurd (a sweep's summary counts such "
               "points; default: none, no check)",
               "", Positive()),
    OptionReal("-ball_loss_factor", "1", LossFactorHelp().c_str(), "0.85", Between(0, 1, true, false)),
    // The oblique impact (docs/model.md "Oblique impacts"): the friction and the ball's inertia
    // act only where the surfaces slide across each other, -impact_offset or -ball_spin not 0
    // (head-on, even with -flight, nothing moves along the tangent), and the tangential
    // compliance only where there is friction.
    OptionReal("-ball_spin", "rad/s",
               "Incoming spin about the bat's axis direction (> 0: backspin of the incoming ball, as a fastball; < 0: "
               "topspin, as a curveball); needs -ball_radius and a round bat (-beam_profile) or a string bed (there "
               "about the mains' direction x, > 0 the same sense: its face at the bed moving toward +z)",
               "0"),
    OptionNeeds(OptionReal("-ball_inertia_factor", "1",
                           "Moment of inertia of the ball I/(m R^2) (0.4: a solid sphere; a baseball about 0.4, a "
                           "tennis ball about 0.55), for an oblique impact",
                           "0.4", Between(0, 2.0 / 3.0, true, false)),
                {"-ball_radius", kOblique, "-ball_friction!=0"}),
    OptionNeeds(OptionReal("-ball_friction", "1",
                           "Coulomb friction coefficient mu of ball on bat, for an oblique impact (0: frictionless)",
                           "0.5", NonNegative()),
                {"-ball_radius", kOblique}),
    OptionNeeds(OptionReal("-ball_tangential_cor", "1",
                           "Tangential restitution e_T of the contact's tangential compliance (0: the surfaces leave "
                           "rolling; baseball on wood about 0.3, Cross & Nathan 2006); not given: no compliance, a "
                           "rigid grip",
                           "", Between(0, 1, false, true)),
                {"-ball_radius", kOblique, "-ball_friction!=0"}),
  };
  for (const ContactLaw *law : ContactLaws())
    m.options.insert(m.options.end(), law->Options().begin(), law->Options().end());
  return m;
}

// The rows of one law, read into b's values (numbers, in order) and *in (what was given; the
// text of file and text rows). in may be null (-help of a law not chosen).
PetscErrorCode BallLawOptionsRead(PetscOptionItems *PetscOptionsObject, const OptionModule &M, const ContactLaw &law,
                                  BallParams *b, ContactLawInput *in)
{
  PetscInt i = 0;

  PetscFunctionBeginUser;
  for (const OptionSpec &row : law.Options()) {
    PetscBool set = PETSC_FALSE;
    if (row.kind == OptionKind::Real) {
      PetscCheck(i < kContactLawMaxValues, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "the %s law has more than %d numeric options", law.Name(), kContactLawMaxValues);
      PetscCall(OptionsRead(PetscOptionsObject, M, row.name.c_str(), &b->value[i++], &set));
    } else if (row.kind == OptionKind::File || row.kind == OptionKind::Text) {
      std::string text;
      PetscCall(OptionsRead(PetscOptionsObject, M, row.name.c_str(), &text, &set));
      if (set && in) in->text[row.name] = text;
    } else
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_PLIB, "option %s of the %s law: a law's options are numbers, texts or files",
              row.name.c_str(), law.Name());
    if (set && in) in->given.push_back(row.name);
  }
  PetscFunctionReturn(0);
}

// An option of another law than the one chosen is refused, naming both laws.
PetscErrorCode BallOtherLawOptions(MPI_Comm comm, const ContactLaw &chosen)
{
  PetscFunctionBeginUser;
  for (const ContactLaw *law : ContactLaws()) {
    if (law == &chosen) continue;
    for (const OptionSpec &row : law->Options()) {
      PetscBool set = PETSC_FALSE;
      PetscCall(PetscOptionsHasName(NULL, NULL, row.name.c_str(), &set));
      if (!set) continue;
      std::string own;
      for (const OptionSpec &r : chosen.Options()) own += (own.empty() ? "" : ", ") + r.name;
      SETERRQ(comm, PETSC_ERR_ARG_INCOMP,
              "%s is a %s parameter but -ball_law is %s: give -ball_law %s, or the %s law's options (%s)",
              row.name.c_str(), law->Name(), chosen.Name(), law->Name(), chosen.Name(), own.c_str());
    }
  }
  PetscFunctionReturn(0);
}

} // namespace

const OptionModule &BallOptionModule()
{
  static const OptionModule m = BuildBallOptions();
  return m;
}

PetscErrorCode BallParamsFromOptions(MPI_Comm comm, BallParams *b)
{
  const OptionModule &M      = BallOptionModule();
  std::string         name   = b->law->Name();
  PetscBool           help   = PETSC_FALSE;
  const ContactLaw   *chosen = nullptr;
  ContactLawInput     in;
  std::string         why;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  PetscOptionsBegin(comm, NULL, M.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_mass", &b->mass, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_speed", &b->speed, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_law", &name, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_radius", &b->radius, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_loss_factor", &b->loss_factor, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_spin", &b->spin, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_inertia_factor", &b->inertia_factor, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_friction", &b->friction, NULL));
  {
    PetscReal e_T = 0; // shown as no default under -help (none: a rigid grip)
    PetscBool set = PETSC_FALSE;
    PetscCall(OptionsRead(PetscOptionsObject, M, "-ball_tangential_cor", &e_T, &set));
    if (set) b->tangential_cor = e_T;
  }
  chosen = ContactLawFind(name.c_str()); // a known name: the reader checked the choice
  if (chosen != b->law) BallParamsUseLaw(b, chosen);
  for (const ContactLaw *law : ContactLaws()) { // the chosen law's options; under -help every law's
    if (law == chosen) PetscCall(BallLawOptionsRead(PetscOptionsObject, M, *law, b, &in));
    else if (help) {
      BallParams other;
      BallParamsUseLaw(&other, law);
      PetscCall(BallLawOptionsRead(PetscOptionsObject, M, *law, &other, nullptr));
    }
  }
  PetscOptionsEnd();

  PetscCall(BallOtherLawOptions(comm, *chosen));
  in.read_cor_table = CorTableRead;
  const int code    = chosen->Configure(in, b, &why);
  PetscCheck(!code, comm, code, "%s", why.c_str());
  PetscFunctionReturn(0);
}

} // namespace beamimpact

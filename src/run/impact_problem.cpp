// One impact's problem built before the first step (see impact_problem.hpp): the projection of
// an oblique impact, the system and everything read from it, -impact_after, -ts_type and the
// modal truncation, each resolved here once.
#include "run/impact_problem.hpp"

#include "run/stage.hpp"
#include "solvers/ts_modal.hpp"

#include <petscts.h>

namespace beamimpact {

namespace {

// The system (the structure's, or built and kept there), the coupling at the impact point, the
// swing's speed at it and the frame's motion, the contact's scales of the approach speed.
PetscErrorCode ProblemSystem(ImpactStructure *structure, ImpactProblem *pb)
{
  const Scenario &sc = pb->sc;
  std::string     why;

  PetscFunctionBeginUser;
  if (structure && structure->sys) pb->system = structure->sys;
  else {
    auto built = std::make_shared<BeamSystem>();
    PetscCheck(BeamSystemBuild(sc.beam, built.get(), &why), pb->comm, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
    pb->system = built;
    if (structure) structure->sys = pb->system;
  }
  const BeamSystem &sys = pb->sys();
  pb->g                 = BeamSystemCoupling(sys, sc.impact.x, sc.impact.z);
  pb->approach          = sc.ball.speed;
  if (sc.swing.Swings()) { // the bat moves rigidly toward the ball (-y): V(x) = V_cm + Omega (x - x_cm)
    const BeamRigidBody body = BeamRigidBodyOf(sc.beam);
    pb->V_x                  = SwingSpeedAt(sc.swing, body, sc.impact.x);
    pb->approach             = sc.ball.speed + pb->V_x;
    PetscCheck(pb->approach > 0, pb->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-bat_speed %g, -bat_angular_velocity %g: the bat moves at %g m/s at x = %g m, so ball (-ball_speed %g) "
               "and bat do not approach",
               (double)sc.swing.bat_speed, (double)sc.swing.bat_angular_velocity, (double)pb->V_x, (double)sc.impact.x,
               (double)sc.ball.speed);
    pb->beam_velocity = BeamSystemSwingVelocity(sys, sc.swing, body);
    pb->frame.v       = pb->beam_velocity; // the frame moves with the bat's rigid swing
  }
  if (ForceOperatorDriven(sys, &pb->frame)) { // the hands' work is counted from Q(0)
    const std::vector<PetscReal> zero(sys.ndof, 0.0);
    ForceState                   at0; // t = 0: undeformed, moving with the frame
    at0.y        = zero.data();
    at0.ys       = sys.fields;
    at0.v        = pb->frame.v.data();
    at0.vs       = sys.fields;
    at0.frame    = &pb->frame;
    pb->frame.q0 = ForceOperatorFrameMomentum(sys, at0, 0, sys.ndof) +
                   sc.ball.mass * FrameMotionAt(pb->frame, pb->g) * sc.ball.speed;
  }
  BallParams approaching = sc.ball; // the contact's scales are those of the approach speed
  approaching.speed      = pb->approach;
  pb->scales             = ContactScalesOf(sys, approaching);
  PetscFunctionReturn(0);
}

// Whether this run follows the free vibration in modes: -impact_after modal (the default)
// where the beam allows it; with the default, a beam that does not is integrated in time and
// the reason printed (once per process); asked for explicitly, it is an error.
PetscErrorCode ImpactAfterResolve(MPI_Comm comm, const ImpactParams &ip, const BeamSystem &sys, bool *modal)
{
  static bool said = false;
  std::string why;

  PetscFunctionBeginUser;
  *modal = ip.after == ImpactAfter::Modal;
  if (!*modal || BeamModesAvailable(sys, &why)) PetscFunctionReturn(0);
  PetscCheck(!ip.after_set, comm, PETSC_ERR_SUP, "-impact_after modal is not possible: %s; use -impact_after time",
             why.c_str());
  if (!said)
    PetscCall(PetscPrintf(comm,
                          "note: the free vibration after separation is integrated in time (-impact_after time): %s\n",
                          why.c_str()));
  said   = true;
  *modal = false;
  PetscFunctionReturn(0);
}

// The one reader of the modal engine's options in a run (-modal_modes, -modal_tolerance,
// -modal_refine, -modal_weight; solvers/beam_modes.hpp), with what the run sets: the contact
// time scale T and the force's start from the approach speed (a ball at rest: the bat's), the
// run's cost line and progress (with report_setup). The modal reference: every mode (the dense
// exact solution) unless -modal_modes is given, T its own default.
PetscErrorCode TruncationRead(const ImpactProblem &pb, ModalTruncation *t)
{
  const ImpactParams &ip = pb.sc.impact;

  PetscFunctionBeginUser;
  PetscCall(ModalTruncationFromOptions(pb.comm, t));
  if (pb.method == ImpactMethod::ModalReference) {
    PetscBool asked = PETSC_FALSE;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-modal_modes", &asked));
    if (!asked) t->modes = ModalModes::All;
    PetscFunctionReturn(0);
  }
  t->contact_time   = ContactTimeScale(pb.sc.ball, pb.approach);
  t->force_exponent = ContactStartExponent(pb.sc.ball, pb.approach);
  t->cost_warn      = ip.report_setup ? ip.cost_warn : 0;
  t->progress       = ip.report_setup ? ip.progress : 0;
  PetscFunctionReturn(0);
}

// -ts_type as the TS stepper takes it (the formulation depends on it; rk when not given).
PetscErrorCode TSTypeRead(std::string *ts_type)
{
  char      type[256] = TSRK;
  PetscBool flg;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-ts_type", type, sizeof(type), &flg));
  *ts_type = type;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ImpactProblemBuild(MPI_Comm comm, const Scenario &given, ImpactMethod method, ImpactStructure *structure,
                                  ImpactProblem *pb)
{
  PetscFunctionBeginUser;
  *pb        = ImpactProblem();
  pb->comm   = comm;
  pb->method = method;
  if (ObliqueImpact(given)) PetscCall(ObliqueNormalScenario(comm, given, &pb->sc)); // F_n(t) along the normal first
  else pb->sc = given;
  const Scenario &sc = pb->sc;
  pb->times          = ImpactTimesOf(sc.beam, sc.ball, sc.impact);
  pb->needs_force    = RunStagesNeedForce(sc);
  if (method == ImpactMethod::ModalReference) { // its system is built in its own stage (run/modal_reference.cpp)
    pb->modal_used = true;
  } else {
    PetscCall(ProblemSystem(structure, pb));
    PetscCall(ImpactAfterResolve(comm, sc.impact, pb->sys(), &pb->after_modal));
    if (method == ImpactMethod::Stepped) PetscCall(TSTypeRead(&pb->ts_type));
    const bool ts_modal = method == ImpactMethod::Stepped && TSModalIsType(pb->ts_type.c_str());
    pb->modal_used      = ts_modal || sc.oblique.on || (pb->after_modal && pb->times.window > 0);
  }
  if (pb->modal_used) PetscCall(TruncationRead(*pb, &pb->truncation));
  // -modal_weight share: the modes weighed under this load (-ts_type modal's and the free flight's, one basis)
  if (method != ImpactMethod::ModalReference) pb->truncation.at = pb->g;
  PetscFunctionReturn(0);
}

StepperProblem ImpactProblemStepper(const ImpactProblem &pb, ContactState *contact)
{
  StepperProblem p;
  p.comm          = pb.comm;
  p.sys           = pb.system.get();
  p.g             = pb.g;
  p.ball          = pb.sc.ball;
  p.scales        = pb.scales;
  p.contact       = contact;
  p.beam_velocity = &pb.beam_velocity;
  p.frame         = &pb.frame;
  p.ts_type       = pb.ts_type;
  p.truncation    = pb.truncation;
  return p;
}

PetscErrorCode ImpactProblemNoteTruncation(const ImpactProblem &pb, ModalTruncation *t)
{
  PetscFunctionBeginUser;
  if (pb.modal_used) *t = ImpactProblemPlaneTruncation(pb);
  else PetscCall(TruncationRead(pb, t));
  PetscFunctionReturn(0);
}

ModalTruncation ImpactProblemPlaneTruncation(const ImpactProblem &pb)
{
  ModalTruncation t = pb.truncation;
  t.at              = ContactCoupling(); // no load: -modal_weight share weighs the normal plane's modes only
  return t;
}

} // namespace beamimpact

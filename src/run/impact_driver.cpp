// The impact driver: one phase loop for every stepper. It builds the scenario's system once,
// creates the stepper (PETSc TS, or the leapfrog baseline), steps it onto the stop time and
// the snapshot times, locates and applies every contact event, records what was asked, and
// measures the outcome.
//
//   loop: step -> did the step cross an event? -> locate it (events.cpp) -> apply it
//         (phase switch, stop time) -> restart the stepper if the force law changed
//   until `window` after the last separation (or -impact_max_time).
// After a separation, with -impact_after modal (the default where the beam allows it), the
// free vibration is not stepped: run/free_flight.cpp finds the next contact, if any, in closed
// form, and the stepper is put on the exact state there (and restarted) or at the window's end.
#include "run/events.hpp"
#include "run/free_flight.hpp"
#include "run/stage.hpp"
#include "run/impact.hpp"
#include "run/impact_problem.hpp"
#include "run/monitors.hpp"
#include "run/outcome.hpp"
#include "run/scenario.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/ts_stepper.hpp"

#include <cmath>
#include <memory>

namespace beamimpact {

namespace {

// The program's log stages, registered together on first use: the run's five, then one per
// stage after the contact (run/stage.hpp), in the registry's order.
const std::vector<std::pair<std::string, PetscLogStage>> &ImpactStageIds()
{
  static const std::vector<std::pair<std::string, PetscLogStage>> ids = [] {
    std::vector<std::string> names = {"beamimpact: set-up", "beamimpact: contact", "beamimpact: free flight",
                                      "beamimpact: output", "beamimpact: modal reference"};
    for (const RunStage *s : RunStages()) names.push_back(std::string("beamimpact: ") + s->Name());
    std::vector<std::pair<std::string, PetscLogStage>> v;
    for (const std::string &name : names) {
      PetscLogStage id = -1;
      (void)PetscLogStageRegister(name.c_str(), &id);
      v.push_back({name, id});
    }
    return v;
  }();
  return ids;
}

PetscInt free_flight_samples = 0; // ImpactFreeFlightSamples

} // namespace

PetscInt ImpactFreeFlightSamples() { return free_flight_samples; }

ImpactStageScope::~ImpactStageScope()
{
  if (pushed_) (void)PetscLogStagePop();
}

void ImpactStageScope::End()
{
  if (pushed_) (void)PetscLogStagePop();
  pushed_ = false;
}

void ImpactStageScope::Push(PetscLogStage id)
{
  if (pushed_ && id == id_) return;
  if (pushed_) (void)PetscLogStagePop();
  pushed_ = PetscLogStagePush(id) == 0;
  id_     = id;
}

void ImpactStageScope::Switch(ImpactStage s) { Push(ImpactStageIds()[static_cast<size_t>(s)].second); }

void ImpactStageScope::Switch(const char *name)
{
  for (const auto &e : ImpactStageIds())
    if (e.first.compare(0, 12, "beamimpact: ") == 0 && e.first.substr(12) == name) return Push(e.second);
}

namespace {

// What the measures of the run's state read: the problem's system, coupling, ball and frame,
// the run's contact phase.
MeasureContext RunMeasureContext(const ImpactProblem &pb, const ImpactRunState &run)
{
  return MeasureContext{&pb.sys(), &pb.g, &pb.sc.ball, &run.contact, &pb.frame};
}

// A located event applied; an error when contacts exceed -impact_max_contacts (chatter, or
// an integration gone wrong: the energy tells).
PetscErrorCode ApplyEvent(const ImpactProblem &pb, Stepper &st, ContactEventKind kind, ImpactRunState *run)
{
  const Scenario &sc = pb.sc;
  EventAt         at;
  bool            changed;

  PetscFunctionBeginUser;
  PetscCall(st.Compression(&at.c, &at.cdot));
  at.te              = st.Time();
  const PetscReal te = at.te, E0 = run->record.energy_in;
  PetscCall(ContactEventApply(pb, st.Method().c_str(), kind, at, run, &changed));
  if (kind == ContactEventKind::ContactStart && run->record.contact.contacts > sc.impact.max_contacts) {
    StateMeasures m;
    PetscCall(MeasureState(st, RunMeasureContext(pb, *run), nullptr, &m, nullptr));
    const PetscReal growth = (m.total() - E0) / E0;
    PetscCheck(growth <= sc.impact.energy_growth_tol, st.Comm(), PETSC_ERR_NOT_CONVERGED,
               "more than -impact_max_contacts %" PetscInt_FMT
               " separate contacts by t = %g s, and the energy has grown by %.3g of the incident kinetic energy: the "
               "integration is unstable or inaccurate (not a physical chatter); reduce %s",
               sc.impact.max_contacts, (double)te, (double)growth, st.StepOption().c_str());
    SETERRQ(st.Comm(), PETSC_ERR_NOT_CONVERGED,
            "more than -impact_max_contacts %" PetscInt_FMT
            " separate contacts by t = %g s: the ball is chattering on the beam",
            sc.impact.max_contacts, (double)te);
  }
  if (changed) PetscCall(st.Restart());
  PetscFunctionReturn(0);
}

// Whether the recorder follows peaks of a part of the structure (a wall, a string bed, the hands
// or a registered part's measures): then the series are sampled through a free flight.
bool SystemHasPeaks(const BeamSystem &sys)
{
  return !sys.face_fields.empty() || sys.TiedToFrame() || StructurePartsPeaks(sys);
}

// Whether the series is only an oblique impact's F_n (no monitor asked, no peaks of a wall, a
// string bed, the hands or a registered part to follow): not sampled through a free flight.
bool SparseSeries(const ImpactProblem &pb)
{
  return pb.needs_force && !pb.sc.monitor.any() && !SystemHasPeaks(pb.sys());
}

// The stepper at time t of the free flight ff (started at ff.t0): its own modes (in_modes: the
// modal state, O(k), expanded on this rank's rows when read), else the physical state; m and s
// are the caller's storage, kept over the samples.
PetscErrorCode FreeFlightSetAt(const FreeFlight &ff, bool in_modes, PetscReal t, Stepper &st, ModalState *m,
                               FullState *s)
{
  bool set = false;

  PetscFunctionBeginUser;
  if (in_modes) {
    FreeFlightModalState(ff, t - ff.t0, m);
    PetscCall(st.SetModalState(t, *ff.modes, *m, &set));
  }
  if (!set) {
    FreeFlightState(ff, t - ff.t0, s);
    PetscCall(st.SetState(t, *s));
  }
  PetscFunctionReturn(0);
}

// The free flight after a separation at the stepper's time, in closed form, up to t_stop (the
// window's end) or the next contact (*again): the stepper is left on the exact state there.
// With series monitors the state is recorded from the modes every dt_sample and at the
// snapshot times (so the outputs cover the same times as a stepped run). sparse: the series is
// only an oblique impact's F_n (no monitor asked): when no contact comes back it is recorded
// at the separation and one sample after it only (F_n is 0 from there to the window's end,
// where the driver records it: the tangential plane flies freely over that piece in closed form),
// not every dt_sample (4000 states rebuilt from the modes, which nobody keeps: issue 38's cost).
// run->record.mode_energies: the energy of each kept mode at t_stop when no contact comes back
// (else cleared: a later flight's count). The modes: the problem's truncation, once (run->modes).
PetscErrorCode FreeFlightAdvance(const ImpactProblem &pb, Stepper &st, ImpactRecorder &rec, PetscReal dt_sample,
                                 ImpactRunState *run, bool *again)
{
  const BeamSystem                 &sys    = pb.sys();
  const ContactCoupling            &g      = pb.g;
  const bool                        series = pb.sc.monitor.any() || pb.needs_force, sparse = SparseSeries(pb);
  const PetscReal                   t_stop = run->timeline.t_stop, s_min = 1e-13 * pb.scales.time;
  std::shared_ptr<const BeamModes> &modes = run->modes;
  FullState                         s0, s;
  FreeFlight                        ff;
  PetscReal                         root = 0, found = 0;
  *again = false;

  PetscFunctionBeginUser;
  if (!modes) PetscCall(BeamModesShared(st.Comm(), sys, pb.truncation, &modes));
  const PetscReal t0 = st.Time();
  ModalState      m0;
  bool            in_modes; // the stepper's own modes (-ts_type modal): no projection either way
  PetscCall(st.GetModalState(*modes, &m0, &in_modes));
  if (series) PetscCall(rec.Record(t0)); // the separation itself, as a stepped run records it
  if (in_modes) FreeFlightStartModal(modes, g, t0, m0, &ff);
  else {
    PetscCall(StepperGatherState(st, sys, &s0));
    FreeFlightStart(modes, g, t0, s0, &ff);
  }
  PetscReal pair[2] = {0, 0};
  if (FreeFlightFirstContact(ff, t_stop - t0, s_min, &root)) pair[0] = 1, pair[1] = root;
  PetscCallMPI(MPI_Bcast(pair, 2, MPIU_REAL, 0, st.Comm())); // one decision on every rank
  found                 = pair[0];
  root                  = pair[1];
  *again                = found != 0;
  const PetscReal t_end = *again ? t0 + root : t_stop;
  if (series || rec.NextSnapshot() < t_end) {
    const PetscReal dt     = series && dt_sample > 0 ? std::max(dt_sample, (t_end - t0) / 4000) : PETSC_INFINITY;
    const PetscInt  k_last = series && sparse && !*again ? 1 : PETSC_MAX_INT; // the samples recorded (snapshots apart)
    for (PetscInt k = 1;; ++k) {
      const PetscReal ts = k <= k_last ? t0 + k * dt : PETSC_INFINITY, tn = std::min(ts, rec.NextSnapshot());
      if (!(tn < t_end * (1 - 1e-14))) break;
      PetscCall(FreeFlightSetAt(ff, in_modes, tn, st, &m0, &s));
      free_flight_samples++;
      if (series) PetscCall(rec.Record(tn));
      PetscCall(rec.Snapshots(tn));
      if (tn < ts) --k; // a snapshot first: the sample is still due
    }
  }
  if (*again || !pb.sc.impact.mode_energies) run->record.mode_energies.clear(); // none, or nobody keeps them
  else run->record.mode_energies = FreeFlightModeEnergies(ff, t_end - t0);
  PetscCall(FreeFlightSetAt(ff, in_modes, t_end, st, &m0, &s));
  PetscCall(st.Restart());
  PetscFunctionReturn(0);
}

// The cost model of a stepped run (measured on the development machine, 2 cores, with
// fixed steps at -beam_nodes 2001 to 20001, docs/model.md "Cost"): wall time per step = per node x dofs,
// explicit types (rk, ...) kCostNodeStepExplicit, the others kCostNodeStepImplicit.
constexpr double kCostNodeStepExplicit = 6e-8; // s, rk 4: 5.9e-8 at N = 2001, 5.8e-8 at N = 4001
constexpr double kCostNodeStepImplicit = 1e-7; // s, cn (banded LU): 7.7e-8 at N = 2001, 9.6e-8 at N = 20001

// -ts_type modal on the same run at the default accuracy (the ACOR error of rk4 at its default
// step on the default grid, 1.5e-8; scripts/bench_defaults.sh, docs/model.md "Cost"): its
// default step T_r/200 meets it on every grid (1.4e-11 at N = 41, 7e-11 at N = 641: the beam's
// flow is exact, no stability limit), each step kCostModalDofStep per dof (1.8e-8 at N = 161,
// 1.6e-8 at N = 641), after the beam's modes at -modal_tolerance (the truncated engine's own
// time model, BeamModesExpectedSeconds: a partial solve of the modes below the cut-off, or the
// dense decomposition where it keeps more than a third), done once per beam: a sweep's points
// share them, and the free flight after the separation (-impact_after modal) computes the same
// modes anyway.
constexpr double kModalStepsPerTime = 200;    // steps per contact time scale T_r
constexpr double kCostModalDofStep  = 1.6e-8; // s

// An explicit type whose step the stability limit (~h^2) holds below the contact's own
// T_r/200 is said at set-up, with what -ts_type modal would take when it applies (a linear
// beam with proportional damping and no grip, within the dense decomposition's size) and is at
// least twice as fast: "rk's step is bound by h^2 ...".
PetscErrorCode ImpactStepBoundNote(const ImpactProblem &pb, const IntegratorInfo &info, PetscReal T, double seconds)
{
  const Scenario      &sc     = pb.sc;
  const BeamSystem    &sys    = pb.sys();
  const ContactScales &scales = pb.scales;
  ModalTruncation      t;

  PetscFunctionBeginUser;
  if (!(info.dt_stable > 0) || !(0.9 * info.dt_stable < scales.time / 200) || !BeamModesAvailable(sys, nullptr))
    PetscFunctionReturn(0);
  PetscCall(ImpactProblemNoteTruncation(pb, &t));
  const double dofs   = (double)sys.ndof;
  const double modes  = BeamModesExpectedSeconds(sys, t);
  const bool   anyway = sc.impact.after == ImpactAfter::Modal; // the free flight computes them too
  const double steps  = kModalStepsPerTime * (T / scales.time) * kCostModalDofStep * dofs;
  const double modal  = steps + (anyway ? 0 : modes);
  if (!(modal < 0.5 * seconds)) PetscFunctionReturn(0);
  PetscCall(
    PetscPrintf(pb.comm,
                "cost: -ts_type %s's step is bound by h^2: the stability limit dt_max = %.3g s at N = %" PetscInt_FMT
                " (the contact itself needs only T_r/200 = %.3g s): at least %.3g s of stepping%s; "
                "-ts_type modal takes %s in ~%.2g s at the same accuracy (%.0fx faster), after the beam's modes (~%.2g "
                "s, once per beam%s)\n",
                info.ts_type.c_str(), (double)info.dt_stable, sys.nodes, (double)(scales.time / 200), seconds,
                sc.impact.full_max_time != 0 ? " a point" : "",
                sc.impact.full_max_time != 0 ? "each point" : "this run", modal, seconds / modal, modes,
                anyway ? ": the free flight after the separation computes them too" : ", shared by a sweep's points"));
  PetscFunctionReturn(0);
}

// Before the run (-task impact, and a sweep's first point): the steps the run will take at
// least and their expected wall time, printed when above -impact_cost_warn, with what to
// change; and an explicit step bound by h^2 with the faster choice (ImpactStepBoundNote). The
// stepped time is the contact (T_r), and the window after it when the free flight is stepped
// too; the step is the fixed step, or an explicit adaptive type's stability limit (a bound:
// accuracy may ask for smaller steps); an implicit adaptive run has no estimate.
PetscErrorCode ImpactCostEstimate(const ImpactProblem &pb, const IntegratorInfo &info)
{
  const Scenario      &sc     = pb.sc;
  const BeamSystem    &sys    = pb.sys();
  const ContactScales &scales = pb.scales;

  PetscFunctionBeginUser;
  ImpactParams ip = sc.impact; // a probe (a sweep's 1 ns): the estimate is a whole point's
  if (ip.full_max_time != 0) ip.max_time = ip.full_max_time;
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, ip);
  const bool        modal = pb.after_modal;
  const PetscReal   T     = std::min<PetscReal>(times.max_time, modal ? scales.time : scales.time + times.window);
  const PetscReal   dt    = info.fixed_step ? info.dt_nominal : info.dt_stable;
  if (!(dt > 0) || sc.impact.cost_warn <= 0) PetscFunctionReturn(0);
  const bool   explicit_type = info.dt_stable > 0;
  const double steps         = T / dt;
  const double per_step      = (explicit_type ? kCostNodeStepExplicit : kCostNodeStepImplicit) * sys.nodes * sys.fields;
  const double seconds       = steps * per_step;
  if (explicit_type) PetscCall(ImpactStepBoundNote(pb, info, T, seconds));
  if (seconds <= sc.impact.cost_warn) PetscFunctionReturn(0);
  PetscCall(
    PetscPrintf(pb.comm,
                "cost: at least %.3g steps%s (%.3g s stepped / dt %.3g s, %s) on %" PetscInt_FMT
                " nodes: expected %.3g s of wall time (%.2g s a step); to shorten it: %s, fewer -beam_nodes%s%s\n",
                steps, ip.full_max_time != 0 ? " a point" : "", (double)T, (double)dt,
                info.fixed_step ? "-ts_dt" : "the explicit stability limit", sys.nodes, seconds, per_step,
                info.fixed_step ? "a larger -ts_dt" : "looser -ts_rtol/-ts_atol",
                explicit_type ? " (the explicit limit grows as h^2)" : "",
                explicit_type ? ", or an implicit -ts_type (cn, alpha2, bdf) or -ts_type modal, whose step is not "
                                "bound by the stability limit"
                              : ""));
  PetscFunctionReturn(0);
}

// The end of a run at time t: the contact still open (if any) closed, the final measures
// (refused when not finite), and the stepper's counts.
PetscErrorCode ImpactFinish(const ImpactProblem &pb, Stepper &st, const IntegratorInfo &info, PetscReal t,
                            ImpactRunState *run, ImpactCost *cost)
{
  const Scenario &sc  = pb.sc;
  ImpactRecord   *rec = &run->record;
  StateMeasures  &m1  = rec->end;
  PetscFunctionBeginUser;
  ContactTallyClose(run->contact.phase, run->timeline, t, &rec->contact);
  PetscCall(MeasureState(st, RunMeasureContext(pb, *run), nullptr, &m1, nullptr));
  PetscCheck(std::isfinite(m1.ball_v) && std::isfinite(m1.total()) && std::isfinite(m1.momentum) &&
               std::isfinite(m1.angular_momentum),
             st.Comm(), PETSC_ERR_FP,
             "the solution is not finite (NaN/Inf) at the end of the run, t = %g s, with %s: no result is reported; "
             "the step is unstable%s",
             (double)t, st.Method().c_str(), info.dt_stable > 0 ? " (explicit: keep dt below dt_max)" : "");
  rec->final_time = t;
  rec->energy_end = m1.total();
  if (sc.monitor.segment && sc.monitor.segment_until > 0)
    PetscCheck(t >= sc.monitor.segment_until * (1 - 1e-12), st.Comm(), PETSC_ERR_ARG_INCOMP,
               "-monitor_segment_until %g s is beyond the end of the run (%g s): raise -impact_window so the run lasts "
               "that long",
               (double)sc.monitor.segment_until, (double)t);
  PetscCall(st.Counts(cost));
  PetscFunctionReturn(0);
}

// The event indicators of the stepper's state: the compression and its rate, scaled; a state
// that is not finite stops the run, naming the method.
PetscErrorCode StateIndicators(Stepper &st, const ContactScales &scales, const IntegratorInfo &info, EventIndicators *g)
{
  PetscReal c, cd;

  PetscFunctionBeginUser;
  PetscCall(st.Compression(&c, &cd));
  PetscCheck(std::isfinite(c) && std::isfinite(cd), st.Comm(), PETSC_ERR_FP,
             "the solution is not finite (NaN/Inf) at t = %g s with %s: the step is unstable%s", (double)st.Time(),
             st.Method().c_str(), info.dt_stable > 0 ? " (explicit: keep dt below dt_max)" : "");
  g->c    = c / scales.compression;
  g->cdot = cd / scales.speed;
  PetscFunctionReturn(0);
}

// A long single impact's progress line, -impact_progress seconds of wall time apart (*last: the
// wall time of the last line).
PetscErrorCode ImpactProgressLine(MPI_Comm comm, const ImpactParams &ip, PetscReal t, PetscReal t_stop,
                                  const ImpactCost &cost, const ContactTally &tally, double wall0, double *last)
{
  PetscFunctionBeginUser;
  if (ip.report_setup && ip.progress > 0 && MPI_Wtime() - *last >= ip.progress) {
    *last = MPI_Wtime();
    PetscCall(PetscPrintf(comm,
                          "progress: t = %.4g s simulated (the run stops by %.4g s), %" PetscInt_FMT
                          " steps, %" PetscInt_FMT " contact(s), %.0f s of wall time\n",
                          (double)t, (double)t_stop, cost.steps + cost.event_steps, tally.contacts, *last - wall0));
  }
  PetscFunctionReturn(0);
}

// After a located event: the free flight that follows a separation (-impact_after modal) unless
// the window is already over (-impact_window 0: nothing to follow), and the contact it finds.
PetscErrorCode FreeFlightAfter(const ImpactProblem &pb, Stepper &st, ContactEventKind kind, ImpactRecorder &recorder,
                               ImpactStageScope &stage, ImpactRunState *run)
{
  PetscReal dt_sample;
  bool      again = false;

  PetscFunctionBeginUser;
  if (kind != ContactEventKind::Separation || !pb.after_modal || !(run->timeline.t_stop > st.Time() * (1 + 1e-14)))
    PetscFunctionReturn(0);
  PetscCall(st.NextStep(&dt_sample));
  stage.Switch(ImpactStage::FreeFlight);
  PetscCall(FreeFlightAdvance(pb, st, recorder, dt_sample, run, &again));
  if (again) PetscCall(ApplyEvent(pb, st, ContactEventKind::ContactStart, run));
  PetscFunctionReturn(0);
}

// Steps the stepper from t = 0 to the end of the run. run->contact is the contact state the
// stepper reads. The events and monitors write their records in run->record, the driver its
// steps and time in *cost; info: the stepper's settings (for messages).
PetscErrorCode ImpactDrive(const ImpactProblem &pb, Stepper &st, const IntegratorInfo &info, ImpactRunState *run,
                           ImpactCost *cost)
{
  const Scenario      &sc       = pb.sc;
  const ImpactParams  &ip       = sc.impact;
  const MeasureContext ctx      = RunMeasureContext(pb, *run);
  ImpactRecord        *rec      = &run->record;
  ContactTally        &tally    = rec->contact;
  ContactTimeline     &timeline = run->timeline;

  PetscFunctionBeginUser;
  PetscCall(MeasureState(st, ctx, nullptr, &rec->start, nullptr));
  rec->energy_in = rec->start.total();
  ImpactRecorder recorder(st, ctx, sc.monitor, ip, rec->energy_in, &rec->series, &rec->peaks,
                          pb.needs_force ? &rec->drive : nullptr);
  PetscCall(recorder.Record(0.0));
  PetscCall(recorder.Snapshots(0.0));
  auto         indicators = [&](EventIndicators *g) { return StateIndicators(st, pb.scales, info, g); };
  const double wall0      = MPI_Wtime();
  PetscReal    t          = 0;
  timeline.t_stop         = pb.times.max_time;
  EventIndicators g0, g1;
  PetscCall(indicators(&g0));
  ContactTallyStart(sc.ball, run->contact, pb.approach, &tally);
  rec->after_used = pb.after_modal ? "modal" : "time";
  ImpactStageScope stage(ImpactStage::Contact);
  double           last_progress = wall0;
  while (t < timeline.t_stop * (1 - 1e-14)) {
    PetscCall(ImpactProgressLine(st.Comm(), ip, t, timeline.t_stop, *cost, tally, wall0, &last_progress));
    const PetscReal target = std::min(timeline.t_stop, recorder.NextSnapshot()); // land exactly on both
    PetscReal       dt;
    stage.Switch(run->contact.phase != ContactPhase::Separated ? ImpactStage::Contact : ImpactStage::FreeFlight);
    PetscCall(st.NextStep(&dt));
    if (t + dt > target) dt = target - t;
    PetscCall(st.Step(dt));
    cost->steps++;
    PetscCall(indicators(&g1));
    const int ev = ContactCrossedEvent(run->contact.phase, g0, g1, ip.event_tol);
    if (ev >= 0) {
      const auto kind = static_cast<ContactEventKind>(ev);
      PetscCall(EventLocate(st, kind, t, ContactEventIndicator(kind, g0), ContactEventIndicator(kind, g1), ip.event_tol,
                            indicators, &cost->event_steps));
      PetscCall(ApplyEvent(pb, st, kind, run));
      PetscCall(FreeFlightAfter(pb, st, kind, recorder, stage, run));
      PetscCall(indicators(&g1));
    }
    t  = st.Time();
    g0 = g1;
    PetscCall(recorder.Record(t));
    PetscCall(recorder.Snapshots(t));
  }
  PetscCall(recorder.Flush()); // the samples' peaks
  cost->wall_time                        = MPI_Wtime() - wall0;
  std::shared_ptr<const BeamModes> modes = run->modes; // the free flight's
  if (modes && !rec->mode_energies.empty()) ModeEnergiesLabel(sc.beam, *modes, &rec->mode_energies);
  if (!modes) modes = st.Modes(); // no free flight: -ts_type modal's basis, if it is
  if (modes) rec->modal = {modes->Count(), modes->S.n, BeamModesCutoffHz(*modes)};
  PetscCall(ImpactFinish(pb, st, info, t, run, cost));
  PetscFunctionReturn(0);
}

// An oblique impact's run along the normal is over: the stages after it (run/stage.hpp: the
// tangential contact from its force, the exit, the flight), from the F_n(t) the run recorded for
// them (ImpactRecord::drive, then dropped).
PetscErrorCode ObliqueRunFinish(const ImpactProblem &pb, ImpactRecord *rec)
{
  StageInput in;

  PetscFunctionBeginUser;
  in.sc              = &pb.sc;
  in.series          = &rec->drive;
  in.u_n             = -rec->end.ball_v;
  in.beam.comm       = pb.comm;
  in.beam.sys        = &pb.sys();
  in.beam.g          = &pb.g;
  in.beam.truncation = ImpactProblemPlaneTruncation(pb);
  PetscCall(RunStagesRun(in, &rec->oblique));
  rec->drive = ImpactSeries();
  PetscFunctionReturn(0);
}

// Drives the stepper and hands what the run recorded to the outcome.
PetscErrorCode ImpactDriveAndFinish(const ImpactProblem &pb, Stepper &st, ImpactRunState *run, ImpactResult *res)
{
  ImpactRecord &rec = run->record;

  PetscFunctionBeginUser;
  PetscCall(ImpactDrive(pb, st, *res, run, res));
  if (pb.sc.oblique.on) PetscCall(ObliqueRunFinish(pb, &rec));
  rec.V_x    = pb.V_x;
  rec.scales = pb.scales;
  ImpactOutcomeFinish(pb.sc, pb.sys(), std::move(rec), res);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ImpactRun(MPI_Comm comm, const Scenario &given, ImpactResult *res)
{
  PetscFunctionBeginUser;
  PetscCall(ImpactRun(comm, given, res, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactRun(MPI_Comm comm, const Scenario &given, ImpactResult *res, ImpactStructure *structure)
{
  ImpactProblem            pb;
  ImpactRunState           run; // run.contact: touching, loading, the phase the stepper's force law reads
  std::unique_ptr<Stepper> st;
  TSStepperSettings        set;

  PetscFunctionBeginUser;
  *res = ImpactResult();
  ImpactStageScope stage(ImpactStage::Setup);
  PetscCall(ImpactProblemBuild(comm, given, ImpactMethod::Stepped, structure, &pb));
  const ImpactParams &ip = pb.sc.impact;
  ContactBegin(pb.sc.ball, &run.contact, pb.approach); // the first contact's law state (its exponent)
  set.check_unused_options  = ip.check_unused_options;
  set.report_setup          = ip.report_setup;
  set.strict_solver_options = ip.strict_solver_options;
  set.context_key           = structure ? &structure->stepper_key : nullptr;
  PetscCall(TSStepperCreate(ImpactProblemStepper(pb, &run.contact), set, &st, res));
  stage.End(); // ImpactDrive holds the contact and free-flight stages
  if (ip.report_setup) PetscCall(ImpactCostEstimate(pb, *res));
  PetscCall(ImpactDriveAndFinish(pb, *st, &run, res));
  PetscFunctionReturn(0);
}

PetscErrorCode LeapfrogRun(const Scenario &given, const LeapfrogParams &lp, ImpactResult *res)
{
  ImpactProblem            pb;
  ImpactRunState           run; // run.contact: touching, loading, the phase the stepper's force law reads
  std::unique_ptr<Stepper> st;

  PetscFunctionBeginUser;
  *res = ImpactResult();
  PetscCall(ImpactProblemBuild(PETSC_COMM_SELF, given, ImpactMethod::Leapfrog, nullptr, &pb));
  ContactBegin(pb.sc.ball, &run.contact, pb.approach); // the first contact's law state (its exponent)
  PetscCall(LeapfrogStepperCreate(ImpactProblemStepper(pb, &run.contact), lp, &st, res));
  PetscCall(ImpactDriveAndFinish(pb, *st, &run, res));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The exact modal reference of one impact. See modal_reference.hpp.
#include "run/modal_reference.hpp"

#include "base/memory.hpp"
#include "run/impact.hpp"
#include "run/stage.hpp"
#include "run/outcome.hpp"

#include "run/scenario.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/modal_basis.hpp"
#include "solvers/modal_damped.hpp"

#include <petscblaslapack.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <utility>

namespace beamimpact {

namespace {

// The exact solution as it advances: time, free-dof displacements and velocities (the ball
// last), and the fixed data of the run.
struct ModalRun {
  const ModalSystem *S     = nullptr;
  const BallParams  *ball  = nullptr;
  PetscReal          t_cap = 0, s_min = 0; // s: -impact_max_time; the smallest search step
  PetscReal c_scale = 1; // the compression per unit of g^T q: k'/k for a truncated system (the series spring), else 1
  PetscReal t       = 0;
  std::vector<PetscReal> q, qd;
  ImpactSeries *forces = nullptr; // an oblique impact's run along the normal: F_n(t) sampled in each contact phase
};

// The samples of F_n(t) and dF_n/dt a contact phase gives an oblique impact's tangential contact
// (run/oblique.hpp), which takes the cubic Hermite of both between samples: an error of order
// kForceSamples^-4 in the tangential outputs (about 1e-13 relative at 20000; docs/model.md
// section 13 and docs/convergence.md give it measured).
constexpr PetscInt kForceSamples = 20000;

// F_n = k c and its rate k dc/dt at kForceSamples equal pieces of the contact phase [0, s_sep] of
// the exact solution (the rates at both ends from inside the contact).
template <class Phase>
void ModalSampleForce(const ModalRun &run, const Phase &ph, PetscReal s_sep)
{
  if (!run.forces) return;
  ImpactSeries   &f = *run.forces;
  const PetscReal k = ContactLinearStiffness(*run.ball) * run.c_scale;
  for (PetscInt i = 0; i <= kForceSamples; ++i) {
    const PetscReal s = s_sep * (PetscReal)i / (PetscReal)kForceSamples, t = run.t + s;
    if (!f.time.empty() && !(t > f.time.back())) continue;
    f.time.push_back(t);
    f.force.push_back(i == 0 || i == kForceSamples ? 0.0 : std::max<PetscReal>(0, k * ph.Derivative(s, 0)));
    f.force_rate.push_back(k * ph.Derivative(s, 1));
  }
}

// Energy (J) of the state: kinetic (beam and ball), strain, and the spring's in contact.
PetscReal ModalEnergy(const ModalSystem &S, const std::vector<PetscReal> &q, const std::vector<PetscReal> &qd,
                      bool in_contact)
{
  const BeamSystem      &sys = *S.sys;
  std::vector<PetscReal> shape(sys.ndof, 0.0);
  PetscReal              T = 0, c = 0;
  for (PetscInt d = 0; d < S.n; ++d) {
    T += 0.5 * S.mass[d] * qd[d] * qd[d];
    c += S.g[d] * q[d];
    if (S.dof[d] >= 0) shape[S.dof[d]] = q[d];
  }
  return T + BeamSystemStrainEnergy(sys, shape.data(), sys.fields, 0, sys.ndof) +
         (in_contact ? 0.5 * S.k * c * c : 0.0);
}

// The maximum compressions of a contact phase: dc/dt falling through 0 before the separation
// at s_sep, each followed by a skip to where dc/dt rises again (a local minimum).
template <class Phase>
void ModalMaxCompressions(const ModalRun &run, const Phase &ph, PetscReal s_sep, ContactTally *tally)
{
  PetscReal s    = 0, s_max;
  Phase     rate = ph;
  while (ModalFirstCrossing(rate, 1, +1.0, s_sep - s, run.s_min, &s_max)) {
    s += s_max;
    const PetscReal c = run.c_scale * ph.Derivative(s, 0);
    tally->events.push_back({ContactEventKind::MaxCompression, run.t + s, c, ContactLinearStiffness(*run.ball) * c});
    tally->max_compression = std::max(tally->max_compression, c);
    // Continue after this maximum: restart the search from the state at s.
    std::vector<PetscReal> qs, qds;
    ph.State(s, qs, qds);
    rate.From(qs, qds);
    PetscReal s_min_c;
    if (!ModalFirstCrossing(rate, 1, -1.0, s_sep - s, run.s_min, &s_min_c)) break;
    s += s_min_c;
    ph.State(s, qs, qds);
    rate.From(qs, qds);
  }
}

// A contact phase from run.t to the separation (c falling through 0).
template <class Phase>
PetscErrorCode ModalContactPhase(ModalRun &run, const Phase &ph, ContactTally *tally)
{
  PetscReal s_sep;

  PetscFunctionBeginUser;
  PetscCheck(ModalFirstCrossing(ph, 0, +1.0, run.t_cap - run.t, run.s_min, &s_sep), PETSC_COMM_SELF,
             PETSC_ERR_NOT_CONVERGED, "modal reference: the ball is still in contact at -impact_max_time %g s",
             (double)run.t_cap);
  ModalMaxCompressions(run, ph, s_sep, tally);
  ModalSampleForce(run, ph, s_sep);
  ph.State(s_sep, run.q, run.qd);
  run.t += s_sep;
  tally->events.push_back({ContactEventKind::Separation, run.t, 0.0, 0.0});
  PetscFunctionReturn(0);
}

// A separated phase from run.t to the next contact (c rising through 0) or to t_stop, the end
// of the window after the separation; *contact tells which.
PetscErrorCode ModalFreePhase(ModalRun &run, const ModalPhase &ph, PetscReal t_stop, PetscInt max_contacts,
                              ContactTally *tally, bool *contact)
{
  PetscReal s_con;

  PetscFunctionBeginUser;
  *contact = ModalFirstCrossing(ph, 0, -1.0, t_stop - run.t, run.s_min, &s_con);
  if (!*contact) {
    ph.State(t_stop - run.t, run.q, run.qd);
    run.t = t_stop;
    PetscFunctionReturn(0);
  }
  ph.State(s_con, run.q, run.qd);
  run.t += s_con;
  tally->contacts++;
  PetscCheck(tally->contacts <= max_contacts, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED,
             "modal reference: more than -impact_max_contacts %" PetscInt_FMT " contacts", max_contacts);
  tally->events.push_back({ContactEventKind::ContactStart, run.t, 0.0, 0.0});
  PetscFunctionReturn(0);
}

// The contact times and the peak force from the events.
void ModalTallyClose(const BallParams &ball, ContactTally *tally)
{
  PetscReal start = 0;
  bool      first = true;
  for (const ContactEvent &e : tally->events) {
    if (e.kind == ContactEventKind::ContactStart) start = e.time;
    if (e.kind == ContactEventKind::Separation) {
      if (first) tally->contact_time = e.time - start;
      first = false;
      tally->contact_time_total += e.time - start;
    }
  }
  tally->peak_force = ContactLinearStiffness(ball) * tally->max_compression;
}

// The measures of the state (separated; the linear spring stores nothing then) as a stepper's
// are taken (run/measures.cpp): energies, momenta about x = 0 (a Timoshenko section's spin
// included), and D, the energy the beam's damping dissipated.
StateMeasures ModalMeasures(const ModalRun &run, PetscReal x_imp, PetscReal z_imp, PetscReal D)
{
  const ModalSystem     &S    = *run.S;
  const BeamSystem      &sys  = *S.sys;
  const BallParams      &ball = *run.ball;
  std::vector<PetscReal> shape(sys.ndof, 0.0), rate(sys.ndof, 0.0);
  StateMeasures          m;
  PetscReal              p = 0, l = 0, r = 0;
  const PetscInt         roll = sys.RollField();
  for (PetscInt d = 0; d + 1 < S.n; ++d) {
    shape[S.dof[d]]    = run.q[d];
    rate[S.dof[d]]     = run.qd[d];
    const PetscInt dof = S.dof[d], f = dof % sys.fields, node = dof / sys.fields;
    if (sys.Deflection(f)) {
      p += S.mass[d] * run.qd[d];
      l += S.mass[d] * sys.NodeX(node) * run.qd[d];
      r += S.mass[d] * sys.DofZ(dof) * run.qd[d];
      if (sys.Face(f)) { // a part's deflections across the face: its account's share
        PetscReal *own = m.account_momentum[sys.AccountOf(f)];
        own[0] += S.mass[d] * run.qd[d], own[1] += S.mass[d] * sys.NodeX(node) * run.qd[d],
          own[2] += S.mass[d] * sys.DofZ(dof) * run.qd[d];
      }
    } else if (sys.Rotation(f)) l += S.mass[d] * run.qd[d];
    else if (f == roll) r += S.mass[d] * run.qd[d];
  }
  if (!sys.parts.empty()) { // the registered parts: their rigid points' momenta, their slots
    for (const RigidPoint &pt : sys.rigid_points)
      if (!sys.held[pt.dof]) p += sys.mass[pt.dof] * rate[pt.dof], l += sys.mass[pt.dof] * pt.x * rate[pt.dof];
    PartState ps;
    ps.y = shape.data(), ps.v = rate.data(), ps.ys = ps.vs = sys.fields, ps.d0 = 0, ps.d1 = sys.ndof;
    StructurePartsMeasure(sys, ps, m.part_slot);
  }
  m.ball_y       = run.q[S.n - 1];
  m.ball_v       = run.qd[S.n - 1];
  m.ball_kinetic = 0.5 * ball.mass * m.ball_v * m.ball_v;
  PetscReal stored[kMaxAccounts], kinetic[kMaxAccounts]; // each account's, as run/measures.cpp keeps them
  BeamSystemAccountEnergies(sys, shape.data(), sys.fields, rate.data(), sys.fields, 0, sys.ndof, stored, kinetic);
  m.beam_kinetic = m.beam_strain = 0;
  for (PetscInt a = 0; a < StructureAccountCount(); ++a) // an account apart (the wall's): not the beam's
    if (StructureAccountApart(a)) m.apart_energy += stored[a] + kinetic[a];
    else m.beam_kinetic += kinetic[a], m.beam_strain += stored[a];
  for (PetscInt a = 1; a < StructureAccountCount(); ++a) m.account_energy[a] = stored[a] + kinetic[a];
  for (PetscInt d = 0; d < S.BeamDofs(); ++d) // the wall's share of the compression (S.g = dc/dq = -w)
    if (StructureAccountApart(sys.AccountOf(S.dof[d] % sys.fields))) m.apart_deflection -= S.g[d] * run.q[d];
  if (!sys.face_fields.empty())
    for (PetscInt d = 0; d < sys.ndof; ++d) {
      const PetscInt f = d % sys.fields, i = d / sys.fields;
      if (!sys.Face(f) || sys.held[d]) continue;
      const PetscReal phi = roll >= 0 ? shape[sys.Dof(i, roll)] : 0.0;
      m.face_deflection   = std::max(m.face_deflection, std::abs(shape[d] - shape[sys.Dof(i)] - sys.DofZ(d) * phi));
    }
  m.beam_momentum    = p;
  m.beam_moment      = l;
  m.momentum         = p + ball.mass * m.ball_v;
  m.angular_momentum = l + ball.mass * x_imp * m.ball_v;
  m.beam_roll        = r;
  m.roll_momentum    = r + ball.mass * z_imp * m.ball_v;
  m.beam_dissipated  = D;
  return m;
}

} // namespace

static PetscInt ModalReferenceFreeDofs(const BeamSystem &sys)
{
  PetscInt n = 0;
  for (PetscInt d = 0; d < sys.ndof; ++d) n += sys.held[d] ? 0 : 1;
  return n;
}

bool ModalReferenceApplies(const Scenario &sc, std::string *why)
{
  std::string w;
  if (!StructurePartsModalRefusal(sc.beam).empty()) w = StructurePartsModalRefusal(sc.beam);
  else if (!ContactLinear(sc.ball))
    w = std::string("needs -ball_law linear (the ") + ContactLawName(sc.ball.law) +
        " law is nonlinear: use a tight run of a high-order integrator as the reference)";
  if (why) *why = w;
  return w.empty();
}

namespace {

// The run's start: the ball at v_i, a swinging bat's rigid motion; *V_x the bat's speed toward
// the ball at the impact point, *E0 the total energy (J).
void ModalStart(const Scenario &sc, const BeamSystem &sys, ModalRun *run, PetscReal *V_x, PetscReal *E0)
{
  const ModalSystem &S    = *run->S;
  const BallParams  &ball = sc.ball;
  run->q.assign(S.n, 0.0);
  run->qd.assign(S.n, 0.0);
  run->qd[S.n - 1] = ball.speed;
  *V_x             = 0;
  if (sc.swing.Swings()) {
    const BeamRigidBody          body = BeamRigidBodyOf(sc.beam);
    const std::vector<PetscReal> v0   = BeamSystemSwingVelocity(sys, sc.swing, body);
    for (PetscInt d = 0; d + 1 < S.n; ++d) run->qd[d] = v0[S.dof[d]];
    *V_x = SwingSpeedAt(sc.swing, body, sc.impact.x);
  }
  *E0 = sc.swing.Swings() ? ModalEnergy(S, run->q, run->qd, false) : 0.5 * ball.mass * ball.speed * ball.speed;
}

// What the run hands the outcome at its end (D: dissipated by the beam's damping, J).
void ModalFinish(const Scenario &sc, const BeamSystem &sys, const ModalRun &run, PetscReal E0, PetscReal D,
                 PetscReal V_x, ImpactRecord *rec)
{
  ModalTallyClose(sc.ball, &rec->contact);
  rec->end               = ModalMeasures(run, sc.impact.x, sc.impact.z, D);
  rec->energy_in         = E0;
  rec->energy_end        = ModalEnergy(*run.S, run.q, run.qd, false) + D;
  rec->final_time        = run.t;
  rec->V_x               = V_x;
  BallParams approaching = sc.ball; // the contact's scales are those of the approach speed, as for a stepped run
  approaching.speed      = sc.ball.speed + V_x;
  rec->scales            = ContactScalesOf(sys, approaching);
}

// An oblique impact (sc: its run along the normal, sc.oblique.on): the stages after the contact
// (run/stage.hpp: the tangential contact driven by the sampled F_n(t), the bat's second plane in
// the modes of `truncation`, the exit, the flight), as a stepped run finishes it
// (run/impact_driver.cpp); the samples are then dropped.
PetscErrorCode ModalObliqueFinish(MPI_Comm comm, const Scenario &sc, const BeamSystem &sys,
                                  const ModalTruncation &truncation, ImpactRecord *rec)
{
  StageInput in;

  PetscFunctionBeginUser;
  if (!sc.oblique.on) PetscFunctionReturn(0);
  const ContactCoupling g = BeamSystemCoupling(sys, sc.impact.x, sc.impact.z);
  in.sc                   = &sc;
  in.series               = &rec->drive;
  in.u_n                  = -rec->end.ball_v;
  in.beam.comm            = comm; // the modes of the second plane on the reference's ranks
  in.beam.sys             = &sys;
  in.beam.g               = &g;
  in.beam.truncation      = truncation;
  if (!(in.beam.truncation.contact_time > 0))
    in.beam.truncation.contact_time = ContactTimeScale(sc.ball, ImpactApproachSpeed(sc));
  PetscCall(RunStagesRun(in, &rec->oblique));
  rec->drive = ImpactSeries();
  PetscFunctionReturn(0);
}

} // namespace

namespace {

PetscErrorCode ModalReferenceDense(MPI_Comm comm, const Scenario &sc, const BeamSystem &sys,
                                   const ModalTruncation &truncation, ImpactResult *res);

// The truncated system (docs/model.md §12): the kept beam modes z_j (mass-normalised: mass 1,
// stiffness w_j^2) and the ball, with c = y_b - sum_j gamma_j z_j, in contact through the series
// spring k' = k / (1 + k G_r) of the contact spring and the modes left out (their static
// flexibility G_r at the point); the compression itself is c k'/k. Its phases' bases: separated,
// diagonal; in contact, the dense eigen-decomposition (LAPACK syev) of the (kept + 1) system.
struct TruncatedSystem {
  ModalSystem R; // over (z_1 .. z_k, y_b): mass 1 .. 1, m_b; g = (-gamma, 1); k'
  ModalBasis  contact, free;
  PetscReal   c_scale = 1; // k'/k
};

// gamma_j = sum_q w_q phi_j(d_q) / sqrt(m_{d_q}): mode j's deflection at the point of coupling g.
std::vector<PetscReal> ModeGammas(const BeamModes &m, const ContactCoupling &g)
{
  const PetscInt         n = m.S.n, nm = m.Count();
  std::vector<PetscReal> gw(n, 0.0), gamma(nm, 0.0);
  for (PetscInt d = 0; d < n; ++d)
    for (PetscInt q = 0; q < g.n; ++q)
      if (m.S.dof[d] == g.dof[q]) gw[d] += g.w[q] / std::sqrt(m.S.mass[d]);
  for (PetscInt j = 0; j < nm; ++j)
    for (PetscInt d = 0; d < n; ++d) gamma[j] += m.B.Phi[(size_t)j * n + d] * gw[d];
  return gamma;
}

PetscErrorCode TruncatedSystemBuild(const BeamModes &m, const ModalCorrection &corr, const BallParams &ball,
                                    TruncatedSystem *T)
{
  const PetscInt               nm = m.Count(), n = nm + 1;
  const std::vector<PetscReal> gamma = ModeGammas(m, corr.g);
  const PetscReal              k = ContactLinearStiffness(ball), kp = k / (1 + k * corr.Gr);
  ModalSystem                 &R = T->R;

  PetscFunctionBeginUser;
  R.sys  = &m.sys;
  R.n    = n;
  R.k    = kp;
  R.ball = true;
  R.dof.assign(n, -1);
  R.mass.assign(n, 1.0);
  R.mass[nm] = ball.mass;
  R.g.assign(n, 1.0);
  for (PetscInt j = 0; j < nm; ++j) R.g[j] = -gamma[j];
  T->c_scale = kp / k;
  // Separated: the modes themselves and the ball (rigid).
  T->free.omega.assign(m.B.omega.begin(), m.B.omega.end());
  T->free.omega.push_back(0.0);
  T->free.Phi.assign((size_t)n * n, 0.0);
  for (PetscInt j = 0; j < n; ++j) T->free.Phi[j + (size_t)j * n] = 1.0;
  // In contact: M^{-1/2} (diag(w^2, 0) + k' g g^T) M^{-1/2}.
  std::vector<PetscReal> A((size_t)n * n), w(n), gs(n);
  for (PetscInt r = 0; r < n; ++r) gs[r] = R.g[r] / std::sqrt(R.mass[r]);
  for (PetscInt c = 0; c < n; ++c)
    for (PetscInt r = 0; r < n; ++r)
      A[r + (size_t)c * n] = kp * gs[r] * gs[c] + (r == c && r < nm ? m.B.omega[r] * m.B.omega[r] : 0.0);
  PetscBLASInt bn, lwork = -1, info;
  PetscReal    wq;
  PetscCall(PetscBLASIntCast(n, &bn));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "U", &bn, A.data(), &bn, w.data(), &wq, &lwork, &info));
  std::vector<PetscReal> work((size_t)wq);
  PetscCall(PetscBLASIntCast((PetscInt)wq, &lwork));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "U", &bn, A.data(), &bn, w.data(), work.data(), &lwork, &info));
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK syev failed (info %d)", (int)info);
  T->contact.omega.resize(n);
  for (PetscInt j = 0; j < n; ++j) T->contact.omega[j] = std::sqrt(std::max<PetscReal>(w[j], 0.0));
  T->contact.Phi = std::move(A);
  for (ModalBasis *B : {&T->contact, &T->free}) {
    B->gamma.assign(n, 0.0);
    for (PetscInt j = 0; j < n; ++j)
      for (PetscInt r = 0; r < n; ++r) B->gamma[j] += gs[r] * B->Phi[r + (size_t)j * n];
  }
  PetscFunctionReturn(0);
}

// Between the truncated state (z, zd; the ball last) and the full one (free beam dofs, the ball
// last, as ModalSystemBuild orders them): y = M^{-1/2} Phi z, z = Phi^T M^{1/2} y.
void TruncatedToFull(const BeamModes &m, const std::vector<PetscReal> &z, std::vector<PetscReal> &q)
{
  const PetscInt n = m.S.n, nm = m.Count();
  q.assign(n + 1, 0.0);
  for (PetscInt j = 0; j < nm; ++j)
    for (PetscInt d = 0; d < n; ++d) q[d] += m.B.Phi[(size_t)j * n + d] * z[j];
  for (PetscInt d = 0; d < n; ++d) q[d] /= std::sqrt(m.S.mass[d]);
  q[n] = z[nm];
}
void FullToTruncated(const BeamModes &m, const std::vector<PetscReal> &q, std::vector<PetscReal> &z)
{
  const PetscInt n = m.S.n, nm = m.Count();
  z.assign(nm + 1, 0.0);
  for (PetscInt j = 0; j < nm; ++j)
    for (PetscInt d = 0; d < n; ++d) z[j] += m.B.Phi[(size_t)j * n + d] * std::sqrt(m.S.mass[d]) * q[d];
  z[nm] = q[n];
}

// The undamped phases of a truncated run, contact first, to the end of the window after the
// last separation.
PetscErrorCode TruncatedPhases(ModalRun &run, const TruncatedSystem &T, const ImpactTimes &times, PetscInt max_contacts,
                               ContactTally *tally)
{
  ModalPhase ph;
  bool       touching = true;

  PetscFunctionBeginUser;
  ph.S = &T.R;
  for (bool more = true; more;) {
    ph.B = touching ? &T.contact : &T.free;
    ph.From(run.q, run.qd);
    if (touching) {
      PetscCall(ModalContactPhase(run, ph, tally));
      touching = false;
    } else {
      PetscCall(ModalFreePhase(run, ph, std::min(run.t_cap, run.t + times.window), max_contacts, tally, &touching));
      more = touching;
    }
  }
  PetscFunctionReturn(0);
}

// The reference on the modes kept (m truncated, the beam undamped): the same events and
// outcome as the dense one, the state carried in the kept modes and the ball.
PetscErrorCode ModalReferenceTruncated(MPI_Comm comm, const Scenario &sc, const BeamSystem &sys, const BeamModes &m,
                                       const ModalTruncation &truncation, ImpactResult *res)
{
  const ImpactParams    &ip = sc.impact;
  const ModalCorrection *corr;
  TruncatedSystem        T;
  ModalRun               full, run;
  ImpactRecord           rec;
  PetscReal              V_x, E0;

  PetscFunctionBeginUser;
  const double wall0 = MPI_Wtime();
  PetscCall(m.StaticCorrection(BeamSystemCoupling(sys, ip.x, ip.z), &corr));
  PetscCall(TruncatedSystemBuild(m, *corr, sc.ball, &T));
  const ModalSystem S = ModalSystemBuild(sys, corr->g, sc.ball.mass,
                                         ContactLinearStiffness(sc.ball)); // the full state's layout
  full.S = &S, full.ball = &sc.ball;
  ModalStart(sc, sys, &full, &V_x, &E0);
  rec.start               = ModalMeasures(full, ip.x, ip.z, 0);
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, ip);
  run.S = &T.R, run.ball = &sc.ball, run.c_scale = T.c_scale;
  run.t_cap = times.max_time;
  run.s_min = 1e-13 * ContactTimeScale(sc.ball, ImpactApproachSpeed(sc));
  if (sc.oblique.on) run.forces = &rec.drive;
  FullToTruncated(m, full.q, run.q);
  FullToTruncated(m, full.qd, run.qd);
  rec.contact.contacts = 1;
  rec.contact.events.push_back({ContactEventKind::ContactStart, 0.0, 0.0, 0.0});
  PetscCall(TruncatedPhases(run, T, times, ip.max_contacts, &rec.contact));
  TruncatedToFull(m, run.q, full.q);
  TruncatedToFull(m, run.qd, full.qd);
  full.t = run.t;
  ModalFinish(sc, sys, full, E0, 0, V_x, &rec);
  PetscCall(ModalObliqueFinish(comm, sc, sys, truncation, &rec));
  rec.after_used   = "modal";
  rec.modal        = {m.Count(), m.S.n, BeamModesCutoffHz(m)};
  *res             = ImpactResult();
  res->ts_type     = "modal";
  res->formulation = "exact, truncated";
  ImpactOutcomeFinish(sc, sys, std::move(rec), res);
  res->wall_time = MPI_Wtime() - wall0;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ModalReferenceRunSystem(MPI_Comm comm, const Scenario &sc, const BeamSystem &sys,
                                       const ModalTruncation &truncation, ImpactResult *res)
{
  std::shared_ptr<const BeamModes> modes;
  ModalTruncation                  t = truncation;
  std::string                      why;

  PetscFunctionBeginUser;
  PetscCheck(ModalReferenceApplies(sc, &why), PETSC_COMM_SELF, PETSC_ERR_SUP, "-reference modal %s", why.c_str());
  if (t.modes != ModalModes::All &&
      !sys.Damped()) { // a damped beam: every mode (its contact phases are the first-order modes')
    if (!(t.contact_time > 0))
      t.contact_time = ContactTimeScale(sc.ball,
                                        ImpactApproachSpeed(sc)); // as -ts_type modal and the free flight take it
    PetscCall(BeamModesShared(comm, sys, t, &modes));
  }
  if (modes && modes->truncated) PetscCall(ModalReferenceTruncated(comm, sc, sys, *modes, t, res));
  else PetscCall(ModalReferenceDense(comm, sc, sys, t, res)); // every mode kept: the dense reference
  PetscFunctionReturn(0);
}

PetscErrorCode ModalReferenceRunSystem(const Scenario &sc, const BeamSystem &sys, ImpactResult *res)
{
  ModalTruncation all;

  PetscFunctionBeginUser;
  all.modes = ModalModes::All;
  PetscCall(ModalReferenceDense(PETSC_COMM_SELF, sc, sys, all, res));
  PetscFunctionReturn(0);
}

namespace {

// The dense reference (every mode; a damped beam's first-order modes in contact); an oblique
// impact's second plane in the modes of `truncation`.
PetscErrorCode ModalReferenceDense(MPI_Comm comm, const Scenario &sc, const BeamSystem &sys,
                                   const ModalTruncation &truncation, ImpactResult *res)
{
  const BallParams   &ball = sc.ball;
  const ImpactParams &ip   = sc.impact;
  ModalBasis          contact_basis, free_basis;
  ModalRun            run;
  ModalPhase          ph;
  ImpactRecord        rec;
  bool                touching = true;
  std::string         why;

  PetscFunctionBeginUser;
  PetscCheck(ModalReferenceApplies(sc, &why), PETSC_COMM_SELF, PETSC_ERR_SUP, "-reference modal %s", why.c_str());
  const double need = ModalReferenceMemory(sys), limit = ModalReferenceMemoryLimit();
  PetscCheck(need <= limit, PETSC_COMM_SELF, PETSC_ERR_MEM,
             "-reference modal with N = %" PetscInt_FMT " nodes (%" PetscInt_FMT
             " free dofs) would need about %.3g GB for its dense %s matrices, above the limit of %.3g GB "
             "(-reference_max_memory, default half of the physical memory); reduce -beam_nodes, or use a tight TS run "
             "as the reference",
             sys.nodes, ModalReferenceFreeDofs(sys), need / 1e9, sys.Damped() ? "damped first-order" : "modal",
             limit / 1e9);
  const double wall0 = MPI_Wtime();
  *res               = ImpactResult();
  res->ts_type       = "modal";
  res->formulation   = "exact";
  rec.after_used     = "modal"; // exact throughout
  ModalSystem S = ModalSystemBuild(sys, BeamSystemCoupling(sys, ip.x, ip.z), ball.mass, ContactLinearStiffness(ball));
  S.mirror      = truncation.mirror;
  // A damped beam: the contact phases in the damped first-order modes (solvers/modal_damped.hpp),
  // which also give the dissipated energy of every phase exactly.
  const bool       damped = sys.Damped();
  ModalDampedBasis damped_contact, damped_free;
  PetscReal        D = 0, V_x, E0;
  if (damped) {
    PetscCall(ModalDampedBasisBuild(S, true, &damped_contact));
    PetscCall(ModalDampedBasisBuild(S, false, &damped_free));
  } else PetscCall(ModalBasisBuild(S, true, &contact_basis, truncation.refine_all));
  PetscCall(ModalBasisBuild(S, false, &free_basis, truncation.refine_all));

  const ImpactTimes times = ImpactTimesOf(sc.beam, ball, ip);
  run.S                   = &S;
  run.ball                = &ball;
  run.t_cap               = times.max_time;
  run.s_min               = 1e-13 * ContactTimeScale(ball, ImpactApproachSpeed(sc));
  if (sc.oblique.on) run.forces = &rec.drive;
  ModalStart(sc, sys, &run, &V_x, &E0);
  rec.start            = ModalMeasures(run, ip.x, ip.z, 0);
  rec.contact.contacts = 1;
  rec.contact.events.push_back({ContactEventKind::ContactStart, 0.0, 0.0, 0.0});
  for (bool more = true; more;) {
    const PetscReal  t0 = run.t;
    ModalDampedPhase dph;
    if (damped) {
      dph.S = &S;
      dph.B = touching ? &damped_contact : &damped_free;
      dph.From(run.q, run.qd);
    }
    ph.S = &S;
    ph.B = touching ? &contact_basis : &free_basis;
    if (!(damped && touching)) ph.From(run.q, run.qd);
    if (touching) {
      if (damped) PetscCall(ModalContactPhase(run, dph, &rec.contact));
      else PetscCall(ModalContactPhase(run, ph, &rec.contact));
      touching = false;
    } else {
      PetscCall(
        ModalFreePhase(run, ph, std::min(run.t_cap, run.t + times.window), ip.max_contacts, &rec.contact, &touching));
      more = touching;
    }
    if (damped) D += dph.Dissipated(run.t - t0);
  }
  ModalFinish(sc, sys, run, E0, D, V_x, &rec);
  PetscCall(ModalObliqueFinish(comm, sc, sys, truncation, &rec));
  ImpactOutcomeFinish(sc, sys, std::move(rec), res);
  res->wall_time = MPI_Wtime() - wall0;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode ModalReferenceRun(const Scenario &sc, ImpactResult *res)
{
  ModalTruncation all;

  PetscFunctionBeginUser;
  all.modes = ModalModes::All;
  PetscCall(ModalReferenceRun(sc, all, res));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalReferenceRun(const Scenario &sc, const ModalTruncation &truncation, ImpactResult *res)
{
  PetscFunctionBeginUser;
  PetscCall(ModalReferenceRun(PETSC_COMM_SELF, sc, truncation, res));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalReferenceRun(MPI_Comm comm, const Scenario &sc, const ModalTruncation &truncation,
                                 ImpactResult *res)
{
  BeamSystem  sys;
  std::string why;

  PetscFunctionBeginUser;
  ImpactStageScope stage(ImpactStage::ModalReference); // -log_view: its own stage
  PetscCheck(BeamSystemBuild(sc.beam, &sys, &why), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  PetscCall(ModalReferenceRunSystem(comm, sc, sys, truncation, res));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalReferenceRunSystem(const Scenario &sc, const BeamSystem &sys, const ModalTruncation &truncation,
                                       ImpactResult *res)
{
  PetscFunctionBeginUser;
  PetscCall(ModalReferenceRunSystem(PETSC_COMM_SELF, sc, sys, truncation, res));
  PetscFunctionReturn(0);
}

double ModalReferenceMemory(const BeamSystem &sys)
{
  const double n = ModalReferenceFreeDofs(sys) + 1.0; // and the ball
  return (sys.Damped() ? 32.0 : 4.0) * n * n * sizeof(PetscReal);
}

double ModalReferenceMemoryLimit()
{
  PetscReal gb  = 0;
  PetscBool set = PETSC_FALSE;
  if (!PetscOptionsGetReal(NULL, NULL, "-reference_max_memory", &gb, &set) && set) return gb * 1e9;
  return MemoryLimit(); // -max_memory, default half of the physical memory
}

} // namespace beamimpact

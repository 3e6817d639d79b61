// Stormer-Verlet baseline of the semi-discrete impact: banded stiffness on plain
// arrays, fixed step, events located by re-stepping. See leapfrog.hpp.
#include "solvers/leapfrog.hpp"
#include "run/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace beamimpact {

namespace {

// One state of the beam and ball: y is padded with two zeros on each side so the
// 5-point rows need no branches (node i is y[i + 2]).
struct LeapfrogState {
  std::vector<PetscReal> y, v, a; // m, m/s, m/s^2
  PetscReal              yb = 0, vb = 0, ab = 0; // ball: m, m/s, m/s^2
  PetscReal              c = 0, F = 0;           // compression (m) and force (N) at this state
};

struct LeapfrogProblem {
  BeamOperator           op;
  BallParams             ball;
  ImpactStencil          st;
  ContactState           contact;
  PetscInt               N = 0;
  std::vector<PetscReal> band;     // band[5 i + d] = K(i, i + d - 2) / m_i (1/s^2); zero rows for held nodes
  PetscReal              gj = 0, gj1 = 0; // contact share of nodes j, j+1 divided by their mass (1/kg); 0 if held
  PetscInt               n_force = 0;

  PetscReal Compression(const LeapfrogState &s) const { return s.yb - (st.w * s.y[st.j + 2] + (1 - st.w) * s.y[st.j + 3]); }
  PetscReal CompressionRate(const LeapfrogState &s) const { return s.vb - (st.w * s.v[st.j] + (1 - st.w) * s.v[st.j + 1]); }

  // s.a, s.ab, s.c, s.F from s.y, s.yb; and, with half_kick, v += half_kick * a.
  void Force(LeapfrogState &s, PetscReal half_kick)
  {
    n_force++;
    const PetscReal *b  = band.data();
    const PetscReal *yp = s.y.data() + 2;
    PetscReal       *a = s.a.data(), *v = s.v.data();
    for (PetscInt i = 0; i < N; ++i) {
      const PetscReal *r = b + 5 * i;
      a[i]               = -(r[0] * yp[i - 2] + r[1] * yp[i - 1] + r[2] * yp[i] + r[3] * yp[i + 1] + r[4] * yp[i + 2]);
      v[i] += half_kick * a[i];
    }
    s.c = Compression(s);
    s.F = ContactForce(ball, contact, s.c);
    a[st.j] += gj * s.F;
    a[st.j + 1] += gj1 * s.F;
    v[st.j] += half_kick * gj * s.F;
    v[st.j + 1] += half_kick * gj1 * s.F;
    s.ab = -s.F / ball.mass;
    s.vb += half_kick * s.ab;
  }

  // One velocity-Verlet step of size tau from S into T (S is left unchanged).
  void Step(const LeapfrogState &S, LeapfrogState &T, PetscReal tau)
  {
    const PetscReal  h2 = 0.5 * tau;
    const PetscReal *ys = S.y.data() + 2, *vs = S.v.data(), *as = S.a.data();
    PetscReal       *yt = T.y.data() + 2, *vt = T.v.data();
    for (PetscInt i = 0; i < N; ++i) {
      const PetscReal vh = vs[i] + h2 * as[i];
      vt[i]              = vh;
      yt[i]              = ys[i] + tau * vh;
    }
    T.vb = S.vb + h2 * S.ab;
    T.yb = S.yb + tau * T.vb;
    Force(T, h2);
  }

  struct Measures {
    PetscReal total = 0, momentum = 0, angular = 0, beam_kinetic = 0, beam_strain = 0, work = 0, stored = 0;
  };
  Measures Measure(const LeapfrogState &s, PetscReal x_imp) const
  {
    Measures m;
    m.beam_kinetic = BeamKineticEnergy(op, s.v.data(), 1, 0, N);
    m.beam_strain  = BeamStrainEnergy(op, s.y.data() + 2, 1, 0, N);
    m.work         = ContactWork(ball, contact, s.c);
    m.stored       = ContactStoredEnergy(ball, contact, s.c);
    m.total        = 0.5 * ball.mass * s.vb * s.vb + m.work + m.beam_kinetic + m.beam_strain;
    for (PetscInt i = 0; i < N; ++i) {
      m.momentum += op.mass[i] * s.v[i];
      m.angular += op.mass[i] * i * op.h * s.v[i];
    }
    m.momentum += ball.mass * s.vb;
    m.angular += ball.mass * x_imp * s.vb;
    return m;
  }
};

} // namespace

PetscErrorCode LeapfrogParamsFromOptions(MPI_Comm comm, LeapfrogParams *p)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Leapfrog (Stormer-Verlet) baseline", "beamimpact");
  PetscCall(PetscOptionsReal("-leapfrog_dt", "Fixed step (s); <= 0: -leapfrog_dt_fraction x the stability limit 2/omega_max", "", p->dt, &p->dt, NULL));
  PetscCall(PetscOptionsReal("-leapfrog_dt_fraction", "Step as a fraction of the stability limit, when -leapfrog_dt is not given", "", p->dt_fraction, &p->dt_fraction, NULL));
  PetscOptionsEnd();
  PetscCheck(p->dt_fraction > 0 && p->dt_fraction <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-leapfrog_dt_fraction %g is not allowed: use 0 < fraction <= 1", (double)p->dt_fraction);
  PetscFunctionReturn(0);
}

PetscReal LeapfrogStableStep(const BeamParams &beam, const BallParams &ball, PetscReal x_imp)
{
  const BeamOperator op      = BeamOperatorBuild(beam);
  const PetscReal    c_scale = ContactCompressionScale(ball);
  const PetscReal    k_bound = ball.law == ContactLawKind::Linear ? ball.k : std::max(ball.m, ball.n) * ball.k1 * std::pow(2 * c_scale, ball.m - 1);
  return 2.0 / BeamMaxFrequencyBound(op, BeamImpactStencil(op, x_imp), k_bound, ball.mass);
}

PetscErrorCode LeapfrogRun(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, const LeapfrogParams &lp, ImpactResult *res)
{
  LeapfrogProblem P;

  PetscFunctionBeginUser;
  *res             = ImpactResult();
  res->x           = ip.x;
  res->ts_type     = "leapfrog";
  res->formulation = "explicit";
  P.op             = BeamOperatorBuild(beam);
  P.ball           = ball;
  P.st             = BeamImpactStencil(P.op, ip.x);
  P.contact        = ContactState(); // touching, loading
  P.N              = P.op.N;
  const PetscInt N = P.N;

  // Banded M^{-1} K from the operator's own rows.
  P.band.assign(5 * N, 0.0);
  for (PetscInt i = 0; i < N; ++i) {
    PetscInt  cols[5];
    PetscReal vals[5];
    const PetscInt n = BeamStiffnessRow(P.op, i, cols, vals);
    for (PetscInt q = 0; q < n; ++q) P.band[5 * i + (cols[q] - i + 2)] = vals[q] / P.op.mass[i];
  }
  P.gj  = P.op.held[P.st.j] ? 0.0 : P.st.w / P.op.mass[P.st.j];
  P.gj1 = P.op.held[P.st.j + 1] ? 0.0 : (1.0 - P.st.w) / P.op.mass[P.st.j + 1];

  // Step and its stability limit (the same Gershgorin bound as ImpactRun).
  const PetscReal t_contact = ContactTimeScale(ball);
  const PetscReal c_scale   = ContactCompressionScale(ball);
  const PetscReal v_scale   = ball.speed;
  res->dt_stable            = LeapfrogStableStep(beam, ball, ip.x);
  res->omega_max_bound      = 2.0 / res->dt_stable;
  const PetscReal dt        = lp.dt > 0 ? lp.dt : lp.dt_fraction * res->dt_stable;
  PetscCheck(std::isfinite(dt) && dt > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-leapfrog_dt %g is not allowed: the step must be > 0 (s)", (double)dt);
  PetscCheck(dt <= res->dt_stable, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "-leapfrog_dt %g is above the Stormer-Verlet stability limit dt_max = 2/omega_max = %g s on this grid (N = %" PetscInt_FMT ", omega_max <= %g rad/s); use -leapfrog_dt <= %g or fewer nodes",
             (double)dt, (double)res->dt_stable, N, (double)res->omega_max_bound, (double)res->dt_stable);
  PetscCheck(dt <= t_contact / 8, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-leapfrog_dt %g is more than 1/8 of the contact time scale %g s: events could be missed; use a smaller step", (double)dt, (double)t_contact);
  res->dt_nominal = dt;
  const ImpactTimes times = ImpactTimesOf(beam, ball, ip);

  // Initial state: beam at rest, ball touching, moving in +y.
  LeapfrogState S0, S1;
  for (LeapfrogState *s : {&S0, &S1}) {
    s->y.assign(N + 4, 0.0);
    s->v.assign(N, 0.0);
    s->a.assign(N, 0.0);
  }
  S0.vb = ball.speed;
  P.Force(S0, 0.0);
  LeapfrogState *cur = &S0, *nxt = &S1;
  const auto     m0  = P.Measure(*cur, ip.x);

  auto indicators = [&](const LeapfrogState &s, PetscReal t, EventIndicators *g) -> PetscErrorCode {
    PetscFunctionBeginUser;
    g->c    = s.c / c_scale;
    g->cdot = P.CompressionRate(s) / v_scale;
    PetscCheck(std::isfinite(g->c) && std::isfinite(g->cdot), PETSC_COMM_SELF, PETSC_ERR_FP, "leapfrog: the solution is not finite at t = %g s (dt = %g s, dt_max = %g s)", (double)t, (double)dt, (double)res->dt_stable);
    PetscFunctionReturn(0);
  };

  const double wall0 = MPI_Wtime();
  PetscReal       t = 0;
  ContactTimeline timeline;
  timeline.t_stop = times.max_time;
  PetscInt     steps = 0, event_steps = 0;
  EventIndicators g0, g1;
  PetscCall(indicators(*cur, t, &g0));
  res->contacts = 1;
  res->events.push_back({ContactEventKind::ContactStart, 0.0, 0.0, 0.0});
  while (t < timeline.t_stop * (1 - 1e-14)) {
    const PetscReal tau = std::min(dt, timeline.t_stop - t);
    P.Step(*cur, *nxt, tau);
    steps++;
    PetscCall(indicators(*nxt, t + tau, &g1));
    PetscReal   taken = tau;
    const int   ev    = ContactCrossedEvent(P.contact.phase, g0, g1, ip.event_tol);
    if (ev >= 0) {
      // Locate: re-step from the saved start (cur) with step tn in (ta, tb) until the
      // indicator is within tolerance (Illinois iterations, as ImpactRun).
      const auto kind    = static_cast<ContactEventKind>(ev);
      const bool falling = ContactEventFalling(kind);
      auto       ind     = [&](const EventIndicators &g) { return ContactEventIndicator(kind, g); };
      PetscReal  ta = 0, tb = tau, ga = ind(g0), gb = ind(g1);
      bool       at_post = true;
      int        side    = 0;
      for (int it = 0;; ++it) {
        if (at_post && std::abs(gb) <= ip.event_tol) break;
        if (!at_post && std::abs(ga) <= ip.event_tol) break;
        if (tb - ta <= 1e-13 * tau) { // bracket at round-off: take the post side
          if (at_post) break;
          P.Step(*cur, *nxt, tb);
          event_steps++;
          PetscCall(indicators(*nxt, t + tb, &g1));
          at_post = true;
          break;
        }
        PetscCheck(it < 100, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "leapfrog: event %s could not be located in [%g, %g] s (indicator %g -> %g)", ContactEventName(kind), (double)(t + ta), (double)(t + tb), (double)ga,
                   (double)gb);
        PetscReal tn = tb - gb * (tb - ta) / (gb - ga);
        if (!(tn > ta && tn < tb)) tn = 0.5 * (ta + tb);
        P.Step(*cur, *nxt, tn);
        event_steps++;
        PetscCall(indicators(*nxt, t + tn, &g1));
        const PetscReal gv   = ind(g1);
        const bool      post = falling ? gv <= 0 : gv >= 0;
        if (post) {
          tb = tn;
          gb = gv;
          if (side == 1) ga *= 0.5;
          side    = 1;
          at_post = true;
        } else {
          ta = tn;
          ga = gv;
          if (side == -1) gb *= 0.5;
          side    = -1;
          at_post = false;
        }
      }
      taken              = at_post ? tb : ta;
      const PetscReal te = t + taken;
      const PetscReal c  = nxt->c;
      bool            force_changed;
      PetscCall(ContactEventApply(PETSC_COMM_SELF, kind, te, c, ball, times, "leapfrog", &P.contact, &timeline, res, &force_changed));
      PetscCheck(res->contacts <= ip.max_contacts, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "leapfrog: more than -impact_max_contacts %" PetscInt_FMT " separate contacts by t = %g s", ip.max_contacts, (double)te);
      if (force_changed) P.Force(*nxt, 0.0); // a of the new phase at the event state
      PetscCall(indicators(*nxt, te, &g1));
    }
    t += taken;
    std::swap(cur, nxt);
    g0 = g1;
  }
  res->wall_time        = MPI_Wtime() - wall0;
  res->ended_in_contact = P.contact.phase != ContactPhase::Separated ? PETSC_TRUE : PETSC_FALSE;
  if (res->ended_in_contact) {
    res->contact_time_total += t - timeline.contact_start;
    if (res->contacts == 1) res->contact_time = t - timeline.contact_start;
  }

  const auto m1               = P.Measure(*cur, ip.x);
  res->final_time             = t;
  res->ball_final_velocity    = cur->vb;
  res->acor                   = -cur->vb / ball.speed;
  res->acor_corrected         = ball.law == ContactLawKind::Linear ? res->acor * ball.loss_factor : res->acor;
  res->energy_error           = (m1.total - m0.total) / m0.total;
  res->linear_momentum_error  = (m1.momentum - m0.momentum) / (ball.mass * ball.speed);
  res->angular_momentum_error = (m1.angular - m0.angular) / (ball.mass * ball.speed * beam.length);
  res->beam_kinetic_end       = m1.beam_kinetic;
  res->beam_strain_end        = m1.beam_strain;
  res->ball_dissipated_end    = m1.work - m1.stored;
  res->steps                  = steps;
  res->event_steps            = event_steps;
  res->function_evals         = P.n_force;
  PetscFunctionReturn(0);
}

PetscErrorCode LeapfrogRun(const Scenario &sc, const LeapfrogParams &lp, ImpactResult *res) { return LeapfrogRun(sc.beam, sc.ball, sc.impact, lp, res); }

} // namespace beamimpact

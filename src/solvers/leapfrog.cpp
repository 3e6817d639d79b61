// Stormer-Verlet baseline on plain arrays behind the Stepper interface. See leapfrog.hpp.
#include "solvers/leapfrog.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace beamimpact {

namespace {

// One state of the beam and ball: y is padded with bw zeros on each side so the band rows
// need no branches (dof d is y[d + bw]).
struct LeapfrogState {
  std::vector<PetscReal> y, v, a;           // m, m/s, m/s^2 (per dof)
  std::vector<PetscReal> vh;                // m/s, damped beam: the half-step velocity that led to this state
  PetscReal              yb = 0, vb = 0, ab = 0; // ball: m, m/s, m/s^2
  PetscReal              c = 0, F = 0;      // compression (m) and force (N) at this state
};

class LeapfrogStepper : public Stepper {
public:
  const BeamSystem      *sys = nullptr;
  ContactCoupling        g;
  BallParams             ball;
  ContactState          *contact = nullptr;
  PetscInt               n = 0, bw = 0;
  std::vector<PetscReal> band;         // M^{-1} K: band[(2 bw + 1) i + o] (1/s^2); zero rows for held dofs
  PetscReal              gm[2] = {0, 0}; // coupling weight over the dof's mass (1/kg); 0 if held
  PetscReal              dt = 0, dt_stable = 0, t = 0, t_prev = 0; // s
  LeapfrogState          A, B;
  LeapfrogState         *cur = &A, *other = &B; // after a step, *other holds the state before it
  PetscInt               n_force = 0;
  // Damped beam (see leapfrog.hpp): y + beta vh (padded like y), and the dissipated energy
  // with the rate P = v^T C v and dP/dt now and at the start of the last step.
  bool                   damped = false;
  bool                   gripped = false; // the hands (BeamSystem::grip_*)
  PetscReal              tf = 0;          // s, the time of the state Force()/ForceDamped() evaluate
  std::vector<PetscReal> yw, cv;
  PetscReal              dissipated = 0, rate = 0, rate_dot = 0, dissipated_prev = 0, rate_prev = 0, rate_dot_prev = 0;

  PetscReal CompressionOf(const LeapfrogState &s) const { return s.yb - (g.w[0] * s.y[g.dof[0] + bw] + g.w[1] * s.y[g.dof[1] + bw]); }

  // s.a, s.ab, s.c, s.F from s.y, s.yb; and, with half_kick, v += half_kick * a.
  void Force(LeapfrogState &s, PetscReal half_kick)
  {
    const PetscInt   W  = 2 * bw + 1;
    const PetscReal *yp = s.y.data() + bw;
    PetscReal       *a = s.a.data(), *v = s.v.data();
    n_force++;
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *r   = band.data() + W * i;
      const PetscReal *yi  = yp + i - bw;
      PetscReal        sum = 0;
      for (PetscInt o = 0; o < W; ++o) sum += r[o] * yi[o];
      a[i] = -sum;
      if (gripped) a[i] += sys->grip_k[i] * sys->grip_v[i] * tf / sys->mass[i]; // the frame's drive
      v[i] += half_kick * a[i];
    }
    s.c = CompressionOf(s);
    s.F = ContactForce(ball, *contact, s.c);
    for (PetscInt q = 0; q < 2; ++q) {
      a[g.dof[q]] += gm[q] * s.F;
      v[g.dof[q]] += half_kick * gm[q] * s.F;
    }
    s.ab = -s.F / ball.mass;
    s.vb += half_kick * s.ab;
  }

  // Force() of the damped scheme: a = M^{-1} (-K (y + beta vh) + g F) - alpha v, the alpha part
  // trapezoidal: v = (v + half_kick f) / (1 + half_kick alpha).
  void ForceDamped(LeapfrogState &s, PetscReal half_kick)
  {
    const PetscInt   W = 2 * bw + 1;
    const PetscReal  alpha = sys->damping_mass, beta = sys->damping_stiffness;
    PetscReal       *a = s.a.data(), *v = s.v.data();
    n_force++;
    for (PetscInt i = 0; i < n; ++i) yw[i + bw] = s.y[i + bw] + beta * s.vh[i];
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *r   = band.data() + W * i;
      const PetscReal *yi  = yw.data() + i;
      PetscReal        sum = 0;
      for (PetscInt o = 0; o < W; ++o) sum += r[o] * yi[o];
      a[i] = -sum;
      if (gripped) // the grip: beta K without its spring, the frame's drive, the damper's frame part
        a[i] += (beta * sys->grip_k[i] * s.vh[i] + sys->grip_k[i] * sys->grip_v[i] * tf + sys->grip_c[i] * sys->grip_v[i]) / sys->mass[i];
    }
    s.c = CompressionOf(s);
    s.F = ContactForce(ball, *contact, s.c);
    for (PetscInt q = 0; q < 2; ++q) a[g.dof[q]] += gm[q] * s.F;
    for (PetscInt i = 0; i < n; ++i) { // the grip's damper c_i/m_i is trapezoidal with alpha
      const PetscReal ai = gripped ? alpha + sys->grip_c[i] / sys->mass[i] : alpha;
      v[i]               = (v[i] + half_kick * a[i]) / (1 + half_kick * ai);
      a[i] -= ai * v[i];
    }
    s.ab = -s.F / ball.mass;
    s.vb += half_kick * s.ab;
  }
  // P = v^T C v and dP/dt = 2 a^T C v at the current state.
  void DissipationRateNow()
  {
    BeamSystemDampingApply(*sys, cur->v.data(), sys->fields, 0, n, cv.data(), sys->fields);
    rate     = BeamSystemDissipationRate(*sys, cur->v.data(), sys->fields, 0, n);
    rate_dot = 0;
    for (PetscInt i = 0; i < n; ++i) rate_dot += 2 * cur->a[i] * cv[i];
  }

  MPI_Comm    Comm() const override { return PETSC_COMM_SELF; }
  std::string Method() const override { return "leapfrog"; }
  std::string StepOption() const override { return "-leapfrog_dt"; }
  PetscReal   Time() const override { return t; }
  PetscErrorCode Step(PetscReal tau) override
  {
    const PetscReal  h2 = 0.5 * tau;
    const PetscReal *ys = cur->y.data() + bw, *vs = cur->v.data(), *as = cur->a.data();
    PetscReal       *yt = other->y.data() + bw, *vt = other->v.data();
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal vh = vs[i] + h2 * as[i];
      vt[i]              = vh;
      yt[i]              = ys[i] + tau * vh;
    }
    other->vb = cur->vb + h2 * cur->ab;
    other->yb = cur->yb + tau * other->vb;
    tf = t + tau;
    if (damped) {
      other->vh = other->v;
      ForceDamped(*other, h2);
    } else Force(*other, h2);
    std::swap(cur, other);
    t_prev = t;
    t += tau;
    if (damped) { // Hermite (corrected trapezoidal) rule on P over the step, as the TS stepper
      dissipated_prev = dissipated;
      rate_prev       = rate;
      rate_dot_prev   = rate_dot;
      DissipationRateNow();
      dissipated += 0.5 * tau * (rate_prev + rate) + tau * tau / 12 * (rate_dot_prev - rate_dot);
    }
    return 0;
  }
  PetscErrorCode RollBack() override
  {
    std::swap(cur, other);
    t = t_prev;
    if (damped) {
      dissipated = dissipated_prev;
      rate       = rate_prev;
      rate_dot   = rate_dot_prev;
    }
    return 0;
  }
  PetscErrorCode Restart() override
  {
    tf = t;
    if (damped) { // the acceleration of the new phase at the event state
      ForceDamped(*cur, 0.0);
      DissipationRateNow();
    } else Force(*cur, 0.0);
    return 0;
  }
  PetscReal Dissipated() const override { return dissipated; }
  PetscErrorCode SetState(PetscReal t_new, const FullState &s) override
  {
    for (PetscInt i = 0; i < n; ++i) {
      cur->y[i + bw] = s.y[i];
      cur->v[i]      = s.v[i];
    }
    if (damped) cur->vh = cur->v; // the exact velocity stands for the half-step one
    cur->yb = s.ball_y;
    cur->vb = s.ball_v;
    cur->c  = CompressionOf(*cur);
    t = t_prev = t_new;
    if (damped) dissipated = dissipated_prev = s.dissipated;
    return 0;
  }
  PetscErrorCode NextStep(PetscReal *tau) override
  {
    *tau = dt;
    return 0;
  }
  PetscErrorCode Compression(PetscReal *c, PetscReal *cdot) override
  {
    *c    = CompressionOf(*cur);
    *cdot = cur->vb - (g.w[0] * cur->v[g.dof[0]] + g.w[1] * cur->v[g.dof[1]]);
    return 0;
  }
  PetscErrorCode ViewBegin(StateView *sv) override
  {
    sv->y        = cur->y.data() + bw;
    sv->v        = cur->v.data();
    sv->y_stride = sv->v_stride = sys->fields;
    sv->d0                      = 0;
    sv->d1                      = n;
    sv->ball_y                  = cur->yb;
    sv->ball_v                  = cur->vb;
    return 0;
  }
  PetscErrorCode ViewEnd(StateView *sv) override
  {
    *sv = StateView();
    return 0;
  }
  PetscErrorCode GatherDisplacement(std::vector<PetscReal> *y) override
  {
    y->resize(sys->nodes);
    for (PetscInt i = 0; i < sys->nodes; ++i) (*y)[i] = cur->y[sys->Dof(i) + bw];
    return 0;
  }
  PetscErrorCode Counts(StepperCounts *c) override
  {
    c->function_evals = n_force;
    return 0;
  }
  std::string EnergyGrowthCause() const override
  {
    char text[256];
    PetscSNPrintf(text, sizeof(text), "(leapfrog, fixed step %g s, dt_max = %g s): with the %s law energy can only be %s", (double)dt, (double)dt_stable, ContactLawName(ball.law),
                  ContactElastic(ball) ? "conserved" : "lost");
    return text;
  }
};

} // namespace

const OptionModule &LeapfrogOptionTable()
{
  static const OptionModule m = {
    "leapfrog",
    "Leapfrog (Stormer-Verlet) baseline",
    {
      OptionReal("-leapfrog_dt", "s", "Fixed step; <= 0: -leapfrog_dt_fraction x the stability limit 2/omega_max", "-1"),
      OptionReal("-leapfrog_dt_fraction", "1", "Step as a fraction of the stability limit, when -leapfrog_dt is not given", "0.9", Between(0, 1, true, false)),
    },
  };
  return m;
}

PetscErrorCode LeapfrogParamsFromOptions(MPI_Comm comm, LeapfrogParams *p)
{
  const OptionModule &T = LeapfrogOptionTable();
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-leapfrog_dt", &p->dt, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-leapfrog_dt_fraction", &p->dt_fraction, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscReal LeapfrogStableStep(const BeamSystem &sys, const ContactCoupling &g, const BallParams &ball)
{
  const PetscReal w = BeamSystemMaxFrequencyBound(sys, g, ContactScalesOf(sys, ball).stiffness, ball.mass);
  if (!sys.Damped()) return 2.0 / w;
  // (2/w)(sqrt(1 + zeta^2) - zeta) with zeta = beta w/2, written without the cancellation.
  // The mass-like dampers (alpha, the grip's c_i/m_i) are trapezoidal: no bound of their own.
  const PetscReal zeta = 0.5 * sys.damping_stiffness * w;
  return 2.0 / (w * (std::sqrt(1 + zeta * zeta) + zeta));
}

PetscErrorCode LeapfrogStepperCreate(const BeamSystem &sys, const ContactCoupling &g, const BallParams &ball, const ContactScales &scales, ContactState *contact, const LeapfrogParams &lp,
                                     const std::vector<PetscReal> &beam_velocity, std::unique_ptr<Stepper> *stepper, IntegratorInfo *info)
{
  auto S = std::make_unique<LeapfrogStepper>();

  PetscFunctionBeginUser;
  S->sys     = &sys;
  S->g       = g;
  S->ball    = ball;
  S->contact = contact;
  S->n       = sys.ndof;
  S->bw      = sys.bw;
  const PetscInt W = 2 * sys.bw + 1;
  S->band.assign((size_t)W * sys.ndof, 0.0);
  for (PetscInt i = 0; i < sys.ndof; ++i)
    for (PetscInt o = 0; o < W; ++o) S->band[(size_t)W * i + o] = sys.band[(size_t)W * i + o] / sys.mass[i];
  for (PetscInt q = 0; q < 2; ++q) S->gm[q] = g.w[q] / sys.mass[g.dof[q]];
  // Step and its stability limit (the same Gershgorin bound as the TS stepper).
  S->dt_stable          = LeapfrogStableStep(sys, g, ball);
  info->ts_type         = "leapfrog";
  info->formulation     = "explicit";
  info->dt_stable       = S->dt_stable;
  info->omega_max_bound = sys.Damped() ? BeamSystemMaxFrequencyBound(sys, g, ContactScalesOf(sys, ball).stiffness, ball.mass) : 2.0 / S->dt_stable;
  S->dt                 = lp.dt > 0 ? lp.dt : lp.dt_fraction * S->dt_stable;
  PetscCheck(std::isfinite(S->dt) && S->dt > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-leapfrog_dt %g is not allowed: the step must be > 0 (s)", (double)S->dt);
  PetscCheck(S->dt <= S->dt_stable, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "-leapfrog_dt %g is above the Stormer-Verlet stability limit dt_max = %s = %g s on this grid (N = %" PetscInt_FMT ", omega_max <= %g rad/s); use -leapfrog_dt <= %g or fewer nodes",
             (double)S->dt, sys.Damped() ? "(2/omega_max)(sqrt(1 + zeta^2) - zeta), zeta = beta omega_max/2" : "2/omega_max", (double)S->dt_stable, sys.nodes, (double)info->omega_max_bound, (double)S->dt_stable);
  PetscCheck(S->dt <= scales.time / 8, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-leapfrog_dt %g is more than 1/8 of the contact time scale %g s: events could be missed; use a smaller step", (double)S->dt,
             (double)scales.time);
  info->dt_nominal = S->dt;
  // Initial state: beam at rest, ball touching, moving in +y.
  for (LeapfrogState *s : {&S->A, &S->B}) {
    s->y.assign(sys.ndof + 2 * sys.bw, 0.0);
    s->v.assign(sys.ndof, 0.0);
    s->a.assign(sys.ndof, 0.0);
  }
  S->A.vb     = ball.speed;
  if (!beam_velocity.empty()) S->A.v = beam_velocity; // a swinging bat: a rigid motion (no force)
  S->damped   = sys.Damped();
  S->gripped  = sys.Gripped();
  if (S->damped) {
    for (LeapfrogState *s : {&S->A, &S->B}) s->vh.assign(sys.ndof, 0.0);
    S->yw.assign(sys.ndof + 2 * sys.bw, 0.0);
    S->cv.assign(sys.ndof, 0.0);
    S->ForceDamped(S->A, 0.0);
    S->DissipationRateNow();
  } else S->Force(S->A, 0.0);
  S->n_force = 0;
  *stepper   = std::move(S);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

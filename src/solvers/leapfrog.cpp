// Stormer-Verlet baseline on plain arrays behind the Stepper interface. See leapfrog.hpp.
#include "solvers/leapfrog.hpp"

#include "system/dissipation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace beamimpact {

namespace {

// One state of the beam and ball: y is padded with bw zeros on each side so the band rows
// need no branches (dof d is y[d + bw]).
struct LeapfrogState {
  std::vector<PetscReal> y, v, a; // m, m/s, m/s^2 (per dof)
  std::vector<PetscReal> vh;      // m/s, damped beam: the half-step velocity that led to this state (padded like y)
  PetscReal              yb = 0, vb = 0, ab = 0; // ball: m, m/s, m/s^2
  PetscReal              c = 0, F = 0;           // compression (m) and force (N) at this state
};

class LeapfrogStepper : public Stepper {
public:
  const BeamSystem      *sys   = nullptr;
  const FrameMotion     *frame = nullptr; // the swing's frame (owned by the run driver)
  ContactCoupling        g;
  BallParams             ball;
  ContactState          *contact = nullptr;
  PetscInt               n = 0, bw = 0;
  std::vector<PetscReal> band; // M^{-1} K: band[(2 bw + 1) i + o] (1/s^2); zero rows for held dofs
  PetscReal              gm[ContactCoupling::kMaxEntries] = {}; // coupling weight over the dof's mass (1/kg); 0 if held
  PetscReal              dt = 0, dt_stable = 0, t = 0, t_prev = 0; // s
  LeapfrogState          A, B;
  LeapfrogState         *cur = &A, *other = &B; // after a step, *other holds the state before it
  PetscInt               n_force = 0;
  // The force operator's other parts (see leapfrog.hpp): the drive f(0, 0, t) of a moving frame,
  // and with damping M^{-1} C split into its band (lagged: the half-step velocity) and its
  // diagonal (trapezoidal), with the dissipation rule on P = v^T C v.
  bool                   drives = false; // the frame moves and a term is tied to it: f(0, 0, t) is evaluated
  bool                   damped = false;
  PetscReal              tf     = 0; // s, the time of the state Force()/ForceDamped() evaluate
  std::vector<PetscReal> drive;      // N, f(0, 0, tf)
  std::vector<PetscReal> cband,
    crate; // M^{-1} C less its diagonal part (1/s; empty: none), the diagonal part over the mass (1/s)
  std::vector<PetscReal> cv;
  DissipationIntegral    D;

  PetscReal CompressionOf(const LeapfrogState &s) const
  {
    PetscReal u = 0; // g^T y
    for (PetscInt q = 0; q < g.n; ++q) u = q == 0 ? g.w[q] * s.y[g.dof[q] + bw] : u + g.w[q] * s.y[g.dof[q] + bw];
    return s.yb - u;
  }
  void ContactAndDrive(LeapfrogState &s)
  {
    s.c = CompressionOf(s);
    s.F = ContactForce(ball, *contact, s.c);
    if (drives) ForceOperatorDrive(*sys, tf, frame, 0, n, drive.data(), sys->fields);
  }

  // s.a, s.ab, s.c, s.F from s.y, s.yb; and, with half_kick, v += half_kick * a.
  void Force(LeapfrogState &s, PetscReal half_kick)
  {
    const PetscInt   W  = 2 * bw + 1;
    const PetscReal *yp = s.y.data() + bw;
    PetscReal       *a = s.a.data(), *v = s.v.data();
    n_force++;
    ContactAndDrive(s);
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *r   = band.data() + W * i;
      const PetscReal *yi  = yp + i - bw;
      PetscReal        sum = 0;
      for (PetscInt o = 0; o < W; ++o) sum += r[o] * yi[o];
      a[i] = -sum;
      if (drives) a[i] -= drive[i] / sys->mass[i];
      v[i] += half_kick * a[i];
    }
    for (PetscInt q = 0; q < g.n; ++q) {
      a[g.dof[q]] += gm[q] * s.F;
      v[g.dof[q]] += half_kick * gm[q] * s.F;
    }
    s.ab = -s.F / ball.mass;
    s.vb += half_kick * s.ab;
  }

  // Force() of the damped scheme: a = M^{-1} (-(K y + C_band vh + f(0, 0, t)) + g F) - C_diag/m v,
  // the diagonal part trapezoidal: v = (v + half_kick f) / (1 + half_kick C_diag/m).
  void ForceDamped(LeapfrogState &s, PetscReal half_kick)
  {
    const PetscInt   W  = 2 * bw + 1;
    const PetscReal *yp = s.y.data() + bw, *vh = s.vh.data() + bw;
    PetscReal       *a = s.a.data(), *v = s.v.data();
    n_force++;
    ContactAndDrive(s);
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal *r   = band.data() + W * i;
      const PetscReal *yi  = yp + i - bw;
      PetscReal        sum = 0;
      for (PetscInt o = 0; o < W; ++o) sum += r[o] * yi[o];
      if (!cband.empty()) {
        const PetscReal *rc = cband.data() + W * i;
        const PetscReal *vi = vh + i - bw;
        for (PetscInt o = 0; o < W; ++o) sum += rc[o] * vi[o];
      }
      a[i] = -sum;
      if (drives) a[i] -= drive[i] / sys->mass[i];
    }
    for (PetscInt q = 0; q < g.n; ++q) a[g.dof[q]] += gm[q] * s.F;
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal ai = crate.empty() ? 0.0 : crate[i];
      v[i]               = (v[i] + half_kick * a[i]) / (1 + half_kick * ai);
      a[i] -= ai * v[i];
    }
    s.ab = -s.F / ball.mass;
    s.vb += half_kick * s.ab;
  }
  // P = v^T C v and dP/dt = 2 a^T C v at the current state (the velocities relative to the frame).
  void DissipationRateNow(PetscReal *P, PetscReal *Pdot)
  {
    ForceState fs;
    fs.v     = cur->v.data();
    fs.vs    = sys->fields;
    fs.t     = t;
    fs.frame = frame;
    ForceOperatorDampingApply(*sys, fs, 0, n, cv.data(), sys->fields);
    *P    = ForceOperatorDissipationRate(*sys, fs, 0, n);
    *Pdot = 0;
    for (PetscInt i = 0; i < n; ++i) *Pdot += 2 * cur->a[i] * cv[i];
  }

  MPI_Comm       Comm() const override { return PETSC_COMM_SELF; }
  std::string    Method() const override { return "leapfrog"; }
  std::string    StepOption() const override { return "-leapfrog_dt"; }
  PetscReal      Time() const override { return t; }
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
    tf        = t + tau;
    if (damped) {
      std::copy(other->v.begin(), other->v.end(), other->vh.begin() + bw);
      ForceDamped(*other, h2);
    } else Force(*other, h2);
    std::swap(cur, other);
    t_prev = t;
    t += tau;
    if (damped) { // the dissipation rule over the step (system/dissipation.hpp)
      PetscReal P, Pdot;
      DissipationRateNow(&P, &Pdot);
      D.Step(tau, P, Pdot);
    }
    return 0;
  }
  PetscErrorCode RollBack() override
  {
    std::swap(cur, other);
    t = t_prev;
    if (damped) D.RollBack();
    return 0;
  }
  PetscErrorCode Restart() override
  {
    tf = t;
    if (damped) { // the acceleration of the new phase at the event state
      PetscReal P, Pdot;
      ForceDamped(*cur, 0.0);
      DissipationRateNow(&P, &Pdot);
      D.Restart(P, Pdot);
    } else Force(*cur, 0.0);
    return 0;
  }
  PetscReal      Dissipated() const override { return D.dissipated; }
  PetscErrorCode SetState(PetscReal t_new, const FullState &s) override
  {
    for (PetscInt i = 0; i < n; ++i) {
      cur->y[i + bw] = s.y[i];
      cur->v[i]      = s.v[i];
    }
    if (damped)
      std::copy(cur->v.begin(), cur->v.end(), cur->vh.begin() + bw); // the exact velocity stands for the half-step one
    cur->yb = s.ball_y;
    cur->vb = s.ball_v;
    cur->c  = CompressionOf(*cur);
    t = t_prev = t_new;
    if (damped) D.Set(s.dissipated);
    return 0;
  }
  PetscErrorCode NextStep(PetscReal *tau) override
  {
    *tau = dt;
    return 0;
  }
  PetscErrorCode Compression(PetscReal *c, PetscReal *cdot) override
  {
    *c          = CompressionOf(*cur);
    PetscReal u = 0; // g^T v
    for (PetscInt q = 0; q < g.n; ++q) u = q == 0 ? g.w[q] * cur->v[g.dof[q]] : u + g.w[q] * cur->v[g.dof[q]];
    *cdot = cur->vb - u;
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
  PetscErrorCode GatherFields(PetscInt f0, PetscInt nf, std::vector<PetscReal> *y) override
  {
    y->resize((size_t)sys->nodes * nf);
    for (PetscInt i = 0; i < sys->nodes; ++i)
      for (PetscInt f = 0; f < nf; ++f) (*y)[i * nf + f] = cur->y[sys->Dof(i, f0 + f) + bw];
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
    PetscSNPrintf(text, sizeof(text),
                  "(leapfrog, fixed step %g s, dt_max = %g s): with the %s law energy can only be %s", (double)dt,
                  (double)dt_stable, ContactLawName(ball.law), ContactElastic(ball) ? "conserved" : "lost");
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
      OptionReal("-leapfrog_dt", "s", "Fixed step; <= 0: -leapfrog_dt_fraction x the stability limit 2/omega_max",
                 "-1"),
      OptionReal("-leapfrog_dt_fraction", "1",
                 "Step as a fraction of the stability limit, when -leapfrog_dt is not given", "0.9",
                 Between(0, 1, true, false)),
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
  const PetscReal zeta = 0.5 * ForceOperatorDampingScales(sys).stiffness * w;
  return 2.0 / (w * (std::sqrt(1 + zeta * zeta) + zeta));
}

PetscErrorCode LeapfrogStepperCreate(const StepperProblem &p, const LeapfrogParams &lp,
                                     std::unique_ptr<Stepper> *stepper, IntegratorInfo *info)
{
  const BeamSystem      &sys    = *p.sys;
  const ContactCoupling &g      = p.g;
  const BallParams      &ball   = p.ball;
  const ContactScales   &scales = p.scales;
  auto                   S      = std::make_unique<LeapfrogStepper>();

  PetscFunctionBeginUser;
  S->sys           = &sys;
  S->frame         = p.frame;
  S->g             = g;
  S->ball          = ball;
  S->contact       = p.contact;
  S->n             = sys.ndof;
  S->bw            = sys.bw;
  const PetscInt W = 2 * sys.bw + 1;
  S->band.assign((size_t)W * sys.ndof, 0.0);
  for (PetscInt i = 0; i < sys.ndof; ++i)
    for (PetscInt o = 0; o < W; ++o) S->band[(size_t)W * i + o] = sys.band[(size_t)W * i + o] / sys.mass[i];
  for (PetscInt q = 0; q < g.n; ++q) S->gm[q] = g.w[q] / sys.mass[g.dof[q]];
  if (sys.Damped()) { // M^{-1} C: its band (if any) and its diagonal part
    const ForceOperator &op = sys.forces;
    if (!op.damping_band.empty()) {
      S->cband.assign((size_t)W * sys.ndof, 0.0);
      for (PetscInt i = 0; i < sys.ndof; ++i)
        for (PetscInt o = 0; o < W; ++o) S->cband[(size_t)W * i + o] = op.damping_band[(size_t)W * i + o] / sys.mass[i];
    }
    if (!op.damping_diag.empty()) {
      S->crate.assign(sys.ndof, 0.0);
      for (PetscInt i = 0; i < sys.ndof; ++i) S->crate[i] = op.damping_diag[i] / sys.mass[i];
    }
  }
  // Step and its stability limit (the same Gershgorin bound as the TS stepper).
  S->dt_stable          = LeapfrogStableStep(sys, g, ball);
  info->ts_type         = "leapfrog";
  info->formulation     = "explicit";
  info->dt_stable       = S->dt_stable;
  info->omega_max_bound = sys.Damped()
                          ? BeamSystemMaxFrequencyBound(sys, g, ContactScalesOf(sys, ball).stiffness, ball.mass)
                          : 2.0 / S->dt_stable;
  S->dt                 = lp.dt > 0 ? lp.dt : lp.dt_fraction * S->dt_stable;
  PetscCheck(std::isfinite(S->dt) && S->dt > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "-leapfrog_dt %g is not allowed: the step must be > 0 (s)", (double)S->dt);
  PetscCheck(S->dt <= S->dt_stable, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "-leapfrog_dt %g is above the Stormer-Verlet stability limit dt_max = %s = %g s on this grid (N = "
             "%" PetscInt_FMT ", omega_max <= %g rad/s); use -leapfrog_dt <= %g or fewer nodes",
             (double)S->dt,
             sys.Damped() ? "(2/omega_max)(sqrt(1 + zeta^2) - zeta), zeta = beta omega_max/2" : "2/omega_max",
             (double)S->dt_stable, sys.nodes, (double)info->omega_max_bound, (double)S->dt_stable);
  PetscCheck(S->dt <= scales.time / 8, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "-leapfrog_dt %g is more than 1/8 of the contact time scale %g s: events could be missed; use a smaller "
             "step",
             (double)S->dt, (double)scales.time);
  info->dt_nominal = S->dt;
  // Initial state: beam at rest, ball touching, moving in +y.
  for (LeapfrogState *s : {&S->A, &S->B}) {
    s->y.assign(sys.ndof + 2 * sys.bw, 0.0);
    s->v.assign(sys.ndof, 0.0);
    s->a.assign(sys.ndof, 0.0);
  }
  S->A.vb = ball.speed;
  if (!p.beam_velocity->empty()) S->A.v = *p.beam_velocity; // a swinging bat: a rigid motion (no force)
  S->damped = sys.Damped();
  S->drives = ForceOperatorDriven(sys, p.frame);
  if (S->drives) S->drive.assign(sys.ndof, 0.0);
  if (S->damped) {
    PetscReal P, Pdot;
    for (LeapfrogState *s : {&S->A, &S->B}) s->vh.assign(sys.ndof + 2 * sys.bw, 0.0);
    S->cv.assign(sys.ndof, 0.0);
    S->ForceDamped(S->A, 0.0);
    S->DissipationRateNow(&P, &Pdot);
    S->D.Restart(P, Pdot);
  } else S->Force(S->A, 0.0);
  S->n_force = 0;
  *stepper   = std::move(S);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

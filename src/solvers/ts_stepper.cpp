// The PETSc TS stepper: set-up of the TS for the formulation of its type, and the Stepper
// interface over it. See ts_stepper.hpp; residuals, Jacobians and diagnostics are in
// ts_residuals.cpp, ts_jacobian.cpp and ts_diagnostics.cpp.
#include "solvers/ts_stepper.hpp"

#include "base/memory.hpp"
#include "base/option_table.hpp"
#include "base/options_util.hpp"
#include "solvers/irk_stage_pc.hpp"
#include "solvers/rk_stability.hpp"
#include "solvers/ts_galpha2.hpp"
#include "solvers/ts_modal.hpp"
#include "solvers/ts_problem.hpp"
#include "system/dissipation.hpp"

#include <petscdmcomposite.h>
#include <petscdmda.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>

namespace beamimpact {

namespace {

// Types whose steps can be rolled back, so that events can be located (PETSc 3.18).
bool TypeCanRollBack(const char *type)
{
  for (const char *t : {TSRK, TSTHETA, TSCN, TSBEULER, TSBDF, TSARKIMEX, TSROSW, TSALPHA, TSALPHA2, TSIRK, TSMODAL})
    if (!std::strcmp(t, type)) return true;
  return false;
}

// -ts_type names a type PETSc or the program registers; else our message before TSSetType's
// "Unknown TS type", naming the types to use, and for rk2 ... rk5 (a method, not a type) the
// rk type with its tableau.
PetscErrorCode TSCheckTypeKnown(const char *type, MPI_Comm comm)
{
  void (*create)(void) = nullptr;

  PetscFunctionBeginUser;
  PetscCall(TSInitializePackage()); // TSList
  PetscCall(PetscFunctionListFind(TSList, type, &create));
  if (create || TSModalIsType(type) || !std::strcmp(type, TSALPHA2)) PetscFunctionReturn(0);
  char hint[200] = "";
  if (std::strlen(type) == 3 && !std::strncmp(type, "rk", 2) && type[2] >= '3' && type[2] <= '5')
    std::snprintf(hint, sizeof hint, "; for the Runge-Kutta method of order %c use -ts_type rk -ts_rk_type %s", type[2],
                  type[2] == '3'   ? "3 (or 3bs)"
                  : type[2] == '4' ? "4"
                                   : "5dp (or 5bs)");
  else if (!std::strcmp(type, "rk2"))
    std::snprintf(hint, sizeof hint,
                  "; for a Runge-Kutta method use -ts_type rk -ts_rk_type 3bs, 4 or 5dp (the order-2 tableaus 2a, 2b "
                  "are refused: unstable for an undamped oscillation)");
  SETERRQ(comm, PETSC_ERR_ARG_UNKNOWN_TYPE,
          "-ts_type %s is not an integrator: use one of rk (with -ts_rk_type 3bs, 4, 5dp, ...), cn, theta, beuler, "
          "bdf, arkimex, rosw, alpha, alpha2, irk, modal%s",
          type, hint);
}

// The per-structure context: the layout, the TS configured from the options (type, its
// set-up and work vectors), the state vectors and the Jacobian's storage. Built once for a
// structure and a set of integrator options (its key) and reused by every run on them (the
// points of a sweep, the repeats of a study): a run changes only the contact point, the ball,
// the initial state and the contact state (TSStepperCreate). What the options set at the
// build is kept here and replayed on reuse, so that a reused run is the fresh one bit for bit.
struct TSContext {
  std::string key; // TSContextKey: comm, grid, formulation, type, solver options
  TSProblem   P;   // the callbacks' context (its address is the TS's)
  TS          ts = nullptr;
  Vec         U = nullptr, V = nullptr; // V: velocities of the second-order form
  NewtonFloor newton_floor;             // the SNES convergence test's context
  bool        finished        = false;  // the last run on it ended normally (else it is dropped)
  bool        monitored       = false;  // -ts_monitor (or any TS monitor) given
  bool        dt_from_options = false, dt_max_from_options = false; // -ts_dt, -ts_adapt_dt_max given
  PetscReal   dt_option = 0;                                        // s, -ts_dt as TSSetFromOptions read it
  PetscReal   dt_min = 0, dt_max = 0; // s, the adaptor's step limits after TSSetFromOptions
  PetscReal   ystar = -1;             // the rk tableau's imaginary-axis stability bound (-1: not computed)
  ~TSContext()
  {
    TSDestroy(&ts);
    VecDestroy(&U);
    VecDestroy(&V);
    TSJacobianDestroy(P);
    TSLayoutDestroy(&P.L);
  }
};

// The contexts of the structures run last (most recent first), and what reuse saved.
constexpr size_t                       kTSContextCacheSize = 4; // a categorical axis over a few types keeps each one
std::deque<std::shared_ptr<TSContext>> context_cache;
PetscInt                               n_built = 0, n_reused = 0;
bool                                   finalize_registered = false;

// The cache is emptied when PetscFinalize destroys the objects registered with
// PetscObjectRegisterDestroy, its first step, while every PETSc package is alive (a
// PetscRegisterFinalize function could run after the finalizer of a package that was
// initialized after it, e.g. SNES's after an explicit run's context was kept).
PetscErrorCode TSContextCacheFinalize(void *)
{
  context_cache.clear();
  return 0;
}

void TSContextDrop(const std::shared_ptr<TSContext> &c)
{
  context_cache.erase(std::remove(context_cache.begin(), context_cache.end(), c), context_cache.end());
}

// A context of that key that no run holds, moved to the front; nullptr if none.
std::shared_ptr<TSContext> TSContextFind(const std::string &key)
{
  for (auto it = context_cache.begin(); it != context_cache.end(); ++it)
    if ((*it)->key == key && it->use_count() == 1) {
      auto c = *it;
      context_cache.erase(it);
      context_cache.push_front(c);
      return c;
    }
  return nullptr;
}

PetscErrorCode TSContextKeep(const std::shared_ptr<TSContext> &c)
{
  PetscFunctionBeginUser;
  if (!finalize_registered) {
    PetscContainer sentinel; // destroyed by PetscFinalize, emptying the cache
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &sentinel));
    PetscCall(PetscContainerSetPointer(sentinel, &context_cache));
    PetscCall(PetscContainerSetUserDestroy(sentinel, TSContextCacheFinalize));
    PetscCall(PetscObjectRegisterDestroy((PetscObject)sentinel));
  }
  finalize_registered = true;
  context_cache.push_front(c);
  while (context_cache.size() > kTSContextCacheSize) context_cache.pop_back();
  PetscFunctionReturn(0);
}

// The key of a context: the communicator, the grid and its ghost width, the type, and every
// option that the TS, its nonlinear and linear solvers and their matrices read (-ts_, -snes_,
// -ksp_, -pc_, -mat_), as written. The beam's values, the contact point and the ball are not
// in it: they are set on every run.
PetscErrorCode TSContextKey(MPI_Comm comm, const BeamSystem &sys, const char *type, std::string *key)
{
  char *all = nullptr;

  PetscFunctionBeginUser;
  key->assign(reinterpret_cast<const char *>(&comm), sizeof comm);
  *key += " " + std::to_string((long long)sys.nodes) + " " + std::to_string((long long)sys.fields) + " " +
          std::to_string((long long)sys.GhostNodes()) + " " + type + " |";
  PetscCall(PetscOptionsGetAll(NULL, &all));
  bool keep = false;
  for (const char *p = all ? all : "";;) { // the words of the database, split at white space (once a point: no stream)
    while (*p && std::isspace(static_cast<unsigned char>(*p))) ++p;
    const char *word = p;
    while (*p && !std::isspace(static_cast<unsigned char>(*p))) ++p;
    const size_t n = (size_t)(p - word);
    if (!n) break;
    if (n > 1 && word[0] == '-' && std::isalpha(static_cast<unsigned char>(word[1]))) {
      keep = false;
      for (const char *prefix : {"-ts_", "-snes_", "-ksp_", "-pc_", "-mat_"})
        keep = keep || (n >= std::strlen(prefix) && !std::strncmp(word, prefix, std::strlen(prefix)));
    }
    if (keep) key->append(" ").append(word, n);
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

class TSStepper : public Stepper {
public:
  explicit TSStepper(std::shared_ptr<TSContext> c) :
    C(std::move(c)), P(C->P), ts(C->ts), U(C->U), V(C->V), newton_floor(C->newton_floor)
  {
  }
  std::shared_ptr<TSContext> C;
  TSProblem                 &P;
  TS                        &ts;
  Vec                       &U, &V; // V: velocities of the second-order form
  NewtonFloor               &newton_floor;
  StepperCounts              counts0; // the TS's cumulative counts when this run started on it
  bool                       fixed_step = true;
  PetscReal                  dt_nominal = 0, dt_cap = 0; // s
  ContactScales              scales;
  IntegratorInfo             info;
  std::string                rk_type; // -ts_rk_type, for messages
  // Damped beam: the dissipated energy D by the dissipation rule (system/dissipation.hpp).
  bool                damped    = false;
  bool                monitored = false; // -ts_monitor (or any TS monitor) given: called after each step
  DissipationIntegral D;
  // The open view (ViewBegin/ViewEnd).
  TSStateRead        view_x;
  Vec                view_X = nullptr, view_Vb = nullptr, view_Vr = nullptr;
  const PetscScalar *view_varr = nullptr;

  ~TSStepper() override
  {
    if (ts) TSViewFromOptions(ts, NULL, "-ts_view"); // at the end, as TSSolve would
    if (!C->finished) TSContextDrop(C);              // a run that stopped on an error: its context is not reused
  }
  MPI_Comm                         Comm() const override { return P.L.comm; }
  std::string                      Method() const override { return "-ts_type " + info.ts_type; }
  std::shared_ptr<const BeamModes> Modes() const override { return TSModalModes(ts); }
  std::string                      StepOption() const override { return fixed_step ? "-ts_dt" : "-ts_rtol/-ts_atol"; }
  PetscReal                        Time() const override
  {
    PetscReal t = 0;
    TSGetTime(ts, &t);
    return t;
  }
  PetscErrorCode Step(PetscReal dt) override
  {
    const PetscReal t0 = Time();

    PetscFunctionBeginUser;
    PetscCall(TSSetTimeStep(ts, dt));
    PetscCall(TSStep(ts));
    PetscCall(TSCheckStep(P, ts, info.ts_type.c_str(), info.omega_max_bound));
    if (monitored) { // -ts_monitor and friends: the driver calls TSStep itself, so it calls the monitors too
      Vec      U;
      PetscInt step;
      PetscCall(TSGetSolution(ts, &U));
      PetscCall(TSGetStepNumber(ts, &step));
      PetscCall(TSMonitor(ts, step, Time(), U));
    }
    if (damped) { // the step just taken, by the dissipation rule
      PetscReal P, Pdot;
      PetscCall(DissipationRateNow(&P, &Pdot));
      D.Step(Time() - t0, P, Pdot);
    }
    PetscFunctionReturn(0);
  }
  PetscErrorCode RollBack() override
  {
    PetscFunctionBeginUser;
    PetscCall(TSRollBack(ts));
    if (damped) D.RollBack();
    PetscFunctionReturn(0);
  }
  PetscErrorCode Restart() override
  {
    PetscFunctionBeginUser;
    PetscCall(TSRestartStep(ts));
    if (damped) PetscCall(DissipationRestart()); // the new phase's acceleration
    PetscFunctionReturn(0);
  }
  PetscReal      Dissipated() const override { return D.dissipated; }
  PetscErrorCode DissipationRestart()
  {
    PetscReal P, Pdot;

    PetscFunctionBeginUser;
    PetscCall(DissipationRateNow(&P, &Pdot));
    D.Restart(P, Pdot);
    PetscFunctionReturn(0);
  }
  PetscErrorCode DissipationRateNow(PetscReal *r, PetscReal *rdot)
  {
    Vec       X, Vel;
    PetscBool modal;

    PetscFunctionBeginUser;
    PetscCall(TSModalDissipationRate(ts, r, rdot, &modal)); // -ts_type modal: from its modes, O(modes)
    if (modal) PetscFunctionReturn(0);
    PetscCall(Solution(&X, &Vel));
    PetscCall(TSDissipationRate(P, Time(), X, Vel, r, rdot));
    PetscFunctionReturn(0);
  }
  PetscErrorCode NextStep(PetscReal *dt) override
  {
    PetscFunctionBeginUser;
    if (fixed_step) *dt = dt_nominal;
    else {
      PetscCall(TSGetTimeStep(ts, dt));
      *dt = std::min(*dt, dt_cap);
    }
    PetscFunctionReturn(0);
  }
  PetscErrorCode Solution(Vec *X, Vec *Vel) const
  {
    PetscFunctionBeginUser;
    *Vel = nullptr;
    PetscCall(TSModalSyncSolution(ts)); // -ts_type modal: the physical state of its modes, when read
    if (P.form == Formulation::SecondOrder) PetscCall(TS2GetSolution(ts, X, Vel));
    else PetscCall(TSGetSolution(ts, X));
    PetscFunctionReturn(0);
  }
  PetscErrorCode Compression(PetscReal *c, PetscReal *cdot) override;
  PetscErrorCode SetState(PetscReal t, const FullState &s) override;
  PetscErrorCode GetModalState(const BeamModes &m, ModalState *s, bool *done) override;
  PetscErrorCode SetModalState(PetscReal t, const BeamModes &m, const ModalState &s, bool *done) override;
  PetscErrorCode ModalStateUnwritten(std::shared_ptr<const BeamModes> *modes, ModalState *s, bool *done) override;
  PetscErrorCode Sample(StateSample *s, bool *done) override;
  PetscErrorCode Expand(const std::vector<StateSample> &s, SampleRange *r, std::vector<PetscReal> *y,
                        std::vector<PetscReal> *v) override;
  PetscErrorCode ViewBegin(StateView *v) override;
  PetscErrorCode ViewEnd(StateView *v) override;
  PetscErrorCode GatherFields(PetscInt f0, PetscInt nf, std::vector<PetscReal> *y) override;
  PetscErrorCode Counts(StepperCounts *n) override;
  std::string    EnergyGrowthCause() const override;
};

// Compression and its rate from the owned values (no ghost scatter), summed over ranks.
PetscErrorCode TSStepper::Compression(PetscReal *c, PetscReal *cdot)
{
  const TSLayout    &L  = P.L;
  const PetscInt     nf = L.fields;
  Vec                X, Vel, Xb, Xr, Vb = nullptr, Vr = nullptr;
  const PetscScalar *x, *xr, *v = nullptr, *vr = nullptr;
  PetscReal          vals[2] = {0, 0};
  PetscBool          modal;

  PetscFunctionBeginUser;
  PetscCall(TSModalCompression(ts, c, cdot, &modal)); // -ts_type modal: from its modes, O(modes)
  if (modal) PetscFunctionReturn(0);
  PetscCall(Solution(&X, &Vel));
  PetscCall(DMCompositeGetAccess(L.pack, X, &Xb, &Xr));
  PetscCall(VecGetArrayRead(Xb, &x));
  PetscCall(VecGetArrayRead(Xr, &xr));
  if (Vel) {
    PetscCall(DMCompositeGetAccess(L.pack, Vel, &Vb, &Vr));
    PetscCall(VecGetArrayRead(Vb, &v));
    PetscCall(VecGetArrayRead(Vr, &vr));
  }
  // Deflection block and velocity block of the owned nodes, by global node.
  const PetscScalar *bx = x - L.xs * L.dof, *bv = Vel ? v - L.xs * nf : bx + nf;
  const PetscInt     vstride = Vel ? nf : L.dof;
  if (L.rank == 0) {
    vals[0] = xr[0];
    vals[1] = Vel ? vr[0] : xr[1];
  }
  for (PetscInt q = 0; q < P.g.n; ++q) {
    const PetscInt d = P.g.dof[q], node = d / nf, f = d % nf;
    if (node < L.xs || node >= L.xe) continue;
    vals[0] -= P.g.w[q] * bx[node * L.dof + f];
    vals[1] -= P.g.w[q] * bv[node * vstride + f];
  }
  if (Vel) {
    PetscCall(VecRestoreArrayRead(Vr, &vr));
    PetscCall(VecRestoreArrayRead(Vb, &v));
    PetscCall(DMCompositeRestoreAccess(L.pack, Vel, &Vb, &Vr));
  }
  PetscCall(VecRestoreArrayRead(Xr, &xr));
  PetscCall(VecRestoreArrayRead(Xb, &x));
  PetscCall(DMCompositeRestoreAccess(L.pack, X, &Xb, &Xr));
  if (L.size > 1) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, vals, 2, MPIU_REAL, MPIU_SUM, L.comm));
  *c    = vals[0];
  *cdot = vals[1];
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::SetState(PetscReal t, const FullState &s)
{
  const TSLayout &L  = P.L;
  const PetscInt  nf = L.fields;
  Vec             X, Vel;
  TSStateWrite    w;

  PetscFunctionBeginUser;
  PetscCall(Solution(&X, &Vel));
  PetscCall(TSStateWriteBegin(L, X, &w));
  for (PetscInt node = L.xs; node < L.xe; ++node)
    for (PetscInt f = 0; f < nf; ++f) {
      w.beam[node * L.dof + f] = s.y[node * nf + f];
      if (!Vel) w.beam[node * L.dof + nf + f] = s.v[node * nf + f];
    }
  if (w.ball) {
    w.ball[0] = s.ball_y;
    if (!Vel) w.ball[1] = s.ball_v;
  }
  PetscCall(TSStateWriteEnd(L, X, &w));
  if (Vel) {
    PetscCall(TSStateWriteBegin(L, Vel, &w));
    for (PetscInt node = L.xs; node < L.xe; ++node)
      for (PetscInt f = 0; f < nf; ++f) w.beam[node * L.dof + f] = s.v[node * nf + f];
    if (w.ball) w.ball[0] = s.ball_v;
    PetscCall(TSStateWriteEnd(L, Vel, &w));
  }
  PetscCall(TSSetTime(ts, t));
  if (damped) D.Set(s.dissipated);
  PetscFunctionReturn(0);
}

// -ts_type modal in the basis m: its own modal state, no projection (ts_modal.hpp).
PetscErrorCode TSStepper::GetModalState(const BeamModes &m, ModalState *s, bool *done)
{
  PetscBool ok = PETSC_FALSE;

  PetscFunctionBeginUser;
  *done = false;
  if (TSModalModes(ts).get() != &m) PetscFunctionReturn(0);
  PetscCall(TSModalGetState(ts, &s->z, &s->zd, &s->ball_y, &s->ball_v, &ok));
  s->dissipated = D.dissipated;
  *done         = ok;
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::SetModalState(PetscReal t, const BeamModes &m, const ModalState &s, bool *done)
{
  PetscBool ok = PETSC_FALSE;

  PetscFunctionBeginUser;
  *done = false;
  if (TSModalModes(ts).get() != &m) PetscFunctionReturn(0);
  PetscCall(TSModalSetState(ts, s.z, s.zd, s.ball_y, s.ball_v, &ok));
  if (!ok) PetscFunctionReturn(0);
  PetscCall(TSSetTime(ts, t));
  if (damped) D.Set(s.dissipated);
  *done = true;
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::ModalStateUnwritten(std::shared_ptr<const BeamModes> *modes, ModalState *s, bool *done)
{
  PetscBool ok = PETSC_FALSE;

  PetscFunctionBeginUser;
  *done  = false;
  *modes = TSModalModes(ts);
  if (!*modes) PetscFunctionReturn(0);
  PetscCall(TSModalGetUnwrittenState(ts, &s->z, &s->zd, &s->ball_y, &s->ball_v, &ok));
  s->dissipated = D.dissipated;
  *done         = ok;
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::Sample(StateSample *s, bool *done)
{
  PetscBool ok = PETSC_FALSE;

  PetscFunctionBeginUser;
  s->t = Time();
  PetscCall(TSModalSample(ts, &s->z, &s->zd, &s->ball_y, &s->ball_v, &s->static_force, &ok));
  *done = ok;
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::Expand(const std::vector<StateSample> &s, SampleRange *r, std::vector<PetscReal> *y,
                                 std::vector<PetscReal> *v)
{
  const PetscInt count = (PetscInt)s.size(), k = count ? (PetscInt)s[0].z.size() : 0;
  PetscBool      ok = PETSC_FALSE;

  PetscFunctionBeginUser;
  std::vector<PetscReal> Z((size_t)k * 2 * count), F(count); // [Z Zd]: the rates' columns after the amplitudes'
  for (PetscInt q = 0; q < count; ++q) {
    PetscCheck((PetscInt)s[q].z.size() == k, Comm(), PETSC_ERR_ARG_SIZ, "samples of different bases");
    std::copy(s[q].z.begin(), s[q].z.end(), Z.begin() + (size_t)q * k);
    std::copy(s[q].zd.begin(), s[q].zd.end(), Z.begin() + (size_t)(count + q) * k);
    F[q] = s[q].static_force;
  }
  PetscInt gxs, gxm; // the ghosted nodes: the owned ones and the neighbours' the stencil reaches
  PetscCall(DMDAGetGhostCorners(P.L.da, &gxs, NULL, NULL, &gxm, NULL, NULL));
  r->d0 = P.L.D0(), r->d1 = P.L.D1(), r->e0 = gxs * P.L.fields, r->e1 = (gxs + gxm) * P.L.fields;
  const size_t ne = (size_t)(r->e1 - r->e0);
  y->assign(ne * count, 0.0);
  v->assign(ne * count, 0.0);
  PetscCall(TSModalExpand(ts, Z.data(), F.data(), count, r->e0, r->e1, y->data(), v->data(), &ok));
  PetscCheck(ok, Comm(), PETSC_ERR_SUP, "%s keeps no samples to expand", Method().c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::ViewBegin(StateView *sv)
{
  const TSLayout &L = P.L;
  Vec             Vel;

  PetscFunctionBeginUser;
  PetscCall(Solution(&view_X, &Vel));
  PetscCall(TSStateReadBegin(L, view_X, &view_x));
  sv->y        = view_x.beam;
  sv->y_stride = L.dof;
  sv->d0       = L.D0();
  sv->d1       = L.D1();
  sv->ball_y   = view_x.ball[0];
  if (Vel) {
    const PetscScalar *vr;
    PetscScalar        ball_v;
    PetscCall(DMCompositeGetAccess(L.pack, Vel, &view_Vb, &view_Vr));
    PetscCall(VecGetArrayRead(view_Vb, &view_varr));
    PetscCall(VecGetArrayRead(view_Vr, &vr));
    ball_v = L.rank == 0 ? vr[0] : 0.0;
    PetscCall(VecRestoreArrayRead(view_Vr, &vr));
    if (L.size > 1) PetscCallMPI(MPI_Bcast(&ball_v, 1, MPIU_SCALAR, 0, L.comm));
    sv->v        = view_varr - L.xs * L.fields;
    sv->v_stride = L.fields;
    sv->ball_v   = ball_v;
  } else {
    sv->v        = view_x.beam + L.fields;
    sv->v_stride = L.dof;
    sv->ball_v   = view_x.ball[1];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TSStepper::ViewEnd(StateView *sv)
{
  Vec X, Vel;

  PetscFunctionBeginUser;
  PetscCall(Solution(&X, &Vel));
  if (Vel) {
    PetscCall(VecRestoreArrayRead(view_Vb, &view_varr));
    PetscCall(DMCompositeRestoreAccess(P.L.pack, Vel, &view_Vb, &view_Vr));
  }
  PetscCall(TSStateReadEnd(P.L, view_X, &view_x));
  *sv = StateView();
  PetscFunctionReturn(0);
}

// Fields [f0, f0 + nf) of the displacement on rank 0 (gathered in natural node order).
PetscErrorCode TSStepper::GatherFields(PetscInt f0, PetscInt nf, std::vector<PetscReal> *y)
{
  const TSLayout &L = P.L;
  Vec             X, Vel, Xb, Xr, y0, yall;
  VecScatter      sc;

  PetscFunctionBeginUser;
  PetscCall(Solution(&X, &Vel));
  PetscCall(DMCompositeGetAccess(L.pack, X, &Xb, &Xr));
  const PetscInt n = L.xe - L.xs;
  PetscCall(VecCreateMPI(L.comm, n * nf, PETSC_DETERMINE, &y0));
  {
    const PetscScalar *x;
    PetscScalar       *o;
    PetscCall(VecGetArrayRead(Xb, &x));
    PetscCall(VecGetArray(y0, &o));
    for (PetscInt i = 0; i < n; ++i)
      for (PetscInt f = 0; f < nf; ++f) o[i * nf + f] = x[i * L.dof + f0 + f];
    PetscCall(VecRestoreArray(y0, &o));
    PetscCall(VecRestoreArrayRead(Xb, &x));
  }
  PetscCall(DMCompositeRestoreAccess(L.pack, X, &Xb, &Xr));
  PetscCall(VecScatterCreateToZero(y0, &sc, &yall));
  PetscCall(VecScatterBegin(sc, y0, yall, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, y0, yall, INSERT_VALUES, SCATTER_FORWARD));
  if (L.rank == 0) {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(yall, &a));
    y->assign(a, a + L.nodes * nf);
    PetscCall(VecRestoreArrayRead(yall, &a));
  }
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&yall));
  PetscCall(VecDestroy(&y0));
  PetscFunctionReturn(0);
}

// The TS's cumulative counts (over every run on its context).
PetscErrorCode TSCumulativeCounts(TS ts, Formulation form, StepperCounts *n)
{
  PetscFunctionBeginUser;
  PetscCall(TSGetStepRejections(ts, &n->rejected_steps));
  if (form != Formulation::Explicit) {
    PetscCall(TSGetSNESFailures(ts, &n->failed_solves));
    PetscCall(TSGetSNESIterations(ts, &n->nonlinear_its));
    PetscCall(TSGetKSPIterations(ts, &n->linear_its));
  }
  PetscFunctionReturn(0);
}

// This run's counts. Called once the run is over (ImpactFinish): the context is then fit for
// the next run.
PetscErrorCode TSStepper::Counts(StepperCounts *n)
{
  PetscFunctionBeginUser;
  PetscCall(TSCumulativeCounts(ts, P.form, n));
  n->rejected_steps -= counts0.rejected_steps;
  n->failed_solves -= counts0.failed_solves;
  n->nonlinear_its -= counts0.nonlinear_its;
  n->linear_its -= counts0.linear_its;
  n->function_evals      = P.count.func;
  n->jacobian_evals      = P.count.jac;
  n->jacobian_assemblies = P.count.assembled;
  C->finished            = true;
  PetscFunctionReturn(0);
}

std::string TSStepper::EnergyGrowthCause() const
{
  PetscReal t = 0, tp = 0;
  TSGetTime(ts, &t);
  TSGetPrevTime(ts, &tp);
  const PetscReal dt_last = t - tp;
  char            cause[512];
  const char     *reduce = fixed_step ? "-ts_dt" : "-ts_rtol/-ts_atol";
  if (TSModalIsType(info.ts_type.c_str()))
    PetscSNPrintf(cause, sizeof(cause),
                  "the modal splitting step does not resolve the contact (contact time scale %g s; the beam itself has "
                  "no step limit); reduce -ts_dt or use -ts_modal_order 4",
                  (double)scales.time);
  else if (P.form == Formulation::Explicit && fixed_step)
    PetscSNPrintf(cause, sizeof(cause),
                  "the fixed step is %.3g x the stability limit dt_max = %g s computed for this grid and contact; use "
                  "a smaller -ts_dt",
                  (double)(dt_last / info.dt_stable), (double)info.dt_stable);
  else if (P.form == Formulation::Explicit)
    PetscSNPrintf(cause, sizeof(cause),
                  "the error controller let the step reach the explicit stability limit dt_max = %g s; tighten "
                  "-ts_rtol/-ts_atol or use a fixed -ts_dt below dt_max",
                  (double)info.dt_stable);
  else if (P.form == Formulation::IMEX)
    PetscSNPrintf(cause, sizeof(cause),
                  "-ts_type %s treats the contact force explicitly, and the step is too large for the contact "
                  "stiffness (contact time scale %g s); reduce %s or use a fully implicit type (cn, bdf, alpha2)",
                  info.ts_type.c_str(), (double)scales.time, reduce);
  else
    PetscSNPrintf(cause, sizeof(cause), "the %s does not resolve the contact (contact time scale %g s); reduce %s",
                  fixed_step ? "step" : "tolerance", (double)scales.time, reduce);
  char text[700];
  PetscSNPrintf(text, sizeof(text),
                "(-ts_type %s%s%s, %s step %g s): with the %s law energy can only be %s; likely cause: %s",
                info.ts_type.c_str(), rk_type.empty() ? "" : " -ts_rk_type ", rk_type.c_str(),
                fixed_step ? "fixed" : "adaptive, last", (double)dt_last, ContactLawName(P.ball.law),
                ContactElastic(P.ball) ? "conserved" : "lost", cause);
  return text;
}

// The TS with the callbacks of the formulation and direct solves of the (banded) Jacobian.
PetscErrorCode CreateTS(TSStepper &S, const char *type)
{
  TSProblem &P = S.P;

  PetscFunctionBeginUser;
  PetscCall(TSGAlpha2Register()); // -ts_type alpha2: generalized-alpha with a consistent restart (ts_galpha2.hpp)
  PetscCall(TSModalRegister());   // -ts_type modal: exact beam flow in its modes, contact by splitting (ts_modal.hpp)
  PetscCall(TSCreate(P.L.comm, &S.ts));
  PetscCall(TSSetType(S.ts, type));
  PetscCall(TSSetDM(S.ts, P.L.pack));
  PetscCall(TSSetProblemType(S.ts, TS_NONLINEAR));
  PetscCall(DMCreateGlobalVector(P.L.pack, &S.U));
  switch (P.form) {
  case Formulation::Explicit:
    PetscCall(TSSetRHSFunction(S.ts, NULL, TSRHSExplicit, &P));
    break;
  case Formulation::IMEX: // the Jacobian is set after the options (TSJacobianInstall): which one depends on the
                          // preconditioner
    PetscCall(TSSetIFunction(S.ts, NULL, TSIFunctionBeam, &P));
    PetscCall(TSSetRHSFunction(S.ts, NULL, TSRHSContact, &P));
    break;
  case Formulation::Implicit:
    PetscCall(TSSetIFunction(S.ts, NULL, TSIFunctionBeam, &P));
    break;
  case Formulation::SecondOrder:
    PetscCall(TSSetI2Function(S.ts, NULL, TSI2FunctionBeam, &P));
    break;
  }
  if (P.form != Formulation::Explicit) {
    SNES snes;
    KSP  ksp;
    PC   pc;
    PetscCall(TSGetSNES(S.ts, &snes));
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscBool irk;
    PetscCall(PetscStrcmp(type, TSIRK, &irk));
    if (irk) { // the stages' coupled system is a KAIJ matrix (I x A^-1/dt + J x I), which PETSc cannot factor:
               // GMRES on it, preconditioned by its exact LU assembled from J (irk_stage_pc.hpp)
      PetscCall(KSPSetType(ksp, KSPGMRES));
      PetscCall(KSPSetTolerances(ksp, 1e-12, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      PetscCall(IrkStagePCSet(P, pc));
    } else { // a direct solve: the beam's LU kept per step, the contact by Sherman-Morrison (ts_problem.hpp)
      PetscCall(KSPSetType(ksp, KSPPREONLY));
      PetscCall(TSJacobianSetDefaultPC(P, pc));
    }
  }
  PetscFunctionReturn(0);
}

// What the chosen type and step must allow, said before PETSc's set-up fails in its own words:
// a type that cannot roll back a step (no event location; basicsymplectic and mprk would
// also ask for RHS splits), a step that is not a finite positive number, and a theta method
// outside [1/2, 1] (theta < 1/2 amplifies an undamped oscillation at every step; 0 is the
// explicit Euler method, whose implicit solve divides by theta dt).
PetscErrorCode TSCheckTypeSettings(TS ts, const char *type, MPI_Comm comm)
{
  PetscReal dt;
  PetscBool theta;

  PetscFunctionBeginUser;
  PetscCheck(TypeCanRollBack(type), comm, PETSC_ERR_SUP,
             "-ts_type %s cannot roll back a step, so contact start, maximum compression and separation cannot be "
             "located as events; "
             "use one that can: rk (e.g. -ts_rk_type 4 or 5dp), cn, theta, beuler, bdf, arkimex, rosw, alpha, alpha2, "
             "modal",
             type);
  PetscCall(TSGetTimeStep(ts, &dt));
  char value[64]; // PETSc's %g would write 0 as "0." and nan as "nan."
  std::snprintf(value, sizeof value, "%g", (double)dt);
  PetscCheck(std::isfinite(dt) && dt > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-ts_dt %s is not allowed: the time step must be a finite number > 0 (s)", value);
  PetscCall(PetscStrcmp(type, TSTHETA, &theta));
  if (theta) {
    PetscReal th;
    PetscCall(TSThetaGetTheta(ts, &th));
    std::snprintf(value, sizeof value, "%g", (double)th);
    PetscCheck(th >= 0.5 && th <= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-ts_theta_theta %s is not allowed: use 0.5 <= theta <= 1 (0.5: Crank-Nicolson, 1: backward Euler); "
               "theta < 0.5 amplifies an undamped oscillation at every step%s",
               value, th == 0 ? ", and theta = 0 is the explicit Euler method (use -ts_type rk)" : "");
  }
  PetscFunctionReturn(0);
}

// Defaults that options override (a step resolving the contact, capped so one step cannot
// hold two events), then the options, then what the run needs of the solver.
// KSPSolve and SNESSolve read their viewers (-ksp_converged_reason, -snes_view, ...) at each
// solve, after ConfigureTS's unused-option check: where the integrator has the solver they act,
// so they are marked read here (PetscOptionsHasName) instead of being reported unused.
PetscErrorCode MarkSolveTimeViewers(TS ts)
{
  static const char *ksp_names[]  = {"-ksp_converged_reason",
                                     "-ksp_converged_rate",
                                     "-ksp_view",
                                     "-ksp_view_pre",
                                     "-ksp_view_mat",
                                     "-ksp_view_pmat",
                                     "-ksp_view_rhs",
                                     "-ksp_view_solution",
                                     "-ksp_view_mat_explicit",
                                     "-ksp_view_preconditioned_operator_explicit",
                                     "-ksp_view_final_residual",
                                     "-ksp_view_eigenvalues",
                                     "-ksp_view_eigenvalues_explicit",
                                     "-ksp_view_singularvalues"};
  static const char *snes_names[] = {"-snes_converged_reason", "-snes_view", "-snes_view_pre", "-snes_view_solution"};
  SNES               snes;
  KSP                ksp;
  const char        *prefix;
  PetscBool          set;

  PetscFunctionBeginUser;
  PetscCall(TSGetSNES(ts, &snes));
  PetscCall(SNESGetOptionsPrefix(snes, &prefix));
  for (const char *n : snes_names) PetscCall(PetscOptionsHasName(NULL, prefix, n, &set));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  for (const char *n : ksp_names) PetscCall(PetscOptionsHasName(NULL, prefix, n, &set));
  PetscFunctionReturn(0);
}

PetscErrorCode ConfigureTS(TSStepper &S, const char *type, const TSStepperSettings &set)
{
  TSAdapt   adapt;
  PetscBool flag;

  PetscFunctionBeginUser;
  S.dt_cap = S.scales.time / 8;
  PetscCall(TSSetTimeStep(S.ts, S.scales.time / 200));
  PetscCall(TSSetMaxTime(S.ts, 1e30)); // the run driver decides when to stop
  PetscCall(TSSetMaxSteps(S.ts, PETSC_MAX_INT));
  PetscCall(TSSetExactFinalTime(S.ts, TS_EXACTFINALTIME_MATCHSTEP));
  PetscCall(TSGetAdapt(S.ts, &adapt));
  PetscCall(TSAdaptSetStepLimits(adapt, PETSC_DEFAULT, S.dt_cap));
  PetscCall(TSSetFromOptions(S.ts));
  if (S.P.form != Formulation::Explicit)
    PetscCall(TSJacobianInstall(S.P, S.ts)); // the shell J, or the assembled one for -pc_type lu etc.
  { // what the options set, replayed when the context is reused (TSContextReuse)
    TSContext &C = *S.C;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_dt", &flag));
    C.dt_from_options = flag;
    PetscCall(TSGetTimeStep(S.ts, &C.dt_option));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_adapt_dt_max", &flag));
    C.dt_max_from_options = flag;
    PetscCall(TSAdaptGetStepLimits(adapt, &C.dt_min, &C.dt_max));
  }
  TSType    now;
  PetscBool same, fixed;
  PetscCall(TSGetType(S.ts, &now));
  PetscCall(PetscStrcmp(now, type, &same));
  PetscCheck(same, S.P.L.comm, PETSC_ERR_ARG_WRONG,
             "TS type changed from %s to %s after setup: set -ts_type on the command line or in an options file", type,
             now);
  S.info.ts_type = now;
  PetscCall(PetscObjectTypeCompare((PetscObject)adapt, TSADAPTNONE, &fixed));
  S.fixed_step      = fixed;
  S.info.fixed_step = fixed;
  // The error tolerances control an adaptive step only; a fixed one (-ts_adapt_type none, the
  // default of modal, cn, theta, beuler, alpha, alpha2) they leave as it is: a note when given.
  for (const char *tol : {"-ts_rtol", "-ts_atol"})
    OptionWithoutEffectSet(tol,
                           fixed ? std::string("the step is fixed, -ts_type ") + now +
                                     " with -ts_adapt_type none: -ts_dt sets it"
                                 : "",
                           {"-ts_type", "-ts_adapt_type"});
  if (S.P.form != Formulation::Explicit) {
    PetscBool user_test;
    SNES      snes;
    PetscCall(TSGetSNES(S.ts, &snes));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-snes_convergence_test", &user_test));
    S.newton_floor = {&S.P, S.ts, S.info.omega_max_bound * S.info.omega_max_bound};
    if (!user_test) PetscCall(SNESSetConvergenceTest(snes, TSConvergedWithRoundoffFloor, &S.newton_floor, NULL));
  }
  PetscCall(TSSetErrorIfStepFails(S.ts, PETSC_FALSE));   // failures are explained by TSCheckStep
  PetscCall(TSCheckTypeSettings(S.ts, now, S.P.L.comm)); // before TSSetUp, whose errors would not say why
  PetscCall(
    IrkStageLayout(S.ts, S.P.L.pack)); // -ts_type irk on more than one rank: its stage vector split as the state
  PetscCall(TSSetUp(S.ts));
  PetscCall(IrkStageAfterSetUp(S.ts)); // -ts_type irk: a new step size reaches its stage matrix on every rank
  if (S.P.form != Formulation::Explicit) PetscCall(MarkSolveTimeViewers(S.ts));
  if (set.check_unused_options) PetscCall(OptionsCheckUnused(S.P.L.comm, {}, set.strict_solver_options));
  if (S.P.form != Formulation::Explicit) { // the last Newton solve's residual history explains a failure
    SNES snes;
    PetscCall(TSGetSNES(S.ts, &snes));
    PetscCall(SNESSetConvergenceHistory(snes, NULL, NULL, PETSC_DECIDE, PETSC_TRUE));
  }
  PetscFunctionReturn(0);
}

// Explicit stability: the imaginary-axis bound of the rk tableau over omega_max.
PetscErrorCode ExplicitStability(TSStepper &S)
{
  const MPI_Comm comm = S.P.L.comm;

  PetscFunctionBeginUser;
  if (S.P.form != Formulation::Explicit || TSModalIsType(S.info.ts_type.c_str()))
    PetscFunctionReturn(0); // modal: no limit from the beam
  PetscCheck(S.info.ts_type == TSRK, comm, PETSC_ERR_SUP,
             "-ts_type %s is explicit but not rk: only rk tableaus have a computed stability limit here; use -ts_type "
             "rk",
             S.info.ts_type.c_str());
  PetscInt         s;
  const PetscReal *A, *b;
  TSRKType         rktype;
  PetscCall(TSRKGetTableau(S.ts, &s, &A, &b, NULL, NULL, NULL, NULL, NULL));
  PetscCall(TSRKGetType(S.ts, &rktype));
  S.rk_type = rktype;
  if (S.C->ystar < 0) S.C->ystar = RKImaginaryStabilityBound(s, A, b); // a constant of the tableau: once per context
  const PetscReal ystar = S.C->ystar;
  PetscCheck(ystar > 0, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-ts_rk_type %s is unstable for an undamped oscillation at any step (its stability region does not "
             "contain the imaginary axis); use -ts_rk_type 3bs, 4 or 5dp, or an implicit type (cn, bdf, alpha2)",
             rktype);
  const BeamSystem &sys = *S.P.sys;
  // Damped: the largest step with every mode's eigenvalues -zeta w +- w sqrt(zeta^2 - 1),
  // zeta = alpha/(2w) + beta w/2, w <= omega_max, in the stability region (rk_stability.hpp);
  // alpha and beta the force operator's damping scales (a grip's c_i/m_i counts as alpha).
  const DampingScales ds = ForceOperatorDampingScales(sys);
  S.info.dt_stable = sys.Damped() ? RKDampedStabilityBound(s, A, b, S.info.omega_max_bound, ds.mass_rate, ds.stiffness)
                                  : ystar / S.info.omega_max_bound;
  PetscReal dt;
  PetscBool dt_set;
  PetscCall(TSGetTimeStep(S.ts, &dt));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_dt", &dt_set));
  if (!dt_set) PetscCall(TSSetTimeStep(S.ts, std::min(dt, 0.9 * S.info.dt_stable)));
  else if (S.fixed_step)
    PetscCheck(dt <= S.info.dt_stable, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-ts_dt %g is above the stability limit dt_max = %g s of -ts_type rk -ts_rk_type %s on this grid (N = "
               "%" PetscInt_FMT
               ", omega_max <= %g rad/s, set by %s%s); use -ts_dt <= %g, fewer nodes, or an implicit type",
               (double)dt, (double)S.info.dt_stable, rktype, S.P.sys->nodes, (double)S.info.omega_max_bound,
               BeamSystemPartWords(sys, S.info.omega_max_dof), sys.Damped() ? ", with the beam's Rayleigh damping" : "",
               (double)S.info.dt_stable);
  if (S.info.dt_stable <
      0.05 / S.info.omega_max_bound) { // strong damping: overdamped grid modes, dt_max far below 1/omega_max
    // An adaptive step let past dt_max there leaves those modes ringing from step to step (the
    // contact's rate of compression with them), which no event can be located on: cap it.
    TSAdapt adapt;
    S.dt_cap = std::min(S.dt_cap, 0.9 * S.info.dt_stable);
    PetscCall(TSGetAdapt(S.ts, &adapt));
    PetscCall(TSAdaptSetStepLimits(adapt, PETSC_DEFAULT, S.dt_cap));
  }
  PetscFunctionReturn(0);
}

// The integrator, its step and stability limit; and whether the step or the tolerance can
// resolve the contact (docs/stability.md: T_r/400 verified to 1e-3 in the ACOR). Said once,
// by the run that reports its set-up (not by every case of a sweep or study).
PetscErrorCode ReportSetup(TSStepper &S)
{
  const MPI_Comm  comm = S.P.L.comm;
  const PetscReal T = S.scales.time, dt = S.dt_nominal;

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "ts %s (%s)  dt %.3e s%s\n", S.info.ts_type.c_str(), S.info.formulation.c_str(),
                        (double)dt, S.fixed_step ? "" : " (initial; adaptive)"));
  if (S.info.dt_stable > 0)
    PetscCall(PetscPrintf(comm, "explicit stability limit dt_max %.4e s (omega_max <= %.4e rad/s, set by %s)\n",
                          (double)S.info.dt_stable, (double)S.info.omega_max_bound,
                          BeamSystemPartWords(*S.P.sys, S.info.omega_max_dof)));
  if (S.fixed_step && dt > T / 8)
    PetscCall(PetscPrintf(comm,
                          "WARNING: fixed step -ts_dt %g s is more than 1/8 of the contact time scale %g s: the "
                          "contact is poorly resolved and events may be missed\n",
                          (double)dt, (double)T));
  else if (S.fixed_step && dt > T / 100)
    PetscCall(PetscPrintf(comm,
                          "WARNING: fixed step -ts_dt %g s resolves the contact time scale %g s with only %.0f steps: "
                          "errors of 1e-3 or more in the ACOR are possible; use -ts_dt <= %.2e (T_r/400)\n",
                          (double)dt, (double)T, (double)(T / dt), (double)(T / 400)));
  // Adaptive explicit steps cannot stay above the stability limit (the error controller rejects
  // the growth): when dt_max is below T_r/100, the rule of the fixed-step warning, every step
  // resolves the contact whatever the tolerances (the bare default run, RK at dt_max = T_r/118,
  // has its ACOR within 2.1e-6 of the exact modal reference), and no tolerance warning is true.
  const bool stability_resolves = S.info.dt_stable > 0 && S.info.dt_stable <= T / 100;
  if (!S.fixed_step && !stability_resolves) {
    PetscReal atol, rtol;
    PetscCall(TSGetTolerances(S.ts, &atol, NULL, &rtol, NULL));
    if (rtol > 1e-4 || atol > 1e-3 * S.scales.compression)
      PetscCall(
        PetscPrintf(comm,
                    "WARNING: adaptive step with -ts_rtol %g -ts_atol %g cannot resolve the contact (compression scale "
                    "%.3g m, contact time %.3g s): errors of 1e-3 or more in the ACOR are possible; "
                    "use -ts_atol <= %.1e (1e-5 of the compression scale) and -ts_rtol <= 1e-6, or a fixed -ts_dt <= "
                    "%.2e (T_r/400)\n",
                    (double)rtol, (double)atol, (double)S.scales.compression, (double)T,
                    (double)(1e-5 * S.scales.compression), (double)(T / 400)));
  }
  PetscFunctionReturn(0);
}

// Beam undeformed with the velocities `beam_velocity` (per dof; empty: at rest), ball
// touching at the impact point moving in +y at `speed`.
PetscErrorCode SetInitialState(TSStepper &S, PetscReal speed, const std::vector<PetscReal> &beam_velocity)
{
  const TSLayout &L  = S.P.L;
  const PetscInt  nf = L.fields;
  TSStateWrite    o;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(S.U));
  PetscCall(TSStateWriteBegin(L, S.U, &o));
  if (o.ball) o.ball[0] = 0; // position: just touching
  if (o.ball && S.P.form != Formulation::SecondOrder) o.ball[1] = speed;
  if (!beam_velocity.empty() && S.P.form != Formulation::SecondOrder)
    for (PetscInt d = L.D0(); d < L.D1(); ++d) o.beam[(d / nf) * L.dof + nf + d % nf] = beam_velocity[d];
  PetscCall(TSStateWriteEnd(L, S.U, &o));
  if (S.P.form == Formulation::SecondOrder) {
    if (!S.V) PetscCall(VecDuplicate(S.U, &S.V));
    PetscCall(VecZeroEntries(S.V));
    PetscCall(TSStateWriteBegin(L, S.V, &o));
    if (o.ball) o.ball[0] = speed;
    if (!beam_velocity.empty())
      for (PetscInt d = L.D0(); d < L.D1(); ++d) o.beam[(d / nf) * L.dof + d % nf] = beam_velocity[d];
    PetscCall(TSStateWriteEnd(L, S.V, &o));
    PetscCall(TS2SetSolution(S.ts, S.U, S.V));
  } else PetscCall(TSSetSolution(S.ts, S.U));
  PetscCall(TSSetTime(S.ts, 0.0));
  PetscCall(TSSetStepNumber(S.ts, 0));
  PetscFunctionReturn(0);
}

// A new context: the layout, the TS of the type with the program's defaults and then the
// options, and the checks of what the options set.
PetscErrorCode TSContextBuild(MPI_Comm comm, TSStepper &S, const char *type, const TSStepperSettings &set)
{
  TSProblem &P = S.P;

  PetscFunctionBeginUser;
  PetscCall(
    TSLayoutCreate(comm, P.sys->nodes, P.sys->fields, P.sys->GhostNodes(), P.form != Formulation::SecondOrder, &P.L));
  PetscCall(CreateTS(S, type));
  PetscCall(ConfigureTS(S, type, set));
  PetscBool max_steps = PETSC_FALSE, max_time = PETSC_FALSE;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_max_steps", &max_steps));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_max_time", &max_time));
  PetscCheck(!max_steps && !max_time, comm, PETSC_ERR_ARG_INCOMP,
             "%s is not used here: the run's end is set by its events (the window after the last separation); use "
             "-impact_max_time (s) to cap the simulated time or -impact_window to shorten it",
             max_steps ? "-ts_max_steps" : "-ts_max_time");
  char *all = nullptr; // any -ts_monitor* option: TSSetFromOptions installed a monitor
  PetscCall(PetscOptionsGetAll(NULL, &all));
  S.monitored = S.C->monitored = all && std::strstr(all, "-ts_monitor");
  PetscCall(PetscFree(all));
  PetscReal atol, rtol;
  PetscCall(TSGetTolerances(S.ts, &atol, NULL, &rtol, NULL));
  for (auto tol : {std::make_pair("-ts_atol", atol), std::make_pair("-ts_rtol", rtol)}) {
    char value[64]; // PETSc's %g would write -1 as "-1."
    std::snprintf(value, sizeof value, "%g", (double)tol.second);
    PetscCheck(tol.second >= 0 && std::isfinite(tol.second), comm, PETSC_ERR_ARG_OUTOFRANGE,
               "%s %s is not allowed: an error tolerance must be finite and >= 0", tol.first, value);
  }
  PetscFunctionReturn(0);
}

// A context reused for this run: what ConfigureTS set from the run (the default step T_r/200
// and the cap T_r/8 from this ball's contact time, the Newton floor from this contact's
// omega_max) set again, what the options set (-ts_dt, -ts_adapt_dt_min/max) replayed; the
// Jacobian's contact term set for this contact point: the beam's factors (one per step size)
// are kept, the same numbers a fresh TS would factor (TSJacobianNewPoint); with -pc_type lu
// the assembled J is rebuilt (its pattern holds the coupled dofs) and factored anew.
PetscErrorCode TSContextReuse(TSStepper &S, const char *type)
{
  TSProblem       &P = S.P;
  const TSContext &C = *S.C;
  TSAdapt          adapt;
  PetscBool        fixed;

  PetscFunctionBeginUser;
  if (TSModalIsType(type))
    PetscCall(
      TSModalNewPoint(S.ts)); // -ts_type modal: the modes (shared), gamma and the static correction at this point
  if (P.form != Formulation::Explicit) {
    PetscCall(TSJacobianNewPoint(P, S.ts)); // the beam's factors kept; the contact point's vectors (or the assembled
                                            // J's pattern) anew
    S.newton_floor.omega2 = S.info.omega_max_bound * S.info.omega_max_bound;
  }
  if (P.form == Formulation::SecondOrder) { // alpha2: its restart's one-off check, as on a new TS
    GAlpha2Restart kind;
    PetscCall(TSGAlpha2GetRestart(S.ts, &kind));
    PetscCall(TSGAlpha2SetRestart(S.ts, kind));
  }
  S.dt_cap = S.scales.time / 8;
  PetscCall(TSSetTimeStep(S.ts, C.dt_from_options ? C.dt_option : S.scales.time / 200));
  PetscCall(TSGetAdapt(S.ts, &adapt));
  PetscCall(TSAdaptSetStepLimits(adapt, C.dt_min, C.dt_max_from_options ? C.dt_max : S.dt_cap));
  PetscCall(PetscObjectTypeCompare((PetscObject)adapt, TSADAPTNONE, &fixed));
  S.info.ts_type    = type;
  S.fixed_step      = fixed;
  S.info.fixed_step = fixed;
  S.monitored       = C.monitored;
  PetscFunctionReturn(0);
}

// The memory of a run's state on the grid of sys under the TS type (bytes), estimated before it
// is allocated: 320 B a node (the grid's own arrays) and a number of doubles a dof: the state and
// the stages, 40 (rk; 0 for alpha2's second-order form, 72 for arkimex and rosw, 100 for bdf:
// their stages and history), for an implicit type its Jacobian and factor, 11 (2 bw + 1) (bw the
// half-band in dofs; an upper bound on a string bed's wide band, whose factor is sparser), and
// for irk's s-stage system (s = 2) 30 s + 20 s^2 (2 bw + 1) more. Measured on uniform beams (PETSc
// 3.18, one rank, the growth of the peak resident memory from 1e5 to 4e5 nodes, Euler-Bernoulli:
// one dof a node, bw 2): rk 625 B a node (Timoshenko, two dofs: 940 B), alpha2 750, cn 1070,
// arkimex 1260, bdf 1580, irk 4600 B; the model gives 640 (960), 760, 1080, 1336, 1560, 4760 B.
// -ts_type modal's modes are estimated where they are computed (solvers/beam_modes.cpp).
double TSStepperMemory(const BeamSystem &sys, Formulation form, const char *type)
{
  const double dofs = (double)sys.nodes * sys.fields, band = 2.0 * sys.bw + 1, s = 2;
  double       per = 40; // doubles a dof
  if (form == Formulation::SecondOrder) per = 0;
  for (const char *t : {TSARKIMEX, TSROSW})
    if (!std::strcmp(type, t)) per = 72;
  if (!std::strcmp(type, TSBDF)) per = 100;
  if (form != Formulation::Explicit) per += 11 * band;
  if (!std::strcmp(type, TSIRK)) per += 30 * s + 20 * s * s * band;
  return 320 * (double)sys.nodes + per * sizeof(PetscReal) * dofs;
}

} // namespace

PetscErrorCode TSStepperCreate(const StepperProblem &p, const TSStepperSettings &set, std::unique_ptr<Stepper> *stepper,
                               IntegratorInfo *info)
{
  const MPI_Comm       comm   = p.comm;
  const BeamSystem    &sys    = *p.sys;
  const ContactScales &scales = p.scales;
  const BallParams    &ball   = p.ball;
  const char *const    type   = p.ts_type.c_str(); // the formulation depends on it (read by the run's set-up)
  std::string          key;

  PetscFunctionBeginUser;
  PetscCall(TSCheckTypeKnown(type, comm));
  // A run that checks its options builds its own TS (the check is of what that set-up read).
  const bool cacheable = !set.check_unused_options;
  if (cacheable && set.context_key && !set.context_key->empty()) key = *set.context_key;
  else if (cacheable) {
    PetscCall(TSContextKey(comm, sys, type, &key)); // every option of the database, joined and split
    if (set.context_key) *set.context_key = key;
  }
  std::shared_ptr<TSContext> C     = cacheable ? TSContextFind(key) : nullptr;
  const bool                 reuse = C != nullptr;
  if (!reuse) C = std::make_shared<TSContext>();
  C->finished         = false; // until this run's Counts
  auto       S        = std::make_unique<TSStepper>(C);
  TSProblem &P        = S->P;
  P.sys               = &sys;
  P.frame             = p.frame;
  P.g                 = p.g;
  P.ball              = ball;
  P.truncation        = p.truncation;
  P.contact           = p.contact;
  P.form              = FormulationOfType(type);
  P.jac.contact       = P.form == Formulation::Implicit || P.form == Formulation::SecondOrder;
  P.count             = TSCounters();
  S->scales           = scales;
  S->info.formulation = FormulationName(P.form);
  if (TSModalIsType(type))
    S->info
      .formulation = "modal (exact beam flow, polynomial contact force)"; // explicit right-hand side, exact beam flow
  S->info.omega_max_bound = BeamSystemMaxFrequencyBound(sys, p.g, scales.stiffness, ball.mass, &S->info.omega_max_dof);
  if (reuse) PetscCall(TSContextReuse(*S, type));
  else {
    char what[160];
    std::snprintf(what, sizeof what,
                  "-ts_type %s on %" PetscInt_FMT " nodes (%" PetscInt_FMT
                  " dofs: its state, and an implicit type's Jacobian and factor)",
                  type, sys.nodes, sys.nodes * sys.fields);
    PetscCall(MemoryCheck(comm, TSStepperMemory(sys, P.form, type), what, "use fewer -beam_nodes"));
    PetscCall(TSContextBuild(comm, *S, type, set));
  }
  PetscCall(ExplicitStability(*S));
  PetscCall(TSGetTimeStep(S->ts, &S->dt_nominal));
  PetscCheck(S->dt_nominal > 0 && std::isfinite(S->dt_nominal), comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-ts_dt %g is not allowed: the time step must be > 0 (s)", (double)S->dt_nominal);
  S->info.dt_nominal = S->dt_nominal;
  if (set.report_setup) PetscCall(ReportSetup(*S));
  PetscCall(SetInitialState(*S, ball.speed, *p.beam_velocity));
  if (reuse) PetscCall(TSRestartStep(S->ts)); // the last run's step history is not this run's
  S->damped = sys.Damped();
  if (S->damped) PetscCall(S->DissipationRestart());
  PetscCall(TSCumulativeCounts(S->ts, P.form, &S->counts0));
  if (cacheable && !reuse && !C->monitored) { // a monitor may keep state of its own: not reused
    C->key = key;
    PetscCall(TSContextKeep(C));
  }
  (reuse ? n_reused : n_built)++;
  *info    = S->info;
  *stepper = std::move(S);
  PetscFunctionReturn(0);
}

void TSStepperContextCounts(PetscInt *built, PetscInt *reused)
{
  *built  = n_built;
  *reused = n_reused;
}

PetscInt TSStepperBeamFactorizations() { return TSJacobianFactorizations(); }

PetscErrorCode TSStepperContextCacheClear()
{
  PetscFunctionBeginUser;
  context_cache.clear();
  PetscFunctionReturn(0);
}

} // namespace beamimpact

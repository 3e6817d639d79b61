// The exact modal reference of one impact. See modal_reference.hpp.
#include "run/modal_reference.hpp"

#include "run/scenario.hpp"
#include "solvers/modal_basis.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace beamimpact {

PetscErrorCode ModalReferenceRun(const Scenario &sc, ImpactResult *res)
{
  const BeamParams   &beam = sc.beam;
  const BallParams   &ball = sc.ball;
  const ImpactParams &ip   = sc.impact;
  BeamSystem          sys;
  std::string         why;
  ModalBasis          contact_basis, free_basis;

  PetscFunctionBeginUser;
  PetscCheck(ball.law == ContactLawKind::Linear, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "-reference modal needs -ball_law linear (the hysteretic law is nonlinear: use a tight run of a high-order integrator as the reference)");
  const double wall0 = MPI_Wtime();
  *res               = ImpactResult();
  res->x             = ip.x;
  res->ts_type       = "modal";
  res->formulation   = "exact";
  PetscCheck(BeamSystemBuild(beam, &sys, &why), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s", why.c_str());
  const ModalSystem S = ModalSystemBuild(sys, BeamSystemCoupling(sys, ip.x), ball.mass, ball.k);
  PetscCall(ModalBasisBuild(S, true, &contact_basis));
  PetscCall(ModalBasisBuild(S, false, &free_basis));

  const ImpactTimes times  = ImpactTimesOf(beam, ball, ip);
  const PetscReal   t_cap  = times.max_time;
  const PetscReal   s_min  = 1e-13 * ContactTimeScale(ball);
  const PetscReal   E0     = 0.5 * ball.mass * ball.speed * ball.speed;
  std::vector<PetscReal> q(S.n, 0.0), qd(S.n, 0.0);
  qd[S.n - 1]         = ball.speed;
  PetscReal  t        = 0;
  bool       touching = true;
  ModalPhase ph;
  res->contacts = 1;
  res->events.push_back({ContactEventKind::ContactStart, 0.0, 0.0, 0.0});
  auto energy = [&](bool in_contact) {
    std::vector<PetscReal> shape(sys.ndof, 0.0);
    PetscReal              T = 0, c = 0;
    for (PetscInt d = 0; d < S.n; ++d) {
      T += 0.5 * S.mass[d] * qd[d] * qd[d];
      c += S.g[d] * q[d];
      if (S.dof[d] >= 0) shape[S.dof[d]] = q[d];
    }
    return T + BeamSystemStrainEnergy(sys, shape.data(), sys.fields, 0, sys.ndof) + (in_contact ? 0.5 * S.k * c * c : 0.0);
  };
  for (;;) {
    ph.S = &S;
    ph.B = touching ? &contact_basis : &free_basis;
    ph.From(q, qd);
    if (touching) {
      PetscReal s_sep;
      PetscCheck(ModalFirstCrossing(ph, 0, +1.0, t_cap - t, s_min, &s_sep), PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "modal reference: the ball is still in contact at -impact_max_time %g s", (double)t_cap);
      // Maximum compressions: dc/dt falling through 0 before the separation.
      PetscReal s = 0, s_max;
      ModalPhase rate = ph;
      while (ModalFirstCrossing(rate, 1, +1.0, s_sep - s, s_min, &s_max)) {
        s += s_max;
        const PetscReal c = ph.Derivative(s, 0);
        res->events.push_back({ContactEventKind::MaxCompression, t + s, c, ball.k * c});
        res->max_compression = std::max(res->max_compression, c);
        // Continue after this maximum: restart the search from the state at s.
        std::vector<PetscReal> qs, qds;
        ph.State(s, qs, qds);
        rate.From(qs, qds);
        // Skip to where dc/dt rises again (a local minimum), then look for the next maximum.
        PetscReal s_min_c;
        if (!ModalFirstCrossing(rate, 1, -1.0, s_sep - s, s_min, &s_min_c)) break;
        s += s_min_c;
        ph.State(s, qs, qds);
        rate.From(qs, qds);
      }
      ph.State(s_sep, q, qd);
      t += s_sep;
      res->events.push_back({ContactEventKind::Separation, t, 0.0, 0.0});
      touching = false;
    } else {
      const PetscReal t_stop = std::min(t_cap, t + times.window);
      PetscReal       s_con;
      if (ModalFirstCrossing(ph, 0, -1.0, t_stop - t, s_min, &s_con)) {
        ph.State(s_con, q, qd);
        t += s_con;
        res->contacts++;
        PetscCheck(res->contacts <= ip.max_contacts, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "modal reference: more than -impact_max_contacts %" PetscInt_FMT " contacts", ip.max_contacts);
        res->events.push_back({ContactEventKind::ContactStart, t, 0.0, 0.0});
        touching = true;
      } else {
        ph.State(t_stop - t, q, qd);
        t = t_stop;
        break;
      }
    }
  }
  // Contact times from the event list.
  PetscReal start = 0;
  bool      first = true;
  for (const ContactEvent &e : res->events) {
    if (e.kind == ContactEventKind::ContactStart) start = e.time;
    if (e.kind == ContactEventKind::Separation) {
      if (first) res->contact_time = e.time - start;
      first = false;
      res->contact_time_total += e.time - start;
    }
  }
  res->peak_force          = ball.k * res->max_compression;
  res->final_time          = t;
  res->ball_final_velocity = qd[S.n - 1];
  res->acor                = -qd[S.n - 1] / ball.speed;
  res->acor_corrected      = res->acor * ball.loss_factor;
  res->energy_error        = (energy(false) - E0) / E0;
  {
    std::vector<PetscReal> shape(sys.ndof, 0.0);
    PetscReal              T = 0;
    for (PetscInt d = 0; d + 1 < S.n; ++d) {
      T += 0.5 * S.mass[d] * qd[d] * qd[d];
      shape[S.dof[d]] = q[d];
    }
    res->beam_kinetic_end = T;
    res->beam_strain_end  = BeamSystemStrainEnergy(sys, shape.data(), sys.fields, 0, sys.ndof);
  }
  res->wall_time = MPI_Wtime() - wall0;
  PetscFunctionReturn(0);
}

} // namespace beamimpact

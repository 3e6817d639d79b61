// Timoshenko beam as a beam theory (model/beam_theory.hpp): two fields per node, the
// deflection w (m) and the section rotation psi (rad),
//
//   rho A w_tt   = (kappa G A (w' - psi))' + f
//   rho I psi_tt = (EI psi')' + kappa G A (w' - psi)
//
// on linear elements [x_i, x_i+1] with one-point (midpoint) integration of both terms, which
// is exact for the bending term and keeps the shear term free of locking:
//
//   U = 1/2 sum_e h [ EI_e ((psi_i+1 - psi_i)/h)^2 + kGA_e ((w_i+1 - w_i)/h - (psi_i + psi_i+1)/2)^2 ]
//
// with the element's mean section (exact integrals of the profile), and lumped masses rho A h
// and rho I h shared half to each end node of an element. Free ends need nothing (natural
// conditions); a node holds what its support holds (model/support.hpp): a clamped node w and
// psi, a pinned node w only, a guided one psi only. The frequencies converge at second order in
// h, and the fastest wave is a shear or bar wave: omega_max ~ 2 sqrt(E/rho)/h, an explicit step limit
// that grows like h rather than h^2.
#include "model/beam_theory.hpp"

#include <cmath>

namespace beamimpact {

void TimoshenkoBuild(const BeamParams &p, BeamDiscretization *d)
{
  const PetscInt              N    = p.nodes;
  const PetscReal             h    = p.length / (N - 1);
  const std::vector<NodeHold> hold = BeamNodeHolds(p);
  d->fields                        = 2;
  d->mass.assign(2 * N, 0.0);
  d->held.assign(2 * N, 0);
  d->strain.clear();
  d->frequency_unit = std::sqrt(p.EI / p.mu) / (p.length * p.length);
  for (PetscInt i = 0; i < N; ++i) {
    d->held[2 * i]     = HoldsDeflection(hold[i]); // what the supports hold (model/support.hpp)
    d->held[2 * i + 1] = HoldsRotation(hold[i]);
  }
  for (PetscInt e = 0; e < N - 1; ++e) {
    const SectionProperties s  = BeamSectionMean(p, e * h, (e + 1) * h);
    const PetscInt          w0 = 2 * e, p0 = 2 * e + 1, w1 = 2 * e + 2, p1 = 2 * e + 3;
    d->mass[w0] += 0.5 * s.mu * h;
    d->mass[w1] += 0.5 * s.mu * h;
    d->mass[p0] += 0.5 * s.rhoI * h;
    d->mass[p1] += 0.5 * s.rhoI * h;

    StrainTerm bend;
    bend.n      = 2;
    bend.owner  = w0;
    bend.dof[0] = p0, bend.dof[1] = p1;
    bend.b[0] = -1.0 / h, bend.b[1] = 1.0 / h;
    bend.weight = s.EI * h;
    if (!(d->held[p0] && d->held[p1])) d->strain.push_back(bend);

    StrainTerm shear;
    shear.n      = 4;
    shear.owner  = w0;
    shear.dof[0] = w0, shear.dof[1] = p0, shear.dof[2] = w1, shear.dof[3] = p1;
    shear.b[0] = -1.0 / h, shear.b[1] = -0.5, shear.b[2] = 1.0 / h, shear.b[3] = -0.5;
    shear.weight = s.kGA * h;
    if (!(d->held[w0] && d->held[p0] && d->held[w1] && d->held[p1])) d->strain.push_back(shear);
  }
}

} // namespace beamimpact

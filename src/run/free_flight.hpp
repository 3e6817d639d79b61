// After a separation: the exact free vibration of the beam and the free flight of the ball
// (docs/model.md, "After separation"), instead of integrating them in time (-impact_after modal).
//
// The state at the separation is projected on the beam's modes (solvers/beam_modes.hpp,
// computed once per beam), so that in closed form
//   y(t0 + s) = M^{-1/2} sum_k phi_k z_k(s),   y_b(t0 + s) = y_b0 + v_b0 s,
// every z_k an exact (damped) free vibration or rigid motion. The compression
//   c(s) = y_b(s) - (w0 y_d0 + w1 y_d1)(s) = y_b0 + v_b0 s - sum_k gamma_k z_k(s)
// is negative while separated; the next contact is its first root. The search excludes
// roots rigorously: with f = -c > 0 at s, f'(s), L1 >= sup |c'| = |v_b0| + sum |gamma_k| sup |z_k'|
// and L2 >= sup |c''| = sum |gamma_k| sup |z_k''|, f has no root on [s, s + d) for
//   d = max( f / L1,  (f' + sqrt(f'^2 + 2 L2 f)) / L2 )
// (the first from f(s + u) >= f - L1 u, the second from f(s + u) >= f + f' u - L2 u^2 / 2);
// the search steps by d (less a round-off margin) and cannot step over a root, which it then
// brackets and bisects to round-off. sup |z_k^(p)| is the bound of the mode's energy, which
// never grows (ModalModeBound).
#pragma once

#include "run/impact.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/stepper.hpp"
#include "system/beam_system.hpp"

#include <memory>
#include <vector>

namespace beamimpact {

struct FreeFlight {
  std::shared_ptr<const BeamModes> modes;
  std::vector<PetscReal>           gamma; // per mode: its share of the deflection at the impact point
  std::vector<PetscReal>           z, zd; // modal coordinates and velocities at s = 0
  PetscReal                        t0 = 0, yb0 = 0, vb0 = 0; // s, m, m/s at s = 0
  PetscReal dissipated0 = 0, energy0 = 0; // J: dissipated by the beam's damping by t0, the beam's energy at t0
  PetscReal L1 = 0, L2 = 0;               // bounds on |c'|, |c''| over s >= 0
  PetscInt  evals = 0;                    // evaluations of c by the search
};

// The whole state of the stepper on every rank (beam dofs in dof order, held dofs 0).
PetscErrorCode StepperGatherState(Stepper &st, const BeamSystem &sys, FullState *s);

// Projects the state s at time t0 on the modes; g: the ball's coupling.
void FreeFlightStart(std::shared_ptr<const BeamModes> modes, const ContactCoupling &g, PetscReal t0, const FullState &s,
                     FreeFlight *ff);

// The same from a state already in those modes (the stepper's own, Stepper::GetModalState): O(modes).
void FreeFlightStartModal(std::shared_ptr<const BeamModes> modes, const ContactCoupling &g, PetscReal t0,
                          const ModalState &s, FreeFlight *ff);

// d^p c / ds^p at s (p = 0, 1, 2); *mag (if given): the sum of the magnitudes of its terms.
PetscReal FreeFlightCompression(const FreeFlight &ff, PetscReal s, int p, PetscReal *mag = nullptr);

// The first s in (0, s_end] where c rises to 0 (the beam comes back); false if none. Roots
// closer than s_min to s = 0 are the separation itself and are stepped over.
bool FreeFlightFirstContact(FreeFlight &ff, PetscReal s_end, PetscReal s_min, PetscReal *root);

// The exact state at s (time t0 + s).
void FreeFlightState(const FreeFlight &ff, PetscReal s, FullState *out);
// The same in the modes (O(modes), for Stepper::SetModalState).
void FreeFlightModalState(const FreeFlight &ff, PetscReal s, ModalState *out);

// The energy each kept mode carries at s (ModeEnergy: frequency, energy, rigid; the fraction is
// the outcome's). Their sum is the beam's kinetic and strain energy of FreeFlightState(ff, s).
// O(modes kept): cheap beside the projection FreeFlightStart did.
std::vector<ModeEnergy> FreeFlightModeEnergies(const FreeFlight &ff, PetscReal s);

} // namespace beamimpact

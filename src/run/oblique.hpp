// The oblique impact in a run (docs/model.md "Oblique impacts", MODEL section 10): an impact
// with -impact_offset D or -ball_spin not 0 (or -flight) is split along the contact's fixed
// normal n and tangent t (model/oblique.hpp):
//
//   * along n, the existing impact on the flexible bat, any law, any integrator: the run's
//     scenario with the ball's and the swing's speeds projected on n (times cos theta; exactly
//     today's run head-on, cos theta = 1);
//   * along t, the friction force, driven by that run's normal force F_n(t) (the run records the
//     ball's series for it, F_n and dF_n/dt at every step: the cubic Hermite between them), on
//     the ball (translation and spin), the bat's roll about its axis (free bat: the profile's
//     polar inertia 2 int rho I dx; otherwise held) and the bat in its second plane:
//       - flexible (-impact_tangential_plane flexible, the default): the same beam system in the
//         same modes (solvers/beam_modes: -modal_modes, -modal_tolerance, the static
//         correction), driven at the impact point by -F_t and moving with the swing's component
//         along t (model/oblique.hpp, TangentialPlane). For a round, straight bat the planes
//         decouple and F_n does not depend on the tangential motion, so this second run is
//         exact for the model given F_n(t); it needs a beam the modes carry (no -grip) and no
//         damping (refused otherwise, naming the rigid plane);
//       - rigid: its effective mass at the impact point (free bat: Eq. 11's M_e; a rig free
//         about its pivot: I_p / (x - x_p)^2; otherwise held).
// On a racket's string bed (-impact_angle, or -ball_spin with the point inside the head's outline;
// docs/model.md section 13, "On the string bed"; MODEL.md section 17) the face is flat: n is the
// bed's normal, t the face's z (across the mains), the ball's path at -impact_angle from n; along n
// the run at v cos(angle) (the racket's swing is along n already), along t the tangential contact
// on the bed in its own plane (model/oblique.hpp, BedInPlaneModel): the mains under the ball
// sliding sideways on the frame's rigid motion along t (held, or its effective mass there); with
// -impact_tangential_plane rigid the mains locked (the rigid-surface model on the frame's mass).
// The exit is in the bed's frame: the launch angle from the normal, > 0 toward +z.
// These are the first stage after the contact (run/stages/tangential.cpp); then, with -flight,
// the next (run/stages/flight.cpp): the batted ball's flight (solvers/flight_ts.hpp) from the exit speed,
// launch angle and spin.
#pragma once

#include "model/flight.hpp"
#include "model/oblique.hpp"
#include "model/swing.hpp"
#include "solvers/beam_modes.hpp"
#include "solvers/flight_ts.hpp"
#include "system/beam_system.hpp"

#include <petscsys.h>

#include <memory>
#include <vector>

namespace beamimpact {

struct Scenario;
struct ImpactSeries;
struct StageResult;

// -flight after an impact: the flight's ball, air and aerodynamics (-flight_*, -air_*; the
// launch comes from the impact).
struct FlightAfterImpact {
  PetscBool         on = PETSC_FALSE;
  FlightParams      params;
  FlightSolveParams solve;
};

// The incoming impact of a run whose scenario was projected on the normal (on: projected).
struct ObliqueIncoming {
  bool            on         = false;
  PetscReal       ball_speed = 0; // m/s, as given
  SwingParams     swing;          // as given
  ObliqueGeometry geometry;
  PetscReal       bat_radius = 0;     // m, at the impact point
  bool            bed        = false; // on a string bed: n its normal, t its z (the bed's frame)
  PetscReal       angle      = 0;     // rad, on a bed: the ball's path from n (-impact_angle)
};

// What the stages after the contact (run/stage.hpp) hand the outcome: the tangential contact and
// the exit, and each stage's own result.
struct ObliqueRecord {
  bool             on = false;
  ObliqueGeometry  geometry;
  TangentialModel  model;
  TangentialBodies before, after;
  TangentialState  contact;
  ObliqueExit      exit;
  bool             flexible = false;      // the bat's second plane in its modes (else rigid, or no tangential force)
  TangentialPlane  plane;                 // flexible: its state after the contact
  PetscInt         plane_rigid_modes = 0; // flexible: the rigid modes among plane.omega (the first)
  PetscReal        plane_vibration   = 0; // J, flexible: the energy of its flexible modes after the contact
  PetscReal
    plane_damped = 0; // J, flexible: the energy the beam's damping took in that plane up to the end of the contact
  PetscReal       plane_momentum0 = 0, plane_momentum = 0; // N s, flexible: the bat's momentum along t before and after
  bool            bed = false;         // on a string bed: the plane is bed_plane (the mains on the frame)
  BedInPlaneModel bed_plane;           // bed: the frame's mass, the mains' stiffness and mass in the face's plane
  PetscReal       bed_slide_peak  = 0; // m, bed (flexible): the mains' largest slide from the frame, at the run's steps
  PetscReal       bed_energy_peak = 0; // J, bed (flexible): the energy of their vibration on the frame at most
  // The stages after the contact (run/stage.hpp): each registered stage's own result, in the
  // registry's order (nullptr: it did not run), the flight's (-flight) among them.
  std::vector<std::shared_ptr<const StageResult>> stages;
};

// Whether the impact is oblique: -impact_offset, -impact_angle or -ball_spin not 0, or -flight.
bool ObliqueImpact(const Scenario &sc);

// The scenario of the run along the normal: checks the geometry (a round section at the impact
// point, -ball_radius, |D| < R_b + R_bat; on a string bed -ball_radius and no -impact_offset;
// -impact_angle only there) and projects the ball's and the swing's speeds.
PetscErrorCode ObliqueNormalScenario(MPI_Comm comm, const Scenario &sc, Scenario *normal);

// The beam of the run along the normal, for the flexible second plane.
struct ObliqueBeam {
  MPI_Comm               comm = PETSC_COMM_SELF; // the run's (the modes are computed collectively on it)
  const BeamSystem      *sys  = nullptr;
  const ContactCoupling *g    = nullptr;
  ModalTruncation        truncation; // -modal_modes, -modal_tolerance, with the contact's time scale
};

// The bat's second plane in the modes of beam's system (TangentialPlane: the modes, the point's
// share of each, the static correction of a truncated basis), moving with velocity (m/s per dof
// along t; empty: at rest); rigid: the rigid modes among them (the first). Refuses a beam the
// modes cannot carry (a grip), naming -impact_tangential_plane rigid; a damped beam decays in its modes.
PetscErrorCode ObliquePlaneBuild(const ObliqueBeam &beam, const std::vector<PetscReal> &velocity, TangentialPlane *p,
                                 PetscInt *rigid);
// The plane's momentum along t (N s) and its angular momentum about x = 0 in that plane (N m s,
// sum m_d x_d v_d over the translational dofs, a registered part's point masses (an absorber)
// among them: a Timoshenko section's spin is left out).
PetscErrorCode ObliquePlaneMomenta(const ObliqueBeam &beam, const TangentialPlane &p, PetscReal *P, PetscReal *L);

// After the run along the normal (sc: its projected scenario; series: its ball series, F_n at
// every step): the tangential contact and the exit (the tangential stage's work).
PetscErrorCode ObliqueFinish(const Scenario &sc, const ImpactSeries &series, PetscReal ball_normal_speed_end,
                             const ObliqueBeam &beam, ObliqueRecord *rec);

} // namespace beamimpact

// One ball-beam impact as a PETSc TS problem (docs/model.md).
//
// State: the beam on a 1-D DMDA (y, v per node; or y only for alpha2) and the
// ball (y_b, v_b; or y_b only) on a DMRedundant, packed in a DMComposite.
// The ball starts touching the beam at x_imp with speed v_i; contact start,
// maximum compression (loading -> unloading) and separation are events located
// by rollback and re-stepping onto the root (so the integrator's own state is
// on the event, not an interpolant), after which the integrator restarts. The
// run continues for a post-contact window after each separation so that a
// double impact is caught (by default not stepped: the beam's exact free vibration in its
// modes, run/free_flight.hpp), and the ACOR is the ball's final speed.
#pragma once

#include "model/beam.hpp"
#include "model/contact.hpp"
#include "solvers/stepper.hpp"
#include "system/beam_system.hpp"

#include <petscsys.h>

#include <cmath>
#include <memory>

#include <string>
#include <vector>

namespace beamimpact {

// How the run follows the beam and the ball after a separation (-impact_after): integrated in
// time by the stepper, or the exact free vibration in the beam's modes (run/free_flight.hpp).
enum class ImpactAfter {
  Time  = 0,
  Modal = 1
};
const char *ImpactAfterName(ImpactAfter a);

// -impact_* options.
struct ImpactParams {
  ImpactAfter after     = ImpactAfter::Modal; // modal wherever the beam allows it (else time, saying why)
  PetscBool   after_set = PETSC_FALSE;        // -impact_after was given: modal where it cannot be is an error
  PetscReal   x         = 0.55;               // m, impact point measured from the x = 0 end
  PetscReal   z = 0; // m, -impact_z: across the face from the frame's axis (a racket's off-centre hit; 0: on the axis)
  PetscReal   offset = 0; // m, -impact_offset: the ball's line of flight above the bat's axis (0: head-on)
  PetscReal   angle  = 0; // deg, -impact_angle: a string bed's oblique impact, the ball's path from the face's normal
  PetscBool   tangential_rigid = PETSC_FALSE; // -impact_tangential_plane rigid: the bat rigid in its second plane
                                              // (default flexible, run/oblique.hpp)
  PetscReal
    window = -1; // s, time simulated after each separation (-1: not given, 2 fundamental periods; a given one is >= 0)
  PetscReal max_time      = -1; // s, cap on the simulated time (< 0: window + 100 contact times)
  PetscReal full_max_time = 0;  // s, not an option: 0, or this run is a probe capped by max_time (a sweep's 1 ns) and
                                // the cost estimates are a full point's, capped by full_max_time (< 0: the default cap)
  PetscReal event_tol            = 1e-10;       // event indicators (c / c_scale, dc/dt / v_i) are located to this
  PetscInt  max_contacts         = 50;          // a run with more separate contacts stops with an error
  PetscBool energy_check         = PETSC_FALSE; // stop when the total energy grows beyond -impact_energy_growth_tol
  PetscReal energy_growth_tol    = 1e-3;        // relative to the incident kinetic energy
  PetscBool check_unused_options = PETSC_FALSE; // not an option: the task asks for the check once the TS is set up
  PetscBool
    report_setup = PETSC_FALSE; // not an option: print the integrator, its step and stability limit before the run
  // With report_setup: a cost estimate before a run expected to take more than cost_warn s of
  // wall time, and a progress line every `progress` s of wall time (0: none).
  PetscReal cost_warn = 30, progress = 10;       // s, -impact_cost_warn, -impact_progress
  PetscBool strict_solver_options = PETSC_FALSE; // not an option: left-over PETSc solver options are errors (a study's
                                                 // configuration)
  PetscReal rigid_loss_fraction = 0; // not an option here: f of Eq. (11) for the rigid_acor column (a sweep's
                                     // -rigid_loss_fraction; 0 for -task impact)
  // Not an option: the energy of each kept mode at the end (/modes_energy of -task impact's file);
  // a sweep's points keep no file of their own and skip it.
  PetscBool mode_energies = PETSC_TRUE;
};

// What to record during the run (nothing by default): -monitor_* and -snapshot_times.
struct MonitorRequest {
  PetscBool              ball   = PETSC_FALSE;     // ball position, velocity, compression, force per step
  PetscBool              energy = PETSC_FALSE;     // energy terms per step
  std::vector<PetscReal> velocity_at;              // m, beam velocity at these points per step
  std::vector<PetscReal> snapshot_times;           // s, beam displacement y(x) at these times (stepped onto exactly)
  PetscBool              segment    = PETSC_FALSE; // kinetic energy of the beam segment [segment_x0, segment_x1]
  PetscReal              segment_x0 = 0, segment_x1 = 0; // m
  PetscReal              segment_until = -1; // s, the segment's peak is taken over t <= this (< 0: whole run)
  // A structure part present had its own monitor row given (StructurePart::Monitors: the hands'):
  // its series per step.
  bool parts = false;
  bool any() const { return ball || energy || !velocity_at.empty() || segment || parts; }
};

// Per-step time series (rank 0 holds them; only the requested ones are filled).
struct ImpactSeries {
  std::vector<PetscReal> time;                               // s
  std::vector<PetscReal> ball_y, ball_v, compression, force; // m, m/s, m, N
  // N/s, dF/dt at each step (the law's dF/dc times dc/dt; at a separation, on the branch the ball
  // left by): with force, the cubic Hermite F_n(t) an oblique impact's tangential contact takes.
  // Recorded with force, not written to the output.
  std::vector<PetscReal> force_rate;
  std::vector<PetscReal> ball_kinetic, ball_stored, ball_dissipated; // J
  std::vector<PetscReal> beam_kinetic, beam_strain, total_energy;    // J
  std::vector<PetscReal> beam_dissipated;                            // J, by the beam's damping (damped beams only)
  // J, [account][step]: the energy of each present part's account with a series of its own
  // (StructurePart::AccountSeries: the string bed's bed_energy, the roll's twist_energy, in beam_*;
  // the barrel wall's shell_energy, kept apart from beam_*).
  std::vector<std::vector<PetscReal>> account_energy;
  std::vector<PetscReal>              velocity_at_x;   // m, the points of velocity_at
  std::vector<std::vector<PetscReal>> velocity_at;     // m/s, [point][step]
  std::vector<PetscReal>              segment_kinetic; // J, kinetic energy of the monitored segment
  std::vector<PetscReal>              snapshot_time;   // s
  std::vector<std::vector<PetscReal>> snapshot_y;      // m, [snapshot][node]
  // The present parts' own fields (StructurePart::Snapshot: the barrel wall's W_n, the string bed's
  // deflection from its frame), in registry order: each [snapshot][values as its spec lays them
  // out] (rank 0), its labels and the spec /snapshots writes them by.
  struct PartSnapshots {
    PartSnapshotSpec                    spec;
    const StructurePart                *part = nullptr;
    std::vector<std::vector<PetscReal>> values;
    std::vector<PetscInt>               labels;
  };
  std::vector<PartSnapshots> snapshot_parts;
  // The registered structure parts' series (system/structure_part.hpp: a slot with `series`,
  // under -monitor_energy): /series/<name> in its unit, one value per step.
  struct Keyed {
    std::string            name, unit;
    std::vector<PetscReal> values;
    std::string            dim; // the series it is on ("": time; a stage's own axis, e.g. flight_time)
  };
  std::vector<Keyed> keyed;
};

enum class ContactEventKind {
  ContactStart   = 0,
  MaxCompression = 1,
  Reload         = 2,
  Separation     = 3
};
const char *ContactEventName(ContactEventKind k);

struct ContactEvent {
  ContactEventKind kind;
  PetscReal        time;        // s
  PetscReal        compression; // m
  PetscReal        force;       // N
  // Contact start only (0 on the other events): the approach speed dc/dt at the impact point
  // (m/s), and the wall coefficient of restitution e and unloading exponent n the hysteretic
  // law uses for this contact (from -ball_cor_table at that speed, else the ball's fixed
  // ones; the linear law: e = 1, n = 0).
  PetscReal approach_speed = 0, cor = 0, n = 0;
};

// What the contact events record for the outcome (run/events.cpp writes it, run/outcome.cpp
// reads it): every located event, the contacts and their durations, the largest force and
// compression at a maximum-compression event.
struct ContactTally {
  std::vector<ContactEvent> events;
  PetscInt                  contacts           = 0; // separate contacts
  PetscReal                 contact_time       = 0; // s, duration of the first contact
  PetscReal                 contact_time_total = 0; // s, summed over all contacts
  PetscReal                 peak_force         = 0; // N
  PetscReal                 max_compression    = 0; // m
  bool touching = false; // the run ended with the ball still in contact (its contact closed at the end)
};

// What the monitors record for the outcome (run/monitors.cpp): the peaks over the steps.
struct MonitorPeaks {
  PetscReal segment_kinetic = 0, segment_kinetic_time = 0; // J, s: -monitor_segment
  PetscReal frame_force = 0, frame_force_time = 0; // N, s: the largest |force of the bat on the swing's frame| (-grip)
  // The accounts kept apart (the barrel wall, -barrel_hoop_frequency or -beam_shell): their largest
  // displacement under the ball (m, into the bat) over the steps (its energy's: its account's); NaN
  // where no stepper measured it (the modal reference).
  PetscReal apart_deflection = NAN;
  // The face (a racket's string bed, -strings_frame): its largest deflection from the frame (m) over the steps;
  // each energy account's largest energy (J, StateMeasures::account_energy: a present part's own); NaN
  // where no stepper measured them (the modal reference).
  PetscReal face_deflection              = NAN;
  PetscReal account_energy[kMaxAccounts] = {NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  static_assert(kMaxAccounts == 8, "account_energy's initialiser");
  // The registered structure parts' slots with `peak` (system/structure_part.hpp): the largest
  // |value| over the steps, by slot (StateMeasures::part_slot); NaN where not measured.
  PetscReal part_peak[kMaxPartSlots] = {NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  static_assert(kMaxPartSlots == 8, "part_peak's initialiser");
};

// The scales of one impact, for studies that judge a step or a run against them (the stability
// study reads them from the file's root attributes instead of re-deriving them; the ball's
// rigid-wall values are in the run record, from its law: ball_wall_contact_time, ball_wall_cor).
struct ImpactScales {
  PetscReal contact_time_scale = 0; // s, T_r: the contact time against the beam's free mass (ContactScales::time)
  PetscReal compression_scale  = 0; // m, the compression scale of the event indicators (ContactScales::compression)
};

// The result of one impact (identical on every rank of the communicator), in three parts
// that travel separately: the physical outcome, what it cost, and how it was integrated;
// plus the located events, the requested time series and the impact's scales. ImpactResult
// derives from the three so that a column reads r.acor or r.steps directly.
//
// The outcome is the storage of the results table (run/results_table.hpp: every column's name,
// unit, description, when it applies and how it is computed, defined once there), written only
// by run/outcome.cpp. A quantity that does not apply to the scenario is NaN, never a number a
// reader could take for a value (the table says where). The units below are the table's.
struct ImpactOutcome {
  PetscReal x                         = 0;           // m
  PetscReal acor                      = 0;           // -v_b,final / v_i
  PetscReal acor_corrected            = 0;           // acor * loss factor (linear spring); = acor for hysteresis
  PetscReal contact_time              = 0;           // s, duration of the first contact
  PetscReal contact_time_total        = 0;           // s, summed over all contacts
  PetscReal peak_force                = 0;           // N
  PetscReal max_compression           = 0;           // m
  PetscInt  contacts                  = 0;           // separate contacts
  PetscReal ball_final_velocity       = 0;           // m/s
  PetscReal final_time                = 0;           // s, simulated
  PetscBool ended_in_contact          = PETSC_FALSE; // the run hit -impact_max_time while touching
  PetscBool compression_beyond_radius = PETSC_FALSE; // max_compression > -ball_radius (given): physically absurd
  // Invariants at the end (relative to the incident kinetic energy / momentum). The momenta
  // only where they are invariants (no held dof, no grip, no mass-proportional damping).
  PetscReal
    energy_in = 0; // J, E_in: the ball's 1/2 m_b v_i^2 and a swinging bat's kinetic energy, the fractions' denominator
  PetscReal energy_error           = 0; // (E_end - E_0) / E_0, E including the ball's work W
  PetscReal linear_momentum_error  = 0; // (p_end - p_0) / (m_b v_i)
  PetscReal angular_momentum_error = 0; // about x = 0, / (m_b v_i L)
  PetscReal beam_kinetic_end = 0, beam_strain_end = 0, ball_dissipated_end = 0; // J
  PetscReal ball_kinetic_end = 0; // J, the ball's rebound kinetic energy 1/2 m_b v_b,final^2
  // The energy the beam's damping (Rayleigh, and a grip's damper) dissipated by the end (J; it is
  // in energy_error's E; 0 for an undamped beam), and as a fraction of the incident kinetic energy.
  PetscReal beam_dissipated_end = 0, damping_fraction = 0;
  // Where the energy brought in (E_in: the ball's and a swinging bat's kinetic energy) went, as
  // fractions of it, at the end of the run (docs/model.md section 4; with damping_fraction, the
  // roll's fraction below and the parts' own, they add up to 1): lost
  // in the ball (hysteresis; for an elastic law 1 - loss_factor^2 of the rebound energy), the
  // ball's rebound (an elastic law: loss_factor^2 of it), the structure's rigid translation P^2/2M
  // and rotation (about its centre of mass, or its pin), and its bending vibration (the beam's
  // energy less its share of the rigid motions).
  PetscReal ball_loss_fraction = 0, rebound_fraction = 0, translation_fraction = 0, rotation_fraction = 0,
            vibration_fraction = 0;
  // The bat in play: the batted-ball speed (m/s, away from the bat, lab frame), the collision
  // efficiency q = (bbs - V(x)) / (v_ball + V(x)) (= acor for a bat at rest); a beam with no held
  // dof: its recoil, the centre-of-mass speed (m/s, toward the ball) and angular velocity
  // (rad/s) at the end; a rig free about its pivot (-beam_pivot, no other support): its recoil
  // factor r and BBCOR = e_A (1 + r) + r.
  PetscReal bbs = 0, collision_efficiency = 0, bat_speed_end = 0, bat_angular_velocity_end = 0;
  PetscReal recoil_factor = 0, bbcor = 0;
  // With -monitor_segment: the peak kinetic energy (J) of the segment and when (s).
  PetscReal segment_kinetic_peak = 0, segment_kinetic_peak_time = 0;
  // A racket (-beam_torsion): a free frame's roll rate at the end (rad/s) and its rigid roll energy
  // L_x^2 / 2 I_x as a fraction of E_in; the angular momentum about the frame's axis, its change over
  // the run / (m_b v_i L). (The wall's, the bed's and the roll's own columns are their parts'.)
  PetscReal roll_rate_end = 0, roll_fraction = 0, roll_momentum_error = 0;
  // The rigid-body model, Eq. (11), for a free beam at rest (no support, pivot, grip or swing):
  // its ACOR with the loss fraction ImpactParams::rigid_loss_fraction, and the loss fraction
  // for which it gives acor_corrected (the forced fit).
  PetscReal rigid_acor = 0, rigid_forced_loss_fraction = 0;
};

// The stepper's own counts, and the driver's.
struct ImpactCost : StepperCounts {
  PetscInt  steps = 0, event_steps = 0; // accepted steps; extra steps to locate events
  PetscReal wall_time = 0;              // s, time stepping only
};

// Where the impact's energy went, mode by mode (docs/model.md §12): after the ball has left, at
// the end of a run whose free flight is modal, the energy each kept mode of the beam carries,
// 1/2 (zd^2 + w^2 z^2) in mass-normalised coordinates. A rigid mode (frequency 0) carries its
// kinetic energy: of a beam with no held dof, the translation P^2/2M and the rotation
// L_cm^2/2I_cm about the centre of mass, in that order.
struct ModeEnergy {
  PetscReal frequency = 0;     // Hz (0: a rigid mode)
  PetscReal energy    = 0;     // J
  PetscReal fraction  = 0;     // 1: energy / E_in, the energy brought in (the outcome's)
  bool      rigid     = false; // a rigid mode
  // What it is (run/energy_parts.hpp): a rigid mode's motion ("translation", "rotation", "roll"),
  // a flexible one's part as -task modes names it ("bending", "roll", "wall", "strings"); the
  // modes of one label add up to the matching fraction column.
  const char *part = "";
};

// The modal engine a run used (the free flight's basis, else -ts_type modal's, else the truncated
// reference's): the modes kept of the free dofs and the cut-off (docs/model.md §12). kept = 0:
// none; cutoff NaN where no cut-off chose them (-modal_modes all or K).
struct ModalEngineUse {
  PetscInt  kept = 0, free_dofs = 0;
  PetscReal cutoff = 0; // Hz
};

struct ImpactResult : ImpactOutcome, ImpactCost, IntegratorInfo {
  ModalEngineUse modal;      // the modes kept and the cut-off (the run record's modal_modes_kept, modal_cutoff)
  std::string    after_used; // how the run followed a separation: "modal" or "time" (-impact_after as resolved)
  std::vector<ModeEnergy>
    mode_energies; // at the end, one per kept mode: only when the run ended in a modal free flight
  std::vector<ContactEvent> events;
  ImpactSeries              series;
  ImpactScales              scales;
  // The columns of the stages after the contact (run/stage.hpp: an oblique impact's exit_speed,
  // spin, ..., the flight's distance, ...) and of the registered structure parts
  // (run/results_table.hpp, ResultColumn::keyed), by their index in the table's keyed columns;
  // NaN (or beyond the end) where a stage does not apply or a part is absent. By name:
  // ImpactResultColumn(name)->Get(r).
  std::vector<double> keyed;
};

// The run's time rules: after each separation the run continues for `window`; it never
// goes beyond `max_time` (s). Shared by ImpactRun and the modal reference.
struct ImpactTimes {
  PetscReal window   = 0; // s
  PetscReal max_time = 0; // s
};
ImpactTimes ImpactTimesOf(const BeamParams &beam, const BallParams &ball, const ImpactParams &ip);

PetscErrorCode ImpactParamsFromOptions(MPI_Comm comm, const BeamParams &beam, ImpactParams *p);
PetscErrorCode MonitorRequestFromOptions(MPI_Comm comm, const BeamParams &beam, MonitorRequest *m);

// PETSc log stages of the program, for -log_view: "beamimpact: set-up" (the system and the
// stepper), "beamimpact: contact" (steps while the ball touches), "beamimpact: free flight"
// (after a separation: the modal free flight, or the steps of -impact_after time),
// "beamimpact: output" (the results file; a sweep's rewrites of its file too), "beamimpact:
// modal reference" (-reference modal, the exact modal solution: its modes and phases), and one
// per stage after the contact, "beamimpact: <name>" (run/stage.hpp: "tangential", an oblique
// impact's friction on the ball and the bat's second plane from the normal run's force, and
// "flight", the batted ball's flight), registered after them. Registered on first use. A scope
// pushes a stage and pops it when it ends (also on an error return, so a sweep's failed points
// keep the stack balanced); Switch changes the stage it holds, End pops it early.
enum class ImpactStage {
  Setup,
  Contact,
  FreeFlight,
  Output,
  ModalReference
};
class ImpactStageScope {
public:
  ImpactStageScope() = default; // holds no stage until a Switch
  explicit ImpactStageScope(ImpactStage s) { Switch(s); }
  ~ImpactStageScope();
  void Switch(ImpactStage s);
  void Switch(const char *name); // a stage after the contact's (run/stage.hpp), by its name
  void End();                    // pops the stage now
  ImpactStageScope(const ImpactStageScope &)            = delete;
  ImpactStageScope &operator=(const ImpactStageScope &) = delete;

private:
  void          Push(PetscLogStage id);
  bool          pushed_ = false;
  PetscLogStage id_     = -1; // the stage it holds
};

struct Scenario;

// The states the free flights after separations rebuilt from the modes for the series and the
// snapshots since the process started (for tests: an oblique impact's F_n alone needs none).
PetscInt ImpactFreeFlightSamples();

// The ball's and the bat's approach speed at the impact point (m/s): -ball_speed plus a
// swinging bat's speed there toward the ball.
PetscReal ImpactApproachSpeed(const Scenario &sc);

// Runs one impact on comm (the DMDA is distributed over its ranks). The TS is
// configured from the options database (no prefix): -ts_type and friends.
PetscErrorCode ImpactRun(MPI_Comm comm, const Scenario &scenario, ImpactResult *result);

// The system of one structure, kept by a caller whose next runs are on the same beam (a sweep's
// points on one structure): ImpactRun with it uses `sys` when set, which must be the system of
// the scenario's beam (BeamSystemBuild of scenario.beam: the caller's promise), and else builds
// the system and leaves it there; likewise the key of the integrator's context (TSStepperSettings::
// context_key: the caller promises the integrator's options unchanged too). Reset both (a new
// ImpactStructure) when the beam or any option outside the point's own changes.
struct ImpactStructure {
  std::shared_ptr<const BeamSystem> sys;
  std::string                       stepper_key; // the integrator context's key (empty: not computed yet)
};
PetscErrorCode ImpactRun(MPI_Comm comm, const Scenario &scenario, ImpactResult *result, ImpactStructure *structure);

// The same impact with the hand-written leapfrog baseline (solvers/leapfrog.hpp), serial.
struct LeapfrogParams;
PetscErrorCode LeapfrogRun(const Scenario &scenario, const LeapfrogParams &lp, ImpactResult *result);

} // namespace beamimpact

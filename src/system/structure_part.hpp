// The registry of structure parts: a part of the structure beside the beam's theory fields, one
// file each in system/parts/ and one line in StructureParts() (system/structure.cpp), in the
// order their fields are appended (a new part goes last). A part brings its option module, its
// parameters (model/beam.hpp: PartParams, held in BeamParams::parts), its fields, masses and
// strain terms, its force terms (system/force_operator.hpp), the dofs a rigid motion carries,
// its measures of a state and the results columns, series and summary line computed from them.
// The system's build, the options' reader, the measures, the recorder, the outcome, the results
// table, the run record, -help and the summary loop over the registered parts: no code outside
// a part's file names it; the energy accounts (the split's parts, -task modes' families) are the
// beam's and those the parts declare (AccountName, StructureAccountCount). The registered parts: the hands
// (parts/grip.cpp: no fields, a force term tying the handle to the swing's frame), the frame's roll (parts/roll.cpp),
// the barrel wall (parts/wall.cpp: the hoop oscillator or the shell), a racket's string bed (parts/bed.cpp: its nodes
// across the face, the ball's disc on its head) and the tuned absorber (parts/absorber.cpp).
//
// How a part is added: docs/design.md, "Adding a structure part".
#pragma once

#include "base/option_table.hpp"
#include "model/beam_theory.hpp"
#include "system/force_operator.hpp"

#include <petscsys.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace beamimpact {

struct BallParams;
struct BedGrid;
struct BeamSystem;
struct RacketMakerParams;
struct RacketStrung;
struct ContactCoupling;
class StructurePart;

// What a part built (its dofs, the stencil it couples through); derived in the part's file.
struct PartBuilt {
  virtual ~PartBuilt() = default;
};

// One registered part present in a system.
struct PartInstance {
  const StructurePart              *part = nullptr;
  std::shared_ptr<const PartParams> params;
  std::shared_ptr<const PartBuilt>  built;
  PetscInt                          first = -1, count = 0; // its fields [first, first + count) at every node
  PetscInt slot0 = 0, slots = 0; // its measure slots [slot0, slot0 + slots) (StateMeasures::part_slot)
};

// A part's dof that is a deflection at a point x of the beam (m): a rigid motion v0 + slope x
// moves it with the beam there, and it carries momentum m v and moment m x v about x = 0.
struct RigidPoint {
  PetscInt  dof = 0;
  PetscReal x   = 0; // m
};

constexpr int kMaxAccounts  = 8; // the energy accounts of all registered parts and the beam's (fixed: no allocation)
constexpr int kMaxPartSlots = 8; // the measure slots of all present parts together (fixed: no allocation per step)

// One number a part measures on every recorded state (a sum over the owned dofs: the measures
// add the ranks' shares). `peak`: the recorder keeps its largest |value| over the steps (NaN
// where no stepper measured it: the modal reference); `series`: -monitor_energy records it per
// step under /series/<name>.
// `own_monitor`: its series is recorded under the part's own monitor row (StructurePart::Monitors:
// the hands' own), not -monitor_energy.
struct PartSlot {
  const char *name; // "absorber_energy"
  const char *unit; // "J"
  bool        peak        = false;
  bool        series      = false;
  bool        own_monitor = false;
};

// How /snapshots/<name> holds a part's own field in -snapshot_times (StructurePart::Snapshot):
// with `labels`, [time][label][node] on the beam's nodes x and the labels' dataset (the wall's W_n,
// wall_n); without, [time][point] on its face's grid (FaceGrid: the datasets face_x, face_z and the
// point z * len(face_x) + x; the bed's w). `attribute`: its name in the XDMF description.
struct PartSnapshotSpec {
  const char *name = nullptr, *attribute = nullptr;
  const char *description = nullptr; // the dataset's unit and text
  const char *labels = nullptr, *labels_description = nullptr;
  const char *face_x = nullptr, *face_z = nullptr, *face_point = nullptr;
};

// The force operator's frame terms of a state (system/force_operator.hpp: ForceOperatorEnergy,
// ForceOperatorFrameMomentum, ForceOperatorFrameReaction; run/measures.hpp holds them): what a
// part tying the structure to the swing's frame measures (StructurePart::MeasureFrame).
struct FrameMeasures {
  PetscReal stored = 0;            // J, the energy stored in the force terms other than the elastic one
  PetscReal work   = 0;            // J, the work the frame has done on the structure since t = 0
  PetscReal force = 0, moment = 0; // N, N m about x = 0: the force of the structure on the frame
};

// A state as a part's Measure reads it: dof d of y at y[(d / fields) * ys + d % fields] (by global
// node, valid within the system's ghost width of [d0, d1)), v likewise; [d0, d1) the owned dofs.
struct PartState {
  const PetscReal *y = nullptr, *v = nullptr; // m (rad), m/s (rad/s)
  PetscInt         ys = 1, vs = 1, d0 = 0, d1 = 0;
};

// What a part's column reads: its slots at t = 0, at the end and their peaks (in Slots()'s order).
struct PartOutputFacts {
  const PetscReal *start = nullptr, *end = nullptr, *peak = nullptr;
  // Its energy account's (StructureAccountOf; 0 without one): the energy at the end and its largest
  // over the steps (J, stored and kinetic; the peak NaN where not measured: the modal reference),
  // and the flexible energy at the end, less its share of the rigid motions (J, run/energy_parts.hpp).
  PetscReal account_end = 0, account_peak = 0, account_flexible = 0;
  // The largest displacement under the ball of an account kept apart (AccountApart: the wall's,
  // StateMeasures::apart_deflection) and the largest deflection of the face's fields from their frame
  // (the bed's, StateMeasures::face_deflection) over the steps (m; NaN where not measured: the modal
  // reference).
  PetscReal         apart_deflection_peak = 0, face_deflection_peak = 0;
  PetscReal         impact_x = 0; // m, the impact point along the beam
  PetscReal         E_in     = 0; // J, the energy brought into the impact (the fractions' denominator)
  const PartParams *params   = nullptr;
  const BeamParams *beam     = nullptr; // the scenario's beam (the wall's shell frequencies)
  // The largest |force of the structure on the swing's frame| over the steps (N, FrameMeasures::
  // force) and when (s): 0 where no part ties to the frame.
  PetscReal frame_force_peak = 0, frame_force_peak_time = 0;
};

// A results column a part registers: name, unit ("1": dimensionless), description (one line) and
// how the outcome computes it. It applies where the part is present (StructurePart::Presence),
// NaN elsewhere. `share`: a share of E_in, its short name in the summary's energy line (nullptr:
// not a share; run/results_table.hpp's ResultColumn::share). `integer`: a flag (0 or 1), an integer
// dataset that, as the table's counts and flags, always applies: 0 where the part is absent.
struct PartColumn {
  const char *name, *unit, *description;
  double (*compute)(const PartOutputFacts &f);
  const char *share   = nullptr;
  bool        integer = false;
};

// What a part's Resolve and SummaryAt see of the impact: the ball, its approach speed and the point.
struct PartPoint {
  const BallParams *ball     = nullptr;
  PetscReal         approach = 0; // m/s, the ball's speed toward the beam at the point (with the swing's)
  PetscReal         x        = 0; // m, the impact point along the beam
  PetscReal         z        = 0; // m, across the face from the frame's axis (-impact_z)
};

// A part's options as read: the rows given in the options database, by name (with the dash),
// each as its numbers (a flag 1; a list its values).
struct PartOptionValues {
  std::map<std::string, std::vector<PetscReal>> given;
  bool                                          Given(const char *name) const { return given.count(name) > 0; }
};

class StructurePart {
public:
  virtual ~StructurePart() = default;
  // -- identity and options ---------------------------------------------------------------------
  virtual const char         *Name() const     = 0;            // "absorber": registry key, BeamParams::parts key
  virtual const char         *Presence() const = 0;            // "with -absorber": when its columns apply
  virtual const char         *Words() const { return Name(); } // for messages: "the stability limit is set by ..."
  virtual const OptionModule &Options() const = 0; // its rows: -help, the unknown-option check, the run record
  // Whether it makes the frame it sits on (the string bed: a held bed's frame is the head's outline
  // held whole, a racket maker's numbers place its head and its strings weigh on the frame's
  // levels). Such a part is set up by Frame while the beam is read, before the beam's section by a
  // racket maker and the beam's checks, not by Configure. No by default.
  virtual bool Frames() const { return false; }
  // The option without which such a part is absent and its rows are not read at all (the bed's
  // -strings_frame: a bat's run neither reads, checks nor records the bed's rows); nullptr: read
  // always.
  virtual const char *Gate() const { return nullptr; }
  // Its rows as read -> its parameters in *out (nullptr: absent), the head placed by a racket
  // maker's numbers (racket; nullptr without -racket_length); may make the beam its frame (length,
  // nodes, holds, BeamParams::frame_held). 0, or the PETSc error class with *why naming the
  // option, the value and what is allowed (ContactLaw::Configure's contract).
  virtual int Frame(const PartOptionValues &, const RacketMakerParams *, BeamParams *,
                    std::shared_ptr<const PartParams> *out, std::string *) const
  {
    *out = nullptr;
    return 0;
  }
  // Adds what it weighs on a racket maker's frame (its mass and moments, model/racket_maker.hpp).
  virtual void Strung(const PartParams &, RacketStrung *) const { }
  // The grid of its face, where its snapshots and mode shapes are written (the bed's nodes across
  // the head); false for a part with no face.
  virtual bool FaceGrid(const PartParams &, const BeamParams &, BedGrid *) const { return false; }
  // The value -help and /options_used show for its number row `name` when not given (its
  // parameter's own default: the shell's -shell_contact_radius -1, not yet derived; one derived
  // from the rows read before it, `before`); 0 by default.
  virtual PetscReal Unset(const char *, const PartOptionValues & /* before */) const { return 0; }
  // The rows as read (and the beam, its holds resolved) -> its parameters in *out (nullptr: the
  // part is absent). False with *why naming the option, the value as written and what is allowed.
  // Every part but one that Frames has it.
  virtual bool Configure(const PartOptionValues &, const BeamParams &, std::shared_ptr<const PartParams> *out,
                         std::string *) const
  {
    *out = nullptr;
    return true;
  }
  // A note on its parameters the run prints once (without "note: " and newline; "" for none).
  virtual std::string Note(const PartParams &, const BeamParams &) const { return ""; }
  // Its parameters at the impact point (a default from the ball, a check of the point): true with
  // *out left as it was when nothing changes; false with *why naming the option and its value.
  virtual bool Resolve(const PartParams &, const BeamParams &, const PartPoint &, std::shared_ptr<const PartParams> *,
                       std::string *) const
  {
    return true;
  }
  // Why it cannot be with the parts present in beam (all configured: a check against another
  // part), naming the option and its value; "" when it can.
  virtual std::string RefusalWith(const PartParams &, const BeamParams &) const { return ""; }
  // -- the impact point ---------------------------------------------------------------------------
  // Whether the ball at (x, z) (m: along the beam, across from its axis) strikes it rather than the
  // beam (the bed: strictly inside the head's outline). No by default.
  virtual bool Strikes(const PartParams &, PetscReal, PetscReal) const { return false; }
  // Whether it is the structure's face off the axis (the bed): a point off the axis that it does not
  // strike is off the face, and a hit off the axis needs no roll. No by default.
  virtual bool HasFace(const PartParams &) const { return false; }
  // Why `what` (the option that names the point) cannot strike at z (m) across the axis: off its
  // face (held false) or on a point the beam holds (held true); "" leaves it to the beam's checks.
  virtual std::string PointRefusal(const PartParams &, const char *, PetscReal, bool) const { return ""; }
  // Its stiffness (N/m) and mass (kg) in its own plane under the ball at (x, z) (m), against the
  // friction force of an oblique impact (the bed's mains pulled sideways: the tangential stage's
  // plane); false (the default) for none.
  virtual bool InPlane(const PartParams &, PetscReal, PetscReal, PetscReal *, PetscReal *) const { return false; }
  // Why the modal reference (-reference modal) cannot carry it, or nullptr.
  virtual const char *ModalRefusal(const PartParams &) const { return nullptr; }
  // Whether it ties the structure to the swing's frame (the hands): momentum is then not an
  // invariant, nor is the beam free at rest. No by default.
  virtual bool TiesToFrame(const PartParams &) const { return false; }
  // Whether its own monitor row was given (its Slots() with own_monitor record their series).
  virtual bool Monitors(const PartParams &) const { return false; }
  // -- the system ---------------------------------------------------------------------------------
  // Appends its fields to d (BeamDiscretizationWiden: masses, held flags, strain terms); returns
  // how many (0: none).
  virtual PetscInt Build(const PartParams &, const BeamParams &, BeamDiscretization *,
                         std::shared_ptr<const PartBuilt> *) const
  {
    return 0;
  }
  // Build with the parts built before it at hand (the bed's anchoring on the roll's field); by
  // default Build's.
  virtual PetscInt BuildAfter(const PartParams &q, const BeamParams &beam, const std::vector<PartInstance> &,
                              BeamDiscretization *d, std::shared_ptr<const PartBuilt> *out) const
  {
    return Build(q, beam, d, out);
  }
  // Its field f as a deflection w at z (m) across the frame's axis, anchored on the frame's
  // section at x (the bed's nodes across the face): a rigid motion moves it as y + z phi, its mass
  // carries momentum as the beam's deflection does, and its held dofs move with their section
  // (they hold nothing in the rigid motions' null space). NaN: not such a field (the default).
  virtual PetscReal FieldZ(const PartInstance &, PetscInt) const { return NAN; }
  // Its own energy account: its name, the label of the energy split's part and of -task modes' family
  // ("wall"), and its energy's series under -monitor_energy (nullptr: none); nullptr (the default):
  // its fields and strain terms are the beam's account. See StructureAccountOf.
  virtual const char *AccountName() const { return nullptr; }
  virtual const char *AccountSeries() const { return nullptr; }
  // Whether its account is kept apart from the beam's kinetic and strain energies (the barrel wall,
  // in series with the ball: StateMeasures::apart_energy, not in beam_kinetic and beam_strain) and
  // its share of the compression measured (StateMeasures::apart_deflection). No by default.
  virtual bool AccountApart() const { return false; }
  // Its dofs that a rigid motion carries as the beam's deflection at a point.
  virtual void RigidPoints(const PartInstance &, std::vector<RigidPoint> *) const { }
  // Its entries in the ball's coupling at a point of the beam (after the beam's hat entries st, z
  // m across from the axis), in order; none by default.
  virtual void Couple(const PartInstance &, const BeamSystem &, const ImpactStencil &, PetscReal,
                      ContactCoupling *) const
  {
  }
  // Its coupling when the point (x, z) strikes it (m: the bed under the ball's disc), in place of
  // the beam's hat and every other part's entries: true when it does, with g's entries set; false
  // (the default) when the point is not on it.
  virtual bool CoupleInstead(const PartInstance &, const BeamSystem &, PetscReal, PetscReal, ContactCoupling *) const
  {
    return false;
  }
  // What it adds to the masses of the dofs (kg: the hands), before its force terms.
  virtual void AddMasses(const PartInstance &, BeamSystem *) const { }
  // Its force terms, summed after the registered ones of force_operator.cpp.
  virtual void ForceTerms(const PartInstance &, const BeamSystem &,
                          std::vector<std::shared_ptr<const ForceTerm>> *) const
  {
  }
  // -task modes' family detail of its field f (a shell harmonic's n: ModesResult::shell_n), 0 for
  // none: the modes' family is the beam's (0) or the detail whose fields hold the most energy.
  virtual PetscInt FamilyDetail(const PartInstance &, PetscInt) const { return 0; }
  // -- measures and outputs -----------------------------------------------------------------------
  // Whether the recorder follows the outcome's peaks of its fields (the wall's energy and
  // displacement under the ball): the series are then sampled through a free flight.
  virtual bool Peaks() const { return false; }
  // A snapshot's field of its own from every field of every node (u, node-major; empty on the
  // ranks but 0, which still size it), as its spec lays it out ([label][node] flattened and its
  // labels: the shell's W_n of each harmonic n; or [z][x] on its face: the bed's w - y - z phi), and
  // how /snapshots writes it: false for none.
  virtual bool Snapshot(const PartInstance &, const BeamSystem &, const std::vector<PetscReal> &,
                        std::vector<PetscReal> *, std::vector<PetscInt> *, PartSnapshotSpec *) const
  {
    return false;
  }
  virtual std::vector<PartSlot> Slots() const { return {}; }
  // slot[k] += its k-th slot's share of the owned dofs [s.d0, s.d1).
  virtual void Measure(const PartInstance &, const BeamSystem &, const PartState &, PetscReal *) const { }
  // slot[k] set from the force operator's frame terms of the state (after the ranks' sums).
  virtual void                    MeasureFrame(const PartInstance &, const FrameMeasures &, PetscReal *) const { }
  virtual std::vector<PartColumn> Columns() const { return {}; }
  // The results table's column its columns follow (a part that predates the registry keeps its
  // columns' place); nullptr: after the table, in registry order.
  virtual const char *ColumnsAfter() const { return nullptr; }
  // The results columns its summary reads beyond its own (by name, any module's), after them.
  virtual std::vector<const char *> SummaryColumns() const { return {}; }
  // The run summary's line (without newline; "" for none) from its columns' values, in Columns()'s
  // order, then SummaryColumns()'s.
  virtual std::string Summary(const PartParams &, const std::vector<double> &) const { return ""; }
  // Its line in the run summary at the point `at` (the impact's x and z), by default Summary's.
  virtual std::string SummaryAt(const PartParams &q, const std::vector<double> &c, const PartPoint &) const
  {
    return Summary(q, c);
  }
  // A warning on its outcome (without newline; "" for none: the default) from its columns' values as
  // Summary's, the beam and the impact point: the run summary prints it after the ball's own
  // (the barrel wall's displacement beyond its linear range), before the energy line.
  virtual std::string Warning(const PartParams &, const BeamParams &, const std::vector<double> &,
                              const PartPoint &) const
  {
    return "";
  }
  // Whether its summary line comes before the pivot rig's lines (a part that predates the registry
  // keeps its line's place: the bed's); after them, in registry order, by default.
  virtual bool SummaryFirst() const { return false; }
  // Its entries in the run record (/run attributes, in order: name, value in the row's unit).
  virtual void Record(const PartParams &, const BeamParams &, std::vector<std::pair<const char *, PetscReal>> *) const
  {
  }
  // Its text and whole-number entries in the run record, in order (after the numbers of Record).
  virtual void RecordWords(const PartParams &, const BeamParams &, std::vector<std::pair<const char *, std::string>> *,
                           std::vector<std::pair<const char *, long long>> *) const
  {
  }
  // A line of its own before the beam's description (PrintBeamBody; without newline, "" for none),
  // and *body false when the beam is then not described as a body (a held frame). Nothing by default.
  virtual std::string Heading(const PartParams &, bool *) const { return ""; }
  // Its line in the beam's description (PrintBeamBody), appended to the rigid body's: "" for none.
  virtual std::string Describe(const PartParams &, const BeamRigidBody &) const { return ""; }
};

// The registry, in the order the parts' fields are appended (system/structure.cpp).
const std::vector<const StructurePart *> &StructureParts();
const StructurePart                      *StructurePartFind(const char *name); // nullptr if none

// The energy accounts (the parts of the energy split, -task modes' families): 0 the beam's bending
// (and shear; its fields and terms, and those of a part without an account of its own), then one
// for each registered part with an AccountName, in registry order; at most kMaxAccounts.
PetscInt    StructureAccountCount();
const char *StructureAccountName(PetscInt a);           // "bending", "roll", "wall", "strings"
PetscInt    StructureAccountOf(const StructurePart &p); // its account (0: the beam's)
// The part whose account a is (nullptr for the beam's).
const StructurePart *StructureAccountPart(PetscInt a);
// Whether account a's energy is kept apart from the beam's (its part's AccountApart: the wall's).
bool StructureAccountApart(PetscInt a);

// The parts present in p, appended to d in registry order, the strain terms each appends in its
// account (StructureAccountOf) (BeamSystemBuild).
std::vector<PartInstance> StructurePartsBuild(const BeamParams &p, BeamDiscretization *d);
// Each present part's masses added, its force terms appended to sys->forces.terms and its rigid
// points to sys->rigid_points; its measure slots numbered (BeamSystemBuild, before the assembly).
void StructurePartsFinish(BeamSystem *sys);
// The measure slots of the present parts together (<= kMaxPartSlots).
PetscInt StructurePartSlotCount(const BeamSystem &sys);
// slot[k] += every present part's measures of s (its slots at slot0 + k).
void StructurePartsMeasure(const BeamSystem &sys, const PartState &s, PetscReal *slot);
// Whether a present part has peaks the recorder follows (Peaks or measure slots).
bool StructurePartsPeaks(const BeamSystem &sys);
// slot[k] set by every present part from the frame terms fm (its slots at slot0 + k).
void StructurePartsMeasureFrame(const BeamSystem &sys, const FrameMeasures &fm, PetscReal *slot);
// Whether the ball at (x, z) strikes a part present in p (StructurePart::Strikes: the bed's head).
bool StructurePartsStrike(const BeamParams &p, PetscReal x, PetscReal z);
// Whether a part present in p is the structure's face off the axis (StructurePart::HasFace).
bool StructurePartsHaveFace(const BeamParams &p);
// Why `what` cannot strike at z off a present part's face or on a held point (StructurePart::
// PointRefusal; "" when no part refuses it).
std::string StructurePartsPointRefusal(const BeamParams &p, const char *what, PetscReal z, bool held);
// The in-plane stiffness and mass under the ball at (x, z) of the first present part that has them
// (StructurePart::InPlane); false when none.
bool StructurePartsInPlane(const BeamParams &p, PetscReal x, PetscReal z, PetscReal *stiffness, PetscReal *mass);
// Why the modal reference cannot carry the parts present in p ("" when it can).
std::string StructurePartsModalRefusal(const BeamParams &p);
// Why a part present in p cannot be with the others (StructurePart::RefusalWith; "" when none).
std::string StructurePartsRefusalWith(const BeamParams &p);
// Whether a part present in p ties the structure to the swing's frame (StructurePart::TiesToFrame).
bool StructurePartsTieToFrame(const BeamParams &p);
// Whether a part present in p had its own monitor row given (StructurePart::Monitors).
bool StructurePartsMonitor(const BeamParams &p);
// The grid of the face of a part present in p (StructurePart::FaceGrid: the string bed's); false
// when no part has a face.
bool StructurePartsFaceGrid(const BeamParams &p, BedGrid *g);

} // namespace beamimpact

// What a ball's contact law is, and the registry of laws (-ball_law NAME). A law is the force
// F(c) (N) of the ball's compression c = y_ball - y_beam(x_imp) (m) in each phase of a contact
// (loading while c grows, unloading after the maximum compression), everything the solvers,
// the events and the outcome ask of it, and its own -ball_* options. Each law is one file of
// model/contact_laws/ (linear.cpp, hysteresis.cpp, hertz.cpp) and one line in the registry of
// model/contact_law.cpp; nothing else names a law. The solvers call the facade of
// model/contact.hpp, never a law directly.
//
// A law's parameters are plain numbers kept in BallParams::value, in the order of the numeric
// (Real) rows of its option table: the row "-ball_k1" is the value named "k1", whose default is
// the row's. So a new law adds rows, not fields.
#pragma once

#include "base/option_table.hpp"
#include "model/cor_table.hpp"

#include <petscsys.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace beamimpact {

class ContactLaw;

// Which branch of the law is active: the phase of the event-driven model.
enum class ContactPhase {
  Separated = 0,
  Loading   = 1,
  Unloading = 2
};

// The state of the contact in progress (owned by the run driver; the steppers read it).
struct ContactState {
  ContactPhase phase       = ContactPhase::Loading; // the ball starts touching, moving in
  PetscReal    c_max       = 0;                     // m, compression at the last loading->unloading switch
  PetscReal    work_offset = 0;                     // J, W minus the active branch's antiderivative
  // What the law keeps for this contact, set at its start (ContactLaw::Begin) and at the switch
  // (ContactLaw::Unload); 0: not set. The hysteretic law: the unloading coefficient k2 (N/m^n)
  // and exponent n.
  std::array<PetscReal, 2> law{};
};

// Numeric parameters a law may have (hysteresis has 6). Seven keeps BallParams as large as it was
// before the registry: the steppers hold a copy, and at 8 the leapfrog's hot loop ran 10-15 %
// slower from the layout alone (same instructions; measured on the convergence benchmark).
constexpr int kContactLawMaxValues = 7;

// The ball: mass, speed and its contact law with the law's parameters.
struct BallParams {
  PetscReal mass        = 0.042; // kg
  PetscReal speed       = 1.0;   // m/s, incident speed v_i (moving in +y)
  PetscReal radius      = 0;     // m, -ball_radius: a compression beyond it is flagged (0: not given, no check)
  PetscReal loss_factor = 0.85;  // 1, ACOR correction for the ball's losses, applied to an elastic law's ACOR
  // The oblique impact (model/oblique.hpp): I_b = inertia_factor m R^2; the incoming spin
  // (rad/s, > 0: backspin of the incoming ball); Coulomb friction mu at the contact; the
  // tangential restitution e_T of the contact's compliance (< 0: none, a rigid grip).
  PetscReal         inertia_factor = 0.4, spin = 0, friction = 0.5, tangential_cor = -1;
  const ContactLaw *law = nullptr; // the registered law (-ball_law); never null after construction
  std::array<PetscReal, kContactLawMaxValues>
    value{}; // the law's parameters (units: its rows'), in the order of its numeric rows
  // -ball_cor_table: e(v) of the approach speed, for a law that follows one (hysteresis); empty: none.
  CorTable cor_table;
  BallParams(); // the first registered law (linear), with its defaults
};

// One entry of what a law records with the results (run record): a number with its unit, or a
// text (a file name).
struct ContactLawRecord {
  std::string name; // "ball_k1"
  std::string unit; // "N/m^m", "1", "" for a text
  PetscReal   value = 0;
  std::string text; // when is_text
  bool        is_text = false;
};

// The options of a law as given, for ContactLaw::Configure (the numbers are already in
// BallParams::value, checked against their rows).
struct ContactLawInput {
  std::vector<std::string>           given; // names of the law's rows set in the options database
  std::map<std::string, std::string> text;  // text and file rows given: name -> value as written
  // Reads an e(v) table file (io/cor_table_file.cpp: CorTableRead); false with *why.
  bool (*read_cor_table)(const std::string &path, CorTable *t, std::string *why) = nullptr;
  bool        Given(const char *name) const;
  std::string Text(const char *name) const;
};

// A contact law. The phase passed to Force, Stiffness and Stored is Loading or Unloading (the
// facade answers 0 when separated). Inside a contact phase a law extends F oddly to c < 0, so
// that the right-hand side stays smooth up to the located separation event.
class ContactLaw {
public:
  virtual ~ContactLaw() = default;

  // -ball_law NAME, and one line for -help: the formula and what it loses.
  virtual const char *Name() const    = 0;
  virtual const char *Summary() const = 0;
  // Its -ball_* options: units, help, defaults and ranges. The numeric rows, in order, are its
  // parameters (BallParams::value); text and file rows are passed to Configure.
  virtual const std::vector<OptionSpec> &Options() const = 0;
  // The checks across options and the parameters derived from others, after the rows were read:
  // 0, or the PETSc error class of the refusal with *why naming the options and values.
  virtual int Configure(const ContactLawInput &in, BallParams *b, std::string *why) const { return 0; }

  // F (N), dF/dc (N/m) and the stored energy: the active branch's antiderivative (J).
  virtual PetscReal Force(const BallParams &b, const ContactState &s, PetscReal c) const     = 0;
  virtual PetscReal Stiffness(const BallParams &b, const ContactState &s, PetscReal c) const = 0;
  virtual PetscReal Stored(const BallParams &b, const ContactState &s, PetscReal c) const    = 0;
  // At the start of a contact of approach speed v (m/s), and at the loading->unloading switch
  // at compression c (s->c_max is set): what the law keeps for this contact (ContactState::law).
  virtual void Begin(const BallParams &b, ContactState *s, PetscReal v) const { }
  virtual void Unload(const BallParams &b, ContactState *s, PetscReal c) const { }
  // Whether the force changes formula at the maximum compression (then that event matters).
  virtual bool Hysteretic(const BallParams &b) const { return false; }
  // Whether the law keeps all the work done on it (no loss): the ACOR correction
  // -ball_loss_factor applies to its ACOR and the energy partition's ball loss.
  virtual bool Elastic() const = 0;
  // F = k c in every phase (k: LinearStiffness): the exact modal reference applies.
  virtual bool      Linear() const { return false; }
  virtual PetscReal LinearStiffness(const BallParams &b) const;
  // The unloading exponent of this contact, recorded with its start (0: the law has none).
  virtual PetscReal UnloadingExponent(const BallParams &b, const ContactState &s) const { return 0; }

  // On a rigid, fixed wall at approach speed v: coefficient of restitution, maximum compression
  // (m), the loading and unloading times (s; an elastic law unloads as it loaded).
  virtual PetscReal WallCor(const BallParams &b, PetscReal v) const { return 1.0; }
  virtual PetscReal WallMaxCompression(const BallParams &b, PetscReal v) const = 0;
  virtual PetscReal WallLoadingTime(const BallParams &b, PetscReal v) const    = 0;
  virtual PetscReal WallUnloadingTime(const BallParams &b, PetscReal v) const { return WallLoadingTime(b, v); }

  // Scales at the incident speed: contact time (s), compression (m), and a bound on dF/dc over
  // the contact (N/m) for the explicit stability limits.
  virtual PetscReal TimeScale(const BallParams &b) const        = 0;
  virtual PetscReal CompressionScale(const BallParams &b) const = 0;
  virtual PetscReal StiffnessBound(const BallParams &b) const   = 0;

  // Its parameters for the run record (default: every value as ball_<name> with its row's unit).
  virtual std::vector<ContactLawRecord> Record(const BallParams &b) const;
};

// The registry (model/contact_law.cpp), in -help order; the first is the default.
const std::vector<const ContactLaw *> &ContactLaws();
const ContactLaw                      *ContactLawFind(const char *name); // nullptr if unknown (case-insensitive)
std::vector<std::string>               ContactLawNames();
const char                            *ContactLawName(const ContactLaw *law);

// Makes law the ball's law, its parameters the defaults of its rows (mass, speed, radius and the
// loss factor are kept).
void BallParamsUseLaw(BallParams *b, const ContactLaw *law);
// The parameter `name` of the ball's law ("k1": the row -ball_k1): its value (NaN if the law has
// none), or set it (false if the law has none).
PetscReal BallValue(const BallParams &b, const char *name);
bool      BallValueSet(BallParams *b, const char *name, PetscReal v);
// Index of `name` in BallParams::value for law (-1 if none). Name with or without "-ball_".
int ContactLawValueIndex(const ContactLaw &law, const char *name);

// What the ball's law records, then its rigid-wall values at -ball_speed (ball_wall_cor,
// ball_wall_contact_time, ball_wall_max_compression).
std::vector<ContactLawRecord> ContactLawRecordOf(const BallParams &b);

// For the laws' files: the odd power sgn(c)|c|^p and its even antiderivative |c|^(p+1)/(p+1),
// and I(p) = integral_0^1 ds / sqrt(1 - s^p) = B(1/p, 1/2) / p
// (a power-law ball's wall times: t_load = (c_max/v) I(p+1)).
inline PetscReal ContactOddPow(PetscReal c, PetscReal p) { return std::copysign(std::pow(std::abs(c), p), c); }
inline PetscReal ContactPowAntiderivative(PetscReal c, PetscReal p) { return std::pow(std::abs(c), p + 1) / (p + 1); }
PetscReal        PowerLawWallIntegral(PetscReal p);

} // namespace beamimpact

// The hysteretic power-law ball (-ball_law hysteresis; docs/model.md section 2): F = k1 c^m while
// the compression grows (loading), F = k2 c^n while it shrinks (unloading), n >= m >= 1, with
// k2 = k1 c_max^(m-n) (N/m^n) set at the maximum compression so that F is continuous there. On a
// rigid wall it returns e = sqrt((m+1)/(n+1)) at every speed and one cycle loses
// (n-m) k1 c_max^(m+1) / ((m+1)(n+1)); a reload (the compression growing again before the ball
// left) climbs the unloading curve back to its knee (the last c_max), elastically, and the loading
// branch beyond: F = min(k1 c^m, k2 c^n). A real ball is characterised as it is tested (MODEL section 6): by its wall
// COR e (-ball_cor: n = (m+1)/e^2 - 1) and contact time tau at a test speed (-ball_contact_time,
// -ball_test_speed: k1 in closed form), and e may follow a table e(v) of each contact's approach
// speed (-ball_cor_table: n set at the start of each contact).
#include "model/contact.hpp"

#include <algorithm>
#include <cmath>

namespace beamimpact {

namespace {

enum {
  kK1,
  kM,
  kN,
  kCor,
  kContactTime,
  kTestSpeed
}; // BallParams::value: the rows' order
enum {
  kK2,
  kNContact
}; // ContactState::law: this contact's k2 and n

class HysteresisLaw final : public ContactLaw {
public:
  const char *Name() const override { return "hysteresis"; }
  const char *Summary() const override
  {
    return "F = k1 c^m loading, k2 c^n unloading: e = sqrt((m+1)/(n+1)) on a wall";
  }
  const std::vector<OptionSpec> &Options() const override
  {
    static const std::vector<OptionSpec> rows = {
      OptionReal("-ball_k1", "N/m^m", "Hysteresis loading coefficient k1; -ball_law hysteresis", "2e4", Positive()),
      OptionReal("-ball_m", "1", "Hysteresis loading exponent m; -ball_law hysteresis", "1", AtLeast(1)),
      OptionReal("-ball_n", "1", "Hysteresis unloading exponent n (>= m); -ball_law hysteresis", "1.768", AtLeast(1)),
      OptionReal("-ball_cor", "1",
                 "Rigid-wall coefficient of restitution e; sets n = (m+1)/e^2 - 1 (instead of -ball_n); -ball_law "
                 "hysteresis",
                 "", Between(0, 1, true, false)),
      OptionReal("-ball_contact_time", "s",
                 "Rigid-wall contact time tau (first touch to separation) at -ball_test_speed; sets k1 (instead of "
                 "-ball_k1); -ball_law hysteresis",
                 "", Positive()),
      OptionReal("-ball_test_speed", "m/s",
                 "Speed at which -ball_contact_time (and -ball_cor) were measured against a rigid wall; -ball_law "
                 "hysteresis",
                 "", Positive()),
      OptionFile("-ball_cor_table", "File of rows 'v e': wall COR against approach speed (m/s); n follows e(v) at each "
                                    "contact start (instead of -ball_n, -ball_cor); -ball_law hysteresis"),
    };
    return rows;
  }
  int Configure(const ContactLawInput &in, BallParams *b, std::string *why) const override;

  PetscReal Force(const BallParams &b, const ContactState &s, PetscReal c) const override
  {
    if (s.phase == ContactPhase::Loading && Reloading(b, s, c))
      return s.law[kK2] * ContactOddPow(c, UnloadingExponent(b, s));
    return s.phase == ContactPhase::Loading ? b.value[kK1] * ContactOddPow(c, b.value[kM])
                                            : s.law[kK2] * ContactOddPow(c, UnloadingExponent(b, s));
  }
  PetscReal Stiffness(const BallParams &b, const ContactState &s, PetscReal c) const override
  {
    const bool      unloading_curve = s.phase == ContactPhase::Unloading || Reloading(b, s, c);
    const PetscReal p               = unloading_curve ? UnloadingExponent(b, s) : b.value[kM];
    const PetscReal coef            = unloading_curve ? s.law[kK2] : b.value[kK1];
    if (p == 1.0) return coef;
    return coef * p * std::pow(std::abs(c), p - 1);
  }
  PetscReal Stored(const BallParams &b, const ContactState &s, PetscReal c) const override
  {
    if (s.phase == ContactPhase::Loading &&
        s.law[kK2] > 0) { // a reload: the unloading curve up to its knee, the loading branch beyond
      const PetscReal n = UnloadingExponent(b, s), m = b.value[kM], ck = ReloadKnee(b, s);
      if (Reloading(b, s, c)) return s.law[kK2] * ContactPowAntiderivative(c, n);
      return s.law[kK2] * ContactPowAntiderivative(ck, n) +
             b.value[kK1] * (ContactPowAntiderivative(c, m) - ContactPowAntiderivative(ck, m));
    }
    return s.phase == ContactPhase::Loading ? b.value[kK1] * ContactPowAntiderivative(c, b.value[kM])
                                            : s.law[kK2] * ContactPowAntiderivative(c, UnloadingExponent(b, s));
  }
  void Begin(const BallParams &b, ContactState *s, PetscReal v)
    const override // this contact's e(v_approach); a ball that left has recovered: no unloading curve
  {
    s->law[kNContact] = BallExponentAt(b, v);
    s->law[kK2]       = 0;
  }
  // k2 = k1 c^(m-n) at a maximum compression beyond the last one's (k2 only falls as c_max grows); a
  // maximum reached on a reload below the knee keeps the unloading curve the ball is on.
  void Unload(const BallParams &b, ContactState *s, PetscReal c) const override
  {
    const PetscReal k2 = b.value[kK1] * std::pow(std::abs(c), b.value[kM] - UnloadingExponent(b, *s));
    s->law[kK2]        = s->law[kK2] > 0 ? std::min(s->law[kK2], k2) : k2;
  }
  bool Hysteretic(const BallParams &b) const override { return b.value[kM] != b.value[kN] || !b.cor_table.empty(); }
  bool Elastic() const override { return false; }
  PetscReal UnloadingExponent(const BallParams &b, const ContactState &s) const override
  {
    return s.law[kNContact] > 0 ? s.law[kNContact] : b.value[kN];
  }

  PetscReal WallCor(const BallParams &b, PetscReal v) const override
  {
    if (!b.cor_table.empty()) return b.cor_table(v);
    return std::sqrt((b.value[kM] + 1) / (b.value[kN] + 1));
  }
  PetscReal WallMaxCompression(const BallParams &b, PetscReal v) const override
  {
    const PetscReal m = b.value[kM];
    return std::pow(0.5 * (m + 1) * b.mass * v * v / b.value[kK1], 1.0 / (m + 1));
  }
  PetscReal WallLoadingTime(const BallParams &b, PetscReal v) const override
  {
    return WallMaxCompression(b, v) / v * PowerLawWallIntegral(b.value[kM] + 1);
  }
  PetscReal WallUnloadingTime(const BallParams &b, PetscReal v) const override
  {
    const PetscReal e = WallCor(b, v), n = BallExponentAt(b, v);
    return WallMaxCompression(b, v) / (e * v) * PowerLawWallIntegral(n + 1);
  }

  // Wall loading: 1/2 m v^2 = k1 c^(m+1)/(m+1); the time scale from the secant stiffness there.
  PetscReal CompressionScale(const BallParams &b) const override
  {
    const PetscReal m = b.value[kM];
    return std::pow(0.5 * b.mass * b.speed * b.speed * (m + 1) / b.value[kK1], 1.0 / (m + 1));
  }
  PetscReal TimeScale(const BallParams &b) const override
  {
    const PetscReal c    = CompressionScale(b);
    const PetscReal keff = b.value[kK1] * std::pow(c, b.value[kM] - 1); // secant stiffness at c_max
    return M_PI * std::sqrt(b.mass / keff);
  }
  // dF/dc on either branch up to twice the wall's compression.
  PetscReal StiffnessBound(const BallParams &b) const override
  {
    return std::max(b.value[kM], b.value[kN]) * b.value[kK1] * std::pow(2 * CompressionScale(b), b.value[kM] - 1);
  }

  std::vector<ContactLawRecord> Record(const BallParams &b) const override;

private:
  // A reload (the compression growing again before the ball left: ContactPhase::Loading after an
  // unloading, k2 set) follows the unloading curve k2 c^n back up to its knee c_k, where it meets
  // the loading branch (k2 c_k^n = k1 c_k^m: c_k is the last maximum compression), and the loading
  // branch beyond: F = min(k1 c^m, k2 c^n), continuous, and a reload below c_k is elastic (no
  // loss: the ball retraces the curve it unloaded on). Returning to k1 c^m at once would make the
  // force jump up at the reload and the ball give back energy it had dissipated.
  PetscReal ReloadKnee(const BallParams &b, const ContactState &s) const
  {
    const PetscReal n = UnloadingExponent(b, s), m = b.value[kM];
    return n > m ? std::pow(s.law[kK2] / b.value[kK1], 1.0 / (m - n)) : PETSC_MAX_REAL;
  }
  bool Reloading(const BallParams &b, const ContactState &s, PetscReal c) const
  {
    return s.law[kK2] > 0 && std::abs(c) < ReloadKnee(b, s);
  }
};

// Two sources for one parameter, and the pair (contact time, test speed) incomplete.
int CharacterisationConflict(const ContactLawInput &in, std::string *why)
{
  const bool set_k1 = in.Given("-ball_k1"), set_n = in.Given("-ball_n"), set_cor = in.Given("-ball_cor"),
             set_tau = in.Given("-ball_contact_time"), set_vt = in.Given("-ball_test_speed"),
             set_table = in.Given("-ball_cor_table");
  const char *msg      = nullptr;
  if (set_tau && set_k1)
    msg = "-ball_contact_time and -ball_k1 both set the loading coefficient k1: give either -ball_k1 or the "
          "characterisation -ball_contact_time with -ball_test_speed (k1 follows from them)";
  else if (set_vt && set_k1)
    msg = "-ball_test_speed and -ball_k1 both set the loading coefficient k1: give either -ball_k1 or the "
          "characterisation -ball_contact_time with -ball_test_speed (k1 follows from them)";
  else if (set_cor && set_n)
    msg = "-ball_cor and -ball_n both set the unloading exponent n: give either -ball_n or -ball_cor (n = (m+1)/e^2 - "
          "1)";
  else if (set_table && set_n)
    msg = "-ball_cor_table and -ball_n both set the unloading exponent n: with a table, n follows e(v) of each "
          "contact's approach speed; drop -ball_n";
  else if (set_table && set_cor)
    msg = "-ball_cor_table and -ball_cor both set the coefficient of restitution: with a table, e at the test speed is "
          "the table's; drop -ball_cor";
  if (msg) {
    *why = msg;
    return PETSC_ERR_ARG_INCOMP;
  }
  if (set_tau != set_vt) {
    *why = Fmt("%s needs %s: the contact time is measured at a test speed (k1 follows from the two)",
               set_tau ? "-ball_contact_time" : "-ball_test_speed",
               set_tau ? "-ball_test_speed" : "-ball_contact_time");
    return PETSC_ERR_ARG_INCOMP;
  }
  return 0;
}

// n from -ball_cor or the table, then k1 from the contact time (which needs e at the test speed).
int HysteresisLaw::Configure(const ContactLawInput &in, BallParams *b, std::string *why) const
{
  if (const int code = CharacterisationConflict(in, why)) return code;
  PetscReal &k1 = b->value[kK1], &m = b->value[kM], &n = b->value[kN], &cor = b->value[kCor];
  if (in.Given("-ball_cor_table")) {
    if (!in.read_cor_table) {
      *why = "-ball_cor_table: no reader of e(v) tables was given to the hysteretic law";
      return PETSC_ERR_PLIB;
    }
    if (!in.read_cor_table(in.Text("-ball_cor_table"), &b->cor_table, why)) return PETSC_ERR_FILE_UNEXPECTED;
  }
  if (in.Given("-ball_cor")) n = BallExponentFromCor(m, cor);
  if (in.Given("-ball_cor_table"))
    n = BallExponentAt(*b, b->speed); // the first contact's; each later contact sets its own
  if (in.Given("-ball_contact_time")) {
    const PetscReal tau = b->value[kContactTime], vt = b->value[kTestSpeed];
    cor = WallCor(*b, vt);
    k1  = BallK1FromContactTime(b->mass, m, cor, tau, vt);
    if (!(std::isfinite(k1) && k1 > 0)) {
      *why = Fmt("-ball_contact_time %g s at -ball_test_speed %g m/s gives k1 = %g N/m^m, which is not a "
                 "usable number: check the contact time, the speed and -ball_m %g",
                 (double)tau, (double)vt, (double)k1, (double)m);
      return PETSC_ERR_ARG_OUTOFRANGE;
    }
  }
  if (!(n >= m)) {
    *why = Fmt("-ball_n %g is not allowed: the unloading exponent must be >= m = %g (energy can only be "
               "lost)",
               (double)n, (double)m);
    return PETSC_ERR_ARG_OUTOFRANGE;
  }
  return 0;
}

// k1, m, n; the characterisation when given (e, tau, v_t; the table's file).
std::vector<ContactLawRecord> HysteresisLaw::Record(const BallParams &b) const
{
  std::vector<ContactLawRecord> all = ContactLaw::Record(b), out;
  for (const ContactLawRecord &r : all) {
    if (r.name == "ball_cor" && !(b.value[kCor] > 0)) continue;
    if ((r.name == "ball_contact_time" || r.name == "ball_test_speed") && !(b.value[kContactTime] > 0)) continue;
    out.push_back(r);
  }
  if (!b.cor_table.empty()) {
    ContactLawRecord t;
    t.name = "ball_cor_table", t.text = b.cor_table.file, t.is_text = true;
    out.push_back(t);
  }
  return out;
}

} // namespace

const ContactLaw &HysteresisContactLaw()
{
  static const HysteresisLaw law;
  return law;
}

PetscReal ContactCycleLoss(const BallParams &b, PetscReal c_max)
{
  const PetscReal k1 = b.value[kK1], m = b.value[kM], n = b.value[kN];
  return (n - m) * k1 * std::pow(c_max, m + 1) / ((m + 1) * (n + 1));
}

PetscReal BallExponentFromCor(PetscReal m, PetscReal e)
{
  return std::max(m, (m + 1) / (e * e) - 1);
} // e = 1: exactly m, not m - ulp

PetscReal BallExponentAt(const BallParams &b, PetscReal v)
{
  return b.cor_table.empty() ? b.value[kN] : BallExponentFromCor(b.value[kM], b.cor_table(v));
}

PetscReal BallK1FromContactTime(PetscReal mass, PetscReal m, PetscReal e, PetscReal tau, PetscReal v)
{
  const PetscReal n    = BallExponentFromCor(m, e);
  const PetscReal tau1 = (PowerLawWallIntegral(m + 1) + PowerLawWallIntegral(n + 1) / e) /
                         v; // tau at k1 = A, in units where c_max = 1
  return 0.5 * (m + 1) * mass * v * v * std::pow(tau1 / tau, m + 1);
}

} // namespace beamimpact

// The Hertz contact (-ball_law hertz; docs/model.md section 2): F = k c^(3/2), k in N/m^(3/2),
// the force of an elastic sphere pressed on a flat (Hertz 1882; K. L. Johnson, Contact
// Mechanics, section 4.2): k = (4/3) E* sqrt(R) for a ball of radius R, with E* = E/(1 - nu^2)
// against a rigid flat (1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2 for two elastic bodies).
// It loses nothing: on a rigid wall the ball returns at its speed (e = 1), with (power law
// p = 3/2, MODEL section 6)
//   c_max = ((p+1) m_b v^2 / (2 k))^(1/(p+1)),  t = 2 (c_max / v) I(p+1),  I(q) = B(1/q, 1/2)/q,
// so the contact time falls with speed as v^(-1/5). Its ACOR is corrected for the ball's losses
// by -ball_loss_factor, like the linear spring's.
#include "model/contact_law.hpp"

#include <cmath>

namespace beamimpact {

namespace {

enum {
  kK
};                            // BallParams::value: the rows' order
constexpr PetscReal kP = 1.5; // the exponent

class HertzLaw final : public ContactLaw {
public:
  const char                    *Name() const override { return "hertz"; }
  const char                    *Summary() const override { return "F = k c^(3/2), elastic: a sphere on a flat"; }
  const std::vector<OptionSpec> &Options() const override
  {
    static const std::vector<OptionSpec> rows = {
      OptionReal("-ball_hertz_k", "N/m^(3/2)",
                 "Hertz stiffness k of F = k c^(3/2) (a ball of radius R on a rigid flat: (4/3) E/(1 - nu^2) sqrt(R)); "
                 "-ball_law hertz",
                 "5e5", Positive()),
    };
    return rows;
  }

  PetscReal Force(const BallParams &b, const ContactState &, PetscReal c) const override
  {
    return b.value[kK] * ContactOddPow(c, kP);
  }
  PetscReal Stiffness(const BallParams &b, const ContactState &, PetscReal c) const override
  {
    return kP * b.value[kK] * std::sqrt(std::abs(c));
  }
  PetscReal Stored(const BallParams &b, const ContactState &, PetscReal c) const override
  {
    return b.value[kK] * ContactPowAntiderivative(c, kP);
  }
  bool Elastic() const override { return true; }

  PetscReal WallMaxCompression(const BallParams &b, PetscReal v) const override
  {
    return std::pow(0.5 * (kP + 1) * b.mass * v * v / b.value[kK], 1 / (kP + 1));
  }
  PetscReal WallLoadingTime(const BallParams &b, PetscReal v) const override
  {
    return WallMaxCompression(b, v) / v * PowerLawWallIntegral(kP + 1);
  }

  // The wall's contact time and compression at the incident speed; dF/dc up to twice that compression.
  PetscReal TimeScale(const BallParams &b) const override { return 2 * WallLoadingTime(b, b.speed); }
  PetscReal CompressionScale(const BallParams &b) const override { return WallMaxCompression(b, b.speed); }
  PetscReal StiffnessBound(const BallParams &b) const override
  {
    return kP * b.value[kK] * std::sqrt(2 * CompressionScale(b));
  }
};

} // namespace

const ContactLaw &HertzContactLaw()
{
  static const HertzLaw law;
  return law;
}

} // namespace beamimpact

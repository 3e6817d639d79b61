// The linear spring (-ball_law linear, the default; docs/model.md section 2): F = k c, k in N/m.
// It loses nothing: on a rigid wall the ball returns at its speed (e = 1) after pi sqrt(m_b/k),
// and its ACOR is corrected for the ball's losses by -ball_loss_factor (the paper's x 0.85).
// Linear, so the exact modal reference (-reference modal) applies.
#include "model/contact_law.hpp"

#include <cmath>

namespace beamimpact {

namespace {

enum {
  kK
}; // BallParams::value: the rows' order

class LinearLaw final : public ContactLaw {
public:
  const char                    *Name() const override { return "linear"; }
  const char                    *Summary() const override { return "F = k c, elastic"; }
  const std::vector<OptionSpec> &Options() const override
  {
    static const std::vector<OptionSpec> rows = {
      OptionReal("-ball_k", "N/m", "Linear spring stiffness k; -ball_law linear", "2e4", Positive()),
    };
    return rows;
  }

  PetscReal Force(const BallParams &b, const ContactState &, PetscReal c) const override { return b.value[kK] * c; }
  PetscReal Stiffness(const BallParams &b, const ContactState &, PetscReal) const override { return b.value[kK]; }
  PetscReal Stored(const BallParams &b, const ContactState &, PetscReal c) const override
  {
    return 0.5 * b.value[kK] * c * c;
  }
  bool      Elastic() const override { return true; }
  bool      Linear() const override { return true; }
  PetscReal LinearStiffness(const BallParams &b) const override { return b.value[kK]; }

  // A half period of the ball on the spring, whatever the speed: pi sqrt(m_b/k) in all.
  PetscReal WallMaxCompression(const BallParams &b, PetscReal v) const override
  {
    return v * std::sqrt(b.mass / b.value[kK]);
  }
  PetscReal WallLoadingTime(const BallParams &b, PetscReal) const override { return 0.5 * TimeScale(b); }

  PetscReal TimeScale(const BallParams &b) const override { return M_PI * std::sqrt(b.mass / b.value[kK]); }
  PetscReal CompressionScale(const BallParams &b) const override { return b.speed * std::sqrt(b.mass / b.value[kK]); }
  PetscReal StiffnessBound(const BallParams &b) const override { return b.value[kK]; }
};

} // namespace

const ContactLaw &LinearContactLaw()
{
  static const LinearLaw law;
  return law;
}

} // namespace beamimpact

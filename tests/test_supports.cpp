// Supports as a registry (model/support.hpp): the built-in entries hold what docs/model.md says,
// -beam_left/-beam_right choose among the registered names, and a new support is one entry. A
// guided end (the rotation held, the deflection free), registered here as one SupportSpec, gets
// its end condition in both theories, its rigid mode and its modes from what it holds alone;
// they are checked against the closed forms of a uniform beam: guided-free and guided-clamped
// tan(bL) + tanh(bL) = 0 (bL = 2.36502, 5.49780), guided-pinned cos(bL) = 0 (pi/2, 3 pi/2),
// guided-guided sin(bL) = 0 (pi, 2 pi, with the translation rigid).
#include "io/beam_options.hpp"
#include "model/support.hpp"
#include "solvers/modes.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace beamimpact;
using test::AluminiumBeam;
using test::SystemOf;

namespace {

const SupportSpec kGuided = {"guided", "no slope and no shear force: y' = 0, y''' = 0", NodeHold::Guide};

// bL of the flexural modes of p (rigid ones left out): omega = (bL)^2 sqrt(EI/mu)/L^2.
std::vector<PetscReal> BetaL(const BeamParams &p, PetscInt count, PetscInt *rigid)
{
  ModesResult                         modes;
  std::vector<std::vector<PetscReal>> shapes;
  const BeamSystem                    sys = SystemOf(p);
  EXPECT_EQ(0, BeamModesCompute(PETSC_COMM_WORLD, sys, count, &modes, &shapes));
  *rigid = modes.rigid_count;
  std::vector<PetscReal> bl;
  for (PetscReal w : modes.omega)
    if (w > 0) bl.push_back(std::sqrt(w * p.length * p.length / std::sqrt(p.EI / p.mu)));
  return bl;
}

BeamParams Timoshenko(BeamParams p)
{
  const PetscReal E = 7e10, G = 2.6e10, rho = 2700, a = 0.006, b = 0.032; // the paper's aluminium bar
  p.theory = "timoshenko";
  p.kGA    = 5.0 / 6.0 * G * a * b;
  p.rhoI   = rho * b * a * a * a / 12;
  (void)E;
  return p;
}

} // namespace

TEST(Supports, BuiltInEntriesHoldWhatTheModelSays)
{
  const std::vector<std::string> names = SupportNames(), builtin = {"free", "clamped", "pinned"};
  ASSERT_GE(names.size(), 3u);
  EXPECT_EQ(builtin, std::vector<std::string>(names.begin(), names.begin() + 3));
  EXPECT_EQ(NodeHold::None, Support::Free.Holds());
  EXPECT_EQ(NodeHold::Clamp, Support::Clamped.Holds());
  EXPECT_EQ(NodeHold::Pin, Support::Pinned.Holds());
  Support s = Support::Free;
  ASSERT_TRUE(SupportFind("CLAMPED", &s));
  EXPECT_EQ(Support::Clamped, s);
  EXPECT_FALSE(SupportFind("glued", &s));
  // -beam_left and -beam_right offer the registry's names (those registered when the tables were)
  EXPECT_EQ(builtin, BeamOptionTable().Find("-beam_left")->choices);
  EXPECT_EQ(builtin, BeamOptionTable().Find("-beam_right")->choices);
}

// The rigid modes each pair of supports leaves, from what they hold, against the count the
// eigen-solver's check takes from the held dofs and the strain energy of the built system.
TEST(Supports, RigidModesFromWhatTheyHold)
{
  SupportRegister(&kGuided);
  const Support guided(&kGuided);
  for (const Support &l : {Support::Free, Support::Clamped, Support::Pinned, guided})
    for (const Support &r : {Support::Free, Support::Clamped, Support::Pinned, guided})
      for (bool timo : {false, true}) {
        BeamParams p = AluminiumBeam(1.1, 41, l, r);
        if (timo) p = Timoshenko(p);
        EXPECT_EQ(SupportRigidModes(l, r), BeamSystemRigidCount(SystemOf(p))) << l.Name() << "-" << r.Name() << (timo ? " (Timoshenko)" : "");
      }
  EXPECT_EQ(2, SupportRigidModes(Support::Free, Support::Free));
  EXPECT_EQ(1, SupportRigidModes(Support::Pinned, Support::Free));
  EXPECT_EQ(0, SupportRigidModes(Support::Clamped, Support::Free));
  EXPECT_EQ(0, SupportRigidModes(Support::Pinned, Support::Pinned));
  EXPECT_EQ(1, SupportRigidModes(guided, Support::Free));  // the translation
  EXPECT_EQ(1, SupportRigidModes(guided, guided));
  EXPECT_EQ(0, SupportRigidModes(guided, Support::Pinned));
}

// A guided end is one entry: both theories give the modes of the closed forms at second order.
TEST(Supports, AGuidedEndIsOneEntry)
{
  SupportRegister(&kGuided);
  Support guided = Support::Free;
  ASSERT_TRUE(SupportFind("guided", &guided));
  struct Case {
    Support                other;
    PetscInt               rigid;
    std::vector<PetscReal> bl;
  };
  const Case cases[] = {
    {Support::Free, 1, {2.36502, 5.49780}},
    {Support::Clamped, 0, {2.36502, 5.49780}},
    {Support::Pinned, 0, {M_PI / 2, 3 * M_PI / 2}},
    {guided, 1, {M_PI, 2 * M_PI}},
  };
  for (const Case &c : cases)
    for (bool timo : {false, true}) {
      BeamParams p = AluminiumBeam(1.1, 201, guided, c.other);
      if (timo) p = Timoshenko(p);
      PetscInt                     rigid = -1;
      const std::vector<PetscReal> bl    = BetaL(p, c.rigid + 2, &rigid);
      const std::string            what  = std::string("guided-") + c.other.Name() + (timo ? " (Timoshenko)" : "");
      EXPECT_EQ(c.rigid, rigid) << what;
      ASSERT_EQ(2u, bl.size()) << what;
      for (size_t n = 0; n < 2; ++n) EXPECT_NEAR(c.bl[n], bl[n], 1e-3 * c.bl[n]) << what << " mode " << n + 1;
      if (!timo) { // the fundamental's scale for default windows knows the new end too
        EXPECT_NEAR(bl[0], std::sqrt(BeamFundamentalFrequencyEstimate(p) * p.length * p.length / std::sqrt(p.EI / p.mu)), 1e-3 * bl[0]) << what;
      }
    }
}

// The hands (-grip): a spring-damper per metre of handle tying the bat to the swing's rigid
// frame. (a) a uniform grip over a uniform beam: both rigid modes become mass-spring modes at
// sqrt(k'/mu) = sqrt(k L / M); (b) the energy balance closes with the grip's stored energy, its
// damper (in D) and the hands' work, at rest and swinging, TS and leapfrog; (c) the swinging-bat
// identity holds with e_A of the gripped bat at rest (the grip ties to the moving frame) and
// not with e_A of the free bat; (d) a grip of zero strength changes nothing; (e) the registry of
// structure parts gives the hands.
#include "io/ball_options.hpp"
#include "io/beam_options.hpp"
#include "solvers/leapfrog.hpp"
#include "solvers/modes.hpp"

#include "test_helpers.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace beamimpact;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

// The paper's beam (1.1 m aluminium, free-free) and the linear superball at 1 m/s, read from the
// options files as a command line would, plus `extra`.
void Paper(const Opts &extra, BeamParams *beam, BallParams *ball)
{
  Opts all{{"-beam_length", "1.1"}};
  all.insert(all.end(), extra.begin(), extra.end());
  test::ReadScene({"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, all, beam, ball);
}

ImpactResult RunSc(const Scenario &sc, const Opts &ts) { return test::RunWith(PETSC_COMM_WORLD, sc, ts); }

const Opts    kRK4  = {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "1e-6"}};
const Opts    kGrip = {{"-grip", "0,0.15"}, {"-grip_stiffness", "1e5"}, {"-grip_damping", "100"}};

} // namespace

// (a) k' and mu uniform over the whole beam: K_grip = k'/mu M, so the two rigid modes are
// mass-spring modes at sqrt(k'/mu) = sqrt(k L / M) (checked on K itself: the modes solver refuses a grip).
TEST(Grip, UniformGripRigidModesAreMassSpring)
{
  BeamParams beam;
  BallParams ball;
  Paper({{"-grip", "0,1.1"}, {"-grip_stiffness", "2e4"}}, &beam, &ball);
  BeamSystem  sys, free_sys;
  std::string why;
  ASSERT_TRUE(BeamSystemBuild(beam, &sys, &why));
  const BeamParams nogrip = test::WithoutGrip(beam);
  ASSERT_TRUE(BeamSystemBuild(nogrip, &free_sys, &why));
  // the rigid motions are exact eigenvectors of the gripped K: K r = (k'/mu) M r
  const PetscReal w0 = std::sqrt(2e4 * beam.length / (beam.mu * beam.length)); // -grip_stiffness
  for (const auto &r : {BeamSystemRigidVelocity(sys, 1.0, 0.0), BeamSystemRigidVelocity(sys, 0.0, 1.0)}) {
    std::vector<PetscReal> f(sys.ndof);
    BeamSystemStiffnessApply(sys, r.data(), sys.fields, 0, sys.ndof, f.data(), sys.fields);
    for (PetscInt d = 0; d < sys.ndof; ++d) EXPECT_NEAR(f[d], w0 * w0 * sys.mass[d] * r[d], 1e-9 * w0 * w0 * sys.mass[d]);
  }
  ModesResult m;
  EXPECT_NE(0, BeamModesCompute(PETSC_COMM_SELF, sys, 4, &m)) << "the modes solver refuses a grip (not yet supported)";
}

// (b) KE + U + W_ball + D + U_grip - W_hands = const, to the integrator's accuracy, at rest and
// swinging, with Rayleigh damping too, for the TS (rk4, cn, alpha2) and the leapfrog.
TEST(Grip, EnergyBalanceWithGripDamping)
{
  BeamParams beam;
  BallParams ball;
  Opts       o = kGrip;
  o.push_back({"-grip_mass", "0.2"});
  o.push_back({"-beam_damping_stiffness", "1e-6"});
  Paper(o, &beam, &ball);
  ImpactParams ip;
  ip.x      = 0.9;
  ip.window = 5e-3;
  for (bool swing : {false, true}) {
    Scenario sc(beam, ball, ip);
    if (swing) sc.swing.bat_speed = 0.5, sc.swing.bat_angular_velocity = 1.5;
    const ImpactResult r = RunSc(sc, kRK4);
    EXPECT_LT(std::abs(r.energy_error), 1e-9) << "rk4, swing " << swing;
    EXPECT_GT(r.beam_dissipated_end, 0);
    EXPECT_GT(test::Col(r, "grip_force_peak"), 0);
    if (swing) EXPECT_NE(test::Col(r, "hand_work_end"), 0.0);
    else EXPECT_EQ(test::Col(r, "hand_work_end"), 0.0);
    const ImpactResult c = RunSc(sc, {{"-ts_type", "cn"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}});
    EXPECT_LT(std::abs(c.energy_error), 1e-5) << "cn, swing " << swing;
    const ImpactResult a = RunSc(sc, {{"-ts_type", "alpha2"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}});
    EXPECT_LT(std::abs(a.energy_error), 1e-5) << "alpha2, swing " << swing;
    LeapfrogParams lp;
    lp.dt = 2e-6;
    ImpactResult l;
    ASSERT_EQ(0, LeapfrogRun(sc, lp, &l));
    EXPECT_LT(std::abs(l.energy_error), 1e-4) << "leapfrog, swing " << swing;
    EXPECT_NEAR(l.bbs, r.bbs, 1e-4 * std::abs(r.bbs)) << "leapfrog against rk4, swing " << swing;
  }
}

// (c) In the swing's frame the gripped problem is the gripped bat at rest hit at v + V(x): the
// identity BBS = e_A v + (1 + e_A) V(x) holds with e_A of the gripped bat at rest (a check of
// the frame term), not with e_A of the free bat. The slow superball (contact ~4 ms) on the
// paper's beam, a hand-held grip of 15 cm at one end.
TEST(Grip, SwingingIdentityNeedsTheGrippedBatsACOR)
{
  BeamParams gripped, free_beam;
  BallParams ball;
  Paper({{"-grip", "0,0.15"}, {"-grip_stiffness", "1e6"}, {"-grip_damping", "500"}}, &gripped, &ball);
  free_beam = test::WithoutGrip(gripped);
  ImpactParams ip;
  ip.x                = 0.9;
  ip.window           = 0; // to the first separation
  const PetscReal V_x = 0.5 + 1.5 * (0.9 - 0.55);
  Scenario        sw(gripped, ball, ip);
  sw.swing.bat_speed = 0.5, sw.swing.bat_angular_velocity = 1.5;
  BallParams fast = ball;
  fast.speed += V_x;
  const ImpactResult s  = RunSc(sw, kRK4);
  const ImpactResult rg = RunSc(Scenario(gripped, fast, ip), kRK4);
  const ImpactResult rf = RunSc(Scenario(free_beam, fast, ip), kRK4);
  const PetscReal    bbs_g = rg.acor * ball.speed + (1 + rg.acor) * V_x, bbs_f = rf.acor * ball.speed + (1 + rf.acor) * V_x;
  EXPECT_NEAR(bbs_g, s.bbs, 1e-9 * s.bbs);
  EXPECT_GT(std::abs(bbs_f - s.bbs), 1e-6 * s.bbs) << "the free bat's e_A does not describe the gripped swing";
  PetscPrintf(PETSC_COMM_WORLD, "gripped swing: bbs %.9g; identity with the gripped e_A %.9g (diff %.2e), with the free e_A %.9g (diff %.2e)\n", (double)s.bbs, (double)bbs_g,
              (double)(bbs_g - s.bbs), (double)bbs_f, (double)(bbs_f - s.bbs));
}

// (d) A grip of zero stiffness, damping and mass is no grip: the same bits.
TEST(Grip, ZeroGripChangesNothing)
{
  BeamParams beam, none;
  BallParams ball;
  Paper({{"-grip", "0,0.15"}}, &beam, &ball);
  none = test::WithoutGrip(beam);
  ImpactParams ip;
  ip.x                 = 0.9;
  ip.window            = 0;
  const ImpactResult a = RunSc(Scenario(beam, ball, ip), kRK4), b = RunSc(Scenario(none, ball, ip), kRK4);
  EXPECT_EQ(a.acor, b.acor);
  EXPECT_EQ(a.contact_time, b.contact_time);
  EXPECT_EQ(a.peak_force, b.peak_force);
}

// The registry gives the hands (system/structure_part.hpp): a part without fields that ties the
// structure to the swing's frame. Against the formulas over [x_a, x_b] with its span s = x_b - x_a
// (the nodes' shares add up to s exactly): a relative displacement u stores 1/2 k' s u^2, pushes
// the frame with k' s u (plus c' s w for a relative velocity w), the hands add m_hand to the
// beam; momentum is not an invariant; its columns keep their place after bbcor; its refusals.
TEST(GripPart, RegistryGivesTheHands)
{
  const StructurePart *part = StructurePartFind("grip");
  ASSERT_NE(part, nullptr) << "the hands are a registered structure part";
  BeamGrip g;
  g.x_a = 0.03, g.x_b = 0.17, g.stiffness = 1e5, g.damping = 40, g.mass = 0.2; // not on nodes: partial cells
  const PetscReal  s = g.x_b - g.x_a, u = 2e-3, w = 0.3, vf = 0.7, t = 1e-3;
  const BeamParams bare = test::AluminiumBeam(1.1, 23), p = test::WithGrip(bare, g);
  ASSERT_TRUE(p.parts.Has("grip"));
  EXPECT_TRUE(part->TiesToFrame(*p.parts.Find("grip")));
  EXPECT_TRUE(StructurePartsTieToFrame(p));
  EXPECT_FALSE(StructurePartsTieToFrame(bare));
  const BeamSystem S = test::SystemOf(p), F = test::SystemOf(bare);
  EXPECT_TRUE(S.TiedToFrame());
  EXPECT_FALSE(F.TiedToFrame());
  EXPECT_EQ(S.fields, F.fields) << "the hands have no fields";
  PetscReal added = 0; // the hands' mass on the deflections
  for (PetscInt d = 0; d < S.ndof; ++d) added += S.mass[d] - F.mass[d];
  EXPECT_NEAR(added, g.mass, 1e-14);

  // The frame moves uniformly at vf: the handle at vf t + u, moving at vf + w, relative u and w.
  FrameMotion frame;
  frame.v.assign(S.ndof, 0.0);
  std::vector<PetscReal> y(S.ndof, 0.0), v(S.ndof, 0.0);
  for (PetscInt i = 0; i < S.nodes; ++i) frame.v[S.Dof(i)] = vf, y[S.Dof(i)] = vf * t + u, v[S.Dof(i)] = vf + w;
  ForceState fs;
  fs.y = y.data(), fs.ys = S.fields, fs.v = v.data(), fs.vs = S.fields, fs.t = t, fs.frame = &frame;
  PetscReal elastic = 0, stored = 0, force = 0, moment = 0;
  ForceOperatorEnergy(S, fs, 0, S.ndof, &elastic, &stored);
  EXPECT_NEAR(stored, 0.5 * g.stiffness * s * u * u, 1e-12 * g.stiffness * s * u * u);
  ForceOperatorFrameReaction(S, fs, 0, S.ndof, &force, &moment);
  EXPECT_NEAR(force, g.stiffness * s * u + g.damping * s * w, 1e-12 * g.stiffness * s * u);
  EXPECT_NEAR(ForceOperatorDissipationRate(S, fs, 0, S.ndof), g.damping * s * w * w, 1e-12 * g.damping * s * w * w);

  // Momentum is not an invariant with the hands: its error columns do not apply.
  const Scenario held(p, test::Superball(), ImpactParams()), free_bat(bare, test::Superball(), ImpactParams());
  EXPECT_FALSE(ResultMomentumInvariant(held));
  EXPECT_FALSE(ResultFreeBeamAtRest(held));
  EXPECT_TRUE(ResultMomentumInvariant(free_bat));

  // Its columns follow bbcor, in their order, and apply with -grip; their series under its own monitor.
  const std::vector<std::string> names = {"bbcor",         "grip_force_peak", "grip_force_peak_time",
                                          "grip_stored_end", "hand_work_end", "grip_fraction",
                                          "hands_fraction",  "shell_energy_end"};
  const std::vector<ResultColumn> &table = ImpactResultColumns();
  const auto at = std::find_if(table.begin(), table.end(),
                               [](const ResultColumn &c) { return c.name == std::string("bbcor"); });
  ASSERT_LT(at + (names.size() - 1), table.end());
  for (size_t k = 0; k < names.size(); ++k) EXPECT_EQ(names[k], (at + k)->name);
  EXPECT_STREQ(ImpactResultColumn("grip_fraction")->share, "grip");
  EXPECT_STREQ(ImpactResultColumn("grip_force_peak")->applies_text, "with -grip");
  EXPECT_FALSE(part->Monitors(*p.parts.Find("grip")));
  for (const PartSlot &slot : part->Slots()) EXPECT_TRUE(slot.series && slot.own_monitor) << slot.name;

  // Its line, its refusals: the modal reference, the roll's hold without a roll, a held end.
  EXPECT_EQ(part->Summary(*p.parts.Find("grip"), {1, 2, 3, 4}),
            "hands on 0.03-0.17 m: peak force on the hands 1.0000e+00 N at 2.0000e+00 s; grip energy stored at the end "
            "3.0000e+00 J; work done by the hands 4.0000e+00 J");
  EXPECT_NE(StructurePartsModalRefusal(p).find("-grip"), std::string::npos);
  BeamGrip twisted = g;
  twisted.torsion_stiffness = 5;
  EXPECT_NE(StructurePartsRefusalWith(test::WithGrip(bare, twisted))
              .find("-grip_torsion_stiffness 5 without -beam_torsion"),
            std::string::npos);
  BeamParams clamped = bare;
  clamped.left       = Support::Clamped;
  PartOptionValues ov;
  ov.given["-grip"] = {g.x_a, g.x_b};
  std::shared_ptr<const PartParams> q;
  std::string                       why;
  EXPECT_FALSE(part->Configure(ov, clamped, &q, &why));
  EXPECT_NE(why.find("the hands hold a free bat"), std::string::npos) << why;
}

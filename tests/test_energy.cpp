// Where the energy went, as an invariant of every structure (issue 34; docs/model.md section 4):
// at the end of one impact on each structure the suite knows (the paper's free beam, clamped
// and pinned beams, a Timoshenko bat, a damped beam, a swinging bat with and without the hands,
// the pivoted rig, the barrel's hoop and shell, the string bed held, the strung racket rolling,
// the gripped racket whose hand holds the roll) the energy-partition columns of the results
// table (every *_fraction column that applies but Eq. 11's two and the ball's rebound, summed
// by name: a tracked energy without its column is a failure) plus the ball's share, computed
// here from the run's final ball velocity and the energy brought in (the ball's and a swinging
// bat's, the latter from the system's masses and the swing), add up to 1:
//   * exactly up to the energy error (the same number: sum - 1 = energy_error to round-off);
//   * and to the integrator's tolerance, which sets energy_error: -ts_type modal (the beam's flow
//     exact, the contact force a polynomial over each step) 1e-7, measured at most 8.9e-9 here; a
//     run with the hands, which the modal integrator does not carry, Crank-Nicolson at a fixed step
//     of about 1/1500 of the contact (5e-7 s on the bat, 5e-6 s on the racket; second order)
//     1e-5, measured at most 1.2e-6 (at 4 times the step it was 1.8e-5).
// Where the free flight is modal, each label of /modes_energy (a rigid mode's motion, a flexible
// one's part) sums to its column to 1e-10 of E_in, but for the strung racket's bending, roll and
// strings, whose modes the bed shares with its frame (there the labels' total is checked).
#include "model/rigid.hpp"
#include "model/swing.hpp"
#include "run/energy_parts.hpp"
#include "run/measures.hpp"
#include "run/results_table.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace beamimpact;

namespace {

using Opts = std::vector<std::pair<std::string, std::string>>;

const Opts kModal = {{"-ts_type", "modal"}};

struct Case {
  const char              *name;
  std::vector<std::string> files;
  Opts                     options;  // read as a command line's
  PetscReal                x, z;     // m, the impact point
  SwingParams              swing;    // at rest unless set
  Opts                     ts;       // the integrator
  PetscReal                tol;      // the closure's tolerance, set by the integrator
  const char              *parts;    // the labels /modes_energy must hold (space-separated; "" when the flight is stepped)
  bool                     coupled = false; // the bed shares its modes with its frame
};

bool EndsWith(const std::string &s, const char *tail) { return s.size() >= std::strlen(tail) && s.compare(s.size() - std::strlen(tail), std::string::npos, tail) == 0; }

// The energy brought in (J): the ball's, and a swinging bat's from the system's lumped masses.
PetscReal EnergyIn(const Scenario &sc)
{
  PetscReal E = 0.5 * sc.ball.mass * sc.ball.speed * sc.ball.speed;
  if (!sc.swing.Swings()) return E;
  const BeamSystem             sys = test::SystemOf(sc.beam);
  const std::vector<PetscReal> v   = BeamSystemSwingVelocity(sys, sc.swing, BeamRigidBodyOf(sc.beam));
  for (PetscInt d = 0; d < sys.ndof; ++d) E += 0.5 * sys.mass[d] * v[d] * v[d];
  return E;
}

// The energy-partition columns that apply to sc, summed (*listing: name = value).
PetscReal PartitionSum(const Scenario &sc, const ImpactResult &r, std::string *listing)
{
  PetscReal sum = 0;
  for (const ResultColumn &c : ImpactResultColumns()) {
    const std::string n = c.name;
    if (!EndsWith(n, "_fraction") || n == "rigid_loss_fraction" || n == "rigid_forced_loss_fraction" || n == "rebound_fraction" || !c.Applies(sc)) continue;
    EXPECT_TRUE(std::isfinite(c.Get(r))) << n;
    sum += c.Get(r);
    *listing += " " + n + " = " + std::to_string(c.Get(r));
  }
  return sum;
}

// The column a mode's label adds up to.
const char *ColumnOf(const ModeEnergy &e)
{
  static const std::map<std::string, const char *> rigid = {{"translation", "translation_fraction"}, {"rotation", "rotation_fraction"}, {"roll", "roll_fraction"}};
  static const std::map<std::string, const char *> flex  = {{"bending", "vibration_fraction"}, {"roll", "twist_fraction"}, {"wall", "wall_fraction"}, {"strings", "bed_fraction"}};
  const auto &m = e.rigid ? rigid : flex;
  const auto  i = m.find(e.part);
  return i == m.end() ? "" : i->second;
}

void CheckModeParts(const Case &c, const ImpactResult &r)
{
  std::map<std::string, PetscReal> sums;
  PetscReal                        flexible = 0, flexible_columns = 0;
  std::string                      labels;
  for (const ModeEnergy &e : r.mode_energies) {
    const std::string col = ColumnOf(e);
    ASSERT_FALSE(col.empty()) << c.name << ": a mode labelled '" << e.part << "'";
    if (labels.find(" " + std::string(e.part) + " ") == std::string::npos && !e.rigid) labels += " " + std::string(e.part) + " ";
    sums[col] += e.fraction;
    if (!e.rigid) flexible += e.fraction;
  }
  for (const char *p : {"bending", "roll", "wall", "strings"})
    EXPECT_EQ(labels.find(" " + std::string(p) + " ") != std::string::npos, (" " + std::string(c.parts) + " ").find(" " + std::string(p) + " ") != std::string::npos)
      << c.name << ": flexible labels" << labels << ", expected " << c.parts;
  for (const auto &kv : sums) {
    const PetscReal column = ImpactResultColumn(kv.first.c_str())->Get(r);
    const bool      flex   = kv.first != "translation_fraction" && kv.first != "rotation_fraction" && kv.first != "roll_fraction";
    if (flex) flexible_columns += column;
    if (!(c.coupled && flex)) {
      EXPECT_NEAR(kv.second, column, 1e-10) << c.name << ": the modes labelled for " << kv.first;
    }
  }
  EXPECT_NEAR(flexible, flexible_columns, 1e-10) << c.name << ": the flexible modes against the flexible fractions";
}

} // namespace

TEST(EnergyClosure, EveryStructure)
{
  const char *const aluminium = "options/bats/aluminium-bat.opts", *const baseball = "options/balls/baseball.opts";
  const Opts        paper     = {{"-beam_length", "1.1"}, {"-beam_nodes", "41"}};
  const Opts        bat       = {{"-beam_nodes", "41"}};
  const Opts        racket    = {{"-strings_patch_radius", "0.015"}};
  const Opts        hand      = {{"-grip", "0.52,0.72"}, {"-grip_stiffness", "2e4"}, {"-grip_damping", "10"}, {"-grip_mass", "0.3"}};
  const Opts        cn        = {{"-ts_type", "cn"}, {"-ts_dt", "5e-7"}, {"-ts_adapt_type", "none"}};
  SwingParams       swing;
  swing.bat_speed = 24, swing.bat_angular_velocity = 51;
  auto join = [](Opts a, const Opts &b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<Case> cases = {
    {"the paper's free beam (hysteresis)", {"options/base/aluminium-6mm.opts", "options/base/superball-hysteresis.opts"}, paper, 0.9, 0, {}, kModal, 1e-7, "bending"},
    {"the paper's beam clamped at x = 0 (linear, loss factor)", {"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, join(paper, {{"-beam_left", "clamped"}}), 0.9, 0, {}, kModal, 1e-7,
     "bending"},
    {"the paper's beam pinned at x = 0", {"options/base/aluminium-6mm.opts", "options/base/superball-linear.opts"}, join(paper, {{"-beam_left", "pinned"}}), 0.9, 0, {}, kModal, 1e-7, "bending"},
    {"the paper's beam, damped", {"options/base/aluminium-6mm.opts", "options/base/superball-hysteresis.opts"}, join(paper, {{"-beam_damping_stiffness", "1e-5"}, {"-beam_damping_mass", "2"}}), 0.9, 0,
     {}, kModal, 1e-7, "bending"},
    {"a Timoshenko bat", {aluminium, baseball}, join(bat, {{"-beam_theory", "timoshenko"}}), 0.66, 0, {}, kModal, 1e-7, "bending"},
    {"the bat swinging at a ball at rest", {aluminium, baseball}, join(bat, {{"-ball_speed", "0"}}), 0.66, 0, swing, kModal, 1e-7, "bending"},
    {"the bat swinging in the hands", {aluminium, baseball}, join(bat, {{"-grip", "0.05,0.2"}, {"-grip_stiffness", "1e5"}, {"-grip_damping", "100"}}), 0.66, 0, swing, cn, 1e-5, ""},
    {"the pivoted rig", {aluminium, baseball}, join(bat, {{"-beam_pivot", "0.152"}}), 0.66, 0, {}, kModal, 1e-7, "bending"},
    {"the barrel's hoop", {aluminium, baseball}, join(bat, {{"-barrel_hoop_frequency", "1000"}, {"-barrel_hoop_mass", "0.27"}}), 0.66, 0, {}, kModal, 1e-7, "bending wall"},
    {"the barrel's shell", {aluminium, baseball}, join(bat, {{"-beam_shell", "true"}}), 0.66, 0, {}, kModal, 1e-7, "bending wall"},
    {"the string bed held", {"options/base/tennis-ball.opts"},
     {{"-strings_frame", "held"}, {"-head_shape", "ellipse"}, {"-head_length", "0.30"}, {"-head_width", "0.24"}, {"-strings_tension", "240"}, {"-strings_nodes", "21"}}, 0.15, 0.02, {}, kModal, 1e-7,
     "strings"},
    {"the strung racket rolling", {"options/base/racket-strung.opts", "options/base/tennis-ball.opts"}, racket, 0.15, 0.05, {}, kModal, 1e-7, "bending roll strings", true},
    {"the strung racket in a hand holding its roll", {"options/base/racket-strung.opts", "options/base/tennis-ball.opts"}, join(join(racket, hand), {{"-grip_torsion_stiffness", "1e4"}, {"-grip_torsion_damping", "2"}}), 0.15, 0.05,
     {}, {{"-ts_type", "cn"}, {"-ts_dt", "5e-6"}, {"-ts_adapt_type", "none"}}, 1e-5, ""},
  };
  for (const Case &c : cases) {
    Scenario sc;
    test::ReadScene(c.files, c.options, &sc.beam, &sc.ball);
    sc.impact.x  = c.x;
    sc.impact.z  = c.z;
    sc.swing     = c.swing;
    const ImpactResult r = test::RunWith(PETSC_COMM_WORLD, sc, c.ts);
    ASSERT_EQ(1, r.contacts) << c.name;
    const PetscReal E_in = EnergyIn(sc);
    const PetscReal lf   = ContactElastic(sc.ball) ? sc.ball.loss_factor : 1;
    const PetscReal ball = lf * lf * 0.5 * sc.ball.mass * r.ball_final_velocity * r.ball_final_velocity / E_in; // the ball's share
    std::string     listing;
    const PetscReal sum = PartitionSum(sc, r, &listing) + ball;
    EXPECT_NEAR(sum - 1, r.energy_error, 1e-12) << c.name << ": the fractions" << listing << " and the ball's " << ball << " must close with the energy balance";
    EXPECT_NEAR(sum, 1.0, c.tol) << c.name << ":" << listing << ", the ball's " << ball;
    const ResultColumn *rebound = ImpactResultColumn("rebound_fraction");
    EXPECT_NE(nullptr, rebound) << "the ball's share has its column";
    if (rebound) {
      EXPECT_NEAR(rebound->Get(r), ball, 1e-14) << c.name;
    }
    if (sc.ball.speed > 0 && !sc.swing.Swings()) {
      EXPECT_NEAR(ball, r.acor_corrected * r.acor_corrected, 1e-14) << c.name << ": a bat at rest: the ball's share is acor_corrected^2";
    }
    if (*c.parts) {
      ASSERT_FALSE(r.mode_energies.empty()) << c.name;
      CheckModeParts(c, r);
    }
  }
}

// The energy accounts (issue 35): the split's parts, the measures' sums and -task modes' families
// come from the registry, account 0 the beam's, then each part with an AccountName in registry
// order, each name once (StructureAccountName).
TEST(EnergyAccounts, TheRegistryDeclaresThem)
{
  ASSERT_EQ(StructureAccountCount(), 4);
  EXPECT_STREQ(StructureAccountName(0), "bending");
  EXPECT_EQ(StructureAccountPart(0), nullptr) << "the beam's account is no part's";
  PetscInt own = 0;
  for (const StructurePart *p : StructureParts()) {
    const PetscInt a = StructureAccountOf(*p);
    if (!p->AccountName()) {
      EXPECT_EQ(a, 0) << p->Name() << ": no account of its own, the beam's";
      continue;
    }
    EXPECT_EQ(a, ++own) << p->Name() << ": numbered in registry order";
    EXPECT_STREQ(StructureAccountName(a), p->AccountName());
    EXPECT_EQ(StructureAccountPart(a), p);
  }
  EXPECT_STREQ(StructureAccountName(StructureAccountOf(*StructurePartFind("roll"))), "roll");
  EXPECT_STREQ(StructureAccountName(StructureAccountOf(*StructurePartFind("wall"))), "wall");
  EXPECT_STREQ(StructureAccountName(StructureAccountOf(*StructurePartFind("bed"))), "strings");
  EXPECT_TRUE(StructureAccountApart(StructureAccountOf(*StructurePartFind("wall")))) << "not in beam_kinetic, beam_strain";
  EXPECT_FALSE(StructureAccountApart(StructureAccountOf(*StructurePartFind("bed"))));
  EXPECT_FALSE(StructureAccountApart(0));
}

namespace {

// The structure's measures of one state (y, v over every dof), as the recorder takes them.
StateMeasures MeasuresOf(const BeamSystem &sys, const std::vector<PetscReal> &y, const std::vector<PetscReal> &v)
{
  const ContactCoupling g = BeamSystemCoupling(sys, 0.5 * sys.L);
  MeasureContext        ctx;
  ctx.sys = &sys, ctx.g = &g;
  SampleRange r;
  r.d1 = r.e1 = sys.ndof;
  std::vector<StateMeasures> m;
  EXPECT_EQ(0, MeasureStructureStates(PETSC_COMM_SELF, ctx, r, y, v, {0.0}, &m));
  return m.empty() ? StateMeasures() : m[0];
}

// A state of every free dof of the fields in `account` (all accounts: -1), 0 elsewhere.
void StateOn(const BeamSystem &sys, PetscInt account, std::vector<PetscReal> *y, std::vector<PetscReal> *v)
{
  y->assign(sys.ndof, 0.0), v->assign(sys.ndof, 0.0);
  for (PetscInt d = 0; d < sys.ndof; ++d)
    if (!sys.held[d] && (account < 0 || sys.AccountOf(d % sys.fields) == account))
      (*y)[d] = 1e-3 * std::sin(1.3 * d + 0.7), (*v)[d] = std::cos(0.9 * d);
}

// Each account's energies of state (y, v), and their sums against the system's totals.
void CheckAccountsSum(const BeamSystem &sys, const std::vector<PetscReal> &y, const std::vector<PetscReal> &v,
                      PetscReal stored[kMaxAccounts], PetscReal kinetic[kMaxAccounts])
{
  BeamSystemAccountEnergies(sys, y.data(), sys.fields, v.data(), sys.fields, 0, sys.ndof, stored, kinetic);
  const PetscReal U = BeamSystemStrainEnergy(sys, y.data(), sys.fields, 0, sys.ndof);
  const PetscReal T = BeamSystemKineticEnergy(sys, v.data(), sys.fields, 0, sys.ndof);
  PetscReal       su = 0, st = 0;
  for (PetscInt a = 0; a < StructureAccountCount(); ++a) su += stored[a], st += kinetic[a];
  EXPECT_NEAR(su, U, 1e-13 * U) << "the accounts' strain energies sum to the structure's";
  EXPECT_NEAR(st, T, 1e-13 * T) << "the accounts' kinetic energies sum to the structure's";
}

} // namespace

// A strung racket (the beam's bending, the roll, the bed): any state's accounts sum to its strain
// and kinetic energy; a state of the bed's dofs alone (the frame at rest: its links strain against
// the frame's sections y + z phi = 0) is all the bed's account's, in the measures as in the system,
// and its momenta its account's (sum m v, m x v, m z v over its nodes); a rigid translation or
// roll of the whole structure is all rigid in the split, no account's flexible energy. Each fails
// if an account's energy, or a part's momenta, are summed into another's.
TEST(EnergyAccounts, RacketStatesByAccount)
{
  BeamParams beam;
  BallParams ball;
  test::ReadScene({"options/base/racket-strung.opts"}, {{"-strings_patch_radius", "0.015"}}, &beam, &ball);
  const BeamSystem sys = test::SystemOf(beam);
  const PetscInt   bed = StructureAccountOf(*StructurePartFind("bed")), roll = StructureAccountOf(*StructurePartFind("roll"));
  ASSERT_GE(sys.RollField(), 0);
  ASSERT_FALSE(sys.face_fields.empty());
  PetscReal              stored[kMaxAccounts], kinetic[kMaxAccounts];
  std::vector<PetscReal> y, v;
  StateOn(sys, -1, &y, &v);
  CheckAccountsSum(sys, y, v, stored, kinetic);
  for (PetscInt a : {(PetscInt)0, roll, bed}) EXPECT_GT(stored[a] * kinetic[a], 0.0) << "account " << a << " moves";

  StateOn(sys, bed, &y, &v); // the bed alone
  CheckAccountsSum(sys, y, v, stored, kinetic);
  const PetscReal E = stored[bed] + kinetic[bed];
  ASSERT_GT(E, 0.0);
  EXPECT_EQ(stored[0] + kinetic[0] + stored[roll] + kinetic[roll], 0.0) << "no other account's";
  const StateMeasures m = MeasuresOf(sys, y, v);
  EXPECT_NEAR(m.account_energy[bed], E, 1e-13 * E);
  EXPECT_EQ(m.account_energy[roll], 0.0);
  EXPECT_NEAR(m.beam_kinetic + m.beam_strain, E, 1e-13 * E) << "the bed's energy is in the beam's sums";
  EXPECT_EQ(m.apart_energy, 0.0);
  PetscReal P[3] = {0, 0, 0}; // the bed's momenta from its nodes
  for (PetscInt d = 0; d < sys.ndof; ++d)
    if (sys.Face(d % sys.fields) && !sys.held[d])
      P[0] += sys.mass[d] * v[d], P[1] += sys.mass[d] * sys.NodeX(d / sys.fields) * v[d], P[2] += sys.mass[d] * sys.DofZ(d) * v[d];
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(m.account_momentum[bed][k], P[k], 1e-13 * (std::abs(P[k]) + std::abs(P[0]))) << k;
    EXPECT_EQ(m.account_momentum[roll][k], 0.0) << k;
  }

  const struct {
    RigidKind kind;
    PetscReal v0, roll;
  } rigid[] = {{RigidKind::Translation, 1.0, 0.0}, {RigidKind::Roll, 0.0, 1.0}};
  const std::vector<PetscReal> at_rest(sys.ndof, 0.0);
  for (const auto &r : rigid) {
    const std::vector<PetscReal> w  = BeamSystemRigidVelocity(sys, r.v0, 0.0, r.roll);
    const StateMeasures          mr = MeasuresOf(sys, at_rest, w);
    const EnergySplit            s  = EnergySplitOf(beam, sys, mr);
    const PetscReal              T  = mr.beam_kinetic;
    ASSERT_GT(T, 0.0);
    EXPECT_NEAR(s.rigid[(int)r.kind], T, 1e-12 * T) << RigidKindName(r.kind);
    for (PetscInt a = 0; a < StructureAccountCount(); ++a)
      EXPECT_NEAR(s.flexible[a], 0.0, 1e-12 * T) << RigidKindName(r.kind) << ": account " << StructureAccountName(a);
  }
}

// A bat with the barrel's hoop: the wall's account is kept apart from the beam's sums. A state of
// the wall's dof alone is all apart_energy and the wall's account, none of beam_kinetic and
// beam_strain; any state's accounts sum to the structure's energies.
TEST(EnergyAccounts, WallKeptApart)
{
  BeamParams beam;
  BallParams ball;
  test::ReadScene({"options/bats/aluminium-bat.opts"}, {{"-beam_nodes", "41"}}, &beam, &ball);
  beam                 = test::WithPart(beam, "wall", {{"-barrel_hoop_frequency", {1500}}, {"-barrel_hoop_mass", {0.27}}});
  const BeamSystem sys  = test::SystemOf(beam);
  const PetscInt   wall = StructureAccountOf(*StructurePartFind("wall"));
  PetscReal        stored[kMaxAccounts], kinetic[kMaxAccounts];
  std::vector<PetscReal> y, v;
  StateOn(sys, -1, &y, &v);
  CheckAccountsSum(sys, y, v, stored, kinetic);
  const StateMeasures all = MeasuresOf(sys, y, v);
  const PetscReal     U = BeamSystemStrainEnergy(sys, y.data(), sys.fields, 0, sys.ndof);
  const PetscReal     T = BeamSystemKineticEnergy(sys, v.data(), sys.fields, 0, sys.ndof);
  EXPECT_NEAR(all.beam_kinetic + all.beam_strain + all.apart_energy, U + T, 1e-13 * (U + T));
  EXPECT_NEAR(all.apart_energy, stored[wall] + kinetic[wall], 1e-13 * (U + T));

  StateOn(sys, wall, &y, &v); // the hoop's dof alone
  const StateMeasures m = MeasuresOf(sys, y, v);
  const PetscReal     E = BeamSystemStrainEnergy(sys, y.data(), sys.fields, 0, sys.ndof) +
                      BeamSystemKineticEnergy(sys, v.data(), sys.fields, 0, sys.ndof);
  ASSERT_GT(E, 0.0);
  EXPECT_NEAR(m.apart_energy, E, 1e-13 * E);
  EXPECT_NEAR(m.account_energy[wall], E, 1e-13 * E);
  EXPECT_NEAR(m.beam_kinetic, 0.0, 1e-13 * E);
  EXPECT_NEAR(m.beam_strain, 0.0, 1e-13 * E);
  EXPECT_NEAR(EnergySplitOf(beam, sys, m).flexible[wall], E, 1e-13 * E) << "rigid motions do not move the wall";
}

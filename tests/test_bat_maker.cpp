// A bat by its maker's numbers (model/bat_maker.hpp, io/bat_maker_options.hpp): its mass, balance
// point and moments of inertia against the closed forms of the cylinders and truncated cones it is
// made of (a solid wood bat with a narrowing end, a hollow bat with its handle's and barrel's walls
// and an end cap, a cupped end), read through the options as a run reads them; the drop; numbers
// that describe no bat refused with the option named; the batter's swing law (-bat_swing_*); a
// racket by its maker's numbers (-racket_*).
#include "io/beam_options.hpp"
#include "io/scenario_options.hpp"
#include "model/bat_maker.hpp"
#include "model/racket_maker.hpp"
#include "model/swing.hpp"
#include "system/parts/bed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace beamimpact;

namespace {

// Mass and first and second moments about x = 0 of solid truncated cones (radius linear from r0 at
// x = a to r1 at x = a + h), summed: m = rho pi h (r0^2 + r0 r1 + r1^2)/3, about a: rho pi h^2 (r0^2 +
// 2 r0 r1 + 3 r1^2)/12 and rho pi h^3 (r0^2 + 3 r0 r1 + 6 r1^2)/30.
struct Moments {
  double m0 = 0, m1 = 0, m2 = 0;
  void Cone(double rho, double a, double b, double D0, double D1, double sign = 1)
  {
    const double h = b - a, r0 = D0 / 2, r1 = D1 / 2, k = sign * rho * M_PI;
    const double m = k * h * (r0 * r0 + r0 * r1 + r1 * r1) / 3, f = k * h * h * (r0 * r0 + 2 * r0 * r1 + 3 * r1 * r1) / 12;
    const double s = k * h * h * h * (r0 * r0 + 3 * r0 * r1 + 6 * r1 * r1) / 30;
    m0 += m, m1 += m * a + f, m2 += m * a * a + 2 * a * f + s;
  }
  double Centre() const { return m1 / m0; }
  double InertiaAbout(double x) const { return m2 - 2 * x * m1 + x * x * m0; }
};

// The beam the options give, with `opts` set for the reading only.
BeamParams Read(const std::vector<std::pair<std::string, std::string>> &opts, PetscErrorCode *ierr = nullptr)
{
  for (auto &kv : opts) EXPECT_EQ(0, PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()));
  BeamParams           p;
  const PetscErrorCode e = BeamParamsFromOptions(PETSC_COMM_SELF, &p);
  if (ierr) *ierr = e;
  else EXPECT_EQ(0, e);
  for (auto &kv : opts) EXPECT_EQ(0, PetscOptionsClearValue(NULL, kv.first.c_str()));
  return p;
}

void ExpectBody(const BeamParams &p, const Moments &want, const char *what)
{
  const BeamRigidBody b = BeamRigidBodyOf(p);
  EXPECT_NEAR(b.mass, want.m0, 1e-12 * want.m0) << what;
  EXPECT_NEAR(b.x_cm, want.Centre(), 1e-12) << what;
  EXPECT_NEAR(b.inertia_cm, want.InertiaAbout(want.Centre()), 1e-12 * want.m2) << what;
  EXPECT_NEAR(b.inertia_end, want.m2, 1e-12 * want.m2) << what;
  const double xp = 0.1524; // the rig's pivot, 6 in from the knob: I_p = I_cm + M (x_cm - x_p)^2
  EXPECT_NEAR(b.inertia_cm + b.mass * (b.x_cm - xp) * (b.x_cm - xp), want.InertiaAbout(xp), 1e-12 * want.m2) << what;
}

} // namespace

// A solid wood bat whose barrel narrows toward its end (a torpedo-like shape): knob, fillet,
// handle, taper, barrel, end taper as six solid pieces.
TEST(BatMaker, SolidBatIsItsCylindersAndCones)
{
  const double rho = 650, L = 0.8636, k = 0.011, Dk = 0.0445, Dh = 0.0240, x1 = 0.28, x2 = 0.50, Db = 0.0663, x3 = 0.72, De = 0.0560;
  const BeamParams p = Read({{"-bat_length", "0.8636"}, {"-bat_knob_length", "0.011"}, {"-bat_knob_diameter", "0.0445"}, {"-bat_handle_diameter", "0.0240"}, {"-bat_taper_start", "0.28"},
                             {"-bat_taper_end", "0.50"}, {"-bat_barrel_diameter", "0.0663"}, {"-bat_end_taper_start", "0.72"}, {"-bat_end_diameter", "0.056"},
                             {"-beam_youngs_modulus", "1.2e10"}, {"-beam_density", "650"}, {"-beam_nodes", "87"}});
  Moments want;
  want.Cone(rho, 0, k, Dk, Dk);
  want.Cone(rho, k, k + kBatKnobFlare, Dk, Dh);
  want.Cone(rho, k + kBatKnobFlare, x1, Dh, Dh);
  want.Cone(rho, x1, x2, Dh, Db);
  want.Cone(rho, x2, x3, Db, Db);
  want.Cone(rho, x3, L, Db, De);
  EXPECT_DOUBLE_EQ(p.length, L);
  ExpectBody(p, want, "solid torpedo-like bat");
}

// A hollow bat: the solid outline less its bore (the handle's wall through the knob and handle, the
// wall linear along the taper, the barrel's), then an end cap of 60 g: the mass grows by exactly
// 60 g, and the moments by the bore's change (a 1 mm step, then the cap's bore d_c over the rest).
TEST(BatMaker, HollowBatWithEndCap)
{
  const double rho = 2810, L = 0.84, k = 0.012, Dk = 0.046, Dh = 0.0254, x1 = 0.20, x2 = 0.53, Db = 0.066675, t = 0.0025, th = 0.003, lc = 0.02, mc = 0.06;
  std::vector<std::pair<std::string, std::string>> opts = {{"-bat_length", "0.84"}, {"-bat_taper_start", "0.20"}, {"-bat_taper_end", "0.53"}, {"-barrel_wall_thickness", "0.0025"},
                                                           {"-bat_handle_wall_thickness", "0.003"}, {"-beam_youngs_modulus", "7.2e10"}, {"-beam_density", "2810"}};
  const double dh = Dh - 2 * th, db = Db - 2 * t;
  Moments      want;
  want.Cone(rho, 0, k, Dk, Dk);
  want.Cone(rho, k, k + kBatKnobFlare, Dk, Dh);
  want.Cone(rho, k + kBatKnobFlare, x1, Dh, Dh);
  want.Cone(rho, x1, x2, Dh, Db);
  want.Cone(rho, x2, L, Db, Db);
  want.Cone(rho, 0, x1, dh, dh, -1); // the bore
  want.Cone(rho, x1, x2, dh, db, -1);
  want.Cone(rho, x2, L, db, db, -1);
  ExpectBody(Read(opts), want, "hollow bat");

  opts.push_back({"-bat_end_cap_mass", "0.06"});
  const BeamParams capped = Read(opts);
  EXPECT_NEAR(BeamRigidBodyOf(capped).mass, want.m0 + mc, 1e-12);
  // the cap's bore, read from the profile's last row, and the moments of the ring it leaves
  const double dc = capped.section.profile.back().d;
  EXPECT_GT(dc, 0);
  EXPECT_LT(dc, db);
  want.Cone(rho, L - lc, L, db, db); // the bore filled ...
  want.Cone(rho, L - lc, L - lc + kBatEndStep, db, dc, -1); // ... but for the cap's: its step and its bore
  want.Cone(rho, L - lc + kBatEndStep, L, dc, dc, -1);
  ExpectBody(capped, want, "hollow bat with an end cap");
}

// A cupped wood bat: its end bored 1 in deep to 1.5 in.
TEST(BatMaker, CuppedEnd)
{
  const double rho = 700, L = 0.8382, k = 0.012, Dk = 0.046, Dh = 0.0254, x1 = 0.30, x2 = 0.53, Db = 0.066, c = 0.0254, dcup = 0.0381;
  const BeamParams p = Read({{"-bat_length", "0.8382"}, {"-bat_barrel_diameter", "0.066"}, {"-bat_cup_depth", "0.0254"}, {"-bat_cup_diameter", "0.0381"}, {"-beam_youngs_modulus", "1.2e10"},
                             {"-beam_density", "700"}});
  Moments want;
  want.Cone(rho, 0, k, Dk, Dk);
  want.Cone(rho, k, k + kBatKnobFlare, Dk, Dh);
  want.Cone(rho, k + kBatKnobFlare, x1, Dh, Dh);
  want.Cone(rho, x1, x2, Dh, Db);
  want.Cone(rho, x2, L, Db, Db);
  want.Cone(rho, L - c, L - c + kBatEndStep, 0, dcup, -1);
  want.Cone(rho, L - c + kBatEndStep, L, dcup, dcup, -1);
  ExpectBody(p, want, "cupped bat");
}

// The drop L[in] - W[oz]: a 33 in, 30 oz bat is a -3.
TEST(BatMaker, Drop)
{
  EXPECT_NEAR(BatDrop(33 * kMetresPerInch, 30 * kKilogramsPerOunce), 3.0, 1e-12);
  EXPECT_NEAR(BatDrop(0.8382, 0.877), 33 - 0.877 / 0.028349523125, 1e-12);
}

// Numbers that describe no bat: refused, the option named.
TEST(BatMaker, RefusedWithTheOptionNamed)
{
  std::vector<ProfileRow> rows;
  std::string             why;
  BatMakerParams          b;
  b.taper_end = 0.9; // beyond the 0.8382 m bat
  EXPECT_FALSE(BatMakerProfile(b, 700, &rows, &why));
  EXPECT_NE(why.find("-bat_taper_end 0.9"), std::string::npos) << why;
  b             = BatMakerParams();
  b.end_cap_mass = 0.05; // a solid bat
  EXPECT_FALSE(BatMakerProfile(b, 700, &rows, &why));
  EXPECT_NE(why.find("-bat_end_cap_mass 0.05 kg on a solid bat"), std::string::npos) << why;
  b                = BatMakerParams();
  b.wall_thickness = 0.004, b.handle_wall_thickness = 0.013; // thicker than the handle's radius
  EXPECT_FALSE(BatMakerProfile(b, 2810, &rows, &why));
  EXPECT_NE(why.find("-bat_handle_wall_thickness 0.013"), std::string::npos) << why;
  b                = BatMakerParams();
  b.wall_thickness = 0.0025, b.end_cap_mass = 0.5; // more than the end's 2 cm can hold
  EXPECT_FALSE(BatMakerProfile(b, 2810, &rows, &why));
  EXPECT_NE(why.find("does not fit"), std::string::npos) << why;
  PetscErrorCode ierr = 0;
  EXPECT_EQ(0, PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  Read({{"-bat_length", "0.84"}, {"-beam_profile", "x.profile"}, {"-beam_youngs_modulus", "7e10"}, {"-beam_density", "2700"}}, &ierr);
  EXPECT_EQ(0, PetscPopErrorHandler());
  EXPECT_NE(ierr, 0) << "-bat_length with -beam_profile must be refused";
}

// The swing's law (model/swing.hpp): Nathan's game case of the R161 (V_cm 24 m/s, Omega 51 rad/s)
// is a turn at 51 rad/s about x_s = x_cm - 24/51; as a law without I_0 it is the same rigid motion;
// with I_0 half the bat's I_s the swing is 2^(-n) slower everywhere; the bat's speed at x is
// s (v_s + omega_0 (x - x_s)).
TEST(SwingLaw, NathansGameCaseAndTheInertiaLaw)
{
  const std::string     profile = std::string(BEAMIMPACT_SOURCE_DIR) + "/options/bats/r161.profile";
  std::vector<std::pair<std::string, std::string>> bat = {{"-beam_profile", profile}, {"-beam_youngs_modulus", "1.814e10"}, {"-beam_density", "649"}, {"-impact_x", "0.7"}};
  auto scene = [&](std::vector<std::pair<std::string, std::string>> extra) {
    for (auto &kv : bat) extra.push_back(kv);
    for (auto &kv : extra) EXPECT_EQ(0, PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()));
    Scenario sc;
    EXPECT_EQ(0, ScenarioFromOptions(PETSC_COMM_SELF, &sc));
    for (auto &kv : extra) EXPECT_EQ(0, PetscOptionsClearValue(NULL, kv.first.c_str()));
    return sc;
  };
  const Scenario      given = scene({{"-bat_speed", "24"}, {"-bat_angular_velocity", "51"}});
  const BeamRigidBody body  = BeamRigidBodyOf(given.beam);
  char                xs[40];
  std::snprintf(xs, sizeof xs, "%.17g", body.x_cm - 24.0 / 51.0);
  const Scenario law = scene({{"-bat_swing_angular_velocity", "51"}, {"-bat_swing_pivot", xs}});
  EXPECT_NEAR(law.swing.bat_speed, 24, 1e-13);
  EXPECT_NEAR(law.swing.bat_angular_velocity, 51, 1e-13);
  SwingLaw l;
  l.pivot = body.x_cm - 24.0 / 51.0, l.angular_velocity = 51;
  const double Is = SwingLawInertia(l, body);
  EXPECT_NEAR(Is, body.inertia_cm + body.mass * (24.0 / 51.0) * (24.0 / 51.0), 1e-15);
  char i0[40];
  std::snprintf(i0, sizeof i0, "%.17g", Is / 2);
  const Scenario slower = scene({{"-bat_swing_angular_velocity", "51"}, {"-bat_swing_pivot", xs}, {"-bat_swing_reference_inertia", i0}, {"-bat_swing_exponent", "0.27"}});
  const double   s      = std::pow(2.0, -0.27);
  EXPECT_NEAR(slower.swing.bat_angular_velocity, 51 * s, 1e-12);
  for (double x : {0.0, 0.5, 0.84}) EXPECT_NEAR(SwingSpeedAt(slower.swing, body, x), s * 51 * (x - l.pivot), 1e-12) << "x = " << x;
  // a point that moves: V(x) = s (v_s + omega_0 (x - x_s))
  const Scenario moving = scene({{"-bat_swing_angular_velocity", "40"}, {"-bat_swing_pivot", "0.15"}, {"-bat_swing_pivot_speed", "3"}, {"-bat_swing_reference_inertia", i0}});
  const double   s2     = std::pow((body.inertia_cm + body.mass * (body.x_cm - 0.15) * (body.x_cm - 0.15)) / (Is / 2), -0.26);
  EXPECT_NEAR(SwingSpeedAt(moving.swing, body, 0.7), s2 * (3 + 40 * (0.7 - 0.15)), 1e-12);
}

// The string bed makes the frame it sits on (StructurePart::Frame, read with the beam): held, the
// beam becomes the head's outline held whole (its length the head's, its nodes -strings_nodes,
// frame_held, which the hands refuse); on a maker's racket, the frame's levels carry the strings'
// sigma A at the head's centre (RacketStrungBy), so the frame alone weighs the strung mass less
// sigma A, sigma = lambda (1/s_m + 1/s_c) over the ellipse's pi a b.
TEST(RacketMaker, TheBedMakesItsFrame)
{
  const BeamParams held = Read(
    {{"-strings_frame", "held"}, {"-head_length", "0.3"}, {"-head_width", "0.2"}, {"-strings_nodes", "31"}});
  EXPECT_TRUE(held.frame_held);
  EXPECT_EQ(held.length, 0.3);
  EXPECT_EQ(held.nodes, 31);
  ASSERT_NE(StringBedOf(held), nullptr);
  EXPECT_EQ(StringBedOf(held)->head_center, 0.15);
  PetscErrorCode ierr = 0;
  (void)Read({{"-strings_frame", "held"}, {"-grip", "0.05,0.15"}}, &ierr);
  EXPECT_NE(ierr, 0) << "a held frame has nothing to grip";
  const BeamParams none = Read({{"-strings_frame", "none"}});
  EXPECT_FALSE(none.frame_held);
  EXPECT_EQ(StringBedOf(none), nullptr);
  // without its gate -strings_frame the bed's rows are not read at all: a bat's bad -strings_*
  // is no error (the unused-option note says it), as before the bed was a part
  ierr                 = 0;
  const BeamParams bat = Read({{"-strings_tension", "-1"}, {"-head_shape", "oval"}}, &ierr);
  EXPECT_EQ(ierr, 0);
  EXPECT_EQ(StringBedOf(bat), nullptr);
  EXPECT_FALSE(bat.frame_held);

  StringBedParams   bed; // the default bed on a maker's default racket
  RacketMakerParams r;
  RacketMakerHead(r, &bed);
  const RacketStrung s     = RacketStrungBy(bed);
  const double       sigma = bed.linear_density / bed.spacing + bed.linear_density / bed.spacing_crosses;
  EXPECT_NEAR(s.mass, sigma * M_PI * bed.head_length * bed.head_width / 4, 1e-14 * s.mass); // the whole outline
  EXPECT_EQ(s.moment, s.mass * bed.head_center);
  std::vector<PropertiesRow> strung, bare;
  std::string                why;
  ASSERT_TRUE(RacketMakerTable(r, s, &strung, &why)) << why;
  ASSERT_TRUE(RacketMakerTable(r, RacketStrung(), &bare, &why)) << why;
  auto mass = [](const std::vector<PropertiesRow> &rows) {
    double m = 0;
    for (size_t i = 0; i + 1 < rows.size(); ++i)
      m += 0.5 * (rows[i].s.mu + rows[i + 1].s.mu) * (rows[i + 1].x - rows[i].x);
    return m;
  };
  EXPECT_NEAR(mass(bare), r.mass, 1e-12);
  EXPECT_NEAR(mass(strung), r.mass - s.mass, 1e-12);
}

// A racket by its maker's numbers (model/racket_maker.hpp), strung: the strung racket's mass,
// balance and twistweight as given (the frame's two levels solve them with the strings' own
// moments), the head's strung area and its tip 1 cm below the frame's, the frame's EI and GJ; a
// balance no two positive levels can make refused with the range it allows.
TEST(RacketMaker, StrungMassBalanceTwistweightAndHead)
{
  std::vector<std::pair<std::string, std::string>> opts = {{"-racket_length", "0.685"}, {"-racket_mass", "0.305"}, {"-racket_balance", "0.335"}, {"-racket_head_size", "0.0632"},
                                                           {"-racket_twistweight", "0.0015"}, {"-racket_frame_stiffness", "180"}, {"-beam_torsion", "true"}, {"-strings_frame", "beam"},
                                                           {"-beam_nodes", "70"}};
  const BeamParams p = Read(opts);
  const BeamRigidBody b = BeamRigidBodyOf(p);
  EXPECT_NEAR(b.mass, 0.305, 1e-14);
  EXPECT_NEAR(b.x_cm, 0.335, 1e-14);
  EXPECT_NEAR(b.inertia_roll, 0.0015, 1e-15);
  ASSERT_NE(StringBedOf(p), nullptr);
  const StringBedParams &bed = *StringBedOf(p);
  EXPECT_NEAR(M_PI * bed.head_length * bed.head_width / 4, 0.0632, 1e-15);
  EXPECT_NEAR(bed.head_length / bed.head_width, 1.37, 1e-14);
  EXPECT_NEAR(bed.head_center + bed.head_length / 2, 0.685 - 0.01, 1e-14);
  EXPECT_DOUBLE_EQ(SectionAt(p.section, 0.5).EI, 180);
  EXPECT_DOUBLE_EQ(SectionAt(p.section, 0.05).GJ, 350);
  // the frame alone (no strings): the same mass and balance from the frame's own levels
  const BeamParams bare = Read({{"-racket_length", "0.685"}, {"-racket_mass", "0.305"}, {"-racket_balance", "0.335"}});
  EXPECT_NEAR(BeamRigidBodyOf(bare).mass, 0.305, 1e-14);
  EXPECT_NEAR(BeamRigidBodyOf(bare).x_cm, 0.335, 1e-14);
  std::vector<PropertiesRow> rows;
  std::string                why;
  RacketMakerParams          r;
  r.balance = 0.60; // more head-heavy than a head-only frame
  EXPECT_FALSE(RacketMakerTable(r, RacketStrung(), &rows, &why));
  EXPECT_NE(why.find("-racket_balance 0.6 m makes no racket"), std::string::npos) << why;
}

// The same impact with every advertised integrator at tight settings gives the same
// outcome (ACOR to 1e-6), for the linear spring and the hysteretic ball, against a
// Dormand-Prince 5(4) run at a very tight tolerance.
#include "test_helpers.hpp"

#include <cmath>

using namespace beamimpact;
using namespace beamimpact::test;

namespace {
using Opts = std::vector<std::pair<std::string, std::string>>;

struct Config {
  const char *name;
  Opts        opts;
};

const std::vector<Config> &Integrators()
{
  static const std::vector<Config> c = {
    {"rk4 fixed", {{"-ts_type", "rk"}, {"-ts_rk_type", "4"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}}},
    {"rk 5dp adaptive", {{"-ts_type", "rk"}, {"-ts_rk_type", "5dp"}, {"-ts_rtol", "1e-9"}, {"-ts_atol", "1e-11"}}},
    {"cn", {{"-ts_type", "cn"}, {"-ts_dt", "1e-6"}}},
    {"theta 0.5 endpoint", {{"-ts_type", "theta"}, {"-ts_theta_theta", "0.5"}, {"-ts_theta_endpoint", ""}, {"-ts_dt", "1e-6"}}},
    {"bdf2", {{"-ts_type", "bdf"}, {"-ts_bdf_order", "2"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2.5e-7"}}},
    {"arkimex", {{"-ts_type", "arkimex"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}}},
    {"rosw", {{"-ts_type", "rosw"}, {"-ts_adapt_type", "none"}, {"-ts_dt", "2e-6"}}},
    {"alpha2 radius 0.8", {{"-ts_type", "alpha2"}, {"-ts_alpha_radius", "0.8"}, {"-ts_dt", "1e-6"}}},
  };
  return c;
}

void CompareAll(const char *law, double x)
{
  const BeamParams beam = AluminiumBeam(1.1, 41);
  const BallParams ball = Superball(law);
  ImpactParams     ip;
  ip.x      = x;
  ip.window = 4e-3;
  const ImpactResult ref = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, {{"-ts_type", "rk"}, {"-ts_rk_type", "5dp"}, {"-ts_rtol", "1e-12"}, {"-ts_atol", "1e-14"}});
  ASSERT_GT(ref.acor, 0.3);
  for (const Config &c : Integrators()) {
    const ImpactResult r = RunImpact(PETSC_COMM_WORLD, beam, ball, ip, c.opts);
    EXPECT_NEAR(r.acor, ref.acor, 1e-6) << c.name;
    EXPECT_NEAR(r.contact_time, ref.contact_time, 1e-6 * ref.contact_time) << c.name;
    EXPECT_NEAR(r.peak_force, ref.peak_force, 1e-5 * ref.peak_force) << c.name;
    EXPECT_NEAR(r.max_compression, ref.max_compression, 1e-5 * ref.max_compression) << c.name;
    EXPECT_EQ(r.contacts, ref.contacts) << c.name;
  }
}
} // namespace

TEST(Integrators, AgreeWithTheLinearSpring) { CompareAll("linear", 0.9); }
TEST(Integrators, AgreeWithTheHystereticBall) { CompareAll("hysteresis", 0.9); }

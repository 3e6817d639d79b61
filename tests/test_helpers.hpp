// Test helpers: the paper's beams and balls as parameter structs, and a run of
// one impact with TS options pushed into the options database for its duration.
#pragma once

#include "run/impact.hpp"
#include "run/scenario.hpp"
#include "system/beam_system.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace beamimpact::test {

// The paper's aluminium beam: 6 mm x 32 mm, E = 7e10 Pa, rho = 2700 kg/m^3.
inline BeamParams AluminiumBeam(PetscReal length, PetscInt nodes = 41, Support left = Support::Free, Support right = Support::Free)
{
  BeamParams p;
  const PetscReal E = 7e10, rho = 2700, a = 0.006, b = 0.032;
  p.length = length;
  p.nodes  = nodes;
  p.left   = left;
  p.right  = right;
  p.mu     = rho * a * b;
  p.EI     = E * b * a * a * a / 12;
  return p;
}

// A beam made rigid and heavy, clamped at both ends: a wall for the ball.
inline BeamParams WallBeam(PetscReal EI, PetscReal mu, PetscInt nodes = 21)
{
  BeamParams p;
  p.length = 1.1;
  p.nodes  = nodes;
  p.left = p.right = Support::Clamped;
  p.EI             = EI; // N m^2
  p.mu             = mu; // kg/m
  return p;
}

inline BallParams Superball(ContactLawKind law = ContactLawKind::Linear)
{
  BallParams b; // 42 g, 1 m/s, k = 2e4 N/m; hysteresis k1 = 2e4, m = 1, n = 1.768
  b.law = law;
  return b;
}

// The semi-discrete system of a beam (Euler-Bernoulli unless p.theory says otherwise).
inline BeamSystem SystemOf(const BeamParams &p)
{
  BeamSystem  sys;
  std::string why;
  EXPECT_TRUE(BeamSystemBuild(p, &sys, &why)) << why;
  return sys;
}

// Runs one impact with the given TS options set only for this run.
inline ImpactResult RunImpact(MPI_Comm comm, const BeamParams &beam, const BallParams &ball, const ImpactParams &ip, const std::vector<std::pair<std::string, std::string>> &ts_options,
                              const MonitorRequest &mon = MonitorRequest())
{
  for (auto &kv : ts_options) EXPECT_EQ(PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.empty() ? NULL : kv.second.c_str()), 0);
  ImpactResult r;
  EXPECT_EQ(ImpactRun(comm, Scenario{beam, ball, ip, mon}, &r), 0) << "ImpactRun failed";
  for (auto &kv : ts_options) EXPECT_EQ(PetscOptionsClearValue(NULL, kv.first.c_str()), 0);
  return r;
}

} // namespace beamimpact::test

// Test helpers: the paper's beams and balls as parameter structs, and a run of
// one impact with TS options pushed into the options database for its duration.
#pragma once

#include "io/ball_options.hpp"
#include "io/beam_options.hpp"
#include "io/options_files.hpp"
#include "run/impact.hpp"
#include "run/results_table.hpp"
#include "run/scenario.hpp"
#include "system/beam_system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace beamimpact::test {

// The paper's aluminium beam: 6 mm x 32 mm, E = 7e10 Pa, rho = 2700 kg/m^3.
// Eigenvalues (ascending) of a dense symmetric n x n matrix by cyclic Jacobi
// rotations (no LAPACK link needed; accurate to ~eps times the largest |eigenvalue|).
inline std::vector<PetscReal> JacobiEigenvalues(std::vector<PetscReal> A, PetscInt n)
{
  for (int sweep = 0; sweep < 100; ++sweep) {
    PetscReal off = 0, diag = 0;
    for (PetscInt p = 0; p < n; ++p) {
      diag += A[p * n + p] * A[p * n + p];
      for (PetscInt q = p + 1; q < n; ++q) off += A[p * n + q] * A[p * n + q];
    }
    if (off <= 1e-32 * diag) break;
    for (PetscInt p = 0; p < n; ++p)
      for (PetscInt q = p + 1; q < n; ++q) {
        const PetscReal apq = A[p * n + q];
        if (apq == 0.0) continue;
        const PetscReal theta = (A[q * n + q] - A[p * n + p]) / (2 * apq);
        const PetscReal t     = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const PetscReal c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (PetscInt k = 0; k < n; ++k) { // A <- A J (columns p, q)
          const PetscReal akp = A[k * n + p], akq = A[k * n + q];
          A[k * n + p]        = c * akp - s * akq;
          A[k * n + q]        = s * akp + c * akq;
        }
        for (PetscInt k = 0; k < n; ++k) { // A <- J^T A (rows p, q)
          const PetscReal apk = A[p * n + k], aqk = A[q * n + k];
          A[p * n + k]        = c * apk - s * aqk;
          A[q * n + k]        = s * apk + c * aqk;
        }
      }
  }
  std::vector<PetscReal> w(n);
  for (PetscInt p = 0; p < n; ++p) w[p] = A[p * n + p];
  std::sort(w.begin(), w.end());
  return w;
}

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

inline BallParams Superball(const char *law = "linear")
{
  BallParams b; // 42 g, 1 m/s, k = 2e4 N/m; hysteresis k1 = 2e4, m = 1, n = 1.768 (the laws' defaults)
  BallParamsUseLaw(&b, ContactLawFind(law));
  return b;
}

// The beam with the hands g (g.on ignored), through the grip part's own option module, as
// -grip x_a,x_b -grip_stiffness k' -grip_damping c' -grip_mass m -grip_torsion_stiffness ...
// -grip_torsion_damping ... would; WithoutGrip(p): the same beam with no hands.
inline BeamParams WithGrip(BeamParams p, const BeamGrip &g)
{
  const StructurePart *part = StructurePartFind("grip");
  EXPECT_NE(part, nullptr) << "the hands are a registered structure part";
  PartOptionValues v;
  v.given["-grip"]                   = {g.x_a, g.x_b};
  v.given["-grip_stiffness"]         = {g.stiffness};
  v.given["-grip_damping"]           = {g.damping};
  v.given["-grip_mass"]              = {g.mass};
  v.given["-grip_torsion_stiffness"] = {g.torsion_stiffness};
  v.given["-grip_torsion_damping"]   = {g.torsion_damping};
  std::shared_ptr<const PartParams> q;
  std::string                       why;
  EXPECT_TRUE(part->Configure(v, p, &q, &why)) << why;
  p.parts.Set("grip", q);
  return p;
}
inline BeamParams WithoutGrip(BeamParams p)
{
  p.parts.Set("grip", nullptr);
  return p;
}

// The semi-discrete system of a beam (Euler-Bernoulli unless p.theory says otherwise).
inline BeamSystem SystemOf(const BeamParams &p)
{
  BeamSystem  sys;
  std::string why;
  EXPECT_TRUE(BeamSystemBuild(p, &sys, &why)) << why;
  return sys;
}

// The beam with a registered structure part configured through the part's own option module, as
// its options would (the rows given with their values: a flag 1, a list its values); the part
// absent when its Configure says so. E.g. WithPart(p, "wall", {{"-beam_shell", {1}}}).
inline BeamParams WithPart(BeamParams p, const char *name, const std::map<std::string, std::vector<PetscReal>> &given)
{
  const StructurePart *part = StructurePartFind(name);
  EXPECT_NE(part, nullptr) << name << " is a registered structure part";
  if (!part) return p;
  PartOptionValues v;
  v.given = given;
  std::shared_ptr<const PartParams> q;
  std::string                       why;
  EXPECT_TRUE(part->Configure(v, p, &q, &why)) << why;
  p.parts.Set(name, q);
  return p;
}

// A registered part's instance in a system (its fields [first, first + count)), nullptr if absent.
inline const PartInstance *PartIn(const BeamSystem &sys, const char *name)
{
  for (const PartInstance &s : sys.parts)
    if (!std::strcmp(s.part->Name(), name)) return &s;
  return nullptr;
}

// The energy account of the registered part `name` (StructureAccountOf: 0 the beam's).
inline PetscInt AccountOfPart(const char *name) { return StructureAccountOf(*StructurePartFind(name)); }

// A results column's value by name (a part's own column: ImpactResult::keyed).
inline double ColumnOf(const ImpactResult &r, const char *name) { return ImpactResultColumn(name)->Get(r); }

// A hand-made two-field system: field 0 is the one-field system a, field 1 an uncoupled copy
// of it with every mass times mass_factor (no strain term couples the fields), dof = 2 node +
// field. Its modes are those of a and those of a with omega / sqrt(mass_factor); a ball
// striking it touches field 0 only, so it must see exactly the system a.
inline BeamSystem TwoFieldCopies(const BeamSystem &a, PetscReal mass_factor)
{
  EXPECT_EQ(1, a.fields);
  BeamSystem s = a; // L, h, nodes, frequency unit, force terms
  s.fields     = 2;
  s.field_account.assign(2, 0);
  s.ndof       = 2 * a.ndof;
  s.mass.assign(s.ndof, 0.0);
  s.held.assign(s.ndof, 0);
  s.strain.clear();
  for (PetscInt f = 0; f < 2; ++f) {
    for (PetscInt d = 0; d < a.ndof; ++d) {
      s.mass[2 * d + f] = (f ? mass_factor : 1.0) * a.mass[d];
      s.held[2 * d + f] = a.held[d];
    }
    for (StrainTerm t : a.strain) {
      for (PetscInt q = 0; q < t.n; ++q) t.dof[q] = 2 * t.dof[q] + f;
      t.owner = 2 * t.owner + f;
      s.strain.push_back(t);
    }
  }
  BeamSystemAssemble(&s); // index the strain terms, assemble K and C on the new layout
  return s;
}

// Reads beam and ball from options files (as a user's command line would) plus `extra`, in a
// private options database, from the repository root (the files' relative paths start there).
inline void ReadScene(const std::vector<std::string> &files, const std::vector<std::pair<std::string, std::string>> &extra, BeamParams *beam, BallParams *ball)
{
  PetscOptions o;
  char         cwd[4096];
  ASSERT_NE(nullptr, getcwd(cwd, sizeof cwd));
  ASSERT_EQ(0, chdir(BEAMIMPACT_SOURCE_DIR));
  ASSERT_EQ(0, PetscOptionsCreate(&o));
  for (const std::string &f : files) ASSERT_EQ(0, OptionsFileInsert(PETSC_COMM_WORLD, o, f));
  for (auto &kv : extra) ASSERT_EQ(0, PetscOptionsSetValue(o, kv.first.c_str(), kv.second.c_str()));
  ASSERT_EQ(0, PetscOptionsPush(o));
  EXPECT_EQ(0, BeamParamsFromOptions(PETSC_COMM_WORLD, beam));
  EXPECT_EQ(0, BallParamsFromOptions(PETSC_COMM_WORLD, ball));
  ASSERT_EQ(0, PetscOptionsPop());
  ASSERT_EQ(0, PetscOptionsDestroy(&o));
  ASSERT_EQ(0, chdir(cwd));
}

// The R161 (Euler-Bernoulli, 85 nodes) swinging at 24 m/s and 51 rad/s, struck 70 cm from the
// knob by a baseball of linear stiffness 2e6 N/m (the law -reference modal solves), ball at rest
// (set sc.ball.speed), to the first separation.
inline Scenario LinearBallR161()
{
  Scenario sc;
  ReadScene({"options/bats/r161.opts"}, {{"-beam_theory", "euler"}, {"-beam_nodes", "85"}, {"-ball_mass", "0.145"}, {"-ball_radius", "0.0369"}, {"-ball_law", "linear"}, {"-ball_k", "2e6"}}, &sc.beam,
            &sc.ball);
  sc.impact.x                   = 0.7;
  sc.impact.window              = 0;
  sc.swing.bat_speed            = 24;
  sc.swing.bat_angular_velocity = 51;
  return sc;
}

// Runs the impact of a scenario with the given options set only for this run.
inline ImpactResult RunWith(MPI_Comm comm, const Scenario &sc, const std::vector<std::pair<std::string, std::string>> &opts)
{
  for (auto &kv : opts) EXPECT_EQ(0, PetscOptionsSetValue(NULL, kv.first.c_str(), kv.second.c_str()));
  ImpactResult r;
  EXPECT_EQ(0, ImpactRun(comm, sc, &r));
  for (auto &kv : opts) EXPECT_EQ(0, PetscOptionsClearValue(NULL, kv.first.c_str()));
  return r;
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

// The results column `name` of r, any module's (the table's, a stage's after the contact, a
// registered part's): NaN where it does not apply; a failure when no module has it.
inline double Col(const ImpactResult &r, const char *name)
{
  const ResultColumn *c = ImpactResultColumn(name);
  EXPECT_NE(c, nullptr) << "no results column " << name;
  return c ? c->Get(r) : std::nan("");
}

} // namespace beamimpact::test

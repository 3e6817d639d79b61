// The beam's modes, computed once per beam. See beam_modes.hpp.
#include "solvers/beam_modes.hpp"

#include "base/memory.hpp"
#include "solvers/beam_flexibility.hpp"
#include "solvers/modes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <map>

extern "C" void dpbtrf_(const char *uplo, const int *n, const int *kd, double *ab, const int *ldab, int *info);
extern "C" void dpbtrs_(const char *uplo, const int *n, const int *kd, const int *nrhs, const double *ab,
                        const int *ldab, double *b, const int *ldb, int *info);

namespace beamimpact {

namespace {

// Everything of the system that the modes depend on, compared exactly: M, the held dofs, and
// K and C of the force operator (the same M, K and C have the same modes and decay rates).
bool SameBeam(const BeamSystem &a, const BeamSystem &b)
{
  return a.nodes == b.nodes && a.fields == b.fields && a.ndof == b.ndof && a.bw == b.bw && a.mass == b.mass &&
         a.held == b.held && a.band == b.band && a.forces.damping_band == b.forces.damping_band &&
         a.forces.damping_diag == b.forces.damping_diag;
}

// The zero cluster of the computed basis (omega below 1e-3 frequency units; every flexural
// mode of a beam is above 1) replaced by the exact rigid motions, and the flexible modes made
// orthogonal to them (twice, classical Gram-Schmidt). syev and inverse iteration find the
// null space only to eps omega_max^2 / omega_1^2 (1e-11 at N = 41, worse on finer grids), so
// that the computed flexible modes carry a little momentum and a free beam would lose some
// over a window; with the exact rigid modes momentum and angular momentum are kept to
// round-off. Their omega is exactly 0 and they decay only by alpha (C phi = alpha M phi).
// The system has exactly as many rigid motions as BeamSystemRigidMotions finds (K annihilates
// them): when fewer computed modes fall below the threshold but that many lie three decades
// below the next, those are the rigid ones, lifted by round-off (a mass spread over many decades,
// -beam_torsion_inertia 1e-12 on the strung racket: 0.037 rad/s against the threshold 0.035; the
// static correction then held only the translation and failed on the free roll, issue 34).
void ExactRigidModes(BeamModes *m)
{
  const ModalSystem &S = m->S;
  const PetscInt     n = S.n, count = m->Count();
  ModalBasis        &B  = m->B;
  PetscInt           nz = 0;
  while (nz < count && B.omega[nz] < 1e-3 * m->sys.frequency_unit) nz++;
  const auto     rigid = BeamSystemRigidMotions(m->sys);
  const PetscInt r     = (PetscInt)rigid.size();
  if (nz < r && r < count && B.omega[r - 1] < 1e-3 * B.omega[r]) nz = r;
  if (nz > 0 && (PetscInt)rigid.size() == nz) {
    for (PetscInt k = 0; k < nz; ++k) { // M^{1/2} v on the free dofs, orthonormal
      PetscReal *phi = &B.Phi[(size_t)k * n];
      for (PetscInt d = 0; d < n; ++d) phi[d] = std::sqrt(S.mass[d]) * rigid[k][S.dof[d]];
      ModalOrthonormalize(B.Phi, n, k, 2, phi);
    }
    for (PetscInt k = nz; k < count; ++k) ModalOrthonormalize(B.Phi, n, nz, 2, &B.Phi[(size_t)k * n]);
  }
  PetscReal alpha, beta; // C = alpha M + beta K: a rigid mode decays by alpha alone (K phi = 0)
  S.Rayleigh(&alpha, &beta);
  for (PetscInt k = 0; k < nz; ++k) {
    B.omega[k] = 0;
    B.rate[k]  = 0.5 * alpha;
  }
  m->rigid = nz;
}

// The truncation as it decides the basis: the kind, the count, the cut-off.
bool SameTruncation(const ModalTruncation &a, const ModalTruncation &b)
{
  if (ModalWeighsShare(a) != ModalWeighsShare(b)) return false;
  if (ModalWeighsShare(a)) { // the same load, tolerance and time scale
    if (a.at.n != b.at.n || a.tolerance != b.tolerance || a.contact_time != b.contact_time ||
        a.force_exponent != b.force_exponent || a.refine_all != b.refine_all || a.mirror != b.mirror)
      return false;
    for (PetscInt q = 0; q < a.at.n; ++q)
      if (a.at.dof[q] != b.at.dof[q] || a.at.w[q] != b.at.w[q]) return false;
    return true;
  }
  return a.modes == b.modes && (a.modes != ModalModes::Count || a.count == b.count) &&
         (a.modes != ModalModes::Auto || a.Cutoff() == b.Cutoff()) && a.refine_all == b.refine_all &&
         a.mirror == b.mirror;
}

// Whether the cached basis m is the one t asks for on the same beam: the same truncation, or
// two cut-offs of -modal_modes auto both above the highest mode's bound (each the dense
// decomposition of every mode: the same computation, bit for bit, whatever the contact time
// that set the cut-off; a sweep's points, whose approach speeds and so contact times differ,
// share it instead of decomposing again at every point: issue 38's cost).
bool BasisFits(const BeamModes &m, const ModalTruncation &t)
{
  if (SameTruncation(m.request, t)) return true;
  const bool every_mode = m.request.modes == ModalModes::Auto && !(m.cutoff < PETSC_INFINITY) &&
                          m.omega_bound > 0; // built dense, every mode below its cut-off
  return every_mode && t.modes == ModalModes::Auto && t.refine_all == m.request.refine_all &&
         t.mirror == m.request.mirror && !(t.Cutoff() < m.omega_bound);
}

// One cache per group of processes (the ranks of MPI_COMM_WORLD a communicator holds, in its
// order): a basis is computed collectively on its communicator and kept whole on each of its
// ranks, and only calls collective on the same group may find or evict it, so the caches of
// a group's ranks stay identical and either all of them compute (collectively) or none does. A
// call on PETSC_COMM_SELF of one rank alone fills and evicts only that rank's own cache. (On
// one rank PETSC_COMM_SELF and the run's communicator are the same group: one cache, as before.)
using ModesCache = std::deque<std::shared_ptr<const BeamModes>>; // most recent first
std::map<std::vector<int>, ModesCache> caches;
PetscInt                               n_computed = 0, n_reused = 0;

PetscErrorCode CacheOf(MPI_Comm comm, ModesCache **cache)
{
  MPI_Group   group, world;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<int> ranks(size), key(size);
  for (int r = 0; r < size; ++r) ranks[r] = r;
  PetscCallMPI(MPI_Comm_group(comm, &group));
  PetscCallMPI(MPI_Comm_group(MPI_COMM_WORLD, &world));
  PetscCallMPI(MPI_Group_translate_ranks(group, size, ranks.data(), world, key.data()));
  PetscCallMPI(MPI_Group_free(&group));
  PetscCallMPI(MPI_Group_free(&world));
  *cache = &caches[key];
  PetscFunctionReturn(0);
}

} // namespace

// How far double precision resolves the beam's modes: eps times the spread of M^-1 K over the
// lowest flexible mode's scale (Gershgorin's bound on its largest eigenvalue over
// frequency_unit^2: 16 (L/h)^4 for a uniform Euler-Bernoulli beam, 39 at N = 10241, 1e4 at
// N = 40961). Above kModesPrecisionLimit the static flexibility is lost to round-off and the
// shift-and-invert solves on K no longer give the low modes (the ACOR of the paper's beam at
// N = 40961 was 3e-3 off: docs/convergence.md), so the primal path is refused, never used wrong.
//
// Where the structure is statically determinate (BeamFactorCreate) the modes and the static
// correction come instead from the factored form once the primal index passes kFactoredSwitch
// (N > ~4000 for the paper's beam; below it the primal path is kept, bit for bit): its
// round-off is eps times the spread of the frequencies, not of their squares, so its index is
// eps omega_max / frequency_unit (4 (L/h)^2 eps for a uniform Euler-Bernoulli beam: 1.5e-6 at
// N = 40961), held to the same limit.
constexpr double kModesPrecisionLimit = 100;
constexpr double kFactoredSwitch      = 1;

// The spread of M^-1 K: Gershgorin's bound on its largest eigenvalue (1/s^2); *where (may be
// null) the dof of that row.
static double StiffnessSpread(const BeamSystem &sys, PetscInt *where = nullptr)
{
  double         top = 0;
  const PetscInt w   = 2 * sys.bw + 1;
  for (PetscInt i = 0; i < sys.ndof; ++i) {
    if (!(sys.mass[i] > 0)) continue;
    double row = 0;
    for (PetscInt o = 0; o < w; ++o) row += std::abs(sys.band[(size_t)w * i + o]);
    if (row / sys.mass[i] > top && where) *where = i;
    top = std::max(top, row / sys.mass[i]);
  }
  return top;
}

// What to change when the spread is too wide by `factor`, by the part whose dof sets it: the
// frame's roll (its rho J too light for its G J), the strings (too light for their tension), or
// the grid (the beam's h^-4).
static std::string SpreadRemedy(const BeamSystem &sys, PetscInt dof, double factor)
{
  char            text[400];
  const PetscInt  f = dof % sys.fields;
  const PetscReal h = sys.L / (sys.nodes - 1);
  if (f == sys.RollField())
    std::snprintf(text, sizeof text,
                  "set by the frame's roll at x = %.3g m (rho J = %.3g kg m there against its G J): raise "
                  "-beam_torsion_inertia at least %.2g times (or lower -beam_torsion_stiffness)",
                  (double)sys.NodeX(dof / sys.fields), (double)(sys.mass[dof] / h), factor);
  else if (sys.Face(f))
    std::snprintf(text, sizeof text,
                  "set by the strings at x = %.3g m (their mass against their tension): raise -strings_linear_density "
                  "at least %.2g times (or lower -strings_tension)",
                  (double)sys.NodeX(dof / sys.fields), factor);
  else
    std::snprintf(text, sizeof text,
                  "fewer -beam_nodes (the largest grid checked against the dense modes is N = 2561, against a finer "
                  "grid N = 10241)");
  return text;
}

static double ModesPrecisionIndex(const BeamSystem &sys)
{
  if (!(sys.frequency_unit > 0) || sys.band.empty()) return 0;
  return std::numeric_limits<double>::epsilon() * StiffnessSpread(sys) / (sys.frequency_unit * sys.frequency_unit);
}

static double FactoredPrecisionIndex(const BeamSystem &sys)
{
  if (!(sys.frequency_unit > 0) || sys.band.empty()) return 0;
  return std::numeric_limits<double>::epsilon() * std::sqrt(StiffnessSpread(sys)) / sys.frequency_unit;
}

bool BeamModesFactoredForm(const BeamSystem &sys, BeamFactor *F)
{
  return ModesPrecisionIndex(sys) > kFactoredSwitch && BeamFactorCreate(sys, F);
}

// The factored form the modes of sys come from (see above), or null (the primal path: K).
static std::shared_ptr<const BeamFactor> FactoredFormFor(const BeamSystem &sys)
{
  auto F = std::make_shared<BeamFactor>();
  if (!BeamModesFactoredForm(sys, F.get())) return nullptr;
  return F;
}

bool BeamModesAvailable(const BeamSystem &sys, std::string *why)
{
  if (!ForceOperatorModal(sys, nullptr, nullptr, why))
    return false; // a force term the modes cannot carry (the grip: a drive in time, a damper not proportional)
  for (const auto &c : caches) // modes built for the same beam (a sweep's next point): available, without building its
                               // factor again (O(N), 15 ms at N = 40961)
    for (const auto &m : c.second)
      if (SameBeam(m->sys, sys)) return true;
  const double index = ModesPrecisionIndex(sys);
  if (index > kModesPrecisionLimit) {
    BeamFactor  F;
    std::string whynot;
    const bool  factored = BeamFactorCreate(sys, &F, &whynot);
    if (factored && FactoredPrecisionIndex(sys) <= kModesPrecisionLimit) return true;
    if (why) {
      char     text[1000];
      PetscInt where = 0;
      StiffnessSpread(sys, &where);
      std::snprintf(text, sizeof text,
                    "on %d nodes the stiffness spreads over %.1e times its lowest mode's scale, beyond what double "
                    "precision resolves in the modes (at most %.1e), and the factored form %s: %s",
                    (int)sys.nodes, index / std::numeric_limits<double>::epsilon(),
                    kModesPrecisionLimit / std::numeric_limits<double>::epsilon(),
                    factored ? "is beyond it too" : ("does not apply (" + whynot + ")").c_str(),
                    SpreadRemedy(sys, where, index / kModesPrecisionLimit).c_str());
      *why = text;
    }
    return false;
  }
  return true;
}

namespace {

// The time models of the decompositions, in CPU seconds measured on the development machine
// (reference BLAS; docs/convergence.md; on a loaded machine the wall time is a few times more),
// which depend on the band through the refinement (solvers/modal_basis.hpp):
// * Where every mode is refined (ModalRefinesEveryMode: a beam's narrow band), the dense one
//   (dsyevd, then Gram-Schmidt and the refinement over every mode) per free dof cubed (the
//   R161's whole run at n = 2562: 41.8 s, at n = 1282: 4.3 s); a partial eigen-solve and its
//   refinement per free dof per mode asked squared (Krylov-Schur's orthogonalisation dominates;
//   300 of 1282 free dofs 1.18 s, of 2562 2.04 s; measured for nev <= n/4). The dense one is
//   chosen where it is expected to be quicker: above n sqrt(kDense/kPartial) = n/2 modes.
// * Where the band is wide (a string bed: kl ~ 2 fields per node), refining every mode would
//   cost 4 n kl^2 per mode, more than the decomposition; the modes are refined by need instead
//   (a few, by sparse LU), so the models are the decompositions' alone: dsyevd 1.2e-9 n^3 (the
//   held bed at n = 1967 10.3 s, the strung racket at n = 2683 and the rectangular bed at
//   n = 4108), Krylov-Schur 6e-9 n nev^2 (the held bed, 300 to 900 of 1967 modes: 4.4e-9 to
//   6e-9; 400 of 9401: 7.8e-9): the dense one from about 0.45 n modes.
// * With -modal_refine all on a wide band, each mode's banded refinement is added,
//   ModalRefineModeFlops(n, kl) at 1.1e-10 s a flop (dgbtrf and dgbtrs on the held bed of
//   n = 1967, kl = 87: 14 s for every mode).
constexpr double kDenseModesCost           = 2.5e-9;  // s
constexpr double kPartialSolveCost         = 1e-8;    // s
constexpr double kDenseDecompositionCost   = 1.2e-9;  // s
constexpr double kPartialDecompositionCost = 6e-9;    // s
constexpr double kBandRefineFlopCost       = 1.1e-10; // s

// The expected seconds of the dense decomposition of the beam's n free dofs and of a partial
// solve of nev modes (the models above, chosen by the band), with their refinement.
double RefineSeconds(const ModalSystem &S, PetscInt count, bool refine_all)
{
  const PetscInt kl = ModalRefineHalfWidth(S);
  if (ModalRefinesEveryMode(S.n, kl, count) || !refine_all) return 0; // in the constants, or a few modes
  return kBandRefineFlopCost * (double)count * ModalRefineModeFlops(S.n, kl);
}
double DenseSeconds(const ModalSystem &S, bool refine_all)
{
  const double n = (double)S.n;
  return (ModalRefinesEveryMode(S.n, ModalRefineHalfWidth(S), S.n) ? kDenseModesCost : kDenseDecompositionCost) * n *
           n * n +
         RefineSeconds(S, S.n, refine_all);
}
double PartialSeconds(const ModalSystem &S, PetscInt nev, bool refine_all)
{
  return (ModalRefinesEveryMode(S.n, ModalRefineHalfWidth(S), nev) ? kPartialSolveCost : kPartialDecompositionCost) *
           (double)S.n * (double)nev * (double)nev +
         RefineSeconds(S, nev, refine_all);
}

// The modes with omega^2 below sigma (rigid ones included), counted exactly by Sylvester's law
// of inertia: the negative pivots of the banded LDL^T of K - sigma M on the free dofs (no
// pivoting, O(n bw^2); a pivot that vanishes, sigma an eigenvalue to round-off, counts as one).
PetscInt ModesBelow(const BeamSystem &sys, const ModalSystem &S, PetscReal sigma)
{
  const PetscInt         n = S.n, kd = sys.bw, ld = kd + 1;
  std::vector<PetscInt>  free_of(sys.ndof, -1), cols(2 * kd + 1);
  std::vector<PetscReal> vals(2 * kd + 1), a((size_t)ld * n, 0.0); // A(r, c), r >= c, at a[c ld + r - c]
  PetscInt               below = 0;
  for (PetscInt d = 0; d < n; ++d) free_of[S.dof[d]] = d;
  for (PetscInt d = 0; d < n; ++d) {
    const PetscInt nc = BeamSystemStiffnessRow(sys, S.dof[d], cols.data(), vals.data());
    for (PetscInt q = 0; q < nc; ++q) {
      const PetscInt c = free_of[cols[q]];
      if (c >= 0 && c <= d) a[(size_t)c * ld + d - c] += vals[q];
    }
    a[(size_t)d * ld] -= sigma * S.mass[d];
  }
  for (PetscInt j = 0; j < n; ++j) {
    PetscReal *cj = &a[(size_t)j * ld], dj = cj[0];
    if (!(dj > 0)) {
      below++;
      if (dj == 0) dj = -std::numeric_limits<PetscReal>::min();
    }
    for (PetscInt i = j + 1; i < std::min(n, j + ld); ++i) {
      const PetscReal f  = cj[i - j] / dj;
      PetscReal      *ci = &a[(size_t)i * ld];
      for (PetscInt k = i; k < std::min(n, j + ld); ++k) ci[k - i] -= f * cj[k - j];
    }
  }
  return below;
}

// The modes a partial solve asks for to reach the cut-off wc: those below it (ModesBelow) and
// a few above, so that its last is past the cut-off.
PetscInt ModesAskedBelow(const BeamSystem &sys, const ModalSystem &S, PetscReal wc)
{
  return std::min<PetscInt>(S.n, ModesBelow(sys, S, wc * wc) + 8);
}

// The memory of a partial eigen-solve of nev modes of n free dofs (bytes): SLEPc's Krylov-Schur
// basis of ncv = max(2 nev, nev + 15) vectors (its default) and the nev eigenvectors returned,
// 3 nev vectors of n doubles, and its projected problem's dense ncv x ncv matrices (a few).
// Measured (the factored form, 560 modes, 1e4 to 4e4 free dofs): 13.2 kB a free dof; the
// model's 24 nev = 13.4 kB.
double PartialModesBytes(PetscInt n, PetscInt nev)
{
  const double ncv = std::max(2.0 * nev, nev + 15.0);
  return sizeof(PetscReal) * ((ncv + nev) * (double)n + 4 * ncv * ncv);
}

// Refuses a partial solve of nev modes whose memory (PartialModesBytes) is above the run's limit.
PetscErrorCode PartialModesMemoryCheck(MPI_Comm comm, PetscInt n, PetscInt nev)
{
  PetscFunctionBeginUser;
  PetscCall(
    MemoryCheck(comm, PartialModesBytes(n, nev),
                "the beam's modes: a partial eigen-solve of " + std::to_string(nev) + " modes of " + std::to_string(n) +
                  " free dofs",
                "use fewer -beam_nodes, a larger -modal_tolerance (fewer modes) or a -ts_type other than modal"));
  PetscFunctionReturn(0);
}

// Whether the dense decomposition of the n free dofs is expected to be quicker than a partial
// solve of nev modes (the time models above; below 65 dofs always).
bool DenseIsQuicker(const ModalSystem &S, PetscInt nev, bool refine_all)
{
  return S.n <= 64 || DenseSeconds(S, refine_all) <= PartialSeconds(S, nev, refine_all);
}

// The dense decomposition of every mode, with its memory check (3 n^2 doubles: the matrix,
// which becomes the basis, and dsyevd's workspace of 2 n^2) against the run's limit.
PetscErrorCode DenseModes(MPI_Comm comm, BeamModes *m,
                          const char *why = "-modal_modes auto keeps only the modes the contact moves")
{
  const double n = (double)m->S.n, need = 3 * n * n * sizeof(PetscReal);

  PetscFunctionBeginUser;
  PetscCall(
    MemoryCheck(comm, need,
                "-modal_modes " + ModalModesText(m->request) + ": the dense decomposition of every mode of " +
                  std::to_string(m->S.n) + " free dofs",
                "use -modal_modes auto (the modes up to the cut-off of -modal_tolerance) or a number of modes"));
  const double expected = DenseSeconds(m->S, m->request.refine_all); // s
  if (m->request.cost_warn > 0 && expected > m->request.cost_warn)
    PetscCall(PetscPrintf(comm,
                          "beamimpact: the beam's modes: a dense decomposition of %" PetscInt_FMT
                          " free dofs, expected to take about %.0f s (%s)\n",
                          m->S.n, expected, why));
  PetscCall(ModalBasisBuild(m->S, false, &m->B, m->request.refine_all, comm));
  m->method = m->B.mirrored ? "dense, mirror-split" : "dense";
  PetscFunctionReturn(0);
}

// Keeps the first `keep` columns of the basis.
void KeepModes(BeamModes *m, PetscInt keep)
{
  ModalBasis &B = m->B;
  if (!B.by_need) B.refined = std::min(B.refined, keep); // every mode refined: every kept one
  B.Phi.resize((size_t)m->S.n * keep);
  B.omega.resize(keep);
  B.gamma.resize(keep);
  B.rate.resize(keep);
}

// -modal_weight share: Krylov-Schur's largest projected dimension (mpd). SLEPc's default ncv =
// 2 nev orthogonalises against twice the modes at every restart and solves a projected problem
// of that size (dsteqr, cubic): 0.44 s for 320 of the shelled bat's 1849 free dofs, 0.25 s with
// mpd 100 (the same modes to the solver's tolerance).
constexpr PetscInt kShareProjected = 100;

// The modes up to `want` (Count) or up to the cut-off w_c (Auto, want < 0: as many as lie below
// it, counted, and a few more) from a partial eigen-solve, nev grown if it fell short; the
// dense decomposition instead where the time models expect it to be quicker (DenseIsQuicker),
// before each solve. Then keeps what was asked.
PetscErrorCode TruncatedModes(MPI_Comm comm, BeamModes *m, PetscInt want, PetscReal wc)
{
  const PetscInt                      n   = m->S.n;
  const BeamSystem                   &sys = m->sys;
  std::vector<PetscReal>              lambda;
  std::vector<std::vector<PetscReal>> phis;
  PetscInt                            nev = want;

  PetscFunctionBeginUser;
  if (want < 0) nev = ModesAskedBelow(sys, m->S, wc);
  for (;;) {
    if (DenseIsQuicker(m->S, nev, m->request.refine_all)) { // and exact
      PetscCall(DenseModes(comm, m));
      break;
    }
    const double expected = PartialSeconds(m->S, nev, m->request.refine_all); // s
    if (m->request.cost_warn > 0 && expected > m->request.cost_warn)
      PetscCall(PetscPrintf(comm,
                            "cost: the beam's modes: a partial eigen-solve of %" PetscInt_FMT " modes of %" PetscInt_FMT
                            " free dofs (SLEPc), expected to take about %.0f s and %.2g GB; a larger -modal_tolerance "
                            "keeps fewer modes\n",
                            nev, n, expected, PartialModesBytes(n, nev) / 1e9));
    PetscCall(PartialModesMemoryCheck(comm, n, nev));
    const bool share = ModalWeighsShare(m->request); // Krylov-Schur's restarts bounded, the modes refined by need
    PetscCall(BeamModesLowest(comm, sys, nev, m->request.progress, &lambda, &phis, share ? kShareProjected : 0));
    if (want >= 0 || lambda.back() > wc * wc) {
      m->method = "slepc";
      std::vector<PetscReal> Phi((size_t)n * nev);
      for (PetscInt k = 0; k < nev; ++k)
        for (PetscInt d = 0; d < n; ++d) Phi[d + (size_t)k * n] = std::sqrt(m->S.mass[d]) * phis[k][m->S.dof[d]];
      PetscCall(ModalBasisFromModes(m->S, lambda, std::move(Phi), &m->B, !share, m->request.refine_all));
      break;
    }
    const PetscReal grow = std::sqrt(wc / std::sqrt(std::max(lambda.back(), (PetscReal)1e-300)));
    nev                  = std::min<PetscInt>(n, std::max<PetscInt>(2 * nev, (PetscInt)(1.2 * grow * nev) + 8));
    PetscCall(PetscInfo(NULL,
                        "the beam's modes: %" PetscInt_FMT
                        " found below the cut-off %g rad/s; asking for %" PetscInt_FMT "\n",
                        (PetscInt)lambda.size(), (double)wc, nev));
  }
  PetscInt keep = m->Count();
  if (want >= 0) keep = std::min(keep, want);
  else {
    keep = 0;
    while (keep < m->Count() && m->B.omega[keep] <= wc) keep++;
  }
  KeepModes(m, std::max<PetscInt>(keep, 1));
  PetscFunctionReturn(0);
}

// The modes up to `want` (Count) or up to the cut-off w_c (Auto, want < 0) from the factored
// form (BeamModesLowestFactored), nev grown until the cut-off is passed as TruncatedModes does;
// kept as found (exact and orthonormal: no inverse iteration with K's band). Then keeps what
// was asked.
PetscErrorCode FactoredModes(MPI_Comm comm, BeamModes *m, PetscInt want, PetscReal wc)
{
  const PetscInt                      n = m->S.n;
  std::vector<PetscReal>              lambda;
  std::vector<std::vector<PetscReal>> phis;
  PetscInt                            nev = want >= 0 ? std::min(want, n) : ModesAskedBelow(m->sys, m->S, wc);

  PetscFunctionBeginUser;
  for (;;) {
    const double expected = kPartialSolveCost * (double)n * (double)nev * (double)nev; // s
    if (m->request.cost_warn > 0 && expected > m->request.cost_warn)
      PetscCall(PetscPrintf(comm,
                            "cost: the beam's modes: a partial eigen-solve of %" PetscInt_FMT " modes of %" PetscInt_FMT
                            " free dofs (SLEPc, the factored form), expected to take about %.0f s and %.2g GB; a "
                            "larger -modal_tolerance keeps fewer modes\n",
                            nev, n, expected, PartialModesBytes(n, nev) / 1e9));
    PetscCall(PartialModesMemoryCheck(comm, n, nev));
    PetscCall(BeamModesLowestFactored(comm, m->sys, *m->factor, nev, m->request.progress, &lambda, &phis));
    if (want >= 0 || nev >= n || lambda.back() > wc * wc) break;
    const PetscReal grow = std::sqrt(wc / std::sqrt(std::max(lambda.back(), (PetscReal)1e-300)));
    nev                  = std::min<PetscInt>(n, std::max<PetscInt>(2 * nev, (PetscInt)(1.2 * grow * nev) + 8));
    PetscCall(PetscInfo(NULL,
                        "the beam's modes (factored form): %" PetscInt_FMT
                        " found below the cut-off %g rad/s; asking for %" PetscInt_FMT "\n",
                        (PetscInt)lambda.size(), (double)wc, nev));
  }
  const PetscInt         found = (PetscInt)lambda.size();
  std::vector<PetscReal> Phi((size_t)n * found);
  for (PetscInt k = 0; k < found; ++k)
    for (PetscInt d = 0; d < n; ++d) Phi[d + (size_t)k * n] = std::sqrt(m->S.mass[d]) * phis[k][m->S.dof[d]];
  m->method = "slepc, factored form";
  PetscCall(ModalBasisFromModes(m->S, lambda, std::move(Phi), &m->B, false));
  PetscInt keep = 0;
  if (want >= 0) keep = std::min(found, want);
  else
    while (keep < found && m->B.omega[keep] <= wc) keep++;
  KeepModes(m, std::max<PetscInt>(keep, 1));
  PetscFunctionReturn(0);
}

// The primal path (K) on a grid where only the factored form resolves the modes: refused.
PetscErrorCode PrimalCheck(MPI_Comm comm, const BeamModes *m)
{
  PetscFunctionBeginUser;
  PetscCheck(ModesPrecisionIndex(m->sys) <= kModesPrecisionLimit, comm, PETSC_ERR_SUP,
             "-modal_modes %s: the dense decomposition works with the stiffness K, which on %d nodes spreads over %.1e "
             "times its lowest mode's scale, beyond double precision (at most %.1e); use -modal_modes auto or a number "
             "of modes (the factored form) or fewer -beam_nodes",
             ModalModesText(m->request).c_str(), (int)m->sys.nodes,
             ModesPrecisionIndex(m->sys) / std::numeric_limits<double>::epsilon(),
             kModesPrecisionLimit / std::numeric_limits<double>::epsilon());
  PetscFunctionReturn(0);
}

// Share: gamma_k under the load and G (c the correction of every computed mode; of a dense basis
// G is the sum over its modes of gamma_k^2 / w_k^2).
void ShareGammas(const BeamModes &m, const ModalCorrection &c, std::vector<PetscReal> *gamma, PetscReal *G)
{
  const ModalTruncation                     &t = m.request;
  const PetscInt                             n = m.S.n, count = m.Count();
  std::vector<std::pair<PetscInt, PetscInt>> coupled; // (weight, free dof): the coupled dofs are few, found once
  gamma->assign(count, 0.0);
  *G = c.G;
  for (PetscInt q = 0; q < t.at.n; ++q)
    for (PetscInt d = 0; d < n; ++d)
      if (m.S.dof[d] == t.at.dof[q]) coupled.push_back({q, d});
  for (PetscInt k = m.rigid; k < count; ++k) {
    const PetscReal *phi = &m.B.Phi[(size_t)k * n];
    for (const auto &[q, d] : coupled) (*gamma)[k] += t.at.w[q] * phi[d] / std::sqrt(m.S.mass[d]);
    if (!m.truncated) *G += (*gamma)[k] * (*gamma)[k] / (m.B.omega[k] * m.B.omega[k]);
  }
}

// Share: the error of the modes not computed (ModalTruncation's weight), sum_r a_r (pi/(w_r T))^q
// with a_r = gamma_r^2/w_r^2/G: their exact moment for q = 2 ((pi/T)^2 H_r/G), else bounded by
// Hoelder's inequality between the two moments known, sum a_r = G_r/G and sum a_r/w_r^2 = H_r/G:
// (pi/T)^q (G_r/G)^(1 - q/2) (H_r/G)^(q/2), which is at most the bound G_r/G (pi/(w_last T))^q
// used before (H_r <= G_r/w_last^2; 0.4 to 0.6 of it on the shelled bat); 0 for a basis of every mode.
PetscReal ShareRestOf(const ModalTruncation &t, PetscReal gr, PetscReal hr) // gr = G_r/G, hr = H_r/G
{
  const PetscReal q = std::min<PetscReal>(2, t.force_exponent), T = t.contact_time;
  if (q >= 2) return (M_PI / T) * (M_PI / T) * hr;
  return std::pow(M_PI / T, q) * std::pow(gr, 1 - q / 2) * std::pow(hr, q / 2);
}
PetscReal ShareRest(const BeamModes &m, const ModalCorrection &c, PetscReal G)
{
  if (!m.truncated || !(G > 0)) return 0.0;
  return ShareRestOf(m.request, c.Gr / G, c.Hr / G);
}

// Share: how fast the share-weighted error falls with the modes computed, e ~ 1/nev^p: p from the
// error with the upper half of the flexible modes left out against with none (rest), between the
// force's exponent q (each mode's own weight, (pi/(w T))^q, falls at least as 1/nev^q where w
// grows at least as nev: the rate before, which asked for 1100 of the shelled bat's 1849 modes
// where 220 do) and 4.
PetscReal ShareSlope(const BeamModes &m, const std::vector<PetscReal> &gamma, PetscReal G, PetscReal rest,
                     const std::vector<PetscInt> &flexible) // the flexible modes weighed, ascending
{
  const ModalTruncation &t = m.request;
  const PetscReal        q = std::min<PetscReal>(2, t.force_exponent), T = t.contact_time;
  const size_t           count = flexible.size(), half = count / 2;
  PetscReal              e = rest;
  if (!(rest > 0) || !(G > 0) || half == 0) return q;
  for (size_t i = half; i < count; ++i) {
    const PetscReal w = m.B.omega[flexible[i]];
    e += gamma[flexible[i]] * gamma[flexible[i]] / (w * w * G) * std::pow(M_PI / (w * T), q);
  }
  const PetscReal p = std::log(e / rest) / std::log((PetscReal)count / (PetscReal)half);
  return std::isfinite(p) ? std::min<PetscReal>(4, std::max(q, p)) : q;
}

// Keeps the columns of the basis marked in `keep` (in their order).
void KeepModeSet(BeamModes *m, const std::vector<char> &keep)
{
  ModalBasis    &B = m->B;
  const PetscInt n = m->S.n;
  PetscInt       j = 0;
  for (PetscInt k = 0; k < m->Count(); ++k) {
    if (!keep[k]) continue;
    if (j != k) {
      std::copy_n(&B.Phi[(size_t)k * n], n, &B.Phi[(size_t)j * n]);
      B.omega[j] = B.omega[k], B.gamma[j] = B.gamma[k], B.rate[j] = B.rate[k];
    }
    j++;
  }
  KeepModes(m, j);
}

// Share: the fewest of the computed modes whose left-out set keeps the share-weighted error within
// the tolerance: `rest` (the modes not computed: ShareRest, or the groups' sum) and the computed flexible modes left
// out, each (gamma_k^2 / w_k^2 / G) (pi / (w_k T))^q, left out from the smallest weight up (a mode the load hardly
// moves, as a wall harmonic's with a node under the ball, is left to the static correction wherever it lies in the
// spectrum; the rigid modes and at least one flexible mode kept).
void ShareTrim(BeamModes *m, const ModalCorrection &c, PetscReal rest)
{
  const ModalTruncation &t = m->request;
  const PetscInt         n = m->S.n, count = m->Count();
  const PetscReal        q = std::min<PetscReal>(2, t.force_exponent), T = t.contact_time;
  std::vector<PetscReal> gamma, weight(count, 0.0);
  std::vector<PetscInt>  order;
  std::vector<char>      keep(count, 1);
  PetscReal              G;
  ShareGammas(*m, c, &gamma, &G);
  PetscReal error = rest;
  for (PetscInt k = m->rigid; k < count && G > 0; ++k) {
    const PetscReal w = m->B.omega[k];
    weight[k]         = gamma[k] * gamma[k] / (w * w * G) * std::pow(M_PI / (w * T), q);
    order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](PetscInt a, PetscInt b) { return weight[a] < weight[b]; });
  for (size_t i = 0; i + 1 < order.size(); ++i) { // the largest weight always kept
    if (error + weight[order[i]] > t.tolerance) break;
    error += weight[order[i]];
    keep[order[i]] = 0;
  }
  m->share_error = error;
  KeepModeSet(m, keep);
  m->truncated = m->Count() < n;
  m->ForgetCorrections();
}

// The free dofs in groups that K and M do not couple (no entry of K between two groups; M is
// diagonal), each ascending: the barrel wall's harmonics are uncoupled from the beam and from each
// other (model/shell.hpp), so the shelled bat's 1849 free dofs are the beam's 337 and each of three
// harmonics' barrel (414) and handle (90); a beam, a strung racket: one group. Union-find over K's rows.
std::vector<std::vector<PetscInt>> UncoupledGroups(const BeamModes &m)
{
  const BeamSystem                  &sys = m.sys;
  const PetscInt                     n   = m.S.n;
  std::vector<PetscInt>              free_of(sys.ndof, -1), root(n), cols(2 * sys.bw + 1);
  std::vector<PetscReal>             vals(2 * sys.bw + 1);
  std::vector<std::vector<PetscInt>> groups;
  std::map<PetscInt, size_t>         group_of_root;
  auto                               find = [&](PetscInt a) {
    while (root[a] != a) a = root[a] = root[root[a]];
    return a;
  };
  for (PetscInt d = 0; d < n; ++d) free_of[m.S.dof[d]] = d, root[d] = d;
  for (PetscInt d = 0; d < n; ++d) {
    const PetscInt nc = BeamSystemStiffnessRow(sys, m.S.dof[d], cols.data(), vals.data());
    for (PetscInt q = 0; q < nc; ++q) {
      const PetscInt c = free_of[cols[q]];
      if (c < 0 || vals[q] == 0.0) continue;
      const PetscInt a = find(d), b = find(c);
      if (a != b) root[std::max(a, b)] = std::min(a, b);
    }
  }
  for (PetscInt d = 0; d < n; ++d) {
    const auto it = group_of_root.emplace(find(d), groups.size()).first;
    if (it->second == groups.size()) groups.emplace_back();
    groups[it->second].push_back(d);
  }
  return groups;
}

// Share, one group of uncoupled free dofs: its modes as columns over every free dof of m.S
// (M^{1/2} phi, zero off the group) with their omega^2.
struct GroupModes {
  std::vector<PetscInt>               dofs;        // the group's free dofs (indices of m.S), ascending
  PetscInt                            nev = 0;     // modes asked for
  bool                                all = false; // every mode of the group (the dense decomposition)
  std::vector<PetscReal>              lambda;      // (rad/s)^2, ascending
  std::vector<std::vector<PetscReal>> cols;        // per mode: m.S.n entries
};

// The group's `nev` lowest modes from a partial eigen-solve on the system with every dof off the
// group held (BeamModesLowest: its K and M are the group's own), or every mode from the group's
// dense decomposition where nev is more than half of them (or the group has at most 64 dofs).
PetscErrorCode GroupModesCompute(MPI_Comm comm, const BeamModes &m, GroupModes *g)
{
  const ModalSystem    &S   = m.S;
  const PetscInt        nb  = (PetscInt)g->dofs.size();
  BeamSystem            sub = m.sys;
  std::vector<char>     in(sub.ndof, 0);
  std::vector<PetscInt> free_of(sub.ndof, -1);

  PetscFunctionBeginUser;
  for (PetscInt d : g->dofs) in[S.dof[d]] = 1, free_of[S.dof[d]] = d;
  for (PetscInt i = 0; i < sub.ndof; ++i)
    if (!in[i]) sub.held[i] = 1;
  g->lambda.clear();
  g->cols.clear();
  if (nb <= 64 || 2 * g->nev > nb) {
    const ModalSystem Sb = ModalSystemBeamOnly(sub);
    ModalBasis        Bb;
    PetscCall(ModalBasisBuild(Sb, false, &Bb, m.request.refine_all));
    g->all = true, g->nev = nb;
    for (PetscInt k = 0; k < (PetscInt)Bb.omega.size(); ++k) {
      g->lambda.push_back(Bb.omega[k] * Bb.omega[k]);
      g->cols.emplace_back(S.n, 0.0);
      for (PetscInt d = 0; d < Sb.n; ++d) g->cols.back()[free_of[Sb.dof[d]]] = Bb.Phi[d + (size_t)k * Sb.n];
    }
    PetscFunctionReturn(0);
  }
  std::vector<std::vector<PetscReal>> phis;
  PetscCall(PartialModesMemoryCheck(comm, nb, g->nev));
  PetscCall(BeamModesLowest(comm, sub, g->nev, m.request.progress, &g->lambda, &phis, kShareProjected));
  for (const auto &phi : phis) {
    g->cols.emplace_back(S.n, 0.0);
    for (PetscInt d : g->dofs) g->cols.back()[d] = std::sqrt(S.mass[d]) * phi[S.dof[d]];
  }
  PetscFunctionReturn(0);
}

// The basis of every group's modes, ascending (the exact rigid ones then replace the zero
// cluster, ExactRigidModes); *group_of the group of each mode.
PetscErrorCode GroupsBasis(BeamModes *m, const std::vector<GroupModes> &groups, std::vector<PetscInt> *group_of)
{
  const PetscInt                                                   n = m->S.n;
  std::vector<std::pair<PetscReal, std::pair<PetscInt, PetscInt>>> all; // (lambda, (group, mode))
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < (PetscInt)groups.size(); ++b)
    for (PetscInt k = 0; k < (PetscInt)groups[b].lambda.size(); ++k) all.push_back({groups[b].lambda[k], {b, k}});
  std::stable_sort(all.begin(), all.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
  std::vector<PetscReal> lambda, Phi((size_t)n * all.size());
  group_of->clear();
  for (size_t j = 0; j < all.size(); ++j) {
    lambda.push_back(all[j].first);
    group_of->push_back(all[j].second.first);
    std::copy_n(groups[all[j].second.first].cols[all[j].second.second].data(), n, &Phi[j * n]);
  }
  m->method = "slepc, uncoupled groups";
  PetscCall(ModalBasisFromModes(m->S, lambda, std::move(Phi), &m->B, false));
  m->truncated = m->Count() < n;
  ExactRigidModes(m);
  PetscFunctionReturn(0);
}

// Share: the error of a group's modes not computed, from the moments of the static correction's
// shape u_r on the group (K and M do not couple the groups: G_r and H_r are the groups' sums),
// H_r = u_r^T M u_r and G_r = u_r^T K u_r (twice its strain energy) there, as ShareRest.
PetscReal GroupRest(const BeamModes &m, const ModalCorrection &c, const GroupModes &g, PetscReal G)
{
  const BeamSystem      &sys = m.sys;
  std::vector<PetscReal> y(sys.ndof, 0.0);
  PetscReal              H = 0;
  if (g.all || !(G > 0) || c.ur.empty()) return 0.0;
  for (PetscInt d : g.dofs) y[m.S.dof[d]] = c.ur[d], H += m.S.mass[d] * c.ur[d] * c.ur[d];
  const PetscReal Gg = 2 * BeamSystemStrainEnergy(sys, y.data(), sys.fields, 0, sys.ndof);
  return ShareRestOf(m.request, Gg / G, H / G);
}

// Share on uncoupled groups (UncoupledGroups, more than one): each group's lowest modes from its
// own partial solve (its K and M alone: the shelled bat's wall harmonics of 414 and 90 dofs, the beam
// of 337, instead of one solve of 1849 whose Krylov basis orthogonalises across all of them), 32 each
// at first; each group whose own rest is above the tolerance over the number of groups asks for
// more as ShareModes does (its slope measured on its own modes), until the groups' rests together
// are within the tolerance. *rest their sum; *c the static correction of the last basis.
PetscErrorCode ShareGroupModes(MPI_Comm comm, BeamModes *m, std::vector<GroupModes> &groups, PetscReal *rest,
                               const ModalCorrection **c)
{
  const ModalTruncation &t     = m->request;
  const PetscReal        share = t.tolerance / (PetscReal)groups.size();
  std::vector<char>      stale(groups.size(), 1);
  std::vector<PetscInt>  group_of;

  PetscFunctionBeginUser;
  for (auto &g : groups) g.nev = std::min<PetscInt>((PetscInt)g.dofs.size(), 32);
  for (;;) {
    for (size_t b = 0; b < groups.size(); ++b)
      if (stale[b]) PetscCall(GroupModesCompute(comm, *m, &groups[b]));
    std::fill(stale.begin(), stale.end(), 0);
    PetscCall(GroupsBasis(m, groups, &group_of));
    PetscCall(m->StaticCorrection(t.at, c));
    std::vector<PetscReal> gamma, rests;
    PetscReal              G;
    ShareGammas(*m, **c, &gamma, &G);
    *rest = 0;
    for (const auto &g : groups) rests.push_back(GroupRest(*m, **c, g, G)), *rest += rests.back();
    if (!m->truncated || *rest <= t.tolerance) break;
    for (size_t b = 0; b < groups.size(); ++b) {
      if (groups[b].all || rests[b] <= share) continue;
      std::vector<PetscInt> flexible;
      for (PetscInt k = m->rigid; k < m->Count(); ++k)
        if (group_of[k] == (PetscInt)b) flexible.push_back(k);
      const PetscReal slope = ShareSlope(*m, gamma, G, rests[b], flexible),
                      grow  = std::min<PetscReal>(4,
                                                 std::max<PetscReal>(1.5, 1.2 * std::pow(rests[b] / share, 1 / slope)));
      PetscCall(PetscInfo(NULL,
                          "the beam's modes: group %d (%d dofs): %d modes leave a share-weighted error %g above %g "
                          "(falling as 1/nev^%.3g)\n",
                          (int)b, (int)groups[b].dofs.size(), (int)groups[b].nev, (double)rests[b], (double)share,
                          (double)slope));
      groups[b].nev = std::min<PetscInt>((PetscInt)groups[b].dofs.size(), (PetscInt)(groups[b].nev * grow));
      stale[b]      = 1;
    }
    m->ForgetCorrections();
  }
  PetscFunctionReturn(0);
}

// Share (ModalWeighsShare): the lowest modes from a partial eigen-solve, their number grown
// from 64 until the share-weighted error of the rest under the load t.at (the static correction
// there and ShareRest) is within the tolerance, or the dense decomposition (where
// the time models expect it quicker); then the fewest of them that keep it (ShareTrim).
PetscErrorCode ShareModes(MPI_Comm comm, BeamModes *m)
{
  const ModalTruncation &t   = m->request;
  const PetscInt         n   = m->S.n;
  PetscInt               nev = std::min<PetscInt>(n, 64);
  const ModalCorrection *c   = nullptr;

  PetscFunctionBeginUser;
  m->factor = FactoredFormFor(m->sys);
  if (!m->factor) PetscCall(PrimalCheck(comm, m));
  if (!m->factor) {
    std::vector<GroupModes> groups;
    for (auto &dofs : UncoupledGroups(*m)) {
      groups.emplace_back();
      groups.back().dofs = std::move(dofs);
    }
    if (groups.size() > 1) {
      PetscReal rest = 0;
      PetscCall(ShareGroupModes(comm, m, groups, &rest, &c));
      for (const auto &g : groups)
        PetscCall(PetscInfo(NULL, "the beam's modes: a group of %d free dofs, %d modes (%s)\n", (int)g.dofs.size(),
                            (int)g.lambda.size(), g.all ? "dense" : "slepc"));
      ShareTrim(m, *c, rest);
      m->method += ", share-weighted";
      PetscFunctionReturn(0);
    }
  }
  for (;;) {
    if (!m->factor && DenseIsQuicker(m->S, nev, t.refine_all))
      PetscCall(DenseModes(comm, m,
                           "-modal_weight share: the modes the load needs are more than the partial solve's time model "
                           "allows"));
    else if (m->factor) PetscCall(FactoredModes(comm, m, nev, PETSC_INFINITY));
    else PetscCall(TruncatedModes(comm, m, nev, PETSC_INFINITY));
    m->truncated = m->Count() < n;
    ExactRigidModes(m);
    PetscCall(m->StaticCorrection(t.at, &c));
    std::vector<PetscReal> gamma;
    PetscReal              G;
    ShareGammas(*m, *c, &gamma, &G);
    const PetscReal rest = ShareRest(*m, *c, G);
    if (!m->truncated || rest <= t.tolerance) break;
    std::vector<PetscInt> flexible;
    for (PetscInt k = m->rigid; k < m->Count(); ++k) flexible.push_back(k);
    const PetscReal slope = ShareSlope(*m, gamma, G, rest, flexible);
    PetscCall(PetscInfo(NULL,
                        "the beam's modes: %" PetscInt_FMT " leave a share-weighted error %g above %g (falling as "
                        "1/nev^%.3g)\n",
                        m->Count(), (double)rest, (double)t.tolerance, (double)slope));
    m->ForgetCorrections(); // the error falls as 1/nev^slope (measured on the upper half of the modes computed): that,
                            // with a margin, at most 4 times,
    const PetscReal grow = 1.2 * std::pow(rest / t.tolerance, 1 / slope);
    const PetscInt  need = (PetscInt)std::min<PetscReal>((PetscReal)n, nev * std::max<PetscReal>(1.5, grow));
    nev = std::min<PetscInt>(n, (PetscInt)(nev * std::min<PetscReal>(4, std::max<PetscReal>(1.5, grow))));
    if (!m->factor && DenseIsQuicker(m->S, need, t.refine_all))
      nev = need; // or at once the dense decomposition where that many would be slower than it
  }
  {
    std::vector<PetscReal> gamma;
    PetscReal              G;
    ShareGammas(*m, *c, &gamma, &G);
    ShareTrim(m, *c, ShareRest(*m, *c, G));
  }
  m->method += ", share-weighted";
  PetscFunctionReturn(0);
}

// The basis the request asks for (All: dense; Auto below every mode's bound: dense too); a
// truncated one from the factored form where FactoredFormFor gives one, else the primal path.
PetscErrorCode BeamModesBuild(MPI_Comm comm, BeamModes *m)
{
  const ModalTruncation &t = m->request;
  const PetscInt         n = m->S.n;
  ContactCoupling        none;
  const PetscReal        wc = t.Cutoff(),
                  wmax      = t.modes == ModalModes::Auto ? BeamSystemMaxFrequencyBound(m->sys, none, 0.0, 0.0) : 0.0;
  const bool dense          = t.modes == ModalModes::All || (t.modes == ModalModes::Count && t.count >= n) ||
                     (t.modes == ModalModes::Auto &&
                      !(wc < wmax)); // every mode is below the cut-off: all of them, exactly

  PetscFunctionBeginUser;
  if (ModalWeighsShare(t)) {
    PetscCall(ShareModes(comm, m));
    PetscFunctionReturn(0);
  }
  m->cutoff      = t.modes == ModalModes::Auto && !dense ? wc : PETSC_INFINITY;
  m->omega_bound = wmax;
  m->factor      = dense ? nullptr : FactoredFormFor(m->sys);
  if (!m->factor) PetscCall(PrimalCheck(comm, m));
  if (dense && t.modes == ModalModes::Auto && std::isfinite(wc) &&
      wmax > 0) { // every mode below the cut-off: the tolerance from which fewer are kept (the cut-off below the bound)
    char why[256];
    std::snprintf(why, sizeof why,
                  "every mode lies below the cut-off of -modal_tolerance %g, %.3g kHz, above the highest mode's bound "
                  "%.3g kHz; a -modal_tolerance above %.2g keeps fewer",
                  (double)t.tolerance, (double)(wc / (2e3 * M_PI)), (double)(wmax / (2e3 * M_PI)),
                  (double)(t.tolerance * (wc / wmax) * (wc / wmax)));
    PetscCall(DenseModes(comm, m, why));
  } else if (dense) PetscCall(DenseModes(comm, m));
  else if (m->factor) PetscCall(FactoredModes(comm, m, t.modes == ModalModes::Count ? t.count : -1, wc));
  else
    PetscCall(TruncatedModes(comm, m, t.modes == ModalModes::Count ? t.count : -1,
                             t.modes == ModalModes::Count ? PETSC_INFINITY : wc));
  m->truncated = m->Count() < n;
  PetscFunctionReturn(0);
}

} // namespace

double BeamModesExpectedSeconds(const BeamSystem &sys, const ModalTruncation &t)
{
  const ModalSystem S   = ModalSystemBeamOnly(sys);
  const PetscInt    n   = S.n;
  PetscInt          nev = n;
  if (t.modes == ModalModes::Count) nev = std::min(t.count, n);
  else if (t.modes == ModalModes::Auto) {
    ContactCoupling none;
    const PetscReal wc = t.Cutoff();
    if (wc < BeamSystemMaxFrequencyBound(sys, none, 0.0, 0.0)) nev = ModesAskedBelow(sys, S, wc);
  }
  if (DenseIsQuicker(S, nev, t.refine_all)) return DenseSeconds(S, t.refine_all); // as TruncatedModes decides
  return PartialSeconds(S, nev, t.refine_all);
}

PetscInt BeamModesCountBelow(const BeamSystem &sys, PetscReal omega)
{
  return ModesBelow(sys, ModalSystemBeamOnly(sys), omega * omega);
}

PetscErrorCode BeamModesShared(const BeamSystem &sys, std::shared_ptr<const BeamModes> *modes)
{
  ModalTruncation all;

  PetscFunctionBeginUser;
  all.modes     = ModalModes::All;
  all.cost_warn = 0;
  PetscCall(BeamModesShared(PETSC_COMM_SELF, sys, all, modes));
  PetscFunctionReturn(0);
}

PetscErrorCode BeamModesShared(MPI_Comm comm, const BeamSystem &sys, const ModalTruncation &t,
                               std::shared_ptr<const BeamModes> *modes)
{
  std::string why;
  ModesCache *pcache;

  PetscFunctionBeginUser;
  PetscCall(CacheOf(comm, &pcache));
  ModesCache &cache = *pcache;
  for (auto it = cache.begin(); it != cache.end(); ++it)
    if (BasisFits(**it, t) && SameBeam((*it)->sys, sys)) {
      *modes = *it;
      if (it != cache.begin()) {
        cache.erase(it);
        cache.push_front(*modes);
      }
      n_reused++;
      PetscFunctionReturn(0);
    }
  PetscCheck(BeamModesAvailable(sys, &why), comm, PETSC_ERR_SUP, "the beam's modes: %s", why.c_str());
  auto         m  = std::make_shared<BeamModes>();
  const double w0 = MPI_Wtime();
  m->sys          = sys;
  m->S            = ModalSystemBeamOnly(m->sys);
  m->S.mirror     = t.mirror;
  m->request      = t;
  PetscCall(BeamModesBuild(comm, m.get()));
  ExactRigidModes(m.get());
  m->build_seconds = MPI_Wtime() - w0;
  n_computed++;
  cache.push_front(m);
  while ((int)cache.size() > BeamModesCacheSize) cache.pop_back();
  *modes = m;
  PetscFunctionReturn(0);
}

void BeamModesCacheCounts(PetscInt *computed, PetscInt *reused)
{
  *computed = n_computed;
  *reused   = n_reused;
}

} // namespace beamimpact

namespace beamimpact {

namespace {

// The stiffness K on the free dofs with one temporary support per rigid mode (statically
// determinate: a self-equilibrated load has no reactions), banded Cholesky factored once: the
// supports' rows and columns replaced by the identity.
struct SupportedStiffness {
  int                    n = 0, kd = 0, ldab = 1; // free dofs, half-bandwidth, leading dimension
  std::vector<char>      held;                    // per free dof: a temporary support
  std::vector<PetscReal> ab;                      // the factor (LAPACK dpbtrf, lower)
};

PetscErrorCode SupportedStiffnessFactor(const BeamModes &m, const std::vector<PetscInt> &sup, SupportedStiffness *F)
{
  const BeamSystem      &sys = m.sys;
  const int              n = (int)m.S.n, kd = (int)sys.bw, ldab = kd + 1;
  std::vector<PetscInt>  free_of(sys.ndof, -1), cols(2 * sys.bw + 1);
  std::vector<PetscReal> vals(2 * sys.bw + 1);
  int                    info;

  PetscFunctionBeginUser;
  F->n = n, F->kd = kd, F->ldab = ldab;
  F->held.assign(n, 0);
  F->ab.assign((size_t)ldab * n, 0.0);
  for (PetscInt d = 0; d < n; ++d) free_of[m.S.dof[d]] = d;
  for (PetscInt s : sup) F->held[s] = 1;
  for (PetscInt d = 0; d < n; ++d) {
    if (F->held[d]) {
      F->ab[(size_t)d * ldab] = 1.0;
      continue;
    }
    const PetscInt nc = BeamSystemStiffnessRow(sys, m.S.dof[d], cols.data(), vals.data());
    for (PetscInt q = 0; q < nc; ++q) {
      const PetscInt c = free_of[cols[q]];
      if (c <= d && !F->held[c]) F->ab[(size_t)(d - c) + (size_t)c * ldab] = vals[q]; // lower band: (row d, column c)
    }
  }
  dpbtrf_("L", &n, &kd, F->ab.data(), &ldab, &info);
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB,
             "the static correction: the supported stiffness is not positive definite (LAPACK dpbtrf, info %d)", info);
  PetscFunctionReturn(0);
}

// u = K^+ f for a self-equilibrated f on the free dofs: the supported solve and two corrections
// by the residual in the factored form of K (BeamSystemStiffnessApply), whose round-off is
// relative to K u, not to |K| |u| as the band's (the flexibility of a low mode is ~1/w_1^2, the
// band's round-off ~eps w_max^2).
void SupportedStiffnessSolve(const BeamModes &m, const SupportedStiffness &F, const std::vector<PetscReal> &f,
                             std::vector<PetscReal> *pu)
{
  const BeamSystem       &sys = m.sys;
  const int               n = F.n, one = 1;
  std::vector<PetscReal>  y(sys.ndof), Ky(sys.ndof), r(n);
  std::vector<PetscReal> &u = *pu;
  int                     info;
  u.assign(n, 0.0);
  for (int pass = 0; pass < 3; ++pass) { // u = 0, then two corrections: r = f - K u
    std::fill(y.begin(), y.end(), 0.0);
    for (PetscInt d = 0; d < n; ++d) y[m.S.dof[d]] = u[d];
    BeamSystemStiffnessApply(sys, y.data(), sys.fields, 0, sys.ndof, Ky.data(), sys.fields);
    for (PetscInt d = 0; d < n; ++d) r[d] = F.held[d] ? 0.0 : f[d] - Ky[m.S.dof[d]];
    dpbtrs_("L", &n, &F.kd, &one, F.ab.data(), &F.ldab, r.data(), &n, &info);
    for (PetscInt d = 0; d < n; ++d) u[d] += r[d];
  }
}

// u = K^+ f on the free dofs for each load f of fs (self-equilibrated; sup the temporary
// supports), one factor for all the loads.
PetscErrorCode FlexibilitySolve(const BeamModes &m, const std::vector<PetscInt> &sup,
                                const std::vector<const std::vector<PetscReal> *> &fs,
                                std::vector<std::vector<PetscReal>>               *us)
{
  SupportedStiffness F;

  PetscFunctionBeginUser;
  PetscCall(SupportedStiffnessFactor(m, sup, &F));
  us->assign(fs.size(), std::vector<PetscReal>());
  for (size_t i = 0; i < fs.size(); ++i) SupportedStiffnessSolve(m, F, *fs[i], &(*us)[i]);
  PetscFunctionReturn(0);
}

bool SameCoupling(const ContactCoupling &a, const ContactCoupling &b)
{
  if (a.n != b.n) return false;
  for (PetscInt q = 0; q < a.n; ++q)
    if (a.dof[q] != b.dof[q] || a.w[q] != b.w[q]) return false;
  return true;
}

} // namespace

PetscErrorCode BeamModes::StaticCorrection(const ContactCoupling &g, const ModalCorrection **out) const
{
  const PetscInt n = S.n, count = Count();

  PetscFunctionBeginUser;
  for (const auto &c : corrections_)
    if (SameCoupling(c->g, g)) {
      *out = c.get();
      PetscFunctionReturn(0);
    }
  auto c = std::make_shared<ModalCorrection>();
  c->g   = g;
  if (truncated) {
    // The residual load f_r = f - M Phi Phi^T f: the point load less what the kept modes
    // (rigid ones included) carry of it, O(n k) over the kept modes. What the modes left out
    // contribute is then K^+ f_r itself, u_r = K^+ f_r and G_r = f_r^T u_r, a quadratic form
    // (in the factored form |m'_r|^2, a sum of squares): an error eps in a kept mode enters it
    // only to second order (f_r is orthogonal to that mode) or divided by the left-out modes'
    // w^2. G - sum_kept gamma_k^2 / w_k^2 is the same number in exact arithmetic but cancels:
    // G_r/G is 1e-7 at the paper's beam's 563 modes (N = 2561, -modal_tolerance 1e-9), and the
    // lowest modes' gamma_k from a partial solve carry ~1e-7 of error (w_k, a Rayleigh quotient,
    // is exact to round-off), which made G_r 3.2 times too large there (docs/convergence.md).
    std::vector<PetscReal> f(n, 0.0), sm(n);
    std::vector<PetscInt>  loaded;
    for (PetscInt d = 0; d < n; ++d) {
      sm[d] = std::sqrt(S.mass[d]);
      for (PetscInt q = 0; q < g.n; ++q)
        if (S.dof[d] == g.dof[q]) f[d] += g.w[q];
      if (f[d] != 0.0) loaded.push_back(d);
    }
    std::vector<PetscReal> fr = f;
    for (PetscInt k = 0; k < count; ++k) { // g_k over the loaded dofs only (f's other entries are zeros: the same sum)
      const PetscReal *phi = &B.Phi[(size_t)k * n];
      PetscReal        gk  = 0;
      for (PetscInt d : loaded) gk += f[d] * phi[d] / sm[d];
      for (PetscInt d = 0; d < n; ++d) fr[d] -= sm[d] * phi[d] * gk;
    }
    if (factor) { // the factored form: G = |m'|^2, G_r = |m'_r|^2, sums of squares (solvers/beam_flexibility.hpp)
      c->ur.resize(n);
      BeamFactorFlexibility(*factor, f.data(), nullptr, &c->G);
      BeamFactorFlexibility(*factor, fr.data(), c->ur.data(), &c->Gr);
    } else {
      std::vector<std::vector<PetscReal>> R(rigid, std::vector<PetscReal>(n)); // M-orthonormal rigid modes
      for (PetscInt i = 0; i < rigid; ++i)
        for (PetscInt d = 0; d < n; ++d) R[i][d] = B.Phi[d + (size_t)i * n] / sm[d];
      std::vector<PetscReal> load   = f,
                             load_r = fr; // less their rigid-body inertia: f - M R R^T f (f_r has none but round-off)
      for (auto *l : {&load, &load_r})
        for (const auto &r : R) {
          PetscReal a = 0;
          for (PetscInt d = 0; d < n; ++d) a += r[d] * (*l)[d];
          for (PetscInt d = 0; d < n; ++d) (*l)[d] -= S.mass[d] * r[d] * a;
        }
      std::vector<std::vector<PetscReal>> u,
        motions; // the supports from the exact motions (R's entries are over sqrt(m): a light dof's round-off is large)
      for (const auto &v : BeamSystemRigidMotions(sys)) {
        motions.emplace_back(n);
        for (PetscInt d = 0; d < n; ++d) motions.back()[d] = v[S.dof[d]];
      }
      PetscCall(FlexibilitySolve(*this, BeamTemporarySupports(sys, S.dof, motions), {&load, &load_r}, &u));
      for (auto &v : u)
        for (const auto &r : R) { // M-orthogonal to the rigid modes
          PetscReal a = 0;
          for (PetscInt d = 0; d < n; ++d) a += r[d] * S.mass[d] * v[d];
          for (PetscInt d = 0; d < n; ++d) v[d] -= r[d] * a;
        }
      for (PetscInt d = 0; d < n; ++d) c->G += f[d] * u[0][d];
      for (PetscInt d = 0; d < n; ++d) c->Gr += fr[d] * u[1][d];
      c->ur = std::move(u[1]);
    }
  }
  for (PetscInt d = 0; d < (PetscInt)c->ur.size(); ++d) c->Hr += S.mass[d] * c->ur[d] * c->ur[d];
  corrections_.push_back(c);
  if (corrections_.size() > 64) corrections_.erase(corrections_.begin());
  *out = c.get();
  PetscFunctionReturn(0);
}

const OptionModule &ModalOptionTable()
{
  static const OptionModule m = {
    "modal",
    "Modal engine: which of the beam's modes the free flight, -ts_type modal and -reference modal keep",
    {
      OptionText("-modal_modes",
                 "all (every mode: the dense decomposition, the exact check), auto (the modes up to the cut-off pi/(T "
                 "sqrt(-modal_tolerance)), T the contact time scale; the rest through the static correction at the "
                 "contact point) or a number K (the K lowest)",
                 "auto"),
      OptionReal("-modal_tolerance", "1",
                 "-modal_modes auto: the quasi-static error (pi/(omega T))^2 allowed for a mode left out; sets the "
                 "cut-off",
                 "1e-9", Between(0, 1e-2, true, false)),
      OptionNeeds(OptionChoice("-modal_weight",
                               "-modal_modes auto in an impact: mode (every mode below the cut-off of "
                               "-modal_tolerance) or share (the fewest modes, from partial eigen-solves, whose "
                               "left-out rest, each mode weighed by its share gamma^2/(omega^2 G) of the flexibility "
                               "under the ball's load times (pi/(omega T))^q, q the force's exponent at the first "
                               "touch capped at 2, has an error at most -modal_tolerance; the rest by the static "
                               "correction; docs/model.md section 12)",
                               {"mode", "share"}, "mode"),
                  {"-modal_modes=auto"}),
      OptionChoice("-modal_refine",
                   "auto (every mode refined by inverse iteration where the stiffness' band is narrow, as a beam's; "
                   "where it is wide, as a string bed's, the modes whose residual is above 1e-12 of their eigenvalue) "
                   "or all (every mode: the check)",
                   {"auto", "all"}, "auto"),
      OptionChoice("-modal_mirror",
                   "auto (where the structure is mirrored across the face, z -> -z: a racket's string bed about the "
                   "frame's axis, with the frame's roll, the dense decomposition of its even and odd modes apart: a "
                   "quarter of the cost, the same modes to round-off) or off (every mode at once: the check)",
                   {"auto", "off"}, "auto"),
    },
  };
  return m;
}

const std::vector<const char *> &BeamModes::PartLabels() const
{
  if (labels_.size() == (size_t)Count()) return labels_;
  const PetscInt         n = S.n;
  std::vector<PetscReal> e(n);
  labels_.assign(Count(), "");
  for (PetscInt k = 0; k < Count(); ++k) {
    const PetscReal *phi = &B.Phi[(size_t)k * n];
    for (PetscInt q = 0; q < n; ++q) e[q] = phi[q] * phi[q];
    labels_[k] = StructureAccountName(BeamSystemDominantAccount(sys, S.dof.data(), e.data(), n, nullptr));
  }
  return labels_;
}

std::string BeamModesSummary(const BeamModes &m, const ModalCorrection *c)
{
  char buf[512];
  char cut[64] = "none";
  if (m.cutoff < PETSC_INFINITY) std::snprintf(cut, sizeof cut, "%.4g Hz", (double)(m.cutoff / (2 * M_PI)));
  std::snprintf(buf, sizeof buf,
                "modal engine: %d of %d modes (cut-off %s, -modal_modes %s, -modal_tolerance %g; %s, %.3g s)",
                (int)m.Count(), (int)m.S.n, cut, ModalModesText(m.request).c_str(), (double)m.request.tolerance,
                m.method.c_str(), m.build_seconds);
  std::string s = buf;
  if (m.share_error >= 0) {
    std::snprintf(buf, sizeof buf, ", share-weighted error %.3g (force exponent %.3g)", (double)m.share_error,
                  (double)m.request.force_exponent);
    s += buf;
  }
  if (m.B.by_need) { // refined by need (a wide band: ModalRefinesEveryMode)
    std::snprintf(buf, sizeof buf, ", %d modes refined (residual above %g)", (int)m.B.refined,
                  (double)ModalRefineResidual());
    s += buf;
  }
  if (c && m.truncated) {
    std::snprintf(buf, sizeof buf, ", static correction G_r = %.4g m/N (G_r/G = %.3g)", (double)c->Gr,
                  (double)(c->G > 0 ? c->Gr / c->G : 0.0));
    s += buf;
  }
  return s;
}

PetscReal BeamModesCutoffHz(const BeamModes &m)
{
  return m.cutoff < PETSC_INFINITY ? m.cutoff / (2 * M_PI) : std::numeric_limits<PetscReal>::quiet_NaN();
}

std::string ModalModesText(const ModalTruncation &t)
{
  return t.modes == ModalModes::All ? "all" : t.modes == ModalModes::Auto ? "auto" : std::to_string(t.count);
}

PetscErrorCode ModalTruncationFromOptions(MPI_Comm comm, ModalTruncation *t)
{
  const OptionModule &T    = ModalOptionTable();
  std::string         text = ModalModesText(*t);

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-modal_modes", &text, NULL));
  PetscCall(OptionsRead(PetscOptionsObject, T, "-modal_tolerance", &t->tolerance, NULL));
  PetscInt refine = t->refine_all ? 1 : 0;
  PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-modal_refine", &refine, NULL));
  t->refine_all   = refine == 1;
  PetscInt weight = t->weight == ModalWeight::Share ? 1 : 0;
  PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-modal_weight", &weight, NULL));
  t->weight       = weight == 1 ? ModalWeight::Share : ModalWeight::Mode;
  PetscInt mirror = t->mirror ? 0 : 1;
  PetscCall(OptionsReadChoice(PetscOptionsObject, T, "-modal_mirror", &mirror, NULL));
  t->mirror = mirror == 0;
  PetscOptionsEnd();
  if (text == "all") t->modes = ModalModes::All;
  else if (text == "auto") t->modes = ModalModes::Auto;
  else {
    char *end   = nullptr;
    long  count = std::strtol(text.c_str(), &end, 10);
    PetscCheck(end && *end == '\0' && !text.empty() && count >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
               "-modal_modes %s is not allowed: use all, auto or a whole number of modes >= 1", text.c_str());
    t->modes = ModalModes::Count;
    t->count = (PetscInt)count;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The modes of the beam alone, as supported (any theory and profile, held dofs and clamped
// regions, Rayleigh damping): K phi = w^2 M phi on the free dofs, with each mode's decay rate
// sigma = alpha/2 + beta w^2/2 (C = alpha M + beta K is diagonal in this basis, so the damped
// free vibration is exact mode by mode: ModalModeAt).
//
// All of them or the lowest (-modal_modes all|auto|K, -modal_tolerance; docs/model.md §12):
//   all   every mode: dense LAPACK dsyevd of M^{-1/2} K M^{-1/2}, refined by banded inverse
//         iteration (solvers/modal_basis.hpp), exact to round-off; time and memory ~ n^3, n^2.
//   auto  the modes up to the cut-off w_c = pi / (T sqrt(tol)) (T the contact's time scale):
//         a mode above it responds to a load of duration T quasi-statically to (pi/(w T))^2 <=
//         tol, so it is left to the static correction (BeamModesStaticCorrection). When w_c
//         is above every mode (the Gershgorin bound of the system) this is `all`.
//   K     the K lowest modes (rigid ones included).
// A truncated basis comes from a partial eigen-solve (BeamModesLowest: SLEPc Krylov-Schur,
// shift-and-invert with the factorization of the banded K, nev the modes below the cut-off
// counted by Sylvester's inertia and a few more; O(n k) memory and O(n k^2) time), refined as
// the dense one, or from the dense decomposition where its time model expects it to be quicker
// (more than about half the modes kept; exact). On fine grids (eps times the spread of M^-1 K
// over frequency_unit^2 above 1) of a statically determinate beam the truncated basis and the
// static correction come from the factored form instead (solvers/beam_flexibility.hpp: no solve
// with K, round-off eps (L/h)^2 instead of eps (L/h)^4; method "slepc, factored form"), which
// carries the paper's beam to N = 40961.
//
// Computed once per beam and shared: BeamModesShared keeps the last few bases in a small
// cache of this process per group of ranks (the communicator's), keyed by the system's content (nodes, fields, masses,
// held dofs, the bands of K and C of the force operator, compared exactly) and the truncation (modes kept, cut-off), so
// every point of a sweep, every run of a study and every repetition of a scene that builds the same BeamSystem reuses
// one decomposition. The ball and the impact point are not in the key: the ball is free after separation and the impact
// point enters only through the coupling (gamma_k = g^T phi_k, O(n) per run) and the static correction at the point
// (one banded solve, cached per point in the basis).
#pragma once

#include "base/option_table.hpp"
#include "solvers/modal_basis.hpp"
#include "system/beam_system.hpp"

#include <petscsys.h>

#include <cmath>
#include <memory>
#include <string>

namespace beamimpact {

struct BeamFactor;

// Which modes the engine keeps (-modal_modes, -modal_tolerance, -modal_weight) and the scales that choose them.
enum class ModalModes {
  All,
  Auto,
  Count
};
// How Auto chooses the modes (-modal_weight): by each mode's quasi-static error alone (Mode:
// every mode below the cut-off kept), or by that error weighed with the mode's share of the
// flexibility under the ball's load (Share: the fewest modes whose left-out set has a share-weighted error e = sum_k
// (gamma_k^2 / w_k^2 / G) (pi / (w_k T))^q, q = min(p, 2) from the force's start F ~ c^p, at most the tolerance; under
// the coupling `at`, which the impact's callers set; without it, Mode), from partial eigen-solves, one a group of free
// dofs that K and M do not couple (the beam, each harmonic of a shell wall). The modes not computed enter e by their
// moment H_r ((pi/T)^2 H_r/G, q = 2) or Hoelder's bound (pi/T)^q (G_r/G)^(1-q/2) (H_r/G)^(q/2) (q < 2).
enum class ModalWeight {
  Mode,
  Share
};
struct ModalTruncation {
  ModalModes      modes     = ModalModes::Auto;
  PetscInt        count     = 0;    // Count: modes kept (rigid ones included)
  PetscReal       tolerance = 1e-9; // 1: Auto, the quasi-static error allowed (per mode left out, or in all: Share)
  ModalWeight     weight    = ModalWeight::Mode; // -modal_weight
  ContactCoupling at;                            // Share: the load the modes are weighed under (at.n == 0: none, Mode)
  PetscReal force_exponent = 2; // 1: Share, the force's exponent at the first touch, F ~ c^p (ContactStartExponent;
                                // capped at 2)
  PetscReal contact_time = 0;   // s: Auto, the contact's time scale T (ContactTimeScale)
  PetscReal cost_warn    = 30;  // s: a cost line before a decomposition expected to take longer
  PetscReal progress     = 10;  // s: a progress line this often during a partial solve (0: none)
  bool refine_all = false; // -modal_refine all: every mode refined by inverse iteration (the check); false: by need
                           // where the band is wide (ModalRefinesEveryMode)
  bool mirror = true; // -modal_mirror auto: the dense decomposition split by the structure's mirror where it has one
  // rad/s: the cut-off of Auto, pi / (T sqrt(tol)); infinite for All and Count
  PetscReal Cutoff() const
  {
    return modes == ModalModes::Auto && contact_time > 0 ? M_PI / (contact_time * std::sqrt(tolerance))
                                                         : PETSC_INFINITY;
  }
};
// Whether t weighs the modes by their share under a load (Auto, Share and a coupling given).
inline bool ModalWeighsShare(const ModalTruncation &t)
{
  return t.modes == ModalModes::Auto && t.weight == ModalWeight::Share && t.at.n > 0;
}
// -modal_modes, -modal_tolerance, -modal_refine, -modal_weight and -modal_mirror: the modal engine's table (registered
// by app/registry.cpp).
const OptionModule &ModalOptionTable();
// Reads them (T, cost_warn and progress are the caller's).
PetscErrorCode ModalTruncationFromOptions(MPI_Comm comm, ModalTruncation *t);
// "all", "auto" or the count, for messages and the run record.
std::string ModalModesText(const ModalTruncation &t);

// The static correction at a contact point (docs/model.md §12): with f the coupling (the
// point's weights on the free dofs), G = f^T K^+ f the flexibility on the flexible subspace
// (one banded Cholesky solve with temporary supports under the load less its rigid-body
// inertia, then made M-orthogonal to the rigid modes), and what the modes left out contribute,
// quasi-statically, from the residual load f_r = f - M Phi Phi^T f (f less the kept modes'
// share, rigid ones included): u_r = K^+ f_r and G_r = f_r^T u_r (in exact arithmetic
// G - sum over the kept flexible modes of gamma_k^2 / w_k^2, which cancels to G_r/G ~ 1e-7 and
// takes the kept modes' errors to first order). The point moves by -G_r F more than the kept
// modes say. 0 for an untruncated basis.
struct ModalCorrection {
  ContactCoupling        g;      // the point
  PetscReal              G  = 0; // m/N: flexibility at the point (flexible subspace)
  PetscReal              Gr = 0; // m/N: its residual part, the modes left out
  std::vector<PetscReal> ur;     // m/N per free dof: the static shape of the modes left out per unit force
  PetscReal              Hr = 0; // m s^2/N: u_r^T M u_r = sum over the modes left out of gamma_k^2 / w_k^4
};

struct BeamModes {
  BeamSystem      sys;         // the copy the basis was built from (S.sys points here)
  ModalSystem     S;           // the beam's free dofs (no ball)
  ModalBasis      B;           // omega, Phi (S.n x Count(), of M^{-1/2} K M^{-1/2}), rate; gamma unused (0)
  ModalTruncation request;     // as asked
  PetscInt        rigid   = 0; // rigid modes among the kept
  PetscReal       cutoff  = PETSC_INFINITY; // rad/s: the cut-off used (Auto), else infinite
  PetscReal   omega_bound = 0; // rad/s: Auto, the bound on the highest mode the cut-off was compared with (0: not Auto)
  bool        truncated   = false; // fewer modes than free dofs
  std::string method;              // "dense", "dense, mirror-split", "slepc" or "slepc, factored form"
  PetscReal share_error = -1; // Share: the share-weighted error of the modes left out under the load (ShareTrim); < 0:
                              // not weighed
  std::shared_ptr<const BeamFactor>
    factor; // the factored form the modes and the static correction came from (solvers/beam_flexibility.hpp), or null
  double   build_seconds = 0;
  PetscInt Count() const { return (PetscInt)B.omega.size(); }
  // The static correction at the point of coupling g (computed on first use, then cached).
  PetscErrorCode StaticCorrection(const ContactCoupling &g, const ModalCorrection **c) const;
  void           ForgetCorrections() const { corrections_.clear(); } // the basis changed (BeamModesBuild)
  // Each kept mode's part, as -task modes names it (StructureAccountName of the account holding most of
  // its phi^2: "bending", "roll", "wall", "strings"): computed on first use, O(n) per mode, then
  // kept with the basis (a sweep's points label their free flights' modes from it).
  const std::vector<const char *> &PartLabels() const;

private:
  mutable std::vector<std::shared_ptr<ModalCorrection>> corrections_;
  mutable std::vector<const char *>                     labels_;
};

// One line: the modes kept of the free dofs, the cut-off, how they were found and in what time,
// and (c given) the static correction at the point: "modal engine: 98 of 641 modes (cut-off
// 17.6 kHz, -modal_modes auto, -modal_tolerance 1e-06; slepc, 0.41 s), static correction G_r/G = 3.1e-05".
std::string BeamModesSummary(const BeamModes &m, const ModalCorrection *c = nullptr);

// The cut-off that chose the modes (Hz), NaN when none did (-modal_modes all or K, or a cut-off
// above every mode).
PetscReal BeamModesCutoffHz(const BeamModes &m);
// The expected time (s) of the decomposition t asks for on sys: the dense one, or the partial
// eigen-solve of the modes up to the cut-off (the time models in beam_modes.cpp).
double BeamModesExpectedSeconds(const BeamSystem &sys, const ModalTruncation &t);

// The number of the beam's modes (rigid ones included) with omega below `omega` (rad/s),
// counted exactly by Sylvester's law of inertia on K - omega^2 M (a banded LDL^T, O(n bw^2)):
// how many a partial solve of -modal_modes auto asks for.
PetscInt BeamModesCountBelow(const BeamSystem &sys, PetscReal omega);

// Whether the beam's free vibration can be propagated exactly in modes (the force terms are
// modal: no grip); if not, *why says so. Any size: a truncated basis has no size limit, the
// dense one a memory check (BeamModesShared).
bool BeamModesAvailable(const BeamSystem &sys, std::string *why);
// Whether the modes of sys come from the factored form (solvers/beam_flexibility.hpp) when fewer
// than all are asked: where the primal path's round-off index passes its switch (N > ~4000 for
// the paper's beam) and the structure is statically determinate; then *F is its factor. The
// truncated engine and -task modes take the same choice.
bool BeamModesFactoredForm(const BeamSystem &sys, BeamFactor *F);

// The beam's modes, from the cache when the same system was decomposed before with the same
// truncation on the same group of ranks (or with any cut-off of -modal_modes auto above every
// mode, as the cached basis was: the same dense decomposition), else computed and cached (the last BeamModesCacheSize
// per group are kept). Collective on comm: every rank of comm calls it, with the same system and
// truncation, in the same order as its other calls on comm. The comm is the structure's own, the
// communicator of the run that owns the beam (its DMDA's, the TS's, the modal reference's when it
// is run by ImpactRun's ranks): the stepped run, -ts_type modal, the free flight, the oblique
// impact's second plane and -reference modal all call it on that one, so that a cached basis is
// found by all of its ranks or by none. The partial eigen-solve is distributed over comm
// (SLEPc's basis and orthogonalisation split by rows; the factored form's banded solves done
// redundantly on each rank) and the basis is then whole on every rank. PETSC_COMM_SELF is for a
// caller that runs on one rank alone (a rank-local study, a test): its bases are that rank's
// own (one cache per group: ranks of MPI_COMM_WORLD in comm's order). The first form: every mode
// (ModalModes::All, the dense decomposition, no communication), on PETSC_COMM_SELF.
constexpr int  BeamModesCacheSize = 4;
PetscErrorCode BeamModesShared(const BeamSystem &sys, std::shared_ptr<const BeamModes> *modes);
PetscErrorCode BeamModesShared(MPI_Comm comm, const BeamSystem &sys, const ModalTruncation &t,
                               std::shared_ptr<const BeamModes> *modes);
// Cache statistics (for tests): decompositions computed and reused since the process started.
void BeamModesCacheCounts(PetscInt *computed, PetscInt *reused);

} // namespace beamimpact

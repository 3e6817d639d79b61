// Mode frequencies of the beam: SLEPc eigen-solve of K phi = omega^2 M phi over
// the free dofs, and the continuum beta-L reference. See modes.hpp.
#include "solvers/modes.hpp"

#include "solvers/beam_flexibility.hpp"
#include "solvers/beam_modes.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace beamimpact {

PetscInt BeamFreeDofCount(const BeamSystem &op)
{
  PetscInt n = 0;
  for (char held : op.held) n += !held;
  return n;
}

static PetscErrorCode ModesCountCheck(MPI_Comm comm, PetscInt count, PetscInt nfree)
{
  PetscFunctionBeginUser;
  PetscCheck(count >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-modes_count %" PetscInt_FMT " is not allowed: at least 1 mode must be requested", count);
  PetscCheck(count <= nfree, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-modes_count %" PetscInt_FMT " is not allowed: the beam has %" PetscInt_FMT
             " free dofs, so at most %" PetscInt_FMT " modes exist (use 1..%" PetscInt_FMT " or more -beam_nodes)",
             count, nfree, nfree, nfree);
  PetscFunctionReturn(0);
}

const OptionModule &ModesOptionTable()
{
  static const OptionModule m = {
    "modes",
    "Beam modes: eigen-solve of K phi = omega^2 M phi",
    {OptionInt("-modes_count",
               "Number of modes to report, counted from omega = 0 (rigid modes included, reported as 0)", "4",
               AtLeast(1))},
  };
  return m;
}

PetscErrorCode ModesParamsFromOptions(MPI_Comm comm, ModesParams *p, const BeamSystem *op)
{
  const OptionModule &T = ModesOptionTable();
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, T.title.c_str(), "beamimpact");
  PetscCall(OptionsRead(PetscOptionsObject, T, "-modes_count", &p->count, NULL));
  PetscOptionsEnd();
  if (op) PetscCall(ModesCountCheck(comm, p->count, BeamFreeDofCount(*op)));
  PetscFunctionReturn(0);
}

// SLEPc must be initialised before its classes are used. A driver calls
// SlepcInitialize itself; a program that only called PetscInitialize (the test
// main) gets it here on first use, with SlepcFinalize run by PetscFinalize.
// Without -dynamic_library_preload this does no communication.
PetscErrorCode ModesEnsureSlepc()
{
  PetscBool initialized;

  PetscFunctionBeginUser;
  PetscCall(SlepcInitialized(&initialized));
  if (!initialized) {
    PetscCall(SlepcInitializeNoArguments());
    PetscCall(PetscRegisterFinalize(SlepcFinalize));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ModesDirectSolver(MPI_Comm comm, KSP ksp)
{
  PetscMPIInt size;
  PC          pc;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  if (size > 1) PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscFunctionReturn(0);
}

// Deterministic pseudo-random number in [-1, 1) from an index (splitmix64), so the
// Krylov start vector is the same whatever the number of ranks.
static PetscReal HashUniform(PetscInt i)
{
  std::uint64_t z = static_cast<std::uint64_t>(i) + 0x9e3779b97f4a7c15ULL;
  z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z               = z ^ (z >> 31);
  return 2.0 * static_cast<PetscReal>(z >> 11) / 9007199254740992.0 - 1.0; // 2^53
}

// The eigenproblem over the free dofs: K and the diagonal lumped M, distributed by rows.
struct ModesProblem {
  std::vector<PetscInt> free_dofs;  // free row -> dof, in dof order
  std::vector<PetscInt> free_index; // dof -> free row (-1 for held dofs)
  Mat                   K = nullptr, M = nullptr;
  PetscInt              rstart = 0, rend = 0; // rows owned by this rank
};

static PetscErrorCode ModesProblemDestroy(ModesProblem *pb)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&pb->M));
  PetscCall(MatDestroy(&pb->K));
  PetscFunctionReturn(0);
}

// Numbers the free dofs and assembles K (at most 2 bw + 1 nonzeros a row) and M; PETSC_DECIDE
// splits the rows as PetscSplitOwnership does.
static PetscErrorCode ModesProblemAssemble(MPI_Comm comm, const BeamSystem &op, PetscInt count, ModesProblem *pb)
{
  PetscFunctionBeginUser;
  pb->free_index.assign(op.ndof, -1);
  for (PetscInt i = 0; i < op.ndof; ++i)
    if (!op.held[i]) {
      pb->free_index[i] = (PetscInt)pb->free_dofs.size();
      pb->free_dofs.push_back(i);
    }
  const PetscInt nfree = (PetscInt)pb->free_dofs.size();
  PetscCall(ModesCountCheck(comm, count, nfree));

  const PetscInt         width = 2 * op.bw + 1;
  std::vector<PetscInt>  cols(width);
  std::vector<PetscReal> vals(width);
  PetscCall(MatCreateAIJ(comm, PETSC_DECIDE, PETSC_DECIDE, nfree, nfree, width, NULL, width - 1, NULL, &pb->K));
  PetscCall(MatCreateAIJ(comm, PETSC_DECIDE, PETSC_DECIDE, nfree, nfree, 1, NULL, 0, NULL, &pb->M));
  PetscCall(MatGetOwnershipRange(pb->K, &pb->rstart, &pb->rend));
  for (PetscInt r = pb->rstart; r < pb->rend; ++r) {
    const PetscInt i = pb->free_dofs[r];
    const PetscInt n = BeamSystemStiffnessRow(op, i, cols.data(), vals.data());
    for (PetscInt q = 0; q < n; ++q) cols[q] = pb->free_index[cols[q]];
    PetscCall(MatSetValues(pb->K, 1, &r, n, cols.data(), vals.data(), INSERT_VALUES));
    PetscCall(MatSetValue(pb->M, r, r, op.mass[i], INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(pb->K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyBegin(pb->M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pb->K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pb->M, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(pb->K, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(pb->K, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  PetscCall(MatSetOption(pb->M, MAT_SPD, PETSC_TRUE));
  PetscFunctionReturn(0);
}

// Shift-and-invert at sigma = -unit^2 (below every eigenvalue, so K - sigma M is positive
// definite even with rigid modes): the wanted modes are those nearest sigma. The Krylov start
// vector is a hash of the free row, the same whatever the number of ranks.
static PetscErrorCode ModesSolverCreate(MPI_Comm comm, const ModesProblem &pb, PetscInt count, PetscReal unit, EPS *eps,
                                        PetscInt mpd = 0)
{
  ST           st;
  KSP          ksp;
  Vec          x0;
  PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(EPSCreate(comm, eps));
  PetscCall(EPSSetOptionsPrefix(*eps, "modes_"));
  PetscCall(EPSSetOperators(*eps, pb.K, pb.M));
  PetscCall(EPSSetProblemType(*eps, EPS_GHEP));
  PetscCall(EPSSetType(*eps, EPSKRYLOVSCHUR));
  PetscCall(EPSSetDimensions(*eps, count, PETSC_DEFAULT, mpd > 0 ? mpd : PETSC_DEFAULT));
  PetscCall(EPSSetWhichEigenpairs(*eps, EPS_TARGET_MAGNITUDE));
  PetscCall(EPSSetTarget(*eps, -unit * unit));
  PetscCall(EPSSetTolerances(*eps, 1e-12, 1000));
  PetscCall(EPSGetST(*eps, &st));
  PetscCall(STSetType(st, STSINVERT));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(ModesDirectSolver(comm, ksp));
  PetscCall(MatCreateVecs(pb.K, &x0, NULL));
  PetscCall(VecGetArray(x0, &a));
  for (PetscInt r = pb.rstart; r < pb.rend; ++r) a[r - pb.rstart] = 1.0 + 0.5 * HashUniform(r);
  PetscCall(VecRestoreArray(x0, &a));
  PetscCall(EPSSetInitialSpace(*eps, 1, &x0));
  PetscCall(VecDestroy(&x0)); // the EPS keeps its own reference
  PetscCall(EPSSetFromOptions(*eps));
  PetscFunctionReturn(0);
}

// Mass-normalises phi (over every dof) and fixes its sign: the deflection (field 0) of the
// first node above 1e-3 of the largest |phi| is positive; failing that (a mode of the other
// fields only), the first dof above it. Returns the mass norm before scaling (0: a zero vector).
static PetscReal ModeNormalise(const BeamSystem &op, std::vector<PetscReal> &phi)
{
  PetscReal mnorm = 0.0, amax = 0.0;
  for (PetscInt i = 0; i < op.ndof; ++i) mnorm += op.mass[i] * phi[i] * phi[i];
  mnorm = std::sqrt(mnorm);
  if (!(mnorm > 0)) return mnorm;
  for (PetscReal &v : phi) v /= mnorm;
  for (PetscReal v : phi) amax = std::max(amax, std::abs(v));
  PetscInt first = -1;
  for (PetscInt i = 0; i < op.nodes && first < 0; ++i)
    if (std::abs(phi[op.Dof(i)]) > 1e-3 * amax) first = op.Dof(i);
  for (PetscInt d = 0; d < op.ndof && first < 0; ++d)
    if (std::abs(phi[d]) > 1e-3 * amax) first = d;
  if (phi[first] < 0)
    for (PetscReal &w : phi) w = -w;
  return mnorm;
}

// The converged eigenvectors on every rank (phis[m][dof], mass-normalised, 0 at held dofs) and
// each eigenvalue recomputed as the Rayleigh quotient omega^2 = 2 U(phi) / (phi^T M phi), with
// U the strain energy summed from the strain terms (a sum of squares, no cancellation). The
// solver's eigenvalue carries an absolute round-off ~ eps ||M^-1 K|| ~ eps 16 EI/(mu h^4)
// (1e-4 (EI/mu)/L^4 at N = 641), which would blur the rigid modes and the fundamental on fine
// grids; the quotient's error is quadratic in the eigenvector error, so it is accurate to
// round-off in both. Every rank evaluates it on the same gathered vector.
static PetscErrorCode ModesExtract(MPI_Comm comm, EPS eps, const BeamSystem &op, const ModesProblem &pb, PetscInt count,
                                   std::vector<PetscReal> *lambda, std::vector<std::vector<PetscReal>> *phis)
{
  const PetscInt  nfree = (PetscInt)pb.free_dofs.size();
  const PetscReal unit  = op.frequency_unit;
  Vec             x, xall;
  VecScatter      toall;

  PetscFunctionBeginUser;
  lambda->assign(count, 0.0);
  phis->assign(count, std::vector<PetscReal>(op.ndof, 0.0));
  PetscCall(MatCreateVecs(pb.K, &x, NULL));
  PetscCall(VecScatterCreateToAll(x, &toall, &xall));
  for (PetscInt m = 0; m < count; ++m) {
    PetscScalar             kr;
    const PetscScalar      *a;
    std::vector<PetscReal> &phi = (*phis)[m];
    PetscCall(EPSGetEigenpair(eps, m, &kr, NULL, x, NULL));
    PetscCall(VecScatterBegin(toall, x, xall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(toall, x, xall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(xall, &a));
    for (PetscInt r = 0; r < nfree; ++r) phi[pb.free_dofs[r]] = PetscRealPart(a[r]);
    PetscCall(VecRestoreArrayRead(xall, &a));
    PetscCheck(ModeNormalise(op, phi) > 0, comm, PETSC_ERR_PLIB,
               "BeamModesCompute: eigenvector %" PetscInt_FMT " is zero", m);
    (*lambda)[m] = 2.0 * BeamSystemStrainEnergy(op, phi.data(), op.fields, 0, op.ndof); // phi^T M phi = 1
    PetscCall(PetscInfo(eps,
                        "mode %" PetscInt_FMT
                        ": solver omega^2 = %.16e, Rayleigh quotient %.16e (rad/s)^2 = %.6e (EI/mu)/L^4\n",
                        m, (double)PetscRealPart(kr), (double)(*lambda)[m], (double)((*lambda)[m] / (unit * unit))));
  }
  PetscCall(VecScatterDestroy(&toall));
  PetscCall(VecDestroy(&xall));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

// The deflection (field 0) at the nodes of a vector over the dofs.
static std::vector<PetscReal> DeflectionField(const BeamSystem &op, std::vector<PetscReal> &&phi)
{
  if (op.fields == 1) return std::move(phi);
  std::vector<PetscReal> w(op.nodes);
  for (PetscInt i = 0; i < op.nodes; ++i) w[i] = phi[op.Dof(i)];
  return w;
}

// Each field's family detail (StructurePart::FamilyDetail: a shell harmonic's n, the hoop's 2; 0
// the beam's), -1 for a field of another part (the roll, a string bed); empty when no field has one.
// *account: the energy account of the part that gives them.
static std::vector<PetscInt> FieldFamilies(const BeamSystem &op, PetscInt *account)
{
  std::vector<PetscInt> detail(op.fields, 0);
  bool                  any = false;
  for (PetscInt f = 0; f < op.fields; ++f) {
    for (const PartInstance &s : op.parts)
      if (f >= s.first && f < s.first + s.count) detail[f] = s.part->FamilyDetail(s, f);
    if (detail[f] > 0 && !any) *account = op.AccountOf(f);
    any = any || detail[f] > 0;
    if (detail[f] == 0 && op.AccountOf(f) != 0) detail[f] = -1;
  }
  return any ? detail : std::vector<PetscInt>();
}

// The family of a mode (ModesResult::shell_n): the group of fields with the largest kinetic energy
// m phi^2, the beam's (0) or a part's detail (a shell harmonic's n), groups in field order.
static PetscInt ModeFamily(const BeamSystem &op, const std::vector<PetscInt> &detail, const std::vector<PetscReal> &phi)
{
  std::vector<PetscInt> key = {0}, group(op.fields, -1); // each field's group: an index into key
  for (PetscInt f = 0; f < op.fields; ++f) {
    if (detail[f] < 0) continue;
    const size_t g = std::find(key.begin(), key.end(), detail[f]) - key.begin();
    if (g == key.size()) key.push_back(detail[f]);
    group[f] = (PetscInt)g;
  }
  std::vector<PetscReal> e(key.size(), 0.0);
  for (PetscInt d = 0; d < op.ndof; ++d)
    if (group[d % op.fields] >= 0) e[group[d % op.fields]] += op.mass[d] * phi[d] * phi[d];
  return key[std::max_element(e.begin(), e.end()) - e.begin()];
}

// The result in ascending order (the solver's, up to round-off among nearly equal modes);
// modes below kModesRigidThreshold of the frequency unit are rigid: omega, period 0.
static void ModesReport(const BeamSystem &op, const std::vector<PetscReal> &lambda,
                        std::vector<std::vector<PetscReal>> &phis, ModesResult *out,
                        std::vector<std::vector<PetscReal>> *shapes)
{
  const PetscInt        count = (PetscInt)lambda.size();
  std::vector<PetscInt> order(count);
  for (PetscInt m = 0; m < count; ++m) order[m] = m;
  std::stable_sort(order.begin(), order.end(), [&](PetscInt p, PetscInt q) { return lambda[p] < lambda[q]; });

  out->omega.assign(count, 0.0);
  out->frequency.assign(count, 0.0);
  out->period.assign(count, 0.0);
  out->rigid_count = 0;
  if (shapes) shapes->resize(count);
  const std::vector<PetscInt> families = FieldFamilies(op, &out->detail_account); // a wall's harmonics: families
  const bool                  wall = !families.empty(), parts = op.RollField() >= 0 || !op.face_fields.empty();
  if (wall) out->shell_n.assign(count, 0);
  if (parts) out->part.assign(count, 0), out->part_share.assign(count, 0.0);
  if (parts && shapes && !op.face_fields.empty()) out->bed_shape.resize(count);
  for (PetscInt m = 0; m < count; ++m) {
    const std::vector<PetscReal> &phi = phis[order[m]];
    if (wall) out->shell_n[m] = ModeFamily(op, families, phi);
    if (parts) {
      std::vector<PetscReal> e(op.ndof);
      for (PetscInt d = 0; d < op.ndof; ++d) e[d] = op.mass[d] * phi[d] * phi[d];
      out->part[m] = BeamSystemDominantAccount(op, nullptr, e.data(), op.ndof, &out->part_share[m]);
      if (!out->bed_shape.empty()) {
        const std::vector<PetscInt> &face = op.face_fields; // the bed's [z][x], its columns the nodes
        out->bed_shape[m].assign(face.size() * op.nodes, 0.0);
        for (size_t j = 0; j < face.size(); ++j)
          for (PetscInt i = 0; i < op.nodes; ++i) out->bed_shape[m][j * op.nodes + i] = phi[op.Dof(i, face[j])];
      }
    }
    if (shapes) (*shapes)[m] = DeflectionField(op, std::move(phis[order[m]]));
    const PetscReal w = std::sqrt(std::max<PetscReal>(lambda[order[m]], 0.0));
    if (w < kModesRigidThreshold * op.frequency_unit) {
      ++out->rigid_count;
      continue; // reported as exactly 0, period 0
    }
    out->omega[m]     = w;
    out->frequency[m] = w / (2.0 * PETSC_PI);
    out->period[m]    = 2.0 * PETSC_PI / w;
  }
}

PetscErrorCode BeamModesCompute(MPI_Comm comm, const BeamSystem &op, PetscInt count, ModesResult *out,
                                std::vector<std::vector<PetscReal>> *shapes)
{
  ModesProblem                        pb;
  EPS                                 eps;
  PetscInt                            nconv;
  std::vector<PetscReal>              lambda;
  std::vector<std::vector<PetscReal>> phis;

  PetscFunctionBeginUser;
  // The rigid-mode test and the frequencies from the strain energy leave a grip's springs out.
  PetscCheck(!op.TiedToFrame(), comm, PETSC_ERR_SUP,
             "the modes of a beam held by the hands (-grip) are not computed yet: drop -grip for -task modes");
  PetscCheck(out, comm, PETSC_ERR_ARG_NULL, "BeamModesCompute: out must not be NULL");
  PetscCheck(op.ndof >= 3 && op.frequency_unit > 0 && op.L > 0 && (PetscInt)op.mass.size() == op.ndof &&
               (PetscInt)op.held.size() == op.ndof,
             comm, PETSC_ERR_ARG_WRONG,
             "BeamModesCompute: the beam system is not built (%" PetscInt_FMT " dofs, frequency unit %g rad/s, L = %g)",
             op.ndof, (double)op.frequency_unit, (double)op.L);
  {
    BeamFactor F; // a fine grid of a statically determinate beam: the factored form, as the modal engine takes it
                  // (beam_modes.hpp)
    if (BeamModesFactoredForm(op, &F)) {
      PetscCall(BeamModesLowestFactored(comm, op, F, count, 0, &lambda, &phis));
      for (std::vector<PetscReal> &phi : phis) ModeNormalise(op, phi); // the sign convention (already mass-normalised)
      ModesReport(op, lambda, phis, out, shapes);
      out->method = "factored form";
      PetscFunctionReturn(0);
    }
  }
  PetscCall(ModesEnsureSlepc());
  PetscCall(ModesProblemAssemble(comm, op, count, &pb));
  PetscCall(ModesSolverCreate(comm, pb, count, op.frequency_unit, &eps));
  PetscCall(EPSSolve(eps));
  PetscCall(EPSGetConverged(eps, &nconv));
  PetscCheck(nconv >= count, comm, PETSC_ERR_CONV_FAILED,
             "BeamModesCompute: the eigen-solver converged %" PetscInt_FMT " of the %" PetscInt_FMT
             " modes requested by -modes_count",
             nconv, count);
  PetscCall(ModesExtract(comm, eps, op, pb, count, &lambda, &phis));
  ModesReport(op, lambda, phis, out, shapes);
  out->method = "shift-and-invert on K";
  {
    const PetscInt want = std::min(count, BeamSystemRigidCount(op));
    if (out->rigid_count < want) {
      std::string found;
      for (PetscInt m = 0; m < want; ++m) found += (m ? ", " : "") + std::to_string(out->frequency[m]);
      SETERRQ(comm, PETSC_ERR_NOT_CONVERGED,
              "the modes at N = %" PetscInt_FMT " are not resolved: the held dofs allow %" PetscInt_FMT
              " rigid mode(s) at 0 Hz, but the lowest %" PetscInt_FMT
              " found are at %s Hz (the stiffness's round-off, its largest eigenvalue ~N^4 times the fundamental's, "
              "blurs the rigid motions, rounded up to flexural modes); reduce -beam_nodes (the paper's beam is "
              "resolved up to about N = 15000)",
              op.nodes, want, want, found.c_str());
    }
  }
  PetscCall(EPSDestroy(&eps));
  PetscCall(ModesProblemDestroy(&pb));
  PetscFunctionReturn(0);
}

// Progress of a partial solve: a line every `every` seconds of wall time (0: none), checked at
// each restart of Krylov-Schur (EPSMonitor) and at each application of its operator (the
// shift-and-invert's solve, KSPSetPostSolve; the factored form's shell product), so that a
// restart that takes long (n ncv^2: 20 s and more at N = 40961) still says that it runs. The
// converged count is the solver's, capped at the modes wanted (Krylov-Schur converges more of
// its basis than it was asked for: "455 of 317" before).
struct ModesProgress {
  PetscReal every = 0, start = 0, last = 0;
  PetscInt  want  = 0;
  PetscInt  nconv = 0, restarts = 0, applications = 0; // as of the last restart; operator applications so far
  MPI_Comm  comm = MPI_COMM_NULL;                      // where to print
};

static PetscErrorCode ModesProgressTick(ModesProgress *p)
{
  const PetscReal now = MPI_Wtime();

  PetscFunctionBeginUser;
  if (p->every > 0 && now - p->last >= p->every) {
    p->last = now;
    PetscCall(PetscPrintf(p->comm,
                          "beamimpact: the beam's modes: %" PetscInt_FMT " of %" PetscInt_FMT
                          " converged after %" PetscInt_FMT " restart%s (%" PetscInt_FMT
                          " operator application%s), %.1f s\n",
                          p->nconv, p->want, p->restarts, p->restarts == 1 ? "" : "s", p->applications,
                          p->applications == 1 ? "" : "s", (double)(now - p->start)));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ModesProgressMonitor(EPS, PetscInt its, PetscInt nconv, PetscScalar *, PetscScalar *, PetscReal *,
                                           PetscInt, void *ctx)
{
  ModesProgress *p = static_cast<ModesProgress *>(ctx);

  PetscFunctionBeginUser;
  p->nconv    = std::min(nconv, p->want);
  p->restarts = its;
  PetscCall(ModesProgressTick(p));
  PetscFunctionReturn(0);
}

static PetscErrorCode ModesProgressApplied(KSP, Vec, Vec, void *ctx)
{
  ModesProgress *p = static_cast<ModesProgress *>(ctx);

  PetscFunctionBeginUser;
  p->applications++;
  PetscCall(ModesProgressTick(p));
  PetscFunctionReturn(0);
}

PetscErrorCode BeamModesLowest(MPI_Comm comm, const BeamSystem &op, PetscInt count, PetscReal progress,
                               std::vector<PetscReal> *lambda, std::vector<std::vector<PetscReal>> *phis, PetscInt mpd)
{
  ModesProblem  pb;
  EPS           eps;
  PetscInt      nconv;
  ModesProgress prog;

  PetscFunctionBeginUser;
  PetscCall(ModesEnsureSlepc());
  PetscCall(ModesProblemAssemble(comm, op, count, &pb));
  PetscCall(ModesSolverCreate(comm, pb, count, op.frequency_unit, &eps, mpd));
  prog.every = progress;
  prog.start = prog.last = MPI_Wtime();
  prog.want              = count;
  prog.comm              = comm;
  if (progress > 0) {
    ST  st;
    KSP ksp;
    PetscCall(EPSGetST(eps, &st));
    PetscCall(STGetKSP(st, &ksp));
    PetscCall(KSPSetPostSolve(ksp, ModesProgressApplied, &prog));
    PetscCall(EPSMonitorSet(eps, ModesProgressMonitor, &prog, NULL));
  }
  PetscCall(EPSSolve(eps));
  PetscCall(EPSGetConverged(eps, &nconv));
  PetscCheck(nconv >= count, comm, PETSC_ERR_CONV_FAILED,
             "the beam's modes: the eigen-solver converged %" PetscInt_FMT " of the %" PetscInt_FMT
             " lowest modes (-modal_modes, -modal_tolerance)",
             nconv, count);
  PetscCall(ModesExtract(comm, eps, op, pb, count, lambda, phis));
  PetscCall(EPSDestroy(&eps));
  PetscCall(ModesProblemDestroy(&pb));
  std::vector<PetscInt> order(count); // ascending, as the solver's up to round-off among nearly equal modes
  for (PetscInt m = 0; m < count; ++m) order[m] = m;
  std::stable_sort(order.begin(), order.end(), [&](PetscInt a, PetscInt b) { return (*lambda)[a] < (*lambda)[b]; });
  std::vector<PetscReal>              l(count);
  std::vector<std::vector<PetscReal>> v(count);
  for (PetscInt m = 0; m < count; ++m) l[m] = (*lambda)[order[m]], v[m] = std::move((*phis)[order[m]]);
  *lambda = std::move(l);
  *phis   = std::move(v);
  PetscFunctionReturn(0);
}

// The factored eigen-problem (BeamModesLowestFactored): z -> M^{1/2} K^+ M^{1/2} z on the free
// dofs, K^+ by the two banded solves of the factored form (solvers/beam_flexibility.hpp). The
// vectors are split over the communicator by rows (PETSC_DECIDE): each rank gathers z whole,
// applies the solves redundantly (O(n)) and keeps its own rows, so that SLEPc's basis and its
// orthogonalisation (O(n k^2), the cost at N = 40961) split over the ranks. On one rank, no
// gather: the arithmetic of the serial operator.
struct FactoredShell {
  const BeamFactor      *F        = nullptr;
  ModesProgress         *progress = nullptr; // a line now and then during a long solve (null: none)
  PetscMPIInt            size     = 1;
  PetscInt               rstart = 0, rend = 0; // rows owned by this rank
  VecScatter             toall = nullptr;      // z to every rank (size > 1)
  Vec                    zall  = nullptr;
  std::vector<PetscReal> f, u;
};

static PetscErrorCode FactoredShellDestroy(FactoredShell *sh)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterDestroy(&sh->toall));
  PetscCall(VecDestroy(&sh->zall));
  PetscFunctionReturn(0);
}

// The whole of a distributed vector, read-only, on every rank (x itself on one rank).
static PetscErrorCode FactoredGather(FactoredShell *sh, Vec x, const PetscScalar **a)
{
  PetscFunctionBeginUser;
  if (sh->size == 1) PetscCall(VecGetArrayRead(x, a));
  else {
    PetscCall(VecScatterBegin(sh->toall, x, sh->zall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(sh->toall, x, sh->zall, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(sh->zall, a));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode FactoredGatherEnd(FactoredShell *sh, Vec x, const PetscScalar **a)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(sh->size == 1 ? x : sh->zall, a));
  PetscFunctionReturn(0);
}

static PetscErrorCode FactoredMult(Mat A, Vec z, Vec y)
{
  FactoredShell     *sh;
  const PetscScalar *a;
  PetscScalar       *b;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &sh));
  const BeamFactor &F = *sh->F;
  PetscCall(FactoredGather(sh, z, &a));
  for (PetscInt d = 0; d < F.n; ++d) sh->f[d] = std::sqrt(F.mass[d]) * PetscRealPart(a[d]);
  PetscCall(FactoredGatherEnd(sh, z, &a));
  BeamFactorFlexibility(F, sh->f.data(), sh->u.data(), nullptr);
  PetscCall(VecGetArray(y, &b));
  for (PetscInt d = sh->rstart; d < sh->rend; ++d) b[d - sh->rstart] = std::sqrt(F.mass[d]) * sh->u[d];
  PetscCall(VecRestoreArray(y, &b));
  if (sh->progress) PetscCall(ModesProgressApplied(nullptr, nullptr, nullptr, sh->progress));
  PetscFunctionReturn(0);
}

// The flexible modes' vectors z_k (orthonormal, ascending in omega) of the solved EPS as modes
// over all dofs (phi = M^{-1/2} z: mass-normalised), gathered whole on every rank, each lambda
// the Rayleigh quotient of the strain energy.
static PetscErrorCode FactoredExtract(EPS eps, Mat A, const BeamSystem &op, PetscInt nflex,
                                      std::vector<PetscReal> *lambda, std::vector<std::vector<PetscReal>> *phis)
{
  FactoredShell *sh;
  Vec            x;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &sh));
  const BeamFactor &F = *sh->F;
  PetscCall(MatCreateVecs(A, &x, NULL));
  for (PetscInt k = 0; k < nflex; ++k) {
    PetscScalar            kr;
    const PetscScalar     *a;
    std::vector<PetscReal> phi(op.ndof, 0.0);
    PetscCall(EPSGetEigenpair(eps, k, &kr, NULL, x, NULL));
    PetscCall(FactoredGather(sh, x, &a));
    for (PetscInt d = 0; d < F.n; ++d) phi[F.dof[d]] = PetscRealPart(a[d]) / std::sqrt(F.mass[d]);
    PetscCall(FactoredGatherEnd(sh, x, &a));
    const PetscReal l = 2.0 * BeamSystemStrainEnergy(op, phi.data(), op.fields, 0, op.ndof); // phi^T M phi = 1
    PetscCall(PetscInfo(eps,
                        "factored mode %" PetscInt_FMT ": solver omega^2 = %.16e, Rayleigh quotient %.16e (rad/s)^2\n",
                        k, 1.0 / (double)PetscRealPart(kr), (double)l));
    lambda->push_back(l);
    phis->push_back(std::move(phi));
  }
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

// The operator of the factored form on comm (FactoredShell), its rows split by PETSC_DECIDE.
static PetscErrorCode FactoredShellCreate(MPI_Comm comm, FactoredShell *sh, Mat *A)
{
  Vec x;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &sh->size));
  sh->f.assign(sh->F->n, 0.0);
  sh->u.assign(sh->F->n, 0.0);
  PetscCall(MatCreateShell(comm, PETSC_DECIDE, PETSC_DECIDE, sh->F->n, sh->F->n, (void *)sh, A));
  PetscCall(MatShellSetOperation(*A, MATOP_MULT, (void (*)(void))FactoredMult));
  PetscCall(MatSetOption(*A, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetUp(*A));
  PetscCall(MatGetOwnershipRange(*A, &sh->rstart, &sh->rend));
  if (sh->size > 1) {
    PetscCall(MatCreateVecs(*A, &x, NULL));
    PetscCall(VecScatterCreateToAll(x, &sh->toall, &sh->zall));
    PetscCall(VecDestroy(&x));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BeamModesLowestFactored(MPI_Comm comm, const BeamSystem &op, const BeamFactor &F, PetscInt count,
                                       PetscReal progress, std::vector<PetscReal> *lambda,
                                       std::vector<std::vector<PetscReal>> *phis)
{
  const PetscInt nrigid = (PetscInt)F.rigid.size(), nflex = std::min(count, F.n) - nrigid;
  Mat            A;
  FactoredShell  sh;
  EPS            eps;
  Vec            x0;
  PetscScalar   *a;
  PetscInt       nconv;
  ModesProgress  prog;

  PetscFunctionBeginUser;
  lambda->clear();
  phis->clear();
  for (PetscInt i = 0; i < nrigid && i < count; ++i) { // the exact rigid modes, omega = 0
    std::vector<PetscReal> phi(op.ndof, 0.0);
    for (PetscInt d = 0; d < F.n; ++d) phi[F.dof[d]] = F.rigid[i][d];
    lambda->push_back(0.0);
    phis->push_back(std::move(phi));
  }
  if (nflex <= 0) PetscFunctionReturn(0);
  PetscCall(ModesEnsureSlepc());
  sh.F = &F;
  PetscCall(FactoredShellCreate(comm, &sh, &A));
  PetscCall(EPSCreate(comm, &eps));
  PetscCall(EPSSetOperators(eps, A, NULL));
  PetscCall(EPSSetProblemType(eps, EPS_HEP));
  PetscCall(EPSSetType(eps, EPSKRYLOVSCHUR));
  PetscCall(EPSSetDimensions(eps, nflex, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSetWhichEigenpairs(eps, EPS_LARGEST_REAL));
  PetscCall(EPSSetTolerances(eps, 1e-12, 1000));
  PetscCall(MatCreateVecs(A, &x0, NULL));
  PetscCall(VecGetArray(x0, &a));
  for (PetscInt d = sh.rstart; d < sh.rend; ++d)
    a[d - sh.rstart] = 1.0 + 0.5 * HashUniform(d); // the same whatever the number of ranks
  PetscCall(VecRestoreArray(x0, &a));
  PetscCall(EPSSetInitialSpace(eps, 1, &x0));
  PetscCall(VecDestroy(&x0));
  prog.every = progress;
  prog.start = prog.last = MPI_Wtime();
  prog.want              = nflex;
  prog.comm              = comm;
  if (progress > 0) {
    sh.progress = &prog;
    PetscCall(EPSMonitorSet(eps, ModesProgressMonitor, &prog, NULL));
  }
  PetscCall(EPSSolve(eps));
  PetscCall(EPSGetConverged(eps, &nconv));
  if (nconv < nflex) { // freed before the error: a sweep carries on to its next point
    PetscCall(EPSDestroy(&eps));
    PetscCall(MatDestroy(&A));
    PetscCall(FactoredShellDestroy(&sh));
    SETERRQ(comm, PETSC_ERR_CONV_FAILED,
            "the beam's modes (factored form): the eigen-solver converged %" PetscInt_FMT " of the %" PetscInt_FMT
            " lowest flexible modes (-modal_modes, -modal_tolerance)",
            nconv, nflex);
  }
  PetscCall(FactoredExtract(eps, A, op, nflex, lambda, phis));
  PetscCall(EPSDestroy(&eps));
  PetscCall(MatDestroy(&A));
  PetscCall(FactoredShellDestroy(&sh));
  std::vector<PetscInt> order(
    nflex); // ascending in the Rayleigh quotient, as the solver's (descending 1/omega^2) up to round-off
  for (PetscInt k = 0; k < nflex; ++k) order[k] = nrigid + k;
  std::stable_sort(order.begin(), order.end(), [&](PetscInt p, PetscInt q) { return (*lambda)[p] < (*lambda)[q]; });
  std::vector<PetscReal>              l(lambda->begin(), lambda->begin() + nrigid);
  std::vector<std::vector<PetscReal>> v(phis->begin(), phis->begin() + nrigid);
  for (PetscInt k : order) l.push_back((*lambda)[k]), v.push_back(std::move((*phis)[k]));
  *lambda = std::move(l);
  *phis   = std::move(v);
  PetscFunctionReturn(0);
}

std::vector<PetscReal> ModeNodes(const std::vector<PetscReal> &w, PetscReal h)
{
  std::vector<PetscReal> x;
  for (size_t i = 0; i + 1 < w.size(); ++i) {
    if (w[i] == 0.0 && i > 0 && w[i - 1] * w[i + 1] < 0) x.push_back(h * i); // a node on a grid node
    if (w[i] * w[i + 1] < 0) x.push_back(h * (i + w[i] / (w[i] - w[i + 1])));
  }
  return x;
}

PetscInt BeamSystemRigidCount(const BeamSystem &op) { return (PetscInt)BeamSystemRigidMotions(op).size(); }

PetscInt BeamModesRigidCount(Support left, Support right) { return SupportRigidModes(left, right); }

namespace {

// The characteristic equations of a uniform beam, in a form bounded for large x.
enum class BetaEquation {
  CosCoshPlusOne,
  CosCoshMinusOne,
  TanTanh,
  Sin
};

// f(x) and f'(x) for the equation (divided by cosh x where cosh appears).
void BetaEquationEval(BetaEquation e, PetscReal x, PetscReal *f, PetscReal *df)
{
  const PetscReal s = std::sin(x), c = std::cos(x), t = std::tanh(x), sech = 1.0 / std::cosh(x);
  switch (e) {
  case BetaEquation::CosCoshMinusOne: // cos x cosh x = 1  ->  cos x - sech x = 0
    *f  = c - sech;
    *df = -s + sech * t;
    break;
  case BetaEquation::CosCoshPlusOne: // cos x cosh x = -1 ->  cos x + sech x = 0
    *f  = c + sech;
    *df = -s - sech * t;
    break;
  case BetaEquation::TanTanh: // tan x = tanh x -> sin x - cos x tanh x = 0
    *f  = s - c * t;
    *df = c + s * t - c * sech * sech;
    break;
  case BetaEquation::Sin:
    *f  = s;
    *df = c;
    break;
  }
}

} // namespace

PetscErrorCode BeamModesAnalytic(Support left, Support right, PetscReal L, PetscReal EI, PetscReal mu,
                                 PetscInt n_flexural, std::vector<PetscReal> *omega)
{
  // the beta_n L tables of docs/model.md, n = 1, 2, ...
  static const PetscReal free_free[]    = {4.73004, 7.85320, 10.99561, 14.13717};
  static const PetscReal clamped_free[] = {1.87510, 4.69409, 7.85476, 10.99554};
  static const PetscReal pinned_free[]  = {3.92660, 7.06858, 10.21018};

  PetscFunctionBeginUser;
  PetscCheck(omega, PETSC_COMM_SELF, PETSC_ERR_ARG_NULL, "BeamModesAnalytic: omega must not be NULL");
  PetscCheck(L > 0 && EI > 0 && mu > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "BeamModesAnalytic: need L > 0 (m), EI > 0 (N m^2), mu > 0 (kg/m); got L = %g, EI = %g, mu = %g",
             (double)L, (double)EI, (double)mu);
  PetscCheck(n_flexural >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "BeamModesAnalytic: n_flexural = %" PetscInt_FMT " is not allowed: it must be >= 0", n_flexural);

  const auto is = [&](Support a, Support b) {
    return (left == a && right == b) || (left == b && right == a);
  }; // either order
  const PetscReal *table  = nullptr;
  PetscInt         ntable = 0;
  BetaEquation     eq     = BetaEquation::Sin;
  PetscReal        asym_a = 1.0, asym_b = 0.0; // asymptote beta_n L = (asym_a n + asym_b) pi
  if (is(Support::Free, Support::Free) || is(Support::Clamped, Support::Clamped)) {
    table  = free_free;
    ntable = 4;
    eq     = BetaEquation::CosCoshMinusOne;
    asym_a = 1.0, asym_b = 0.5; // (2n+1) pi/2
  } else if (is(Support::Free, Support::Clamped)) {
    table  = clamped_free;
    ntable = 4;
    eq     = BetaEquation::CosCoshPlusOne;
    asym_a = 1.0, asym_b = -0.5; // (2n-1) pi/2
  } else if (is(Support::Free, Support::Pinned) || is(Support::Clamped, Support::Pinned)) {
    table  = pinned_free;
    ntable = 3;
    eq     = BetaEquation::TanTanh;
    asym_a = 1.0, asym_b = 0.25; // (4n+1) pi/4
  } else if (is(Support::Pinned, Support::Pinned)) {
    eq     = BetaEquation::Sin;
    asym_a = 1.0, asym_b = 0.0; // n pi, exact
  } else {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "BeamModesAnalytic: no beta-L reference for supports %s-%s",
            SupportName(left), SupportName(right));
  }

  const PetscReal unit = std::sqrt(EI / mu) / (L * L);
  omega->assign(n_flexural, 0.0);
  for (PetscInt n = 1; n <= n_flexural; ++n) {
    const PetscReal guess = n <= ntable ? table[n - 1] : (asym_a * n + asym_b) * PETSC_PI;
    PetscReal       x     = guess;
    for (int it = 0; it < 50; ++it) {
      PetscReal f, df;
      BetaEquationEval(eq, x, &f, &df);
      const PetscReal dx = f / df;
      x -= dx;
      if (std::abs(dx) <= 4 * PETSC_MACHINE_EPSILON * x) break;
    }
    PetscCheck(std::abs(x - guess) < 1e-3 * guess, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "BeamModesAnalytic: Newton left the root near beta L = %g (mode %" PetscInt_FMT ")", (double)guess, n);
    (*omega)[n - 1] = x * x * unit;
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

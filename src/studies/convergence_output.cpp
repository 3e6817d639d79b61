// -task convergence, the output: the HDF5 file and the printed tables. See convergence_output.hpp.
#include "studies/convergence_output.hpp"

#include "io/h5_dims.hpp"
#include "io/results_h5.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace beamimpact {

namespace {
const PetscReal NaN = std::numeric_limits<PetscReal>::quiet_NaN();
} // namespace

const std::vector<ConvergenceRunColumn> &ConvergenceRunColumns()
{
  using C                                              = const ConvergenceConfig &;
  using R                                              = const ConvergenceRun &;
  static const std::vector<ConvergenceRunColumn> table = {
    {"level", "1", "the level of the sequence, from 0 (the largest step or loosest tolerance)", true,
     [](C, R r) -> double { return (double)r.level; }},
    {"dt", "s (tol runs: initial step)", "the fixed step (a tolerance sequence: the initial step)", false,
     [](C, R r) -> double { return r.dt; }},
    {"rtol", "1", "the relative tolerance (a tolerance sequence)", false, [](C, R r) -> double { return r.rtol; }},
    {"atol", "m or m/s (the state's displacements and velocities)", "the absolute tolerance (a tolerance sequence)",
     false, [](C, R r) -> double { return r.atol; }},
    {"mean_step", "s", "simulated time / accepted steps", false, [](C, R r) -> double { return r.mean_step; }},
    {"step", "s (dt, or mean_step for tol runs)", "the step the orders are measured against", false,
     [](C cfg, R r) -> double { return r.failed ? NaN : ConvergenceStepOf(cfg, r); }},
    {"failed", "1 (1: the level failed)", "1 if the level's run failed (its numbers NaN)", true,
     [](C, R r) -> double { return r.failed ? 1 : 0; }},
    {"acor", "1", "the level's ACOR", false, [](C, R r) -> double { return r.failed ? NaN : r.result.acor; }},
    {"acor_error", "1 (absolute)", "|acor - the reference's acor|", false,
     [](C, R r) -> double { return r.acor_error; }},
    {"contact_time_error", "1 (relative)", "the contact time's error against the reference", false,
     [](C, R r) -> double { return r.contact_time_error; }},
    {"peak_force_error", "1 (relative)", "the peak force's error against the reference", false,
     [](C, R r) -> double { return r.peak_force_error; }},
    {"max_compression_error", "1 (relative)", "the maximum compression's error against the reference", false,
     [](C, R r) -> double { return r.max_compression_error; }},
    {"energy_error", "1 (|E_end - E_0| / E_0)", "the run's own energy balance", false,
     [](C, R r) -> double { return r.energy_error; }},
    {"exit_speed_error", "1 (relative; NaN unless oblique)", "the batted ball's speed against the reference", false,
     [](C, R r) -> double { return r.exit_speed_error; }},
    {"launch_angle_error", "deg (absolute; NaN unless oblique)", "the launch angle against the reference", false,
     [](C, R r) -> double { return r.launch_angle_error; }},
    {"spin_error", "1 (relative; NaN unless oblique)", "the batted ball's spin against the reference", false,
     [](C, R r) -> double { return r.spin_error; }},
    {"contacts", "1", "separate contacts", true, [](C, R r) -> double { return (double)r.result.contacts; }},
    {"wall_time", "s, minimum of the repeats", "wall-clock time of the time stepping, the least of the repeats", false,
     [](C, R r) -> double { return r.failed ? NaN : r.result.wall_time; }},
    {"wall_time_max", "s, maximum of the repeats", "the same, the largest of the repeats", false,
     [](C, R r) -> double { return r.failed ? NaN : r.wall_time_max; }},
    {"steps", "1", "accepted steps", true, [](C, R r) -> double { return (double)r.result.steps; }},
    {"rejected_steps", "1", "steps rejected by the error controller", true,
     [](C, R r) -> double { return (double)r.result.rejected_steps; }},
    {"event_steps", "1", "extra steps to locate events", true,
     [](C, R r) -> double { return (double)r.result.event_steps; }},
    {"function_evals", "1", "residual evaluations", true,
     [](C, R r) -> double { return (double)r.result.function_evals; }},
    {"jacobian_evals", "1", "Jacobian requests", true,
     [](C, R r) -> double { return (double)r.result.jacobian_evals; }},
    {"jacobian_assemblies", "1", "Jacobian re-assemblies", true,
     [](C, R r) -> double { return (double)r.result.jacobian_assemblies; }},
    {"nonlinear_its", "1", "Newton iterations", true, [](C, R r) -> double { return (double)r.result.nonlinear_its; }},
    {"linear_its", "1 (linear solves; preonly LU: one per solve)", "Krylov iterations", true,
     [](C, R r) -> double { return (double)r.result.linear_its; }},
  };
  return table;
}

namespace {

// ---------------------------------------------------------------------------
// The HDF5 file
// ---------------------------------------------------------------------------

// /reference: the reference's outcome and its estimated error (attributes).
PetscErrorCode WriteReference(hid_t file, const ConvergenceReference &ref)
{
  RunRecord           r;
  const ImpactResult &R = ref.result;

  PetscFunctionBeginUser;
  r.add("method", ref.method);
  for (const char *name : {"acor", "acor_corrected", "contact_time", "peak_force", "max_compression", "contacts",
                           "final_time", "energy_error"})
    for (const ResultColumn &c : ImpactResultColumns()) // the outcome as the result table has it
      if (std::strcmp(c.name, name) == 0) r.add(name, c.Get(R));
  r.add("acor_error_estimate", ref.acor_error);
  r.add("contact_time_error_estimate", ref.contact_time_error);
  r.add("peak_force_error_estimate", ref.peak_force_error);
  r.add("observed_order", ref.observed_order);
  r.add("wall_time", ref.wall_time);
  hid_t g = H5Gcreate2(file, "reference", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCall(H5WriteAttributes(g, r));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// One column per quantity of a configuration's runs, one row per level.
PetscErrorCode WriteConfigRuns(hid_t g, const ConvergenceConfig &cfg, const std::vector<ConvergenceRun> &runs)
{
  PetscFunctionBeginUser;
  for (const ConvergenceRunColumn &c : ConvergenceRunColumns()) {
    if (c.integer) {
      std::vector<long long> v;
      for (const ConvergenceRun &r : runs) v.push_back((long long)c.get(cfg, r));
      PetscCall(H5WriteDatasetInt1D(g, c.name, v, c.unit));
    } else {
      std::vector<double> v;
      for (const ConvergenceRun &r : runs) v.push_back(c.get(cfg, r));
      PetscCall(H5WriteDataset1D(g, c.name, v, c.unit));
    }
  }
  PetscFunctionReturn(0);
}

// /configs/<name>: the configuration (attributes), its runs and its observed orders.
PetscErrorCode WriteConfig(hid_t gc, size_t index, const ConvergenceConfig &cfg,
                           const std::vector<ConvergenceRun> &runs, PetscReal error_floor)
{
  RunRecord a;

  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(gc, cfg.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create group /configs/%s", cfg.name.c_str());
  a.add("index", index);
  a.add("file", cfg.file);
  a.add("description", cfg.description);
  a.add("method", cfg.method);
  a.add("options", cfg.options);
  a.add("sequence", ConvergenceSequenceName(cfg.seq.kind));
  a.add("sequence_first", cfg.seq.first);
  a.add("sequence_divisor", cfg.seq.divisor);
  a.add("sequence_count", cfg.seq.count);
  a.add("expected_order", cfg.expected_order);
  a.add("atol_factor", cfg.atol_factor);
  const ConvergenceOrder oa = ConvergenceOrderOf(cfg, runs, error_floor, &ConvergenceRun::acor_error);
  const ConvergenceOrder ot = ConvergenceOrderOf(cfg, runs, error_floor, &ConvergenceRun::contact_time_error);
  const ConvergenceOrder op = ConvergenceOrderOf(cfg, runs, error_floor, &ConvergenceRun::peak_force_error);
  a.add("order_acor_lsq", oa.lsq);
  a.add("order_contact_time_lsq", ot.lsq);
  a.add("order_peak_force_lsq", op.lsq);
  for (auto q : {std::make_pair("order_exit_speed_lsq", &ConvergenceRun::exit_speed_error),
                 std::make_pair("order_launch_angle_lsq", &ConvergenceRun::launch_angle_error),
                 std::make_pair("order_spin_lsq", &ConvergenceRun::spin_error)})
    a.add(q.first, ConvergenceOrderOf(cfg, runs, error_floor, q.second).lsq); // NaN unless oblique
  PetscCall(H5WriteAttributes(g, a));
  PetscCall(WriteConfigRuns(g, cfg, runs));
  PetscCall(H5WriteDataset1D(g, "order_acor_pairwise", oa.pairwise, "1 (between level k-1 and k)"));
  PetscCall(H5WriteDataset1D(g, "order_contact_time_pairwise", ot.pairwise, "1 (between level k-1 and k)"));
  PetscCall(H5WriteDataset1D(g, "order_peak_force_pairwise", op.pairwise, "1 (between level k-1 and k)"));
  PetscCall(H5DimsTable(g, "level"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// /spatial: the reference at each N, the Richardson orders and the continuum limit.
PetscErrorCode WriteSpatial(hid_t file, const ConvergencePlan &plan, const ConvergenceSpatial &sp)
{
  RunRecord a;

  PetscFunctionBeginUser;
  hid_t                  g = H5Gcreate2(file, "spatial", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<long long> nodes(sp.nodes.begin(), sp.nodes.end());
  PetscCall(H5WriteDatasetInt1D(g, "nodes", nodes, "1"));
  PetscCall(H5WriteDataset1D(g, "h", sp.h, "m"));
  PetscCall(H5WriteDataset1D(g, "acor", sp.acor, "1"));
  PetscCall(H5WriteDataset1D(g, "contact_time", sp.contact_time, "s"));
  PetscCall(H5WriteDataset1D(g, "peak_force", sp.peak_force, "N"));
  PetscCall(H5WriteDataset1D(g, "acor_order", sp.acor_order, "1 (Richardson, from the three levels ending here)"));
  PetscCall(H5WriteDataset1D(g, "contact_time_order", sp.contact_time_order,
                             "1 (Richardson, from the three levels ending here)"));
  PetscCall(
    H5WriteDataset1D(g, "peak_force_order", sp.peak_force_order, "1 (Richardson, from the three levels ending here)"));
  a.add("acor_limit", sp.acor_limit);
  a.add("contact_time_limit", sp.contact_time_limit);
  a.add("peak_force_limit", sp.peak_force_limit);
  a.add("acor_order_lsq", sp.acor_order_lsq);
  a.add("contact_time_order_lsq", sp.contact_time_order_lsq);
  a.add("peak_force_order_lsq", sp.peak_force_order_lsq);
  a.add("reference", ConvergenceReferenceLabel(plan));
  PetscCall(H5WriteAttributes(g, a));
  PetscCall(H5DimsTable(g, "nodes"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

std::string OrderText(const ConvergenceOrder &o)
{
  std::string s;
  for (size_t k = 1; k < o.pairwise.size(); ++k)
    s += std::isfinite(o.pairwise[k]) ? ConvergenceFormat(" %.2f", o.pairwise[k]) : std::string(" -");
  return s;
}

} // namespace

PetscErrorCode ConvergenceFileWrite(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                    const ConvergencePlan &plan, const ConvergenceReference *ref,
                                    const std::vector<std::vector<ConvergenceRun>> &all, const RunRecord &summary,
                                    const ConvergenceSpatial *sp)
{
  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileWrite(comm, path, record, [&](long long file) -> PetscErrorCode { // whole or not at all
    PetscFunctionBeginUser;
    if (ref) PetscCall(WriteReference(file, *ref));
    if (!plan.configs.empty()) {
      hid_t gc = H5Gcreate2(file, "configs", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      for (size_t c = 0; c < plan.configs.size(); ++c)
        PetscCall(WriteConfig(gc, c, plan.configs[c], all[c], plan.error_floor));
      H5Gclose(gc);
      hid_t gs = H5Gcreate2(file, "summary", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      PetscCall(H5WriteAttributes(gs, summary));
      H5Gclose(gs);
    }
    if (sp && !sp->nodes.empty()) PetscCall(WriteSpatial(file, plan, *sp));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergenceRecordBuild(const Scenario &sc, const ConvergencePlan &plan, RunRecord *record)
{
  std::string names;

  PetscFunctionBeginUser;
  PetscCall(RunRecordBuild(sc, nullptr, record));
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);
  record->add("task", "convergence");
  record->add("impact_window_effective", times.window); // = impact_window (kept for older readers)
  record->add("impact_max_time_effective", times.max_time);
  record->add("convergence_reference", ConvergenceReferenceLabel(plan));
  record->add("convergence_repeats", plan.repeats);
  record->add("convergence_repeat_budget", plan.repeat_budget);
  record->add("convergence_target", plan.target);
  record->add("convergence_error_floor", plan.error_floor);
  record->add("convergence_common_options", plan.common_file);
  for (auto &c : plan.configs) names += (names.empty() ? "" : ",") + c.name;
  record->add("configs", names);
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// The printed tables
// ---------------------------------------------------------------------------

PetscErrorCode ConvergencePrintRun(MPI_Comm comm, const ConvergenceConfig &cfg, const ConvergenceRun &run)
{
  PetscFunctionBeginUser;
  const std::string what = cfg.seq.kind == ConvergenceSequenceKind::Tolerance ? ConvergenceFormat("rtol %.2e", run.rtol)
                                                                              : ConvergenceFormat("dt %.3e", run.dt);
  if (run.failed) {
    PetscCall(PetscPrintf(comm, "  %-14s L%-2" PetscInt_FMT " %-14s FAILED: %s\n", cfg.name.c_str(), run.level,
                          what.c_str(), run.message.c_str()));
    PetscFunctionReturn(0);
  }
  const ImpactResult &r = run.result;
  PetscCall(
    PetscPrintf(comm,
                "  %-14s L%-2" PetscInt_FMT " %-14s acor_err %.2e  tc_err %.2e  pf_err %.2e  E_err %.2e  wall %.3e s  "
                "steps %" PetscInt_FMT " (+%" PetscInt_FMT " ev, %" PetscInt_FMT " rej)  fevals %" PetscInt_FMT
                "  jac %" PetscInt_FMT "/%" PetscInt_FMT "  lin %" PetscInt_FMT "\n",
                cfg.name.c_str(), run.level, what.c_str(), (double)run.acor_error, (double)run.contact_time_error,
                (double)run.peak_force_error, (double)run.energy_error, (double)r.wall_time, r.steps, r.event_steps,
                r.rejected_steps, r.function_evals, r.jacobian_evals, r.jacobian_assemblies, r.linear_its));
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergencePrintReference(MPI_Comm comm, const ConvergencePlan &plan, const ConvergenceReference &ref)
{
  const ImpactResult &R = ref.result;

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "reference (%s, %.3f s): acor %.14f  contact_time %.12e s  peak_force %.10e N  contacts "
                        "%" PetscInt_FMT "  final_time %.6e s  energy_error %.1e\n",
                        ref.method.c_str(), (double)ref.wall_time, (double)R.acor, (double)R.contact_time,
                        (double)R.peak_force, R.contacts, (double)R.final_time, (double)R.energy_error));
  if (!ReferenceMethodFind(plan.reference)->exact) // its own error, estimated
    PetscCall(PetscPrintf(comm,
                          "  its own error (Richardson over its last three levels, observed order %.2f): acor %.1e, "
                          "contact_time %.1e (rel), peak_force %.1e (rel)\n",
                          (double)ref.observed_order, (double)ref.acor_error, (double)ref.contact_time_error,
                          (double)ref.peak_force_error));
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergencePrintOrders(MPI_Comm comm, const ConvergencePlan &plan,
                                      const std::vector<std::vector<ConvergenceRun>> &all)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "\nobserved orders (against the step; tol runs: the mean step), errors > %g:\n  %-14s %-8s "
                        "%-26s %-10s %-10s %-10s\n",
                        (double)plan.error_floor, "config", "expected", "acor pairwise", "acor lsq", "t_c lsq",
                        "F_max lsq"));
  for (size_t c = 0; c < plan.configs.size(); ++c) {
    const auto &cfg = plan.configs[c];
    const auto  oa  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::acor_error);
    const auto  ot  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::contact_time_error);
    const auto  op  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::peak_force_error);
    PetscCall(PetscPrintf(comm, "  %-14s %-8s %-26s %-10.2f %-10.2f %-10.2f\n", cfg.name.c_str(),
                          cfg.expected_order > 0 ? ConvergenceFormat("%g", cfg.expected_order).c_str() : "-",
                          OrderText(oa).c_str(), (double)oa.lsq, (double)ot.lsq, (double)op.lsq));
  }
  if (all.empty() || all[0].empty() || std::isnan(all[0][0].spin_error)) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(comm,
                        "oblique impact, the batted ball (errors > %g; exit speed and spin relative, launch angle in "
                        "deg):\n  %-14s %-8s %-26s %-26s %-26s\n",
                        (double)plan.error_floor, "config", "expected", "exit_speed pairwise", "launch_angle pairwise",
                        "spin pairwise"));
  for (size_t c = 0; c < plan.configs.size(); ++c) {
    const auto &cfg = plan.configs[c];
    const auto  oe  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::exit_speed_error);
    const auto  ol  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::launch_angle_error);
    const auto  os  = ConvergenceOrderOf(cfg, all[c], plan.error_floor, &ConvergenceRun::spin_error);
    PetscCall(PetscPrintf(comm, "  %-14s %-8s %-26s %-26s %-26s\n", cfg.name.c_str(),
                          cfg.expected_order > 0 ? ConvergenceFormat("%g", cfg.expected_order).c_str() : "-",
                          OrderText(oe).c_str(), OrderText(ol).c_str(), OrderText(os).c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergencePrintCostAtTarget(MPI_Comm comm, const ConvergencePlan &plan,
                                            const std::vector<std::vector<ConvergenceRun>> &all, RunRecord *summary)
{
  PetscInt  best = -1, base = -1;
  PetscReal best_t = 0, base_t = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "\ncost at ACOR error <= %g (fastest level that reaches it; wall time = minimum of up to "
                        "%" PetscInt_FMT " runs, time stepping only):\n",
                        (double)plan.target, plan.repeats));
  for (size_t c = 0; c < plan.configs.size(); ++c) {
    const auto &cfg = plan.configs[c];
    PetscReal   t;
    PetscInt    lv = ConvergenceFastestAtTarget(all[c], plan.target, &t);
    if (lv < 0) {
      PetscCall(PetscPrintf(comm, "  %-14s does not reach it (smallest error %.2e)\n", cfg.name.c_str(),
                            (double)ConvergenceSmallestError(all[c])));
      continue;
    }
    const auto &r = all[c][lv];
    PetscCall(PetscPrintf(comm, "  %-14s %.3e s  level %" PetscInt_FMT "  %s  acor_err %.2e  steps %" PetscInt_FMT "\n",
                          cfg.name.c_str(), (double)t, lv,
                          cfg.seq.kind == ConvergenceSequenceKind::Tolerance
                            ? ConvergenceFormat("rtol %.2e", r.rtol).c_str()
                            : ConvergenceFormat("dt %.3e", r.dt).c_str(),
                          (double)r.acor_error, r.result.steps));
    summary->add("time_at_target_" + cfg.name, t);
    if (cfg.method == "leapfrog") {
      if (base < 0 || t < base_t) base = (PetscInt)c, base_t = t;
    } else if (best < 0 || t < best_t) best = (PetscInt)c, best_t = t;
  }
  summary->add("target", plan.target);
  if (best >= 0) {
    summary->add("best_config", plan.configs[best].name);
    summary->add("best_time", best_t);
  }
  if (base >= 0) {
    summary->add("baseline_config", plan.configs[base].name);
    summary->add("baseline_time", base_t);
  }
  if (best >= 0 && base >= 0) {
    summary->add("baseline_over_best", base_t / best_t);
    PetscCall(PetscPrintf(comm,
                          "best PETSc configuration at ACOR error <= %g: %s, %.3e s; baseline %s: %.3e s; "
                          "baseline/best = %.2f (best/baseline = %.2f)\n",
                          (double)plan.target, plan.configs[best].name.c_str(), (double)best_t,
                          plan.configs[base].name.c_str(), (double)base_t, (double)(base_t / best_t),
                          (double)(best_t / base_t)));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergencePrintSpatialLevel(MPI_Comm comm, PetscInt N, PetscReal h, const ConvergenceReference &ref)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm,
                        "  N %5" PetscInt_FMT
                        "  h %.4e m  acor %.12f  contact_time %.10e s  peak_force %.8e N  (%s, %.2f s)\n",
                        N, (double)h, (double)ref.result.acor, (double)ref.result.contact_time,
                        (double)ref.result.peak_force, ref.method.c_str(), (double)ref.wall_time));
  PetscFunctionReturn(0);
}

PetscErrorCode ConvergencePrintSpatial(MPI_Comm comm, const ConvergenceSpatial &sp)
{
  std::string o;

  PetscFunctionBeginUser;
  PetscCall(
    PetscPrintf(comm,
                "  continuum limit (Richardson, last three N): acor %.10f  contact_time %.8e s  peak_force %.6e N\n",
                (double)sp.acor_limit, (double)sp.contact_time_limit, (double)sp.peak_force_limit));
  for (size_t k = 2; k < sp.acor_order.size(); ++k) o += ConvergenceFormat(" %.3f", sp.acor_order[k]);
  PetscCall(PetscPrintf(comm,
                        "  observed spatial order: acor (triples)%s; least squares: acor %.3f, contact_time %.3f, "
                        "peak_force %.3f\n",
                        o.c_str(), (double)sp.acor_order_lsq, (double)sp.contact_time_order_lsq,
                        (double)sp.peak_force_order_lsq));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

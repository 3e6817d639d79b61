// The record of a run. See run_record.hpp.
#include "io/run_record.hpp"

#include "base/options_util.hpp"

#include <hdf5.h>
#include <slepcsys.h>

#include <ctime>

namespace beamimpact {

// Where and when the file was made: the task, the source's commit, the date (UTC), the host,
// the ranks and the versions of the libraries beside PETSc's.
static PetscErrorCode RunProvenance(RunRecord *rec)
{
  char        task[64] = "impact", host[256] = "", slepc[256] = "", date[64] = "";
  PetscMPIInt size;
  unsigned    maj, min, rel;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-task", task, sizeof task, NULL));
  PetscCall(PetscGetHostName(host, sizeof host));
  PetscCall(SlepcGetVersion(slepc, sizeof slepc));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  H5get_libversion(&maj, &min, &rel);
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  rec->add("task", task);
  rec->add("git", BEAMIMPACT_GIT);
  rec->add("date", date);
  rec->add("host", host);
  rec->add("ranks", size);
  rec->add("slepc_version", slepc);
  rec->add("hdf5_version", std::to_string(maj) + "." + std::to_string(min) + "." + std::to_string(rel));
  PetscFunctionReturn(0);
}

PetscErrorCode RunRecordProgram(RunRecord *rec)
{
  char        petsc_version[256];
  std::string options;

  PetscFunctionBeginUser;
  PetscCall(PetscGetVersion(petsc_version, sizeof(petsc_version)));
  PetscCall(OptionsAsString(&options));
  rec->add("program", std::string("beamimpact ") + BEAMIMPACT_VERSION);
  PetscCall(RunProvenance(rec));
  rec->add("petsc_version", petsc_version);
  rec->add("options", options);
  PetscFunctionReturn(0);
}

PetscErrorCode RunRecordBuild(const BeamParams &beam, RunRecord *rec)
{
  PetscFunctionBeginUser;
  PetscCall(RunRecordProgram(rec));
  rec->add("beam_length", beam.length);
  rec->add("beam_EI", beam.EI);
  rec->add("beam_mu", beam.mu);
  const BeamRigidBody body = BeamRigidBodyOf(beam);
  rec->add("beam_mass", body.mass);
  rec->add("beam_center_of_mass", body.x_cm);
  rec->add("beam_inertia_cm", body.inertia_cm);
  rec->add("beam_inertia_end", body.inertia_end);
  rec->add("beam_theory", beam.theory);
  rec->add("beam_section", SectionSourceName(beam.section.source));
  if (!beam.section.file.empty()) rec->add("beam_section_file", beam.section.file);
  rec->add("beam_nodes", beam.nodes);
  rec->add("beam_left", SupportName(beam.left));
  rec->add("beam_right", SupportName(beam.right));
  rec->add("beam_clamp_x0", beam.has_clamp ? beam.clamp_x0 : -1.0);
  rec->add("beam_clamp_x1", beam.has_clamp ? beam.clamp_x1 : -1.0);
  rec->add("beam_parameter_set", beam.input.parameter_set);
  rec->add("beam_youngs_modulus", beam.input.youngs_modulus);
  rec->add("beam_density", beam.input.density);
  rec->add("beam_thickness", beam.input.thickness);
  rec->add("beam_width", beam.input.width);
  rec->add("beam_youngs_over_density", beam.input.youngs_over_density);
  PetscFunctionReturn(0);
}

PetscErrorCode RunRecordBuild(const Scenario &sc, const ImpactResult *first, RunRecord *rec)
{
  const BallParams &ball = sc.ball;

  PetscFunctionBeginUser;
  PetscCall(RunRecordBuild(sc.beam, rec));
  rec->add("ball_mass", ball.mass);
  rec->add("ball_speed", ball.speed);
  rec->add("ball_law", ContactLawName(ball.law));
  if (ball.radius > 0) rec->add("ball_radius", ball.radius);
  if (ball.law == ContactLawKind::Linear) rec->add("ball_k", ball.k);
  else {
    rec->add("ball_k1", ball.k1);
    rec->add("ball_m", ball.m);
    rec->add("ball_n", ball.n);
    if (ball.cor > 0) rec->add("ball_cor", ball.cor);
    if (ball.contact_time > 0) {
      rec->add("ball_contact_time", ball.contact_time);
      rec->add("ball_test_speed", ball.test_speed);
    }
    if (!ball.cor_table.empty()) rec->add("ball_cor_table", ball.cor_table.file);
  }
  rec->add("ball_loss_factor", ball.loss_factor);
  // The values used: a derived default (-impact_window, -impact_max_time < 0) as computed.
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);
  rec->add("impact_x", sc.impact.x);
  rec->add("impact_window", times.window);
  rec->add("impact_max_time", times.max_time);
  rec->add("impact_window_default", sc.impact.window < 0 ? 1 : 0);
  rec->add("impact_max_time_default", sc.impact.max_time > 0 ? 0 : 1);
  rec->add("impact_event_tol", sc.impact.event_tol);
  rec->add("impact_max_contacts", sc.impact.max_contacts);
  // As resolved by the run: the default modal falls back to time for a beam beyond the modes' limit.
  rec->add("impact_after", first && !first->after_used.empty() ? first->after_used : std::string(ImpactAfterName(sc.impact.after)));
  if (first) {
    rec->add("ts_type", first->ts_type);
    rec->add("formulation", first->formulation);
    rec->add("dt_nominal", first->dt_nominal);
    rec->add("dt_stable", first->dt_stable);
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The record of a run. See run_record.hpp.
#include "io/run_record.hpp"

#include "base/options_util.hpp"
#include "io/options_files.hpp"
#include "io/sha256.hpp"

#include <hdf5.h>
#include <slepcsys.h>

#include <algorithm>
#include <cctype>
#include <ctime>
#include <sstream>

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

PetscErrorCode RunInputFiles(std::vector<InputFile> *files)
{
  std::string all;

  PetscFunctionBeginUser;
  files->clear();
  for (const std::string &f : OptionsFilesRead()) files->push_back({"-options_file", f, ""});
  PetscCall(OptionsAsString(&all)); // "-name value ..." (read without marking an option used)
  const std::vector<std::string> &names = OptionsFilePathOptions();
  std::istringstream              words(all);
  std::string                     w, name;
  while (words >> w) {
    if (w.size() > 1 && w[0] == '-' && !std::isdigit((unsigned char)w[1]) && w[1] != '.') {
      name = w;
      continue;
    }
    if (std::find(names.begin(), names.end(), name) == names.end()) continue;
    for (size_t a = 0;;) { // a comma-separated list (-convergence_configs)
      const size_t      b    = w.find(',', a);
      const std::string path = w.substr(a, b == std::string::npos ? std::string::npos : b - a);
      if (!path.empty()) files->push_back({name, path, ""});
      if (b == std::string::npos) break;
      a = b + 1;
    }
    name.clear();
  }
  for (InputFile &f : *files) (void)Sha256File(f.path, &f.sha256);
  PetscFunctionReturn(0);
}

std::vector<std::string> RunInputAttributeNames(const std::vector<InputFile> &files)
{
  std::vector<std::string>   out;
  std::map<std::string, int> seen;
  for (const InputFile &f : files) {
    const int k = ++seen[f.option];
    out.push_back("input_sha256_" + f.option.substr(1) + (k > 1 ? "_" + std::to_string(k) : ""));
  }
  return out;
}

// The input files' hashes (see run_record.hpp).
static PetscErrorCode RunRecordInputs(RunRecord *rec)
{
  std::vector<InputFile> files;
  std::string            lines;

  PetscFunctionBeginUser;
  PetscCall(RunInputFiles(&files));
  const std::vector<std::string> names = RunInputAttributeNames(files);
  for (size_t k = 0; k < files.size(); ++k) {
    rec->add(names[k], files[k].sha256.empty() ? std::string("unreadable") : files[k].sha256);
    lines += (lines.empty() ? "" : "\n") + files[k].option + " " + files[k].path + " " + files[k].sha256;
  }
  if (!files.empty()) rec->add("input_files", lines);
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
  PetscCall(RunRecordInputs(rec));
  rec->options_used = OptionsUsed();
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
  if (beam.has_pivot) rec->add("beam_pivot", beam.pivot_x); // m, as placed: on the nearest node
  rec->add("beam_parameter_set", beam.input.parameter_set);
  rec->add("beam_youngs_modulus", beam.input.youngs_modulus);
  rec->add("beam_density", beam.input.density);
  rec->add("beam_thickness", beam.input.thickness);
  rec->add("beam_width", beam.input.width);
  rec->add("beam_youngs_over_density", beam.input.youngs_over_density);
  for (const StructurePart *part : StructureParts()) // each registered part present: its entries
    if (const PartParams *q = beam.parts.Find(part->Name())) {
      std::vector<std::pair<const char *, PetscReal>>   entries;
      std::vector<std::pair<const char *, std::string>> words;
      std::vector<std::pair<const char *, long long>>   whole;
      part->Record(*q, beam, &entries);
      part->RecordWords(*q, beam, &words, &whole);
      for (const auto &[name, value] : entries) rec->add(name, value);
      for (const auto &[name, text] : words) rec->add(name, text);
      for (const auto &[name, n] : whole) rec->add(name, n);
    }
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
  for (const ContactLawRecord &r : ContactLawRecordOf(ball))
    r.is_text ? rec->add(r.name, r.text) : rec->add(r.name, (double)r.value); // its parameters and wall values
  rec->add("ball_loss_factor", ball.loss_factor);
  // The values used: a derived default (-impact_window, -impact_max_time < 0) as computed.
  const ImpactTimes times = ImpactTimesOf(sc.beam, sc.ball, sc.impact);
  rec->add("impact_x", sc.impact.x);
  if (sc.impact.z != 0 || StructurePartsHaveFace(sc.beam) || sc.beam.parts.Rolls()) rec->add("impact_z", sc.impact.z);
  rec->add("impact_window", times.window);
  rec->add("impact_max_time", times.max_time);
  rec->add("impact_window_default", sc.impact.window < 0 ? 1 : 0);
  rec->add("impact_max_time_default", sc.impact.max_time > 0 ? 0 : 1);
  rec->add("impact_event_tol", sc.impact.event_tol);
  rec->add("impact_max_contacts", sc.impact.max_contacts);
  // As resolved by the run: the default modal falls back to time for a beam beyond the modes' limit.
  rec->add("impact_after",
           first && !first->after_used.empty() ? first->after_used : std::string(ImpactAfterName(sc.impact.after)));
  if (first && first->modal.kept > 0) { // the modal engine the run used (docs/model.md §12): the modes kept, the
                                        // cut-off (Hz; NaN: none chose them)
    rec->add("modal_modes_kept", first->modal.kept);
    rec->add("modal_cutoff", (double)first->modal.cutoff);
  }
  if (first) {
    rec->add("ts_type", first->ts_type);
    rec->add("formulation", first->formulation);
    rec->add("dt_nominal", first->dt_nominal);
    rec->add("dt_stable", first->dt_stable);
    // The impact's scales, for studies that judge a run against them (a sweep: its probe's).
    if (first->scales.contact_time_scale > 0) {
      rec->add("contact_time_scale", first->scales.contact_time_scale);
      rec->add("compression_scale", first->scales.compression_scale);
    }
  }
  PetscFunctionReturn(0);
}

namespace {

// An attribute of loc (replaced if present): `n` values of memory type `mem` stored as `file`
// (n = -1: a scalar).
PetscErrorCode WriteAttr(hid_t loc, const std::string &name, hid_t file, hid_t mem, const void *data, hssize_t n = -1)
{
  PetscFunctionBeginUser;
  const hsize_t dims[1] = {(hsize_t)(n < 0 ? 1 : n)};
  const hid_t   space   = n < 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, NULL);
  bool          ok      = space >= 0 && (H5Aexists(loc, name.c_str()) <= 0 || H5Adelete(loc, name.c_str()) >= 0);
  const hid_t   attr    = ok ? H5Acreate2(loc, name.c_str(), file, space, H5P_DEFAULT, H5P_DEFAULT) : -1;
  ok                    = attr >= 0 && (n == 0 || H5Awrite(attr, mem, data) >= 0);
  if (attr >= 0) ok = H5Aclose(attr) >= 0 && ok;
  if (space >= 0) H5Sclose(space);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write the attribute %s", name.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode WriteText(hid_t loc, const std::string &name, const std::string &value)
{
  PetscFunctionBeginUser;
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  const PetscErrorCode ierr = WriteAttr(loc, name, type, type, value.c_str());
  H5Tclose(type);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode RunRecordWriteOptionsUsed(long long loc, const RunRecord &rec)
{
  PetscFunctionBeginUser;
  if (rec.options_used.empty()) PetscFunctionReturn(0);
  hid_t g = H5Gcreate2((hid_t)loc, "options_used", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create the group options_used");
  hid_t gu = H5Gcreate2(g, "unit", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        gg = H5Gcreate2(g, "given", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  for (const auto &kv : rec.options_used) {
    const std::string name = kv.first.substr(1); // without the dash
    const OptionUsed &u    = kv.second;
    switch (u.kind) {
    case OptionKind::Real:
      PetscCall(WriteAttr(g, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, &u.number));
      break;
    case OptionKind::Int:
    case OptionKind::Bool: {
      const long long v = (long long)u.number;
      PetscCall(WriteAttr(g, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &v));
    } break;
    case OptionKind::RealList:
      PetscCall(WriteAttr(g, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, u.list.data(), (hssize_t)u.list.size()));
      break;
    default:
      PetscCall(WriteText(g, name, u.text));
      break; // Text, Choice, File
    }
    if (!u.unit.empty()) PetscCall(WriteText(gu, name, u.unit));
    const long long given = u.given ? 1 : 0;
    PetscCall(WriteAttr(gg, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &given));
  }
  H5Gclose(gg);
  H5Gclose(gu);
  H5Gclose(g);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

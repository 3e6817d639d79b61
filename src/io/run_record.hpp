// The record kept with every results file, as root attributes: program and PETSc versions,
// the full options, every parameter of the scenario and the integrator of its first run; and
// every option value the program read (base/option_table.hpp: OptionsUsed), as used (the
// default or the value given), in the group /options_used:
//   /options_used        attribute NAME (the option without its dash): the value, a double
//                        (real), 64-bit integer (whole number; flag 0/1), string (choice, text,
//                        file) or array of doubles (list; empty when none was given);
//   /options_used/unit   attribute NAME: the unit of a number ("1": dimensionless);
//   /options_used/given  attribute NAME: 1 where the option was set, 0 for its default.
// The input files the run read (every options file, includes too, and every file an option
// names: -beam_profile, -beam_properties, -ball_cor_table, ...) by their contents:
//   input_sha256_<option>  root attribute: the SHA-256 of the file's contents (option without
//                          its dash; a second file of the same option _2, _3, ...: the
//                          options files are input_sha256_options_file, _options_file_2, ...);
//   input_files            root attribute: one line per file, "-option path sha256".
// The hashes are part of a sweep's resume signature, the paths are not: an edited table refuses
// a resume, the same table at another path resumes.
// The derived values keep their names as root attributes (beam_mass, beam_EI, ball_k,
// impact_window as used, ...); a group rather than root attributes, so that a sweep's resume
// signature (its root attributes) does not depend on options that change no number.
#pragma once

#include "base/option_table.hpp"
#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace beamimpact {

// Named numbers, whole numbers and strings, in the order they were added. Whole numbers (counts,
// ranks, flags: any integral type given to add) become HDF5 integer attributes (64-bit), the
// others double ones.
struct RunRecord {
  std::vector<std::pair<std::string, double>>      numbers;
  std::vector<std::pair<std::string, long long>>   integers;
  std::vector<std::pair<std::string, std::string>> strings;
  void                                             add(const std::string &k, double v) { numbers.emplace_back(k, v); }
  template <class T, std::enable_if_t<std::is_integral<T>::value, int> = 0>
  void add(const std::string &k, T v)
  {
    integers.emplace_back(k, (long long)v);
  }
  void                              add(const std::string &k, const std::string &v) { strings.emplace_back(k, v); }
  void                              add(const std::string &k, const char *v) { strings.emplace_back(k, v); }
  std::map<std::string, OptionUsed> options_used; // by option name with its dash; written to /options_used
};

// One input file of the run.
struct InputFile {
  std::string option; // "-beam_profile", ..., "-options_file"
  std::string path;   // as given (a path inside an options file resolved against its directory)
  std::string sha256; // of its contents; "" when it cannot be read
};

// The run's input files: the options files read (io/options_files.hpp) and the values of the
// options that name files (OptionsFilePathOptions), from the options database.
PetscErrorCode RunInputFiles(std::vector<InputFile> *files);

// The attribute name of files[k]: input_sha256_<option>[_2, _3, ...].
std::vector<std::string> RunInputAttributeNames(const std::vector<InputFile> &files);

// Program, its provenance, PETSc version and the options (a task with no beam: -task flight).
PetscErrorCode RunRecordProgram(RunRecord *rec);

// The same and the beam's parameters (a task on the beam alone).
PetscErrorCode RunRecordBuild(const BeamParams &beam, RunRecord *rec);

// The same plus the ball, the impact rules and, given a first result, its integrator and the
// impact's scales (contact_time_scale, compression_scale).
PetscErrorCode RunRecordBuild(const Scenario &sc, const ImpactResult *first, RunRecord *rec);

// Writes rec.options_used as the group options_used of loc (an HDF5 file or group id; nothing
// when the record has none). Called where the record's attributes are written.
PetscErrorCode RunRecordWriteOptionsUsed(long long loc, const RunRecord &rec);

} // namespace beamimpact

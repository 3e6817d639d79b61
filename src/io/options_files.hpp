// Options files, read as PETSc reads them (one "-name value" per line, '#' starts a
// comment, "double quotes" keep a value with spaces together, -options_file includes another
// file), with one difference that makes a scene runnable from any directory: a relative path
// written inside a file is relative to that file's directory. That holds for an include
// (-options_file) and for the value of every option that names a file (-beam_profile,
// -beam_properties, -ball_cor_table, -convergence_configs, ...: OptionsFilePathOptions()), and for
// the file of a sampled -sweep axis, NAME=csv:FILE (docs/uncertainty.md).
// Paths on the command line stay relative to the working directory, as everywhere.
//
//   options/scenes/r161-acor.opts:   -options_file ../bats/r161.opts
//   options/bats/r161.opts:          -beam_profile r161.profile
//
// main() expands every -options_file of the command line into the options it holds before
// PETSc reads the command line (OptionsArgsExpand), so PETSc sees the resolved paths; a
// private options database (a convergence configuration, a test) reads a file with
// OptionsFileInsert.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// The options whose values are file names (a comma-separated list for -convergence_configs).
const std::vector<std::string> &OptionsFilePathOptions();

// Every options file read so far (includes too), in the order first read, as opened: the run
// record keeps their SHA-256 (io/run_record.hpp), and -output may name none of them.
const std::vector<std::string> &OptionsFilesRead();

// The tokens of `file`, its includes expanded in place (recursively) and relative paths
// resolved against the directory of the file that wrote them. Returns false with `error` set
// ("-options_file X (included by F): cannot open ..." or an include cycle).
bool OptionsFileExpand(const std::string &file, std::vector<std::string> *tokens, std::string *error);

// `args` (a command line without the program name) with every "-options_file F" replaced by
// the tokens of F (OptionsFileExpand). Other arguments are kept as they are.
bool OptionsArgsExpand(const std::vector<std::string> &args, std::vector<std::string> *expanded, std::string *error);

// Inserts the options of `file` (expanded as above) into `options` (NULL: the global database).
// A file that cannot be read is an error naming it.
PetscErrorCode OptionsFileInsert(MPI_Comm comm, PetscOptions options, const std::string &file);

} // namespace beamimpact

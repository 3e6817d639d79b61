// Options files with paths relative to the file. See options_files.hpp.
#include "io/options_files.hpp"

#include "io/text.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace beamimpact {

namespace {

const int kMaxIncludeDepth = 32;

std::vector<std::string> &FilesRead()
{
  static std::vector<std::string> files;
  return files;
}

// PETSc's rule for a key: a dash followed by something that does not start a number.
bool IsKey(const std::string &t)
{
  return t.size() > 1 && t[0] == '-' && !std::isdigit((unsigned char)t[1]) && t[1] != '.';
}

// One line's tokens: whitespace-separated, '#' starts a comment, "..." is one token.
std::vector<std::string> LineTokens(const std::string &line)
{
  std::vector<std::string> out;
  size_t                   i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace((unsigned char)line[i])) ++i;
    if (i >= line.size() || line[i] == '#') break;
    std::string t;
    if (line[i] == '"') {
      const size_t close = line.find('"', i + 1);
      t                  = line.substr(i + 1, (close == std::string::npos ? line.size() : close) - i - 1);
      i                  = close == std::string::npos ? line.size() : close + 1;
    } else {
      while (i < line.size() && !std::isspace((unsigned char)line[i]) && line[i] != '#') t += line[i++];
    }
    out.push_back(t);
  }
  return out;
}

// `path` as written in a file in directory `dir`: relative to that directory.
std::string Resolve(const std::string &dir, const std::string &path)
{
  if (path.empty() || dir.empty() || path[0] == '/') return path;
  return (std::filesystem::path(dir) / path).lexically_normal().string();
}

std::string ResolveList(const std::string &dir, const std::string &list)
{
  std::string out;
  size_t      a = 0;
  while (true) {
    const size_t b = list.find(',', a);
    out += Resolve(dir, list.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    out += ',';
    a = b + 1;
  }
  return out;
}

// -sweep's sampled axes NAME=csv:FILE[:COLUMN]: FILE relative to the options file's directory.
std::string ResolveSweepFiles(const std::string &dir, const std::string &sweep)
{
  std::string out = sweep;
  for (size_t at = out.find("=csv:"); at != std::string::npos; at = out.find("=csv:", at + 5)) {
    const size_t      a = at + 5, b = std::min(out.find_first_of(":,", a), out.size());
    const std::string path = Resolve(dir, out.substr(a, b - a));
    out.replace(a, b - a, path);
    at = a + path.size() - 5;
  }
  return out;
}

bool Expand(const std::string &file, const std::string &includer, int depth, std::vector<std::string> *tokens,
            std::string *error)
{
  const std::string by = includer.empty() ? "" : " (included by " + includer + ")";
  if (depth > kMaxIncludeDepth) {
    *error = "-options_file " + file + by + ": includes nested deeper than " + std::to_string(kMaxIncludeDepth) +
             " files (a file that includes itself?)";
    return false;
  }
  std::ifstream in(file);
  if (!in) {
    *error = "-options_file " + file + by + ": cannot open the file (" + std::strerror(errno) + ")" +
             (includer.empty() ? "; a path on the command line is relative to the working directory"
                               : "; a path inside an options file is relative to that file's directory");
    return false;
  }
  if (std::find(FilesRead().begin(), FilesRead().end(), file) == FilesRead().end()) FilesRead().push_back(file);
  const std::string               dir   = std::filesystem::path(file).parent_path().string();
  const std::vector<std::string> &paths = OptionsFilePathOptions();
  std::vector<std::string>        lines;
  std::string                     why;
  if (!TextLines(in, &lines, &why)) { // a UTF-8 byte order mark skipped, CR line ends read
    *error = "-options_file " + file + by + ": " + why;
    return false;
  }
  for (size_t lineno = 1; lineno <= lines.size(); ++lineno) {
    const std::string &line  = lines[lineno - 1];
    const std::string  where = file + ":" + std::to_string(lineno);
    if (line.find('\0') != std::string::npos) { // binary data: a message would stop at the NUL
      *error = where + ": the line holds a NUL byte (binary data?): an options file is plain text";
      return false;
    }
    const std::vector<std::string> t = LineTokens(line);
    if (t.empty()) continue;
    // One option per line, as PETSc reads an options file: a stray word would otherwise be
    // dropped without a word by the command-line parser.
    if (t[0] == "alias") *error = where + ": 'alias' lines are not supported; write the option's own name";
    else if (!IsKey(t[0]))
      *error = where + ": '" + t[0] + "' is not an option (an option starts with '-': -" + t[0] + "?)";
    else if (t.size() > 2)
      *error = where + ": " + t[0] + " has more than one value ('" + t[1] + "', '" + t[2] +
               "'): one option and its value per line";
    else if (t[0] == "-options_file" && t.size() < 2) *error = where + ": -options_file needs a file name";
    if (!error->empty()) return false;
    if (t[0] == "-options_file") {
      if (!Expand(Resolve(dir, t[1]), where, depth + 1, tokens, error)) return false;
      continue;
    }
    tokens->push_back(t[0]);
    if (t.size() == 2)
      tokens->push_back(std::find(paths.begin(), paths.end(), t[0]) != paths.end() ? ResolveList(dir, t[1])
                        : t[0] == "-sweep"                                         ? ResolveSweepFiles(dir, t[1])
                                                                                   : t[1]);
  }
  return true;
}

} // namespace

const std::vector<std::string> &OptionsFilePathOptions()
{
  static const std::vector<std::string> names = {"-beam_profile",
                                                 "-beam_properties",
                                                 "-ball_cor_table",
                                                 "-convergence_configs",
                                                 "-convergence_reference_config",
                                                 "-convergence_common_options",
                                                 "-fit_data"};
  return names;
}

const std::vector<std::string> &OptionsFilesRead() { return FilesRead(); }

bool OptionsFileExpand(const std::string &file, std::vector<std::string> *tokens, std::string *error)
{
  return Expand(file, "", 0, tokens, error);
}

bool OptionsArgsExpand(const std::vector<std::string> &args, std::vector<std::string> *expanded, std::string *error)
{
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-options_file") {
      if (i + 1 >= args.size() || IsKey(args[i + 1])) {
        *error = "-options_file needs a file name";
        return false;
      }
      if (!OptionsFileExpand(args[++i], expanded, error)) return false;
    } else expanded->push_back(args[i]);
  }
  return true;
}

PetscErrorCode OptionsFileInsert(MPI_Comm comm, PetscOptions options, const std::string &file)
{
  std::vector<std::string> tokens;
  std::string              error, text;

  PetscFunctionBeginUser;
  PetscCheck(OptionsFileExpand(file, &tokens, &error), comm, PETSC_ERR_FILE_OPEN, "%s", error.c_str());
  for (const std::string &t : tokens) {
    const bool quote = t.empty() || t.find_first_of(" \t") != std::string::npos;
    text += (text.empty() ? "" : " ") + (quote ? "\"" + t + "\"" : t);
  }
  PetscCall(PetscOptionsInsertString(options, text.c_str()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

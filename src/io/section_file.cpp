// Reading section files. See section_file.hpp.
#include "io/section_file.hpp"

#include "io/text.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace beamimpact {

namespace {

// The numeric rows of a file: each row's numbers and its line number. Returns false with
// *why on a missing file, a word that is not a number, or no rows at all.
bool NumberRows(const std::string &path, std::vector<std::vector<double>> *rows, std::vector<int> *lines,
                std::string *why)
{
  std::ifstream in(path);
  if (!in) {
    *why = path + ": cannot open the file (" + std::strerror(errno) + ")";
    return false;
  }
  std::vector<std::string> text;
  if (!TextLines(in, &text, why)) { // a UTF-8 byte order mark skipped, CR line ends read
    *why = path + ": " + *why;
    return false;
  }
  for (int no = 1; no <= (int)text.size(); ++no) {
    std::string line = text[no - 1];
    if (line.find('\0') != std::string::npos) { // binary data: the text would stop at the NUL
      *why = path + ":" + std::to_string(no) +
             ": the line holds a NUL byte (binary data?): a section file is plain text";
      return false;
    }
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream  words(line);
    std::string         w;
    std::vector<double> row;
    while (words >> w) {
      char        *end = nullptr;
      const double v   = std::strtod(w.c_str(), &end);
      if (end == w.c_str() || *end != '\0') {
        *why = path + ":" + std::to_string(no) + ": '" + w + "' is not a number";
        return false;
      }
      if (!std::isfinite(v)) {
        *why = path + ":" + std::to_string(no) + ": '" + w + "' is not a finite number";
        return false;
      }
      row.push_back(v);
    }
    if (row.empty()) continue;
    rows->push_back(row);
    lines->push_back(no);
  }
  if (rows->size() < 2) {
    *why = path + (rows->empty() ? ": the file has no rows"
                                 : ": the file has one row; a beam needs at least two (its two ends)");
    return false;
  }
  return true;
}

std::string At(const std::string &path, int line) { return path + ":" + std::to_string(line) + ": "; }

std::string Num(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

} // namespace

bool ProfileFileRead(const std::string &path, std::vector<ProfileRow> *out, std::string *why)
{
  std::vector<std::vector<double>> rows;
  std::vector<int>                 lines;
  if (!NumberRows(path, &rows, &lines, why)) return false;
  out->clear();
  for (size_t r = 0; r < rows.size(); ++r) {
    const std::vector<double> &v = rows[r];
    if (v.size() < 2 || v.size() > 3) {
      *why = At(path, lines[r]) + "a profile row is 'x D' or 'x D d' (m); this row has " + std::to_string(v.size()) +
             " numbers";
      return false;
    }
    ProfileRow p;
    p.x = v[0], p.D = v[1], p.d = v.size() == 3 ? v[2] : 0.0;
    p.line = lines[r];
    if (!(p.D > 0)) {
      *why = At(path, lines[r]) + "outer diameter D = " + Num(p.D) + " is not allowed: it must be > 0 (m)";
      return false;
    }
    if (!(p.d >= 0 && p.d < p.D)) {
      *why = At(path, lines[r]) + "inner diameter d = " + Num(p.d) + " is not allowed: need 0 <= d < D = " + Num(p.D) +
             " (m)";
      return false;
    }
    if (!out->empty() && !(p.x > out->back().x)) {
      *why = At(path, lines[r]) + "x = " + Num(p.x) +
             " does not increase (the row before has x = " + Num(out->back().x) +
             "): rows go from one end to the other";
      return false;
    }
    out->push_back(p);
  }
  return true;
}

bool PropertiesFileRead(const std::string &path, std::vector<PropertiesRow> *out, bool *has_shear, bool *has_torsion,
                        std::string *why)
{
  std::vector<std::vector<double>> rows;
  std::vector<int>                 lines;
  if (!NumberRows(path, &rows, &lines, why)) return false;
  out->clear();
  const size_t cols                = rows[0].size();
  *has_shear                       = cols >= 5;
  *has_torsion                     = cols == 7;
  static const char *const names[] = {"x", "EI", "mu", "kappaGA", "rhoI", "GJ", "rhoJ"};
  for (size_t r = 0; r < rows.size(); ++r) {
    const std::vector<double> &v = rows[r];
    if ((v.size() != 3 && v.size() != 5 && v.size() != 7) || v.size() != cols) {
      *why = At(path, lines[r]) +
             "a properties row is 'x EI mu', 'x EI mu kappaGA rhoI' or 'x EI mu kappaGA rhoI GJ rhoJ' (the same on "
             "every row; SI units); this row has " +
             std::to_string(v.size()) + " numbers and the first has " + std::to_string(cols);
      return false;
    }
    for (size_t c = 1; c < v.size(); ++c)
      if (!(v[c] > 0)) {
        *why = At(path, lines[r]) + names[c] + " = " + Num(v[c]) + " is not allowed: it must be > 0";
        return false;
      }
    PropertiesRow p;
    p.x    = v[0];
    p.line = lines[r];
    p.s.EI = v[1], p.s.mu = v[2];
    if (cols >= 5) p.s.kGA = v[3], p.s.rhoI = v[4];
    if (cols == 7) p.s.GJ = v[5], p.s.rhoJ = v[6];
    if (!out->empty() && !(p.x > out->back().x)) {
      *why = At(path, lines[r]) + "x = " + Num(p.x) +
             " does not increase (the row before has x = " + Num(out->back().x) +
             "): rows go from one end to the other";
      return false;
    }
    out->push_back(p);
  }
  return true;
}

} // namespace beamimpact

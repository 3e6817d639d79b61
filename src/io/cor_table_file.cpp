// Reading e(v) tables. See cor_table_file.hpp.
#include "io/cor_table_file.hpp"

#include "io/text.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace beamimpact {

// A number as a whole token (strtod accepts "nan" and "inf": they are refused by the caller).
static bool ParseNumber(const std::string &tok, PetscReal *x)
{
  char        *end = nullptr;
  const double d   = std::strtod(tok.c_str(), &end);
  if (end == tok.c_str() || *end != '\0') return false;
  *x = d;
  return true;
}

bool CorTableParse(std::istream &in, const std::string &name, CorTable *t, std::string *why)
{
  std::string line;
  int         lineno = 0;
  CorTable    out;
  out.file = name;
  auto bad = [&](const std::string &what) {
    *why = "-ball_cor_table " + name + ", line " + std::to_string(lineno) + ": " + what;
    return false;
  };
  std::vector<std::string> lines;
  std::string              encoding;
  if (!TextLines(in, &lines, &encoding)) { // a UTF-8 byte order mark skipped, CR line ends read
    *why = "-ball_cor_table " + name + ": " + encoding;
    return false;
  }
  for (std::string &text : lines) {
    line = text;
    ++lineno;
    if (line.find('\0') != std::string::npos)
      return bad("the line holds a NUL byte (binary data?): a COR table is plain text");
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream       ss(line);
    std::vector<std::string> tok;
    for (std::string w; ss >> w;) tok.push_back(w);
    if (tok.empty()) continue;
    if (tok.size() != 2)
      return bad("expected 2 columns 'v e' (approach speed in m/s, coefficient of restitution), found " +
                 std::to_string(tok.size()) + ": '" + line + "'");
    PetscReal v, e;
    if (!ParseNumber(tok[0], &v)) return bad("'" + tok[0] + "' is not a number (approach speed v, m/s)");
    if (!ParseNumber(tok[1], &e)) return bad("'" + tok[1] + "' is not a number (coefficient of restitution e)");
    if (!std::isfinite(v) || v < 0)
      return bad("speed " + tok[0] + " is not allowed: it must be a finite number >= 0 (m/s)");
    if (!std::isfinite(e) || !(e > 0 && e <= 1))
      return bad("coefficient of restitution " + tok[1] + " is not allowed: it must be in (0, 1]");
    if (!out.v.empty() && !(v > out.v.back())) {
      std::ostringstream prev;
      prev << out.v.back();
      return bad("speed " + tok[0] +
                 " is not allowed: the speeds must increase strictly down the table (the row before has " + prev.str() +
                 ")");
    }
    out.v.push_back(v);
    out.e.push_back(e);
  }
  if (out.v.empty()) {
    *why = "-ball_cor_table " + name + ": the table is empty (" + std::to_string(lineno) +
           " lines, none with a row 'v e')";
    return false;
  }
  *t = out;
  return true;
}

bool CorTableRead(const std::string &path, CorTable *t, std::string *why)
{
  std::ifstream in(path);
  if (!in) {
    *why = "-ball_cor_table " + path +
           ": cannot open the file (missing or not readable; a relative path is taken from the directory the program "
           "runs in)";
    return false;
  }
  return CorTableParse(in, path, t, why);
}

} // namespace beamimpact

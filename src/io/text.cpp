// Small text helpers. See text.hpp.
#include "io/text.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <regex>
#include <set>

namespace beamimpact {

static std::string TrimSet(const std::string &s, const char *leading, const char *trailing)
{
  const size_t a = s.find_first_not_of(leading), b = s.find_last_not_of(trailing);
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::string Trim(const std::string &s) { return TrimSet(s, " \t\r\n", " \t\r\n"); }

bool TextFiniteNumber(const std::string &text, double *v)
{
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char *end;
  errno          = 0;
  const double d = std::strtod(t.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(d)) return false;
  *v = d;
  return true;
}

std::string CommentText(const std::string &line) { return TrimSet(line, " \t\r\n#", " \t\r\n"); }

bool TextLines(std::istream &in, std::vector<std::string> *lines, std::string *why)
{
  struct Mark {
    const char *bytes, *hex, *encoding;
  };
  static const Mark wide[] = {{"\xFF\xFE\x00\x00", "FF FE 00 00", "UTF-32"},
                              {"\x00\x00\xFE\xFF", "00 00 FE FF", "UTF-32"},
                              {"\xFF\xFE", "FF FE", "UTF-16"},
                              {"\xFE\xFF", "FE FF", "UTF-16"}};
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  lines->clear();
  for (const Mark &m : wide) {
    const std::string mark(m.bytes, m.encoding[4] == '3' ? 4 : 2);
    if (text.compare(0, mark.size(), mark) == 0) {
      *why = std::string("the file is ") + m.encoding + " text (it starts with the bytes " + m.hex +
             "): save it as UTF-8 or plain ASCII";
      return false;
    }
  }
  size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0; // UTF-8's byte order mark
  while (i < text.size()) {
    const size_t end = text.find_first_of("\r\n", i);
    lines->push_back(text.substr(i, end == std::string::npos ? std::string::npos : end - i));
    if (end == std::string::npos) break;
    i = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
  }
  return true;
}

// PETSc's %g writes a whole number, inf and nan with a trailing dot ("-beam_length inf. is not
// allowed", "-1."): the values in a message are shown as the user wrote them. A full stop at the
// end of the message is kept.
static std::string WithoutPetscDots(const std::string &msg)
{
  static const std::regex dotted("(^|[^0-9A-Za-z.+-])(-?[0-9]+|-?inf|nan)\\.(?=[\\s,;:)])");
  return std::regex_replace(msg, dotted, "$1$2");
}

std::string LastErrorMessage(PetscErrorCode ierr)
{
  const char *text     = nullptr;
  char       *specific = nullptr;
  PetscErrorMessage(ierr, &text, &specific);
  return WithoutPetscDots(specific && specific[0] ? specific : text ? text : "unknown error");
}

PetscErrorCode PrintOnce(MPI_Comm comm, const std::string &text)
{
  static std::set<std::string> said;
  PetscFunctionBeginUser;
  if (said.insert(text).second) PetscCall(PetscPrintf(comm, "%s", text.c_str()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// Small text helpers. See text.hpp.
#include "io/text.hpp"

namespace beamimpact {

static std::string TrimSet(const std::string &s, const char *leading, const char *trailing)
{
  const size_t a = s.find_first_not_of(leading), b = s.find_last_not_of(trailing);
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::string Trim(const std::string &s) { return TrimSet(s, " \t\r\n", " \t\r\n"); }

std::string CommentText(const std::string &line) { return TrimSet(line, " \t\r\n#", " \t\r\n"); }

std::string LastErrorMessage(PetscErrorCode ierr)
{
  const char *text     = nullptr;
  char       *specific = nullptr;
  PetscErrorMessage(ierr, &text, &specific);
  return specific && specific[0] ? specific : text ? text : "unknown error";
}

} // namespace beamimpact

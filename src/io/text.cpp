// Small text helpers. See text.hpp.
#include "io/text.hpp"

#include <regex>
#include <set>

namespace beamimpact {

static std::string TrimSet(const std::string &s, const char *leading, const char *trailing)
{
  const size_t a = s.find_first_not_of(leading), b = s.find_last_not_of(trailing);
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::string Trim(const std::string &s) { return TrimSet(s, " \t\r\n", " \t\r\n"); }

std::string CommentText(const std::string &line) { return TrimSet(line, " \t\r\n#", " \t\r\n"); }

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

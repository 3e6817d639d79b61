// What the studies that drive TAO share. See study_common.hpp.
#include "studies/study_common.hpp"

#include "base/options_util.hpp"
#include "io/run_record.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

namespace beamimpact {

namespace {

PetscErrorCode (*g_loud)(FILE *, const char[], va_list) = nullptr; // the printer to restore

PetscErrorCode QuietVFPrintf(FILE *fd, const char format[], va_list ap)
{
  if (fd == PETSC_STDOUT) return 0;
  return g_loud(fd, format, ap);
}

} // namespace

QuietRanks::QuietRanks(PetscMPIInt rank)
{
  if (rank == 0 || g_loud) return;
  g_loud        = PetscVFPrintf;
  PetscVFPrintf = QuietVFPrintf;
  on            = true;
}

QuietRanks::~QuietRanks()
{
  if (!on) return;
  PetscVFPrintf = g_loud;
  g_loud        = nullptr;
}

LoudScope::LoudScope()
{
  if (!g_loud) return;
  quiet         = PetscVFPrintf;
  PetscVFPrintf = g_loud;
}

LoudScope::~LoudScope()
{
  if (quiet) PetscVFPrintf = quiet;
}

// Rank 0: text put at path whole or not at all (a temporary file beside it, fsync'ed, renamed).
PetscErrorCode StudyWriteAtomically(const std::string &path, const std::string &text, const char *option)
{
  std::string tmp = path + ".XXXXXX";
  PetscFunctionBeginUser;
  std::vector<char> name(tmp.begin(), tmp.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot create a file beside it (%s)", option,
             path.c_str(), std::strerror(errno));
  tmp         = name.data();
  size_t done = 0;
  bool   ok   = true;
  while (ok && done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w < 0 && errno == EINTR) continue;
    ok = w > 0;
    if (ok) done += (size_t)w;
  }
  ok = ok && ::fchmod(fd, 0644) == 0 && ::fsync(fd) == 0;
  ok = (::close(fd) == 0) && ok;
  if (ok) ok = ::rename(tmp.c_str(), path.c_str()) == 0;
  const int err = errno;
  if (!ok) ::unlink(tmp.c_str());
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s %s: writing it failed (%s); a file there is as it was",
             option, path.c_str(), std::strerror(err));
  PetscFunctionReturn(0);
}

PetscErrorCode StudyCheckOptionsOutput(MPI_Comm comm, const std::string &path, const std::string &output,
                                       const char *option, const char *marker, const char *who)
{
  std::vector<InputFile> inputs;
  struct stat            o, i;

  PetscFunctionBeginUser;
  if (path.empty()) PetscFunctionReturn(0);
  PetscCheck(path != output, comm, PETSC_ERR_ARG_WRONG, "%s %s is not allowed: it is -output too", option,
             path.c_str());
  const size_t      slash = path.find_last_of('/');
  const std::string dir   = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  PetscCheck(access(dir.c_str(), W_OK) == 0, comm, PETSC_ERR_FILE_OPEN,
             "%s %s is not allowed: the directory %s does not exist or is not writable", option, path.c_str(),
             dir.c_str());
  if (::stat(path.c_str(), &o) != 0) PetscFunctionReturn(0);
  PetscCheck(S_ISREG(o.st_mode), comm, PETSC_ERR_FILE_OPEN, "%s %s is not allowed: it is not a regular file", option,
             path.c_str());
  PetscCall(RunInputFiles(&inputs));
  for (const InputFile &f : inputs)
    PetscCheck(::stat(f.path.c_str(), &i) != 0 || i.st_dev != o.st_dev || i.st_ino != o.st_ino, comm,
               PETSC_ERR_FILE_OPEN,
               "%s %s is not allowed: it is an input of this run (%s %s); it would be replaced by the study's values. "
               "Give another %s (or -output)",
               option, path.c_str(), f.option.c_str(), f.path.c_str(), option);
  std::ifstream in(path);
  std::string   first;
  std::getline(in, first);
  PetscCheck(first.compare(0, std::strlen(marker), marker) == 0, comm, PETSC_ERR_FILE_OPEN,
             "%s %s is not allowed: it exists and is not an options file %s wrote (its first line is not '%s ...'); it "
             "will not be replaced: give another name, or remove the file",
             option, path.c_str(), who, marker);
  PetscFunctionReturn(0);
}

std::vector<double> FromVec(Vec x)
{
  const PetscScalar *a;
  PetscInt           n;
  VecGetLocalSize(x, &n);
  VecGetArrayRead(x, &a);
  std::vector<double> v(a, a + n);
  VecRestoreArrayRead(x, &a);
  return v;
}

PetscErrorCode ToVec(const std::vector<double> &v, Vec x)
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(x, &a));
  std::copy(v.begin(), v.end(), a);
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

std::string UnitText(const std::string &unit) { return unit.empty() || unit == "1" ? "" : " " + unit; }

PetscErrorCode StudyOptionsCheckUnused(MPI_Comm comm)
{
  PetscFunctionBeginUser;
  for (const char *name :
       {"-tao_test_gradient", "-tao_test_gradient_view", "-tao_test_hessian", "-tao_test_hessian_view"}) {
    PetscBool set; // PetscOptionsHasName marks the option used
    PetscCall(PetscOptionsHasName(NULL, NULL, name, &set));
  }
  PetscCall(OptionsCheckUnused(comm));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

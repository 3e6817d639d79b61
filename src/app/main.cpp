// beamimpact: a ball striking a flexible beam, bat or racket.
//
//   mpirun -n 2 beamimpact -options_file options/default.opts
//   beamimpact -task impact -impact_x 0.9 -ts_type cn -ts_dt 1e-5
//   beamimpact -task modes -beam_left clamped -modes_count 4
//
// The driver only initialises, dispatches the task and finalises. Errors are
// reported as one plain message (the option, the value, what is allowed);
// -error_traceback shows PETSc's full traceback instead.
#include "app/registry.hpp"
#include "app/tasks.hpp"
#include "io/options_files.hpp"
#include "io/text.hpp"
#include "studies/design.hpp"
#include "studies/sweep.hpp"

#include <slepcsys.h>

#include <dlfcn.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

static const char help[] = "beamimpact: a ball striking a flexible beam (R. Cross, Am. J. Phys. 67, 692 (1999)).\n"
                           "  -task impact|modes|sweep|convergence|flight, -output FILE.h5, and the -beam_, -ball_, "
                           "-bat_, -impact_, -monitor_, -modes_, -sweep_,\n"
                           "  -convergence_, -leapfrog_, -ts_, -flight_ and -air_ options below (-help lists them all "
                           "and runs nothing).\n"
                           "  Example: mpirun -n 2 build/release/beamimpact -options_file options/default.opts (paths "
                           "inside an options file are relative to that file)\n\n";

// The command line with every -options_file expanded into the options it holds, relative
// paths inside a file resolved against the file's directory (io/options_files.hpp): a scene
// runs from any directory. A file that cannot be read is said plainly here, before PETSc would
// stop with a traceback and an MPI abort. The strings live as long as PETSc keeps argv.
static bool ExpandCommandLine(int *argc, char ***argv, std::string *error)
{
  static std::vector<std::string> args;
  static std::vector<char *>      ptrs;
  if (!beamimpact::OptionsArgsExpand(std::vector<std::string>(*argv + 1, *argv + *argc), &args, error)) return false;
  args.insert(args.begin(), (*argv)[0]);
  for (std::string &a : args) ptrs.push_back(a.data());
  ptrs.push_back(nullptr);
  *argc = (int)args.size();
  *argv = ptrs.data();
  return true;
}

// The same for the options PETSc takes from the environment (PETSC_OPTIONS, split at blanks as
// PETSc splits it): an -options_file there is expanded too, so that its paths resolve alike.
static bool ExpandEnvironmentOptions(std::string *error)
{
  const char *env = std::getenv("PETSC_OPTIONS");
  if (!env || !std::strstr(env, "-options_file")) return true;
  std::istringstream       words(env);
  std::vector<std::string> in, out;
  for (std::string w; words >> w;) in.push_back(w);
  if (!beamimpact::OptionsArgsExpand(in, &out, error)) {
    *error = "PETSC_OPTIONS: " + *error;
    return false;
  }
  std::string text;
  for (const std::string &w : out)
    text += (text.empty() ? "" : " ") + (w.find_first_of(" \t") == std::string::npos ? w : "\"" + w + "\"");
  return setenv("PETSC_OPTIONS", text.c_str(), 1) == 0;
}

// One BLAS thread per rank unless the environment sets OPENBLAS_NUM_THREADS or OMP_NUM_THREADS:
// the MPI ranks are the program's parallelism, and a threaded OpenBLAS (Debian's libblas.so.3)
// sums its products in another order on 2 threads than on 1, so that an impact run alone and the
// same impact as a point of a sweep under mpirun (a rank bound to one core: one thread) differed
// in the last bit (an ACOR of 0.5709105655702814 against ...2813). Looked up at run time: another
// BLAS has no such function and is left as it is.
static void BLASOneThreadPerRank()
{
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS")) return;
  using SetThreads = void (*)(int);
  if (SetThreads set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

// PETSc's parse errors ("Input string 41.5 has no integer value ...") do not say which option:
// find the option given that value and say it.
static std::string OptionOfParseError(const std::string &msg)
{
  const std::string head = "Input string ";
  if (msg.compare(0, head.size(), head) != 0) return msg;
  const std::string value = msg.substr(head.size(), msg.find(' ', head.size()) - head.size());
  char             *all   = nullptr;
  if (PetscOptionsGetAll(NULL, &all) || !all) return msg;
  std::istringstream words(all);
  std::string        w, name, found;
  while (words >> w) {
    if (w.size() > 1 && w[0] == '-' && !std::isdigit((unsigned char)w[1]) && w[1] != '.') name = w;
    else if (w == value && !name.empty()) found = name;
  }
  PetscFree(all);
  if (found.empty()) return msg;
  const bool integer = msg.find("integer") != std::string::npos;
  return found + " " + value + " is not allowed: it must be " + (integer ? "a whole number" : "a number") + " (" + msg +
         ")";
}

// Under mpirun (Open MPI sets OMPI_COMM_WORLD_SIZE, MPICH's hydra PMI_SIZE): a rank dies with
// its launcher. A killed
// mpirun (kill -9) cannot stop its ranks, which would run on, unseen, until their MPI
// connections break (~2 s, a sweep's ranks journaling rows all the while); the kernel kills
// them at once instead (PR_SET_PDEATHSIG). A launcher already gone before the request
// (the rank reparented) ends the rank here.
static void DieWithLauncher()
{
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE")) return;
  const pid_t parent = getppid();
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) return;
  if (getppid() != parent) _exit(1); // it died before the request took effect
}

// After a task returned an error on some rank: do all ranks agree? Each rank that reached the
// end of the task (failed or not) joins a nonblocking reduction on a communicator of its own
// (the task's collectives cannot match it). When every rank joins, the first failed rank's
// message reaches rank 0, which prints it, and every rank returns through SlepcFinalize: one
// line and exit status 1, no MPI_Abort (Open MPI's launcher would add its own noise). A failed
// rank whose peers do not join within a few seconds (they wait in a collective for it) ends
// the run with MPI_Abort after printing its own message. A rank that succeeded waits for the
// others as long as they run.
static int AgreeOnFailure(MPI_Comm agree, PetscErrorCode ierr)
{
  PetscMPIInt rank, size, first = 0;
  MPI_Comm_rank(agree, &rank);
  MPI_Comm_size(agree, &size);
  const std::string msg = ierr ? OptionOfParseError(beamimpact::LastErrorMessage(ierr)) : std::string();
  if (size == 1) {
    if (ierr) fprintf(stderr, "beamimpact: error: %s\n", msg.c_str());
    return ierr ? 1 : 0;
  }
  PetscMPIInt mine = ierr ? rank : size;
  MPI_Request req;
  MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, agree, &req);
  int          done = 0;
  const double t0   = MPI_Wtime();
  while (!done) {
    MPI_Test(&req, &done, MPI_STATUS_IGNORE);
    if (done) break;
    if (ierr && MPI_Wtime() - t0 > 5.0) { // the others are stuck waiting for this rank
      fprintf(stderr, "beamimpact: error%s: %s\n", rank ? (" (rank " + std::to_string(rank) + ")").c_str() : "",
              msg.c_str());
      fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    usleep(ierr ? 1000 : 20000);
  }
  if (first == size) return 0; // nobody failed
  std::string text = msg;
  if (first != 0) { // rank 0 prints the first failed rank's message
    int n = (int)text.size();
    if (rank == first) {
      MPI_Send(&n, 1, MPI_INT, 0, 1, agree);
      MPI_Send(text.data(), n, MPI_CHAR, 0, 2, agree);
    } else if (rank == 0) {
      MPI_Recv(&n, 1, MPI_INT, first, 1, agree, MPI_STATUS_IGNORE);
      text.assign((size_t)n, '\0');
      MPI_Recv(&text[0], n, MPI_CHAR, first, 2, agree, MPI_STATUS_IGNORE);
    }
  }
  if (rank == 0) fprintf(stderr, "beamimpact: error: %s\n", text.c_str());
  fflush(stderr);
  return 1;
}

int main(int argc, char **argv)
{
  PetscBool traceback = PETSC_FALSE;

  DieWithLauncher();
  BLASOneThreadPerRank();

  std::string error;
  if (!ExpandEnvironmentOptions(&error) || !ExpandCommandLine(&argc, &argv, &error)) {
    const char *rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (!rank || !std::strcmp(rank, "0")) fprintf(stderr, "beamimpact: error: %s\n", error.c_str());
    return 1;
  }

  PetscCall(SlepcInitialize(&argc, &argv, NULL, help));
  PetscCall(beamimpact::RegisterAll());
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-error_traceback", &traceback, NULL));
  if (!traceback) PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  MPI_Comm agree; // for AgreeOnFailure only
  PetscCallMPI(MPI_Comm_dup(PETSC_COMM_WORLD, &agree));
  PetscErrorCode ierr   = beamimpact::RunTask(PETSC_COMM_WORLD);
  const int      failed = AgreeOnFailure(agree, ierr);
  MPI_Comm_free(&agree);
  if (failed) {
    if (!traceback) PetscPopErrorHandler();
    SlepcFinalize();
    return 1;
  }
  if (!traceback) PetscCall(PetscPopErrorHandler());
  PetscCall(SlepcFinalize());
  // 2: a sweep completed with failed points; 3: a design ended beyond its constraints (studies/design.hpp)
  return beamimpact::SweepExitStatus() ? beamimpact::SweepExitStatus() : beamimpact::DesignExitStatus();
}

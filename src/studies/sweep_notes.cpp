// A sweep's notes, once per sweep. See sweep_notes.hpp.
#include "studies/sweep_notes.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace beamimpact {

namespace {

enum class NotesMode {
  Off,
  Remember,
  Collect
};

struct NotesState {
  NotesMode mode                                         = NotesMode::Off;
  PetscErrorCode (*print)(FILE *, const char[], va_list) = nullptr; // PETSc's printer
  std::set<std::string>           said;                             // printed during the set-up
  std::set<std::string>           point;                            // the current point's
  std::map<std::string, PetscInt> counts;
};

NotesState &Notes()
{
  static NotesState s;
  return s;
}

PetscErrorCode NotesVFPrintf(FILE *fd, const char format[], va_list ap)
{
  NotesState &s = Notes();
  char        line[8192];
  va_list     copy;
  va_copy(copy, ap);
  std::vsnprintf(line, sizeof line, format, copy);
  va_end(copy);
  std::string text(line);
  if (text.compare(0, 6, "note: ") == 0) {
    text = text.substr(6);
    while (!text.empty() && text.back() == '\n') text.pop_back();
    if (s.mode == NotesMode::Collect) {
      s.point.insert(text);
      return 0;
    }
    if (!s.said.insert(text).second) return 0; // said already: the set-up reads every point's options too
  }
  return s.print(fd, format, ap);
}

} // namespace

PetscErrorCode SweepNotesBegin()
{
  NotesState &s = Notes();

  PetscFunctionBeginUser;
  if (s.mode == NotesMode::Off) {
    s.print       = PetscVFPrintf;
    PetscVFPrintf = NotesVFPrintf;
  }
  s.mode = NotesMode::Remember;
  s.said.clear(), s.point.clear(), s.counts.clear();
  PetscFunctionReturn(0);
}

void SweepNotesCollect()
{
  if (Notes().mode != NotesMode::Off) Notes().mode = NotesMode::Collect;
}

void SweepNotesPointDone(bool leader)
{
  NotesState &s = Notes();
  if (leader)
    for (const std::string &t : s.point) ++s.counts[t];
  s.point.clear();
}

void SweepNotesAbandon()
{
  NotesState &s = Notes();
  if (s.mode == NotesMode::Off) return;
  PetscVFPrintf = s.print;
  s.mode        = NotesMode::Off;
}

PetscErrorCode SweepNotesEnd(MPI_Comm world, PetscInt npoints)
{
  NotesState &s = Notes();
  PetscMPIInt rank, size;

  PetscFunctionBeginUser;
  if (s.mode == NotesMode::Off) PetscFunctionReturn(0);
  PetscVFPrintf = s.print;
  s.mode        = NotesMode::Off;
  PetscCallMPI(MPI_Comm_rank(world, &rank));
  PetscCallMPI(MPI_Comm_size(world, &size));
  std::string mine; // "count\ttext\n" lines (a note is one line)
  for (auto &kv : s.counts) mine += std::to_string((long long)kv.second) + "\t" + kv.first + "\n";
  PetscMPIInt              n = (PetscMPIInt)mine.size();
  std::vector<PetscMPIInt> counts(size), displs(size);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world));
  std::vector<char> all;
  if (rank == 0) {
    size_t total = 0;
    for (PetscMPIInt r = 0; r < size; ++r) displs[r] = (PetscMPIInt)total, total += counts[r];
    all.resize(total);
  }
  PetscCallMPI(MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0, world));
  if (rank == 0) {
    std::map<std::string, PetscInt> sum;
    std::istringstream              lines(std::string(all.begin(), all.end()));
    for (std::string line; std::getline(lines, line);) {
      const size_t tab = line.find('\t');
      if (tab != std::string::npos) sum[line.substr(tab + 1)] += std::stoll(line.substr(0, tab));
    }
    for (auto &kv : sum)
      if (!s.said.count(kv.first))
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "note (on %" PetscInt_FMT " of %" PetscInt_FMT " points): %s\n",
                              std::min(kv.second, npoints), npoints, kv.first.c_str()));
  }
  s.said.clear(), s.counts.clear();
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The store of a sweep's rows for -output F: per-leader journals, the atomic rewrite of F,
// the parameter signature a resume must match, and the resume from F and the journals.
//
// On disk, for -output F:
//   F          the results: root attributes (parameters, options, progress) and
//              /results/<column> with one row per finished case, ordered by
//              case index (failed cases too: status != 0, their text in
//              /results/reason), and /sweep/<axis> with every case's axis values;
//              a text axis's datasets hold strings, with its values in order as the
//              attribute `values`;
//              rewritten only as F.tmp + fsync + rename(), so F is always a
//              complete HDF5 file (readable by h5py/h5dump at any time).
//   F.parts/   while a sweep runs: lock (flock by rank 0: one sweep per file; removed when
//              the run ends, also by an error or a refused resume; one left by a killed run
//              is not held and is simply taken again),
//              run<R>-rank<r>.bin, the journal of the group leader on world rank
//              r in run (attempt) R: a header with the parameter signature, then
//              one self-checking record per finished case (its numbers and its
//              reason text), appended with a single write(). A record cut by kill -9 fails its checksum and is
//              ignored (that case is simply computed again).
// A rerun of the same command reads F and the journals, checks that they were
// written with the same parameters, rewrites F with every row found, and
// computes only the missing cases. At the end rank 0 gathers this run's rows
// over MPI, writes the complete F and removes F.parts.
#pragma once

#include "io/run_record.hpp"
#include "studies/sweep_plan.hpp"
#include "studies/sweep_uq.hpp"

#include <petscsys.h>

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace beamimpact {

// One column of a sweep row.
struct SweepColumn {
  std::string              name;
  std::string              unit;
  bool                     timing;          // differs from run to run (wall_time): excluded from identity checks
  bool                     integer = false; // a count (double on disk for NaN rows, with the attribute integer = 1)
  std::vector<std::string> labels =
    {}; // a text axis (categorical): the row holds the index of its label; on disk the labels, as strings
  std::string description = {}; // one line, for the results reference (docs/results.md)
};

// The journal of the group leader on world rank `rank` in run (attempt) `run` of -output.
std::string SweepJournalName(const std::string &output, int run, int rank);
// The journals in the directory `parts` (F.parts), as paths in name order, and the largest run
// number among them in *last_run (0 when none; may be NULL).
std::vector<std::string> SweepJournalFiles(const std::string &parts, int *last_run);
// Takes parts/lock for one run writing `output` (flock, not blocking; *lock_fd holds it): an
// error when another run holds it ("another <who> that is still running").
PetscErrorCode SweepPartsLock(const std::string &output, const std::string &parts, const char *who, int *lock_fd);
// A 1-D dataset of variable-length UTF-8 strings in loc (an HDF5 file or group id) with the
// attribute unit = unit_text, and its read-back (false when missing or unreadable).
bool H5WriteStringColumn(long long loc, const char *name, const std::vector<std::string> &v, const char *unit_text);
bool H5ReadStringColumn(long long loc, const char *name, std::vector<std::string> *v);
// A 1-D dataset of numbers read as doubles (false when missing or unreadable).
bool H5ReadDoubleColumn(long long loc, const char *name, std::vector<double> *v);

// Appends rows to one journal file (opened on the first row). A journal that cannot be
// written is not fatal (one warning): the row is also kept in memory and gathered at the
// end; only a resume after a crash would lose it.
struct SweepJournalWriter {
  std::string path;
  uint64_t    signature = 0;
  uint32_t    ncols     = 0;
  int         fd        = -1;
  bool        failed    = false; // warned once; the rows still reach the file at the end

  PetscErrorCode Append(const std::vector<double> &row, const std::string &reason);
  void           Close();
  void           Warn(const char *what);
};

// Reads the complete, valid records of one journal file, from where it stopped
// last time (a record still being written is read next time).
struct SweepJournalReader {
  std::string path;
  off_t       offset    = 0;
  bool        header_ok = false;
  bool        stopped   = false; // a bad record: ignore the rest of the file
  uint64_t    signature = 0;

  enum Status {
    Ok,
    Missing,
    WrongParameters
  };
  Status ReadNew(uint64_t expected_signature, uint32_t ncols, PetscInt ncases,
                 std::map<PetscInt, std::vector<double>> *rows, std::map<PetscInt, std::string> *reasons,
                 PetscInt *added);
};

// Root attributes by name (what the parameter signature is made of).
struct SweepAttributes {
  std::map<std::string, double>      num;
  std::map<std::string, std::string> str;
};

// Rank 0's view of the output: the record, the rows known so far, the journals of the
// current run and the live rewrites.
struct SweepStore {
  std::string                             output, parts; // F and F.parts
  SweepPlan                               plan;          // its axes fill /sweep; -sweep_restart
  std::vector<SweepColumn>                columns;
  RunRecord                               record; // without the progress attributes
  SweepAttributes                         signature;
  uint64_t                                signature_hash = 0;
  uint32_t                                ncols          = 0;
  PetscInt                                ncases         = 0;
  std::map<PetscInt, std::vector<double>> rows;
  std::map<PetscInt, std::string>         reasons;            // of the failed rows (status != 0)
  int                                     status_column = -1; // index of "status" in columns
  std::vector<SweepJournalReader>         live;               // this run's journals
  int                                     lock_fd = -1;
  // -sweep_retry_failed with options changed that the failed rows name as their cause
  // (-impact_max_contacts, -impact_max_time, ...): the file's former signature (its journals
  // still load) and what changed, kept in the file as the attribute sweep_retry_changed.
  uint64_t    retry_signature_hash = 0;
  std::string retry_changed;
  PetscInt    rows_written = -1;
  double      last_write = 0, write_cost = 0; // s (MPI_Wtime), s
  int         writes = 0;                     // live rewrites (SweepStoreRefresh) so far
  SweepUq     uq;                             // a sampled sweep's statistics, once complete (written with the file)
  double      write_total = 0;                // s, their time, reading the journals included
};

// The options that decide a sweep's numbers, "-name value ..." (recorded as
// sweep_checked_options, part of the signature): all but -output, the progress and
// restart options, and logging, monitoring and viewing options.
std::string SweepCheckedOptions(const std::string &all);
// "-name value -name2 -name3 value3 ..." as name (no dash) -> value ("" for a flag given bare).
std::map<std::string, std::string> SweepOptionsParse(const std::string &all);

// Rank 0: the store of `output` for the plan, its row columns and its record (whose
// attributes, all but the volatile ones, make the parameter signature).
void SweepStoreInit(const std::string &output, const SweepPlan &plan, const std::vector<SweepColumn> &columns,
                    const RunRecord &record, SweepStore *S);
// Rank 0: locks the output, loads what is done (file and journals; an error when they
// were written with other parameters), with -sweep_retry_failed forgets the failed rows,
// rewrites the file with all of it, drops the old journals. Returns this run's number
// (for the journal names).
PetscErrorCode SweepStoreOpen(SweepStore &S, int *run);
// Rank 0: follows the journals of this run's group leaders (world ranks).
void SweepStoreFollow(SweepStore &S, int run, const std::vector<PetscMPIInt> &leaders);
// Rank 0 while cases remain: rewrites the file with the rows journaled so far once
// -sweep_write_interval has passed (and at most ~5% of its time).
PetscErrorCode SweepStoreRefresh(SweepStore &S);
// Rank 0 at the end: the complete file (every case must have its row); removes the
// journals and the lock.
PetscErrorCode SweepStoreClose(SweepStore &S);
// Rank 0 when the run stops early (a refused resume, bad input, an error in the farm): removes
// and releases the lock it holds (nothing if it holds none) and F.parts when it is empty; the
// journals stay for a resume.
void SweepStoreRelease(SweepStore &S);

} // namespace beamimpact

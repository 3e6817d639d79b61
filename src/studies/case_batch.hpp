// A case batch: an explicit list of runs of the program ("cases"), each a list of option
// assignments set in the options database as a sweep point sets its axes, run by a task kind
// (impact, modes, flight: CaseTasks) into a row of named numbers. Shared by the studies that
// evaluate the program many times at points they choose themselves: -task fit (a residual is one
// batch, a Jacobian by differences one batch of rows x parameters), and the design and sampling
// studies to come.
//
//   CaseBatchSettings s;
//   s.task    = CaseTaskFind("impact");
//   s.columns = {"acor", "contact_time"};
//   s.store   = "fit.h5";                    // journals in fit.h5.parts/, earlier rows from fit.h5
//   CaseBatch batch;
//   PetscCall(CaseBatchCreate(PETSC_COMM_WORLD, s, &batch));
//   std::vector<CaseOptions> cases = {{{"impact_x", 0.3}, {"ball_k", 2e4}}, {{"impact_x", 0.5}, {"ball_k", 2e4}}};
//   std::vector<CaseRow>     rows;
//   PetscCall(CaseBatchRun(batch, cases, &rows)); // collective; the same rows on every rank
//   ...                                            // the caller's file: CaseBatchWrite(batch, file)
//   PetscCall(CaseBatchFinish(batch));             // the store holds every row: journals removed
//   PetscCall(CaseBatchDestroy(&batch));
//
// * Farm: the cases still to compute are handed out over the ranks of the world by the sweep's
//   farm (studies/sweep_farm.hpp: dynamic load balancing), each case on one rank, so that a row
//   is the same number for number on any number of ranks; the rows are then gathered on every
//   rank (the callers' optimisers run redundantly on each rank with the same numbers).
// * Key: a case is known by the SHA-256 of its complete option text: the task, the columns, every
//   option that decides a number (the options database without the volatile ones, without the
//   study's own prefixes, with the case's settings in place; numbers %.17g, exact) and the
//   contents (SHA-256) of the files the options name. A case whose key is known is never run
//   again: not within a batch, not across a study's batches, not after a rerun.
// * Journal: each rank appends its rows to its journal in store.parts/ with the sweep's journal
//   (studies/sweep_store.hpp: one self-checking record per row, one write(), kill -9 safe; the
//   record's text holds the key and the case). CaseBatchCreate loads the rows of the store's
//   /case_batch group and of every journal left by a killed run, so a rerun computes only the
//   cases nobody has computed. The store's directory is locked while the batch lives.
#pragma once

#include "studies/sweep.hpp"
#include "studies/sweep_farm.hpp"
#include "studies/sweep_plan.hpp"

#include <petscsys.h>

#include <map>
#include <string>
#include <vector>

namespace beamimpact {

// One option a case sets: its name without the dash and its value, a number (set exactly, as
// %.17g) or a text ("modal").
struct CaseSetting {
  std::string name;          // "ball_speed"
  double      value = 0;     // the number (when text is empty)
  std::string text  = {};    // a text value; empty: the number
  std::string Value() const; // as the options database gets it
};
using CaseOptions = std::vector<CaseSetting>;

// "ball_speed=40, impact_x=0.29999999999999999": numbers %.17g (exact: the store), or %g for messages.
std::string CaseOptionsText(const CaseOptions &c, bool exact = true);

// What one case gave: its status (SweepStatus: 0 ok), the task's columns in the order asked
// (NaN where the run gives none) and, for a failed run, the first line of its error (for a run
// that did not fail: why a column is NaN, or empty).
struct CaseRow {
  int                 status = SweepOk;
  std::vector<double> values;
  std::string         reason;
};

// What a rank keeps across the cases it runs: an impact's structure (the sweep's SweepReuse),
// dropped when a case sets other options than the one before.
struct CaseRunState {
  SweepReuse               impact;
  std::vector<std::string> names;           // the option names of the last case
  bool                     checked = false; // a case's options were checked against what the task read
};

// A task kind of a case (a registry: impact, modes, flight; a new kind is one entry).
struct CaseTask {
  const char *name;        // as -fit_task names it
  const char *description; // one line, for -help and messages
  // Whether the task gives the column `name` (its unit in *unit); else false, with the columns it
  // has in words in *why.
  bool (*column)(const std::string &name, std::string *unit, std::string *why);
  // Runs the case whose settings `plan` holds (one point: an axis per setting) on comm, its
  // options set while it runs and cleared after: row->values[k] for columns[k], or a failed row
  // (status, reason). Returns an error only for what no case's values can cause.
  PetscErrorCode (*run)(MPI_Comm comm, const SweepPlan &plan, const std::vector<std::string> &columns,
                        CaseRunState *state, CaseRow *row);
};
const std::vector<const CaseTask *> &CaseTasks();
const CaseTask                      *CaseTaskFind(const std::string &name); // nullptr when none
std::string                          CaseTaskNames();                       // "impact, modes, flight"

struct CaseBatchSettings {
  const CaseTask          *task = nullptr;
  std::vector<std::string> columns;         // the task's columns a row holds, in order
  std::string              store;           // the study's results file ("": no journal, nothing kept after the batch)
  std::vector<std::string> own_prefixes;    // options (no dash) that decide no run, left out of the key: "fit_", "tao_"
  bool                     restart = false; // forget the store's rows and its journals
  PetscInt    stop_after           = 0; // > 0: stop with an error after this many runs on a rank (tests of the resume)
  std::string who                  = "fit"; // the study, in messages ("another fit that is still running")
};

// What the batch has done: runs computed by this process's world (all ranks), cases answered from
// the cache, rows loaded at the start (from the store and the journals), and the ranks' time in runs.
struct CaseBatchCounts {
  PetscInt computed = 0, reused = 0, loaded = 0, loaded_journal = 0;
  double   run_time = 0; // s, summed over the ranks
  double   wall     = 0; // s, in CaseBatchRun on this rank
};

struct CaseBatch {
  MPI_Comm          world = MPI_COMM_NULL;
  PetscMPIInt       rank = 0, size = 1;
  CaseBatchSettings settings;
  std::map<std::string, std::string>
    fixed; // the options that decide a number, by name (no dash) -> value, and file contents
  std::map<std::string, CaseRow>     rows;  // by key: every row known
  std::map<std::string, std::string> cases; // by key: the case's text (CaseOptionsText)
  std::map<std::string, SweepAxis> given; // an option a case sets that the options also give: put back after each case
  TaskFarm                         farm;
  CaseRunState                     state;
  std::string                      parts; // store.parts ("" without a store)
  int                              lock_fd = -1, run = 0;
  uint64_t                         signature    = 0;
  double                           next_ordinal = 0; // of this run's journal records
  SweepJournalWriter               journal;
  PetscInt                         computed_here = 0; // runs on this rank (stop_after)
  CaseBatchCounts                  counts;
};

// Collective on world: the fixed options and the key's prefix; on rank 0 the store's lock, its
// /case_batch rows and its journals (rows for other columns or another task are not loaded), then
// every known row on every rank.
PetscErrorCode CaseBatchCreate(MPI_Comm world, const CaseBatchSettings &s, CaseBatch *b);
// Collective, with the same cases on every rank: the row of each case, computed where its key is
// not known (a case that appears twice runs once), the same on every rank.
PetscErrorCode CaseBatchRun(CaseBatch &b, const std::vector<CaseOptions> &cases, std::vector<CaseRow> *rows);
// The key of a case (64 hex digits) and the text it hashes.
std::string CaseBatchKey(const CaseBatch &b, const CaseOptions &c, std::string *text = nullptr);
// Rank 0: every known row into the group /case_batch of an open HDF5 file (attributes task and
// columns; datasets key, case, status, reason and one per column).
PetscErrorCode CaseBatchWrite(const CaseBatch &b, long long file);
// Rank 0, once the store holds every row (CaseBatchWrite went into it): the journals removed.
PetscErrorCode CaseBatchFinish(CaseBatch &b);
// Collective: the counts summed over the ranks (computed, run_time).
PetscErrorCode CaseBatchGetCounts(const CaseBatch &b, CaseBatchCounts *c);
// Collective: releases the farm and the lock (the journals stay unless CaseBatchFinish ran: a rerun
// resumes).
PetscErrorCode CaseBatchDestroy(CaseBatch *b);
// Not collective (a study stopped by an error on some rank): closes this rank's journal and releases
// the lock rank 0 holds; the farm is left to MPI_Finalize.
void CaseBatchRelease(CaseBatch *b);

} // namespace beamimpact

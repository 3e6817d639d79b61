// The case batch: keys, the cache, the farm, the journals and the store. See case_batch.hpp.
#include "studies/case_batch.hpp"

#include "base/options_util.hpp"
#include "io/results_h5.hpp"
#include "io/run_record.hpp"
#include "io/sha256.hpp"
#include "io/text.hpp"
#include "studies/sweep_notes.hpp"
#include "studies/sweep_store.hpp"

#include <hdf5.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

namespace beamimpact {

namespace {

const PetscInt kJournalOrdinals = 1000000000; // a journal record's ordinal is below this

std::string Number17(double v)
{
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// One line of text: tabs and line ends of an error message made blanks (the record's fields are tab-separated).
std::string OneLine(std::string s)
{
  for (char &c : s)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return s;
}

bool HasPrefix(const std::string &name, const std::vector<std::string> &prefixes)
{
  for (const std::string &p : prefixes)
    if (name.compare(0, p.size(), p) == 0) return true;
  return false;
}

std::string Join(const std::vector<std::string> &v, const char *sep)
{
  std::string out;
  for (const std::string &s : v) out += (out.empty() ? "" : sep) + s;
  return out;
}

// The journal's signature: the layout of its records (task and columns), not the options (the key holds those).
uint64_t LayoutSignature(const CaseBatchSettings &s)
{
  const std::string h = Sha256Hex("beamimpact case batch 1\n" + std::string(s.task->name) + "\n" +
                                  Join(s.columns, ","));
  return std::strtoull(h.substr(0, 16).c_str(), nullptr, 16);
}

// The options that decide a number (SweepCheckedOptions: all but -output, progress, logging,
// monitors, file paths), without the study's own, and the contents of the files options name.
PetscErrorCode FixedOptions(const CaseBatchSettings &s, std::map<std::string, std::string> *fixed)
{
  std::string            all;
  std::vector<InputFile> files;

  PetscFunctionBeginUser;
  PetscCall(OptionsAsString(&all));
  fixed->clear();
  for (auto &kv : SweepOptionsParse(SweepCheckedOptions(all)))
    if (!HasPrefix(kv.first, s.own_prefixes)) (*fixed)[kv.first] = kv.second;
  PetscCall(RunInputFiles(&files));
  for (const InputFile &f : files)
    if (f.option != "-options_file" && !HasPrefix(f.option.substr(1), s.own_prefixes))
      (*fixed)["file " + f.option] = f.sha256.empty() ? "unreadable " + f.path : f.sha256;
  PetscFunctionReturn(0);
}

} // namespace

std::string CaseSetting::Value() const { return text.empty() ? Number17(value) : text; }

std::string CaseOptionsText(const CaseOptions &c, bool exact)
{
  std::string out;
  for (const CaseSetting &s : c) {
    char shown[40];
    std::snprintf(shown, sizeof shown, "%g", s.value);
    out += (out.empty() ? "" : ", ") + s.name + "=" + (exact || !s.text.empty() ? s.Value() : std::string(shown));
  }
  return out;
}

std::string CaseBatchKey(const CaseBatch &b, const CaseOptions &c, std::string *text)
{
  std::map<std::string, std::string> options = b.fixed;
  for (const CaseSetting &s : c) options[s.name] = s.Value();
  std::string t = "beamimpact case batch 1\ntask " + std::string(b.settings.task->name) + "\ncolumns " +
                  Join(b.settings.columns, ",") + "\n";
  for (auto &kv : options) t += (kv.first.compare(0, 5, "file ") == 0 ? "" : "-") + kv.first + " " + kv.second + "\n";
  if (text) *text = t;
  return Sha256Hex(t);
}

// ---------------------------------------------------------------------------
// The store: /case_batch of the study's file and the journals (rank 0)
// ---------------------------------------------------------------------------

namespace {

// The rows of the store's /case_batch, when it was written for the same task and columns.
void LoadStoreFile(CaseBatch &b)
{
  const std::string &path = b.settings.store;
  struct stat        st;
  if (::stat(path.c_str(), &st) != 0) return;
  H5ErrorsQuiet quiet;
  if (H5Fis_hdf5(path.c_str()) <= 0) return;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return;
  const hid_t g = H5Lexists(file, "case_batch", H5P_DEFAULT) > 0 ? H5Gopen2(file, "case_batch", H5P_DEFAULT) : -1;
  if (g >= 0) {
    std::vector<std::string>         layout, keys, cases, reasons;
    std::vector<double>              status;
    std::vector<std::vector<double>> cols(b.settings.columns.size());
    bool                             ok = H5ReadStringColumn(g, "layout", &layout) && layout.size() == 1 &&
              layout[0] == std::string(b.settings.task->name) + ":" + Join(b.settings.columns, ",") &&
              H5ReadStringColumn(g, "key", &keys) && H5ReadStringColumn(g, "case", &cases) &&
              H5ReadStringColumn(g, "reason", &reasons) && H5ReadDoubleColumn(g, "status", &status);
    for (size_t k = 0; ok && k < cols.size(); ++k)
      ok = H5ReadDoubleColumn(g, b.settings.columns[k].c_str(), &cols[k]) && cols[k].size() == keys.size();
    ok = ok && cases.size() == keys.size() && reasons.size() == keys.size() && status.size() == keys.size();
    for (size_t r = 0; ok && r < keys.size(); ++r) {
      CaseRow row;
      row.status = (int)status[r];
      row.reason = reasons[r];
      for (auto &c : cols) row.values.push_back(c[r]);
      if (b.rows.emplace(keys[r], row).second) ++b.counts.loaded;
      b.cases.emplace(keys[r], cases[r]);
    }
    H5Gclose(g);
  }
  H5Fclose(file);
}

// The rows of every journal in store.parts (a killed run's): records of another layout are not loaded.
void LoadJournals(CaseBatch &b, std::vector<std::string> *foreign)
{
  const uint32_t ncols = (uint32_t)(2 + b.settings.columns.size());
  for (const std::string &path : SweepJournalFiles(b.parts, &b.run)) {
    SweepJournalReader                      j;
    std::map<PetscInt, std::vector<double>> records;
    std::map<PetscInt, std::string>         texts;
    j.path = path;
    if (j.ReadNew(b.signature, ncols, kJournalOrdinals, &records, &texts, nullptr) ==
        SweepJournalReader::WrongParameters) {
      foreign->push_back(path);
      continue;
    }
    for (auto &kv : records) {
      b.next_ordinal = std::max(b.next_ordinal, (double)kv.first + 1);
      std::istringstream f(texts[kv.first]);
      std::string        key, text, reason;
      std::getline(f, key, '\t'), std::getline(f, text, '\t'), std::getline(f, reason);
      if (key.size() != 64) continue;
      CaseRow row;
      row.status = (int)kv.second[1];
      row.values.assign(kv.second.begin() + 2, kv.second.end());
      row.reason = reason;
      if (b.rows.emplace(key, row).second) ++b.counts.loaded_journal;
      b.cases.emplace(key, text);
    }
  }
}

PetscErrorCode OpenStore(CaseBatch &b)
{
  std::vector<std::string> foreign;

  PetscFunctionBeginUser;
  const bool made = ::mkdir(b.parts.c_str(), 0755) == 0;
  PetscCheck(made || errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
             "-output %s: cannot create the journal directory %s (%s)", b.settings.store.c_str(), b.parts.c_str(),
             std::strerror(errno));
  PetscCall(SweepPartsLock(b.settings.store, b.parts, b.settings.who.c_str(), &b.lock_fd));
  if (b.settings.restart) {
    for (const std::string &path : SweepJournalFiles(b.parts, &b.run)) ::unlink(path.c_str());
  } else {
    LoadStoreFile(b);
    LoadJournals(b, &foreign);
  }
  b.run += 1;
  if (!foreign.empty())
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "note: %zu journal(s) in %s were written for other columns or another task (%s, ...): their "
                          "runs are not reused\n",
                          foreign.size(), b.parts.c_str(), foreign[0].c_str()));
  PetscFunctionReturn(0);
}

// Rank 0's known rows to every rank: numbers (status, values) and the text "key\tcase\treason\n".
PetscErrorCode BroadcastRows(CaseBatch &b)
{
  std::vector<double> nums;
  std::string         text;
  long long           sizes[2] = {0, 0};

  PetscFunctionBeginUser;
  if (b.rank == 0) {
    for (auto &kv : b.rows) {
      nums.push_back(kv.second.status);
      nums.insert(nums.end(), kv.second.values.begin(), kv.second.values.end());
      text += kv.first + "\t" + b.cases[kv.first] + "\t" + OneLine(kv.second.reason) + "\n";
    }
    sizes[0] = (long long)nums.size(), sizes[1] = (long long)text.size();
  }
  PetscCallMPI(MPI_Bcast(sizes, 2, MPI_LONG_LONG, 0, b.world));
  PetscCallMPI(MPI_Bcast(&b.next_ordinal, 1, MPI_DOUBLE, 0, b.world));
  PetscCallMPI(MPI_Bcast(&b.run, 1, MPI_INT, 0, b.world));
  PetscInt loaded[2] = {b.counts.loaded, b.counts.loaded_journal};
  PetscCallMPI(MPI_Bcast(loaded, 2, MPIU_INT, 0, b.world));
  b.counts.loaded = loaded[0], b.counts.loaded_journal = loaded[1];
  if (sizes[0] == 0) PetscFunctionReturn(0);
  nums.resize((size_t)sizes[0]);
  text.resize((size_t)sizes[1]);
  PetscCallMPI(MPI_Bcast(nums.data(), (int)sizes[0], MPI_DOUBLE, 0, b.world));
  PetscCallMPI(MPI_Bcast(&text[0], (int)sizes[1], MPI_CHAR, 0, b.world));
  if (b.rank == 0) PetscFunctionReturn(0);
  std::istringstream lines(text);
  size_t             p = 0, nv = b.settings.columns.size();
  for (std::string line; std::getline(lines, line);) {
    std::istringstream f(line);
    std::string        key, c, reason;
    std::getline(f, key, '\t'), std::getline(f, c, '\t'), std::getline(f, reason);
    CaseRow row;
    row.status = (int)nums[p];
    row.values.assign(nums.begin() + p + 1, nums.begin() + p + 1 + nv);
    row.reason = reason;
    p += 1 + nv;
    b.rows[key]  = row;
    b.cases[key] = c;
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode CaseBatchCreate(MPI_Comm world, const CaseBatchSettings &s, CaseBatch *b)
{
  PetscFunctionBeginUser;
  PetscCheck(s.task, world, PETSC_ERR_ARG_NULL, "case batch: no task");
  b->world    = world;
  b->settings = s;
  PetscCallMPI(MPI_Comm_rank(world, &b->rank));
  PetscCallMPI(MPI_Comm_size(world, &b->size));
  PetscCall(FixedOptions(s, &b->fixed));
  b->signature        = LayoutSignature(s);
  b->parts            = s.store.empty() ? "" : s.store + ".parts";
  PetscErrorCode ierr = 0;
  if (b->rank == 0 && !s.store.empty()) ierr = OpenStore(*b);
  PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, world));
  PetscCheck(!ierr || b->rank == 0, world, ierr, "the store of the case batch could not be opened on rank 0");
  PetscCall(ierr);
  PetscCall(BroadcastRows(*b));
  PetscCall(TaskFarmCreate(world, 1, &b->farm));
  if (!b->parts.empty()) {
    b->journal.path      = SweepJournalName(s.store, b->run, b->rank);
    b->journal.signature = b->signature;
    b->journal.ncols     = (uint32_t)(2 + s.columns.size());
  }
  PetscFunctionReturn(0);
}

// ---------------------------------------------------------------------------
// Running a batch
// ---------------------------------------------------------------------------

namespace {

// The case as a one-point sweep plan: an axis per setting (a text value a text axis), each with
// the value the options also give (put back after the case).
PetscErrorCode CasePlan(CaseBatch &b, const CaseOptions &c, SweepPlan *plan)
{
  PetscFunctionBeginUser;
  plan->axes.clear();
  for (const CaseSetting &s : c) {
    auto it = b.given.find(s.name);
    if (it == b.given.end()) { // first seen: what the options give for it (the database as it is between cases)
      SweepAxis         a;
      std::vector<char> given(1 << 16, 0);
      PetscBool         has = PETSC_FALSE;
      a.name                = s.name;
      a.unit                = SweepOptionUnit(s.name);
      PetscCall(PetscOptionsGetString(NULL, NULL, ("-" + s.name).c_str(), given.data(), given.size(), &has));
      a.overrides = has == PETSC_TRUE;
      a.given     = has ? given.data() : "";
      it          = b.given.emplace(s.name, a).first;
    }
    SweepAxis a = it->second;
    a.spec      = s.Value();
    if (s.text.empty()) a.values = {s.value};
    else a.values = {0}, a.labels = {s.text};
    plan->axes.push_back(a);
  }
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-rigid_loss_fraction", &plan->rigid_loss_fraction, NULL));
  PetscFunctionReturn(0);
}

// One case on this rank: its row, journaled (the key and the case in the record's text).
PetscErrorCode RunOne(CaseBatch &b, const CaseOptions &c, const std::string &key, double ordinal, CaseRow *row)
{
  SweepPlan                plan;
  std::vector<std::string> names;

  PetscFunctionBeginUser;
  for (const CaseSetting &s : c) names.push_back(s.name);
  if (names != b.state.names)
    b.state = CaseRunState(), b.state.names = names; // other options: the kept structure may not be theirs
  PetscCall(CasePlan(b, c, &plan));
  *row = CaseRow();
  PetscCall(b.settings.task->run(PETSC_COMM_SELF, plan, b.settings.columns, &b.state, row));
  for (const SweepAxis &a :
       plan.axes) { // a value the options gave, put back after the case: used (the case read its own)
    PetscBool has;
    if (a.overrides) PetscCall(PetscOptionsHasName(NULL, NULL, ("-" + a.name).c_str(), &has));
  }
  SweepNotesPointDone(true);
  if (!b.parts.empty()) {
    std::vector<double> record = {ordinal, (double)row->status};
    record.insert(record.end(), row->values.begin(), row->values.end());
    PetscCall(b.journal.Append(record, key + "\t" + OneLine(CaseOptionsText(c)) + "\t" + OneLine(row->reason)));
  }
  ++b.computed_here;
  PetscCheck(b.settings.stop_after <= 0 || b.computed_here < b.settings.stop_after, PETSC_COMM_SELF, PETSC_ERR_USER,
             "-%s_stop_after %" PetscInt_FMT ": stopped after %" PetscInt_FMT
             " runs on rank %d, as asked (a test of the resume: the journals in %s keep them)",
             b.settings.who.c_str(), b.settings.stop_after, b.computed_here, (int)b.rank,
             b.parts.empty() ? "(none: no -output)" : b.parts.c_str());
  PetscFunctionReturn(0);
}

// Every rank's new rows to every rank: numbers [todo index, status, values...] and the reasons.
PetscErrorCode GatherRows(CaseBatch &b, const std::vector<double> &mine, const std::string &mine_text,
                          std::vector<double> *all, std::string *all_text)
{
  std::vector<int> counts(b.size), displs(b.size), tcounts(b.size), tdispls(b.size);
  int              n = (int)mine.size(), nt = (int)mine_text.size();

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, b.world));
  PetscCallMPI(MPI_Allgather(&nt, 1, MPI_INT, tcounts.data(), 1, MPI_INT, b.world));
  int total = 0, ttotal = 0;
  for (int r = 0; r < b.size; ++r) displs[r] = total, total += counts[r], tdispls[r] = ttotal, ttotal += tcounts[r];
  all->resize((size_t)total);
  all_text->assign((size_t)ttotal, '\0');
  PetscCallMPI(
    MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all->data(), counts.data(), displs.data(), MPI_DOUBLE, b.world));
  PetscCallMPI(MPI_Allgatherv(mine_text.data(), nt, MPI_CHAR, ttotal ? &(*all_text)[0] : nullptr, tcounts.data(),
                              tdispls.data(), MPI_CHAR, b.world));
  PetscFunctionReturn(0);
}

// The ranks must ask for the same cases (their optimisers run the same numbers): a check.
PetscErrorCode CheckSameCases(CaseBatch &b, const std::vector<std::string> &keys)
{
  PetscFunctionBeginUser;
  if (b.size == 1) PetscFunctionReturn(0);
  std::string all;
  for (const std::string &k : keys) all += k;
  unsigned long long h = std::strtoull(Sha256Hex(all).substr(0, 15).c_str(), nullptr, 16), lo = h, hi = h;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, b.world));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, b.world));
  PetscCheck(lo == hi, b.world, PETSC_ERR_PLIB,
             "case batch: the ranks asked for different cases (their %ss diverged); please report this",
             b.settings.who.c_str());
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode CaseBatchRun(CaseBatch &b, const std::vector<CaseOptions> &cases, std::vector<CaseRow> *rows)
{
  std::vector<std::string> keys(cases.size());
  std::vector<size_t>      todo; // the first case of each key not known
  std::set<std::string>    queued;
  std::vector<double>      mine, all;
  std::string              mine_text, all_text;
  const double             t0 = MPI_Wtime();

  PetscFunctionBeginUser;
  for (size_t i = 0; i < cases.size(); ++i) {
    keys[i] = CaseBatchKey(b, cases[i]);
    if (!b.rows.count(keys[i]) && queued.insert(keys[i]).second) todo.push_back(i);
  }
  PetscCall(CheckSameCases(b, keys));
  b.counts.reused += (PetscInt)(cases.size() - todo.size());
  const size_t nv  = b.settings.columns.size();
  auto         run = [&](MPI_Comm, PetscInt t) -> PetscErrorCode {
    CaseRow      row;
    const double tr = MPI_Wtime();
    PetscFunctionBeginUser;
    PetscCall(RunOne(b, cases[todo[t]], keys[todo[t]], b.next_ordinal + t, &row));
    b.counts.run_time += MPI_Wtime() - tr;
    mine.push_back((double)t);
    mine.push_back((double)row.status);
    mine.insert(mine.end(), row.values.begin(), row.values.end());
    mine_text += std::to_string((long long)t) + "\t" + OneLine(row.reason) + "\n";
    PetscFunctionReturn(0);
  };
  auto between = [](PetscInt) -> PetscErrorCode { return 0; };
  if (!todo.empty()) {
    SweepNotesCollect();
    PetscCall(TaskFarmRun(b.farm, (PetscInt)todo.size(), run, between));
  }
  PetscCall(GatherRows(b, mine, mine_text, &all, &all_text));
  std::map<size_t, std::string> reasons;
  std::istringstream            lines(all_text);
  for (std::string line; std::getline(lines, line);) {
    const size_t tab = line.find('\t');
    if (tab != std::string::npos) reasons[(size_t)std::stoll(line.substr(0, tab))] = line.substr(tab + 1);
  }
  for (size_t p = 0; p + 2 + nv <= all.size(); p += 2 + nv) {
    const size_t t = (size_t)all[p];
    CaseRow      row;
    row.status = (int)all[p + 1];
    row.values.assign(all.begin() + p + 2, all.begin() + p + 2 + nv);
    row.reason             = reasons[t];
    b.rows[keys[todo[t]]]  = row;
    b.cases[keys[todo[t]]] = CaseOptionsText(cases[todo[t]]);
  }
  b.next_ordinal += (double)todo.size();
  b.counts.computed += (PetscInt)todo.size();
  rows->clear();
  for (const std::string &k : keys) rows->push_back(b.rows.at(k));
  b.counts.wall += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode CaseBatchWrite(const CaseBatch &b, long long file)
{
  std::vector<std::string>         keys, cases, reasons;
  std::vector<double>              status;
  std::vector<std::vector<double>> cols(b.settings.columns.size());

  PetscFunctionBeginUser;
  for (auto &kv : b.rows) {
    keys.push_back(kv.first);
    const auto c = b.cases.find(kv.first);
    cases.push_back(c == b.cases.end() ? std::string() : c->second);
    reasons.push_back(kv.second.reason);
    status.push_back(kv.second.status);
    for (size_t k = 0; k < cols.size(); ++k) cols[k].push_back(kv.second.values[k]);
  }
  const hid_t g = H5Gcreate2((hid_t)file, "case_batch", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /case_batch");
  const std::vector<std::string> layout = {std::string(b.settings.task->name) + ":" + Join(b.settings.columns, ",")};
  const char *const              layout_unit = "text (the task and the columns of the rows: task:column,column,...)";
  bool                           ok          = H5WriteStringColumn(g, "layout", layout, layout_unit) &&
            H5WriteStringColumn(g, "key", keys,
                                "text (SHA-256 of the run's complete options: studies/case_batch.hpp)") &&
            H5WriteStringColumn(g, "case", cases, "text (the options the case set)") &&
            H5WriteStringColumn(g, "reason", reasons, "text (the error of a failed run; empty where status = 0)");
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write /case_batch");
  PetscCall(H5WriteCounts1D(g, "status", status, "1"));
  for (size_t k = 0; k < cols.size(); ++k) {
    std::string unit, why;
    b.settings.task->column(b.settings.columns[k], &unit, &why);
    PetscCall(H5WriteDataset1D(g, b.settings.columns[k].c_str(), cols[k], unit.c_str()));
  }
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode CaseBatchFinish(CaseBatch &b)
{
  PetscFunctionBeginUser;
  b.journal.Close();
  if (b.rank == 0 && !b.parts.empty())
    for (const std::string &path : SweepJournalFiles(b.parts, nullptr)) ::unlink(path.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode CaseBatchGetCounts(const CaseBatch &b, CaseBatchCounts *c)
{
  PetscFunctionBeginUser;
  *c = b.counts;
  PetscCallMPI(MPI_Allreduce(&b.counts.run_time, &c->run_time, 1, MPI_DOUBLE, MPI_SUM, b.world));
  PetscFunctionReturn(0);
}

void CaseBatchRelease(CaseBatch *b)
{
  b->journal.Close();
  if (b->lock_fd >= 0) {
    ::unlink((b->parts + "/lock").c_str()); // while still held
    ::close(b->lock_fd);
    b->lock_fd = -1;
    ::rmdir(b->parts.c_str()); // only when empty: the journals of a resumable run stay
  }
}

PetscErrorCode CaseBatchDestroy(CaseBatch *b)
{
  PetscFunctionBeginUser;
  CaseBatchRelease(b);
  PetscCall(TaskFarmDestroy(&b->farm));
  b->world = MPI_COMM_NULL;
  PetscFunctionReturn(0);
}

} // namespace beamimpact

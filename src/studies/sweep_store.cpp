// The store of a sweep's rows: journals, atomic rewrites, signature and resume. See sweep_store.hpp.
#include "studies/sweep_store.hpp"

#include "base/option_table.hpp"
#include "io/h5_dims.hpp"
#include "io/options_files.hpp"
#include "io/results_h5.hpp"
#include "io/text.hpp"
#include "run/impact.hpp"

#include <hdf5.h>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

namespace beamimpact {

// ---------------------------------------------------------------------------
// Journal: per-leader append-only files of self-checking records
// ---------------------------------------------------------------------------

namespace {

uint64_t Fnv1a(const void *data, size_t n, uint64_t h = 1469598103934665603ULL)
{
  const unsigned char *p = static_cast<const unsigned char *>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

const char     JournalMagic[8] = {'B', 'I', 'S', 'W', 'J', 'N', 'L', '2'};
const uint32_t RecordMagic     = 0x574f5253u;
const uint32_t ReasonMax       = 4096; // bytes of a record's reason text

struct JournalHeader {
  char     magic[8];
  uint64_t signature;
  uint32_t ncols;
  uint32_t reserved;
  uint64_t check; // Fnv1a of the fields above
};

// A record: magic, reason length, the row's numbers, the reason's bytes, the checksum.
size_t RecordBytes(uint32_t ncols, uint32_t reason)
{
  return 2 * sizeof(uint32_t) + ncols * sizeof(double) + reason + sizeof(uint64_t);
}

bool WriteAll(int fd, const void *data, size_t n)
{
  const char *p = static_cast<const char *>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    n -= (size_t)w;
  }
  return true;
}

bool ParseJournalName(const char *name, int *run, int *rank)
{
  char tail[8] = "";
  return std::sscanf(name, "run%d-rank%d.%7s", run, rank, tail) == 3 && std::string(tail) == "bin";
}

// ---------------------------------------------------------------------------
// Parameter signature: what must be equal for a resume
// ---------------------------------------------------------------------------

// Options that do not change any number in the file.
bool OptionIsVolatile(const std::string &name)
{
  // clang-format off
  static const std::set<std::string> exact = {"output",
                                                 "sweep_quiet",
                                                 "sweep_restart",
                                                 "sweep_retry_failed",
                                                 "sweep_progress_interval",
                                                 "sweep_write_interval",
                                                 "sweep_exceedance",
                                                 "sweep_bootstrap",
                                                 "error_traceback",
                                                 "allow_unused_options",
                                                 "help",
                                                 "version"};
  static const char *const prefix[] = {"log_", "malloc", "info", "options_", "on_error", "mpi_", "viewer_",
                                       "ts_monitor", "ts_adapt_monitor", "snes_monitor", "ksp_monitor", "ts_view",
                                       "snes_view", "ksp_view"};
  // clang-format on
  if (exact.count(name)) return true;
  if (name == "max_memory" || name == "flight_series_dt")
    return true; // a limit on what may be allocated; a series a sweep does not keep
  for (const char *p : prefix)
    if (name.compare(0, std::strlen(p), p) == 0) return true;
  return false;
}

// "-name value -name2 -name3 value3 ..." (PetscOptionsGetAll, sorted) -> name -> value.
std::map<std::string, std::string> ParseOptions(const std::string &all)
{
  std::map<std::string, std::string> m;
  std::stringstream                  ss(all);
  std::string                        tok, name;
  auto                               is_name = [](const std::string &t) {
    return t.size() > 1 && t[0] == '-' && (std::isalpha((unsigned char)t[1]) || t[1] == '_');
  };
  while (ss >> tok) {
    if (is_name(tok)) {
      name    = tok.substr(1);
      m[name] = "";
    } else if (!name.empty()) m[name] += (m[name].empty() ? "" : " ") + tok;
  }
  return m;
}

// An attribute that holds the path an option names (ball_cor_table, beam_profile, ...).
bool IsFileOption(const std::string &key)
{
  const std::vector<std::string> &files = OptionsFilePathOptions();
  return std::find(files.begin(), files.end(), "-" + key) != files.end();
}

// Attributes that change while a sweep runs, or with options that do not matter.
bool AttributeIsVolatile(const std::string &key)
{
  // The paths of the input files are not the signature, their contents are (input_sha256_*).
  return key == "options" || key == "sweep_cases_done" || key == "sweep_complete" || key == "date" || key == "host" ||
         key == "ranks" || key == "git" || key == "input_files" || key == "beam_section_file" ||
         key == "sweep_retry_changed" || IsFileOption(key);
}

// The input file an attribute input_sha256_<...> stands for, from the record's input_files
// lines ("-option path sha256"): "-option path", or the option alone.
std::string InputFileOfAttribute(const std::string &key, const std::string &input_files)
{
  std::vector<InputFile> files;
  std::istringstream     lines(input_files);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream w(line);
    InputFile          f;
    if (w >> f.option >> f.path) files.push_back(f);
  }
  const std::vector<std::string> names = RunInputAttributeNames(files);
  for (size_t k = 0; k < files.size(); ++k)
    if (names[k] == key) return files[k].option + " " + files[k].path;
  return "-" + key.substr(std::strlen("input_sha256_"));
}

// An option's value by its numbers ("1.0,3" -> "1,3", ShortestText) when every comma-separated
// part is one; else as written.
std::string CanonicalValue(const std::string &value)
{
  std::string       out, part;
  std::stringstream parts(value);
  while (std::getline(parts, part, ',')) {
    const std::string t   = Trim(part);
    char             *end = nullptr;
    const double      v   = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0') return value;
    out += (out.empty() ? "" : ",") + ShortestText(v);
  }
  return out.empty() ? value : out;
}

// Whether a program option given at `value` (canonical) is at its row's default: the same run as
// without it. PETSc's rows and flags are not: a flag given is not its absence, and PETSc's
// defaults are PETSc's (the rows' defaults are the program's, checked against the code by
// tests/test_options.cpp).
bool AtDefault(const std::string &name, const std::string &value)
{
  const OptionModule *m = OptionModuleOf(name);
  const OptionSpec   *s = m ? m->Find("-" + name) : nullptr;
  return s && !m->petsc && s->kind != OptionKind::Bool && !s->def.empty() && CanonicalValue(s->def) == value;
}

// The plan by its values, however written: "ball_speed=1;3" for -sweep "ball_speed=1.0;3.0" or
// "ball_speed=1:3:2", -sweep_x first as impact_x; "" and the text as written when it does not parse.
std::string CanonicalPlan(const std::string &sweep_x, const std::string &sweep)
{
  std::vector<SweepAxis> axes;
  std::string            why, out;
  if (!sweep_x.empty()) {
    SweepAxis a;
    a.name = "impact_x";
    if (!SweepParsePoints(sweep_x, &a.values, &why, "m")) return "-sweep_x " + sweep_x + " -sweep " + sweep;
    axes.push_back(a);
  }
  if (!sweep.empty() && !SweepParseAxes(sweep, &axes, &why)) return "-sweep_x " + sweep_x + " -sweep " + sweep;
  for (const SweepAxis &a : axes) {
    out += (out.empty() ? "" : ",") + a.name + "=";
    for (size_t k = 0; k < (a.Text() ? a.labels.size() : a.values.size()); ++k)
      out += (k ? ";" : "") + (a.Text() ? a.labels[k] : ShortestText(a.values[k]));
  }
  return out;
}

// The signature as what decides the numbers, not how the options were written (both the file's
// and this run's, before hashing: equal for runs that compute the same): the plan by its values
// (sweep: the axes and their values, -sweep_x's first, in place of -sweep and -sweep_x as written); in
// sweep_checked_options numbers by their values, an option at its default left out (as not given), and the options the
// run did not read left out (sweep_unused_options: -ts_theta_theta under -ts_type rk, an option of another task).
void SignatureCanonical(SweepAttributes *m)
{
  if (m->str.count("sweep") || m->str.count("sweep_x")) {
    const std::string plan = CanonicalPlan(m->str["sweep_x"], m->str["sweep"]);
    m->str.erase("sweep_x");
    m->str["sweep"] = plan;
  }
  std::set<std::string> unused;
  for (auto &kv : ParseOptions(m->str["sweep_unused_options"])) unused.insert(kv.first);
  m->str.erase("sweep_unused_options");
  const auto it = m->str.find("sweep_checked_options");
  if (it == m->str.end()) return;
  std::string out;
  for (auto &kv : ParseOptions(it->second)) {
    const std::string value = CanonicalValue(kv.second);
    if (kv.first == "sweep" || kv.first == "sweep_x" || unused.count(kv.first) || AtDefault(kv.first, value)) continue;
    out += "-" + kv.first + (value.empty() ? "" : " " + value) + " ";
  }
  it->second = out;
}

SweepAttributes SignatureMaps(const RunRecord &rec)
{
  SweepAttributes m;
  for (auto &kv : rec.numbers)
    if (!AttributeIsVolatile(kv.first)) m.num[kv.first] = kv.second;
  for (auto &kv : rec.integers) // read back from the file as doubles too (CollectAttribute)
    if (!AttributeIsVolatile(kv.first)) m.num[kv.first] = (double)kv.second;
  for (auto &kv : rec.strings)
    if (!AttributeIsVolatile(kv.first)) m.str[kv.first] = kv.second;
  SignatureCanonical(&m);
  return m;
}

uint64_t SignatureHash(const SweepAttributes &m)
{
  uint64_t h = Fnv1a("beamimpact-sweep", 16);
  for (auto &kv : m.num) {
    h = Fnv1a(kv.first.data(), kv.first.size(), h);
    h = Fnv1a(&kv.second, sizeof(double), h);
  }
  for (auto &kv : m.str) {
    h = Fnv1a(kv.first.data(), kv.first.size() + 1, h);
    h = Fnv1a(kv.second.data(), kv.second.size() + 1, h);
  }
  return h;
}

std::string RecordString(const RunRecord &rec, const char *key)
{
  for (auto &kv : rec.strings)
    if (kv.first == key) return kv.second;
  return "";
}

std::string ShortValue(const std::string &s) { return s.size() > 60 ? s.substr(0, 57) + "..." : s; }

// Two canonical plans (CanonicalPlan: "name=v1;v2,name2=...") compared axis by axis: "sweep
// axis ball_speed: '1;2' in the file, '1;2.5' now", a long list of values cut after the first
// that differs ("... (value 7: 0.6 in the file, 0.61 now)").
std::vector<std::string> PlanDiff(const std::string &file, const std::string &now)
{
  auto axes = [](const std::string &plan) {
    std::vector<std::pair<std::string, std::string>> out;
    std::stringstream                                ss(plan);
    for (std::string item; std::getline(ss, item, ',');) {
      const size_t eq = item.find('=');
      out.emplace_back(item.substr(0, eq), eq == std::string::npos ? "" : item.substr(eq + 1));
    }
    return out;
  };
  const auto               fa = axes(file), na = axes(now);
  std::vector<std::string> d;
  if (fa.size() != na.size())
    d.push_back("sweep: " + std::to_string(fa.size()) + " axes in the file ('" + ShortValue(file) + "'), " +
                std::to_string(na.size()) + " now ('" + ShortValue(now) + "')");
  for (size_t k = 0; k < std::min(fa.size(), na.size()); ++k) {
    if (fa[k] == na[k]) continue;
    if (fa[k].first != na[k].first) {
      d.push_back("sweep axis " + std::to_string(k + 1) + ": " + fa[k].first + " in the file, " + na[k].first + " now");
      continue;
    }
    std::vector<std::string> fv, nv;
    std::stringstream        fs(fa[k].second), ns(na[k].second);
    for (std::string v; std::getline(fs, v, ';');) fv.push_back(v);
    for (std::string v; std::getline(ns, v, ';');) nv.push_back(v);
    size_t i = 0;
    while (i < fv.size() && i < nv.size() && fv[i] == nv[i]) ++i;
    std::string line = "sweep axis " + fa[k].first + ": '" + ShortValue(fa[k].second) + "' in the file, '" +
                       ShortValue(na[k].second) + "' now";
    if (fv.size() != nv.size())
      line += " (" + std::to_string(fv.size()) + " values in the file, " + std::to_string(nv.size()) + " now)";
    else if (ShortValue(fa[k].second) == ShortValue(na[k].second))
      line += " (value " + std::to_string(i + 1) + ": " + fv[i] + " in the file, " + nv[i] + " now)";
    d.push_back(line);
  }
  return d;
}

// Human-readable differences between the stored and the current signature.
std::string SignatureDiff(const SweepAttributes &file, const SweepAttributes &now, const std::string &input_files)
{
  std::vector<std::string> d;
  char                     buf[512];
  std::set<std::string>    keys;
  for (auto &kv : file.num) keys.insert(kv.first);
  for (auto &kv : now.num) keys.insert(kv.first);
  for (auto &k : keys) {
    if (AttributeIsVolatile(k)) continue;
    const auto a = file.num.find(k), b = now.num.find(k);
    if (a != file.num.end() && b != now.num.end() &&
        (a->second == b->second || (std::isnan(a->second) && std::isnan(b->second))))
      continue;
    std::snprintf(buf, sizeof(buf), "%s: %s in the file, %s now", k.c_str(),
                  a == file.num.end() ? "absent" : std::to_string(a->second).c_str(),
                  b == now.num.end() ? "absent" : std::to_string(b->second).c_str());
    if (a != file.num.end() && b != now.num.end())
      std::snprintf(buf, sizeof(buf), "%s: %.10g in the file, %.10g now", k.c_str(), a->second, b->second);
    d.push_back(buf);
  }
  keys.clear();
  for (auto &kv : file.str) keys.insert(kv.first);
  for (auto &kv : now.str) keys.insert(kv.first);
  for (auto &k : keys) {
    if (AttributeIsVolatile(k)) continue;
    const auto a = file.str.find(k), b = now.str.find(k);
    if (a != file.str.end() && b != now.str.end() && a->second == b->second) continue;
    if (k.compare(0, std::strlen("input_sha256_"), "input_sha256_") == 0) { // an input file's contents
      const std::string which = InputFileOfAttribute(k, input_files);
      if (a == file.str.end() || b == now.str.end())
        std::snprintf(buf, sizeof(buf), "input file %s: %s", which.c_str(),
                      a == file.str.end() ? "read now, not by the sweep that wrote the file"
                                          : "read by the sweep that wrote the file, not now");
      else
        std::snprintf(buf, sizeof(buf),
                      "input file %s: its contents changed since the file was written (SHA-256 %.12s... in the file, "
                      "%.12s... now)",
                      which.c_str(), a->second.c_str(), b->second.c_str());
      d.push_back(buf);
      continue;
    }
    if (k == "sweep" && a != file.str.end() && b != now.str.end()) { // the plans (SignatureCanonical), axis by axis
      for (const std::string &line : PlanDiff(a->second, b->second)) d.push_back(line);
      continue;
    }
    if (k == "sweep_checked_options" && a != file.str.end() && b != now.str.end()) {
      const auto            fo = ParseOptions(a->second), no = ParseOptions(b->second);
      std::set<std::string> names;
      for (auto &kv : fo) names.insert(kv.first);
      for (auto &kv : no) names.insert(kv.first);
      for (auto &n : names) {
        const auto x = fo.find(n), y = no.find(n);
        if (x != fo.end() && y != no.end() && x->second == y->second) continue;
        std::snprintf(buf, sizeof(buf), "option -%s: %s in the file, %s now", n.c_str(),
                      x == fo.end() ? "not set" : ("'" + x->second + "'").c_str(),
                      y == no.end() ? "not set" : ("'" + y->second + "'").c_str());
        d.push_back(buf);
      }
      continue;
    }
    std::snprintf(buf, sizeof(buf), "%s: %s in the file, %s now", k.c_str(),
                  a == file.str.end() ? "absent" : ("'" + ShortValue(a->second) + "'").c_str(),
                  b == now.str.end() ? "absent" : ("'" + ShortValue(b->second) + "'").c_str());
    d.push_back(buf);
  }
  std::string out;
  for (size_t i = 0; i < d.size() && i < 12; ++i) out += "\n  " + d[i];
  if (d.size() > 12) out += "\n  ... (" + std::to_string(d.size() - 12) + " more)";
  return out;
}

// The options a failed row's reason names ("-impact_max_contacts", "-impact_max_time", ...), as
// names without the dash: what -sweep_retry_failed may change.
std::set<std::string> OptionsNamed(const std::map<PetscInt, std::string> &reasons)
{
  std::set<std::string> names;
  for (auto &kv : reasons) {
    const std::string &r = kv.second;
    for (size_t i = 0; (i = r.find('-', i)) != std::string::npos; ++i) {
      if (i > 0 && (std::isalnum((unsigned char)r[i - 1]) || r[i - 1] == '-')) continue;
      size_t j = i + 1;
      while (j < r.size() && (std::isalnum((unsigned char)r[j]) || r[j] == '_')) ++j;
      if (j > i + 2 && std::isalpha((unsigned char)r[i + 1])) names.insert(r.substr(i + 1, j - i - 1));
    }
  }
  return names;
}

// Whether an attribute belongs to one of the options named: the attribute of the option's own
// name or one derived from it (impact_max_time_default).
bool AttributeOfOptions(const std::string &key, const std::set<std::string> &options)
{
  for (const std::string &o : options)
    if (key == o || key.compare(0, o.size() + 1, o + "_") == 0) return true;
  return false;
}

// The signatures differ only in the options named (and their attributes): "" when so, else
// what else differs (SignatureDiff's lines).
std::string DiffBeyond(const SweepAttributes &file, const SweepAttributes &now, const std::set<std::string> &options,
                       std::string *changed)
{
  SweepAttributes a = file, b = now;
  for (auto *m : {&a, &b}) {
    for (auto it = m->num.begin(); it != m->num.end();)
      it = AttributeOfOptions(it->first, options) ? m->num.erase(it) : std::next(it);
    for (auto it = m->str.begin(); it != m->str.end();)
      it = AttributeOfOptions(it->first, options) ? m->str.erase(it) : std::next(it);
  }
  auto fo = ParseOptions(a.str["sweep_checked_options"]), no = ParseOptions(b.str["sweep_checked_options"]);
  for (const std::string &o : options) {
    if (fo[o] != no[o])
      *changed += (changed->empty() ? "" : "; ") + ("-" + o + " " + (fo[o].empty() ? "(default)" : fo[o]) + " -> " +
                                                    (no[o].empty() ? "(default)" : no[o]));
    fo.erase(o), no.erase(o);
  }
  auto join = [](const std::map<std::string, std::string> &m) {
    std::string t;
    for (auto &kv : m) t += "-" + kv.first + (kv.second.empty() ? "" : " " + kv.second) + " ";
    return t;
  };
  a.str["sweep_checked_options"] = join(fo), b.str["sweep_checked_options"] = join(no);
  return SignatureHash(a) == SignatureHash(b) ? std::string() : SignatureDiff(a, b, "");
}

// ---------------------------------------------------------------------------
// HDF5: atomic rewrite and read-back
// ---------------------------------------------------------------------------

herr_t CollectAttribute(hid_t loc, const char *name, const H5A_info_t *, void *op)
{
  SweepAttributes *m     = static_cast<SweepAttributes *>(op);
  hid_t            a     = H5Aopen(loc, name, H5P_DEFAULT);
  hid_t            t     = H5Aget_type(a);
  hid_t            s     = H5Aget_space(a);
  H5T_class_t      cls   = H5Tget_class(t);
  hssize_t         count = H5Sget_simple_extent_npoints(s);
  if ((cls == H5T_FLOAT || cls == H5T_INTEGER) && count == 1) {
    double v = 0;
    if (H5Aread(a, H5T_NATIVE_DOUBLE, &v) >= 0) m->num[name] = v;
  } else if (cls == H5T_STRING && count == 1) {
    if (H5Tis_variable_str(t) > 0) {
      char *p  = nullptr;
      hid_t mt = H5Tcopy(H5T_C_S1);
      H5Tset_size(mt, H5T_VARIABLE);
      if (H5Aread(a, mt, &p) >= 0 && p) {
        m->str[name] = p;
        H5free_memory(p);
      }
      H5Tclose(mt);
    } else {
      std::vector<char> buf(H5Tget_size(t) + 1, 0);
      if (H5Aread(a, t, buf.data()) >= 0) m->str[name] = std::string(buf.data());
    }
  }
  H5Sclose(s);
  H5Tclose(t);
  H5Aclose(a);
  return 0;
}

bool ReadDataset(hid_t g, const char *name, std::vector<double> *v) { return H5ReadDoubleColumn(g, name, v); }

} // namespace

bool H5ReadDoubleColumn(long long loc, const char *name, std::vector<double> *v)
{
  const hid_t g = (hid_t)loc;
  if (H5Lexists(g, name, H5P_DEFAULT) <= 0) return false;
  hid_t ds = H5Dopen2(g, name, H5P_DEFAULT);
  if (ds < 0) return false;
  hid_t          s = H5Dget_space(ds);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  v->assign((size_t)std::max<hssize_t>(0, n), 0.0);
  const bool ok = n <= 0 || H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v->data()) >= 0;
  H5Sclose(s);
  H5Dclose(ds);
  return ok;
}

// ---------------------------------------------------------------------------
// Journal files and checked options
// ---------------------------------------------------------------------------

std::string SweepJournalName(const std::string &output, int run, int rank)
{
  char name[64];
  std::snprintf(name, sizeof(name), ".parts/run%06d-rank%06d.bin", run, rank);
  return output + name;
}

void SweepJournalWriter::Warn(const char *what)
{
  if (!failed) {
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    std::fprintf(stderr,
                 "beamimpact: warning: rank %d cannot %s the sweep journal %s (%s): its points are kept in memory and "
                 "written at the end, but would be computed again after a crash (is -output on a filesystem every rank "
                 "sees?)\n",
                 rank, what, path.c_str(), std::strerror(errno));
  }
  failed = true;
  if (fd >= 0) ::close(fd);
  fd = -1;
}

PetscErrorCode SweepJournalWriter::Append(const std::vector<double> &row, const std::string &reason_in)
{
  PetscFunctionBeginUser;
  PetscCheck(row.size() == ncols, PETSC_COMM_SELF, PETSC_ERR_PLIB, "sweep row has %zu columns, the journal %u",
             row.size(), ncols);
  if (failed) PetscFunctionReturn(0);
  if (fd < 0) {
    fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) {
      Warn("create");
      PetscFunctionReturn(0);
    }
    JournalHeader h;
    std::memset(&h, 0, sizeof(h));
    std::memcpy(h.magic, JournalMagic, sizeof(h.magic));
    h.signature = signature;
    h.ncols     = ncols;
    h.check     = Fnv1a(&h, offsetof(JournalHeader, check));
    if (!WriteAll(fd, &h, sizeof(h))) {
      Warn("write");
      PetscFunctionReturn(0);
    }
  }
  const std::string reason = reason_in.substr(0, ReasonMax);
  std::vector<char> rec(RecordBytes(ncols, (uint32_t)reason.size()));
  uint32_t          head[2] = {RecordMagic, (uint32_t)reason.size()};
  std::memcpy(rec.data(), head, sizeof(head));
  std::memcpy(rec.data() + sizeof(head), row.data(), ncols * sizeof(double));
  std::memcpy(rec.data() + sizeof(head) + ncols * sizeof(double), reason.data(), reason.size());
  const uint64_t check = Fnv1a(rec.data(), rec.size() - sizeof(uint64_t));
  std::memcpy(rec.data() + rec.size() - sizeof(uint64_t), &check, sizeof(check));
  // One write() per record: a kill leaves whole records and at most one cut one.
  if (!WriteAll(fd, rec.data(), rec.size())) Warn("write");
  PetscFunctionReturn(0);
}

void SweepJournalWriter::Close()
{
  if (fd >= 0) ::close(fd);
  fd = -1;
}

SweepJournalReader::Status SweepJournalReader::ReadNew(uint64_t expected_signature, uint32_t ncols, PetscInt ncases,
                                                       std::map<PetscInt, std::vector<double>> *rows,
                                                       std::map<PetscInt, std::string> *reasons, PetscInt *added)
{
  if (stopped) return Ok;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Missing;
  struct stat st;
  if (::fstat(fd, &st) != 0) {
    ::close(fd);
    return Missing;
  }
  std::vector<char> data((size_t)std::max<off_t>(0, st.st_size - offset));
  size_t            got = 0;
  while (got < data.size()) {
    const ssize_t r = ::pread(fd, data.data() + got, data.size() - got, offset + (off_t)got);
    if (r <= 0) break;
    got += (size_t)r;
  }
  ::close(fd);
  data.resize(got);
  size_t pos = 0;
  if (!header_ok) {
    if (data.size() < sizeof(JournalHeader)) return Ok; // not yet written
    JournalHeader h;
    std::memcpy(&h, data.data(), sizeof(h));
    if (std::memcmp(h.magic, JournalMagic, sizeof(h.magic)) != 0 ||
        h.check != Fnv1a(&h, offsetof(JournalHeader, check))) {
      stopped = true;
      return Ok;
    }
    signature = h.signature;
    if (h.signature != expected_signature || h.ncols != ncols) return WrongParameters;
    header_ok = true;
    pos       = sizeof(JournalHeader);
  }
  while (pos + RecordBytes(ncols, 0) <= data.size()) {
    const char *r = data.data() + pos;
    uint32_t    head[2];
    uint64_t    check;
    std::memcpy(head, r, sizeof(head));
    if (head[0] != RecordMagic || head[1] > ReasonMax) {
      stopped = true;
      break;
    }
    const size_t rb = RecordBytes(ncols, head[1]);
    if (pos + rb > data.size()) break; // not yet written in full: read next time
    std::memcpy(&check, r + rb - sizeof(uint64_t), sizeof(check));
    if (check != Fnv1a(r, rb - sizeof(uint64_t))) {
      stopped = true;
      break;
    }
    std::vector<double> row(ncols);
    std::memcpy(row.data(), r + sizeof(head), ncols * sizeof(double));
    const double idx = row[0];
    if (!(idx >= 0 && idx < ncases && idx == std::floor(idx))) {
      stopped = true;
      break;
    }
    if (rows->emplace((PetscInt)idx, std::move(row)).second) {
      if (head[1]) (*reasons)[(PetscInt)idx] = std::string(r + sizeof(head) + ncols * sizeof(double), head[1]);
      if (added) ++*added;
    }
    pos += rb;
  }
  offset += (off_t)pos;
  return Ok;
}

std::map<std::string, std::string> SweepOptionsParse(const std::string &all) { return ParseOptions(all); }

std::string SweepCheckedOptions(const std::string &all)
{
  std::string out;
  for (auto &kv : ParseOptions(all)) {
    if (OptionIsVolatile(kv.first)) continue;
    const std::vector<std::string>
      &files = OptionsFilePathOptions(); // their contents are checked (input_sha256_*), not their paths
    if (std::find(files.begin(), files.end(), "-" + kv.first) != files.end()) continue;
    out += "-" + kv.first + (kv.second.empty() ? "" : " " + kv.second) + " ";
  }
  return out;
}

// ---------------------------------------------------------------------------
// The store
// ---------------------------------------------------------------------------

void SweepStoreInit(const std::string &output, const SweepPlan &plan, const std::vector<SweepColumn> &columns,
                    const RunRecord &record, SweepStore *S)
{
  S->output         = output;
  S->parts          = output + ".parts";
  S->plan           = plan;
  S->columns        = columns;
  S->record         = record;
  S->ncases         = plan.cases();
  S->ncols          = (uint32_t)columns.size();
  S->signature      = SignatureMaps(record);
  S->signature_hash = SignatureHash(S->signature);
  S->status_column  = -1;
  for (size_t c = 0; c < columns.size(); ++c)
    if (columns[c].name == "status") S->status_column = (int)c;
}

// Every /results dataset has a unit; the reasons' and text axes' is this text.
static const char *const kReasonUnit = "text (the error of a failed point; empty where status = 0)";

bool H5WriteStringColumn(long long loc, const char *name, const std::vector<std::string> &v, const char *unit_text)
{
  return H5WriteText1D(loc, name, v, unit_text) == 0;
}

bool H5ReadStringColumn(long long loc, const char *name, std::vector<std::string> *v)
{
  const hid_t g = (hid_t)loc;
  v->clear();
  if (H5Lexists(g, name, H5P_DEFAULT) <= 0) return false;
  hid_t d = H5Dopen2(g, name, H5P_DEFAULT);
  if (d < 0) return false;
  hid_t          s = H5Dget_space(d);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  hid_t          t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  std::vector<char *> p((size_t)std::max<hssize_t>(0, n), nullptr);
  bool                ok = n >= 0 && (n == 0 || H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) >= 0);
  if (ok && n > 0) {
    for (char *c : p) v->push_back(c ? c : "");
    H5Dvlen_reclaim(t, s, H5P_DEFAULT, p.data());
  }
  H5Tclose(t);
  H5Sclose(s);
  H5Dclose(d);
  return ok;
}

// The values of a text axis, in order, as the string-array attribute `values` of dataset `name`
// (so that readers know every value and its order, also those not yet in a row).
static bool WriteValuesAttribute(hid_t g, const char *name, const std::vector<std::string> &labels)
{
  std::vector<const char *> p;
  for (auto &l : labels) p.push_back(l.c_str());
  const hsize_t n = labels.size();
  hid_t         d = H5Dopen2(g, name, H5P_DEFAULT);
  if (d < 0) return false;
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  hid_t      sp = H5Screate_simple(1, &n, NULL);
  hid_t      a  = H5Acreate2(d, "values", t, sp, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = a >= 0 && H5Awrite(a, t, p.data()) >= 0;
  if (a >= 0) H5Aclose(a);
  H5Sclose(sp);
  H5Tclose(t);
  H5Dclose(d);
  return ok;
}

// A text axis's column: the label of each index in v, as strings, with the attribute `values`.
static PetscErrorCode WriteTextColumn(hid_t g, const std::string &output, const char *name,
                                      const std::vector<double> &v, const std::vector<std::string> &labels)
{
  std::vector<std::string> text;

  PetscFunctionBeginUser;
  for (double i : v) text.push_back(i >= 0 && i < (double)labels.size() ? labels[(size_t)i] : std::string());
  PetscCheck(H5WriteStringColumn(g, name, text, kReasonUnit) && WriteValuesAttribute(g, name, labels), PETSC_COMM_SELF,
             PETSC_ERR_FILE_WRITE, "-output %s: cannot write the text column %s", output.c_str(), name);
  PetscFunctionReturn(0);
}

// The file's contents: root attributes, /results and /sweep.
static PetscErrorCode StoreWriteContents(SweepStore &S, hid_t file)
{
  PetscFunctionBeginUser;
  RunRecord rec = S.record;
  rec.add("sweep_cases_done", S.rows.size());
  rec.add("sweep_complete", (PetscInt)S.rows.size() == S.ncases ? 1 : 0);
  if (!S.retry_changed.empty())
    rec.add("sweep_retry_changed", S.retry_changed); // -sweep_retry_failed's changes, one line per retry
  PetscCall(H5WriteAttributes(file, rec));
  hid_t       g    = H5Gcreate2(file, "results", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const auto &cols = S.columns;
  for (size_t c = 0; c < cols.size(); ++c) {
    std::vector<double> v;
    v.reserve(S.rows.size());
    for (auto &kv : S.rows) v.push_back(kv.second[c]);
    if (!cols[c].labels.empty()) PetscCall(WriteTextColumn(g, S.output, cols[c].name.c_str(), v, cols[c].labels));
    else
      PetscCall(
        (cols[c].integer ? H5WriteCounts1D : H5WriteDataset1D)(g, cols[c].name.c_str(), v, cols[c].unit.c_str()));
  }
  std::vector<std::string> reasons;
  reasons.reserve(S.rows.size());
  for (auto &kv : S.rows) {
    const auto it = S.reasons.find(kv.first);
    reasons.push_back(it == S.reasons.end() ? std::string() : it->second);
  }
  PetscCheck(H5WriteStringColumn(g, "reason", reasons, kReasonUnit), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "cannot write /results/reason");
  PetscCall(H5DimsTable(g, "case_index")); // the rows done, by their case
  H5Gclose(g);
  // The plan: every axis's value for every case (also those not yet done).
  hid_t gp = H5Gcreate2(file, "sweep", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  for (size_t k = 0; k < S.plan.axes.size(); ++k) {
    std::vector<double> v(S.ncases);
    for (PetscInt i = 0; i < S.ncases; ++i) v[i] = S.plan.CaseValues(i)[k];
    const SweepAxis &a = S.plan.axes[k];
    if (a.Text()) PetscCall(WriteTextColumn(gp, S.output, a.name.c_str(), v, a.labels));
    else PetscCall(H5WriteDataset1D(gp, a.name.c_str(), v, a.unit.c_str()));
  }
  PetscCall(H5DimsTable(gp, "case")); // every case of the plan, done or not
  H5Gclose(gp);
  PetscCall(SweepUqWrite(S, S.uq, file)); // a sampled sweep's /statistics, /exceedance, /sobol (complete)
  PetscFunctionReturn(0);
}

// The cases whose rows F holds as it is on disk (/results/case_index; none when F is absent,
// unreadable or no regular file: a FIFO put there would block the open), and those the journals
// in F.parts hold (every complete record of this signature).
static void StoreCasesOnDisk(const SweepStore &S, std::set<PetscInt> *in_file, std::set<PetscInt> *in_journals)
{
  struct stat st;
  if (::lstat(S.output.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
    H5ErrorsQuiet       quiet;
    std::vector<double> index;
    const hid_t         file = H5Fopen(S.output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file >= 0) {
      const hid_t g = H5Gopen2(file, "results", H5P_DEFAULT);
      if (g >= 0 && H5ReadDoubleColumn(g, "case_index", &index))
        for (double v : index) in_file->insert((PetscInt)v);
      if (g >= 0) H5Gclose(g);
      H5Fclose(file);
    }
  }
  for (const std::string &path : SweepJournalFiles(S.parts, nullptr)) {
    SweepJournalReader                      j;
    std::map<PetscInt, std::vector<double>> rows;
    std::map<PetscInt, std::string>         reasons;
    PetscInt                                added = 0;
    j.path                                        = path;
    j.ReadNew(S.signature_hash, S.ncols, S.ncases, &rows, &reasons, &added);
    for (auto &kv : rows) in_journals->insert(kv.first);
  }
}

// What a failed rewrite left, for its message: F as it was (or still nothing there, or what was
// put there meanwhile), and where the rows computed that F does not hold are: in the journals in
// F.parts (a resume reads them), in none (the journals could not be written either: those rows
// are computed again), or that there are none (every row is in F, or no point had been computed).
// The journals are read as they are on disk: a row another rank journaled before rank 0 received
// it counts as kept; a point a rank is still finishing is journaled after the count (the message
// says so: a resume may find more rows done than it says, never fewer).
// full: the cause was a full disk (the same command resumes once there is room).
static std::string StoreWriteLeft(const SweepStore &S, bool full)
{
  struct stat        st;
  std::set<PetscInt> in_file, in_journals;
  size_t             kept = 0, lost = 0; // rows not in F: in a journal, in none
  StoreCasesOnDisk(S, &in_file, &in_journals);
  for (PetscInt c : in_journals) kept += !in_file.count(c);
  for (auto &kv : S.rows) lost += !in_file.count(kv.first) && !in_journals.count(kv.first);
  const bool        there    = ::lstat(S.output.c_str(), &st) == 0;
  const std::string left     = !there              ? "nothing was written at " + S.output
                             : S_ISREG(st.st_mode) ? S.output + " is as it was"
                                                   : S.output + " is left as it is (" + FileKind(st.st_mode) + ")";
  const std::string again    = full ? "run the same command again once there is room"
                                    : "run the same command again once the cause is removed";
  const std::string journals = std::to_string(kept) + " row(s) not in it are kept by the journal(s) in " + S.parts +
                               " for a resume (with any point a rank was finishing)";
  if (lost > 0)
    return left + "; " + std::to_string(lost) +
           " row(s) computed are neither in it nor in a journal (the journals could not be written either) and will be "
           "computed again" +
           (kept > 0 ? "; " + journals : "") + ": " + again;
  if (kept > 0) return left + ", and the " + journals + ": " + again;
  return left + (S.rows.empty() ? "; no point had been computed" : "; it holds every row computed so far") + ": " +
         again;
}

// F rewritten whole: built in memory, written to F.tmp (every write checked: a full disk shows
// there), fsync'ed and renamed onto F. On a failure F.tmp is removed and F stays as it was.
static PetscErrorCode StoreWrite(SweepStore &S)
{
  const std::string tmp = S.output + ".tmp";
  const double      t0  = MPI_Wtime();
  std::string       error;

  PetscFunctionBeginUser;
  ImpactStageScope stage(ImpactStage::Output); // -log_view: the rewrites are output
  {
    H5ErrorsQuiet quiet;
    const hid_t   file = (hid_t)H5MemoryFileCreate(); // written to disk by us: every write checked
    PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "-output %s: HDF5 cannot create a file in memory",
               S.output.c_str());
    const PetscErrorCode ierr = StoreWriteContents(S, file);
    if (ierr) error = LastErrorMessage(ierr);
    error = H5MemoryFileInstall(file, S.output, tmp, error); // F.tmp, fsync'ed, renamed onto F
  }
  PetscCheck(error.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-output %s: writing it failed (%s); %s",
             S.output.c_str(), WriteFailureCause(error).c_str(),
             StoreWriteLeft(S, WriteFailureCause(error) != error).c_str());
  S.rows_written = (PetscInt)S.rows.size();
  S.last_write   = MPI_Wtime();
  S.write_cost   = S.last_write - t0;
  PetscFunctionReturn(0);
}

static PetscErrorCode WrongParameters(const SweepStore &S, const std::string &what, const std::string &diff)
{
  PetscFunctionBeginUser;
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
          "-output %s: %s was written by a sweep with different parameters, so it cannot be resumed:%s\n"
          "Rerun with the same options to resume it, add -sweep_restart to discard it and start over, or choose "
          "another -output.",
          S.output.c_str(), what.c_str(), diff.c_str());
  PetscFunctionReturn(0);
}

// A text axis's column read back as the index of each label in labels (NaN for a string that
// is none of them: such a row is not loaded); false when the dataset is missing.
static bool ReadTextColumn(hid_t g, const char *name, const std::vector<std::string> &labels, std::vector<double> *v)
{
  std::vector<std::string> text;
  v->clear();
  if (!H5ReadStringColumn(g, name, &text)) return false;
  for (const std::string &t : text) {
    const auto it = std::find(labels.begin(), labels.end(), t);
    v->push_back(it == labels.end() ? std::numeric_limits<double>::quiet_NaN() : (double)(it - labels.begin()));
  }
  return true;
}

// -sweep_retry_failed with a signature that differs from the file's: allowed when only options
// the failed rows name as their cause changed (e.g. -impact_max_contacts after "more than
// -impact_max_contacts ..."); then the file's rows load, its journals too, and the change is
// recorded (sweep_retry_changed). Anything else is refused as for any resume.
static PetscErrorCode StoreRetryCheck(SweepStore &S, const SweepAttributes &stored)
{
  std::map<PetscInt, std::string> failed;
  std::string                     changed;

  PetscFunctionBeginUser;
  for (auto &kv : S.rows)
    if (S.status_column >= 0 && SweepFailed(kv.second[S.status_column]) && S.reasons.count(kv.first))
      failed[kv.first] = S.reasons[kv.first];
  const std::set<std::string> named = OptionsNamed(failed);
  const std::string           rest  = DiffBeyond(stored, S.signature, named, &changed);
  if (!rest.empty() || changed.empty()) {
    std::string allowed;
    for (const std::string &o : named) allowed += (allowed.empty() ? "-" : ", -") + o;
    PetscCall(
      WrongParameters(S, "the file",
                      SignatureDiff(stored, S.signature, RecordString(S.record, "input_files")) +
                        "\n  (-sweep_retry_failed may change only the options its failed rows name as their cause" +
                        (allowed.empty() ? std::string(": they name none)") : ": " + allowed + ")")));
  }
  S.retry_signature_hash = SignatureHash(stored);
  S.retry_changed += (S.retry_changed.empty() ? "" : "\n") + changed;
  PetscFunctionReturn(0);
}

// Loads the rows of an existing output file after checking its parameters.
static PetscErrorCode StoreLoadFile(SweepStore &S)
{
  struct stat st;

  PetscFunctionBeginUser;
  if (::stat(S.output.c_str(), &st) != 0) PetscFunctionReturn(0);
  H5ErrorsQuiet quiet;
  PetscCheck(H5Fis_hdf5(S.output.c_str()) > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-output %s exists and is not an HDF5 file; add -sweep_restart to overwrite it or choose another -output",
             S.output.c_str());
  hid_t file = H5Fopen(S.output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
             "-output %s exists but cannot be opened as HDF5; add -sweep_restart to overwrite it or choose another "
             "-output",
             S.output.c_str());
  SweepAttributes a;
  H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, NULL, CollectAttribute, &a);
  if (a.str["task"] != "sweep") {
    H5Fclose(file);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
            "-output %s holds no sweep (it was written by -task %s); add -sweep_restart to overwrite it or choose "
            "another -output",
            S.output.c_str(), a.str["task"].empty() ? "impact or modes" : a.str["task"].c_str());
  }
  SweepAttributes stored;
  for (auto &kv : a.num)
    if (!AttributeIsVolatile(kv.first)) stored.num[kv.first] = kv.second;
  for (auto &kv : a.str)
    if (!AttributeIsVolatile(kv.first)) stored.str[kv.first] = kv.second;
  SignatureCanonical(&stored);                       // as this run's (SignatureMaps)
  S.retry_changed    = a.str["sweep_retry_changed"]; // earlier retries, kept
  const bool differs = SignatureHash(stored) != S.signature_hash;
  if (differs && !S.plan.retry_failed) {
    H5Fclose(file);
    PetscCall(
      WrongParameters(S, "the file", SignatureDiff(stored, S.signature, RecordString(S.record, "input_files"))));
  }
  hid_t g = H5Gopen2(file, "results", H5P_DEFAULT);
  PetscCheck(g >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-output %s has no /results group; add -sweep_restart to overwrite it", S.output.c_str());
  const auto                      &cols = S.columns;
  std::vector<std::vector<double>> data(cols.size());
  for (size_t c = 0; c < cols.size(); ++c) {
    const bool ok = cols[c].labels.empty() ? ReadDataset(g, cols[c].name.c_str(), &data[c])
                                           : ReadTextColumn(g, cols[c].name.c_str(), cols[c].labels, &data[c]);
    PetscCheck(ok && data[c].size() == data[0].size(), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
               "-output %s: /results/%s is missing or has the wrong length; add -sweep_restart to overwrite it",
               S.output.c_str(), cols[c].name.c_str());
  }
  std::vector<std::string> reasons;
  const bool               reasons_ok = H5ReadStringColumn(g, "reason", &reasons) && reasons.size() == data[0].size();
  H5Gclose(g);
  H5Fclose(file);
  PetscCheck(reasons_ok, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-output %s: /results/reason is missing or has the wrong length; add -sweep_restart to overwrite it",
             S.output.c_str());
  for (size_t r = 0; r < data[0].size(); ++r) {
    const double idx = data[0][r];
    if (!(idx >= 0 && idx < S.ncases && idx == std::floor(idx))) continue;
    std::vector<double> row(cols.size());
    bool                known = true; // every text value one of its axis's (else the case is computed again)
    for (size_t c = 0; c < cols.size(); ++c) {
      row[c] = data[c][r];
      known  = known && (cols[c].labels.empty() || !std::isnan(row[c]));
    }
    if (!known) continue;
    S.rows.emplace((PetscInt)idx, std::move(row));
    if (!reasons[r].empty()) S.reasons[(PetscInt)idx] = reasons[r];
  }
  if (differs) PetscCall(StoreRetryCheck(S, stored));
  PetscFunctionReturn(0);
}

std::vector<std::string> SweepJournalFiles(const std::string &parts, int *last_run)
{
  std::vector<std::string> names;
  if (last_run) *last_run = 0;
  DIR *d = ::opendir(parts.c_str());
  if (!d) return names;
  while (dirent *e = ::readdir(d)) {
    int run, rank;
    if (ParseJournalName(e->d_name, &run, &rank)) {
      names.push_back(parts + "/" + e->d_name);
      if (last_run) *last_run = std::max(*last_run, run);
    }
  }
  ::closedir(d);
  std::sort(names.begin(), names.end());
  return names;
}

static void RemoveJournals(const SweepStore &S)
{
  for (const std::string &path : SweepJournalFiles(S.parts, nullptr)) ::unlink(path.c_str());
}

// A lock file unlinked by the run that held it between our open() and flock() would leave us
// holding a lock nobody else sees: then the path no longer names the inode we locked, and we
// try again (so too when that run removed the directory under us).
PetscErrorCode SweepPartsLock(const std::string &output, const std::string &parts, const char *who, int *lock_fd)
{
  const std::string path = parts + "/lock";

  PetscFunctionBeginUser;
  for (int attempt = 0;; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0 && errno == ENOENT && attempt < 100) { // the directory just removed by the run that ended
      ::mkdir(parts.c_str(), 0755);
      continue;
    }
    PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot create %s (%s)", output.c_str(),
               path.c_str(), std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
              "-output %s is being written by another %s that is still running (%s is held); wait for it or choose "
              "another -output",
              output.c_str(), who, path.c_str());
    }
    struct stat held, named;
    if (::fstat(fd, &held) == 0 && ::stat(path.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino) {
      *lock_fd = fd;
      PetscFunctionReturn(0);
    }
    ::close(fd);
    PetscCheck(attempt < 100, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
               "-output %s: %s keeps being replaced by another %s; wait for it or choose another -output",
               output.c_str(), path.c_str(), who);
  }
}

// Takes F.parts/lock (flock, not blocking).
static PetscErrorCode StoreLock(SweepStore &S) { return SweepPartsLock(S.output, S.parts, "sweep", &S.lock_fd); }

void SweepStoreRelease(SweepStore &S)
{
  if (S.lock_fd < 0) return;
  ::unlink((S.parts + "/lock").c_str()); // while still held: nobody can take it in between
  ::close(S.lock_fd);
  S.lock_fd = -1;
  ::rmdir(S.parts.c_str()); // only when empty: the journals of a resumable run stay
}

// SweepStoreOpen once the lock is held.
static PetscErrorCode StoreOpenLocked(SweepStore &S, int *run)
{
  PetscFunctionBeginUser;
  if (S.plan.restart) {
    RemoveJournals(S);
    ::unlink(S.output.c_str());
  } else PetscCall(StoreLoadFile(S));
  // Journals of earlier runs (killed before they finished).
  DIR *d = ::opendir(S.parts.c_str());
  PetscCheck(d, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot read %s", S.output.c_str(), S.parts.c_str());
  ::closedir(d);
  for (const std::string &path : SweepJournalFiles(S.parts, run)) {
    SweepJournalReader j;
    j.path                        = path;
    SweepJournalReader::Status st = j.ReadNew(S.signature_hash, S.ncols, S.ncases, &S.rows, &S.reasons, nullptr);
    if (st == SweepJournalReader::WrongParameters && S.retry_signature_hash) { // written before this retry's change
      SweepJournalReader former;
      former.path = j.path;
      st          = former.ReadNew(S.retry_signature_hash, S.ncols, S.ncases, &S.rows, &S.reasons, nullptr);
    }
    if (st == SweepJournalReader::WrongParameters)
      PetscCall(
        WrongParameters(S, "the journal " + j.path, "\n  (its parameter signature differs from the current one)"));
  }
  // -sweep_retry_failed: the failed cases are computed again (their rows are dropped).
  if (S.plan.retry_failed && S.status_column >= 0)
    for (auto it = S.rows.begin(); it != S.rows.end();) {
      if (SweepFailed(it->second[S.status_column])) {
        S.reasons.erase(it->first);
        it = S.rows.erase(it);
      } else ++it;
    }
  // One file holding everything found; only then are the old journals redundant.
  PetscCall(StoreWrite(S));
  RemoveJournals(S);
  *run += 1;
  PetscFunctionReturn(0);
}

PetscErrorCode SweepStoreOpen(SweepStore &S, int *run)
{
  PetscFunctionBeginUser;
  const bool made = ::mkdir(S.parts.c_str(), 0755) == 0;
  PetscCheck(made || errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
             "-output %s: cannot create the journal directory %s (%s)", S.output.c_str(), S.parts.c_str(),
             std::strerror(errno));
  PetscErrorCode ierr = StoreLock(S);
  if (ierr && made) ::rmdir(S.parts.c_str());
  PetscCall(ierr);
  // Refused (other parameters, not a sweep file, ...) or failed: the lock goes with this run.
  ierr = StoreOpenLocked(S, run);
  if (ierr) SweepStoreRelease(S);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

void SweepStoreFollow(SweepStore &S, int run, const std::vector<PetscMPIInt> &leaders)
{
  for (PetscMPIInt r : leaders) {
    SweepJournalReader j;
    j.path = SweepJournalName(S.output, run, r);
    S.live.push_back(j);
  }
}

PetscErrorCode SweepStoreRefresh(SweepStore &S)
{
  const double now = MPI_Wtime();

  PetscFunctionBeginUser;
  // Live rewrites cost rank 0 at most ~5% of its time.
  const double interval = std::max(S.plan.write_interval, 20 * S.write_cost);
  if (now - S.last_write >= interval) {
    PetscInt added = 0;
    for (auto &j : S.live) j.ReadNew(S.signature_hash, S.ncols, S.ncases, &S.rows, &S.reasons, &added);
    if ((PetscInt)S.rows.size() != S.rows_written) PetscCall(StoreWrite(S));
    S.last_write = MPI_Wtime();
    S.write_cost = S.last_write - now; // reading the journals included
    S.write_total += S.write_cost;
    ++S.writes;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SweepStoreClose(SweepStore &S)
{
  PetscFunctionBeginUser;
  PetscCheck((PetscInt)S.rows.size() == S.ncases, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "sweep ended with %zu of %" PetscInt_FMT " rows", S.rows.size(), S.ncases);
  PetscCall(StoreWrite(S));
  RemoveJournals(S);
  SweepStoreRelease(S);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

// The plan of a sweep: the axes registry, point lists, the -sweep_* options and the
// scenario of each case. See sweep_plan.hpp.
#include "studies/sweep_plan.hpp"

#include "run/impact_point.hpp"
#include "io/text.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace beamimpact {

// ---------------------------------------------------------------------------
// The axes a sweep can vary
// ---------------------------------------------------------------------------

namespace {

// impact_x: the impact point (m), on the beam and not held.
void ImpactXSet(Scenario &sc, PetscReal x) { sc.impact.x = x; }

PetscErrorCode ImpactXCheck(MPI_Comm comm, const Scenario &sc, PetscReal x, PetscInt index)
{
  char what[128];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(what, sizeof(what), "-sweep_x point %d, x = %g,", (int)index, (double)x));
  PetscCall(ImpactPointCheck(comm, sc.beam, x, what));
  PetscFunctionReturn(0);
}

std::string ImpactXExample(const Scenario &sc)
{
  char text[64];
  if (PetscSNPrintf(text, sizeof(text), "0:%g:111", (double)sc.beam.length)) return "0:1:11";
  return text;
}

} // namespace

const std::vector<SweepAxisType> &SweepAxisTypes()
{
  static const std::vector<SweepAxisType> types = {
    {"impact_x", "x", "m", "impact points", ImpactXSet, ImpactXCheck, ImpactXExample},
  };
  return types;
}

// ---------------------------------------------------------------------------
// Cases and points
// ---------------------------------------------------------------------------

PetscInt SweepPlan::cases() const
{
  if (axes.empty()) return 0;
  PetscInt n = 1;
  for (auto &a : axes) n *= (PetscInt)a.values.size();
  return n;
}

std::vector<PetscReal> SweepPlan::CaseValues(PetscInt index) const
{
  std::vector<PetscReal> v(axes.size());
  for (size_t k = axes.size(); k-- > 0;) {
    const PetscInt n = (PetscInt)axes[k].values.size();
    v[k]             = axes[k].values[index % n];
    index /= n;
  }
  return v;
}

Scenario SweepCaseFor(const SweepPlan &plan, const Scenario &base, PetscInt index)
{
  Scenario                     c = base;
  const std::vector<PetscReal> v = plan.CaseValues(index);
  for (size_t k = 0; k < plan.axes.size(); ++k) plan.axes[k].type->set(c, v[k]);
  return c;
}

std::string SweepCaseText(const SweepPlan &plan, PetscInt index, bool petsc_format)
{
  const std::vector<PetscReal> v = plan.CaseValues(index);
  std::string                  text;
  for (size_t k = 0; k < plan.axes.size(); ++k) {
    const SweepAxisType &t = *plan.axes[k].type;
    char                 one[128];
    if (petsc_format) {
      if (PetscSNPrintf(one, sizeof(one), "%s = %g %s", t.column, (double)v[k], t.unit)) one[0] = '\0';
    } else std::snprintf(one, sizeof(one), "%s = %g %s", t.column, (double)v[k], t.unit);
    text += (k ? ", " : "") + std::string(one);
  }
  return text;
}

static bool ParseReal(const std::string &text, PetscReal *v)
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

// "start:stop:count", both ends included.
static bool ParseRange(const std::string &spec, std::vector<PetscReal> *values, std::string *why, const std::string &unit)
{
  std::vector<std::string> parts;
  std::stringstream        ss(spec);
  std::string              p;
  while (std::getline(ss, p, ':')) parts.push_back(p);
  if (parts.size() != 3) {
    *why = "a range is start:stop:count (three numbers separated by ':')";
    return false;
  }
  PetscReal a, b;
  if (!ParseReal(parts[0], &a) || !ParseReal(parts[1], &b)) {
    *why = "start and stop of start:stop:count must be numbers (" + unit + ")";
    return false;
  }
  const std::string c = Trim(parts[2]);
  char             *end;
  errno        = 0;
  const long n = c.empty() ? -1 : std::strtol(c.c_str(), &end, 10);
  if (c.empty() || *end != '\0' || errno == ERANGE || n < 0 || n > 100000000) {
    *why = "count of start:stop:count must be a whole number >= 0";
    return false;
  }
  // Rounded to 15 significant digits, so that 0:1.1:111 gives exactly the
  // doubles of 0, 0.01, ..., 1.1 (what -impact_x 0.55 gives), not 1 ulp off.
  for (long k = 0; k < n; ++k) {
    const double raw = k == n - 1 && n > 1 ? b : a + (double)k * ((b - a) / (double)std::max(1L, n - 1));
    char         text[64];
    std::snprintf(text, sizeof(text), "%.15g", raw);
    values->push_back(std::strtod(text, nullptr));
  }
  return true;
}

bool SweepParsePoints(const std::string &spec_in, std::vector<PetscReal> *values, std::string *why, const std::string &unit)
{
  const std::string spec = Trim(spec_in);
  values->clear();
  if (spec.find(':') != std::string::npos) return ParseRange(spec, values, why, unit);
  std::stringstream ss(spec);
  std::string       p;
  while (std::getline(ss, p, ',')) {
    PetscReal v;
    if (!ParseReal(p, &v)) {
      *why = "'" + Trim(p) + "' is not a number; a list is x1,x2,... (" + unit + ")";
      return false;
    }
    values->push_back(v);
  }
  if (!spec.empty() && spec.back() == ',') {
    *why = "empty entry at the end of the list";
    return false;
  }
  return true;
}

// ---------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------

// One axis from its -sweep_<column> value: parsed, every point checked against the base.
static PetscErrorCode SweepAxisRead(MPI_Comm comm, const Scenario &base, const SweepAxisType &t, const char *given, SweepPlan *plan)
{
  SweepAxis   axis;
  std::string why;

  PetscFunctionBeginUser;
  axis.type = &t;
  axis.spec = Trim(given);
  PetscCheck(!axis.spec.empty(), comm, PETSC_ERR_ARG_WRONG, "-sweep_%s needs a value: start:stop:count (both ends included) or x1,x2,... (%s), e.g. -sweep_%s %s", t.column, t.unit, t.column,
             t.example(base).c_str());
  PetscCheck(SweepParsePoints(axis.spec, &axis.values, &why, t.unit), comm, PETSC_ERR_ARG_WRONG, "-sweep_%s %s is not allowed: %s", t.column, axis.spec.c_str(), why.c_str());
  PetscCheck(!axis.values.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_%s %s gives no %s: a sweep needs at least one (count >= 1 in start:stop:count)", t.column, axis.spec.c_str(), t.points);
  for (size_t k = 0; k < axis.values.size(); ++k) PetscCall(t.check(comm, base, axis.values[k], (PetscInt)k));
  plan->axes.push_back(axis);
  PetscFunctionReturn(0);
}

PetscErrorCode SweepPlanFromOptions(MPI_Comm comm, const Scenario &base, SweepPlan *plan)
{
  const std::vector<SweepAxisType> &types = SweepAxisTypes();
  std::vector<std::vector<char>>    given(types.size(), std::vector<char>(1 << 20, 0));
  std::vector<PetscBool>            set(types.size(), PETSC_FALSE);

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "Sweep: many impacts farmed out over MPI ranks (-task sweep)", "beamimpact");
  for (size_t a = 0; a < types.size(); ++a) {
    std::string help = std::string(types[a].points) + " (" + types[a].unit + "): start:stop:count (both ends included) or x1,x2,...";
    help[0]          = (char)std::toupper((unsigned char)help[0]);
    PetscCall(PetscOptionsString((std::string("-sweep_") + types[a].column).c_str(), help.c_str(), "", given[a].data(), given[a].data(), given[a].size(), &set[a]));
  }
  PetscCall(PetscOptionsInt("-sweep_ranks_per_case", "Ranks that solve one impact together (the beam's DMDA is distributed over them)", "", plan->ranks_per_case, &plan->ranks_per_case, NULL));
  PetscCall(PetscOptionsReal("-rigid_loss_fraction", "Loss fraction f of the rigid-body model, Eq. (11), for the rigid_acor column", "", plan->rigid_loss_fraction, &plan->rigid_loss_fraction, NULL));
  PetscCall(PetscOptionsBool("-sweep_quiet", "No progress or summary lines (errors are still reported)", "", plan->quiet, &plan->quiet, NULL));
  PetscCall(PetscOptionsBool("-sweep_restart", "Discard an existing -output file and its journal and start the sweep over", "", plan->restart, &plan->restart, NULL));
  PetscCall(PetscOptionsReal("-sweep_progress_interval", "Seconds between progress lines on rank 0", "", plan->progress_interval, &plan->progress_interval, NULL));
  PetscCall(PetscOptionsReal("-sweep_write_interval", "Minimum seconds between rewrites of -output while the sweep runs (0: as often as a 5% cost cap on rank 0 allows)", "", plan->write_interval,
                             &plan->write_interval, NULL));
  PetscOptionsEnd();

  plan->axes.clear();
  for (size_t a = 0; a < types.size(); ++a)
    if (set[a]) PetscCall(SweepAxisRead(comm, base, types[a], given[a].data(), plan));
  const SweepAxisType &t = types[0]; // the axis every sweep has had so far
  PetscCheck(!plan->axes.empty(), comm, PETSC_ERR_ARG_WRONG, "-task sweep needs the %s: -sweep_%s start:stop:count (both ends included) or -sweep_%s x1,x2,... (%s), e.g. -sweep_%s %s", t.points, t.column,
             t.column, t.unit, t.column, t.example(base).c_str());
  PetscCheck(plan->ranks_per_case >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_ranks_per_case %" PetscInt_FMT " is not allowed: at least 1", plan->ranks_per_case);
  PetscCheck(plan->rigid_loss_fraction >= 0 && plan->rigid_loss_fraction < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-rigid_loss_fraction %g is not allowed: a fraction of the incident energy, 0 <= f < 1",
             (double)plan->rigid_loss_fraction);
  PetscCheck(plan->progress_interval > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_progress_interval %g is not allowed: it must be > 0 (s)", (double)plan->progress_interval);
  PetscCheck(plan->write_interval >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-sweep_write_interval %g is not allowed: it must be >= 0 (s)", (double)plan->write_interval);
  PetscFunctionReturn(0);
}

} // namespace beamimpact

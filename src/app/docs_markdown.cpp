// The Markdown references generated from the tables. See docs_markdown.hpp.
#include "app/docs_markdown.hpp"

#include "base/option_table.hpp"
#include "io/flight_h5.hpp"
#include "run/results_table.hpp"
#include "studies/convergence_output.hpp"
#include "studies/sweep.hpp"

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

namespace beamimpact {

namespace {

// How to rewrite the files, said at the top of each.
const char *const kRewrite = "do not edit it: change the table in `src/`, then `cmake --build --preset dev --target "
                             "docs` (or `scripts/make_docs.sh`) rewrites it; the CTest test `docs_generated` fails "
                             "while it differs";

bool OptionChar(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

// The length of the option name (a row, or a family "-beam_damping_*") at text[i], or 0.
size_t OptionNameAt(const std::string &text, size_t i)
{
  if (text[i] != '-' || (i > 0 && (OptionChar(text[i - 1]) || text[i - 1] == '-'))) return 0;
  size_t j = i + 1;
  while (j < text.size() && OptionChar(text[j])) ++j;
  if (j < text.size() && text[j] == '*' && text[j - 1] == '_') return j + 1 - i;
  return OptionSpecFind(text.substr(i, j - i)) ? j - i : 0;
}

// Text for a table cell: an option's name (-beam_length) in code, the characters Markdown would
// read as markup escaped ('|' ends a cell, '<' opens a tag, '*' emphasises).
std::string Cell(const std::string &text)
{
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const char   c = text[i];
    const size_t n = OptionNameAt(text, i);
    if (n > 0) {
      out += "`" + text.substr(i, n) + "`";
      i += n - 1;
      continue;
    }
    if (c == '|') out += "\\|";
    else if (c == '<') out += "&lt;";
    else if (c == '*') out += "\\*";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

std::string Code(const std::string &text)
{
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return "`" + out + "`";
}

// GitHub's anchor of a heading: lower case, spaces to '-', other punctuation dropped.
std::string Slug(const std::string &heading)
{
  std::string out;
  for (char c : heading) {
    if (std::isalnum((unsigned char)c) || c == '_' || c == '-') out += (char)std::tolower((unsigned char)c);
    else if (c == ' ') out += '-';
  }
  return out;
}

std::string Row(const std::vector<std::string> &cells)
{
  std::string line = "|";
  for (const std::string &c : cells) line += " " + c + " |";
  return line + "\n";
}

std::string Header(const std::vector<std::string> &names)
{
  std::string rule = "|";
  for (size_t k = 0; k < names.size(); ++k) rule += "---|";
  return Row(names) + rule + "\n";
}

// What a row allows, in words: "> 0", "one of `euler`, `timoshenko`", "2 values, each >= 0".
std::string AllowedText(const OptionSpec &s)
{
  const std::string range = s.range_text.empty() ? s.range.Text() : s.range_text;
  switch (s.kind) {
  case OptionKind::Real:
    return range;
  case OptionKind::Int:
    if (!s.range_text.empty()) return s.range_text;
    return std::isfinite(s.range.lo) || std::isfinite(s.range.hi) ? "a whole number " + range : "a whole number";
  case OptionKind::Bool:
    return "a flag (alone, or true/false)";
  case OptionKind::RealList:
    return s.CountText() + " separated by commas, each " + range;
  case OptionKind::Choice: {
    std::string t;
    for (const std::string &c : s.choices) t += (t.empty() ? "one of " : ", ") + Code(c);
    return t;
  }
  case OptionKind::File:
    return s.range_text.empty() ? "a file name" : s.range_text;
  default:
    return s.range_text.empty() ? "text" : s.range_text;
  }
}

// When the option acts (OptionSpec::needs), in words: "with -grip", "with -beam_theory
// timoshenko or -beam_shell"; "" when always.
std::string ActsText(const OptionSpec &s)
{
  std::string t;
  for (const std::string &need : s.needs) {
    std::string alternatives;
    for (size_t a = 0; a <= need.size();) {
      const size_t      b   = std::min(need.find('|', a), need.size());
      const std::string alt = need.substr(a, b - a);
      const size_t      eq  = alt.find('=');
      alternatives += (a ? " or " : "") + alt.substr(0, eq) + (eq == std::string::npos ? "" : " " + alt.substr(eq + 1));
      a = b + 1;
    }
    t += (t.empty() ? "Acts only with " : ", and with ") + alternatives;
  }
  return t.empty() ? t : t + ".";
}

std::string OptionRow(const OptionSpec &s)
{
  const std::string acts = ActsText(s);
  std::string       help = s.help;
  if (!help.empty() && help.back() != '.' && !acts.empty()) help += ".";
  return Row({Code(s.name), s.unit.empty() ? "" : Cell(s.unit), s.def.empty() ? "none" : Code(s.def),
              Cell(AllowedText(s)), Cell(acts.empty() ? help : help + " " + acts)});
}

std::string ModuleHeading(const OptionModule &m) { return "`" + m.name + "`: " + m.title; }

std::string ModuleSection(const OptionModule &m)
{
  std::string md = "\n## " + Cell(ModuleHeading(m)) + "\n\n";
  if (m.petsc) {
    std::string prefixes;
    for (const std::string &p : m.prefixes) prefixes += (prefixes.empty() ? "" : ", ") + Code(p);
    md += "PETSc's own objects read these options; the program lists them so that `-help`, the unknown-option "
          "check and a sweep know them. An option under " +
          prefixes +
          " that is not a row is PETSc's too: a note "
          "when nothing read it, an error when it is close to a row (a typo).\n\n";
  }
  md += Header({"option", "unit", "default", "allowed", "description"});
  for (const OptionSpec &s : m.options) md += OptionRow(s);
  return md;
}

} // namespace

std::string DocsOptionsMarkdown()
{
  size_t count = 0;
  for (const OptionModule *m : OptionModules()) count += m->options.size();
  std::string md = "# Options reference\n\n";
  md += "Generated from the option tables by `beamimpact -help_markdown options`; " + std::string(kRewrite) + ".\n\n";
  md += "Every option the program reads is one row of its module's table (`src/base/option_table.hpp`), and `-help` "
        "prints the same rows: " +
        std::to_string(count) + " options in " + std::to_string(OptionModules().size()) +
        " modules. A value is checked against its row before any work (a number finite and in its range, a whole "
        "number, a known choice, a list of the right length without empty items); an error names the option, the value "
        "as written and what is allowed. *unit* `1` is dimensionless; *default* `none` means not given: the feature is "
        "off, or the value is derived (the row's description says from what). An option given where it does not act "
        "(\"Acts only with ...\") is a one-line `note:`, and a sweep axis over it is refused. What each option "
        "means in the model, with its symbol: [model.md](model.md); the columns the runs write: "
        "[results.md](results.md).\n\n";
  for (const OptionModule *m : OptionModules())
    md += "* [" + Cell(ModuleHeading(*m)) + "](#" + Slug(ModuleHeading(*m)) + ")\n";
  for (const OptionModule *m : OptionModules()) md += ModuleSection(*m);
  return md;
}

namespace {

std::string ImpactSection()
{
  std::string md = "\n## `-task impact`: `/results`\n\n"
                   "One row per impact (a sweep: per point, below). A column that does not apply to the scenario "
                   "(*applies*) is NaN, never a number that could be read as a value; a count always applies. In an "
                   "impact file each dataset carries its `unit`, this `description`, `applies` (1 or 0 for this run) "
                   "and `applies_when` (the rule in words); *integer* columns are integer datasets there, and the "
                   "root attribute `results_columns` lists the columns in this order.";
  std::string shares; // the shares of E_in (ResultColumn::share), which close to 1
  for (const ResultColumn &c : ImpactResultColumns())
    if (c.share) shares += (shares.empty() ? "" : ", ") + Code(c.name);
  md += " Where the energy went: " + shares +
        ", each where its energy exists, are shares of the energy brought in, `energy_in`; "
        "for every structure they add up to 1 + `energy_error`, so to 1 within the integrator's error "
        "([model.md, section 4](model.md#4-energies-and-invariants)).\n\n";
  md += Header({"column", "unit", "integer", "applies", "description"});
  for (const ResultColumn &c : ImpactResultColumns())
    md += Row({Code(c.name), Cell(c.unit), c.integer ? "yes" : "", Cell(c.applies_text), Cell(c.description)});
  return md;
}

std::string SweepSection()
{
  SweepPlan plan; // one placeholder axis: where the axes' columns go
  SweepAxis axis;
  axis.name = "NAME"; // as -sweep NAME=SPEC
  axis.unit = "the option's";
  plan.axes.push_back(axis);
  std::string md = "\n## `-task sweep`: `/results`\n\n"
                   "One row per point, in the order of the points (the same whatever the number of ranks): the sweep's "
                   "own columns, then every column of `-task impact` above. Every column is float64, the counts too (a "
                   "failed row holds NaN in every number); a count carries the attribute `integer` = 1. A text axis "
                   "(`ts_type`) holds strings. Beside them, `reason` (text): the first line of a failed run's error, "
                   "empty for status 0. More in [sweep.md](sweep.md).\n\n";
  md += Header({"column", "unit", "description"});
  for (const SweepColumn &c : SweepColumns(plan)) {
    if (c.name == ImpactResultColumns().front().name) break; // the impact table follows
    md += Row({Code(c.name), Cell(c.unit), Cell(c.description)});
  }
  md += "\nThe codes of `status`:\n\n" + Header({"status", "meaning"});
  for (int s = SweepOk; s <= SweepOffFace; ++s) md += Row({std::to_string(s), Cell(SweepStatusName(s))});
  return md;
}

std::string ConvergenceSection()
{
  std::string md = "\n## `-task convergence`: `/configs/<name>`\n\n"
                   "One group per configuration, one row per level of its sequence. The file's other groups "
                   "(`/reference`, `/summary`, `/spatial`) and the configurations' attributes are in "
                   "[convergence.md](convergence.md). The *unit* is the dataset's `unit` attribute as written.\n\n";
  md += Header({"column", "unit", "integer", "description"});
  for (const ConvergenceRunColumn &c : ConvergenceRunColumns())
    md += Row({Code(c.name), Cell(c.unit), c.integer ? "yes" : "", Cell(c.description)});
  return md;
}

std::string FlightSection()
{
  std::string md = "\n## `-task flight`: `/results`\n\n"
                   "One row; the trajectory is in `/series` ([flight.md](flight.md)).\n\n";
  md += Header({"column", "unit", "integer", "description"});
  for (const FlightResultColumn &c : FlightResultColumns())
    md += Row({Code(c.name), Cell(c.unit), c.integer ? "yes" : "", Cell(c.description)});
  return md;
}

} // namespace

std::string DocsResultsMarkdown()
{
  std::string md = "# Results reference\n\n";
  md += "Generated from the results tables by `beamimpact -help_markdown results`; " + std::string(kRewrite) + ".\n\n";
  md += "The columns of the `/results` table each task writes to its HDF5 file, each defined once in the program "
        "(`-task impact`: `src/run/results_table.cpp`, which also gives the summary line its values; a sweep: "
        "`src/studies/sweep.cpp`; the convergence study: `src/studies/convergence_output.cpp`; the flight: "
        "`src/io/flight_h5.cpp`). Every dataset has a `unit` attribute (`1`: dimensionless). `-task modes` writes no "
        "results table: its datasets, and the other groups of every file (attributes, `/options_used`, `/events`, "
        "`/series`, `/snapshots`, `/modes_energy`), are in [model.md, section 9](model.md#9-output-files). "
        "`scripts/h5_to_csv.py FILE.h5` writes any of them as CSV.\n";
  md += ImpactSection() + SweepSection() + ConvergenceSection() + FlightSection();
  return md;
}

PetscErrorCode DocsPrintMarkdown(MPI_Comm comm, const std::string &which)
{
  PetscFunctionBeginUser;
  const std::string md = which == "options" ? DocsOptionsMarkdown() : DocsResultsMarkdown();
  PetscCall(PetscPrintf(comm, "%s", md.c_str()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

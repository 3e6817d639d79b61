// The string bed's modes in a held frame. See task_strings.hpp.
#include "app/task_strings.hpp"

#include "base/options_util.hpp"
#include "io/string_bed_h5.hpp"
#include "io/string_bed_options.hpp"
#include "solvers/modes.hpp"
#include "solvers/string_bed_modes.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace beamimpact {

PetscErrorCode TaskModesIsStringBed(MPI_Comm comm, PetscBool *bed)
{
  PetscBool given;
  PetscFunctionBeginUser;
  *bed = PETSC_FALSE;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-strings_frame", &given));
  if (given)
    PetscCall(StringBedRequested(comm, bed)); // read through its row only when given: a beam's file records no bed
  PetscFunctionReturn(0);
}

PetscErrorCode StringBedHelpOptions(MPI_Comm comm)
{
  StringBedParams p;
  EPS             eps; // the bed's eigensolver options (-strings_modes_eps_*, -strings_modes_st_*)
  PetscFunctionBeginUser;
  PetscCall(StringBedParamsFromOptions(comm, &p));
  if (!EPSCreate(comm, &eps)) {
    (void)EPSSetOptionsPrefix(eps, "strings_modes_");
    (void)EPSSetFromOptions(eps);
    (void)EPSDestroy(&eps);
  }
  PetscFunctionReturn(0);
}

namespace {

// The rectangle's membrane frequencies f_mn, ascending (the first `count`), for the summary.
std::vector<PetscReal> RectangleFrequencies(const Membrane &m, const StringBedParams &p, size_t count)
{
  std::vector<PetscReal> f;
  const PetscInt         kmax = (PetscInt)count + 2;
  for (PetscInt i = 1; i <= kmax; ++i)
    for (PetscInt j = 1; j <= kmax; ++j) f.push_back(MembraneRectangleFrequency(m, p.head_length, p.head_width, i, j));
  std::sort(f.begin(), f.end());
  f.resize(std::min(f.size(), count));
  return f;
}

PetscErrorCode PrintStringBedModes(MPI_Comm comm, const StringBedParams &p, const StringBedModes &modes)
{
  const Membrane m = StringBedMembrane(p);
  const BedGrid  g = StringBedGrid(p);
  PetscMPIInt    size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscPrintf(comm,
                        "string bed: %s %g x %g m, mains %.1f N at %.2f mm, crosses %.1f N at %.2f mm, %.3f g/m a "
                        "string: N_x %.1f N/m, N_z %.1f N/m, sigma %.5f kg/m^2\n",
                        HeadShapeName(p.shape), (double)p.head_length, (double)p.head_width, (double)p.tension,
                        (double)(p.spacing * 1e3), (double)p.tension_crosses, (double)(p.spacing_crosses * 1e3),
                        (double)(p.linear_density * 1e3), (double)m.N_x, (double)m.N_z, (double)m.sigma));
  PetscCall(PetscPrintf(comm,
                        "grid %" PetscInt_FMT " x %" PetscInt_FMT " (h_x %.3f mm, h_z %.3f mm), %" PetscInt_FMT
                        " free nodes, on %d rank%s\n",
                        g.nx, g.nz, (double)(g.hx * 1e3), (double)(g.hz * 1e3), modes.free_nodes, (int)size,
                        size > 1 ? "s" : ""));
  const bool                   rect  = p.shape == HeadShape::Rectangle;
  const std::vector<PetscReal> exact = rect ? RectangleFrequencies(m, p, modes.frequency.size())
                                            : std::vector<PetscReal>();
  PetscCall(PetscPrintf(comm,
                        "modes of the string bed in a held frame (SLEPc, shift-and-invert):\n  mode  frequency (Hz)  "
                        "period (ms)%s\n",
                        rect ? "  membrane f_mn (Hz)" : ""));
  for (size_t q = 0; q < modes.frequency.size(); ++q) {
    PetscCall(PetscPrintf(comm, "  %4d  %14.4f  %11.5f", (int)q + 1, (double)modes.frequency[q],
                          (double)(1e3 / modes.frequency[q])));
    PetscCall(rect ? PetscPrintf(comm, "  %18.4f\n", (double)exact[q]) : PetscPrintf(comm, "\n"));
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode TaskStringBedModes(MPI_Comm comm, const std::string &output)
{
  StringBedParams p;
  ModesParams     mp;
  StringBedModes  modes;
  PetscFunctionBeginUser;
  PetscCall(StringBedParamsFromOptions(comm, &p));
  PetscCall(ModesParamsFromOptions(comm, &mp, nullptr));
  PetscCall(StringBedModesCompute(comm, StringBedGrid(p), StringBedMembrane(p), mp.count, &modes));
  PetscCall(OptionsCheckUnused(comm)); // after the solve: the eigensolver reads its -strings_modes_eps_* options
  PetscCall(PrintStringBedModes(comm, p, modes));
  if (output.empty()) PetscFunctionReturn(0);
  RunRecord rec;
  PetscCall(StringBedRunRecordBuild(p, modes, &rec));
  PetscCall(ResultsWriteStringBedModesFile(comm, output, rec, p, modes));
  PetscCall(PetscPrintf(comm, "wrote %s\n", output.c_str()));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

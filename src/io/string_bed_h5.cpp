// The results file of the string bed's modes. See string_bed_h5.hpp.
#include "io/string_bed_h5.hpp"

#include "io/h5_dims.hpp"
#include "io/results_h5.hpp"

#include <hdf5.h>

namespace beamimpact {

PetscErrorCode StringBedRunRecordBuild(const StringBedParams &p, const StringBedModes &modes, RunRecord *rec)
{
  const Membrane m = StringBedMembrane(p);
  const BedGrid  g = StringBedGrid(p);
  PetscFunctionBeginUser;
  PetscCall(RunRecordProgram(rec));
  rec->add("strings_frame", p.frame);
  rec->add("strings_tension", p.tension);
  rec->add("strings_tension_crosses", p.tension_crosses);
  rec->add("strings_spacing", p.spacing);
  rec->add("strings_spacing_crosses", p.spacing_crosses);
  rec->add("strings_linear_density", p.linear_density);
  rec->add("head_shape", HeadShapeName(p.shape));
  rec->add("head_length", p.head_length);
  rec->add("head_width", p.head_width);
  rec->add("head_center", p.head_center);
  // Derived: the membrane and the grid.
  rec->add("membrane_N_x", m.N_x);
  rec->add("membrane_N_z", m.N_z);
  rec->add("membrane_sigma", m.sigma);
  rec->add("strings_nodes", g.nx);
  rec->add("strings_nodes_width", g.nz);
  rec->add("strings_h_x", g.hx);
  rec->add("strings_h_z", g.hz);
  rec->add("strings_free_nodes", modes.free_nodes);
  rec->add("modes_count", (PetscInt)modes.frequency.size());
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteStringBedModesFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                              const StringBedParams &p, const StringBedModes &modes)
{
  const BedGrid g = StringBedGrid(p);
  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileWrite(comm, path, record, [&](long long file) -> PetscErrorCode {
    PetscFunctionBeginUser;
    hid_t gm = H5Gcreate2(file, "modes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    PetscCheck(gm >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create /modes in %s", path.c_str());
    PetscCall(H5WriteDataset1D(gm, "frequency", modes.frequency, "Hz"));
    PetscCall(H5WriteDataset1D(gm, "omega", modes.omega, "rad/s"));
    PetscCall(H5WriteBedGrid(gm, g, "x", "z"));
    for (size_t q = 0; q < modes.shape.size(); ++q) {
      std::vector<std::vector<double>> rows(g.nz);
      for (PetscInt j = 0; j < g.nz; ++j)
        rows[j].assign(modes.shape[q].begin() + j * g.nx, modes.shape[q].begin() + (j + 1) * g.nx);
      const std::string name = "shape_" + std::to_string(q + 1);
      PetscCall(H5WriteDataset2D(gm, name.c_str(), rows, "kg^-1/2 (deflection, mass-normalised), [z][x]"));
      PetscCall(H5DimsAttach(gm, name.c_str(), {"z", "x"}));
    }
    PetscCall(H5DimsTable(gm, "mode"));
    H5Gclose(gm);
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

} // namespace beamimpact

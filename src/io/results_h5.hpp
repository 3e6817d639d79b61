// HDF5 output of impacts: the results table (run/results_table.hpp: its columns, units and
// NaN where a column does not apply), run attributes and the impact's scales, events, time
// series and snapshots; and of a beam's modes. Files are written by rank 0 of the task's communicator with the
// HDF5 C API (the data are small: one row per impact, 1-D beam snapshots).
#pragma once

#include "io/run_record.hpp"
#include "run/impact.hpp"
#include "run/results_table.hpp"
#include "run/scenario.hpp"
#include "solvers/modes.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace beamimpact {

// Writes a new file (replacing any) for results of the scenario sc: root attributes (the record,
// with the ball's rigid-wall values ball_wall_contact_time and ball_wall_cor and the first
// result's scales contact_time_scale and compression_scale; the table's column order
// results_columns), /results (every column of the table, one row per result, with the
// attributes unit, description, applies (1 or 0: whether the column applies to sc; NaN where it
// does not) and applies_when (in words)), and for the first result its /events, /series,
// /snapshots and /modes_energy (a modal free flight's energy per mode at the end) when they hold
// data. Every dataset carries its CF units and netCDF dimensions (io/h5_dims.hpp); with snapshots,
// their XDMF description beside the file (io/xdmf.hpp: path.xmf for path.h5).
PetscErrorCode ResultsWriteImpactFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                      const std::vector<ImpactResult> &results, const Scenario &sc);

// Writes a new file (replacing any, H5ResultsFileWrite) on rank 0 of comm: root attributes; /modes with the
// frequency (Hz), period (s) and omega (rad/s) of each mode, the deflection shapes (one row per
// mode over the nodes /beam/x) and the nodes of the first two flexible modes (nodes_1, nodes_2,
// m); /beam with the node positions and the section there (EI, mu; the profile's D and d when
// the beam has one), for plots of the bat with its modes (scripts/plot_bat.py).
PetscErrorCode ResultsWriteModesFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                     const ModesResult &modes, const std::vector<std::vector<PetscReal>> &shapes,
                                     const BeamParams &beam);

// What a file that -output names holds: whether it exists (and its size), is HDF5, and the
// root attributes program ("beamimpact ...") and task of a results file of this program.
struct ResultsFileInfo {
  bool        exists = false, hdf5 = false;
  long long   size = 0; // bytes
  std::string program, task;
  bool        Ours() const { return hdf5 && program.compare(0, 10, "beamimpact") == 0 && !task.empty(); }
};
PetscErrorCode ResultsFileInspect(const std::string &path, ResultsFileInfo *info);

// What a stat mode is, in words for a message: "a regular file", "a directory", "a character
// device", "a block device", "a FIFO (named pipe)", "a socket", "a symbolic link".
const char *FileKind(unsigned mode);

// A task's results file at path, whole or not at all: on rank 0 of comm a temporary file
// beside it (path.XXXXXX.tmp) gets the run record as root attributes and what write adds; it
// is closed (every write checked, the close too: a full disk shows there) and renamed onto
// path only when all of it succeeded. On a failure the temporary file is removed, a file at
// path is left as it was, and the error names -output (no crash at exit: every HDF5 handle is
// closed with the file). The other ranks write nothing. xdmf: the XDMF description of the
// file's snapshots (io/xdmf.hpp), installed with it at XdmfPathFor(path) (H5MemoryFileInstall).
PetscErrorCode H5ResultsFileWrite(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                  const std::function<PetscErrorCode(long long file)> &write,
                                  const std::string                                   &xdmf = "");

// An HDF5 file built in memory (the core driver, no backing store), -1 on failure; written out
// by H5MemoryFileSave, which closes it in any case (path empty: only closes) and writes its
// bytes to path with checked write(2) calls and an fsync: "" on success, else what went wrong.
// A full disk is then an error of ours, never a close that fails inside HDF5.
long long   H5MemoryFileCreate();
std::string H5MemoryFileSave(long long file, const std::string &path);

// The memory file put at path whole or not at all: saved (H5MemoryFileSave, which closes it) to
// tmp beside path (tmp empty: a new unique path.XXXXXX.tmp, with the permissions a plain create
// gives), renamed onto path and the directory fsync'ed; "" on success, else what went wrong,
// with tmp removed and a file at path left as it was. Only a new name or a regular file at path
// is replaced: path checked by lstat just before the rename (a device, FIFO, socket, directory
// or symbolic link put there since -output was checked is left alone, an error); a tmp that is
// not a regular file (a link, a device, a FIFO) is not written through. error not empty: only
// closes the file and returns error (a writer that failed before its file was complete). The
// file's XDMF description xdmf (not empty: the file has snapshots) goes to XdmfPathFor(path) the
// same way, saved before the file and renamed onto its place after it; xdmf empty: a description
// this program wrote there is removed with the file it described (XdmfFileOurs).
std::string H5MemoryFileInstall(long long file, const std::string &path, const std::string &tmp,
                                const std::string &error, const std::string &xdmf = "");

// A write failure's cause for a message: error itself, after "disk full: " when it is one
// (ENOSPC or EDQUOT's text in it).
std::string WriteFailureCause(const std::string &error);

// HDF5's own error printing off while an object lives: a failed call is reported once, by us.
class H5ErrorsQuiet {
public:
  H5ErrorsQuiet();
  ~H5ErrorsQuiet();
  H5ErrorsQuiet(const H5ErrorsQuiet &)            = delete;
  H5ErrorsQuiet &operator=(const H5ErrorsQuiet &) = delete;

private:
  void (*func_)(); // the handler as it was (HDF5's H5E_auto2_t, stored as a plain function pointer)
  void *data_;
};

// Small HDF5 helpers (rank 0 only; return negative hid_t/herr_t on failure).
PetscErrorCode H5WriteAttributes(long long loc, const RunRecord &record);
PetscErrorCode H5WriteDataset1D(long long loc, const char *name, const std::vector<double> &v, const char *unit);
// A string bed's grid as two datasets x_name, z_name (m, from the head's centre: along the
// frame's axis and across the face) in loc.
PetscErrorCode H5WriteBedGrid(long long loc, const BedGrid &g, const char *x_name, const char *z_name);
PetscErrorCode H5WriteDatasetInt1D(long long loc, const char *name, const std::vector<long long> &v,
                                   const char *unit); // 64-bit integers
// Counts that must stay double (NaN in a failed sweep row): the dataset carries the integer
// attribute integer = 1, so that readers write its finite values as whole numbers.
PetscErrorCode H5WriteCounts1D(long long loc, const char *name, const std::vector<double> &v, const char *unit);
PetscErrorCode H5WriteDataset2D(long long loc, const char *name, const std::vector<std::vector<double>> &rows,
                                const char *unit);
// A dataset [row][n1][n2] of rows of n1 * n2 values each.
PetscErrorCode H5WriteDataset3D(long long loc, const char *name, const std::vector<std::vector<double>> &rows,
                                size_t n1, size_t n2, const char *unit);
// A 1-D dataset of variable-length UTF-8 strings, with its unit.
PetscErrorCode H5WriteText1D(long long loc, const char *name, const std::vector<std::string> &v, const char *unit);

} // namespace beamimpact

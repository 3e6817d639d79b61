// The XDMF description of a results file's snapshots, so that ParaView opens them as a time series:
// beside out.h5, out.xmf (XDMF 3) holds one temporal collection per field (the beam, the string
// bed, the barrel's wall), one grid per snapshot time: a rectilinear grid (a line of the beam's
// nodes, or a 2-D grid) whose node values are that time's row of the field's [time][...] dataset
// in out.h5, named relative to out.xmf. The row is given as Xdmf 3 writes a part of an HDF5
// dataset, "out.h5:/snapshots/y|k 0:1 1:1 N:T N" (start:stride:count:dataspace), which ParaView's
// Xdmf3 readers (its default for .xmf) read; its legacy "XDMF Reader" (Xdmf 2) does not.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// One field of the snapshots: values [time][ny][nx] (or [time][ny * nx]) on the grid x by y.
struct XdmfField {
  std::string name;        // the collection's name (beam, bed, wall)
  std::string attribute;   // the values' name in ParaView (y, w, W)
  std::string x, y;        // HDF5 paths of the grid's axes (y empty: one line at y = 0)
  PetscInt    nx = 0;      // length of x
  PetscInt    ny = 1;      // length of y (1 for a line)
  std::string values;      // HDF5 path of the values
  bool        flat = true; // values [time][ny * nx] (else [time][ny][nx])
};

// The description's path beside an HDF5 file: out.h5 (or .hdf5, .he5) -> out.xmf, else path.xmf.
std::string XdmfPathFor(const std::string &h5_path);

// The XDMF text of the fields at the snapshot times (s) of the HDF5 file named h5_name (as written
// in the text: the name relative to the .xmf). It begins with a comment naming this program,
// which XdmfFileOurs recognises.
std::string XdmfTimeSeries(const std::string &h5_name, const std::vector<double> &times,
                           const std::vector<XdmfField> &fields);

// Whether the file at path is an XDMF description this program wrote (false if absent).
bool XdmfFileOurs(const std::string &path);

} // namespace beamimpact

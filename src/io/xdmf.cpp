// The XDMF description of the snapshots. See xdmf.hpp.
#include "io/xdmf.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace beamimpact {

namespace {

// The first line after the XML declaration: XdmfFileOurs looks for it.
const char *const kMarker = "<!-- Written by beamimpact:";

std::string XmlEscaped(const std::string &s)
{
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string Number(double v)
{
  char b[32];
  for (int digits = 15; digits <= 17; ++digits) { // the shortest text that reads back as v: the HDF5 value exactly
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

// A DataItem of n doubles read from the HDF5 file: h5:path.
std::string HdfItem(const std::string &dims, const std::string &h5, const std::string &path)
{
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5 + ":" +
         path + "</DataItem>";
}

// One grid: field f at snapshot k of T.
void WriteGrid(std::ostringstream &o, const std::string &h5, const XdmfField &f, size_t k, size_t T, double t)
{
  const std::string nx = std::to_string(f.nx), ny = std::to_string(f.ny), n = std::to_string(f.nx * f.ny),
                    in = "          ";
  o << "      <Grid Name=\"" << f.name << "_" << k << "\" GridType=\"Uniform\">\n";
  o << "        <Time Value=\"" << Number(t) << "\"/>\n";
  o << "        <Topology TopologyType=\"2DRectMesh\" Dimensions=\"" << ny << " " << nx << "\"/>\n";
  o << "        <Geometry GeometryType=\"VXVY\">\n";
  o << in << HdfItem(nx, h5, f.x) << "\n";
  if (f.y.empty())
    o << in << "<DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">0</DataItem>\n";
  else o << in << HdfItem(ny, h5, f.y) << "\n";
  o << "        </Geometry>\n";
  // Row k of the values as Xdmf 3 reads a part of an HDF5 dataset, path|start:stride:count:dataspace
  // (ParaView's Xdmf3 readers do not read an attribute through an XDMF HyperSlab item: its type is
  // asked before its values are read).
  const std::string K = std::to_string(k), ts = std::to_string(T);
  const std::string part = f.flat ? K + " 0:1 1:1 " + n + ":" + ts + " " + n // [time][ny * nx]
                                  : K + " 0 0:1 1 1:1 " + ny + " " + nx + ":" + ts + " " + ny + " " + nx;
  o << "        <Attribute Name=\"" << f.attribute << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
  o << in << HdfItem(ny + " " + nx, h5, f.values + "|" + part) << "\n";
  o << "        </Attribute>\n";
  o << "      </Grid>\n";
}

} // namespace

std::string XdmfPathFor(const std::string &h5_path)
{
  const size_t      slash = h5_path.find_last_of('/'), dot = h5_path.find_last_of('.');
  const bool        ext = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  const std::string e   = ext ? h5_path.substr(dot) : std::string();
  return (e == ".h5" || e == ".hdf5" || e == ".he5" ? h5_path.substr(0, dot) : h5_path) + ".xmf";
}

std::string XdmfTimeSeries(const std::string &h5_name, const std::vector<double> &times,
                           const std::vector<XdmfField> &fields)
{
  std::ostringstream o;
  const std::string  h5 = XmlEscaped(h5_name);
  o << "<?xml version=\"1.0\" ?>\n";
  o << kMarker << " the snapshots of " << h5 << " as time series, one collection per field (io/xdmf.hpp) -->\n";
  o << "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  for (const XdmfField &f : fields) {
    o << "    <Grid Name=\"" << f.name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (size_t k = 0; k < times.size(); ++k) WriteGrid(o, h5, f, k, times.size(), times[k]);
    o << "    </Grid>\n";
  }
  o << "  </Domain>\n</Xdmf>\n";
  return o.str();
}

bool XdmfFileOurs(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  char          head[256] = {0};
  if (!in.read(head, sizeof head - 1) && in.gcount() <= 0) return false;
  return std::strstr(head, kMarker) != nullptr;
}

} // namespace beamimpact

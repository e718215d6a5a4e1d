#include "src/io/xdmf.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/io/io_error.hpp"

namespace bagnold::io {

std::string xdmf_text(const grid::StructuredGrid& grid, const std::vector<IndexedSnapshot>& snapshots,
                      const std::vector<std::string>& field_names) {
  const int nx = grid.cells(0), ny = grid.cells(1), nz = grid.cells(2);
  std::ostringstream s;
  s.precision(12);
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& snap : snapshots) {
    s << "   <Grid Name=\"t=" << snap.time << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << snap.time << "\"/>\n"
      << "    <Topology TopologyType=\"3DRectMesh\" Dimensions=\"" << nz + 1 << " " << ny + 1 << " "
      << nx + 1 << "\"/>\n"
      << "    <Geometry GeometryType=\"VXVYVZ\">\n";
    const char* faces[] = {"x_faces", "y_faces", "z_faces"};
    for (int d = 0; d < 3; ++d)
      s << "     <DataItem Dimensions=\"" << grid.cells(d) + 1
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << snap.file << ":/grid/"
        << faces[d] << "</DataItem>\n";
    s << "    </Geometry>\n";
    auto attribute = [&](const std::string& name, const std::string& path, const char* type,
                         int precision) {
      s << "    <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "     <DataItem Dimensions=\"" << nz << " " << ny << " " << nx << "\" NumberType=\""
        << type << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << snap.file << ":"
        << path << "</DataItem>\n    </Attribute>\n";
    };
    attribute("cell_flags", "/grid/cell_flags", "UChar", 1);
    for (const auto& name : field_names)
      if (std::find(snap.absent_fields.begin(), snap.absent_fields.end(), name) == snap.absent_fields.end())
        attribute(name, "/fields/" + name, "Float", 8);
    s << "   </Grid>\n";
  }
  s << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return s.str();
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw Hdf5Error("cannot write " + path + " (disk full?)");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw Hdf5Error("cannot rename " + temporary + " to " + path);
}

}  // namespace bagnold::io

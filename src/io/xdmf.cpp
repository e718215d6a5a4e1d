#include "src/io/xdmf.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/io/io_error.hpp"

namespace bagnold::io {

namespace {

bool absent(const IndexedSnapshot& snap, const std::string& name) {
  return std::find(snap.absent_fields.begin(), snap.absent_fields.end(), name) != snap.absent_fields.end();
}

// One <Attribute> of cell data: `dimensions` of the stored array, "Vector" for a trailing 3.
void attribute(std::ostringstream& s, const std::string& file, const std::string& name,
               const std::string& path, const char* kind, const std::string& dimensions,
               const char* type, int precision) {
  s << "     <Attribute Name=\"" << name << "\" AttributeType=\"" << kind << "\" Center=\"Cell\">\n"
    << "      <DataItem Dimensions=\"" << dimensions << "\" NumberType=\"" << type
    << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << file << ":" << path
    << "</DataItem>\n     </Attribute>\n";
}

void cells_grid(std::ostringstream& s, const grid::StructuredGrid& grid, const IndexedSnapshot& snap,
                const IndexedFields& fields) {
  const int nx = grid.cells(0), ny = grid.cells(1), nz = grid.cells(2);
  const std::string cells = std::to_string(nz) + " " + std::to_string(ny) + " " + std::to_string(nx);
  s << "    <Grid Name=\"cells\" GridType=\"Uniform\">\n"
    << "     <Topology TopologyType=\"3DRectMesh\" Dimensions=\"" << nz + 1 << " " << ny + 1 << " "
    << nx + 1 << "\"/>\n"
    << "     <Geometry GeometryType=\"VXVYVZ\">\n";
  const char* faces[] = {"x_faces", "y_faces", "z_faces"};
  for (int d = 0; d < 3; ++d)
    s << "      <DataItem Dimensions=\"" << grid.cells(d) + 1
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << snap.file << ":/grid/"
      << faces[d] << "</DataItem>\n";
  s << "     </Geometry>\n";
  attribute(s, snap.file, "cell_flags", "/grid/cell_flags", "Scalar", cells, "UChar", 1);
  for (const auto& name : fields.cell_scalars)
    if (!absent(snap, name)) attribute(s, snap.file, name, "/fields/" + name, "Scalar", cells, "Float", 8);
  for (const auto& name : fields.cell_vectors)
    if (!absent(snap, name))
      attribute(s, snap.file, name, "/fields/" + name, "Vector", cells + " 3", "Float", 8);
  s << "    </Grid>\n";
}

void openings_grid(std::ostringstream& s, const IndexedSnapshot& snap, const IndexedFields& fields) {
  const std::string n = std::to_string(snap.opening_faces);
  s << "    <Grid Name=\"openings\" GridType=\"Uniform\">\n"
    << "     <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << n << "\">\n"
    << "      <DataItem Dimensions=\"" << n << " 4\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">"
    << snap.file << ":/openings/quads</DataItem>\n     </Topology>\n"
    << "     <Geometry GeometryType=\"XYZ\">\n"
    << "      <DataItem Dimensions=\"" << 4 * snap.opening_faces
    << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << snap.file
    << ":/openings/points</DataItem>\n     </Geometry>\n";
  attribute(s, snap.file, "region", "/openings/region", "Scalar", n, "Int", 4);
  for (const auto& name : fields.opening_scalars)
    attribute(s, snap.file, name, "/openings/" + name, "Scalar", n, "Float", 8);
  for (const auto& name : fields.opening_vectors)
    attribute(s, snap.file, name, "/openings/" + name, "Vector", n + " 3", "Float", 8);
  s << "    </Grid>\n";
}

}  // namespace

std::string xdmf_text(const grid::StructuredGrid& grid, const std::vector<IndexedSnapshot>& snapshots,
                      const IndexedFields& fields) {
  std::ostringstream s;
  s.precision(12);
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& snap : snapshots) {
    s << "   <Grid Name=\"t=" << snap.time << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "    <Time Value=\"" << snap.time << "\"/>\n";
    cells_grid(s, grid, snap, fields);
    if (snap.opening_faces > 0) openings_grid(s, snap, fields);
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

#pragma once
// HDF5 snapshots: one file per snapshot, written by rank 0 alone (HDF5's serial driver) from the
// values every rank sends it; read by every rank on its own.
//
// Layout of a snapshot file (docs/output.md):
//   /                    attributes: time [s], step, dt [s], format_version, bagnold_version, title,
//                        and the run's record (SnapshotInfo::record: the resolved deck, the
//                        command line, git hash, ranks, ...; src/run/provenance.hpp)
//   /grid/{x,y,z}_faces  face coordinates [m] (n + 1 each)
//   /grid/cell_flags     uint8 (nz, ny, nx): 0 blocked, 1 fluid, 2 boundary (blocked, next to fluid)
//   /fields/NAME         float64 (nz, ny, nx); value on fluid cells, NaN (the fill value) on
//                        every other cell; attribute `centering`: cell | x_face | y_face | z_face
//                        (a face field holds the east/north/top face of each cell)
//                        a cell vector (CellVectorView) is float64 (nz, ny, nx, 3), for viewing
//   /boundary/natural    int64: natural indices of the boundary cells (extended box, x fastest)
//   /boundary/NAME       float64: the field on those boundary cells (restart needs them)
//   /openings/           the faces of the boundary openings (grid/opening_faces.hpp), for
//                        viewing: points (4 per face), quads, region, and NAME per face
// The file is written as NAME.tmp and renamed when complete, so a crash never leaves a torn
// snapshot under its final name.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "src/grid/cell_flags.hpp"
#include "src/grid/opening_faces.hpp"
#include "src/io/io_error.hpp"
#include "src/parallel/layout.hpp"

namespace bagnold::io {

enum class Centering { cell, x_face, y_face, z_face };
const char* centering_name(Centering c);

struct FieldView {
  std::string name;
  Centering centering = Centering::cell;
  std::span<const double> values;  // local_count() entries (owned and halo)
  std::string units;               // SI, as the dataset's `units` attribute ("1": dimensionless)
};

// A cell-centred vector for viewing (ParaView's glyphs and stream lines take it as it is): 3
// values per local cell (x, y, z), written on the fluid cells as /fields/NAME of shape
// (nz, ny, nx, 3), NaN elsewhere; attributes centering "cell", units, checksum. Never read back.
struct CellVectorView {
  std::string name;
  std::span<const double> values;  // 3 × local_count() entries, component fastest
  std::string units;
};

// Values on the opening faces for viewing: /openings/NAME, `width` values per face (shape
// (faces) or (faces, width)). Never read back.
struct OpeningFieldView {
  std::string name;
  int width = 1;               // 1: a scalar; 3: a vector
  std::vector<double> values;  // `width` per face of OpeningsView::owned, in that order
  std::string units;
};

// The opening faces (the same list on every rank), the ones this rank writes the values of
// (those whose owner cell it owns), and their fields.
struct OpeningsView {
  std::vector<grid::OpeningFace> faces;
  std::vector<std::size_t> owned;  // ordinals into `faces`
  std::vector<OpeningFieldView> fields;
  std::vector<std::string> region_names;  // of every boundary region, by index (attribute)
};

// What a snapshot carries only to be looked at: derived from the fields, never read back.
struct ViewingData {
  std::vector<CellVectorView> cell_vectors;
  OpeningsView openings;
};

// A root attribute naming how the run was made: a variable-length UTF-8 string or an int64.
struct RecordAttribute {
  std::string name;
  std::variant<std::string, long> value;
};

struct SnapshotInfo {
  double time = 0.0;
  long step = 0;
  double dt = 0.0;       // [s] the last step
  std::string title;
  double dt_next = 0.0;  // [s] the step the time loop would take next (exact restart)
  // The time-step controller's recorded costs (exact restart), attribute time_step_memory.
  std::vector<double> time_step_memory;
  std::vector<RecordAttribute> record;  // written on the root; not read back by read_snapshot
};

struct SnapshotHeader {
  double time = 0.0;                       // [s] when the snapshot was written
  std::vector<std::string> absent_fields;  // of the names asked about, those it has no field for
  std::size_t opening_faces = 0;           // faces in /openings (0: none, or written before it)
};
// A snapshot's time, which of `names` it lacks and how many opening faces it holds (rank-local,
// serial read); throws when unreadable.
SnapshotHeader read_snapshot_header(const std::string& path, const std::vector<std::string>& names);

// A string attribute of the snapshot's root (rank-local, serial read); nothing when the snapshot
// has no such attribute (written before it existed). Throws when the file is unreadable.
std::optional<std::string> read_text_attribute(const std::string& path, const std::string& name);

// About how many bytes write_snapshot writes for `field_count` fields and `vector_count` cell
// vectors and `opening_faces` opening faces (with `opening_values` values per face), from above:
// the arrays, the grid, the attributes, and 2 KiB of HDF5 metadata per dataset (its metadata
// block; measured 0.7-1.5 KiB). For checking that the disk has room before writing
// (run/output_writer.hpp).
std::uintmax_t snapshot_size_estimate(const parallel::Layout& layout, const grid::CellFlags& flags,
                                      std::size_t field_count, const SnapshotInfo& info,
                                      std::size_t vector_count = 0, std::size_t opening_faces = 0,
                                      std::size_t opening_values = 0);

// Collective: every rank calls with the same field names in the same order (and the same
// viewing data names and opening faces), and sends its owned values to rank 0, which writes the
// file alone, each dataset whole. The file is written as PATH.tmp and renamed when complete;
// rank 0 first reserves `reserve` bytes on disk for it (disk_reservation.hpp; 0: none). Every
// step of rank 0's is agreed on by all ranks (agree.hpp): a failure throws Hdf5Error naming the
// snapshot on every rank, the .tmp removed.
void write_snapshot(const std::string& path, const parallel::Layout& layout,
                    const grid::CellFlags& flags, const std::vector<FieldView>& fields,
                    const SnapshotInfo& info, const ViewingData& viewing = {},
                    std::uintmax_t reserve = 0);

struct SnapshotContents {
  SnapshotInfo info;
  std::vector<std::string> field_names;
};

// Collective: each rank reads the named fields into `fields` (local_count() entries each, halo
// included) for whatever layout the reader has, so a run restarts on any number of ranks. A
// failure on any rank throws on every rank (agree.hpp). Throws when the
// snapshot's grid differs from `layout`'s grid, or lacks a named field that is not in
// `optional` (an optional field the file lacks reads as NaN and is not in field_names).
SnapshotContents read_snapshot(const std::string& path, const parallel::Layout& layout,
                               const std::vector<std::string>& names,
                               std::vector<std::vector<double>>& fields,
                               const std::vector<std::string>& optional = {});

}  // namespace bagnold::io

#pragma once
// Translates an MFIX deck's records (src/app/mfix_namelist.hpp) into a Bagnold deck (TOML with
// comments), for box geometries. Every record is either translated, noted as a comment (it has
// no effect on the solution Bagnold computes, e.g. MFIX's own output files), or listed as
// unsupported with its line and why; nothing is dropped silently (docs/import-mfix.md).
//
// Frame: MFIX has y vertical, Bagnold z. A point (x, y, z) of MFIX is (x, z, y) in Bagnold;
// vectors (gravity, velocities) and faces (y- is z-, z+ is y+) map alike.

#include "src/app/mfix_namelist.hpp"

#include <array>
#include <string>
#include <vector>

namespace bagnold::app::mfix {

struct Unsupported {
  int line = 0;
  std::string keyword;  // e.g. "bc_type(3)"
  std::string why;
};

struct ImportResult {
  std::string deck;                      // the Bagnold deck; with lenient, it lists `unsupported`
  std::vector<Unsupported> unsupported;  // in the order of the file's lines
};

struct ImportOptions {
  std::string source_name;  // the file's name, written into the deck's header comment
  bool lenient = false;     // write the unsupported keywords as comments instead of refusing
};

ImportResult import_deck(const std::vector<Record>& records, const ImportOptions& options);

// MFIX point or vector (x, y vertical, z) in Bagnold's frame (x, y, z vertical).
std::array<double, 3> to_bagnold_frame(const std::array<double, 3>& mfix);

// "FILE:LINE: KEYWORD: why" lines for an error message.
std::string unsupported_report(const std::string& file, const std::vector<Unsupported>& list);

}  // namespace bagnold::app::mfix

// bagnold import-mfix FILE: an MFIX deck (mfix.dat or .mfx) as a Bagnold deck, on stdout or in
// the file -o names. A keyword Bagnold cannot express stops it with one error listing them all
// (exit 2) unless --lenient, which writes them into the deck as comments (docs/import-mfix.md).
#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/app/mfix_import.hpp"
#include "src/app/mfix_namelist.hpp"

#include <mpi.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace bagnold::app {

int import_mfix_command(const ImportMfixArguments& args) {
  std::ifstream in(args.file);
  if (!in) {
    say(args.file + ": cannot open the MFIX deck", true);
    return bad_input;
  }
  std::stringstream text;
  text << in.rdbuf();
  std::vector<mfix::Record> records;
  try {
    records = mfix::parse_namelist(text.str());
  } catch (const mfix::NamelistError& e) {
    say(args.file + ":" + std::to_string(e.line()) + ": " + e.what(), true);
    return bad_input;
  }
  // The header names the file without its directory, so a deck imported from anywhere is the same.
  const std::string name = std::filesystem::path(args.file).filename().string();
  const auto result = mfix::import_deck(records, {.source_name = name, .lenient = args.lenient});
  if (!result.unsupported.empty() && !args.lenient) {
    const auto n = result.unsupported.size();
    say(mfix::unsupported_report(args.file, result.unsupported) + "bagnold import-mfix: " +
            args.file + ": " + std::to_string(n) + " keyword" + (n == 1 ? "" : "s") +
            " Bagnold cannot express (listed above); --lenient writes them as comments instead",
        true);
    return bad_input;
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return success;
  if (!args.output.empty()) {
    std::ofstream out(args.output);
    out << result.deck;
    if (!out) {
      say(args.output + ": cannot write the deck", true);
      return bad_input;
    }
  }
  if (args.output.empty() || args.also_stdout) std::cout << result.deck << std::flush;
  return success;
}

}  // namespace bagnold::app

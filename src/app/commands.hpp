#pragma once
// The subcommands of `bagnold`; each returns an ExitCode.

#include <string>
#include <vector>

namespace bagnold::app {

struct DeckArguments {
  std::string deck;
  std::vector<std::string> overrides;  // --set key=value
  std::string petsc_options;           // --petsc-options "-log_view ..."
  std::string restart;                 // --restart SNAPSHOT_OR_RUN_DIR
  bool force = false;                  // --force: restart with a deck other than the snapshot's
  bool overwrite = false;              // --overwrite: replace the run in the output directory
  bool verbose = false;                // --verbose: log every change of dt
  std::vector<std::string> command_line;  // argv, for the run's provenance
};

struct RheometerArguments {
  std::string model;
  std::vector<double> phis;         // solids volume fractions [-]
  std::vector<double> shear_rates;  // [1/s]
  std::string deck;                 // optional: material and model constants from a deck
  std::vector<std::string> overrides;
};

struct ImportMfixArguments {
  std::string file;          // the MFIX deck (mfix.dat or .mfx)
  std::string output;        // -o FILE: write the deck there (else stdout)
  bool also_stdout = false;  // --stdout: with -o, print it too
  bool lenient = false;      // --lenient: unsupported keywords become comments
};

int import_mfix_command(const ImportMfixArguments& args);
int rheometer_command(const RheometerArguments& args);
int check_command(const DeckArguments& args);
int run_command(const DeckArguments& args);
int info_command();
int keys_command();

// Prints a message on rank 0 only (stderr when `error`).
void say(const std::string& text, bool error = false);

}  // namespace bagnold::app

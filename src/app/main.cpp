// bagnold: the command-line program. Subcommands: run, check, rheometer, info, keys,
// import-mfix; and
// `bagnold help [COMMAND]`, the same as --help.
#include <CLI/CLI.hpp>

#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/io/failed_file.hpp"
#include "src/parallel/communicator.hpp"
#include "src/util/build_info.hpp"
#include "src/util/closest_match.hpp"

#include <algorithm>
#include <iostream>

int main(int argc, char** argv) {
  using namespace bagnold::app;
  bagnold::parallel::MpiSession mpi(argc, argv);

  CLI::App cli{"Bagnold: two-fluid (Euler-Euler) gas-solid flow solver for dense granular flows"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "bagnold " + bagnold::version() + " (git " + bagnold::git_hash() + ")");

  DeckArguments deck_args;
  auto add_deck_options = [&](CLI::App* sub) {
    sub->add_option("deck", deck_args.deck, "Deck file (TOML)")->required();
    sub->add_option("--set", deck_args.overrides,
                    "Override a deck key, e.g. --set solids.diameter=1e-3 (repeatable)")
        ->allow_extra_args(false);
  };
  auto* run = cli.add_subcommand("run", "Run the simulation a deck describes");
  add_deck_options(run);
  auto* restart = run->add_option(
      "--restart", deck_args.restart,
      "Continue from a snapshot (or the last snapshot of a run directory), writing into its run "
      "directory unless --set output.directory is given; the deck must be the snapshot's except "
      "for [run] and [output]");
  run->add_flag("--force", deck_args.force,
                "With --restart: continue even though the deck differs from the snapshot's")
      ->needs(restart);
  run->add_flag("--overwrite", deck_args.overwrite,
                "Replace the run the output directory holds (its snapshots, run.xmf, monitor.csv, "
                "run.toml, provenance.toml, diagnostic.h5) instead of refusing");
  run->add_flag("--verbose", deck_args.verbose,
                "Log every change of dt with its reason, instead of one summary line per snapshot "
                "interval");
  run->add_option("--petsc-options", deck_args.petsc_options,
                  "PETSc options, e.g. \"-log_view -pressure_ksp_monitor\"");
  auto* check = cli.add_subcommand(
      "check", "Validate a deck without running; print the resolved configuration and geometry");
  add_deck_options(check);
  auto* info = cli.add_subcommand("info", "Version, build, MPI, PETSc, HDF5 and available models");
  RheometerArguments rheo;
  auto* rheometer = cli.add_subcommand(
      "rheometer", "Evaluate a solids-stress model under steady simple shear; CSV on stdout");
  rheometer->add_option("--model", rheo.model, "Model name (see bagnold info)")->required();
  rheometer->add_option("--phi", rheo.phis, "Solids volume fractions, e.g. 0.5,0.55,0.58")
      ->required()->delimiter(',');
  rheometer->add_option("--shear-rate", rheo.shear_rates, "Shear rates [1/s], e.g. 1,10,100")
      ->required()->delimiter(',');
  rheometer->add_option("--deck", rheo.deck, "Take material and model constants from a deck");
  rheometer->add_option("--set", rheo.overrides,
                        "Material or model key, e.g. --set solids.friction=0.5 (repeatable)")
      ->allow_extra_args(false);
  ImportMfixArguments import_args;
  auto* import_mfix = cli.add_subcommand(
      "import-mfix", "Write a Bagnold deck (TOML) from an MFIX deck (mfix.dat or .mfx); docs/import-mfix.md");
  import_mfix->add_option("file", import_args.file, "MFIX deck")->required();
  import_mfix->add_option("-o,--output", import_args.output, "Write the deck to this file instead of stdout");
  import_mfix->add_flag("--stdout", import_args.also_stdout, "With -o: print the deck on stdout too");
  import_mfix->add_flag("--lenient", import_args.lenient,
                        "Write the keywords Bagnold cannot express as comments instead of refusing");
  auto* keys = cli.add_subcommand("keys", "Print the deck key reference (Markdown, docs/deck.md)");

  // `bagnold help [COMMAND]` prints what --help prints.
  if (argc > 1 && std::string(argv[1]) == "help") {
    const CLI::App* topic = &cli;
    if (argc > 2) {
      try {
        topic = cli.get_subcommand(argv[2]);
      } catch (const CLI::OptionNotFound&) {
        say(std::string("bagnold help: unknown command '") + argv[2] + "'", true);
        return bad_input;
      }
    }
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) std::cout << topic->help();
    return success;
  }
  // Name an unknown command (CLI11 would only say that a subcommand is required).
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> known;
    for (const auto* sub : cli.get_subcommands([](CLI::App*) { return true; }))
      known.push_back(sub->get_name());
    if (std::find(known.begin(), known.end(), argv[1]) == known.end()) {
      std::string message = std::string("bagnold: unknown command '") + argv[1] + "'";
      if (auto guess = bagnold::closest_match(argv[1], known)) message += "; did you mean '" + *guess + "'?";
      say(message + " (commands: " + bagnold::join(known) + ")", true);
      return bad_input;
    }
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const int code = rank == 0 ? cli.exit(e) : (e.get_exit_code() == 0 ? 0 : 1);
    return code == 0 ? success : bad_input;
  }
  deck_args.command_line.assign(argv, argv + argc);
  if (run->parsed()) {
    const int code = run_command(deck_args);
    if (bagnold::io::a_failed_file_is_open()) bagnold::io::exit_leaving_failed_files_open(code);
    return code;
  }
  if (check->parsed()) return check_command(deck_args);
  if (info->parsed()) return info_command();
  if (rheometer->parsed()) return rheometer_command(rheo);
  if (keys->parsed()) return keys_command();
  if (import_mfix->parsed()) return import_mfix_command(import_args);
  return bad_input;
}

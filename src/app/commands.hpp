#pragma once
// The subcommands of `bagnold`; each returns an ExitCode.

#include <string>
#include <vector>

namespace bagnold::app {

struct DeckArguments {
  std::string deck;
  std::vector<std::string> overrides;  // --set key=value
};

int check_command(const DeckArguments& args);
int run_command(const DeckArguments& args);
int info_command();
int keys_command();

// Prints a message on rank 0 only (stderr when `error`).
void say(const std::string& text, bool error = false);

}  // namespace bagnold::app

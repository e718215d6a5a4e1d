#include "src/run/provenance.hpp"

#include <cstdlib>
#include <ctime>

#include "src/deck/schema.hpp"
#include "src/util/build_info.hpp"

namespace bagnold::run {

std::string utc_iso8601(std::chrono::system_clock::time_point time) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(time);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string shell_command_line(const std::vector<std::string>& arguments) {
  std::string out;
  for (const auto& a : arguments) {
    if (!out.empty()) out += ' ';
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                                                         "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                         "0123456789@%+=:,./_-") == std::string::npos;
    if (plain) {
      out += a;
      continue;
    }
    out += '\'';
    for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

Provenance describe_run(const std::vector<std::string>& arguments, int ranks,
                        const std::string& petsc_options, const std::string& restart_from) {
  Provenance p;
  p.command_line = shell_command_line(arguments);
  p.version = version();
  p.git_hash = git_hash();
  p.ranks = ranks;
  p.petsc_options = petsc_options;
  if (const char* environment = std::getenv("PETSC_OPTIONS")) p.petsc_options_environment = environment;
  p.start_time = utc_iso8601(std::chrono::system_clock::now());
  p.restart_from = restart_from;
  return p;
}

std::string provenance_toml(const Provenance& p) {
  using deck::to_toml_text;
  return "[[run]]\n"
         "command_line = " + to_toml_text(p.command_line) + "\n" +
         "version = " + to_toml_text(p.version) + "\n" +
         "git_hash = " + to_toml_text(p.git_hash) + "\n" +
         "ranks = " + std::to_string(p.ranks) + "\n" +
         "petsc_options = " + to_toml_text(p.petsc_options) + "\n" +
         "petsc_options_environment = " + to_toml_text(p.petsc_options_environment) + "\n" +
         "start_time = " + p.start_time + "\n" +
         "restart_from = " + to_toml_text(p.restart_from) + "\n";
}

std::vector<io::RecordAttribute> snapshot_record(const Provenance& p, const std::string& resolved_deck) {
  return {{"deck", resolved_deck},
          {"command_line", p.command_line},
          {"git_hash", p.git_hash},
          {"ranks", static_cast<long>(p.ranks)},
          {"petsc_options", p.petsc_options},
          {"petsc_options_environment", p.petsc_options_environment},
          {"start_time", p.start_time},
          {"restart_from", p.restart_from}};
}

}  // namespace bagnold::run

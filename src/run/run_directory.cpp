#include "src/run/run_directory.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/io/io_error.hpp"
#include "src/io/xdmf.hpp"

namespace bagnold::run {

namespace fs = std::filesystem;

namespace {

// The run's files besides the snapshots (run_directory.hpp).
const std::vector<std::string> record_files = {"run.xmf", "monitor.csv", "diagnostic.h5",
                                               "run.toml", "provenance.toml"};

const char* provenance_header =
    "# How the run in this directory was made: one [[run]] per start or restart of `bagnold run`\n"
    "# (docs/output.md, \"Provenance\"). start_time is UTC; restart_from is the snapshot a restart\n"
    "# continued from (\"\" for a fresh start). The deck in effect is run.toml.\n\n";

bool is_run_file(const std::string& name) {
  const std::string stem =
      name.size() > 4 && name.ends_with(".tmp") ? name.substr(0, name.size() - 4) : name;
  return snapshot_number(stem).has_value() ||
         std::find(record_files.begin(), record_files.end(), stem) != record_files.end();
}

}  // namespace

std::string snapshot_name(std::size_t number) {
  char name[64];
  std::snprintf(name, sizeof name, "snapshot_%06zu.h5", number);
  return name;
}

std::optional<std::size_t> snapshot_number(const std::string& file_name) {
  std::size_t n = 0;
  int consumed = 0;
  if (std::sscanf(file_name.c_str(), "snapshot_%zu.h5%n", &n, &consumed) != 1 ||
      static_cast<std::size_t>(consumed) != file_name.size() || snapshot_name(n) != file_name)
    return std::nullopt;
  return n;
}

std::vector<std::size_t> snapshot_numbers(const std::string& directory) {
  std::vector<std::size_t> numbers;
  for (const auto& entry : fs::directory_iterator(directory))
    if (const auto n = snapshot_number(entry.path().filename().string())) numbers.push_back(*n);
  std::sort(numbers.begin(), numbers.end());
  return numbers;
}

std::string restart_directory(const std::string& file_or_directory) {
  if (fs::is_directory(file_or_directory)) return file_or_directory;
  const fs::path parent = fs::path(file_or_directory).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

bool holds_run(const std::string& directory) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return false;
  if (fs::exists(fs::path(directory) / "monitor.csv", ec)) return true;
  for (const auto& entry : fs::directory_iterator(directory, ec))
    if (snapshot_number(entry.path().filename().string())) return true;
  return false;
}

std::vector<std::string> remove_run(const std::string& directory) {
  std::vector<std::string> removed;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return removed;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(directory))
    if (is_run_file(entry.path().filename().string())) doomed.push_back(entry.path());
  std::sort(doomed.begin(), doomed.end());
  for (const auto& path : doomed) {
    if (!fs::remove(path, ec) && ec)
      throw io::Hdf5Error("cannot remove " + path.string() + " (" + ec.message() + ")");
    removed.push_back(path.filename().string());
  }
  return removed;
}

void write_run_record(const std::string& directory, const std::string& resolved_deck,
                      const std::string& provenance_entry, bool continuing) {
  const fs::path dir(directory);
  io::write_file_atomically((dir / "run.toml").string(), resolved_deck);
  std::string provenance = provenance_header;
  if (continuing) {
    std::ifstream in(dir / "provenance.toml", std::ios::binary);
    if (in) {
      std::ostringstream old;
      old << in.rdbuf();
      provenance = old.str();
      if (!provenance.empty() && provenance.back() != '\n') provenance += '\n';
      provenance += '\n';
    }
  }
  io::write_file_atomically((dir / "provenance.toml").string(), provenance + provenance_entry);
}

}  // namespace bagnold::run

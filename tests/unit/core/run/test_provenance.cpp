// The provenance record: UTC ISO 8601 times, a command line a shell reads back to the same
// arguments, provenance.toml entries that are valid TOML holding every field, the snapshot
// attributes.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cstdio>

#include "src/run/provenance.hpp"
#include "src/util/build_info.hpp"

namespace bagnold::tests {
namespace {

TEST(Provenance, TimesAreUtcIso8601) {
  using namespace std::chrono;
  EXPECT_EQ(run::utc_iso8601(system_clock::time_point{}), "1970-01-01T00:00:00Z");
  // 2026-12-01 09:30:05 UTC = 1796117405 s after the epoch.
  EXPECT_EQ(run::utc_iso8601(system_clock::time_point{seconds{1796117405}}), "2026-12-01T09:30:05Z");
}

TEST(Provenance, TheCommandLineReadsBackInAShell) {
  const std::vector<std::string> args = {"build/bagnold", "run", "cases/bin/bin-10mm.toml",
                                         "--set", "solids.diameter = 1e-3", "--set",
                                         "run.title=\"it's\"", "--petsc-options", "-log_view $HOME", ""};
  const std::string line = run::shell_command_line(args);
  EXPECT_EQ(line.substr(0, 48), "build/bagnold run cases/bin/bin-10mm.toml --set ");
  // sh splits it back into the same arguments, one per line.
  FILE* shell = popen(("printf '%s\\n' " + line.substr(line.find(' ') + 1)).c_str(), "r");
  ASSERT_NE(shell, nullptr);
  std::string out;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, shell)) out += buffer;
  pclose(shell);
  std::string expected;
  for (std::size_t i = 1; i < args.size(); ++i) expected += args[i] + "\n";
  EXPECT_EQ(out, expected) << line;
}

TEST(Provenance, AnEntryIsValidTomlWithEveryField) {
  auto p = run::describe_run({"bagnold", "run", "deck.toml", "--restart", "runs/a b"}, 3,
                             "-log_view", "runs/a b/snapshot_000002.h5");
  p.petsc_options_environment = "-pressure_ksp_monitor \"x\"";
  EXPECT_EQ(p.version, version());
  EXPECT_EQ(p.git_hash, git_hash());
  EXPECT_FALSE(p.git_hash.empty());
  const auto table = toml::parse(run::provenance_toml(p));
  const auto& entry = *table["run"].as_array()->front().as_table();
  EXPECT_EQ(entry["command_line"].value<std::string>(), "bagnold run deck.toml --restart 'runs/a b'");
  EXPECT_EQ(entry["version"].value<std::string>(), version());
  EXPECT_EQ(entry["git_hash"].value<std::string>(), git_hash());
  EXPECT_EQ(entry["ranks"].value<int>(), 3);
  EXPECT_EQ(entry["petsc_options"].value<std::string>(), "-log_view");
  EXPECT_EQ(entry["petsc_options_environment"].value<std::string>(), p.petsc_options_environment);
  EXPECT_EQ(entry["restart_from"].value<std::string>(), "runs/a b/snapshot_000002.h5");
  ASSERT_TRUE(entry["start_time"].is_date_time());  // a TOML offset date-time, not a string
  EXPECT_EQ(entry["start_time"].as_date_time()->get().offset->minutes, 0);
}

TEST(Provenance, SnapshotAttributesCarryTheDeckAndEveryField) {
  run::Provenance p;
  p.command_line = "bagnold run d.toml";
  p.ranks = 2;
  const auto record = run::snapshot_record(p, "[run]\nend_time = 1.0\n");
  std::vector<std::string> names;
  for (const auto& r : record) names.push_back(r.name);
  EXPECT_EQ(names, (std::vector<std::string>{"deck", "command_line", "git_hash", "ranks",
                                             "petsc_options", "petsc_options_environment",
                                             "start_time", "restart_from"}));
  EXPECT_EQ(std::get<std::string>(record[0].value), "[run]\nend_time = 1.0\n");
  EXPECT_EQ(std::get<long>(record[3].value), 2);
}

}  // namespace
}  // namespace bagnold::tests

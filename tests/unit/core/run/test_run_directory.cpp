// The files of a run directory: which ones make a run, which ones --overwrite removes (those,
// their temporaries, nothing else), where a restart's directory is, and the run record.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "src/run/run_directory.hpp"

namespace bagnold::tests {
namespace {

namespace fs = std::filesystem;

// A fresh directory under the test's working directory.
fs::path fresh(const std::string& name) {
  const fs::path dir = fs::current_path() / ("run_directory_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void touch(const fs::path& path, const std::string& text = "x\n") { std::ofstream(path) << text; }

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RunDirectory, SnapshotNamesAreExactlyTheWrittenForm) {
  EXPECT_EQ(run::snapshot_name(12), "snapshot_000012.h5");
  EXPECT_EQ(run::snapshot_number("snapshot_000012.h5"), std::optional<std::size_t>(12));
  for (const auto* other : {"snapshot_00012.h5", "snapshot_+00012.h5", "snapshot_000012.h5.tmp",
                            "snapshot_000012.h5x", "diagnostic.h5"})
    EXPECT_FALSE(run::snapshot_number(other)) << other;
}

TEST(RunDirectory, ARunIsASnapshotOrAMonitor) {
  const auto dir = fresh("holds");
  EXPECT_FALSE(run::holds_run((dir / "missing").string()));
  EXPECT_FALSE(run::holds_run(dir.string()));  // empty
  touch(dir / "notes.txt");
  touch(dir / "snapshot_00009.h5");  // not the written form
  touch(dir / "run.toml");           // a record alone is no run to lose
  EXPECT_FALSE(run::holds_run(dir.string()));
  touch(dir / "snapshot_000003.h5");
  EXPECT_TRUE(run::holds_run(dir.string()));
  fs::remove(dir / "snapshot_000003.h5");
  touch(dir / "monitor.csv");
  EXPECT_TRUE(run::holds_run(dir.string()));
}

TEST(RunDirectory, RemovingARunLeavesEveryOtherFile) {
  const auto dir = fresh("remove");
  const std::set<std::string> run_files = {
      "snapshot_000000.h5", "snapshot_000001.h5", "snapshot_000002.h5.tmp", "run.xmf",
      "run.xmf.tmp", "monitor.csv", "diagnostic.h5", "run.toml", "provenance.toml"};
  const std::set<std::string> others = {"notes.txt", "snapshot_00009.h5", "snapshot_+00007.h5",
                                        "my_run.toml", "monitor.csv.bak", "sub"};
  for (const auto& n : run_files) touch(dir / n);
  for (const auto& n : others) n == "sub" ? (void)fs::create_directory(dir / n) : touch(dir / n);
  touch(dir / "sub" / "monitor.csv");  // another run's, one level down: not this one's
  const auto removed = run::remove_run(dir.string());
  EXPECT_EQ(std::set<std::string>(removed.begin(), removed.end()), run_files);
  EXPECT_EQ(names_in(dir), others);
  EXPECT_TRUE(fs::exists(dir / "sub" / "monitor.csv"));
  EXPECT_FALSE(run::holds_run(dir.string()));
}

TEST(RunDirectory, ARestartsDirectoryIsTheOneGivenOrTheSnapshots) {
  const auto dir = fresh("restart");
  touch(dir / "snapshot_000004.h5");
  touch(dir / "snapshot_000002.h5");
  EXPECT_EQ(run::restart_directory(dir.string()), dir.string());
  EXPECT_EQ(run::restart_directory((dir / "snapshot_000002.h5").string()), dir.string());
  EXPECT_EQ(run::restart_directory("snapshot_000002.h5"), ".");
}

TEST(RunDirectory, TheRecordIsTheDeckAndOneProvenanceEntryPerStart) {
  const auto dir = fresh("record");
  run::write_run_record(dir.string(), "[run]\nend_time = 1.0\n", "[[run]]\nranks = 1\n", false);
  EXPECT_EQ(read(dir / "run.toml"), "[run]\nend_time = 1.0\n");
  run::write_run_record(dir.string(), "[run]\nend_time = 2.0\n", "[[run]]\nranks = 2\n", true);
  EXPECT_EQ(read(dir / "run.toml"), "[run]\nend_time = 2.0\n");
  const auto appended = toml::parse_file((dir / "provenance.toml").string());
  const auto* runs = appended["run"].as_array();
  ASSERT_NE(runs, nullptr);
  ASSERT_EQ(runs->size(), 2u);
  EXPECT_EQ((*runs)[0].as_table()->get("ranks")->value<int>(), 1);
  EXPECT_EQ((*runs)[1].as_table()->get("ranks")->value<int>(), 2);
  // A fresh start begins a new record.
  run::write_run_record(dir.string(), "[run]\nend_time = 3.0\n", "[[run]]\nranks = 3\n", false);
  EXPECT_EQ(toml::parse_file((dir / "provenance.toml").string())["run"].as_array()->size(), 1u);
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"run.toml", "provenance.toml"}));  // no .tmp
}

}  // namespace
}  // namespace bagnold::tests

// The monitor time series: a header of column names, one row per append, and on restart the
// rows later than the restart time dropped (a row at the restart time is kept).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/io/monitor.hpp"

namespace bagnold::tests {
namespace {

namespace fs = std::filesystem;

class MonitorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = fs::temp_directory_path() / ("bagnold_monitor_" + std::to_string(::getpid()));
    fs::create_directories(m_dir);
    m_path = (m_dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                       ".csv"))
                 .string();
    fs::remove(m_path);
  }
  void TearDown() override { fs::remove_all(m_dir); }
  std::string contents() const {
    std::ifstream in(m_path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path m_dir;
  std::string m_path;
};

TEST_F(MonitorTest, HeaderAndRows) {
  {
    io::Monitor m(m_path, {"dt", "inventory_solids"}, true);
    EXPECT_EQ(m.columns(), (std::vector<std::string>{"dt", "inventory_solids"}));
    EXPECT_EQ(contents(), "time,dt,inventory_solids\n");
    m.append(0.0, {1e-4, 2.5});
    m.append(0.125, {2e-4, -3.0});
    EXPECT_EQ(contents(), "time,dt,inventory_solids\n0,0.0001,2.5\n0.125,0.0002,-3\n");
  }
}

TEST_F(MonitorTest, ResumeDropsRowsAfterTheRestartTime) {
  std::ofstream(m_path) << "time,dt\n0,1\n0.1,2\n0.2,3\n0.30000000000000004,4\n0.4,5\n";
  const double restart = 0.3;
  io::Monitor m(m_path, {"dt"}, true, &restart);
  // 0.30000000000000004 is the restart time up to round-off: kept.
  EXPECT_EQ(contents(), "time,dt\n0,1\n0.1,2\n0.2,3\n0.30000000000000004,4\n");
  m.append(0.35, {6.0});
  EXPECT_EQ(contents(), "time,dt\n0,1\n0.1,2\n0.2,3\n0.30000000000000004,4\n0.35,6\n");
}

TEST_F(MonitorTest, ResumeWithOtherColumnsKeepsTheRowsByName) {
  // A run of an older build, without the last column: its rows stay, with nan there.
  std::ofstream(m_path) << "time,dt,courant\n0,1,0.5\n0.1,2,0.25\n0.2,3,0.125\n";
  const double restart = 0.1;
  io::Monitor m(m_path, {"dt", "courant", "force_residual"}, true, &restart);
  EXPECT_EQ(contents(), "time,dt,courant,force_residual\n0,1,0.5,nan\n0.1,2,0.25,nan\n");
  EXPECT_FALSE(fs::exists(m_path + ".before-restart"));  // nothing was dropped
  m.append(0.15, {4.0, 0.5, 1e-3});
  EXPECT_EQ(contents(), "time,dt,courant,force_residual\n0,1,0.5,nan\n0.1,2,0.25,nan\n0.15,4,0.5,0.001\n");
}

TEST_F(MonitorTest, ResumeThatDropsAColumnKeepsTheEarlierFileWhole) {
  const std::string earlier = "time,dt,flux_orifice\n0,1,0\n0.1,2,0\n";
  std::ofstream(m_path) << earlier;
  const double restart = 0.1;
  io::Monitor m(m_path, {"flux_top", "dt"}, true, &restart);
  EXPECT_EQ(contents(), "time,flux_top,dt\n0,nan,1\n0.1,nan,2\n");
  std::ifstream in(m_path + ".before-restart");
  std::ostringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), earlier);
}

TEST_F(MonitorTest, NewRunReplacesAnOldSeries) {
  std::ofstream(m_path) << "time,dt\n0,1\n0.1,2\n";
  io::Monitor m(m_path, {"dt"}, true);
  EXPECT_EQ(contents(), "time,dt\n");
}

TEST_F(MonitorTest, InactiveMonitorWritesNothing) {
  io::Monitor m(m_path, {"dt"}, false);
  m.append(0.0, {1.0});
  EXPECT_FALSE(fs::exists(m_path));
}

}  // namespace
}  // namespace bagnold::tests

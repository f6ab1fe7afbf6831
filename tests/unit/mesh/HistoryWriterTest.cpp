#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "io/HistoryWriter.hpp"

using contessa::io::HistoryWriter;

namespace {

std::string tempPath() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "contessa_history_" + info->name() + "_" + std::to_string(getpid()) + ".csv";
}

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST(HistoryWriter, HeaderIntegersAndDoubles) {
  const std::string path = tempPath();
  {
    HistoryWriter history(path, {"step", "time", "attempts", "newton_iterations", "load_factor"},
                          {"step", "attempts", "newton_iterations"});
    // The header is on disk before any row.
    EXPECT_EQ(contents(path), "step,time,attempts,newton_iterations,load_factor\n");
    history.writeRow({1, 0.1, 1, 4, 1.0 / 3.0});
    history.writeRow({2, 0.25, 3, 12, 1e-20});
    EXPECT_EQ(history.rowsWritten(), 2);
    // Rows are flushed as they are written: read back while the writer is still alive.
    EXPECT_EQ(contents(path),
              "step,time,attempts,newton_iterations,load_factor\n"
              "1,0.1,1,4,0.333333333333\n"
              "2,0.25,3,12,1e-20\n");
  }
  std::remove(path.c_str());
}

TEST(HistoryWriter, LargeIntegersAndNonFiniteValues) {
  const std::string path = tempPath();
  {
    HistoryWriter history(path, {"step", "residual"}, {"step"});
    history.writeRow({123456789012.0, std::numeric_limits<double>::quiet_NaN()});
    history.writeRow({3.0000000001, 123456.789012345});
  }
  EXPECT_EQ(contents(path), "step,residual\n123456789012,nan\n3,123456.789012\n");
  std::remove(path.c_str());
}

TEST(HistoryWriter, AllDoubleColumnsByDefaultAndQuotedNames) {
  const std::string path = tempPath();
  {
    HistoryWriter history(path, {"time", "force, N"});
    history.writeRow({2, 2.5});
  }
  EXPECT_EQ(contents(path), "time,\"force, N\"\n2,2.5\n");
  std::remove(path.c_str());
}

TEST(HistoryWriter, RejectsBadUse) {
  const std::string path = tempPath();
  EXPECT_THROW(HistoryWriter(path, {"time"}, {"step"}), std::invalid_argument);
  HistoryWriter history(path, {"step", "time"}, {"step"});
  EXPECT_THROW(history.writeRow({1}), std::invalid_argument);
  EXPECT_EQ(history.rowsWritten(), 0);
  std::remove(path.c_str());
  try {
    HistoryWriter bad("/nonexistent/dir/history.csv", {"time"});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/history.csv"), std::string::npos);
  }
}

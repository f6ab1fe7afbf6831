// The history CSV reports a path it cannot write with the system's reason.
#include <gtest/gtest.h>

#include <string>

#include "io/HistoryWriter.hpp"
#include "io/OutputWriteError.hpp"

TEST(HistoryWriter, PathThatIsADirectoryNamesTheSystemReason) {
  const std::string path = ::testing::TempDir();
  try {
    contessa::io::HistoryWriter history(path, {"step"});
    FAIL() << "no exception";
  } catch (const contessa::io::OutputWriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot create " + path + ": Is a directory");
  }
}

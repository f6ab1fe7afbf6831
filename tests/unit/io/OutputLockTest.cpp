// One run per output: the second lock on the same output fails while the first is held, naming its
// holder, and succeeds once it is released.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <memory>
#include <string>

#include "common/Error.hpp"
#include "io/OutputLock.hpp"

using contessa::InputError;
using contessa::io::OutputLock;

namespace {

std::string tempDirectory() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string dir = ::testing::TempDir() + "contessa_lock_" + info->name() + "_" + std::to_string(getpid());
  mkdir(dir.c_str(), 0755);
  return dir;
}

bool exists(const std::string& path) {
  struct stat info {};
  return stat(path.c_str(), &info) == 0;
}

}  // namespace

TEST(OutputLock, SecondRunOnTheSameOutputIsRefusedNamingTheFirst) {
  const std::string dir = tempDirectory();
  auto first = std::make_unique<OutputLock>(dir, "tube");
  EXPECT_EQ(first->path(), dir + "/tube.lock");
  EXPECT_TRUE(first->warning().empty());
  try {
    OutputLock second(dir, "tube");
    FAIL() << "the second lock was granted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("--output-dir " + dir + ": another run is writing tube.exo there (PID " +
                                std::to_string(getpid()) + " on host ",
                            0),
              0u)
        << message;
    EXPECT_NE(message.find("lock file " + dir + "/tube.lock)"), std::string::npos) << message;
  }
  // Another name in the same directory is another output.
  EXPECT_NO_THROW(OutputLock other(dir, "ring"));
  first.reset();
  EXPECT_FALSE(exists(dir + "/tube.lock"));
  EXPECT_NO_THROW(OutputLock again(dir, "tube"));
  rmdir(dir.c_str());
}

TEST(OutputLock, LockFileLeftByAKilledRunDoesNotBlock) {
  const std::string dir = tempDirectory();
  std::ofstream(dir + "/tube.lock") << "PID 1 on host gone since 2000-01-01 00:00:00\n";
  EXPECT_NO_THROW(OutputLock lock(dir, "tube"));
  EXPECT_FALSE(exists(dir + "/tube.lock"));
  rmdir(dir.c_str());
}

TEST(OutputLock, DirectoryThatDoesNotExistIsAnInputError) {
  try {
    OutputLock lock("/nonexistent/dir", "tube");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--output-dir /nonexistent/dir: cannot write into the directory: No such file or directory "
              "(creating /nonexistent/dir/tube.lock)");
  }
}

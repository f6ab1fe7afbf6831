// How failures reach the user (apps/contessa/Failure): one line and an exit status on any number of
// ranks; bad input seen by one rank only is agreed on by all. Run on 1 rank and on 2 (failure_test_np2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <new>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "Failure.hpp"
#include "common/Error.hpp"

namespace {

using contessa::InputError;
using contessa::app::FailureReporter;

auto comm() { return Tpetra::getDefaultComm(); }
bool root() { return comm()->getRank() == 0; }

// Runs `body` through a reporter; returns its status and what it wrote on stderr.
std::pair<int, std::string> report(const std::function<int()>& body) {
  FailureReporter reporter(comm(), "testing");
  ::testing::internal::CaptureStderr();
  const int status = reporter.run(body);
  return {status, ::testing::internal::GetCapturedStderr()};
}

// Every rank fails alike: rank 0 prints one line, every rank returns the status.
void expectOneLine(const std::function<int()>& body, int status, const std::string& line) {
  const auto [s, err] = report(body);
  EXPECT_EQ(s, status);
  EXPECT_EQ(err, root() ? "contessa: error: " + line + "\n" : "");
}

TEST(FailureReporter, EveryKindOfErrorIsOneLineWithItsStatus) {
  expectOneLine([]() -> int { throw InputError("deck.xml:3: unclosed element <ParameterList>"); }, 2,
                "deck.xml:3: unclosed element <ParameterList>");
  expectOneLine([]() -> int { throw std::bad_alloc(); }, 1, "out of memory while testing");
  expectOneLine([]() -> int {
    throw std::runtime_error("Piro_NOXSolver_Def.hpp:178:\n\nThrow number = 1\n\nThrow test that evaluated to true: "
                             "true\n\nthe solve did not converge");
  }, 1, "the solve did not converge");
  expectOneLine([]() -> int { throw 42; }, 1, "internal error (an exception of unknown type) while testing");
  const auto [status, err] = report([] { return 3; });
  EXPECT_EQ(status, 3);
  EXPECT_EQ(err, "");
}

TEST(AgreeOnInput, AnErrorOnTheLastRankStopsEveryRank) {
  // As a mesh file that only the last rank cannot read: every rank throws that rank's message.
  const int last = comm()->getSize() - 1;
  try {
    contessa::app::agreeOnInput(*comm(), [&] {
      if (comm()->getRank() == last) throw InputError("Problem/Mesh/File Name: mesh file 'm.exo' does not exist");
    });
    FAIL() << "no error on rank " << comm()->getRank();
  } catch (const InputError& e) {
    const std::string expected = "Problem/Mesh/File Name: mesh file 'm.exo' does not exist" +
                                 (last == 0 ? std::string() : " (on rank " + std::to_string(last) + ")");
    EXPECT_EQ(std::string(e.what()), expected);
  }
  EXPECT_NO_THROW(contessa::app::agreeOnInput(*comm(), [] {}));
  try {
    contessa::app::agreeOnInput(*comm(), [] { throw std::bad_alloc(); });
    FAIL() << "no error";
  } catch (const InputError&) {
    FAIL() << "out of memory is not bad input";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "out of memory while reading the deck and building the mesh");
  }
}

TEST(ShareDeckText, ReadOnceOnRankZero) {
  // A named pipe has one reader: every rank gets its text only if rank 0 alone reads it (a second
  // reader would wait for a writer forever).
  std::string dir = root() ? (std::filesystem::temp_directory_path() / ("contessa_failure_" + std::to_string(::getpid()))).string()
                           : std::string();
  int length = static_cast<int>(dir.size());
  Teuchos::broadcast(*comm(), 0, &length);
  dir.resize(length);
  Teuchos::broadcast(*comm(), 0, length, &dir[0]);
  const std::string fifo = dir + "/deck.xml";
  std::thread writer;
  if (root()) {
    std::filesystem::create_directories(dir);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    writer = std::thread([&] { std::ofstream(fifo) << "<ParameterList/>\n"; });
  }
  EXPECT_EQ(contessa::app::shareDeckText(*comm(), fifo), "<ParameterList/>\n");
  if (root()) {
    writer.join();
    std::filesystem::remove_all(dir);
  }
  try {
    contessa::app::shareDeckText(*comm(), dir + "/missing.xml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/missing.xml: cannot open deck file (no such file)");
  }
}

}  // namespace

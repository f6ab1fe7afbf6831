// The restart file's format (io/RestartFile.hpp): records come back as written (sorted by key, any order
// in), and a file that is not one, of another version, truncated or with a changed byte is refused with a
// one-line InputError naming the file; deckDifference names the first parameter that differs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "common/Error.hpp"
#include "io/RestartFile.hpp"

namespace io = contessa::io;
using contessa::InputError;

namespace {

io::RestartContent sample() {
  io::RestartContent c;
  c.deck = "Problem/Mesh/Type = Annulus Sector\nPiro/LOCA/Step Size/Contacts Per Step = 2\n";
  c.nodes = 1428;
  c.elements = 1313;
  c.meshHash = 0x0123456789abcdefULL;
  c.records = {{20, 7, {1.5, -2.25}}, {10, 3, {0.1, 1e-300, -0.0}}, {20, 1, {}}, {1, 0, {42}}};
  return c;
}

std::string errorOf(const std::string& bytes) {
  try {
    io::decodeRestart(bytes, "out/tube.restart");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RestartFile, RecordsComeBackSortedAndExact) {
  const auto c = io::decodeRestart(io::encodeRestart(sample()), "x");
  EXPECT_EQ(c.deck, sample().deck);
  EXPECT_EQ(c.nodes, 1428);
  EXPECT_EQ(c.elements, 1313);
  EXPECT_EQ(c.meshHash, 0x0123456789abcdefULL);
  ASSERT_EQ(c.records.size(), 4u);
  EXPECT_EQ(c.records[0].kind, 1);
  EXPECT_EQ(c.records[1].kind, 10);
  EXPECT_EQ(c.records[1].values, (std::vector<double>{0.1, 1e-300, -0.0}));
  EXPECT_TRUE(std::signbit(c.records[1].values[2]));
  EXPECT_EQ(c.records[2].id, 1);
  EXPECT_TRUE(c.records[2].values.empty());
  EXPECT_EQ(c.records[3].id, 7);
  const io::RestartRecords index(c.records);
  EXPECT_EQ(index.at(20, 7, "element 8"), (std::vector<double>{1.5, -2.25}));
  EXPECT_EQ(index.find(20, 2), nullptr);
  EXPECT_THROW(index.at(20, 2, "element 3"), InputError);
}

TEST(RestartFile, DamagedFilesAreRefusedInOneLine) {
  const std::string good = io::encodeRestart(sample());
  EXPECT_EQ(errorOf("<ParameterList/>"), "--restart out/tube.restart: not a Contessa restart file");
  EXPECT_EQ(errorOf(good.substr(0, 100)), "--restart out/tube.restart: truncated restart file (100 bytes, " +
                                              std::to_string(good.size()) + " expected)");
  std::string changed = good;
  changed[changed.size() - 3] ^= 0x40;
  EXPECT_EQ(errorOf(changed), "--restart out/tube.restart: corrupt restart file (checksum mismatch)");
  EXPECT_EQ(errorOf(good + "x"), "--restart out/tube.restart: corrupt restart file (1 bytes past its end)");
  std::string version = good;
  version[16] = 9;
  EXPECT_EQ(errorOf(version), "--restart out/tube.restart: restart file format version 9, this Contessa reads version 2");
  for (const std::string& e : {errorOf(changed), errorOf(good.substr(0, 40))}) EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(RestartFile, DeckDifferenceNamesTheParameter) {
  const std::string a = "A/x = 1\nA/y = 2\n";
  EXPECT_EQ(io::deckDifference(a, a), "");
  EXPECT_EQ(io::deckDifference(a, "A/x = 1\nA/y = 3\n"), "A/y is 2 in the restart file, 3 here");
  EXPECT_EQ(io::deckDifference(a, "A/x = 1\nA/y = 2\nA/z = 0\n"), "A/z is not in the restart file's deck (0 here)");
  EXPECT_EQ(io::deckDifference(a, "A/x = 1\n"), "A/y (2) is in the restart file's deck, not here");
}

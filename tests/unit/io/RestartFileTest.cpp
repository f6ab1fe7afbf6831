// The restart file's format (io/RestartFile.hpp, netCDF-4 with named fields): the state comes back bit for
// bit; a field added to a class is written and read with no other code changed; a file that is not one,
// of the old binary format, truncated or with a changed value is refused with a one-line InputError
// naming the file; deckDifference names the first parameter that differs.
#include <gtest/gtest.h>

#include <netcdf.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "common/Error.hpp"
#include "common/StateRecord.hpp"
#include "io/RestartFile.hpp"

namespace io = contessa::io;
using contessa::InputError;
using contessa::StateReader;
using contessa::StateRecord;
using contessa::StateTableWriter;
using contessa::StateValues;
using contessa::StateWriter;

namespace {

io::RestartContent sample() {
  io::RestartContent c;
  c.deck = "Problem/Mesh/Type = Annulus Sector\nPiro/LOCA/Step Size/Contacts Per Step = 2\n";
  c.nodes = 1428;
  c.elements = 1313;
  c.meshHash = 0xf123456789abcdefULL;  // above 2^63: an unsigned attribute
  auto& run = c.state.child("continuation");
  run.put("lambda", std::vector<double>{1234.5678}, {});
  run.put("increments", std::vector<std::int64_t>{12}, {});
  run.put("empty", std::vector<double>{}, {0});
  run.putText("method", "Contact Beta");
  c.state.child("step_size").child("contact_beta").put("predicted_fractions", std::vector<double>{0.1, -0.0}, {2});
  StateTableWriter rows(c.state.child("nodes"));
  for (const std::int64_t node : {2, 0, 1}) {
    rows.beginRow(node);
    rows("displacement", std::vector<double>{0.5 + static_cast<double>(node), -1e-300});
  }
  rows.finish();
  c.state.child("contact").child("interface_0").child("slaves").put(
      "gap", std::vector<double>{std::numeric_limits<double>::infinity(), std::nan("")}, {2});
  StateTableWriter none(c.state.child("contact").child("interface_0").child("master"));
  none.finish();  // a table with no rows
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

// A class that keeps state over a restart, in two versions: After declares one more field than Before,
// with one line in its stateFields and nothing else in the program changed.
struct Before {
  double angle = 0;
  int swings = 0;
  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("angle", self.angle);
    field("swings", self.swings);
  }
};
struct After {
  double angle = 0;
  int swings = 0;
  std::vector<double> trace;  // the added member
  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("angle", self.angle);
    field("swings", self.swings);
    field("trace", self.trace);  // the added line
  }
};

template <class T>
std::string fileOf(const T& object) {
  io::RestartContent c;
  StateWriter w(c.state.child("pendulum"));
  T::stateFields(object, w);
  return io::encodeRestart(c);
}

template <class T>
T loaded(const std::string& bytes) {
  const auto c = io::decodeRestart(bytes, "out/pendulum.restart");
  T object;
  StateReader in(c.state.child("pendulum"));
  T::stateFields(object, in);
  c.state.requireAllRead();
  return object;
}

template <class T>
std::string loadError(const std::string& bytes) {
  try {
    loaded<T>(bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RestartFile, StateComesBackBitForBit) {
  const std::string bytes = io::encodeRestart(sample());
  const auto c = io::decodeRestart(bytes, "x");
  EXPECT_EQ(c.deck, sample().deck);
  EXPECT_EQ(c.nodes, 1428);
  EXPECT_EQ(c.elements, 1313);
  EXPECT_EQ(c.meshHash, 0xf123456789abcdefULL);
  auto expected = sample().state;
  expected.sortTables();
  EXPECT_TRUE(contessa::sameState(c.state, expected));
  // Rows sorted by id whatever order they were written in.
  EXPECT_EQ(c.state.child("nodes").fields().at("id").integers, (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(c.state.child("nodes").fields().at("displacement").doubles[4], 2.5);
  EXPECT_EQ(c.state.child("continuation").getText("method"), "Contact Beta");
  EXPECT_EQ(c.state.origin(), "--restart x");
  // The same content, the same bytes: a file independent of the order the ranks' rows came in.
  EXPECT_EQ(io::encodeRestart(sample()), bytes);
}

// The file on disk: netCDF-4 that a standard tool reads, and opens for writing (an edit by a tool), read
// back as written.
TEST(RestartFile, IsNetcdf4ThatOtherToolsReadAndEdit) {
  const std::string path = "restart_file_test_" + std::to_string(::getpid()) + ".restart";
  ASSERT_EQ(io::writeRestartFile(path, sample()), "");
  auto expected = sample().state;
  expected.sortTables();
  EXPECT_TRUE(contessa::sameState(io::readRestartFile(path).state, expected));
  int nc = -1, group = -1, sub = -1, var = -1, version = 0;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &nc), NC_NOERR);
  EXPECT_EQ(nc_get_att_int(nc, NC_GLOBAL, "format_version", &version), NC_NOERR);
  EXPECT_EQ(version, 3);
  ASSERT_EQ(nc_inq_grp_ncid(nc, "continuation", &group), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(group, "lambda", &var), NC_NOERR);
  double lambda = 0;
  EXPECT_EQ(nc_get_var_double(group, var, &lambda), NC_NOERR);
  EXPECT_EQ(lambda, 1234.5678);
  ASSERT_EQ(nc_inq_grp_ncid(nc, "nodes", &sub), NC_NOERR);
  int dims = 0;
  ASSERT_EQ(nc_inq_varid(sub, "displacement", &var), NC_NOERR);
  EXPECT_EQ(nc_inq_varndims(sub, var, &dims), NC_NOERR);
  EXPECT_EQ(dims, 2);
  nc_close(nc);
  std::remove(path.c_str());
  EXPECT_NE(io::writeRestartFile("no/such/directory/x.restart", sample()), "");
}

// Issue 18: a field added to one class is written and read without touching any other file, and files
// of the other version are refused naming the field.
TEST(RestartFile, AFieldAddedToOneClassIsWrittenAndRead) {
  After a;
  a.angle = 0.75;
  a.swings = 3;
  a.trace = {0.125, -2.5, 1e10};
  const After b = loaded<After>(fileOf(a));
  EXPECT_EQ(b.angle, 0.75);
  EXPECT_EQ(b.swings, 3);
  EXPECT_EQ(b.trace, a.trace);
  Before old;
  old.angle = 0.5;
  EXPECT_EQ(loaded<Before>(fileOf(old)).angle, 0.5);
  // An older file lacks the field; a newer one has a field the older class does not know.
  EXPECT_EQ(loadError<After>(fileOf(old)), "--restart out/pendulum.restart: pendulum/trace: missing (this Contessa needs it)");
  EXPECT_EQ(loadError<Before>(fileOf(a)),
            "--restart out/pendulum.restart: pendulum/trace: unknown field (this Contessa does not read it: "
            "written by another version?)");
}

// Issue 22: a value that is not finite, in a file whose checksum is valid, is refused naming the field
// and the file.
TEST(RestartFile, ANaNWithAValidChecksumIsRefusedNamingTheField) {
  io::RestartContent c = sample();
  c.state.sortTables();  // rows by id: row 1 is node id 1
  auto& nodes = c.state.child("nodes");
  const_cast<contessa::StateField&>(nodes.fields().at("displacement")).doubles[3] = std::nan("");
  const auto back = io::decodeRestart(io::encodeRestart(c), "out/tube.restart");  // the checksum holds
  contessa::StateTableReader rows(back.state.child("nodes"));
  std::vector<double> u;
  rows.seek(0, "node 1");
  rows("displacement", u);
  rows.seek(1, "node 2");
  try {
    rows("displacement", u);
    ADD_FAILURE() << "a NaN displacement was read";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--restart out/tube.restart: nodes/id 1/displacement: value 1 is nan, a finite number expected");
  }
}

TEST(RestartFile, DamagedFilesAreRefusedInOneLine) {
  const std::string good = io::encodeRestart(sample());
  EXPECT_EQ(errorOf("<ParameterList/>"), "--restart out/tube.restart: not a Contessa restart file");
  EXPECT_EQ(errorOf(good.substr(0, 100)), "--restart out/tube.restart: truncated restart file (100 bytes, " +
                                              std::to_string(good.size()) + " expected)");
  // A changed value (lambda's last byte): the file still opens, the checksum does not match.
  double lambda = 1234.5678;
  char pattern[sizeof lambda];
  std::memcpy(pattern, &lambda, sizeof lambda);
  const auto at = good.find(std::string(pattern, sizeof pattern));
  ASSERT_NE(at, std::string::npos);
  std::string changed = good;
  changed[at] ^= 0x01;
  EXPECT_EQ(errorOf(changed), "--restart out/tube.restart: corrupt restart file (checksum mismatch)");
  // A netCDF-4 file that is not a restart file.
  io::RestartContent other;
  std::string foreign = io::encodeRestart(other);
  const auto title = foreign.find("Contessa restart file");
  ASSERT_NE(title, std::string::npos);
  foreign[title] = 'X';
  EXPECT_EQ(errorOf(foreign), "--restart out/tube.restart: not a Contessa restart file");
  for (const std::string& e : {errorOf(changed), errorOf(good.substr(0, 40)), errorOf(good.substr(0, 3000))})
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

// A restart file written before named fields (format version 2: the "CONTESSA RESTART" binary header) is
// refused with its format version.
TEST(RestartFile, AnOldFormatIsRefusedWithItsVersion) {
  std::string old = "CONTESSA RESTART";
  const std::uint32_t version = 2;
  old.append(reinterpret_cast<const char*>(&version), sizeof version);
  old.append(std::string(40, '\0'));
  EXPECT_EQ(errorOf(old),
            "--restart out/tube.restart: restart file format version 2 (a binary file of positional records), this "
            "Contessa reads version 3 (netCDF-4 with named fields); continue the run with the Contessa that wrote "
            "it, or start it again");
}

TEST(RestartFile, DeckDifferenceNamesTheParameter) {
  const std::string a = "A/x = 1\nA/y = 2\n";
  EXPECT_EQ(io::deckDifference(a, a), "");
  EXPECT_EQ(io::deckDifference(a, "A/x = 1\nA/y = 3\n"), "A/y is 2 in the restart file, 3 here");
  EXPECT_EQ(io::deckDifference(a, "A/x = 1\nA/y = 2\nA/z = 0\n"), "A/z is not in the restart file's deck (0 here)");
  EXPECT_EQ(io::deckDifference(a, "A/x = 1\n"), "A/y (2) is in the restart file's deck, not here");
}

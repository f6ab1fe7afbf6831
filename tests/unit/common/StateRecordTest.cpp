// Named state (common/StateRecord.hpp): what a class declares once comes back as saved; a field that is
// missing, of another type or shape, not finite, or unknown is refused in one line naming it; tables
// gathered from several ranks in any order read back by id.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "common/Error.hpp"
#include "common/StateRecord.hpp"

using contessa::InputError;
using contessa::StateField;
using contessa::StateReader;
using contessa::StateRecord;
using contessa::StateTableReader;
using contessa::StateTableWriter;
using contessa::StateValues;
using contessa::StateWriter;

namespace {

enum class Phase { Open = 0, Stick = 1, Slip = 2 };

// A class with one member of every kind a declaration takes.
struct Sample {
  double lambda = 0;
  double gap = 0;  // may be +inf
  int count = 0;
  bool flag = false;
  Phase phase = Phase::Open;
  std::vector<double> fractions;
  std::array<double, 2> xi{};
  std::array<int, 3> nodes{};
  std::array<std::array<double, 2>, 3> x{};
  std::string label;

  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("lambda", self.lambda);
    field("gap", self.gap, StateValues::AnyDouble);
    field("count", self.count);
    field("flag", self.flag);
    field("phase", self.phase);
    field("fractions", self.fractions);
    field("xi", self.xi);
    field("nodes", self.nodes);
    field("x", self.x);
    field("label", self.label);
  }
  void saveState(StateRecord& r) const {
    StateWriter w(r);
    stateFields(*this, w);
  }
  void loadState(const StateRecord& r) {
    StateReader in(r);
    stateFields(*this, in);
  }
};

Sample filled() {
  Sample s;
  s.lambda = 0.1;
  s.gap = std::numeric_limits<double>::infinity();
  s.count = -7;
  s.flag = true;
  s.phase = Phase::Slip;
  s.fractions = {0.25, 1e-300, -0.0};
  s.xi = {-1.0, 0.5};
  s.nodes = {4, -2, 9};
  s.x = {{{1, 2}, {3, 4}, {5, 6}}};
  s.label = "plate";
  return s;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(StateRecord, DeclaredFieldsComeBackAsSaved) {
  StateRecord r;
  filled().saveState(r.child("sample"));
  EXPECT_EQ(r.child("sample").fields().at("x").shape, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(r.child("sample").fields().at("phase").type, StateField::Type::Int64);
  Sample back;
  back.loadState(r.child("sample"));
  EXPECT_EQ(r.firstUnread(), "");
  EXPECT_EQ(back.lambda, 0.1);
  EXPECT_TRUE(std::isinf(back.gap));
  EXPECT_EQ(back.count, -7);
  EXPECT_TRUE(back.flag);
  EXPECT_EQ(back.phase, Phase::Slip);
  EXPECT_EQ(back.fractions, filled().fractions);
  EXPECT_TRUE(std::signbit(back.fractions[2]));
  EXPECT_EQ(back.xi, filled().xi);
  EXPECT_EQ(back.nodes, filled().nodes);
  EXPECT_EQ(back.x, filled().x);
  EXPECT_EQ(back.label, "plate");
}

TEST(StateRecord, AFieldThatDoesNotFitIsNamedInOneLine) {
  StateRecord file;
  filled().saveState(file.child("sample"));
  file.setOrigin("--restart out/tube.restart");
  const auto load = [](const StateRecord& r) { return errorOf([&r] { Sample().loadState(r.child("sample")); }); };

  StateRecord withoutCount;
  for (const auto& [name, f] : file.child("sample").fields())
    if (name != "count") withoutCount.putField(name, f);
  withoutCount.setOrigin("--restart out/tube.restart");
  EXPECT_EQ(errorOf([&] { Sample().loadState(withoutCount); }),
            "--restart out/tube.restart: count: missing (this Contessa needs it)");

  StateRecord reshaped = file;
  reshaped.child("sample").put("xi", std::vector<double>{1, 2, 3}, {3});
  EXPECT_EQ(load(reshaped), "--restart out/tube.restart: sample/xi: double [3] in the file, double [2] expected");
  StateRecord retyped = file;
  retyped.child("sample").put("count", std::vector<double>{3}, {});
  EXPECT_EQ(load(retyped), "--restart out/tube.restart: sample/count: double [] in the file, int64 [] expected");

  StateRecord notFinite = file;
  notFinite.child("sample").put("xi", std::vector<double>{0.5, std::nan("")}, {2});
  EXPECT_EQ(load(notFinite), "--restart out/tube.restart: sample/xi: value 1 is nan, a finite number expected");
  StateRecord infinite = file;
  infinite.child("sample").put("lambda", std::vector<double>{-std::numeric_limits<double>::infinity()}, {});
  EXPECT_EQ(load(infinite), "--restart out/tube.restart: sample/lambda: is -inf, a finite number expected");
  StateRecord gapNaN = file;  // declared AnyDouble: taken as it is
  gapNaN.child("sample").put("gap", std::vector<double>{std::nan("")}, {});
  EXPECT_EQ(load(gapNaN), "");

  StateRecord unknown = file;
  unknown.child("sample").put("spin", std::vector<double>{1}, {});
  EXPECT_EQ(load(unknown), "");
  EXPECT_EQ(unknown.firstUnread(), "sample/spin");
  EXPECT_EQ(errorOf([&] { unknown.requireAllRead(); }),
            "--restart out/tube.restart: sample/spin: unknown field (this Contessa does not read it: written by "
            "another version?)");
  StateRecord unknownGroup = file;
  unknownGroup.child("later").child("deeper").put("n", std::vector<std::int64_t>{1}, {});
  EXPECT_EQ(load(unknownGroup), "");
  EXPECT_EQ(unknownGroup.firstUnread(), "later/deeper/n");
  // A claimed child is its owner's to check.
  unknownGroup.claim("later");
  EXPECT_EQ(unknownGroup.firstUnread(), "");
  EXPECT_EQ(load(file), "");
}

// Two ranks' rows, interleaved ids: merged, sorted, read back by id, with the row named in errors.
TEST(StateRecord, TablesMergeFromRanksAndReadById) {
  const auto piece = [](std::vector<std::int64_t> ids) {
    StateRecord r;
    StateTableWriter rows(r.child("nodes"));
    for (const auto id : ids) {
      rows.beginRow(id);
      rows("displacement", std::vector<double>{0.5 * static_cast<double>(id), -1.0 * static_cast<double>(id)});
      rows("owner", static_cast<int>(ids[0] % 2));
    }
    rows.finish();
    return r;
  };
  StateRecord all = piece({1, 3, 4});
  all.merge(piece({0, 2}));
  all.merge(StateRecord());  // a rank with nothing
  all.sortTables();
  const StateRecord& nodes = all.child("nodes");
  ASSERT_TRUE(nodes.isTable());
  EXPECT_EQ(nodes.rows(), 5u);
  EXPECT_EQ(nodes.fields().at("id").integers, (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(nodes.fields().at("displacement").shape, (std::vector<std::size_t>{5, 2}));
  StateTableReader rows(nodes);
  std::vector<double> u;
  int owner = -1;
  rows.seek(3, "node 4");
  rows("displacement", u);
  rows("owner", owner);
  EXPECT_EQ(u, (std::vector<double>{1.5, -3.0}));
  EXPECT_EQ(owner, 1);
  rows.seek(2, "node 3");
  rows("owner", owner);
  EXPECT_EQ(owner, 0);
  EXPECT_EQ(all.firstUnread(), "");
  all.setOrigin("f.restart");
  StateTableReader again(all.child("nodes"));
  EXPECT_EQ(errorOf([&] { again.seek(7, "node 8"); }), "f.restart: nodes/id: no row for node 8");

  StateRecord bad = all;
  auto& column = const_cast<StateField&>(bad.child("nodes").fields().at("displacement"));
  column.doubles[3 * 2 + 1] = std::numeric_limits<double>::infinity();
  StateTableReader badRows(bad.child("nodes"));
  badRows.seek(3, "node 4");
  EXPECT_EQ(errorOf([&] { badRows("displacement", u); }),
            "f.restart: nodes/id 3/displacement: value 1 is inf, a finite number expected");
}

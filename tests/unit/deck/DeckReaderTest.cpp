// Reading decks: malformed XML, the shape of a ParameterList, duplicated names, value texts (finite
// numbers, arrays) and --set overrides give one line naming the file, the line and the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include "common/Error.hpp"
#include "common/ErrorText.hpp"
#include "deck/DeckReader.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/ValueText.hpp"

namespace {

using contessa::InputError;
using contessa::deck::parseDeck;
using Teuchos::ParameterList;

// A deck whose lines are numbered 1.. in the order written here.
const std::string kGood =
    "<ParameterList name=\"Contessa\">\n"                                        // 1
    "  <ParameterList name=\"Problem\">\n"                                       // 2
    "    <ParameterList name=\"Mesh\">\n"                                        // 3
    "      <Parameter name=\"Type\" type=\"string\" value=\"Rectangle\"/>\n"     // 4
    "      <Parameter name=\"Length X\" type=\"double\" value=\"2.0\"/>\n"       // 5
    "      <Parameter name=\"Elements X\" type=\"int\" value=\"4\"/>\n"          // 6
    "    </ParameterList>\n"                                                     // 7
    "    <ParameterList name=\"Output\">\n"                                      // 8
    "      <Parameter name=\"Reaction Node Sets\" type=\"Array(string)\" value=\"{right, left}\"/>\n"  // 9
    "    </ParameterList>\n"                                                     // 10
    "  </ParameterList>\n"                                                       // 11
    "</ParameterList>\n";                                                        // 12

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// parseDeck must refuse `text` with one line that contains `expected`.
void expectDeckError(const std::string& text, const std::string& expected) {
  try {
    parseDeck(text, "deck.xml");
    FAIL() << "no error; expected: " << expected;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(expected), std::string::npos) << "message: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
    EXPECT_EQ(msg.find("Throw"), std::string::npos) << "Teuchos throw text: " << msg;
  }
}

TEST(DeckReader, GoodDeckReadsWithTypes) {
  const auto deck = parseDeck(kGood, "deck.xml");
  EXPECT_EQ(deck->name(), "Contessa");
  const auto& mesh = deck->sublist("Problem").sublist("Mesh");
  EXPECT_EQ(mesh.get<std::string>("Type"), "Rectangle");
  EXPECT_DOUBLE_EQ(mesh.get<double>("Length X"), 2.0);
  EXPECT_EQ(mesh.get<int>("Elements X"), 4);
  const auto& sets = deck->sublist("Problem").sublist("Output").get<Teuchos::Array<std::string>>("Reaction Node Sets");
  ASSERT_EQ(sets.size(), 2);
  EXPECT_EQ(sets[0], "right");
  EXPECT_EQ(sets[1], "left");
}

TEST(DeckReader, ByteOrderMarkCrLfCommentsDeclarationAndEntities) {
  std::string text = "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"UTF-8\"?>\r\n<!-- a comment -- with dashes -->\r\n" + kGood;
  text = replaced(text, "value=\"Rectangle\"", "value=\"Rect&#97;ngle\"");
  text = replaced(text, "\"Length X\"", "'Length X'");
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const auto deck = parseDeck(crlf, "deck.xml");
  EXPECT_EQ(deck->sublist("Problem").sublist("Mesh").get<std::string>("Type"), "Rectangle");
  EXPECT_DOUBLE_EQ(deck->sublist("Problem").sublist("Mesh").get<double>("Length X"), 2.0);
  // The five predefined entities, in an attribute.
  const auto amp = parseDeck(replaced(kGood, "value=\"Rectangle\"", "value=\"a &amp; &lt;b&gt; &quot;c&quot; &apos;d&apos;\""), "d");
  EXPECT_EQ(amp->sublist("Problem").sublist("Mesh").get<std::string>("Type"), "a & <b> \"c\" 'd'");
}

TEST(DeckReader, MalformedXmlNamesTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "deck.xml: the deck is empty"},
      {"  \n\n <!-- only a comment -->\n", "deck.xml: the deck is empty"},
      {kGood.substr(0, kGood.find("</ParameterList>")),  // truncated after line 6
       "deck.xml:3: unclosed element <ParameterList name=\"Mesh\"> (the file ends at line 7"},
      {kGood.substr(0, kGood.find("value=\"4\"") + 8), "deck.xml:6: <Parameter name=\"Elements X\">: the value of 'value' is not closed: the file ends first"},
      {kGood.substr(0, kGood.find("type=\"int\"")), "deck.xml:6: the file ends inside the tag <Parameter name=\"Elements X\">"},
      {replaced(kGood, "value=\"2.0\"/>", "value=\"2.0\">"),
       "deck.xml:5: unclosed element <Parameter name=\"Length X\"> (line 7 has </ParameterList> first; a Parameter ends with '/>')"},
      {replaced(kGood, "    </ParameterList>\n    <ParameterList name=\"Output\">", "    </Parameterlist>\n    <ParameterList name=\"Output\">"),
       "deck.xml:3: unclosed element <ParameterList name=\"Mesh\"> (line 7 has </Parameterlist> first)"},
      {replaced(kGood, "value=\"4\"/>\n", "value=\"4\"/>\n    </ParameterList>\n"),
       "deck.xml:13: '</ParameterList>' closes nothing: the root element <ParameterList name=\"Contessa\"> from line 1 "
       "already ended at line 12 (an extra </ParameterList>?; line 8 closes <ParameterList name=\"Problem\"> (line 2) at another indentation)"},
      {kGood + "<ParameterList name=\"Piro\"/>\n", "deck.xml:13: a second top-level element '<ParameterList name=\"Piro\"/>'"},
      {kGood + "</ParameterList>\n", "deck.xml:13: '</ParameterList>' closes nothing"},
      {kGood + "trailing words\n", "deck.xml:13: text after the end of the root element"},
      {"# a shell script\n" + kGood, "deck.xml:1: not an XML deck: it must start with <ParameterList>"},
      {replaced(kGood, "value=\"2.0\"", "value=\xE2\x80\x9C" "2.0\xE2\x80\x9D"),
       "deck.xml:5: <Parameter name=\"Length X\">: the value of 'value' is in typographic quotes"},
      {replaced(kGood, "value=\"2.0\"", "value=2.0"), "deck.xml:5: <Parameter name=\"Length X\">: the value of 'value' must be in quotes"},
      {replaced(kGood, "value=\"Rectangle\"", "value=\"A & B\""), "deck.xml:4: a bare '&' (write & as &amp;)"},
      {replaced(kGood, "value=\"Rectangle\"", "value=\"&nbsp;\""), "deck.xml:4: unknown entity '&nbsp;'"},
      {replaced(kGood, "value=\"Rectangle\"", "value=\"a<b\""), "deck.xml:4: '<' in <Parameter name=\"Type\">: the value of 'value'"},
      {replaced(kGood, "type=\"double\" value", "type=\"double\" type=\"int\" value"), "deck.xml:5: attribute 'type' given twice"},
      {replaced(kGood, "name=\"Length X\" type", "name=\"Length X\"type"), "deck.xml:5: unexpected 't' in the tag"},
      {kGood + "<!-- unclosed", "deck.xml:13: comment '<!--' is not closed"},
      {"<!DOCTYPE deck>\n" + kGood, "deck.xml:1: '<!DOCTYPE deck>': DOCTYPE and other declarations are not supported"},
      {std::string("\xFF\xFE<\0P", 4), "deck.xml: the deck is UTF-16 text; save it as UTF-8"},
      {std::string("CDF\x02\0\0", 6), "deck.xml: not an XML deck (it holds binary data"},
  };
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(expected);
    expectDeckError(text, expected);
  }
}

TEST(DeckReader, ShapeOfAParameterList) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<Deck name=\"x\"/>", "deck.xml:1: the root element must be <ParameterList>, not <Deck>"},
      {replaced(kGood, "<Parameter name=\"Type\"", "<Paramter name=\"Type\""),
       "deck.xml:4: unknown element <Paramter> in Problem/Mesh (a ParameterList holds <Parameter> and <ParameterList>"},
      {replaced(kGood, "<Parameter name=\"Type\"", "<Parameter nmae=\"Type\""), "deck.xml:4: unknown attribute 'nmae' in <Parameter>"},
      {replaced(kGood, "value=\"2.0\"", "value=\"2.0\" unit=\"mm\""),
       "deck.xml:5: unknown attribute 'unit' in <Parameter name=\"Length X\"> (expected name, type, value)"},
      {replaced(kGood, "<ParameterList name=\"Mesh\">", "<ParameterList>"), "deck.xml:3: <ParameterList> without a name in Problem"},
      {replaced(kGood, " name=\"Type\"", ""), "deck.xml:4: <Parameter> without a name in Problem/Mesh"},
      {replaced(kGood, " type=\"double\"", ""), "deck.xml:5: Problem/Mesh/Length X: <Parameter> without a type"},
      {replaced(kGood, " value=\"2.0\"", ""), "deck.xml:5: Problem/Mesh/Length X: <Parameter> without a value"},
      {replaced(kGood, "type=\"double\"", "type=\"float\""),
       "deck.xml:5: Problem/Mesh/Length X: unknown type 'float' (expected one of: string, double, int, bool, Array(string), Array(double), Array(int))"},
      {replaced(kGood, "type=\"double\"", "type=\"Double\""), "Problem/Mesh/Length X: unknown type 'Double'"},
      {replaced(kGood, "value=\"2.0\"/>", "value=\"2.0\">3.0</Parameter>"),
       "deck.xml:5: Problem/Mesh/Length X: a Parameter holds no text or elements"},
      {replaced(kGood, "<ParameterList name=\"Mesh\">", "<ParameterList name=\"Mesh\">\n      stray words"),
       "deck.xml:4: text inside <ParameterList name=\"Mesh\">"},
  };
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(expected);
    expectDeckError(text, expected);
  }
}

TEST(DeckReader, DuplicatedNamesAreRefused) {
  // The same value twice, another value, a sublist twice, a parameter and a sublist of one name.
  const std::string line5 = "      <Parameter name=\"Length X\" type=\"double\" value=\"2.0\"/>\n";
  expectDeckError(replaced(kGood, line5, line5 + line5),
                  "deck.xml:6: Problem/Mesh/Length X: given twice in one list (lines 5 and 6); keep one");
  expectDeckError(replaced(kGood, line5, line5 + "      <Parameter name=\"Length X\" type=\"double\" value=\"3.0\"/>\n"),
                  "deck.xml:6: Problem/Mesh/Length X: given twice in one list (lines 5 and 6)");
  expectDeckError(replaced(kGood, "  </ParameterList>\n</ParameterList>",
                           "    <ParameterList name=\"Mesh\">\n    </ParameterList>\n  </ParameterList>\n</ParameterList>"),
                  "deck.xml:11: Problem/Mesh: given twice in one list (lines 3 and 11)");
  expectDeckError(replaced(kGood, line5, line5 + "      <ParameterList name=\"Length X\"/>\n"),
                  "deck.xml:6: Problem/Mesh/Length X: given twice in one list (lines 5 and 6)");
  // The same name in different lists is fine.
  EXPECT_NO_THROW(parseDeck(replaced(kGood, "<ParameterList name=\"Output\">\n",
                                     "<ParameterList name=\"Output\">\n      <Parameter name=\"Type\" type=\"string\" value=\"x\"/>\n"),
                            "deck.xml"));
}

TEST(DeckReader, ValuesMustReadAsTheirTypeAndBeFinite) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"inf", "deck.xml:5: Problem/Mesh/Length X: 'inf' is not a finite number"},
      {"-Infinity", "'-Infinity' is not a finite number"},
      {"nan", "'nan' is not a finite number"},
      {"NAN(0x1)", "'NAN(0x1)' is not a finite number"},
      {"1e999", "'1e999' is not a finite number (too large for a double)"},
      {"-1e400", "'-1e400' is not a finite number (too large for a double)"},
      {"0x10", "'0x10' is not a valid double"},
      {"1e-2x", "'1e-2x' is not a valid double"},
      {"1,5", "'1,5' is not a valid double"},
      {"", "'' is not a valid double"},
  };
  for (const auto& [value, expected] : cases) {
    SCOPED_TRACE(value);
    expectDeckError(replaced(kGood, "value=\"2.0\"", "value=\"" + value + "\""), expected);
  }
  expectDeckError(replaced(kGood, "value=\"4\"", "value=\"4.5\""), "deck.xml:6: Problem/Mesh/Elements X: '4.5' is not a valid int");
  expectDeckError(replaced(kGood, "value=\"4\"", "value=\"3000000000\""), "'3000000000' is out of the range of an int");
  expectDeckError(replaced(kGood, "type=\"double\" value=\"2.0\"", "type=\"bool\" value=\"yes\""),
                  "'yes' is not a valid bool (expected true or false)");
  // Arrays: braces, elements of the right type, no empty element.
  const auto array = [&](const std::string& type, const std::string& value) {
    return replaced(kGood, "type=\"Array(string)\" value=\"{right, left}\"", "type=\"" + type + "\" value=\"" + value + "\"");
  };
  expectDeckError(array("Array(double)", "{0.0, inf}"),
                  "deck.xml:9: Problem/Output/Reaction Node Sets: element 2 of {0.0, inf}: 'inf' is not a finite number");
  expectDeckError(array("Array(double)", "{0.0, abc}"), "element 2 of {0.0, abc}: 'abc' is not a valid double");
  expectDeckError(array("Array(double)", "{0.0, }"), "element 2 of {0.0,}: empty (a stray comma?)");
  expectDeckError(array("Array(double)", "0.0, 1.0"), "expected an array {a, b, ...}, got '0.0, 1.0'");
  expectDeckError(array("Array(int)", "{1, 2.5}"), "element 2 of {1, 2.5}: '2.5' is not a valid int");
  const auto empty = parseDeck(array("Array(double)", "{ }"), "deck.xml");
  EXPECT_TRUE(empty->sublist("Problem").sublist("Output").get<Teuchos::Array<double>>("Reaction Node Sets").empty());
  const auto tiny = parseDeck(replaced(kGood, "value=\"2.0\"", "value=\"1e-400\""), "deck.xml");  // underflow reads as 0
  EXPECT_EQ(tiny->sublist("Problem").sublist("Mesh").get<double>("Length X"), 0.0);
}

TEST(DeckOverridesText, ArraysAndNonFiniteNumbers) {
  auto deck = parseDeck(kGood, "deck.xml");
  deck->sublist("Problem").sublist("Contact").sublist("plate").sublist("Rigid Surface")
      .set("Motion", Teuchos::Array<double>(2, 0.0));
  contessa::deck::applyOverrides(*deck, {"Problem/Contact/plate/Rigid Surface/Motion={0.0, -75.2}"});
  const auto& motion = deck->sublist("Problem").sublist("Contact").sublist("plate").sublist("Rigid Surface")
                           .get<Teuchos::Array<double>>("Motion");
  ASSERT_EQ(motion.size(), 2);
  EXPECT_DOUBLE_EQ(motion[1], -75.2);
  contessa::deck::applyOverrides(*deck, {"Problem/Contact/plate/Rigid Surface/Motion=1.5,2", "Problem/Output/Reaction Node Sets={top}"});
  EXPECT_DOUBLE_EQ(deck->sublist("Problem").sublist("Contact").sublist("plate").sublist("Rigid Surface")
                       .get<Teuchos::Array<double>>("Motion")[0], 1.5);
  EXPECT_EQ(deck->sublist("Problem").sublist("Output").get<Teuchos::Array<std::string>>("Reaction Node Sets").size(), 1);

  const auto expectSetError = [&](const std::string& item, const std::string& expected) {
    try {
      contessa::deck::applyOverrides(*deck, {item});
      FAIL() << "no error for " << item;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  expectSetError("Problem/Contact/plate/Rigid Surface/Motion={0.0, nan}",
                 "--set Problem/Contact/plate/Rigid Surface/Motion={0.0, nan}: element 2 of {0.0, nan}: 'nan' is not a finite number");
  expectSetError("Problem/Contact/plate/Rigid Surface/Motion={0.0; -75.2}", "element 1 of {0.0; -75.2}: '0.0; -75.2' is not a valid double");
  expectSetError("Problem/Mesh/Length X=inf", "--set Problem/Mesh/Length X=inf: 'inf' is not a finite number");
  expectSetError("Problem/Mesh/Length X=1e999", "'1e999' is not a finite number (too large for a double)");
  expectSetError("Problem/Mesh/Elements X=1e3", "'1e3' is not a valid int");
}

TEST(DeckOverridesText, NewValuesAreTypedByValidationWithTheSameRules) {
  // A --set value that is not in the deck is text until validation types it: the same reader applies.
  Teuchos::ParameterList valid("valid");
  valid.set("Value", 0.0);
  valid.set("Motion", Teuchos::Array<double>());
  const auto expectError = [&](const std::string& item, const std::string& expected) {
    Teuchos::ParameterList deck("deck");
    contessa::deck::applyOverrides(deck, {item});
    try {
      contessa::deck::validateAndSetDefaults(deck, valid, "P");
      FAIL() << "no error for " << item;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  expectError("Value=inf", "P/Value: 'inf' is not a finite number");
  expectError("Value=abc", "P/Value: expected type double, got string 'abc'");
  expectError("Motion={1, -inf}", "P/Motion: element 2 of {1, -inf}: '-inf' is not a finite number");
  Teuchos::ParameterList deck("deck");
  contessa::deck::applyOverrides(deck, {"Motion=0.0, -75.2"});
  contessa::deck::validateAndSetDefaults(deck, valid, "P");
  EXPECT_DOUBLE_EQ(deck.get<Teuchos::Array<double>>("Motion")[1], -75.2);
  // Values that entered the list by program, not text, are checked too.
  Teuchos::ParameterList direct("deck");
  direct.set("Value", std::nan(""));
  EXPECT_THROW(contessa::deck::validateAndSetDefaults(direct, valid, "P"), InputError);
  direct.set("Value", 1.0);
  direct.set("Motion", Teuchos::Array<double>(1, HUGE_VAL));
  EXPECT_THROW(contessa::deck::validateAndSetDefaults(direct, valid, "P"), InputError);
}

TEST(DeckFile, ReadOnceFromAPipeAndRefuseADirectory) {
  const auto dir = std::filesystem::temp_directory_path() / ("contessa_deck_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  try {
    contessa::deck::readDeck(dir.string());
    FAIL() << "a directory was read as a deck";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(": is a directory, not a deck file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(contessa::deck::readDeck((dir / "missing.xml").string()), InputError);
  // A named pipe can be read once: the deck must not be opened twice (it would wait for a second writer).
  const auto fifo = dir / "deck.xml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << kGood; });
  const auto deck = contessa::deck::readDeck(fifo.string());
  writer.join();
  EXPECT_EQ(deck->sublist("Problem").sublist("Mesh").get<int>("Elements X"), 4);
  std::filesystem::remove_all(dir);
}

TEST(ErrorText, TeuchosThrowTextIsRemoved) {
  const std::string teuchos =
      "/build/trilinos/packages/teuchos/parameterlist/src/Teuchos_XMLParser.cpp:397:\n\nThrow number = 1\n\n"
      "Throw test that evaluated to true: curopen != 0\n\nXML parse error at line 15: file ended\nbefore closing";
  EXPECT_EQ(contessa::plainMessage(teuchos), "XML parse error at line 15: file ended before closing");
  EXPECT_EQ(contessa::plainMessage(std::string("plain\ntext")), "plain text");
  EXPECT_EQ(contessa::plainMessage(std::string(500, 'a')).size(), 303u);
}

}  // namespace

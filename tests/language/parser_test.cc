// The parser alone: sentence kinds, tokenizing, the errors it reports, and
// properties over generated sentences (rapidcheck).
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "language/parser.h"

namespace apprentice::language {
namespace {

std::string form_of(std::string_view sentence) {
  auto form = parse(sentence);
  return form ? format_logical_form(*form) : "error: " + form.error().message;
}

TEST(Tokenize, LowerCasesStripsFinalPunctuationAndSplitsCommas) {
  EXPECT_EQ(tokenize("  Put X, then Y.  "), (std::vector<std::string>{"put", "x", ",", "then", "y"}));
  EXPECT_EQ(tokenize("'Pick up ceramic-plate'"), (std::vector<std::string>{"pick", "up", "ceramic-plate"}));
  EXPECT_EQ(tokenize("Yes!?"), (std::vector<std::string>{"yes"}));
  EXPECT_TRUE(tokenize(" . ").empty());
}

TEST(Parse, TaskStructure) {
  EXPECT_EQ(form_of("Tidy kitchen."), "(task \"tidy kitchen\")");
  EXPECT_EQ(form_of("Repeat the following tasks while an object is on the table."),
            "(repeat-while (on \"table\"))");
  EXPECT_EQ(form_of("Repeat the following tasks while an object is in the dish rack."),
            "(repeat-while (in \"dish rack\"))");
  EXPECT_EQ(form_of("Clear an object that is on the table."), "(subtask \"clear\" (on \"table\"))");
  EXPECT_EQ(form_of("You are done."), "(done)");
  EXPECT_EQ(form_of("Repeat."), "(repeat)");
}

TEST(Parse, AnswersInAnyCaseWithOrWithoutAPeriod) {
  for (std::string_view yes : {"yes", "Yes.", "YES", "yes!"}) EXPECT_EQ(form_of(yes), "(answer yes)") << yes;
  for (std::string_view no : {"no", "No.", "NO", "no."}) EXPECT_EQ(form_of(no), "(answer no)") << no;
}

TEST(Parse, GoalDescriptionsWithAAnOrNoArticle) {
  EXPECT_EQ(form_of("If the object is a ceramic-plate then the goal is that the object is in the dishwasher and "
                    "the dishwasher is closed."),
            "(goal (category \"ceramic-plate\") (in \"object\" \"dishwasher\") (closed \"dishwasher\"))");
  EXPECT_EQ(form_of("If the object is an apple-core then the goal is that the object is in the garbage."),
            "(goal (category \"apple-core\") (in \"object\" \"garbage\"))");
  EXPECT_EQ(form_of("If the object is apple-cider then the goal is that the object is on the counter and the "
                    "fridge is open."),
            "(goal (category \"apple-cider\") (on \"object\" \"counter\") (open \"fridge\"))");
}

TEST(Parse, ActionCommands) {
  EXPECT_EQ(form_of("Open the fridge."), "(action open \"fridge\")");
  EXPECT_EQ(form_of("Close the fridge."), "(action close \"fridge\")");
  EXPECT_EQ(form_of("Pick up the ketchup."), "(action pick-up \"ketchup\")");
  EXPECT_EQ(form_of("Put the ketchup in the fridge."), "(action put \"ketchup\" (in \"fridge\"))");
  EXPECT_EQ(form_of("Pick up ceramic-plate from table"), "(action pick-up \"ceramic-plate\" (from \"table\"))");
  EXPECT_EQ(form_of("Put plastic bottle in recycling bin"), "(action put \"plastic bottle\" (in \"recycling bin\"))");
  EXPECT_EQ(form_of("Put the mug onto the counter"), "(action put \"mug\" (on \"counter\"))");
  EXPECT_EQ(form_of("put down the cup into the sink"), "(action put \"cup\" (in \"sink\"))");
  EXPECT_EQ(form_of("put-down ceramic-plate in dishwasher"), "(action put \"ceramic-plate\" (in \"dishwasher\"))");
  EXPECT_EQ(form_of("pick-up ceramic-plate"), "(action pick-up \"ceramic-plate\")");
}

TEST(Parse, TheLanguageModelsGoalStatements) {
  EXPECT_EQ(form_of("the goal is that the plastic-bottle is in the recycling bin and the recycling bin is closed"),
            "(goal (in \"plastic-bottle\" \"recycling bin\") (closed \"recycling bin\"))");
  EXPECT_EQ(form_of("the goal is that the crackers are in the pantry"), "(goal (in \"crackers\" \"pantry\"))");
  EXPECT_EQ(form_of("The goal is that the milk is in the fridge, and the fridge is closed."),
            "(goal (in \"milk\" \"fridge\") (closed \"fridge\"))");
  EXPECT_EQ(form_of("the goal is that milk is in fridge and fridge is closed"),
            "(goal (in \"milk\" \"fridge\") (closed \"fridge\"))");
}

TEST(Parse, UnknownPredicatesKeepTheirWords) {
  EXPECT_EQ(form_of("the goal is that the plate is in the dishwasher and the dishwasher is turned on"),
            "(goal (in \"plate\" \"dishwasher\") (is \"dishwasher\" \"turned on\"))");
  EXPECT_EQ(form_of("the goal is that the plate is in the sink and the sink is full of water"),
            "(goal (in \"plate\" \"sink\") (is \"sink\" \"full of water\"))");
  EXPECT_EQ(form_of("the goal is that the dishwasher is on"), "(goal (is \"dishwasher\" \"on\"))");
  // A piece without a verb belongs to its neighbour.
  EXPECT_EQ(form_of("the goal is that the dishwasher is closed and started"),
            "(goal (is \"dishwasher\" \"closed and started\"))");
  EXPECT_EQ(form_of("the goal is that the half and half is in the fridge"),
            "(goal (in \"half and half\" \"fridge\"))");
}

TEST(Parse, ErrorsSayWhatWasExpected) {
  EXPECT_EQ(form_of("the goal is for the plate to be in the sink"), "error: expected 'that' after 'the goal is'");
  EXPECT_EQ(form_of("Pick the ketchup"), "error: expected 'up' after 'pick'");
  EXPECT_EQ(form_of("Put the ketchup"), "error: expected 'in' or 'on' and a place after 'put'");
  EXPECT_EQ(form_of("the goal is that the"), "error: expected 'is' or 'are' after 'the goal is that'");
  EXPECT_EQ(form_of(""), "error: expected a sentence, got nothing");
  EXPECT_EQ(form_of("If the object is a mug the goal is that"), "error: expected 'then' after 'if the object is ...'");
  EXPECT_NE(form_of("the goal is that all the dishes are in the sink").find("error: expected a noun phrase"),
            std::string::npos);
  EXPECT_EQ(form_of(std::string(3000, 'a')), "error: sentence longer than 2000 bytes");
}

// Sentences built from the grammar parse back to what was built.
RC_GTEST_PROP(ParseProperty, GeneratedGoalStatementsRoundTrip, ()) {
  const std::vector<std::string> nouns = {"ketchup", "plastic-bottle", "recycling bin", "fridge", "dish rack",
                                          "box-of-aluminum-foil", "trash can"};
  const std::vector<std::string> articles = {"", "the "};
  std::size_t n = *rc::gen::inRange<std::size_t>(1, 5);
  std::string sentence = "the goal is that ";
  std::string expected = "(goal";
  for (std::size_t i = 0; i < n; ++i) {
    std::string thing = *rc::gen::elementOf(nouns);
    std::string place = *rc::gen::elementOf(nouns);
    std::string article = *rc::gen::elementOf(articles);
    if (i > 0) sentence += *rc::gen::element<std::string>(" and ", ", ", ", and ");
    if (*rc::gen::arbitrary<bool>()) {
      sentence += article + thing + " is in " + article + place;
      expected += " (in \"" + thing + "\" \"" + place + "\")";
    } else {
      sentence += article + place + " is closed";
      expected += " (closed \"" + place + "\")";
    }
  }
  expected += ")";
  auto form = parse(sentence);
  RC_ASSERT(form.has_value());
  RC_ASSERT(format_logical_form(*form) == expected);
}

// Whatever the words, parse returns (a form or an error) and never crashes;
// the libFuzzer target (fuzz/) tries raw bytes.
RC_GTEST_PROP(ParseProperty, AnyWordsParseOrFailCleanly, ()) {
  const std::vector<std::string> vocabulary = {"the", "a", "goal", "is", "that", "and", ",", "in", "on", "if",
                                               "then", "object", "put", "pick", "up", "from", "open", "close",
                                               "closed", "repeat", "yes", "are", "fridge", "bin", "there", "."};
  auto words = *rc::gen::container<std::vector<std::string>>(rc::gen::elementOf(vocabulary));
  std::string sentence;
  for (const std::string& w : words) sentence += w + " ";
  auto form = parse(sentence);
  if (form) RC_ASSERT(!format_logical_form(*form).empty());
  else RC_ASSERT(!form.error().message.empty());
}

}  // namespace
}  // namespace apprentice::language

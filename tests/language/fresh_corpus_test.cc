// The fresh reply corpora (tests/language/fresh/set1 to set8): every labelled
// reply read with read_reply in the context its line describes, and scored
// against its meaning (fresh_corpus.h). The figures are a measurement and
// are printed, not asserted; what is asserted is that the scorer works:
// every line parses and names things of its world, the counts add up, and
// hand-checked lines score as they must.
//
//   build/tests/language/language_tests --gtest_filter='FreshCorpus.*'
//
// With APPRENTICE_FRESH_LINES=FILE each line's outcome, label and reading
// are written to FILE.
#include <cstdlib>
#include <fstream>
#include <iostream>

#include <gtest/gtest.h>

#include "fresh_corpus.h"
#include "language_fixtures.h"
#include "util/text.h"

namespace apprentice::language::fresh {
namespace {

using testing::grounder;
using testing::source_path;

std::string acts_text(const Acts& acts) {
  std::vector<std::string> parts;
  for (const auto& act : acts) parts.push_back(join(act, " & "));
  return join(parts, " ; ");
}

// Scores a whole set; the lines' count is checked by the caller.
Report score_set(const std::string& set, std::size_t& lines) {
  const std::filesystem::path folder = source_path("tests/language/fresh/" + set);
  Corpus corpus = read_corpus(folder);
  for (const std::string& e : corpus.errors) ADD_FAILURE() << set << ": " << e;
  Worlds worlds(folder);
  Report report;
  std::vector<double> times;
  std::ofstream detail;
  if (const char* path = std::getenv("APPRENTICE_FRESH_LINES")) detail.open(path, std::ios::app);
  for (const Line& line : corpus.lines) {
    std::string error;
    const Scenario* scenario = worlds.get(line.world, error);
    if (scenario == nullptr) {
      ADD_FAILURE() << line.file << ": " << error;
      continue;
    }
    Scored scored = score(grounder(), scenario->world, line);
    EXPECT_EQ(scored.error, "") << line.file << " " << line.id;
    add(report, line, scored.outcome);
    times.push_back(scored.seconds);
    if (detail)
      detail << line.id << "\t" << to_string(scored.outcome) << "\t" << line.asked << "\t" << line.reply << "\t"
             << acts_text(scored.label) << "\t" << (scored.reading.empty() ? scored.reply_line : acts_text(scored.reading))
             << "\n";
  }
  lines = corpus.lines.size();
  // The counts add up: every line once per question and once overall.
  int by_asked = 0;
  for (const auto& [asked, tally] : report.by_asked) by_asked += tally.total();
  EXPECT_EQ(by_asked, report.overall.total());
  EXPECT_EQ(static_cast<std::size_t>(report.overall.total()), corpus.lines.size());
  for (const auto& [act, tally] : report.by_act) EXPECT_LE(tally.total(), report.overall.total()) << act;
  std::cout << "Fresh corpus " << set << " (" << corpus.lines.size() << " replies):\n" << format_report(report);
  // How long reading a reply took (a measurement, not a limit; this build,
  // this machine's load).
  if (!times.empty()) {
    std::sort(times.begin(), times.end());
    std::cout << "read_acts per reply: median " << times[times.size() / 2] * 1000 << " ms, 95th percentile "
              << times[times.size() * 95 / 100] * 1000 << " ms\n";
  }
  return report;
}

TEST(FreshCorpus, Set1IsReadAndScored) {
  std::size_t lines = 0;
  Report report = score_set("set1", lines);
  EXPECT_EQ(lines, 741u);
  // Every act kind of FORMAT.md that set 1 uses is counted.
  for (const char* act : {"goal", "task", "subtask", "undo", "correction", "question", "command", "leave", "help"})
    EXPECT_GT(report.by_act[act].total(), 0) << act;
}

TEST(FreshCorpus, Set2IsReadAndScored) {
  if (!std::filesystem::exists(source_path("tests/language/fresh/set2"))) GTEST_SKIP() << "no set 2 yet";
  std::size_t lines = 0;
  score_set("set2", lines);
  EXPECT_GE(lines, 400u);
}

TEST(FreshCorpus, Set3IsReadAndScored) {
  std::size_t lines = 0;
  Report report = score_set("set3", lines);
  EXPECT_EQ(lines, 187u);
  for (const char* act : {"goal", "task", "subtask", "undo", "question", "command", "leave", "yes", "no"})
    EXPECT_GT(report.by_act[act].total(), 0) << act;
}

// Sets 4-6: the set has `expected_lines` replies, and each act a teacher
// uses in them, choosing included, is scored at least once.
void expect_read_with_every_act(const std::string& set, std::size_t expected_lines) {
  std::size_t lines = 0;
  Report report = score_set(set, lines);
  EXPECT_EQ(lines, expected_lines);
  for (const char* act : {"goal", "task", "subtask", "undo", "question", "command", "leave", "yes", "no", "choose"})
    EXPECT_GT(report.by_act[act].total(), 0) << set << ": " << act;
}

TEST(FreshCorpus, Set4IsReadAndScored) {
  expect_read_with_every_act("set4", 341u);
}

// Set 5 is the held-out set of issue 21: scored as it came, never read by
// the engineers who work on the reader.
TEST(FreshCorpus, Set5IsReadAndScored) {
  expect_read_with_every_act("set5", 326u);
}

// Set 6, the second held-out set of issue 21 (written 2026-12-06 before
// that day's reader work, by writers who saw no code): scored as it came.
TEST(FreshCorpus, Set6IsReadAndScored) {
  expect_read_with_every_act("set6", 347u);
}

// Set 7, the third held-out set of issue 21 (written 2026-12-06 23:05
// UTC, before that night's reader work, by writers who saw no code):
// scored as it came.
TEST(FreshCorpus, Set7IsReadAndScored) {
  expect_read_with_every_act("set7", 324u);
}

// Set 8, the fourth held-out set of issue 21 (written 2026-12-07 06:03 UTC by
// writers who saw no code, before that day's reader work): scored as it
// came.
TEST(FreshCorpus, Set8IsReadAndScored) {
  expect_read_with_every_act("set8", 577u);
}

// The scorer itself, on lines written here, in set 1's bathroom.
class FreshScorer : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    scenario_ = worlds_.get("bathroom.yaml", error);
    ASSERT_NE(scenario_, nullptr) << error;
  }
  Scored scored(const std::string& asked, const std::string& about, const std::string& reply,
                const std::string& meaning, const std::string& context = "{}") {
    Line line;
    line.id = "test";
    line.world = "bathroom.yaml";
    line.asked = asked;
    if (!about.empty()) line.about = about;
    line.context = nlohmann::json::parse(context);
    line.reply = reply;
    line.meaning = nlohmann::json::parse(meaning);
    Scored s = score(grounder(), scenario_->world, line);
    EXPECT_EQ(s.error, "") << reply;
    return s;
  }
  Worlds worlds_{source_path("tests/language/fresh/set1")};
  const Scenario* scenario_ = nullptr;
};

TEST_F(FreshScorer, AGoalReadAsLabelledIsMeant) {
  Scored s = scored("goal", "toothbrush", "put it in the cabinet",
                    R"([{"act": "goal", "things": ["toothbrush"], "place": "cabinet", "relation": "in", "closed": null}])",
                    R"({"subtask": {"verb": "store", "place": "counter"}})");
  EXPECT_EQ(s.outcome, Outcome::kMeant) << s.reply_line;
  EXPECT_EQ(s.label, (Acts{{"goal toothbrush in cabinet closed=null"}}));
}

TEST_F(FreshScorer, AGoalToAnotherPlaceIsActedOnWrongly) {
  Scored s = scored("goal", "toothbrush", "put it in the cabinet",
                    R"([{"act": "goal", "things": ["toothbrush"], "place": "hamper", "relation": "in", "closed": null}])");
  EXPECT_EQ(s.outcome, Outcome::kWrong);
  // A door the label closes and the reading does not: wrong too.
  Scored closed = scored("goal", "toothbrush", "put it in the cabinet",
                         R"([{"act": "goal", "things": ["toothbrush"], "place": "cabinet", "relation": "in", "closed": true}])");
  EXPECT_EQ(closed.outcome, Outcome::kWrong);
}

TEST_F(FreshScorer, LookAlikesAreNamedByTheirProperties) {
  Scored s = scored("which", "", "the bottom one", R"([{"act": "choose", "place": "bottom drawer"}])",
                    R"({"choices": ["top drawer", "bottom drawer"]})");
  EXPECT_EQ(s.outcome, Outcome::kMeant) << s.reply_line;
  EXPECT_EQ(s.label, (Acts{{"choose bottom drawer"}}));
  Scored wrong = scored("which", "", "the bottom one", R"([{"act": "choose", "place": "top drawer"}])",
                        R"({"choices": ["top drawer", "bottom drawer"]})");
  EXPECT_EQ(wrong.outcome, Outcome::kWrong);
}

TEST_F(FreshScorer, ARefusalIsASafeMissAndMeetsAnAskBack) {
  Scored refused = scored("goal", "towel", "frobnicate the wibble",
                          R"([{"act": "goal", "things": ["towel"], "place": "hamper", "relation": "in", "closed": null}])");
  EXPECT_EQ(refused.outcome, Outcome::kAskedBack) << refused.reply_line;
  Scored ask_back = scored("goal", "towel", "frobnicate the wibble", R"([{"act": "ask-back", "why": "no sense"}])");
  EXPECT_EQ(ask_back.outcome, Outcome::kMeant);
  // A usable reading where a person would have asked is wrong.
  Scored taken = scored("goal", "towel", "put it in the hamper", R"([{"act": "ask-back", "why": "test"}])");
  EXPECT_EQ(taken.outcome, Outcome::kWrong) << taken.reply_line;
}

TEST_F(FreshScorer, FewerGoalsThanSaidIsASafeMissAndAnotherActIsNot) {
  const std::string two = R"([{"act": "goal", "things": ["towel", "jeans"], "place": "hamper", "relation": "in", "closed": null}])";
  Scored one = scored("goal", "towel", "put it in the hamper", two);
  EXPECT_EQ(one.outcome, Outcome::kAskedBack) << one.reply_line;
  EXPECT_EQ(one.label, (Acts{{"goal jeans in hamper closed=null", "goal towel in hamper closed=null"}}));
  Scored help = scored("goal", "towel", "help", two);
  EXPECT_EQ(help.outcome, Outcome::kWrong);
  Scored undo = scored("goal", "towel", "undo", R"([{"act": "undo"}])");
  EXPECT_EQ(undo.outcome, Outcome::kMeant);
}

TEST_F(FreshScorer, TheRestOfANoIsReadWhereTheProposedThingGoes) {
  const std::string context =
      R"({"proposal": {"thing": "hair-dryer", "place": "cabinet", "relation": "in", "closed": true}})";
  Scored s = scored("yes-no", "", "no, the bottom drawer",
                    R"([{"act": "no"}, {"act": "goal", "things": ["hair-dryer"], "place": "bottom drawer", "relation": "in", "closed": null}])",
                    context);
  EXPECT_EQ(s.outcome, Outcome::kMeant) << s.reply_line;
  EXPECT_EQ(s.reading, (Acts{{"no"}, {"goal hair-dryer in bottom drawer closed=null"}}));
}

TEST_F(FreshScorer, AnEndingCountsByTheQuestion) {
  EXPECT_EQ(scored("task-step", "", "You are done.", R"([{"act": "task-done"}])").outcome, Outcome::kMeant);
  EXPECT_EQ(scored("subtask-end", "", "You are done.", R"([{"act": "part-done"}])").outcome, Outcome::kMeant);
  EXPECT_EQ(scored("subtask-end", "", "You are done.", R"([{"act": "task-done"}])").outcome, Outcome::kWrong);
  // At a proposal about a thing, as at the question where it goes (the
  // agent leaves it as told either way): the part's end when nothing else
  // is to come, else asked back.
  const std::string proposal =
      R"({"proposal": {"thing": "hair-dryer", "place": "cabinet", "relation": "in", "closed": true}, "still_to_come": []})";
  EXPECT_EQ(scored("yes-no", "hair-dryer", "I'm done", R"([{"act": "part-done"}])", proposal).outcome, Outcome::kMeant);
  const std::string more =
      R"({"proposal": {"thing": "hair-dryer", "place": "cabinet", "relation": "in", "closed": true}, "still_to_come": ["razor"]})";
  EXPECT_EQ(scored("yes-no", "hair-dryer", "I'm done", R"([{"act": "part-done"}])", more).outcome, Outcome::kAskedBack);
}

TEST(FreshScorerReport, TheTableAddsUp) {
  Report report;
  Line line;
  line.asked = "goal";
  line.meaning = nlohmann::json::parse(R"([{"act": "undo"}, {"act": "goal"}])");
  add(report, line, Outcome::kMeant);
  add(report, line, Outcome::kWrong);
  EXPECT_EQ(report.overall.total(), 2);
  EXPECT_EQ(report.by_act["correction"].meant, 1);
  EXPECT_EQ(report.by_act["undo"].wrong, 1);
  EXPECT_EQ(report.by_asked["goal"].total(), 2);
  EXPECT_NE(format_report(report).find("| **all lines** | **2** | **1 (50.0%)** | **0** | **1 (50.0%)** |"),
            std::string::npos)
      << format_report(report);
}

}  // namespace
}  // namespace apprentice::language::fresh

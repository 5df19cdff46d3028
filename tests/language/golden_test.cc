// Golden cases: tests/language/golden/*.test hold one case per block, in a
// plain-text format after DuckDB's .test files:
//
//   # optional comment lines
//   sentence: Close the recycling bin.
//   object: plastic-bottle1            (optional: the object of interest)
//   form: (action close "recycling bin")        ("none" if it does not parse)
//   result: failure affordance-mismatch openable recycling-bin1
//
// Blocks are separated by blank lines; every sentence is interpreted in
// data/scenarios/tidy-kitchen-35.yaml. Run with APPRENTICE_UPDATE_GOLDEN=1
// to rewrite the form and result lines from the current code; the header
// (the file's reviewed note, tests/common/golden_note.h), the comments and
// the known-wrong lines are kept. Then read the diff and update the note.
//
// A known wrong reading: a case whose result is not what a person meant,
// but which is not fixed yet, keeps the code's current reading in `result:`
// (so that a change to it is still caught) and says what a person meant in
//   known-wrong: action (pick-up ketchup1 table1)
// The test counts these cases apart and prints them; when the code comes to
// read one as meant, the test fails until the case is promoted (the
// known-wrong value made the result, the mark removed) and the note updated.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/golden_note.h"
#include "language/logical_form.h"
#include "golden_blocks.h"
#include "language_fixtures.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::source_path;
using testing::world35;

struct Case {
  std::size_t line = 0;  // where the block starts
  std::vector<std::string> comments;
  std::string sentence;
  std::string object;
  std::string form;
  std::string result;
  std::string known_wrong;  // what a person meant, when `result` is not it
};

// Reads the blocks; a malformed line fails the test and is skipped.
std::vector<Case> read_cases(const std::filesystem::path& path) {
  std::vector<Case> cases;
  for (const testing::GoldenBlock& block : testing::read_golden_blocks(path)) {
    Case c;
    c.line = block.line;
    c.comments = block.comments;
    for (const auto& [key, value] : block.fields) {
      if (key == "sentence") c.sentence = value;
      else if (key == "object") c.object = value;
      else if (key == "form") c.form = value;
      else if (key == "result") c.result = value;
      else if (key == "known-wrong") c.known_wrong = value;
      else ADD_FAILURE() << path.filename() << ":" << block.line << ": unknown key '" << key << "'";
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

void write_cases(const std::filesystem::path& path, const std::vector<std::string>& header,
                 const std::vector<Case>& cases) {
  std::ofstream out(path);
  for (const std::string& line : header) out << line << "\n";
  if (!header.empty()) out << "\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    for (const std::string& comment : c.comments) out << comment << "\n";
    out << "sentence: " << c.sentence << "\n";
    if (!c.object.empty()) out << "object: " << c.object << "\n";
    out << "form: " << c.form << "\n";
    out << "result: " << c.result << "\n";
    if (!c.known_wrong.empty()) out << "known-wrong: " << c.known_wrong << "\n";
    if (i + 1 < cases.size()) out << "\n";
  }
}

void run_golden_file(const std::filesystem::path& path) {
  std::vector<Case> cases = read_cases(path);
  ASSERT_FALSE(cases.empty()) << path;
  // The first block may be a header of comments only: the reviewed note.
  std::vector<std::string> header;
  if (cases.front().sentence.empty()) {
    header = cases.front().comments;
    cases.erase(cases.begin());
  }
  bool update = apprentice::testing::golden_update_requested();
  std::ostringstream known_wrong;
  int known_wrong_count = 0;
  for (Case& c : cases) {
    SCOPED_TRACE(path.filename().string() + ":" + std::to_string(c.line) + ": " + c.sentence);
    ASSERT_FALSE(c.sentence.empty()) << "a block without a sentence";
    std::optional<ObjectId> object;
    if (!c.object.empty()) {
      object = world35().universe->find(c.object);
      ASSERT_TRUE(object.has_value()) << "no object " << c.object;
    }
    Interpretation in = grounder().interpret(c.sentence, world35(), object);
    std::string form = in.form ? format_logical_form(*in.form) : "none";
    std::string result = format_grounding(world35(), in.result);
    if (!c.known_wrong.empty()) {
      ++known_wrong_count;
      known_wrong << "  " << path.filename().string() << ":" << c.line << " \"" << c.sentence
                  << "\"\n      read now:          " << result << "\n      a person meant:    " << c.known_wrong
                  << "\n";
      EXPECT_NE(result, c.known_wrong) << "now read as a person meant: make `" << c.known_wrong
                                       << "` the result, remove the known-wrong line and update the file's note";
    }
    if (update) {
      c.form = form;
      c.result = result;
      continue;
    }
    EXPECT_EQ(form, c.form);
    EXPECT_EQ(result, c.result);
  }
  std::printf("%s: %zu cases, %d known wrong reading(s) (pinned as read now)\n%s", path.filename().c_str(),
              cases.size(), known_wrong_count, known_wrong.str().c_str());
  if (update) {
    write_cases(path, header, cases);
    std::printf("%s", apprentice::testing::golden_update_reminder(path).c_str());
  }
}

TEST(Golden, Sentences) { run_golden_file(source_path("tests/language/golden/sentences.test")); }

// Every failure kind and every sentence kind appears in the golden file.
TEST(Golden, CoversEveryKind) {
  std::vector<Case> cases = read_cases(source_path("tests/language/golden/sentences.test"));
  std::string all;
  for (const Case& c : cases) all += c.form + "\n" + c.result + "\n";
  for (std::string_view needle :
       {"(task ", "(repeat-while ", "(subtask ", "(done)", "(repeat)", "(answer yes)", "(answer no)",
        "(goal (category", "(goal (in", "(action open", "(action close", "(action pick-up", "(action put",
        "failure unknown-word", "failure uninterpretable", "failure ungrounded-object",
        "failure affordance-mismatch", "failure unknown-predicate", "(open ", "(on "})
    EXPECT_NE(all.find(needle), std::string::npos) << needle;
}

// Every golden file of every module (tests/*/golden/*) carries its reviewed
// note, so that a new golden file cannot be added without one.
TEST(GoldenNotes, EveryGoldenFileHasAReviewedNote) {
  int files = 0;
  for (const auto& module : std::filesystem::directory_iterator(source_path("tests"))) {
    std::filesystem::path dir = module.path() / "golden";
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      ++files;
      std::ifstream in(entry.path(), std::ios::binary);
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::vector<std::string> missing = apprentice::testing::golden_note_missing(text);
      std::string list;
      for (const std::string& field : missing) list += " '" + field + "'";
      EXPECT_TRUE(missing.empty()) << entry.path() << " lacks a reviewed note, or its note lacks" << list
                                   << " (see tests/common/golden_note.h and DEVELOPERS.md, \"Golden files\")";
    }
  }
  EXPECT_GE(files, 7) << "the golden files were not found under " << source_path("tests");
}

// The check above can fail: a file without a note, or with an incomplete
// one, is caught.
TEST(GoldenNotes, CatchesAMissingOrIncompleteNote) {
  using apprentice::testing::golden_note_missing;
  using apprentice::testing::split_golden_note;
  EXPECT_EQ(golden_note_missing("sentence: Repeat.\nform: (repeat)\nresult: repeat\n").size(), 7u);
  // A header with no blank line after it is not a note.
  EXPECT_EQ(golden_note_missing("# Reviewed: x, 2026-11-30.\nclose(?r) <- steps=1\n").size(), 7u);
  std::string note =
      "# Reviewed: engineer \"golden\", 2026-11-30.\n# Covers: x\n# Source: x\n# Why right: x\n"
      "# Read: all 3 cases.\n# Found: nothing wrong.\n# Hand check: x\n\n";
  EXPECT_TRUE(golden_note_missing(note + "sentence: Repeat.\n").empty());
  EXPECT_EQ(split_golden_note(note + "body\n").first, note);
  EXPECT_EQ(split_golden_note(note + "body\n").second, "body\n");
  // A review needs its date.
  std::string undated = note;
  undated.replace(undated.find("2026-11-30"), 10, "last week");
  EXPECT_EQ(golden_note_missing(undated + "sentence: Repeat.\n"), std::vector<std::string>{"Reviewed:"});
}

}  // namespace
}  // namespace apprentice::language

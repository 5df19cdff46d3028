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
// to rewrite the form and result lines from the current code (then review
// the diff).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

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
    if (i + 1 < cases.size()) out << "\n";
  }
}

void run_golden_file(const std::filesystem::path& path) {
  std::vector<Case> cases = read_cases(path);
  ASSERT_FALSE(cases.empty()) << path;
  // The first block may be a header of comments only.
  std::vector<std::string> header;
  if (cases.front().sentence.empty()) {
    header = cases.front().comments;
    cases.erase(cases.begin());
  }
  bool update = std::getenv("APPRENTICE_UPDATE_GOLDEN") != nullptr;
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
    if (update) {
      c.form = form;
      c.result = result;
      continue;
    }
    EXPECT_EQ(form, c.form);
    EXPECT_EQ(result, c.result);
  }
  if (update) write_cases(path, header, cases);
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

}  // namespace
}  // namespace apprentice::language
